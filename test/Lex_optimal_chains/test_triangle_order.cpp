// The order of Lemma 4.14 against an exact oracle built from CGAL's exact kernel, on random
// triangles, constructed near-ties, exact ties and degenerate shapes; the certified bound of
// the fast key; and the sort of the dual graph of Delaunay triangulations with many ties.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Lex_optimal_chains_traits_3.h>
#include <CGAL/Lex_optimal_chains/internal/Largest_facets_3.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <iostream>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_3;
using Triangle = std::array<Point, 3>;
namespace LI = CGAL::Lex_optimal_chains::internal;

// ---- oracle: CGAL's exact kernel, with its own angle predicate and squared radius ------------
EK::Point_3 to_exact(const Point& p) { return EK::Point_3(p.x(), p.y(), p.z()); }

struct Exact_radii { EK::FT rb2, rc2; bool degenerate; };

Exact_radii oracle_radii(const Triangle& t)
{
  const EK::Point_3 p = to_exact(t[0]), q = to_exact(t[1]), r = to_exact(t[2]);
  Exact_radii res;
  res.degenerate = CGAL::collinear(p, q, r);
  res.rc2 = res.degenerate ? EK::FT(0) : CGAL::squared_radius(p, q, r);
  // an angle of the triangle is obtuse: the smallest enclosing ball has the opposite edge as diameter
  if(CGAL::angle(q, p, r) == CGAL::OBTUSE)      res.rb2 = CGAL::squared_distance(q, r) / 4;
  else if(CGAL::angle(p, q, r) == CGAL::OBTUSE) res.rb2 = CGAL::squared_distance(p, r) / 4;
  else if(CGAL::angle(p, r, q) == CGAL::OBTUSE) res.rb2 = CGAL::squared_distance(p, q) / 4;
  else res.rb2 = res.rc2;
  return res;
}

CGAL::Comparison_result oracle_compare(const Triangle& a, const Triangle& b)
{
  const Exact_radii x = oracle_radii(a), y = oracle_radii(b);
  if(x.rb2 != y.rb2) return x.rb2 < y.rb2 ? CGAL::SMALLER : CGAL::LARGER;
  if(x.degenerate != y.degenerate) return x.degenerate ? CGAL::SMALLER : CGAL::LARGER; // R_C infinite first
  if(!x.degenerate && x.rc2 != y.rc2) return x.rc2 > y.rc2 ? CGAL::SMALLER : CGAL::LARGER;
  // tie-break: sorted vertex triples, lexicographically
  std::array<std::array<double, 3>, 3> s, u;
  for(int i = 0; i < 3; ++i) {
    s[i] = {{a[i].x(), a[i].y(), a[i].z()}};
    u[i] = {{b[i].x(), b[i].y(), b[i].z()}};
  }
  std::sort(s.begin(), s.end());
  std::sort(u.begin(), u.end());
  return s < u ? CGAL::SMALLER : (u < s ? CGAL::LARGER : CGAL::EQUAL);
}

// ---- helpers ---------------------------------------------------------------------------------
CGAL::Random rng(12345);
Point random_point(double s = 1) { return Point(rng.get_double(-s, s), rng.get_double(-s, s), rng.get_double(-s, s)); }
Triangle random_triangle() { return Triangle{{random_point(), random_point(), random_point()}}; }

Point nudge(const Point& p, int ulps)
{
  double x = p.x();
  for(int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, ulps > 0 ? 2.0 : -2.0);
  return Point(x, p.y(), p.z());
}

const CGAL::Lex_optimal_chains_traits_3<K> traits;
const auto compare_order = traits.compare_triangle_order_3_object();

CGAL::Comparison_result ours(const Triangle& a, const Triangle& b)
{
  return compare_order(a[0], a[1], a[2], b[0], b[1], b[2]);
}

int checked = 0;
void check(const Triangle& a, const Triangle& b)
{
  const CGAL::Comparison_result expected = oracle_compare(a, b);
  const CGAL::Comparison_result got = ours(a, b);
  if(got != expected) {
    std::cerr << "MISMATCH\n" << a[0] << " | " << a[1] << " | " << a[2] << "\n"
              << b[0] << " | " << b[1] << " | " << b[2] << "\n got " << int(got) << " expected " << int(expected) << "\n";
  }
  assert(got == expected);
  // antisymmetry and invariance under the order of the vertices
  assert(ours(b, a) == -expected);
  assert(ours(Triangle{{a[2], a[0], a[1]}}, Triangle{{b[1], b[0], b[2]}}) == expected);
  ++checked;
}

