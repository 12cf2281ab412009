// Algorithms 9, 10 and 11 against oracles written here:
// - the augmented disjoint sets against explicit potentials;
// - Algorithm 11: the representative chain of random cycles has exactly that boundary;
// - Algorithm 10 (absolute and relative, Z2 and Q) against the matrix algorithm of the
//   thesis for general complexes (column reduction of the boundary matrix of the tetrahedra
//   of DT + infinite vertex, rows in the triangle order, then elimination from the largest
//   triangle down; exact rationals), and over Z2 against brute force over all 3-chains.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Random.h>
#include <CGAL/Lex_optimal_chains_traits_3.h>
#include <CGAL/lex_optimal_homologous_chain.h>
#include <CGAL/Lex_optimal_chains/internal/Augmented_union_find.h>
#include <CGAL/Lex_optimal_chains/internal/Homologous_chain_3.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <random>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using DT = CGAL::Delaunay_triangulation_3<K>;
using Vertex_handle = DT::Vertex_handle;
using Cell_handle = DT::Cell_handle;
using Facet = DT::Facet;
namespace LOC = CGAL::Lex_optimal_chains;
using Q = CGAL::Exact_rational;

template <class Arithmetic>
void test_augmented_union_find(CGAL::Random& rng)
{
  using Value = typename Arithmetic::Value;
  for(int trial = 0; trial < 200; ++trial) {
    const int n = rng.get_int(2, 40);
    LOC::internal::Augmented_union_find<Arithmetic> sets(n);
    std::vector<int> set_of(n);
    std::vector<std::int64_t> potential(n, 0); // value of the path x -> y is potential[x] - potential[y]
    for(int i = 0; i < n; ++i) set_of[i] = i;
    for(int step = 0; step < 3 * n; ++step) {
      const int x = rng.get_int(0, n), y = rng.get_int(0, n);
      const auto fx = sets.find(x), fy = sets.find(y);
      assert((fx.first == fy.first) == (set_of[x] == set_of[y]));
      if(fx.first == fy.first) {
        // g(x) - g(y) is the value of the path x -> y
        const Value d = Arithmetic::add(fx.second, Arithmetic::negate(fy.second));
        assert(d == Arithmetic::from_integer(potential[x] - potential[y]));
        continue;
      }
      const std::int64_t delta = rng.get_int(-5, 6);
      // path r1 -> r2 gets value delta: shift the potentials of r1's set
      const std::int64_t shift = delta - (potential[fx.first] - potential[fy.first]);
      const int old = set_of[x];
      for(int i = 0; i < n; ++i)
        if(set_of[i] == old) { set_of[i] = set_of[y]; potential[i] += shift; }
      sets.link_roots(fx.first, fy.first, Arithmetic::from_integer(delta));
    }
  }
  // a forest given by parent pointers (as the contraction sets it), then flattened: the same
  // path values through `find`, `find_in_flat` and after further links
  for(int trial = 0; trial < 100; ++trial) {
    const int n = rng.get_int(2, 60);
    std::vector<std::uint32_t> parent(n);
    std::vector<std::int64_t> link(n, 0), potential(n, 0); // potential: value of the path to the root
    for(int x = 0; x < n; ++x) {
      parent[x] = x == 0 || rng.get_double() < 0.2 ? std::uint32_t(x) : std::uint32_t(rng.get_int(0, x)); // parents first
      if(parent[x] != std::uint32_t(x)) link[x] = rng.get_int(-4, 5);
      potential[x] = parent[x] == std::uint32_t(x) ? 0 : link[x] + potential[parent[x]];
    }
    std::vector<std::uint32_t> root(n);
    for(int x = 0; x < n; ++x) root[x] = parent[x] == std::uint32_t(x) ? x : root[parent[x]];
    LOC::internal::Augmented_union_find<Arithmetic> sets(n);
    for(int x = 0; x < n; ++x) sets.set_parent(std::uint32_t(x), parent[x]);
    sets.set_forest_of_parents([&](std::uint32_t x, std::uint32_t p) {
      assert(p == parent[x]);
      return Arithmetic::from_integer(link[x]);
    });
    assert(sets.is_forest());
    const bool flat = trial % 2 == 0;
    if(flat) sets.flatten();
    for(int x = 0; x < n; ++x) {
      const auto f = flat ? sets.find_in_flat(x) : sets.find(x);
      assert(f.first == root[x] && f.second == Arithmetic::from_integer(potential[x]));
    }
  }
  // parent pointers with a cycle of three elements or more (parents in any order otherwise) are
  // refused: find() would loop forever; a cycle of two (two cells whose largest facet is the
  // same) is broken at its element of larger index, which becomes a root
  auto forest_of = [](const std::vector<std::uint32_t>& parent) {
    LOC::internal::Augmented_union_find<Arithmetic> sets(parent.size());
    for(std::uint32_t x = 0; x < parent.size(); ++x) sets.set_parent(x, parent[x]);
    sets.set_forest_of_parents([](std::uint32_t, std::uint32_t) { return Arithmetic::from_integer(1); });
    return sets;
  };
  int refused_cycles = 0, broken_pairs = 0;
  for(int trial = 0; trial < 40; ++trial) {
    const int n = rng.get_int(3, 40);
    std::vector<std::uint32_t> order(n), parent(n);
    for(int x = 0; x < n; ++x) order[x] = std::uint32_t(x);
    std::shuffle(order.begin(), order.end(), std::mt19937(trial));
    for(int i = 0; i < n; ++i) parent[order[i]] = i == 0 ? order[0] : order[rng.get_int(0, i)]; // a tree
    assert(forest_of(parent).is_forest());
    const std::uint32_t leaf = trial % 2 == 0 ? order[n - 1] : order[1]; // order[1] is a child of the root
    parent[order[0]] = leaf; // the root under another element: a cycle
    std::size_t length = 1;
    for(std::uint32_t x = leaf; x != order[0]; x = parent[x]) ++length;
    const auto behaviour = CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION);
    bool refused = false;
    try {
      auto sets = forest_of(parent);
      assert(length == 2);
      const std::uint32_t high = (std::max)(order[0], leaf), low = (std::min)(order[0], leaf);
      assert(sets.find(high).first == high && sets.find(low).first == high);
      ++broken_pairs;
    } catch(const CGAL::Failure_exception&) { refused = true; }
    CGAL::set_error_behaviour(behaviour);
    assert(refused == (length >= 3));
    if(refused) ++refused_cycles;
  }
  assert(refused_cycles > 0 && broken_pairs > 0);
}

