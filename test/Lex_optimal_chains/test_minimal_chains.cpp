// The matrix algorithms on arbitrary simplicial complexes (thesis sections 4.3, 4.7), against
// oracles no one here wrote and properties from the thesis:
// - Proposition 3: the minimal 2-chain of the full 2-complex bounded by the convex hull is
//   CGAL's Delaunay_triangulation_2 (Z2, Z/p, Q);
// - Theorem 4.19: with weights, CGAL's Regular_triangulation_2 (hidden points absent), and in
//   3D the minimal 3-chain of the full 3-complex is Regular_triangulation_3;
// - the generalized order with zero weights equals the order of Lemma 4.14 on triangles;
// - on small Delaunay_triangulation_3 complexes, the min-cut of the closed-surface work
//   equals Lex-OHCP of the boundary of the interior cell;
// - linearity (Lemma 4.12) and uniqueness (Lemma 4.11) of M_lex, Z2 brute force;
// - the critical basis: Betti number, Lemma 4.50, Observation 4.49, minimality, and
//   Definition 4.47 by brute force over Z2;
// - bad input.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/lex_optimal_closed_surface.h>
#include <CGAL/Lex_optimal_chains/minimal_chains.h>
#include <CGAL/Lex_optimal_chains/internal/Sparse_critical_basis.h>
#include <CGAL/Lex_optimal_chains/Simplex_orders.h>
#include <CGAL/Lex_optimal_chains/triangulation_complex.h>

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cassert>
#include <iostream>
#include <set>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_2 = K::Point_2;
using Point_3 = K::Point_3;
namespace LOC = CGAL::Lex_optimal_chains;
using Simplex = LOC::Simplicial_complex::Simplex;
using Zp = LOC::Zp_field<>;

template <class Field>
std::set<Simplex> support(const LOC::Simplicial_complex& c, int k, const LOC::Chain<Field>& chain)
{
  std::set<Simplex> s;
  for(const auto& e : chain) s.insert(c.simplex(k, e.first));
  return s;
}

// the hull boundary of the points as an oriented 1-chain (counterclockwise)
template <class Field>
LOC::Chain<Field> hull_boundary(const LOC::Simplicial_complex& c, const std::vector<Point_2>& points)
{
  std::vector<std::size_t> ids(points.size()), hull;
  for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
  CGAL::convex_hull_2(ids.begin(), ids.end(), std::back_inserter(hull),
                      CGAL::Convex_hull_traits_adapter_2<K, CGAL::Pointer_property_map<Point_2>::const_type>(
                        CGAL::make_property_map(points)));
  LOC::Chain<Field> chain;
  for(std::size_t i = 0; i < hull.size(); ++i) {
    std::uint32_t a = std::uint32_t(hull[i]), b = std::uint32_t(hull[(i + 1) % hull.size()]);
    const long sign = a < b ? 1 : -1;
    chain.emplace_back(std::uint32_t(c.index(Simplex{(std::min)(a, b), (std::max)(a, b)})), Field::from_integer(sign));
  }
  std::sort(chain.begin(), chain.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  return chain;
}

template <class Field>
void test_delaunay_2(CGAL::Random& rng)
{
  for(int trial = 0; trial < 12; ++trial) {
    const int n = rng.get_int(4, 22);
    std::vector<Point_2> points;
    for(int i = 0; i < n; ++i) points.emplace_back(rng.get_double(), rng.get_double());
    const LOC::Simplicial_complex c = LOC::Simplicial_complex::full(std::uint32_t(n), 2);
    const auto order = LOC::sort_simplices(c, 2, LOC::Triangle_order<Point_2>(points));
    const auto result = LOC::minimal_chain_with_boundary<Field>(c, 2, order, hull_boundary<Field>(c, points));
    assert(result);
    // the oracle
    CGAL::Delaunay_triangulation_2<K> dt;
    std::vector<std::pair<Point_2, std::uint32_t>> indexed;
    for(std::uint32_t i = 0; i < std::uint32_t(n); ++i) indexed.emplace_back(points[i], i);
    std::map<Point_2, std::uint32_t> index_of;
    for(const auto& pi : indexed) index_of[pi.first] = pi.second;
    dt.insert(points.begin(), points.end());
    std::set<Simplex> expected;
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      Simplex s{index_of[f->vertex(0)->point()], index_of[f->vertex(1)->point()], index_of[f->vertex(2)->point()]};
      std::sort(s.begin(), s.end());
      expected.insert(s);
    }
    assert(support<Field>(c, 2, *result) == expected);
    // the complex of the triangulation has the same triangles
    const auto tc = LOC::triangulation_complex_2(dt);
    std::set<Simplex> from_helper;
    for(std::size_t i = 0; i < tc.complex.number_of_simplices(2); ++i) {
      Simplex s;
      for(std::uint32_t v : tc.complex.simplex(2, i)) s.push_back(index_of[tc.vertices[v]->point()]);
      std::sort(s.begin(), s.end());
      from_helper.insert(s);
    }
    assert(from_helper == expected && tc.complex.number_of_simplices(1) == dt.number_of_faces() + dt.number_of_vertices() - 1);
    // oriented fields: every triangle counterclockwise with coefficient 1
    for(const auto& e : *result) {
      const Simplex& s = c.simplex(2, e.first);
      const bool ccw = CGAL::orientation(points[s[0]], points[s[1]], points[s[2]]) == CGAL::LEFT_TURN;
      assert(e.second == Field::from_integer(ccw ? 1 : -1));
    }
  }
}