void check_fast_key(const Triangle& t)
{
  LI::Triangle_coordinates_3 c;
  for(int i = 0; i < 3; ++i) c[i] = {{t[i].x(), t[i].y(), t[i].z()}};
  double rb2, err;
  if(!LI::approximate_squared_rb(c, 1.0 / (1ull << 36), rb2, err)) return;
  const EK::FT exact = oracle_radii(t).rb2;
  // |exact - rb2| <= err * rb2
  const EK::FT diff = exact - EK::FT(rb2);
  assert(CGAL::abs(diff) <= EK::FT(err) * EK::FT(rb2));
}

// ---- the largest facet of a cell (internal/Largest_facets_3.h) against the oracle ----------
struct Test_vertex { Point p; const Point& point() const { return p; } };
struct Test_cell
{
  std::array<Test_vertex, 4> v;
  const Test_vertex* vertex(int i) const { return &v[i]; }
};

int largest_checked = 0, largest_decided_from_lengths = 0;
void check_largest_facet(const std::array<Point, 4>& p)
{
  for(int i = 0; i < 4; ++i)
    for(int k = i + 1; k < 4; ++k)
      if(p[i] == p[k]) return;
  auto facet = [&](int j) { return Triangle{{p[(j + 1) & 3], p[(j + 2) & 3], p[(j + 3) & 3]}}; };
  int expected = 0;
  for(int j = 1; j < 4; ++j)
    if(oracle_compare(facet(j), facet(expected)) == CGAL::LARGER) expected = j;
  Test_cell c;
  for(int i = 0; i < 4; ++i) c.v[i].p = p[i];
  std::size_t exact = 0;
  // the facet-by-facet path alone (the fallback), the lengths-only path when it decides, and both
  LI::Cell_facets_3 facets(c);
  const int got = facets.largest(exact);
  LI::Coordinates_3 coordinates[4];
  for(int i = 0; i < 4; ++i) coordinates[i] = LI::Coordinates_3{{p[i].x(), p[i].y(), p[i].z()}};
  const int fast = LI::certified_largest_facet(coordinates);
  const int combined = LI::largest_facet(c, exact);
  if(got != expected || (fast >= 0 && fast != expected) || combined != expected)
    std::cerr << "LARGEST FACET MISMATCH " << p[0] << " | " << p[1] << " | " << p[2] << " | " << p[3] << ": got "
              << got << ", " << fast << ", " << combined << " expected " << expected << "\n";
  assert(got == expected);
  assert(fast < 0 || fast == expected);
  assert(combined == expected);
  ++largest_checked;
  if(fast >= 0) ++largest_decided_from_lengths;
}