// ----- chains as maps over canonically oriented simplices -----------------------------------

// orientation sign of the permutation taking `from` to `to` (both of 3 distinct elements)
template <class T>
int permutation_sign(const std::array<T, 3>& from, const std::array<T, 3>& to)
{
  for(int r = 0; r < 3; ++r)
    if(from[r] == to[0] && from[(r + 1) % 3] == to[1]) return 1;
  return -1;
}

std::array<Vertex_handle, 3> outward_triangle(const Facet& f)
{
  const int i = f.second;
  std::array<Vertex_handle, 3> t{{f.first->vertex((i + 1) & 3), f.first->vertex((i + 2) & 3), f.first->vertex((i + 3) & 3)}};
  if(i & 1) std::swap(t[1], t[2]);
  return t;
}

// canonical form: vertices sorted by address, and the sign of the given orientation
std::pair<std::array<Vertex_handle, 3>, int> canonical(const std::array<Vertex_handle, 3>& t)
{
  std::array<Vertex_handle, 3> s = t;
  std::sort(s.begin(), s.end());
  return {s, permutation_sign(t, s)};
}

using Chain = std::map<std::array<Vertex_handle, 3>, std::int64_t>; // canonical triangle -> coefficient

void add(Chain& c, const std::array<Vertex_handle, 3>& t, std::int64_t k, bool z2)
{
  const auto ct = canonical(t);
  std::int64_t& x = c[ct.first];
  x += ct.second * k;
  if(z2) x = ((x % 2) + 2) % 2;
  if(x == 0) c.erase(ct.first);
}