void test_regular_2(CGAL::Random& rng)
{
  using RT = CGAL::Regular_triangulation_2<K>;
  int hidden_seen = 0;
  for(int trial = 0; trial < 12; ++trial) {
    const int n = rng.get_int(5, 18);
    std::vector<Point_2> points;
    std::vector<double> weights;
    for(int i = 0; i < n; ++i) {
      points.emplace_back(rng.get_double(), rng.get_double());
      weights.push_back(rng.get_double(0, 0.02));
    }
    const LOC::Simplicial_complex c = LOC::Simplicial_complex::full(std::uint32_t(n), 2);
    const auto order = LOC::sort_simplices(c, 2, LOC::Weighted_simplex_order<Point_2>(points, weights));
    const auto result = LOC::minimal_chain_with_boundary<LOC::Z2_field>(c, 2, order, hull_boundary<LOC::Z2_field>(c, points));
    assert(result);
    RT rt;
    std::map<Point_2, std::uint32_t> index_of;
    for(std::uint32_t i = 0; i < std::uint32_t(n); ++i) {
      rt.insert(RT::Weighted_point(points[i], weights[i]));
      index_of[points[i]] = i;
    }
    hidden_seen += n - int(rt.number_of_vertices());
    std::set<Simplex> expected;
    for(auto f = rt.finite_faces_begin(); f != rt.finite_faces_end(); ++f) {
      Simplex s;
      for(int j = 0; j < 3; ++j) s.push_back(index_of[f->vertex(j)->point().point()]);
      std::sort(s.begin(), s.end());
      expected.insert(s);
    }
    assert(support<LOC::Z2_field>(c, 2, *result) == expected);
  }
  std::cout << "regular triangulations 2D: " << hidden_seen << " hidden points in all\n";
}

void test_regular_3(CGAL::Random& rng)
{
  using RT = CGAL::Regular_triangulation_3<K>;
  for(int trial = 0; trial < 4; ++trial) {
    const int n = 12;
    std::vector<Point_3> points;
    std::vector<double> weights;
    for(int i = 0; i < n; ++i) {
      points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
      weights.push_back(trial == 0 ? 0.0 : rng.get_double(0, 0.02));
    }
    const LOC::Simplicial_complex c = LOC::Simplicial_complex::full(std::uint32_t(n), 3);
    RT rt;
    std::map<Point_3, std::uint32_t> index_of;
    for(std::uint32_t i = 0; i < std::uint32_t(n); ++i) {
      rt.insert(RT::Weighted_point(points[i], weights[i]));
      index_of[points[i]] = i;
    }
    // the hull boundary, oriented as the boundary of the regular triangulation
    LOC::Chain<LOC::Z2_field> hull;
    std::set<Simplex> expected;
    for(auto ci = rt.finite_cells_begin(); ci != rt.finite_cells_end(); ++ci) {
      Simplex s;
      for(int j = 0; j < 4; ++j) s.push_back(index_of[ci->vertex(j)->point().point()]);
      std::sort(s.begin(), s.end());
      expected.insert(s);
      for(int j = 0; j < 4; ++j)
        if(rt.is_infinite(ci->neighbor(j))) {
          Simplex f;
          for(int l = 0; l < 4; ++l) if(l != j) f.push_back(index_of[ci->vertex(l)->point().point()]);
          std::sort(f.begin(), f.end());
          hull.emplace_back(std::uint32_t(c.index(f)), 1);
        }
    }
    std::sort(hull.begin(), hull.end());
    const auto order = LOC::sort_simplices(c, 3, LOC::Weighted_simplex_order<Point_3>(points, weights));
    const auto result = LOC::minimal_chain_with_boundary<LOC::Z2_field>(c, 3, order, hull);
    assert(result && support<LOC::Z2_field>(c, 3, *result) == expected);
  }
}