// Cells whose largest facets are close or exactly tied, in every vertex order: obtuse pairs on
// a common longest edge (equal R_B, R_C decides), acute against obtuse on that edge, nearly
// right facets, grid cells, and the same cells scaled far up and down.
void check_largest_facets()
{
  auto all_orders = [](std::array<Point, 4> p) {
    std::sort(p.begin(), p.end());
    do check_largest_facet(p); while(std::next_permutation(p.begin(), p.end()));
  };
  // A cell met by a random campaign on a grid with shifts of 1e-13: two obtuse facets on the
  // same longest edge, one of them so flat (an edge of 2.5e-13) that |pq x pr|^2 from the
  // lengths comes out negative; the lengths-only path certified a wrong facet there before it
  // required a known, positive R_B. At several scales (powers of 2: the same cell, exactly).
  {
    // a NaN coordinate (rejected by the public functions) on any vertex leaves the cell
    // undecided. This guards the outcome only: it also holds without the range check of the
    // squared lengths (every comparison with a NaN length fails), so it does not test that check
    for(int k = 0; k < 4; ++k) {
      LI::Coordinates_3 c[4] = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
      c[k][k % 3] = std::numeric_limits<double>::quiet_NaN();
      assert(LI::certified_largest_facet(c) < 0);
    }
  }
  for(int e : {0, -30, 30, -200, 200}) {
    const double s = std::ldexp(1.0, e);
    all_orders({{Point(0, 0.25000000000025002 * s, 0.125 * s), Point(2.4999999999999999e-13 * s, 0.25000000000025002 * s, 0.125 * s),
                 Point(1.25e-13 * s, 0.25000000000012501 * s, 0), Point(0.12500000000024999 * s, 0.25000000000025002 * s, 0)}});
  }
  for(int i = 0; i < 200; ++i) {
    // far up and down, and so far down that products of squared lengths are subnormal
    const int far = i % 3 == 0 ? 262 : 200;
    const double scale = std::ldexp(1.0, i % 5 == 0 ? (i % 2 ? far : -far) : rng.get_int(-3, 4));
    const K::Vector_3 shift(rng.get_int(-5, 5), rng.get_int(-5, 5), rng.get_int(-5, 5));
    auto at = [&](double x, double y, double z) { return Point(x * scale, y * scale, z * scale) + shift * scale; };
    const double x = rng.get_double(0.2, 0.8), y = rng.get_double(-0.3, 0.3), z = rng.get_double(0.05, 0.45);
    const double h = rng.get_double(0.3, 0.7); // the second apex: obtuse below 0.5, acute above
    // mirror apexes (an exact tie of both radii), and one of them moved by a few ulps
    all_orders({{at(0, 0, 0), at(1, 0, 0), at(x, y, z), at(x, y, -z)}});
    all_orders({{at(0, 0, 0), at(1, 0, 0), at(x, y, z), nudge(at(x, y, -z), rng.get_int(-3, 4))}});
    // a second apex nearly at the same height: close R_C, same R_B
    all_orders({{at(0, 0, 0), at(1, 0, 0), at(x, y, z), at(x, -y, -z * (1 + rng.get_double(-1e-12, 1e-12)))}});
    // acute or obtuse second facet on the same longest edge, and a nearly right one
    all_orders({{at(0, 0, 0), at(1, 0, 0), at(x, y, z), at(0.5, 0, -h)}});
    all_orders({{at(0, 0, 0), at(1, 0, 0), at(x, y, z), nudge(at(0, 0, 0.5), rng.get_int(-2, 3))}});
    // flat cells: two obtuse facets on the common longest edge (the same R_B) with their apexes
    // at a height of 1e-5, whose circumradii differ by about 1e-7 relative: less than the error
    // of R_C evaluated from the edge lengths alone (a bound that is too tight fails here)
    const double flat = 1e-5 * z;
    all_orders({{at(0, 0, 0), at(1, 0, 0), at(x, y * flat, flat),
                 at(x * (1 + rng.get_double(-1e-7, 1e-7)), y * flat, -flat * (1 + rng.get_double(-1e-7, 1e-7)))}});
    // grid cells: ties of every kind
    auto g = [&]() { return at(rng.get_int(0, 3), rng.get_int(0, 3), rng.get_int(0, 3)); };
    std::array<Point, 4> q{{g(), g(), g(), g()}};
    if(!CGAL::coplanar(q[0], q[1], q[2], q[3])) all_orders(q);
    all_orders({{at(x, y, z), at(z, x, y), at(y, z, x), at(h, h, -h)}});
  }
}