using Edge_chain = std::map<std::pair<Vertex_handle, Vertex_handle>, std::int64_t>;

void add_edge(Edge_chain& c, Vertex_handle u, Vertex_handle v, std::int64_t k, bool z2)
{
  if(v < u) { std::swap(u, v); k = -k; }
  std::int64_t& x = c[{u, v}];
  x += k;
  if(z2) x = ((x % 2) + 2) % 2;
  if(x == 0) c.erase({u, v});
}

Edge_chain boundary(const Chain& c, bool z2)
{
  Edge_chain b;
  for(const auto& tk : c) {
    const auto& t = tk.first;
    add_edge(b, t[1], t[2], tk.second, z2);
    add_edge(b, t[2], t[0], tk.second, z2);
    add_edge(b, t[0], t[1], tk.second, z2);
  }
  return b;
}

std::vector<Point> random_points(CGAL::Random& rng, int n, bool grid)
{
  std::vector<Point> points;
  while(int(points.size()) < n) {
    if(grid) points.emplace_back(rng.get_int(0, 4), rng.get_int(0, 4), rng.get_int(0, 4)); // exact ties
    else points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  }
  return points;
}

void test_representative_chain(CGAL::Random& rng)
{
  int tested = 0;
  for(int trial = 0; trial < 60; ++trial) {
    const bool z2 = trial % 2 == 0;
    DT dt;
    for(const Point& p : random_points(rng, rng.get_int(10, 300), trial % 3 == 0)) dt.insert(p);
    if(dt.dimension() < 3) continue;
    // a random cycle: the boundary of random finite triangles with random coefficients
    std::vector<Facet> facets(dt.finite_facets_begin(), dt.finite_facets_end());
    Chain source;
    for(int k = rng.get_int(1, 12); k > 0; --k)
      add(source, outward_triangle(facets[rng.get_int(0, int(facets.size()))]), z2 ? 1 : rng.get_int(-2, 3), z2);
    const Edge_chain cycle = boundary(source, z2);
    std::vector<LOC::internal::Oriented_edge<Vertex_handle, std::int64_t>> edges;
    for(const auto& e : cycle) edges.push_back({e.first.first, e.first.second, e.second});
    Chain got;
    if(z2) {
      std::vector<LOC::internal::Oriented_edge<Vertex_handle, std::uint8_t>> edges2;
      for(const auto& e : edges) edges2.push_back({e.source, e.target, std::uint8_t(e.coefficient & 1)});
      LOC::internal::Representative_chain_3<DT, LOC::internal::Z2_arithmetic> r(dt, edges2);
      for(const auto& t : r.chain()) add(got, t.vertices, t.coefficient, true);
    } else {
      LOC::internal::Representative_chain_3<DT, LOC::internal::Integer_arithmetic> r(dt, edges);
      for(const auto& t : r.chain()) {
        Cell_handle c;
        int i, j, k;
        assert(dt.is_facet(t.vertices[0], t.vertices[1], t.vertices[2], c, i, j, k));
        add(got, t.vertices, t.coefficient, false);
      }
    }
    assert(boundary(got, z2) == cycle);
    ++tested;
  }
  assert(tested > 40);

  // errors: a lone edge is not a cycle; a non-edge is refused
  DT dt;
  for(const Point& p : random_points(rng, 50, false)) dt.insert(p);
  const auto e = *dt.finite_edges_begin();
  const Vertex_handle u = e.first->vertex(e.second), v = e.first->vertex(e.third);
  bool thrown = false;
  try {
    LOC::internal::Representative_chain_3<DT, LOC::internal::Integer_arithmetic> r(dt, {{u, v, 1}});
  } catch(const LOC::Input_error& err) { thrown = err.code() == LOC::Input_error_code::BOUNDARY_NOT_A_CYCLE; }
  assert(thrown);
  Vertex_handle far;
  Cell_handle c;
  int i, j;
  for(auto w = dt.finite_vertices_begin(); w != dt.finite_vertices_end(); ++w)
    if(Vertex_handle(w) != u && !dt.is_edge(u, w, c, i, j)) far = w;
  assert(far != Vertex_handle());
  thrown = false;
  try {
    LOC::internal::Representative_chain_3<DT, LOC::internal::Integer_arithmetic> r(dt, {{u, far, 1}, {far, u, -1}});
  } catch(const LOC::Input_error& err) { thrown = err.code() == LOC::Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION; }
  assert(thrown);
}