void test_orders_agree(CGAL::Random& rng)
{
  // grid points: many exact ties of both radii
  std::vector<Point_2> points;
  for(int i = 0; i < 14; ++i) points.emplace_back(rng.get_int(0, 4), rng.get_int(0, 4));
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  for(int i = 0; i < 6; ++i) points.emplace_back(rng.get_double(0, 4), rng.get_double(0, 4));
  const std::vector<double> zero(points.size(), 0.0);
  const LOC::Simplicial_complex c = LOC::Simplicial_complex::full(std::uint32_t(points.size()), 2);
  const auto a = LOC::sort_simplices(c, 2, LOC::Triangle_order<Point_2>(points));
  const auto b = LOC::sort_simplices(c, 2, LOC::Weighted_simplex_order<Point_2>(points, zero));
  assert(a == b);
}

// On a small 3D Delaunay triangulation: the min-cut of the closed-surface work separating the
// cell of an interior point from the infinite vertex is Lex-OHCP of the boundary of that cell
// in the complex whose 3-simplices are the other finite cells.
void test_closed_surface_is_lex_ohcp(CGAL::Random& rng)
{
  using DT = CGAL::Delaunay_triangulation_3<K>;
  for(int trial = 0; trial < 10; ++trial) {
    std::vector<Point_3> points;
    for(int i = 0; i < 60; ++i) {
      const double u = rng.get_double(0, 6.283), v = rng.get_double(-1, 1), r = 1 + rng.get_double(-0.05, 0.05);
      points.emplace_back(r * std::sqrt(1 - v * v) * std::cos(u), r * std::sqrt(1 - v * v) * std::sin(u), r * v);
    }
    DT dt(points.begin(), points.end());
    const auto tc = LOC::triangulation_complex_3(dt);
    assert(tc.complex.number_of_simplices(3) == dt.number_of_finite_cells() &&
           tc.complex.number_of_simplices(2) == dt.number_of_finite_facets() &&
           tc.complex.number_of_simplices(1) == dt.number_of_finite_edges());
    std::map<Point_3, std::uint32_t> index_of;
    for(std::uint32_t i = 0; i < points.size(); ++i) index_of[points[i]] = i;
    const Point_3 inside(0.01, 0.02, 0.03);
    const DT::Cell_handle source = dt.locate(inside);
    auto simplex = [&](DT::Cell_handle ch, int skip) {
      Simplex s;
      for(int j = 0; j < 4; ++j) if(j != skip) s.push_back(index_of[ch->vertex(j)->point()]);
      std::sort(s.begin(), s.end());
      return s;
    };
    LOC::Simplicial_complex c(std::uint32_t(points.size()));
    for(auto ch = dt.finite_cells_begin(); ch != dt.finite_cells_end(); ++ch) {
      if(DT::Cell_handle(ch) == source) for(int j = 0; j < 4; ++j) c.add_simplex(simplex(ch, j));
      else c.add_simplex(simplex(ch, -1));
    }
    LOC::Chain<LOC::Z2_field> gamma0;
    for(int j = 0; j < 4; ++j) gamma0.emplace_back(std::uint32_t(c.index(simplex(source, j))), 1);
    std::sort(gamma0.begin(), gamma0.end());
    const auto order = LOC::sort_simplices(c, 2, LOC::Triangle_order<Point_3>(points));
    const auto general = support<LOC::Z2_field>(c, 2, LOC::minimal_homologous_chain<LOC::Z2_field>(c, 2, order, gamma0));
    std::vector<DT::Facet> cut;
    CGAL::lex_optimal_closed_surface(dt, std::back_inserter(cut),
                                     LOC::parameters::interior_points(std::vector<Point_3>{inside}));
    std::set<Simplex> fast;
    for(const auto& f : cut) fast.insert(simplex(f.first, f.second));
    assert(fast == general);
  }
}

// random complexes: linearity, uniqueness and Z2 brute force
template <class Field>
LOC::Chain<Field> random_chain(CGAL::Random& rng, std::size_t m, bool z2)
{
  std::map<std::uint32_t, long> c;
  for(int k = rng.get_int(0, 5); k > 0; --k) c[std::uint32_t(rng.get_int(0, int(m)))] += z2 ? 1 : rng.get_int(-3, 4);
  LOC::Chain<Field> chain;
  for(const auto& e : c)
    if(!Field::is_zero(Field::from_integer(e.second))) chain.emplace_back(e.first, Field::from_integer(e.second));
  return chain;
}