int main()
{
  // 1. random triangles
  for(int i = 0; i < 2000; ++i) {
    const Triangle a = random_triangle(), b = random_triangle();
    check(a, b);
    check_fast_key(a);
  }

  // 2. obtuse triangles sharing their longest edge: equal R_B, order by R_C reversed
  for(int i = 0; i < 300; ++i) {
    const Point p = random_point(), q = random_point();
    const Point m = CGAL::midpoint(p, q);
    auto apex = [&]() { return m + (random_point(0.05) - CGAL::ORIGIN); };
    const Triangle a{{p, q, apex()}}, b{{q, apex(), p}};
    check(a, b);
    check_fast_key(a);
  }

  // 3. near ties: a triangle and its copy with one coordinate moved by a few ulps
  for(int i = 0; i < 300; ++i) {
    const Triangle a = random_triangle();
    for(int u : {-2, -1, 1, 2}) {
      const Triangle b{{nudge(a[0], u), a[1], a[2]}};
      check(a, b);
      check_fast_key(b);
    }
  }

  // 4. exact ties: co-spherical and congruent triangles on an integer grid (both radii equal)
  for(int i = 0; i < 300; ++i) {
    auto g = [&]() { return Point(rng.get_int(0, 4), rng.get_int(0, 4), rng.get_int(0, 4)); };
    Triangle a{{g(), g(), g()}}, b{{g(), g(), g()}};
    if(CGAL::collinear(a[0], a[1], a[2]) && a[0] != a[1] && a[1] != a[2] && a[0] != a[2]) {
      check(a, b); // degenerate but distinct points: infinite circumradius
      continue;
    }
    if(a[0] == a[1] || a[1] == a[2] || a[0] == a[2] || b[0] == b[1] || b[1] == b[2] || b[0] == b[2]) continue;
    if(CGAL::collinear(b[0], b[1], b[2])) continue;
    check(a, b);
    const K::Vector_3 shift(rng.get_int(-3, 3), rng.get_int(-3, 3), rng.get_int(-3, 3));
    check(a, Triangle{{a[0] + shift, a[1] + shift, a[2] + shift}}); // congruent: exact tie of both radii
  }

  // 5. right triangles and nearly right ones (the obtuse test is undecidable in double)
  for(int i = 0; i < 300; ++i) {
    const double x = rng.get_int(1, 100), y = rng.get_int(1, 100);
    const Triangle right{{Point(0, 0, 0), Point(x, 0, 0), Point(0, y, 0)}};
    const Triangle near{{Point(0, 0, 0), nudge(Point(x, 0, 0), rng.get_int(-2, 3)), Point(0, y, 0)}};
    const Triangle acute{{Point(0, 0, 0), Point(x, 0, 0), Point(x / 2, std::sqrt(x * x + y * y) / 2, 0)}};
    check(right, near);
    check(right, acute);
    check_fast_key(near);
  }

  // 6. needles and flat triangles
  for(int i = 0; i < 300; ++i) {
    const Point p = random_point(), q = random_point();
    const double t = rng.get_double(-0.5, 1.5);
    const Point on_line = p + t * (q - p);
    const Triangle flat{{p, q, nudge(on_line, rng.get_int(-3, 4))}};
    const Triangle needle{{p, nudge(p, 1 + rng.get_int(0, 3)), q}};
    check(flat, needle);
    check(flat, random_triangle());
    check_fast_key(flat);
    check_fast_key(needle);
  }
  std::cout << checked << " comparisons agree with the exact oracle\n";
  check_largest_facets();
  std::cout << largest_checked << " cells: the largest facet agrees with the exact oracle (" << largest_decided_from_lengths
            << " decided from the edge lengths)\n";

  // 7. the dual graph of Delaunay triangulations of grids (massive exact ties) is sorted exactly
  for(int trial = 0; trial < 3; ++trial) {
    std::vector<Point> pts;
    for(int x = 0; x < 7; ++x)
      for(int y = 0; y < 7; ++y)
        for(int z = 0; z < 4; ++z)
          if(trial == 0 || rng.get_double() < 0.7)
            pts.emplace_back(x * (trial == 2 ? 0.1 : 1.0), y * (trial == 2 ? 0.1 : 1.0), z * 0.7);
    CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
    LI::Sorted_dual_graph_3<CGAL::Delaunay_triangulation_3<K>> graph(dt, [](double) { return true; });
    const auto& rec = graph.records();
    assert(rec.size() == std::size_t(std::distance(dt.finite_facets_begin(), dt.finite_facets_end())));
    for(std::size_t i = 1; i < rec.size(); ++i) {
      const auto a = graph.coordinates(rec[i - 1]), b = graph.coordinates(rec[i]);
      assert(LI::compare_triangle_order(a, b) == CGAL::SMALLER);
    }
    std::cout << "grid " << trial << ": " << rec.size() << " triangles sorted, "
              << graph.number_of_records_in_runs() << " in close runs, " << graph.number_of_exactly_sorted_records() << " placed by the exact comparator\n";
  }

  // 8. the fast paths (keys, same-longest-edge runs ordered by q, runs in double) on a noisy
  //    sphere, where almost nothing reaches the exact comparator: every adjacent pair is checked
  {
    std::vector<Point> pts;
    while(pts.size() < 15000) {
      const K::Vector_3 v(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
      const double l = std::sqrt(v.squared_length());
      if(l > 1e-3 && l < 1) pts.push_back(CGAL::ORIGIN + v / l * (1 + rng.get_double(-0.003, 0.003)));
    }
    CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
    LI::Sorted_dual_graph_3<CGAL::Delaunay_triangulation_3<K>> graph(dt, [](double) { return true; });
    const auto& rec = graph.records();
    for(std::size_t i = 1; i < rec.size(); ++i)
      assert(LI::compare_triangle_order(graph.coordinates(rec[i - 1]), graph.coordinates(rec[i])) == CGAL::SMALLER);
    assert(graph.number_of_records_in_runs() > rec.size() / 10); // the runs were exercised
    const int checked_before = largest_checked, decided_before = largest_decided_from_lengths;
    for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      check_largest_facet({{c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point()}});
    // on sampled surfaces the lengths-only path decides nearly every cell (the others are slower)
    const int cells = largest_checked - checked_before, decided = largest_decided_from_lengths - decided_before;
    std::cout << "noisy sphere: " << decided << " of " << cells << " largest facets decided from the edge lengths\n";
    assert(decided >= cells - cells / 1000);
    std::cout << "noisy sphere: " << rec.size() << " triangles sorted, " << graph.number_of_records_in_runs()
              << " in close runs, " << graph.number_of_exactly_sorted_records() << " placed by the exact comparator\n";
  }
  return 0;
}