// ----- the matrix oracle --------------------------------------------------------------------

// Lexicographic minimal chain in gamma0 + span(boundaries of all cells of DT + infinite
// vertex), rows of B removed; rows ordered by the triangle order (infinite triangles last).
Chain matrix_oracle(const DT& dt, const Chain& gamma0, const std::vector<std::array<Vertex_handle, 3>>& relative, bool z2)
{
  // the rows: every triangle of the completed complex, sorted
  std::vector<std::array<Vertex_handle, 3>> rows;
  for(auto f = dt.all_facets_begin(); f != dt.all_facets_end(); ++f) rows.push_back(canonical(outward_triangle(*f)).first);
  CGAL::Lex_optimal_chains_traits_3<K>::Compare_triangle_order_3 compare;
  auto rank_less = [&](const std::array<Vertex_handle, 3>& a, const std::array<Vertex_handle, 3>& b) {
    const bool ia = dt.is_infinite(a[0]) || dt.is_infinite(a[1]) || dt.is_infinite(a[2]);
    const bool ib = dt.is_infinite(b[0]) || dt.is_infinite(b[1]) || dt.is_infinite(b[2]);
    if(ia != ib) return ib;
    if(ia) return a < b;
    return compare(a[0]->point(), a[1]->point(), a[2]->point(), b[0]->point(), b[1]->point(), b[2]->point()) == CGAL::SMALLER;
  };
  std::sort(rows.begin(), rows.end(), rank_less);
  std::map<std::array<Vertex_handle, 3>, int> row_of;
  for(std::size_t r = 0; r < rows.size(); ++r) row_of[rows[r]] = int(r);
  std::vector<char> in_b(rows.size(), 0);
  for(const auto& t : relative) in_b[row_of.at(canonical(t).first)] = 1;
  auto normalize = [&](std::vector<Q>& v) {
    for(std::size_t r = 0; r < v.size(); ++r) {
      if(in_b[r]) v[r] = 0;
      if(z2) { // the integers appearing stay small: reduce mod 2
        const double d = CGAL::to_double(v[r]);
        v[r] = (long(d) % 2 + 2) % 2;
      }
    }
  };
  // columns: boundaries of every cell
  std::vector<std::vector<Q>> columns;
  for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    std::vector<Q> col(rows.size(), 0);
    for(int i = 0; i < 4; ++i) {
      const auto ct = canonical(outward_triangle(Facet(c, i)));
      col[row_of.at(ct.first)] += ct.second;
    }
    normalize(col);
    columns.push_back(col);
  }
  auto low = [](const std::vector<Q>& v) {
    for(int r = int(v.size()) - 1; r >= 0; --r) if(v[r] != 0) return r;
    return -1;
  };
  std::map<int, std::size_t> column_of_low;
  for(std::size_t j = 0; j < columns.size(); ++j) {
    for(int l = low(columns[j]); l >= 0 && column_of_low.count(l); l = low(columns[j])) {
      const auto& p = columns[column_of_low[l]];
      const Q factor = columns[j][l] / p[l];
      for(std::size_t r = 0; r < rows.size(); ++r) columns[j][r] -= factor * p[r];
      normalize(columns[j]);
    }
    const int l = low(columns[j]);
    if(l >= 0) column_of_low[l] = j;
  }
  std::vector<Q> g(rows.size(), 0);
  for(const auto& tk : gamma0) g[row_of.at(tk.first)] += Q(tk.second);
  normalize(g);
  for(int r = int(rows.size()) - 1; r >= 0; --r) {
    if(g[r] == 0 || !column_of_low.count(r)) continue;
    const auto& p = columns[column_of_low[r]];
    const Q factor = g[r] / p[r];
    for(std::size_t s = 0; s < rows.size(); ++s) g[s] -= factor * p[s];
    normalize(g);
  }
  Chain result;
  for(std::size_t r = 0; r < rows.size(); ++r) {
    if(g[r] == 0) continue;
    assert(!(dt.is_infinite(rows[r][0]) || dt.is_infinite(rows[r][1]) || dt.is_infinite(rows[r][2])));
    // the integer coefficients of the optimum of an integral chain are integers
    assert(z2 || Q(std::int64_t(CGAL::to_double(g[r]))) == g[r]);
    result[rows[r]] = std::int64_t(CGAL::to_double(g[r]));
  }
  return result;
}