template <class Field>
LOC::Chain<Field> combine(const LOC::Chain<Field>& a, typename Field::Value fa, const LOC::Chain<Field>& b, typename Field::Value fb)
{
  std::map<std::uint32_t, typename Field::Value> m;
  for(const auto& e : a) m[e.first] = Field::add(m.count(e.first) ? m[e.first] : Field::zero(), Field::multiply(fa, e.second));
  for(const auto& e : b) m[e.first] = Field::add(m.count(e.first) ? m[e.first] : Field::zero(), Field::multiply(fb, e.second));
  LOC::Chain<Field> c;
  for(const auto& e : m) if(!Field::is_zero(e.second)) c.push_back(e);
  return c;
}

LOC::Simplicial_complex random_complex(CGAL::Random& rng, std::uint32_t n, int simplices, int largest = 4)
{
  LOC::Simplicial_complex c(n);
  for(int i = 0; i < simplices; ++i) {
    std::set<std::uint32_t> s;
    const int size = rng.get_int(2, largest + 1);
    while(int(s.size()) < size) s.insert(std::uint32_t(rng.get_int(0, int(n))));
    c.add_simplex(Simplex(s.begin(), s.end()));
  }
  return c;
}

// the boundary of a k-chain
template <class Field>
LOC::Chain<Field> boundary_of(const LOC::Simplicial_complex& c, int k, const LOC::Chain<Field>& chain)
{
  std::map<std::uint32_t, typename Field::Value> b;
  for(const auto& e : chain)
    for(const auto& fs : c.boundary(k, e.first))
      b[fs.first] = Field::add(b.count(fs.first) ? b[fs.first] : Field::zero(), Field::multiply(Field::from_integer(fs.second), e.second));
  LOC::Chain<Field> result;
  for(const auto& e : b) if(!Field::is_zero(e.second)) result.push_back(e);
  return result;
}

// Z2 brute force: the smallest chain g + (any sum of boundaries of (k+1)-simplices), the
// simplices of `excluded` (bits by rank) removed; chains as bits by rank
std::uint64_t brute_force_minimum(const LOC::Simplicial_complex& c, int k, const std::vector<std::uint32_t>& rank,
                                  std::uint64_t g, std::uint64_t excluded)
{
  std::vector<std::uint64_t> columns;
  for(std::size_t j = 0; j < c.number_of_simplices(k + 1); ++j) {
    std::uint64_t col = 0;
    for(const auto& fs : c.boundary(k + 1, j)) col ^= std::uint64_t(1) << rank[fs.first];
    columns.push_back(col);
  }
  std::uint64_t best = ~std::uint64_t(0);
  for(std::uint64_t sub = 0; sub < (std::uint64_t(1) << columns.size()); ++sub) {
    std::uint64_t x = g;
    for(std::size_t i = 0; i < columns.size(); ++i) if(sub >> i & 1) x ^= columns[i];
    best = (std::min)(best, x & ~excluded);
  }
  return best;
}