// Z2 brute force: every subset of finite cells, plus all or none of the infinite cells
Chain brute_force_z2(const DT& dt, const Chain& gamma0, const std::vector<std::array<Vertex_handle, 3>>& relative)
{
  std::vector<std::array<Vertex_handle, 3>> rows;
  for(auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) rows.push_back(canonical(outward_triangle(*f)).first);
  CGAL::Lex_optimal_chains_traits_3<K>::Compare_triangle_order_3 compare;
  std::sort(rows.begin(), rows.end(), [&](const auto& a, const auto& b) {
    return compare(a[0]->point(), a[1]->point(), a[2]->point(), b[0]->point(), b[1]->point(), b[2]->point()) == CGAL::SMALLER;
  });
  assert(rows.size() <= 64);
  std::map<std::array<Vertex_handle, 3>, int> row_of;
  for(std::size_t r = 0; r < rows.size(); ++r) row_of[rows[r]] = int(r);
  std::uint64_t mask_b = 0;
  for(const auto& t : relative) mask_b |= std::uint64_t(1) << row_of.at(canonical(t).first);
  auto finite_boundary = [&](Cell_handle c) {
    std::uint64_t m = 0;
    for(int i = 0; i < 4; ++i) {
      const auto t = canonical(outward_triangle(Facet(c, i))).first;
      if(row_of.count(t)) m ^= std::uint64_t(1) << row_of.at(t);
    }
    return m;
  };
  std::vector<std::uint64_t> cells;
  std::uint64_t infinite = 0;
  for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    if(dt.is_infinite(c)) infinite ^= finite_boundary(c);
    else cells.push_back(finite_boundary(c));
  }
  cells.push_back(infinite);
  std::uint64_t g = 0;
  for(const auto& tk : gamma0) if(tk.second & 1) g ^= std::uint64_t(1) << row_of.at(tk.first);
  std::uint64_t best = ~std::uint64_t(0);
  const std::size_t n = cells.size();
  for(std::uint64_t s = 0; s < (std::uint64_t(1) << n); ++s) {
    std::uint64_t x = g;
    for(std::size_t i = 0; i < n; ++i) if(s >> i & 1) x ^= cells[i];
    x &= ~mask_b;
    best = (std::min)(best, x);
  }
  Chain result;
  for(std::size_t r = 0; r < rows.size(); ++r) if(best >> r & 1) result[rows[r]] = 1;
  return result;
}

void test_optimal_chain(CGAL::Random& rng)
{
  int tested = 0, brute = 0, relative_tested = 0;
  for(int trial = 0; trial < 240; ++trial) {
    const bool z2 = trial % 2 == 0;
    const bool grid = trial % 3 == 0;
    DT dt;
    for(const Point& p : random_points(rng, rng.get_int(5, grid ? 16 : 10), grid)) dt.insert(p);
    if(dt.dimension() < 3) continue;
    std::vector<Facet> facets(dt.finite_facets_begin(), dt.finite_facets_end());
    Chain gamma0;
    std::vector<std::pair<Facet, std::int64_t>> input;
    for(int k = rng.get_int(1, 6); k > 0; --k) {
      const Facet f = facets[rng.get_int(0, int(facets.size()))];
      const std::int64_t coefficient = z2 ? 1 : rng.get_int(-2, 3);
      input.emplace_back(f, coefficient);
      add(gamma0, outward_triangle(f), coefficient, z2);
    }
    std::vector<Facet> b_facets;
    std::vector<std::array<Vertex_handle, 3>> b_triangles;
    if(trial % 4 >= 2) { // relative to a few random triangles
      for(int k = rng.get_int(1, 5); k > 0; --k) {
        const Facet f = facets[rng.get_int(0, int(facets.size()))];
        b_facets.push_back(f);
        b_triangles.push_back(outward_triangle(f));
      }
      ++relative_tested;
    }
    std::vector<std::pair<Facet, std::int64_t>> output;
    const auto field = z2 ? LOC::Coefficient_field::Z2 : LOC::Coefficient_field::Q;
    const auto report = CGAL::lex_optimal_homologous_chain(dt, input, std::back_inserter(output),
                                       LOC::parameters::relative_facets(b_facets, LOC::parameters::coefficient_field(field)));
    assert(report.number_of_relative_triangles > 0 || b_facets.empty());
    Chain got;
    for(const auto& fk : output) {
      assert(fk.second > 0);
      add(got, outward_triangle(fk.first), fk.second, z2);
    }
    const Chain expected = matrix_oracle(dt, gamma0, b_triangles, z2);
    if(got != expected)
      std::cerr << "trial " << trial << (z2 ? " Z2" : " Q") << (b_facets.empty() ? " absolute" : " relative") << ": "
                << got.size() << " triangles, expected " << expected.size() << "\n";
    assert(got == expected);
    if(z2 && dt.number_of_cells() <= 20) {
      assert(brute_force_z2(dt, gamma0, b_triangles) == expected);
      ++brute;
    }
    if(b_facets.empty()) { // absolute: same boundary as gamma0
      assert(boundary(got, z2) == boundary(gamma0, z2));
    }
    ++tested;
  }
  std::cout << tested << " optimal chains against the matrix algorithm (" << relative_tested << " relative), "
            << brute << " against brute force\n";
  assert(tested > 150 && brute > 10 && relative_tested > 40);
}

// The contraction of Algorithm 10 (internal/Homologous_chain_3.h) against Algorithm 10 as the
// thesis states it, written here from the internal pieces: all the finite facets sorted, the
// cells alone but for the infinite ones, every facet processed in decreasing order. The public
// function must give the same facets, with the same coefficients, in the same order, while
// sorting fewer facets. Clouds of a few thousand points (where most cells are contracted),
// grids (exact ties), a chain of many random triangles and a chain along a surface, absolute
// and relative, over Z2 and Q.
template <class Arithmetic>
std::vector<std::pair<Facet, std::int64_t>> full_algorithm_10(const DT& dt, const std::vector<std::pair<Facet, std::int64_t>>& input,
                                                              const std::vector<Facet>& b_facets)
{
  using Graph = LOC::internal::Sorted_dual_graph_3<DT>;
  using Value = typename Arithmetic::Value;
  Graph graph(dt, [](double) { return true; });
  LOC::internal::Record_values<Value> gamma0(graph.number_of_cells());
  for(const auto& fk : input) {
    const auto code = graph.record_code(fk.first.first, fk.first.second);
    const Value v = Arithmetic::from_integer(fk.second);
    gamma0.template add<Arithmetic>(code.first, code.second ? Arithmetic::negate(v) : v);
  }
  LOC::internal::Record_values<std::uint8_t> relative(graph.number_of_cells());
  for(const Facet& f : b_facets) relative.template add<LOC::internal::Z2_arithmetic>(graph.record_code(f.first, f.second).first, 1);
  std::vector<std::uint32_t> infinite;
  std::vector<Cell_handle> hull;
  dt.incident_cells(dt.infinite_vertex(), std::back_inserter(hull));
  for(const Cell_handle& c : hull) infinite.push_back(graph.position(c));
  auto sets = LOC::internal::sets_with_infinite_node<Arithmetic>(graph.number_of_cells(), infinite);
  const auto chain = LOC::internal::lexicographic_homologous_chain<Arithmetic>(graph, sets, gamma0, relative,
                                                                               [](double) { return true; });
  std::vector<std::pair<Facet, std::int64_t>> result;
  LOC::Open_surface_report report;
  LOC::internal::write_chain<Arithmetic>(dt, graph.cell_positions(), chain, std::back_inserter(result), report);
  return result;
}