template <class Field>
void test_properties(CGAL::Random& rng, bool z2)
{
  int brute = 0, relative_brute = 0;
  for(int trial = 0; trial < 150; ++trial) {
    const LOC::Simplicial_complex c = random_complex(rng, 7, rng.get_int(2, 9));
    const int k = rng.get_int(1, 3);
    if(c.number_of_simplices(k) == 0) continue;
    const std::size_t m = c.number_of_simplices(k);
    std::vector<std::uint32_t> order(m);
    for(std::uint32_t i = 0; i < m; ++i) order[i] = i;
    CGAL::cpp98::random_shuffle(order.begin(), order.end(), rng);
    const auto g1 = random_chain<Field>(rng, m, z2), g2 = random_chain<Field>(rng, m, z2);
    const auto m1 = LOC::minimal_homologous_chain<Field>(c, k, order, g1);
    const auto m2 = LOC::minimal_homologous_chain<Field>(c, k, order, g2);
    // linearity: M(a g1 + b g2) = a M(g1) + b M(g2)
    const auto a = Field::from_integer(rng.get_int(1, 4)), b = Field::from_integer(rng.get_int(-3, 3));
    assert(LOC::minimal_homologous_chain<Field>(c, k, order, combine<Field>(g1, a, g2, b)) == combine<Field>(m1, a, m2, b));
    // uniqueness: adding a boundary does not change the minimum
    LOC::Chain<Field> with_boundary = g1;
    if(c.number_of_simplices(k + 1) > 0) {
      const std::size_t j = std::size_t(rng.get_int(0, int(c.number_of_simplices(k + 1))));
      LOC::Chain<Field> bd;
      for(const auto& fs : c.boundary(k + 1, j)) bd.emplace_back(fs.first, Field::from_integer(fs.second));
      std::sort(bd.begin(), bd.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      with_boundary = combine<Field>(g1, Field::one(), bd, Field::from_integer(rng.get_int(1, 3)));
    }
    assert(LOC::minimal_homologous_chain<Field>(c, k, order, with_boundary) == m1);
    // Z2 brute force over all (k+1)-chains, absolute, then relative to a random subcomplex B
    if(z2 && c.number_of_simplices(k + 1) <= 12 && m <= 60) {
      std::vector<std::uint32_t> rank(m);
      for(std::uint32_t r = 0; r < m; ++r) rank[order[r]] = r;
      auto bits = [&](const LOC::Chain<Field>& x) { std::uint64_t b = 0; for(const auto& e : x) b ^= std::uint64_t(1) << rank[e.first]; return b; };
      assert(bits(m1) == brute_force_minimum(c, k, rank, bits(g1), 0));
      ++brute;
      LOC::Simplicial_complex b(c.number_of_vertices());
      for(int i = rng.get_int(1, 4); i > 0; --i) {
        const int d = rng.get_int(0, k + 1);
        if(c.number_of_simplices(d) > 0) b.add_simplex(c.simplex(d, std::size_t(rng.get_int(0, int(c.number_of_simplices(d))))));
      }
      std::uint64_t in_b = 0;
      for(std::size_t i = 0; i < b.number_of_simplices(k); ++i) in_b |= std::uint64_t(1) << rank[c.index(b.simplex(k, i))];
      assert(bits(LOC::minimal_homologous_chain<Field>(c, k, order, g1, &b)) == brute_force_minimum(c, k, rank, bits(g1), in_b));
      ++relative_brute;
    }
    // imposed boundary: the boundary of a random chain is bounded, the minimum is at most it
    if(k >= 1) {
      const LOC::Chain<Field> boundary = boundary_of<Field>(c, k, g1);
      const auto minimal = LOC::minimal_chain_with_boundary<Field>(c, k, order, boundary);
      assert(minimal);
      // it has that boundary, and is not larger than g1, which has it too
      const LOC::Chain<Field> minimal_boundary = boundary_of<Field>(c, k, *minimal);
      assert(minimal_boundary == boundary);
      std::vector<std::uint32_t> rank(m);
      for(std::uint32_t r = 0; r < m; ++r) rank[order[r]] = r;
      auto top = [&](const LOC::Chain<Field>& x) { long t = -1; for(const auto& e : x) t = (std::max)(t, long(rank[e.first])); return t; };
      assert(top(*minimal) <= top(g1));
    }
  }
  if(z2) assert(brute > 40 && relative_brute > 40);
}

// The sparse Observation 4.54 (internal/Sparse_critical_basis.h) finds the dense critical
// basis from another basis of the same space of minimal cycles (sums of its elements, in
// another order), and says which sums of its inputs its elements are.
template <class Chain>
void check_sparse_critical_basis(CGAL::Random& rng, const std::vector<Chain>& basis, const std::vector<std::uint32_t>& rank,
                                 std::size_t m)
{
  namespace I = LOC::internal;
  std::vector<I::Z2_chain> dense;
  for(const auto& b : basis) {
    I::Z2_chain c;
    for(const auto& e : b) c.push_back(rank[e.first]);
    std::sort(c.begin(), c.end());
    dense.push_back(c);
  }
  std::vector<I::Z2_chain> other;
  for(std::size_t i = 0; i < dense.size(); ++i)
    other.push_back(i + 1 < dense.size() ? I::z2_sum(dense[i], dense[i + 1]) : dense[i]);
  other.push_back(I::z2_sum(other[0], other.back())); // one dependent input
  CGAL::cpp98::random_shuffle(other.begin(), other.end(), rng);
  const I::Z2_critical_basis sparse = I::z2_critical_basis(other, m);
  assert(sparse.elements == dense);
  for(std::size_t i = 0; i < dense.size(); ++i) {
    I::Z2_chain sum;
    for(std::uint32_t j : sparse.sums_of[i]) sum = I::z2_sum(sum, other[j]);
    assert(sum == dense[i]);
  }
}

// The rank over Z2 of the boundary matrix from dimension d (>= 1) to d - 1, without the
// simplices that `excluded(dimension, index)` names (its rows and columns), by a Gaussian
// elimination on bit rows written here.
template <class Excluded>
std::size_t z2_boundary_rank(const LOC::Simplicial_complex& c, int d, const Excluded& excluded)
{
  std::vector<std::vector<bool>> rows;
  for(std::size_t j = 0; j < c.number_of_simplices(d); ++j) {
    if(excluded(d, j)) continue;
    std::vector<bool> row(c.number_of_simplices(d - 1), false);
    for(const auto& fs : c.boundary(d, j)) if(!excluded(d - 1, fs.first)) row[fs.first] = !row[fs.first];
    rows.push_back(row);
  }
  std::size_t r = 0;
  for(std::size_t col = 0; col < c.number_of_simplices(d - 1) && r < rows.size(); ++col) {
    std::size_t p = r;
    while(p < rows.size() && !rows[p][col]) ++p;
    if(p == rows.size()) continue;
    std::swap(rows[p], rows[r]);
    for(std::size_t q = 0; q < rows.size(); ++q)
      if(q != r && rows[q][col])
        for(std::size_t x = 0; x < rows[q].size(); ++x) rows[q][x] = rows[q][x] != rows[r][x];
    ++r;
  }
  return r;
}

template <class Field>
void test_critical_basis(CGAL::Random& rng, bool z2)
{
  std::size_t largest = 0;
  for(int trial = 0; trial < 120; ++trial) {
    // every other trial: a graph with several triangles, rich in independent cycles
    const bool graph = trial % 2 == 0;
    const LOC::Simplicial_complex c = graph ? random_complex(rng, 8, rng.get_int(8, 20), rng.get_int(2, 4))
                                            : random_complex(rng, 8, rng.get_int(3, 14));
    const int k = graph ? 1 : rng.get_int(0, 3);
    const std::size_t m = c.number_of_simplices(k);
    if(m == 0) continue;
    std::vector<std::uint32_t> order(m);
    for(std::uint32_t i = 0; i < m; ++i) order[i] = i;
    CGAL::cpp98::random_shuffle(order.begin(), order.end(), rng);
    std::vector<std::uint32_t> rank(m);
    for(std::uint32_t r = 0; r < m; ++r) rank[order[r]] = r;
    const auto basis = LOC::critical_basis<Field>(c, k, order);
    if(z2 && basis.size() > 1) check_sparse_critical_basis(rng, basis, rank, m);
    // its size is the Betti number: m - rank d_k - rank d_{k+1}, ranks by Z2 / field elimination
    auto rank_of = [&](int dim) -> std::size_t {
      if(dim <= 0 || c.number_of_simplices(dim) == 0) return 0;
      if(z2) return z2_boundary_rank(c, dim, [](int, std::size_t) { return false; });
      std::vector<LOC::internal::Sparse_column<Field>> cols;
      for(std::size_t j = 0; j < c.number_of_simplices(dim); ++j) {
        LOC::internal::Sparse_column<Field> col;
        for(const auto& fs : c.boundary(dim, j)) col.emplace_back(fs.first, Field::from_integer(fs.second));
        std::sort(col.begin(), col.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        cols.push_back(col);
      }
      LOC::internal::Column_reduction<Field> r(cols, c.number_of_simplices(dim - 1), false);
      std::size_t nonzero = 0;
      for(std::size_t j = 0; j < r.number_of_columns(); ++j) nonzero += !r.reduced(j).empty();
      return nonzero;
    };
    assert(basis.size() == m - rank_of(k) - rank_of(k + 1));
    largest = (std::max)(largest, basis.size());
    auto crit = [&](const LOC::Chain<Field>& x) {
      std::uint32_t best = x.front().first;
      for(const auto& e : x) if(rank[e.first] > rank[best]) best = e.first;
      return best;
    };
    auto coefficient = [&](const LOC::Chain<Field>& x, std::uint32_t s) {
      for(const auto& e : x) if(e.first == s) return e.second;
      return Field::zero();
    };
    for(std::size_t i = 0; i < basis.size(); ++i) {
      // minimal in its class
      assert(LOC::minimal_homologous_chain<Field>(c, k, order, basis[i]) == basis[i]);
      // Lemma 4.50
      for(std::size_t j = 0; j < basis.size(); ++j)
        assert(coefficient(basis[j], crit(basis[i])) == (i == j ? Field::one() : Field::zero()));
      // Observation 4.49: increasing critical simplices (hence increasing chains)
      if(i > 0) assert(rank[crit(basis[i - 1])] < rank[crit(basis[i])]);
    }
    // Definition 4.47 by brute force over Z2: b_{i+1} is the smallest minimal cycle outside
    // the span of the previous ones (all elements of Z^min are sums of basis elements)
    if(z2 && basis.size() <= 10 && m <= 60) {
      auto bits = [&](const LOC::Chain<Field>& x) { std::uint64_t b = 0; for(const auto& e : x) b ^= std::uint64_t(1) << rank[e.first]; return b; };
      std::vector<std::uint64_t> all;
      for(std::uint64_t s = 1; s < (std::uint64_t(1) << basis.size()); ++s) {
        std::uint64_t x = 0;
        for(std::size_t i = 0; i < basis.size(); ++i) if(s >> i & 1) x ^= bits(basis[i]);
        all.push_back(x);
      }
      std::vector<std::uint64_t> span{0};
      for(std::size_t i = 0; i < basis.size(); ++i) {
        std::uint64_t best = ~std::uint64_t(0);
        for(std::uint64_t x : all)
          if(std::find(span.begin(), span.end(), x) == span.end()) best = (std::min)(best, x);
        assert(best == bits(basis[i]));
        const std::size_t size = span.size();
        for(std::size_t j = 0; j < size; ++j) span.push_back(span[j] ^ best);
      }
    }
  }
  std::cout << "critical bases of up to " << largest << " cycles\n";
  assert(largest >= 5);
}

void test_bad_input()
{
  LOC::Simplicial_complex c(4);
  c.add_simplex({0, 1, 2});
  c.add_simplex({1, 2, 3});
  expect_error(LOC::Input_error_code::INVALID_CHAIN, [&] { c.add_simplex({0, 0, 1}); });  // not simplicial
  expect_error(LOC::Input_error_code::INVALID_CHAIN, [&] { c.add_simplex({0, 9}); });     // no such vertex
  std::vector<std::uint32_t> order{0, 1};
  // non-finite points and weights
  const std::vector<Point_2> bad_points{Point_2(0, 0), Point_2(std::nan(""), 1), Point_2(1, 0)};
  const std::vector<double> weights{0, 0, 0}, bad_weights{0, std::numeric_limits<double>::infinity(), 0};
  const std::vector<Point_2> good_points{Point_2(0, 0), Point_2(0, 1), Point_2(1, 0)};
  expect_error(LOC::Input_error_code::NON_FINITE_COORDINATE, [&] { LOC::Triangle_order<Point_2> o(bad_points); });
  expect_error(LOC::Input_error_code::NON_FINITE_COORDINATE, [&] { LOC::Weighted_simplex_order<Point_2> o(bad_points, weights); });
  expect_error(LOC::Input_error_code::NON_FINITE_COORDINATE, [&] { LOC::Weighted_simplex_order<Point_2> o(good_points, bad_weights); });
  expect_error(LOC::Input_error_code::TOO_LARGE, [&] { LOC::Simplicial_complex::full(3, -2); });
  // a boundary that is not a cycle: a single edge
  expect_error(LOC::Input_error_code::BOUNDARY_NOT_A_CYCLE,
               [&] { LOC::minimal_chain_with_boundary<LOC::Z2_field>(c, 2, order, LOC::Chain<LOC::Z2_field>{{0, 1}}); });
  // a simplex not in the complex
  expect_error(LOC::Input_error_code::INVALID_CHAIN,
               [&] { LOC::minimal_homologous_chain<LOC::Z2_field>(c, 2, order, LOC::Chain<LOC::Z2_field>{{7, 1}}); });
  // an order that is not a permutation
  expect_error(LOC::Input_error_code::INVALID_CHAIN,
               [&] { LOC::minimal_homologous_chain<LOC::Z2_field>(c, 2, std::vector<std::uint32_t>{0, 0}, {}); });
  // a cycle that bounds nothing: the hollow triangle 0-1-3
  LOC::Simplicial_complex h(4);
  h.add_simplex({0, 1}); h.add_simplex({1, 3}); h.add_simplex({0, 3});
  LOC::Chain<LOC::Z2_field> loop{{std::uint32_t(h.index({0, 1})), 1}, {std::uint32_t(h.index({0, 3})), 1}, {std::uint32_t(h.index({1, 3})), 1}};
  std::sort(loop.begin(), loop.end());
  // no triangle at all: the loop is not a boundary
  assert(!LOC::minimal_chain_with_boundary<LOC::Z2_field>(h, 1 + 1, std::vector<std::uint32_t>{}, loop));
  // with a triangle elsewhere, still not
  LOC::Simplicial_complex h2 = h;
  h2.add_simplex({0, 1, 2});
  const std::vector<std::uint32_t> one{0};
  LOC::Chain<LOC::Z2_field> loop2;
  for(const Simplex& e : {Simplex{0, 1}, Simplex{1, 3}, Simplex{0, 3}}) loop2.emplace_back(std::uint32_t(h2.index(e)), 1);
  std::sort(loop2.begin(), loop2.end());
  assert(!LOC::minimal_chain_with_boundary<LOC::Z2_field>(h2, 2, one, loop2));
}

// The critical basis relative to a subcomplex B over Z2, in dimensions 0 and 1 (where
// critical_basis() leaves out the cycles whose largest simplex is the low of a boundary): its
// size is the relative Betti number (ranks of the relative boundary matrices by
// z2_boundary_rank()), each element is a relative cycle with no simplex of B, minimal in its class,
// and Lemma 4.50 holds.
void test_relative_critical_basis(CGAL::Random& rng)
{
  using F = LOC::Z2_field;
  std::size_t largest = 0, trials = 0;
  for(int trial = 0; trial < 150; ++trial) {
    const LOC::Simplicial_complex c = random_complex(rng, 8, rng.get_int(6, 16), rng.get_int(2, 4));
    const int k = rng.get_int(0, 2);
    const std::size_t m = c.number_of_simplices(k);
    if(m == 0) continue;
    LOC::Simplicial_complex b(c.number_of_vertices()); // a few simplices of K with their faces
    for(int i = rng.get_int(1, 4); i > 0; --i) {
      const int d = rng.get_int(0, c.dimension() + 1);
      if(c.number_of_simplices(d) == 0) continue;
      b.add_simplex(c.simplex(d, std::size_t(rng.get_int(0, int(c.number_of_simplices(d))))));
    }
    auto in_b = [&](int d, std::size_t i) { return d >= 0 && b.index(c.simplex(d, i)) >= 0; };
    // rank over Z2 of the boundary from dimension d to d - 1, rows and columns of B removed
    auto relative_rank = [&](int d) -> std::size_t {
      return d <= 0 || c.number_of_simplices(d) == 0 ? 0 : z2_boundary_rank(c, d, in_b);
    };
    std::size_t outside = 0;
    for(std::size_t i = 0; i < m; ++i) outside += !in_b(k, i);
    std::vector<std::uint32_t> order(m);
    for(std::uint32_t i = 0; i < m; ++i) order[i] = i;
    CGAL::cpp98::random_shuffle(order.begin(), order.end(), rng);
    std::vector<std::uint32_t> rank(m);
    for(std::uint32_t r = 0; r < m; ++r) rank[order[r]] = r;
    const auto basis = LOC::critical_basis<F>(c, k, order, &b);
    assert(basis.size() == outside - relative_rank(k) - relative_rank(k + 1));
    auto crit = [&](const LOC::Chain<F>& x) {
      std::uint32_t best = x.front().first;
      for(const auto& e : x) if(rank[e.first] > rank[best]) best = e.first;
      return best;
    };
    for(std::size_t i = 0; i < basis.size(); ++i) {
      for(const auto& e : basis[i]) assert(!in_b(k, e.first));
      for(const auto& e : boundary_of<F>(c, k, basis[i])) assert(in_b(k - 1, e.first)); // a relative cycle
      assert(LOC::minimal_homologous_chain<F>(c, k, order, basis[i], &b) == basis[i]);
      for(std::size_t j = 0; j < basis.size(); ++j) {
        bool has = false;
        for(const auto& e : basis[j]) has = has || e.first == crit(basis[i]);
        assert(has == (i == j)); // Lemma 4.50
      }
    }
    largest = (std::max)(largest, basis.size());
    trials += !basis.empty();
  }
  std::cout << "relative critical bases in dimensions 0 and 1: up to " << largest << " elements, " << trials
            << " non-empty" << std::endl;
  assert(largest >= 3 && trials >= 50);
}

int main()
{
  CGAL::Random rng(17);
  test_delaunay_2<LOC::Z2_field>(rng);
  test_delaunay_2<Zp>(rng);
  test_delaunay_2<LOC::Q_field>(rng);
  test_regular_2(rng);
  test_regular_3(rng);
  test_orders_agree(rng);
  test_closed_surface_is_lex_ohcp(rng);
  test_properties<LOC::Z2_field>(rng, true);
  test_properties<Zp>(rng, false);
  test_properties<LOC::Q_field>(rng, false);
  test_critical_basis<LOC::Z2_field>(rng, true);
  test_critical_basis<Zp>(rng, false);
  test_critical_basis<LOC::Q_field>(rng, false);
  test_relative_critical_basis(rng);
  test_bad_input();
  std::cout << "test_minimal_chains: OK\n";
  return 0;
}