void test_contraction_against_full_algorithm_10(CGAL::Random& rng)
{
  int compared = 0;
  for(int trial = 0; trial < 24; ++trial) {
    const bool z2 = trial % 2 == 0, relative = trial % 4 >= 2;
    const int kind = (trial / 4) % 3; // 0: cloud, 1: grid, 2: sphere with a chain along it
    std::vector<Point> points;
    if(kind == 0) for(int i = 0; i < 3000; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
    if(kind == 1)
      for(int i = 0; i <= 8; ++i)
        for(int j = 0; j <= 8; ++j)
          for(int k = 0; k <= 5; ++k) points.emplace_back(i, j, k);
    if(kind == 2)
      while(points.size() < 3000) {
        const double x = rng.get_double(-1, 1), y = rng.get_double(-1, 1), z = rng.get_double(-1, 1);
        const double r = std::sqrt(x * x + y * y + z * z);
        if(r > 0.1 && r < 1) points.emplace_back(x / r + rng.get_double(-0.01, 0.01), y / r, z / r);
      }
    const DT dt(points.begin(), points.end());
    std::vector<Facet> facets(dt.finite_facets_begin(), dt.finite_facets_end());
    std::vector<std::pair<Facet, std::int64_t>> input;
    if(kind == 2) { // the facets of the upper cells of the hull, a chain with a long boundary
      for(const Facet& f : facets)
        if(dt.is_infinite(f.first->neighbor(f.second)) && f.first->vertex((f.second + 1) & 3)->point().z() > 0.3)
          input.emplace_back(f, z2 ? 1 : rng.get_int(1, 3));
    } else {
      for(int k = rng.get_int(50, 400); k > 0; --k)
        input.emplace_back(facets[rng.get_int(0, int(facets.size()))], z2 ? 1 : rng.get_int(-3, 4));
    }
    std::vector<Facet> b_facets;
    if(relative)
      for(int k = rng.get_int(20, 200); k > 0; --k) b_facets.push_back(facets[rng.get_int(0, int(facets.size()))]);
    const auto field = z2 ? LOC::Coefficient_field::Z2 : LOC::Coefficient_field::Q;
    std::vector<std::pair<Facet, std::int64_t>> got;
    CGAL::lex_optimal_homologous_chain(dt, input, std::back_inserter(got),
                                       LOC::parameters::relative_facets(b_facets, LOC::parameters::coefficient_field(field)));
    const auto expected = z2 ? full_algorithm_10<LOC::internal::Z2_arithmetic>(dt, input, b_facets)
                             : full_algorithm_10<LOC::internal::Integer_arithmetic>(dt, input, b_facets);
    if(got != expected)
      std::cerr << "trial " << trial << (z2 ? " Z2" : " Q") << (relative ? " relative" : " absolute") << " kind " << kind
                << ": " << got.size() << " facets, expected " << expected.size() << "\n";
    assert(got == expected);
    assert(!got.empty());
    ++compared;
  }
  // the contraction leaves few facets to sort
  {
    std::vector<Point> points;
    for(int i = 0; i < 3000; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
    const DT dt(points.begin(), points.end());
    const LOC::internal::Handle_index_map<DT::Cell> cells(dt.tds().cells().begin(), dt.tds().cells().end());
    std::vector<std::uint32_t> infinite;
    std::vector<Cell_handle> hull;
    dt.incident_cells(dt.infinite_vertex(), std::back_inserter(hull));
    for(const Cell_handle& c : hull) infinite.push_back(cells.index(&*c));
    LOC::internal::Record_values<std::uint8_t> gamma0(cells.size()), relative(cells.size());
    gamma0.add<LOC::internal::Z2_arithmetic>(LOC::internal::Sorted_dual_graph_3<DT>::record_code(
                                               dt, cells, dt.finite_facets_begin()->first, dt.finite_facets_begin()->second).first, 1);
    const LOC::internal::Contracted_homologous_graph_3<LOC::internal::Z2_arithmetic, DT> contracted(
      dt, cells, infinite, gamma0, relative, [](double) { return true; });
    const std::size_t all = LOC::internal::Sorted_dual_graph_3<DT>::number_of_finite_facets(dt);
    std::cout << "contraction: " << contracted.graph().records().size() << " of " << all << " facets sorted\n";
    assert(contracted.graph().records().size() * 2 < all);
  }
  std::cout << compared << " optimal chains of the contracted graph against the full Algorithm 10\n";
}

// Algorithm 11 + 10 through the public function: the optimum bounded by a cycle equals the
// optimum homologous to any chain with that boundary.
void test_chain_with_boundary(CGAL::Random& rng)
{
  for(int trial = 0; trial < 40; ++trial) {
    const bool z2 = trial % 2 == 0;
    DT dt;
    for(const Point& p : random_points(rng, rng.get_int(20, 200), trial % 3 == 0)) dt.insert(p);
    std::vector<Facet> facets(dt.finite_facets_begin(), dt.finite_facets_end());
    Chain source;
    std::vector<std::pair<Facet, std::int64_t>> input;
    for(int k = rng.get_int(1, 10); k > 0; --k) {
      const Facet f = facets[rng.get_int(0, int(facets.size()))];
      input.emplace_back(f, 1);
      add(source, outward_triangle(f), 1, z2);
    }
    std::vector<std::pair<Vertex_handle, Vertex_handle>> cycle;
    for(const auto& e : boundary(source, z2)) {
      for(std::int64_t k = 0; k < std::abs(e.second); ++k) {
        if(e.second > 0) cycle.emplace_back(e.first.first, e.first.second);
        else cycle.emplace_back(e.first.second, e.first.first);
      }
    }
    const auto field = z2 ? LOC::Coefficient_field::Z2 : LOC::Coefficient_field::Q;
    std::vector<std::pair<Facet, std::int64_t>> a, b;
    const auto report = CGAL::lex_optimal_chain_with_boundary(dt, cycle, std::back_inserter(a), LOC::parameters::coefficient_field(field));
    CGAL::lex_optimal_homologous_chain(dt, input, std::back_inserter(b), LOC::parameters::coefficient_field(field));
    Chain ca, cb;
    for(const auto& fk : a) add(ca, outward_triangle(fk.first), fk.second, z2);
    for(const auto& fk : b) add(cb, outward_triangle(fk.first), fk.second, z2);
    assert(ca == cb);
    assert(boundary(ca, z2) == boundary(source, z2));
    assert(report.number_of_facets == a.size());
  }
}

int main()
{
  CGAL::Random rng(11);
  test_augmented_union_find<LOC::internal::Z2_arithmetic>(rng);
  test_augmented_union_find<LOC::internal::Integer_arithmetic>(rng);
  test_representative_chain(rng);
  test_optimal_chain(rng);
  test_contraction_against_full_algorithm_10(rng);
  test_chain_with_boundary(rng);
  std::cout << "test_homologous_chain: OK\n";
  return 0;
}
