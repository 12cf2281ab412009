// Partitions in line representation: the kinetic partition against its own rules checked by
// brute force with exact arithmetic, against CGAL's arrangement of full lines when segments
// may cross everything, builders from polygons and arrangements, cells, bad input.
#include <CGAL/Arr_non_caching_segment_basic_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_partition_simplification/IO/GeoJSON.h>
#include <CGAL/Polygon_partition_simplification/line_partition_from_geometry_2.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/simplify_polygon_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_partition_simplification/internal/Crossing_free_edges_2.h>
#include <CGAL/Polygon_partition_simplification/internal/remove_defective_edges_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Segment_grid_2.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
namespace PPS = CGAL::Polygon_partition_simplification;
using Partition = PPS::Line_partition_2<K>;


std::vector<K::Segment_2> random_segments(std::size_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 100), d(-8, 8);
  std::vector<K::Segment_2> s;
  while(s.size() < n) {
    const double x = u(rng), y = u(rng), dx = d(rng), dy = d(rng);
    if(dx == 0 && dy == 0) continue;
    s.emplace_back(K::Point_2(x, y), K::Point_2(x + dx, y + dy));
  }
  return s;
}

double total_area(const Partition& p)
{
  std::vector<Partition::Polygon_with_holes_2> cells;
  p.cells(std::back_inserter(cells));
  double area = 0;
  for(const auto& c : cells) {
    assert(c.outer_boundary().is_simple());
    area += CGAL::to_double(c.outer_boundary().area());
    for(auto h = c.holes_begin(); h != c.holes_end(); ++h) area += CGAL::to_double(h->area());
  }
  return area;
}

// Short segments in a few clusters, long ones across them, and axis-parallel ones on a
// lattice (collinear pieces, equal arrival times): the candidates of most rays come from far
// cells of the grid of the propagation, at all distances.
std::vector<K::Segment_2> mixed_segments(unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1), angle(0, 6.283185307179586);
  std::vector<K::Segment_2> s;
  for(int cluster = 0; cluster < 4; ++cluster) {
    const double cx = 100 * u(rng), cy = 100 * u(rng);
    for(int i = 0; i < 40; ++i) {
      const double x = cx + 6 * u(rng), y = cy + 6 * u(rng), a = angle(rng), l = 0.05 + 0.5 * u(rng);
      s.emplace_back(K::Point_2(x, y), K::Point_2(x + l * std::cos(a), y + l * std::sin(a)));
    }
  }
  while(s.size() < 168) { // long ones, inside [0, 100]^2 like the others
    const K::Point_2 p(100 * u(rng), 100 * u(rng)), q(100 * u(rng), 100 * u(rng));
    if(CGAL::squared_distance(p, q) > 60 * 60) s.emplace_back(p, q);
  }
  for(int i = 0; i < 5; ++i)
    for(int j = 0; j < 5; ++j) {
      s.emplace_back(K::Point_2(20 * i, 20 * j + 3), K::Point_2(20 * i + 2, 20 * j + 3));
      s.emplace_back(K::Point_2(20 * i + 10, 20 * j), K::Point_2(20 * i + 10, 20 * j + 1));
    }
  return s;
}

// Segments of 2 to 30 cm in a 3 m square at projected coordinates (x about 4e6, y about 5.2e6,
// as in UTM): the double computations must not lose the centimeters.
std::vector<K::Segment_2> projected_segments(unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<K::Segment_2> s;
  while(s.size() < 150) {
    const double x = 4e6 + 3 * u(rng), y = 5.2e6 + 3 * u(rng), a = 6.283185307179586 * u(rng), l = 0.02 + 0.28 * u(rng);
    const K::Point_2 p(x, y), q(x + l * std::cos(a), y + l * std::sin(a));
    if(p != q) s.emplace_back(p, q);
  }
  return s;
}

// crossing_distance: a growing end reaches the point I where the segment j that stops it and the
// line of a segment k far from I meet exactly. Its next intersection (the line of k, at I) is at
// distance 0, so it crosses j, however the double parameters of j and k at I round (found by
// search among configurations where they round in the order that once made it stop).
void test_crossing_distance_at_concurrent_lines()
{
  using KP = PPS::internal::Kinetic_propagation_2<EK>;
  auto parameter = [](double px, double py, double qx, double qy, double ox, double oy, double vx, double vy) {
    const double a = py - qy, b = qx - px, c = px * qy - py * qx;
    return -(a * ox + b * oy + c) / (a * vx + b * vy);
  };
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t found = 0;
  for(int attempt = 0; attempt < 100000 && found < 3; ++attempt) {
    const double ix = 0.3 + 0.4 * u(rng), iy = 0.3 + 0.4 * u(rng);
    const double ux = 0.125, uy = 0.03125 * (1 + int(u(rng) * 3));
    const double ax = ix - 2 * ux, ay = iy - 2 * uy, bx = ix - ux, by = iy - uy; // grows from b to I
    if(bx + (bx - ax) != ix || by + (by - ay) != iy) continue;
    const double jx = ix - 0.0625, jy = iy + 0.25;
    const double kdx = 0.03125 * (1 + int(u(rng) * 4)), kdy = 0.0625;
    const std::vector<EK::Segment_2> segments{
      EK::Segment_2(EK::Point_2(ax, ay), EK::Point_2(bx, by)), EK::Segment_2(EK::Point_2(ix, iy), EK::Point_2(jx, jy)),
      EK::Segment_2(EK::Point_2(ix + 3 * kdx, iy + 3 * kdy), EK::Point_2(ix + 4 * kdx, iy + 4 * kdy))};
    if(!EK::Line_2(segments[2].source(), segments[2].target()).has_on(EK::Point_2(ix, iy))) continue;
    const double tj = parameter(ix, iy, jx, jy, bx, by, bx - ax, by - ay);
    const double tk = parameter(ix + 3 * kdx, iy + 3 * kdy, ix + 4 * kdx, iy + 4 * kdy, bx, by, bx - ax, by - ay);
    if(!(tk < tj)) continue;
    ++found;
    const std::array<EK::Point_2, 4> box{EK::Point_2(-10, -10), EK::Point_2(10, -10), EK::Point_2(10, 10), EK::Point_2(-10, 10)};
    KP crossing(segments, box, 0, 0.5);
    crossing.run();
    assert(crossing.extent(0).target() != EK::Point_2(ix, iy)); // went on
    KP stopping(segments, box, 0, 0); // without the option it stops at I
    stopping.run();
    assert(stopping.extent(0).target() == EK::Point_2(ix, iy));
  }
  assert(found == 3);
}

// The rules of the kinetic framework, checked on the extents by brute force (exact), in a box
// around the segments.
void test_kinetic_rules(const std::vector<K::Segment_2>& input)
{
  std::vector<EK::Segment_2> segments;
  for(const auto& s : input)
    segments.emplace_back(EK::Point_2(s.source().x(), s.source().y()), EK::Point_2(s.target().x(), s.target().y()));
  const CGAL::Bbox_2 bbox = CGAL::bbox_2(input.begin(), input.end());
  const double margin = 0.2 * std::max(bbox.xmax() - bbox.xmin(), bbox.ymax() - bbox.ymin());
  const double x0 = bbox.xmin() - margin, x1 = bbox.xmax() + margin, y0 = bbox.ymin() - margin, y1 = bbox.ymax() + margin;
  const std::array<EK::Point_2, 4> box{EK::Point_2(x0, y0), EK::Point_2(x1, y0), EK::Point_2(x1, y1), EK::Point_2(x0, y1)};
  PPS::internal::Kinetic_propagation_2<EK> propagation(segments, box, 0, 0);
  propagation.run();
  std::vector<EK::Segment_2> extents;
  for(std::size_t i = 0; i < segments.size(); ++i) extents.push_back(propagation.extent(i));
  auto on_box = [&](const EK::Point_2& p) {
    for(int k = 0; k < 4; ++k)
      if(EK::Segment_2(box[k], box[(k + 1) % 4]).has_on(p)) return true;
    return false;
  };
  // arrival time of segment j at a point of its line: 0 on the segment, else the distance
  auto arrival2 = [&](std::size_t j, const EK::Point_2& p) {
    if(segments[j].has_on(p)) return EK::FT(0);
    return std::min(CGAL::squared_distance(p, segments[j].source()), CGAL::squared_distance(p, segments[j].target()));
  };
  for(std::size_t i = 0; i < segments.size(); ++i) {
    assert(extents[i].has_on(segments[i].source()) && extents[i].has_on(segments[i].target()));
    for(const EK::Point_2& end : {extents[i].source(), extents[i].target()}) {
      if(segments[i].has_on(end)) continue; // did not grow on this side
      if(on_box(end)) continue;
      // stopped by an extent that got there no later
      bool stopped = false;
      for(std::size_t j = 0; j < segments.size() && !stopped; ++j)
        if(j != i && extents[j].has_on(end) && arrival2(j, end) <= arrival2(i, end)) stopped = true;
      assert(stopped);
    }
    for(std::size_t j = i + 1; j < segments.size(); ++j) {
      const auto x = CGAL::intersection(extents[i], extents[j]);
      const EK::Point_2* p = PPS::internal::get_if<EK::Point_2>(x);
      if(!p) continue;
      const bool end_of_one = *p == extents[i].source() || *p == extents[i].target() ||
                              *p == extents[j].source() || *p == extents[j].target();
      // a proper crossing happens only where both initial segments already cross
      if(!end_of_one) assert(segments[i].has_on(*p) && segments[j].has_on(*p));
    }
  }
  // the same extents for the segments in another order
  std::vector<std::size_t> order(segments.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = order.size() - 1 - i;
  std::vector<EK::Segment_2> shuffled;
  for(std::size_t i : order) shuffled.push_back(segments[i]);
  PPS::internal::Kinetic_propagation_2<EK> again(shuffled, box, 0, 0);
  again.run();
  for(std::size_t k = 0; k < order.size(); ++k) {
    const EK::Segment_2 a = again.extent(k), b = extents[order[k]];
    assert((a.source() == b.source() && a.target() == b.target()) || (a.source() == b.target() && a.target() == b.source()));
  }
}

void test_simple_configurations()
{
  // one segment: the box cut in two
  {
    Partition p = CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {1, 0}}});
    assert(p.is_valid());
    assert(p.number_of_lines() == 5 && p.number_of_cells() == 2);
  }
  // a T: the short segment below stops at the long one
  {
    std::vector<K::Segment_2> s{{{0, 0}, {10, 0}}, {{5, -4}, {5, -1}}};
    Partition p = CGAL::kinetic_partition_2(s);
    assert(p.is_valid() && p.number_of_cells() == 3);
  }
  // the last to arrive stops: segment 0 grows right and reaches x = 3 at time 2, segment 1
  // grows up and gets there at time 0.5 first, so segment 0 stops and 1 goes on to the box
  {
    std::vector<K::Segment_2> s{{{0, 0}, {1, 0}}, {{3, -1}, {3, -0.5}}, {{-6, 6}, {12, 6}}};
    Partition p = CGAL::kinetic_partition_2(s);
    assert(p.is_valid());
    double rightmost = -1e9;
    for(std::size_t e = 0; e < p.number_of_edges(); ++e) {
      const auto seg = p.segment(e);
      if(std::abs(seg.source().y()) < 1e-9 && std::abs(seg.target().y()) < 1e-9)
        rightmost = std::max({rightmost, seg.source().x(), seg.target().x()});
    }
    assert(std::abs(rightmost - 3) < 1e-9);
  }
  // two crossing segments: four cells
  {
    std::vector<K::Segment_2> s{{{0, 0}, {2, 2}}, {{0, 2}, {2, 0}}};
    assert(CGAL::kinetic_partition_2(s).number_of_cells() == 4);
  }
  // the two pieces of one wall, collinear but for the roundings of their coordinates: the
  // smallest rectangle of their nearly flat hull has a first side that rounds to a point
  // (its axis was NaN: a crash in GMP)
  {
    std::vector<K::Segment_2> s{{{0.0, 0.0}, {3.464101615137755, 1.9999999999999998}},
                                {{5.196152422706632, 2.9999999999999996}, {8.660254037844387, 4.999999999999999}}};
    assert(CGAL::kinetic_partition_2(s).is_valid());
    s = {{{0, 0}, {1, 1}}, {{2, 2}, {3, 3.0000000000000004}}};
    assert(CGAL::kinetic_partition_2(s).is_valid());
  }
  // an X of the diagonals of a square: the lines pass through the corners of the box, which
  // are rounded, and a diagonal that misses its corner by 1e-16 ended at a point with the
  // corner's coordinates (the partition was invalid: two points coincided)
  for(const double side : {1., 2., 3., 7., 10., 13., 100., 1e-3, 12345.6789}) {
    std::vector<K::Segment_2> s{{{0, 0}, {side, side}}, {{0, side}, {side, 0}}};
    Partition p = CGAL::kinetic_partition_2(s);
    assert(p.is_valid() && p.number_of_cells() == 4);
    assert(CGAL::simplify_polygon_partition_2(p).cells_after == 4 && p.is_valid());
  }
  // Chains closed by ends that meet at time 0 and hang at a single point: the cell around them
  // was not a simple polygon (the partition was invalid); an end stopped at one of their
  // corners goes on and splits it. An "X" whose two lower ends are joined (a triangle hanging
  // at the crossing); a loop with a reflex corner, whose first candidate ray goes into the
  // loop; a chain whose corners are not at the ends of the defective edges (found by fuzzing);
  // two squares sharing a corner, alone in the rectangle (the first end joins them to the
  // rectangle, the second splits the cell: 4 cells).
  for(const std::vector<K::Segment_2>& s :
      {std::vector<K::Segment_2>{{{0, 0}, {3, 2}}, {{0, 2}, {3, 0}}, {{0, 0}, {3, 0}}},
       std::vector<K::Segment_2>{{{1, 1}, {0, 1}}, {{4, 0}, {0, 3}}, {{2, 3}, {1, 1}}, {{3, 3}, {4, 3}}, {{4, 0}, {0, 1}}},
       std::vector<K::Segment_2>{{{1, 2}, {3, 1}}, {{4, 3}, {3, 4}}, {{4, 0}, {3, 3}}, {{3, 0}, {1, 2}},
                                 {{3, 3}, {2, 1}}, {{4, 0}, {3, 2}}, {{0, 0}, {2, 3}}},
       std::vector<K::Segment_2>{{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 1}}, {{0, 1}, {0, 0}},
                                 {{1, 1}, {2, 1}}, {{2, 1}, {2, 2}}, {{2, 2}, {1, 2}}, {{1, 2}, {1, 1}}}}) {
    PPS::Kinetic_partition_report report;
    const Partition p = CGAL::kinetic_partition_2(s, PPS::parameters::report(&report));
    assert(p.is_valid() && report.extended_corner_ends >= 1);
    if(s.size() == 8) assert(report.extended_corner_ends == 2 && p.number_of_cells() == 4);
    // the same partition for the segments in another order, or reversed
    std::vector<K::Segment_2> other(s.rbegin(), s.rend());
    for(auto& x : other) x = x.opposite();
    const Partition q = CGAL::kinetic_partition_2(other);
    assert(q.is_valid() && q.number_of_lines() == p.number_of_lines() && q.number_of_vertices() == p.number_of_vertices() &&
          q.number_of_edges() == p.number_of_edges() && q.number_of_cells() == p.number_of_cells());
    // the corners stay: every endpoint shared by two segments is a point of the partition
    for(const auto& x : s)
      for(const auto& end : {x.source(), x.target()}) {
        if(std::count_if(s.begin(), s.end(), [&](const K::Segment_2& y) { return y.source() == end || y.target() == end; }) < 2)
          continue;
        bool found = false;
        for(std::size_t v = 0; v < p.number_of_vertices() && !found; ++v)
          found = CGAL::squared_distance(p.point(v), end) < 1e-20;
        assert(found);
      }
  }
  // a line that passes within rounding errors of a corner of the bounding rectangle (the
  // diagonal y = x of a rectangle centered on it): the rectangle was cut into an edge whose
  // ends rounded together, and the partition was not valid; the rectangle now keeps its
  // corners away from the lines
  {
    std::vector<K::Segment_2> s{{{1, 2}, {1, 4}}, {{0, 0}, {1, 1}}, {{0, 3}, {1, 2}}};
    const Partition p = CGAL::kinetic_partition_2(s);
    assert(p.is_valid() && p.number_of_cells() == 3);
  }
  // exactly collinear segments share one line
  {
    std::vector<K::Segment_2> s{{{0, 0}, {1, 1}}, {{3, 3}, {4, 4}}, {{0, 4}, {1, 4}}};
    Partition p = CGAL::kinetic_partition_2(s);
    assert(p.is_valid() && p.number_of_lines() == 4 + 2);
  }
}

// With unlimited crossings every segment reaches the box: the partition is the arrangement
// of the full lines clipped to the box, computed independently by CGAL.
void test_against_line_arrangement()
{
  const auto s = random_segments(25, 7);
  Partition p = CGAL::kinetic_partition_2(s, PPS::parameters::maximum_number_of_crossings(std::size_t(1000)));
  assert(p.is_valid());
  // the box of the partition: its four fixed lines
  std::vector<EK::Segment_2> curves;
  std::vector<EK::Point_2> corners;
  for(std::size_t e = 0; e < p.number_of_edges(); ++e)
    if(p.lines()[p.edges()[e].line].is_fixed) {
      const auto seg = p.segment(e);
      curves.emplace_back(EK::Point_2(seg.source().x(), seg.source().y()), EK::Point_2(seg.target().x(), seg.target().y()));
    }
  CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>> box_arrangement;
  CGAL::insert(box_arrangement, curves.begin(), curves.end());
  // clip each full line to the box (the box is convex)
  std::vector<EK::Segment_2> all = curves;
  for(const auto& seg : s) {
    const EK::Line_2 line(EK::Point_2(seg.source().x(), seg.source().y()), EK::Point_2(seg.target().x(), seg.target().y()));
    std::vector<EK::Point_2> hits;
    for(const auto& c : curves) {
      const auto x = CGAL::intersection(line, c);
      if(const EK::Point_2* q = PPS::internal::get_if<EK::Point_2>(x)) hits.push_back(*q);
    }
    std::sort(hits.begin(), hits.end());
    all.emplace_back(hits.front(), hits.back());
  }
  CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>> oracle;
  CGAL::insert(oracle, all.begin(), all.end());
  assert(p.number_of_cells() == oracle.number_of_faces() - 1);
  // kinetic partitions without crossings have fewer cells
  assert(CGAL::kinetic_partition_2(s).number_of_cells() < p.number_of_cells());
  // one crossing allowed: in between
  const std::size_t one = CGAL::kinetic_partition_2(s, PPS::parameters::maximum_number_of_crossings(std::size_t(1))).number_of_cells();
  assert(one >= CGAL::kinetic_partition_2(s).number_of_cells() && one <= p.number_of_cells());
  // the crossing distance makes more connections
  assert(CGAL::kinetic_partition_2(s, PPS::parameters::crossing_distance(5.)).number_of_cells() >=
        CGAL::kinetic_partition_2(s).number_of_cells());
}

// Cells tile the bounding rectangle; the partition follows rigid motions and scalings.
void test_cells_and_invariance()
{
  const auto s = random_segments(60, 3);
  Partition p = CGAL::kinetic_partition_2(s);
  assert(p.is_valid());
  // the area of the rectangle = the sum of the cell areas
  double box_area = 0;
  {
    std::vector<K::Point_2> corners;
    for(const auto& v : p.vertices()) {
      std::size_t fixed = 0;
      for(auto l : v.lines) fixed += p.lines()[l].is_fixed ? 1 : 0;
      if(fixed == 2) corners.push_back(p.point(std::size_t(&v - p.vertices().data())));
    }
    assert(corners.size() == 4);
    std::vector<K::Point_2> hull;
    CGAL::convex_hull_2(corners.begin(), corners.end(), std::back_inserter(hull));
    box_area = CGAL::to_double(CGAL::Polygon_2<K>(hull.begin(), hull.end()).area());
  }
  assert(std::abs(total_area(p) - box_area) < 1e-6 * box_area);
  // exact transformations: rotation by 90 degrees, integer translation, scaling by 4
  std::vector<K::Segment_2> moved;
  for(const auto& seg : s) {
    auto f = [](const K::Point_2& q) { return K::Point_2(-4 * q.y() + 1024, 4 * q.x() - 512); };
    moved.emplace_back(f(seg.source()), f(seg.target()));
  }
  Partition q = CGAL::kinetic_partition_2(moved);
  assert(q.number_of_lines() == p.number_of_lines() && q.number_of_vertices() == p.number_of_vertices() &&
        q.number_of_edges() == p.number_of_edges() && q.number_of_cells() == p.number_of_cells());
}

void test_builders()
{
  // two squares sharing an edge: 5 lines (collinear edges share one), 6 points, 7 edges, 2 cells
  std::vector<CGAL::Polygon_2<K>> squares(2);
  for(double x : {0., 1.}) {
    auto& sq = squares[std::size_t(x)];
    sq.push_back(K::Point_2(x, 0)); sq.push_back(K::Point_2(x + 1, 0));
    sq.push_back(K::Point_2(x + 1, 1)); sq.push_back(K::Point_2(x, 1));
  }
  Partition p = PPS::line_partition_from_polygons_2(squares);
  assert(p.is_valid());
  assert(p.number_of_lines() == 5 && p.number_of_vertices() == 6 && p.number_of_edges() == 7 && p.number_of_cells() == 2);
  // cells that touch at a corner (parcels of a cadastral map): only the unbounded face is
  // pinched, the partition is valid and can be simplified
  auto square_at = [](double x, double y, double size) {
    CGAL::Polygon_2<K> sq;
    for(const auto& [dx, dy] : {std::pair(0., 0.), std::pair(1., 0.), std::pair(1., 1.), std::pair(0., 1.)})
      sq.push_back(K::Point_2(x + size * dx, y + size * dy));
    return sq;
  };
  {
    Partition corner = PPS::line_partition_from_polygons_2(std::vector<CGAL::Polygon_2<K>>{square_at(0, 0, 1), square_at(1, 1, 1)});
    assert(corner.is_valid() && corner.number_of_cells() == 2);
    CGAL::simplify_polygon_partition_2(corner);
    assert(corner.is_valid() && corner.number_of_cells() == 2);
    // the same two squares inside a larger one: the cell around them has a pinched hole
    const Partition inside = PPS::line_partition_from_polygons_2(
      std::vector<CGAL::Polygon_2<K>>{square_at(-1, -1, 4), square_at(0, 0, 1), square_at(1, 1, 1)});
    assert(!inside.is_valid());
    // a diamond touching the side of a square from inside: the cell around it is pinched
    CGAL::Polygon_2<K> diamond;
    for(const auto& [x, y] : {std::pair(2., 0.), std::pair(3., 1.), std::pair(2., 2.), std::pair(1., 1.)}) diamond.push_back(K::Point_2(x, y));
    const Partition touching = PPS::line_partition_from_polygons_2(std::vector<CGAL::Polygon_2<K>>{square_at(0, 0, 4), diamond});
    assert(!touching.is_valid());
    // in a kinetic partition the contact point lies inside the rectangle: the cell around the
    // two squares would have a pinched hole
    auto walls = [](double gap) {
      std::vector<K::Segment_2> s;
      for(double o : {0., 1. + gap}) {
        const K::Point_2 a(o, o), b(o + 1, o), c(o + 1, o + 1), d(o, o + 1);
        s.insert(s.end(), {K::Segment_2(a, b), K::Segment_2(b, c), K::Segment_2(c, d), K::Segment_2(d, a)});
      }
      return s;
    };
    // (it was not valid; an end stopped at one of the corners now goes on and splits that cell)
    assert(CGAL::kinetic_partition_2(walls(0)).is_valid() && CGAL::kinetic_partition_2(walls(0.01)).is_valid());
  }
  // a polygon with a hole (a courtyard): 8 lines, 8 points, 8 edges, 2 cells (the ring and the yard)
  CGAL::Polygon_2<K> outer, yard;
  for(const auto& [x, y] : {std::pair(0., 0.), std::pair(4., 0.), std::pair(4., 4.), std::pair(0., 4.)}) outer.push_back(K::Point_2(x, y));
  for(const auto& [x, y] : {std::pair(1., 1.), std::pair(1., 3.), std::pair(3., 3.), std::pair(3., 1.)}) yard.push_back(K::Point_2(x, y));
  std::vector<CGAL::Polygon_with_holes_2<K>> courtyard{CGAL::Polygon_with_holes_2<K>(outer, &yard, &yard + 1)};
  Partition h = PPS::line_partition_from_polygons_2(courtyard);
  assert(h.is_valid());
  assert(h.number_of_lines() == 8 && h.number_of_vertices() == 8 && h.number_of_edges() == 8 && h.number_of_cells() == 2);
  // the same from a CGAL arrangement, with a dangling edge that is dropped
  CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>> arrangement;
  std::vector<EK::Segment_2> segments{{EK::Point_2(0, 0), EK::Point_2(2, 0)}, {EK::Point_2(2, 0), EK::Point_2(2, 1)},
                                      {EK::Point_2(2, 1), EK::Point_2(0, 1)}, {EK::Point_2(0, 1), EK::Point_2(0, 0)},
                                      {EK::Point_2(1, 0), EK::Point_2(1, 1)}, {EK::Point_2(2, 1), EK::Point_2(3, 2)}};
  CGAL::insert(arrangement, segments.begin(), segments.end());
  Partition a = PPS::line_partition_from_arrangement_2<K>(arrangement);
  assert(a.is_valid() && a.number_of_lines() == 5 && a.number_of_edges() == 7 && a.number_of_cells() == 2);
  // GeoJSON: one feature per cell, closed rings
  std::vector<Partition::Polygon_with_holes_2> cells;
  a.cells(std::back_inserter(cells));
  std::ostringstream os;
  assert(PPS::IO::write_GeoJSON(os, cells));
  const std::string text = os.str();
  std::size_t features = 0;
  for(std::size_t at = text.find("\"Feature\""); at != std::string::npos; at = text.find("\"Feature\"", at + 1)) ++features;
  assert(features == 2);
}

template <class F>
void expect_error(PPS::Input_error_code code, F f)
{
  try { f(); } catch(const PPS::Input_error& e) { assert(e.code() == code); return; }
  assert(!"no error");
}

void test_bad_input()
{
  // a nearly horizontal segment (a rise of the smallest subnormal): the equation of its line
  // divided by its x coefficient overflowed the doubles, and converting that back to an exact
  // number crashed (SIGFPE in GMP); lines are now divided by their larger coefficient
  {
    const std::vector<K::Segment_2> s{{K::Point_2(0, 0), K::Point_2(1, 4.9406564584124654e-324)},
                                      {K::Point_2(0, 1), K::Point_2(1, 2)},
                                      {K::Point_2(0.5, -1), K::Point_2(0.6, 3)}};
    const Partition p = CGAL::kinetic_partition_2(s);
    assert(p.is_valid() && p.number_of_lines() == 7);
    for(const auto& l : p.lines()) assert(std::isfinite(l.coefficients[0]) && std::isfinite(l.coefficients[1]) && std::isfinite(l.coefficients[2]));
  }
  using C = PPS::Input_error_code;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_error(C::EMPTY_INPUT, [] { CGAL::kinetic_partition_2(std::vector<K::Segment_2>{}); });
  expect_error(C::NON_FINITE_COORDINATE, [&] { CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {nan, 1}}}); });
  expect_error(C::ZERO_LENGTH_SEGMENT, [] { CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {1, 1}}, {{2, 2}, {2, 2}}}); });
  { // a segment given twice is merged: the partition of the segment alone
    const Partition twice = CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {1, 1}}, {{1, 1}, {0, 0}}});
    const Partition once = CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {1, 1}}});
    assert(twice.is_valid() && twice.number_of_cells() == 2 && twice.number_of_edges() == once.number_of_edges());
  }
  expect_error(C::INVALID_PARAMETER, [] {
    CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {1, 1}}}, PPS::parameters::crossing_distance(-1.));
  });
  expect_error(C::INVALID_PARAMETER, [] {
    CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {1, 1}}}, PPS::parameters::bounding_box_margin(1e-300));
  });
  // coordinates at the ends of the double range
  expect_error(C::NON_FINITE_COORDINATE, [] { CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {1e300, 1}}}); });
  expect_error(C::ZERO_LENGTH_SEGMENT, [] { CGAL::kinetic_partition_2(std::vector<K::Segment_2>{{{0, 0}, {1e-300, 0}}}); });
  expect_error(C::EMPTY_INPUT, [] { PPS::line_partition_from_polygons_2(std::vector<CGAL::Polygon_2<K>>{}); });
  expect_error(C::NO_CELL, [] {
    std::vector<CGAL::Polygon_2<K>> flat(1);
    flat[0].push_back(K::Point_2(0, 0)); flat[0].push_back(K::Point_2(1, 0));
    PPS::line_partition_from_polygons_2(flat);
  });
  // huge coordinates are refused by every builder (the kinetic partition refuses them too)
  expect_error(C::NON_FINITE_COORDINATE, [] {
    std::vector<CGAL::Polygon_2<K>> huge(1);
    for(const auto& [x, y] : {std::pair(0., 0.), std::pair(1e120, 0.), std::pair(1e120, 1e120)}) huge[0].push_back(K::Point_2(x, y));
    PPS::line_partition_from_polygons_2(huge);
  });
  // C arrays are ranges too
  const K::Segment_2 walls[4] = {{{0, 0}, {2, 0}}, {{2, 0}, {2, 1}}, {{2, 1}, {0, 1}}, {{0, 1}, {0, 0}}};
  assert(CGAL::kinetic_partition_2(walls).number_of_cells() >= 1);
  CGAL::Polygon_2<K> squares[2];
  for(double x : {0., 1.})
    for(const auto& [dx, dy] : {std::pair(0., 0.), std::pair(1., 0.), std::pair(1., 1.), std::pair(0., 1.)})
      squares[std::size_t(x)].push_back(K::Point_2(x + dx, dy));
  assert(PPS::line_partition_from_polygons_2(squares).number_of_cells() == 2);
}

// The validity check on hand-made partitions of the unit square (lines x = 0, x = 1, y = 0,
// y = 1, x = 0.5, y = 0.5), whose defects are known.
void test_validity_check()
{
  using Line = Partition::Line;
  auto line = [](double a, double b, double c) { Line l; l.coefficients = {{a, b, c}}; return l; };
  const std::vector<Line> lines{line(1, 0, 0), line(1, 0, -1), line(0, 1, 0), line(0, 1, -1),
                                line(1, 0, -0.5), line(0, 1, -0.5)};
  // points 0-3 the corners, 4 and 5 on the bottom and top sides, 6 and 7 on the left and right
  // sides, 8 the center
  std::vector<Partition::Vertex> points{{{0, 2}}, {{1, 2}}, {{1, 3}}, {{0, 3}}, {{2, 4}}, {{3, 4}},
                                        {{0, 5}}, {{1, 5}}, {{4, 5}}};
  const std::vector<Partition::Edge> sides{{2, 0, 4}, {2, 4, 1}, {1, 1, 7}, {1, 7, 2},
                                           {3, 2, 5}, {3, 5, 3}, {0, 3, 6}, {0, 6, 0}};
  auto with = [&](std::vector<Partition::Edge> extra) {
    std::vector<Partition::Edge> edges = sides;
    edges.insert(edges.end(), extra.begin(), extra.end());
    return Partition(Partition::Frame(), lines, points, edges);
  };
  // valid: the square cut in four by the two middle lines
  {
    const Partition p = with({{4, 4, 8}, {4, 8, 5}, {5, 6, 8}, {5, 8, 7}});
    assert(p.defect().empty() && p.defective_edges().empty() && p.number_of_cells() == 4);
    std::vector<Partition::Polygon_with_holes_2> cells;
    p.cells(std::back_inserter(cells));
    assert(cells.size() == 4);
    for(const auto& c : cells) assert(std::abs(c.outer_boundary().area() - 0.25) < 1e-12);
  }
  // the middle edges cross without a point at the center
  {
    const Partition p = with({{4, 4, 5}, {5, 6, 7}});
    assert(p.defect().find("cross") != std::string::npos);
    assert(p.defective_edges() == std::vector<std::size_t>({8, 9}));
    assert(p.number_of_cells() == 4); // counted on the arrangement, which adds the crossing
  }
  auto reported = [](const Partition& p, std::size_t e) {
    const std::vector<std::size_t> d = p.defective_edges();
    return std::find(d.begin(), d.end(), e) != d.end();
  };
  // an edge dangles into the square (its cell's boundary also passes twice through its foot)
  {
    const Partition p = with({{4, 4, 8}});
    assert(p.defect().find("dangles") != std::string::npos);
    assert(reported(p, 8));
    assert(p.number_of_cells() == 1);
  }
  // the vertical middle line cuts the square in two, the left half of the horizontal one cuts
  // the left half in two: valid, three cells
  {
    const Partition p = with({{4, 4, 8}, {4, 8, 5}, {5, 6, 8}});
    assert(p.is_valid() && p.number_of_cells() == 3);
  }
  // the right half of the horizontal middle line, from the right side, without the vertical
  // line: it dangles
  {
    const Partition p = with({{4, 4, 8}, {4, 8, 5}, {5, 8, 7}, {5, 6, 8}});
    assert(p.is_valid() && p.number_of_cells() == 4);
    const Partition q = with({{5, 8, 7}});
    assert(q.defect().find("dangles") != std::string::npos && reported(q, 8) && q.number_of_cells() == 1);
  }
  // a point at infinity: the two vertical sides "meet"
  {
    points.push_back({{0, 1}});
    const Partition p = with({{0, 3, 9}});
    points.pop_back();
    assert(p.defect().find("infinity") != std::string::npos);
    assert(p.defective_edges() == std::vector<std::size_t>({8}));
    assert(p.number_of_cells() == 1); // the edge to infinity bounds nothing
    assert(p.exact_arrangement().number_of_edges() == 8);
  }
  // an edge off its line
  {
    const Partition p = with({{5, 4, 8}});
    assert(p.defect().find("off its line") != std::string::npos);
  }
  // With the sides fixed (a kinetic partition), the cells must tile the square. The line
  // x = -0.5 with its points on the bottom and top sides extended past the corners 0 and 3:
  // a plane graph with two cells, the square and a strip outside it, whose edge on x = -0.5
  // bounds the unbounded face. Valid without fixed lines, not with them.
  {
    std::vector<Line> fixed_lines = lines;
    fixed_lines[4] = line(1, 0, 0.5);
    const std::vector<Partition::Vertex> corners_and_two{{{0, 2}}, {{1, 2}}, {{1, 3}}, {{0, 3}}, {{2, 4}}, {{3, 4}}};
    const std::vector<Partition::Edge> edges{{2, 4, 0}, {2, 0, 1}, {1, 1, 2}, {3, 2, 3}, {3, 3, 5}, {0, 3, 0}, {4, 4, 5}};
    const Partition free_sides(Partition::Frame(), fixed_lines, corners_and_two, edges);
    assert(free_sides.is_valid() && free_sides.number_of_cells() == 2);
    for(int side = 0; side < 4; ++side) fixed_lines[side].is_fixed = true;
    const Partition p(Partition::Frame(), fixed_lines, corners_and_two, edges);
    assert(p.defect().find("tile") != std::string::npos);
    assert(p.defective_edges() == std::vector<std::size_t>({6}));
    // the valid partition in four with fixed sides stays valid
    std::vector<Partition::Edge> four = sides;
    for(const Partition::Edge& e : std::vector<Partition::Edge>{{4, 4, 8}, {4, 8, 5}, {5, 6, 8}, {5, 8, 7}}) four.push_back(e);
    std::vector<Line> fixed_square = lines;
    for(int side = 0; side < 4; ++side) fixed_square[side].is_fixed = true;
    assert(Partition(Partition::Frame(), fixed_square, points, four).is_valid());
  }
  // The square with fixed sides cut by x = 0.5 and a square ring of side 0.2 centered at
  // (cx, 0.5): in the left cell it is valid (a cell with a hole), outside the square it is
  // not. Whether a part lies in a cell of another is decided by the parity of the crossings of
  // a ray with the outer boundary of that part only: with all its edges, the middle edge
  // made the ring in the left cell "outside" and the ring outside "inside".
  {
    std::vector<Line> ring_lines = lines;
    for(int side = 0; side < 4; ++side) ring_lines[side].is_fixed = true;
    const std::vector<Partition::Edge> cut_square{{2, 0, 4}, {2, 4, 1}, {1, 1, 2}, {3, 2, 5}, {3, 5, 3}, {0, 3, 0}, {4, 4, 5}};
    for(const double cx : {0.2, -0.5}) {
      std::vector<Line> l = ring_lines;
      const std::size_t first_line = l.size();
      l.push_back(line(1, 0, -(cx - 0.1)));
      l.push_back(line(1, 0, -(cx + 0.1)));
      l.push_back(line(0, 1, -0.4));
      l.push_back(line(0, 1, -0.6));
      const std::size_t x0 = first_line, x1 = first_line + 1, y0 = first_line + 2, y1 = first_line + 3;
      const std::vector<Partition::Vertex> pts{{{0, 2}}, {{1, 2}}, {{1, 3}}, {{0, 3}}, {{2, 4}}, {{3, 4}},
                                               {{x0, y0}}, {{x1, y0}}, {{x1, y1}}, {{x0, y1}}};
      std::vector<Partition::Edge> e = cut_square;
      for(const Partition::Edge& r : std::vector<Partition::Edge>{{y0, 6, 7}, {x1, 7, 8}, {y1, 8, 9}, {x0, 9, 6}}) e.push_back(r);
      const Partition p(Partition::Frame(), l, pts, e);
      if(cx > 0) assert(p.is_valid() && p.number_of_cells() == 3);
      else assert(p.defect().find("tile") != std::string::npos &&
                 p.defective_edges() == std::vector<std::size_t>({7, 8, 9, 10}));
    }
  }
}

// The last step of the rounding, on the square of test_validity_check() (its sides fixed, as the
// sides of a kinetic partition's rectangle): what a defect leaves, and the cells after.
void test_removal_of_defective_edges()
{
  using Line = Partition::Line;
  auto line = [](double a, double b, double c, bool fixed) {
    Line l;
    l.coefficients = {{a, b, c}};
    l.is_fixed = fixed;
    return l;
  };
  const std::vector<Line> lines{line(1, 0, 0, true),    line(1, 0, -1, true),   line(0, 1, 0, true),
                                line(0, 1, -1, true),   line(1, 0, -0.5, false), line(0, 1, -0.5, false),
                                line(1, 0, -0.5, false)}; // the last one: the vertical middle line again
  const std::vector<Partition::Vertex> points{{{0, 2}}, {{1, 2}}, {{1, 3}}, {{0, 3}}, {{2, 4, 6}}, {{3, 4, 6}},
                                              {{0, 5}}, {{1, 5}}, {{4, 5}}};
  const std::vector<Partition::Edge> sides{{0, 0, 6}, {0, 3, 6}, {1, 1, 7}, {1, 2, 7},
                                           {2, 0, 4}, {2, 1, 4}, {3, 2, 5}, {3, 3, 5}};
  // the square with `extra` edges (and `more_points` after its points), repaired; `defect`: a
  // part of what is wrong before
  auto repaired = [&](std::vector<Partition::Edge> extra, std::size_t& removed,
                      const std::vector<Partition::Vertex>& more_points = {}, const std::string& defect = "") {
    std::vector<Partition::Edge> edges = sides;
    edges.insert(edges.end(), extra.begin(), extra.end());
    std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) {
      return std::tie(x.line, x.source, x.target) < std::tie(y.line, y.source, y.target);
    });
    std::vector<Partition::Vertex> vertices = points;
    vertices.insert(vertices.end(), more_points.begin(), more_points.end());
    assert(Partition(Partition::Frame(), lines, vertices, edges).defect().find(defect) != std::string::npos);
    assert(!Partition(Partition::Frame(), lines, vertices, edges).is_valid());
    removed = PPS::internal::remove_defective_edges<Partition::Geom_traits>(lines, vertices, edges);
    return Partition(Partition::Frame(), lines, vertices, edges);
  };
  auto cell_areas = [](const Partition& p) {
    std::vector<Partition::Polygon_with_holes_2> cells;
    p.cells(std::back_inserter(cells));
    std::vector<double> areas;
    for(const auto& c : cells) areas.push_back(c.outer_boundary().area());
    std::sort(areas.begin(), areas.end());
    return areas;
  };
  std::size_t removed = 0;
  // the middle edges cross without a point at the center: one goes (the first by its line, as
  // they are as long), the points it leaves on the bottom and top sides are joined away
  {
    const Partition p = repaired({{4, 4, 5}, {5, 6, 7}}, removed, {}, "cross");
    assert(removed == 1 && p.is_valid());
    assert(p.number_of_edges() == 7 && p.number_of_vertices() == 6);
    for(const auto& e : p.edges()) assert(e.line != 4 && e.line != 6);
    assert(cell_areas(p) == std::vector<double>({0.5, 0.5}));
  }
  // an edge dangles into the square: removed (and counted), the sides joined
  {
    const Partition p = repaired({{4, 4, 8}}, removed, {}, "dangles");
    assert(removed == 1 && p.is_valid() && p.number_of_edges() == 4 && p.number_of_cells() == 1);
  }
  // the vertical middle line twice, its two edges between the same two points: one is left
  {
    const Partition p = repaired({{4, 4, 5}, {6, 4, 5}}, removed, {}, "overlap");
    assert(removed == 1 && p.is_valid() && p.number_of_edges() == 7); // the sides joined at 6 and 7
    assert(cell_areas(p) == std::vector<double>({0.5, 0.5}));
  }
  // the cross of the two middle lines, its center given twice (two points that coincide), each
  // copy with one half of each line: the first edge at the center goes, then the edge of the
  // other line left dangling at its copy, and the other copy's two edges cut a quarter off
  {
    const Partition p = repaired({{4, 4, 8}, {5, 6, 8}, {4, 5, 9}, {5, 7, 9}}, removed,
                                 {{{4, 5}}}, // point 9, the center as point 8
                                 "coincide");
    assert(removed == 2 && p.is_valid() && p.number_of_edges() == 8); // one for the defect, one dangling
    assert(cell_areas(p) == std::vector<double>({0.25, 0.75}));
  }
}

// The face part of the validity check (facial walks of the rotation system) against the
// faces of CGAL's arrangement of the edges, on kinetic partitions with random edges removed
// (which leaves dangling edges, bridges and pinched cell boundaries): same verdict, same
// edges reported.
void test_faces_against_arrangement()
{
  using Arrangement = CGAL::Arrangement_2<CGAL::Arr_non_caching_segment_basic_traits_2<K>>;
  std::size_t invalid = 0, total = 0, opened = 0;
  for(unsigned seed = 1; seed <= 40; ++seed) {
    const Partition full = CGAL::kinetic_partition_2(random_segments(12 + seed % 20, seed));
    std::mt19937 rng(seed);
    std::vector<Partition::Edge> edges = full.edges();
    const std::size_t removed = 1 + seed % 4;
    for(std::size_t k = 0; k < removed && edges.size() > 1; ++k)
      edges.erase(edges.begin() + std::uniform_int_distribution<std::size_t>(0, edges.size() - 1)(rng));
    const Partition p(full.frame(), full.lines(), full.vertices(), edges);
    // the oracle
    std::vector<std::array<double, 2>> points(p.number_of_vertices());
    for(std::size_t v = 0; v < points.size(); ++v) points[v] = p.normalized_point(v);
    std::map<std::pair<std::array<double, 2>, std::array<double, 2>>, std::size_t> edge_of;
    std::vector<K::Segment_2> segments;
    for(std::size_t e = 0; e < edges.size(); ++e) {
      const auto& a = points[edges[e].source];
      const auto& b = points[edges[e].target];
      edge_of[std::minmax(a, b)] = e;
      segments.emplace_back(K::Point_2(a[0], a[1]), K::Point_2(b[0], b[1]));
    }
    Arrangement arrangement;
    CGAL::insert_non_intersecting_curves(arrangement, segments.begin(), segments.end());
    assert(arrangement.number_of_edges() == edges.size()); // no crossing: one arrangement edge per edge
    auto edge_at = [&](Arrangement::Halfedge_const_handle h) {
      const std::array<double, 2> a{{h->source()->point().x(), h->source()->point().y()}};
      const std::array<double, 2> b{{h->target()->point().x(), h->target()->point().y()}};
      return edge_of.at(std::minmax(a, b));
    };
    std::vector<std::size_t> expected;
    for(auto h = arrangement.halfedges_begin(); h != arrangement.halfedges_end(); ++h)
      if(h->face() == h->twin()->face()) expected.push_back(edge_at(h));
    for(auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
      if(f->is_unbounded()) { // pinched there, the boundary of no cell: cells touching at a corner
        // but only the sides of the rectangle may bound it
        for(auto c = f->holes_begin(); c != f->holes_end(); ++c) {
          auto h = *c;
          do {
            const std::size_t e = edge_at(h);
            if(!p.lines()[edges[e].line].is_fixed) expected.push_back(e);
            h = h->next();
          } while(h != *c);
        }
        continue;
      }
      std::vector<Arrangement::Halfedge_const_handle> ccbs;
      ccbs.push_back(f->outer_ccb());
      for(auto h = f->holes_begin(); h != f->holes_end(); ++h) ccbs.push_back(*h);
      for(auto start : ccbs) {
        std::map<Arrangement::Vertex_const_handle, Arrangement::Halfedge_const_handle> arrival;
        auto h = start;
        do {
          auto [it, first_time] = arrival.emplace(h->target(), h);
          if(!first_time)
            for(auto in : {it->second, Arrangement::Halfedge_const_handle(h)}) {
              expected.push_back(edge_at(in));
              expected.push_back(edge_at(in->next()));
            }
          h = h->next();
        } while(h != start);
      }
    }
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    assert(p.defective_edges() == expected);
    assert(p.is_valid() == expected.empty());
    invalid += expected.empty() ? 0 : 1;
    opened += p.defect().find("tile") != std::string::npos ? 1 : 0; // a side removed
    ++total;
  }
  std::cout << "faces against the arrangement: " << invalid << " invalid of " << total << ", " << opened
            << " with the rectangle opened" << std::endl;
  assert(invalid >= total / 4 && invalid < total && opened > 0); // every verdict was exercised
}

// The grid used by the kinetic propagation and the validity check lists every segment in the
// cell of each of its points (checked on points sampled along random segments, short and long,
// axis-parallel and not, nearly horizontal across row boundaries, in a grid whose cells are
// much smaller than the long ones).
void test_segment_grid()
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-50, 50), v(-1, 1);
  std::vector<std::array<double, 4>> segments;
  for(int i = 0; i < 300; ++i) {
    const double x = u(rng), y = u(rng);
    const double scale = i % 10 == 0 ? 60 : 1;
    std::array<double, 4> s{{x, y, x + scale * v(rng), y + scale * v(rng)}};
    if(i % 7 == 0) s[3] = s[1]; // horizontal
    if(i % 11 == 0) s[2] = s[0]; // vertical
    for(double& c : s) c = std::clamp(c, -100., 100.);
    segments.push_back(s);
  }
  // and segments rising by a few units in the last place across row boundaries (with the same
  // number of segments, the grid has the same rows)
  const std::size_t first_flat = segments.size();
  segments.resize(first_flat + 20, {{0, 0, 1, 0}});
  {
    const PPS::internal::Segment_grid_2 rows(segments, {{-100, -100}}, {{100, 100}});
    for(std::size_t k = 0; k < 20; ++k) {
      const double boundary = -100 + double(1 + k % 15) * rows.cell_size(); // inside the rectangle
      const double ulp = boundary - std::nextafter(boundary, -1000.);
      segments[first_flat + k] = {{-90. + k, boundary - 2 * ulp, 90. - k, boundary + 6 * ulp}};
    }
  }
  const PPS::internal::Segment_grid_2 grid(segments, {{-100, -100}}, {{100, 100}});
  assert(grid.cell_size() < 20);
  for(std::uint32_t i = 0; i < segments.size(); ++i) {
    const auto& s = segments[i];
    for(int k = 0; k <= 1000; ++k) {
      const double t = k / 1000.;
      const double x = k == 1000 ? s[2] : s[0] + t * (s[2] - s[0]), y = k == 1000 ? s[3] : s[1] + t * (s[3] - s[1]);
      const int cx = grid.column(x), cy = grid.row(y);
      bool listed = false;
      grid.for_each_in_ring(cx, cy, 0, [&](std::uint32_t j) { listed = listed || j == i; });
      assert(listed);
    }
  }
}

// The crossing test of the validity check against all pairs, decided here with other exact
// predicates (for edges sharing an end, whether one contains the other end), on edges crowded in the unit
// square and a few with an end very far away (as the points of rejected reductions can be):
// the grid covers the crowded part only, and the far edges are tested against all the others.
void test_crossings_with_far_points()
{
  using P = K::Point_2;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<std::size_t, 2>> edges;
  auto add_point = [&](double x, double y) { points.push_back({{x, y}}); return points.size() - 1; };
  for(int i = 0; i < 400; ++i) { // short random edges, some crossing
    const double x = u(rng), y = u(rng);
    const std::size_t a = add_point(x, y), b = add_point(x + 0.1 * u(rng), y + 0.1 * u(rng));
    edges.push_back({{a, b}});
  }
  // far edges: across the crowd, from the crowd, and overlapping along y = x from a shared end
  const std::size_t o = add_point(0.125, 0.125);
  edges.push_back({{o, add_point(1e6, 1e6)}});
  edges.push_back({{o, add_point(2e6, 2e6)}});
  edges.push_back({{add_point(-3e7, 0.5), add_point(3e7, 0.5)}});
  edges.push_back({{add_point(0.3, -4e6), add_point(0.3, 5e6)}});
  edges.push_back({{add_point(0.5, 0.75), add_point(-7e5, 9e5)}});
  edges.push_back({{add_point(5e6, 5e6), add_point(6e6, 6e6)}}); // far from everything
  // a crowded edge overlapping another along y = x, from a shared end
  edges.push_back({{o, add_point(0.0625, 0.0625)}});
  edges.push_back({{add_point(-0.5, -0.5), add_point(0.015625, 0.015625)}});
  auto meet = [&](std::size_t i, std::size_t j) {
    const auto& e = edges[i];
    const auto& f = edges[j];
    auto pt = [&](std::size_t v) { return P(points[v][0], points[v][1]); };
    std::size_t common = 0, shared = 0;
    for(std::size_t a : e) for(std::size_t b : f) if(a == b) { ++common; shared = a; }
    if(common == 0) return CGAL::do_intersect(K::Segment_2(pt(e[0]), pt(e[1])), K::Segment_2(pt(f[0]), pt(f[1])));
    const P s = pt(shared), a = pt(e[0] == shared ? e[1] : e[0]), b = pt(f[0] == shared ? f[1] : f[0]);
    return K::Segment_2(s, a).has_on(b) || K::Segment_2(s, b).has_on(a); // overlapping
  };
  std::vector<std::pair<std::size_t, std::size_t>> expected;
  for(std::size_t i = 0; i < edges.size(); ++i)
    for(std::size_t j = i + 1; j < edges.size(); ++j)
      if(meet(i, j)) expected.emplace_back(i, j);
  const auto found = PPS::internal::crossing_edge_pairs<K>(points, edges, true, [](const auto&, const auto&) { return true; });
  std::cout << "crossings with far points: " << found.size() << " pairs (brute force " << expected.size() << ")" << std::endl;
  assert(found == expected);
  std::size_t far_pairs = 0;
  for(const auto& [i, j] : expected) if(i >= 400 || j >= 400) ++far_pairs;
  assert(far_pairs >= 6);
  // with some edges known free of crossings: only the pairs with a suspect are reported
  const auto some = PPS::internal::crossing_edge_pairs<K>(points, edges, true, [&](const auto& a, const auto&) {
    return a[0] < 0; // the edges whose first end has x < 0
  });
  std::vector<std::pair<std::size_t, std::size_t>> expected_some;
  for(const auto& [i, j] : expected)
    if(points[edges[i][0]][0] < 0 || points[edges[j][0]][0] < 0) expected_some.push_back({i, j});
  assert(some == expected_some);
  // the edges known free of crossings given as a set of coordinates (inserted either way round)
  PPS::internal::Segment_coordinate_set known(8);
  for(std::size_t e = 0; e < edges.size(); e += 2)
    known.insert(points[edges[e][e % 4 == 0 ? 0 : 1]], points[edges[e][e % 4 == 0 ? 1 : 0]]);
  for(std::size_t e = 0; e < edges.size(); ++e) {
    assert(known.contains(points[edges[e][0]], points[edges[e][1]]) == (e % 2 == 0));
    assert(known.contains(points[edges[e][1]], points[edges[e][0]]) == (e % 2 == 0));
  }
  const auto odd = PPS::internal::crossing_edge_pairs<K>(points, edges, true, [&](const auto& a, const auto& b) {
    return !known.contains(a, b);
  });
  std::vector<std::pair<std::size_t, std::size_t>> expected_odd;
  for(const auto& [i, j] : expected)
    if(i % 2 == 1 || j % 2 == 1) expected_odd.push_back({i, j});
  assert(odd == expected_odd);
  // The same reference edges with their grid kept (Crossing_free_edges): the same pairs, and
  // the same again for a state with some reference edges gone, others duplicated by a second
  // edge on the same two points, and its points renumbered.
  std::vector<std::array<double, 4>> reference;
  for(std::size_t e = 0; e < edges.size(); e += 2)
    reference.push_back({{points[edges[e][0]][0], points[edges[e][0]][1], points[edges[e][1]][0], points[edges[e][1]][1]}});
  const PPS::internal::Crossing_free_edges crossing_free(reference);
  assert(crossing_free.crossing_pairs<K>(points, edges, true) == expected_odd);
  assert(crossing_free.crossing_pairs<K>(points, edges, false).size() == 1);
  {
    std::vector<std::array<double, 2>> renumbered(points.rbegin(), points.rend());
    const std::size_t last = points.size() - 1;
    std::vector<std::array<std::size_t, 2>> state;
    for(std::size_t e = 0; e < edges.size(); ++e)
      if(e % 6 != 2) state.push_back({{last - edges[e][0], last - edges[e][1]}});
    state.push_back(state[3]); // a reference edge (edges[4]) given twice: both are suspects
    std::vector<std::pair<std::size_t, std::size_t>> expected_state;
    for(std::size_t i = 0; i < state.size(); ++i)
      for(std::size_t j = i + 1; j < state.size(); ++j) {
        const auto& a = renumbered[state[i][0]];
        const auto& b = renumbered[state[i][1]];
        const auto& c = renumbered[state[j][0]];
        const auto& d = renumbered[state[j][1]];
        const bool suspects = !known.contains(a, b) || !known.contains(c, d) || i == 3 || j == 3 || j + 1 == state.size();
        if(suspects && PPS::internal::edges_meet<K>(renumbered, state[i], state[j])) expected_state.push_back({i, j});
      }
    const auto found_state = crossing_free.crossing_pairs<K>(renumbered, state, true);
    std::cout << "crossings of a state against kept reference edges: " << found_state.size() << " pairs (brute force "
              << expected_state.size() << ")" << std::endl;
    assert(found_state == expected_state);
    assert(!expected_state.empty());
  }
}

// A straight wall at an angle given in pieces (a polyline with vertices on the wall, or
// overlapping pieces), collinear only up to rounding, crossed by other walls. Its pieces are
// moved onto one line: the partition is valid and the wall is one line, with no edge removed by
// the rounding. Without the move (collinearity_distance 0), nearly every such scene gives a
// partition that is invalid, or valid only after the rounding removed edges: the check fails
// there, which shows the scenes exercise the case.
void test_nearly_collinear_walls()
{
  std::size_t invalid_without = 0, scenes = 0;
  for(unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    const double a = 6.28 * u(rng), c = std::cos(a), sn = std::sin(a);
    const bool chain = seed % 2 == 0;
    std::vector<K::Segment_2> s;
    double t = 0;
    for(int k = 0; k < 6; ++k) { // on the line through the origin with direction (c, sn), up to rounding
      const double t0 = chain ? t : 20 * u(rng), t1 = t0 + 1 + 5 * u(rng);
      t = t1;
      s.emplace_back(K::Point_2(t0 * c, t0 * sn), K::Point_2(t1 * c, t1 * sn));
    }
    for(int k = 0; k < 6; ++k) {
      const double x = 30 * u(rng) - 5, y = 30 * u(rng) - 5, b = 6.28 * u(rng);
      s.emplace_back(K::Point_2(x, y), K::Point_2(x + 8 * std::cos(b), y + 8 * std::sin(b)));
    }
    ++scenes;
    PPS::Kinetic_partition_report report;
    const bool valid_without =
      CGAL::kinetic_partition_2(s, PPS::parameters::report(&report, PPS::parameters::collinearity_distance(0.))).is_valid();
    invalid_without += valid_without && report.removed_edges == 0 ? 0 : 1;
    Partition p = CGAL::kinetic_partition_2(s, PPS::parameters::report(&report));
    assert(p.is_valid() && report.removed_edges == 0);
    // the six pieces are on one line (at most 6 + 1 + 4 lines: the other walls may be collinear)
    assert(p.number_of_lines() <= 6 + 1 + 4);
    std::vector<K::Segment_2> shuffled = s;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const Partition q = CGAL::kinetic_partition_2(shuffled);
    assert(q.number_of_lines() == p.number_of_lines() && q.number_of_vertices() == p.number_of_vertices() &&
          q.number_of_edges() == p.number_of_edges());
    CGAL::simplify_polygon_partition_2(p); // a valid input is accepted
    if(seed == 1)
      expect_error(PPS::Input_error_code::INVALID_PARAMETER,
                   [&] { CGAL::kinetic_partition_2(s, PPS::parameters::collinearity_distance(-1.)); });
  }
  std::cout << "nearly collinear walls: " << invalid_without << " of " << scenes
            << " scenes invalid, or with edges removed, without moving the pieces onto one line" << std::endl;
  assert(invalid_without >= scenes / 2);
}

// The same for polygons: two rotated rectangles side by side, whose sides have vertices in
// their middle (where a neighbour's corner is: the shared side has one from each), collinear
// only up to rounding, and one roof side bent by 1 cm on purpose. The pieces of each straight
// side are put back on one line, the rings stay joined (cells tile the polygons), the bent
// side keeps its two lines. Without it, most scenes were invalid.
void test_nearly_collinear_polygon_edges()
{
  std::size_t invalid_without = 0, scenes = 0;
  for(unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    const double a = 6.28 * u(rng), c = std::cos(a), sn = std::sin(a);
    auto at = [&](double x, double y) { return K::Point_2(x * c - y * sn, x * sn + y * c); };
    const double t = 0.2 + 0.6 * u(rng), v = 0.2 + 0.6 * u(rng), w = 0.2 + 0.6 * u(rng);
    std::vector<CGAL::Polygon_2<K>> rectangles(2);
    for(const auto& [x, y] : {std::pair(0., 0.), std::pair(10 * t, 0.), std::pair(10., 0.), std::pair(10., 5 * v),
                              std::pair(10., 5.), std::pair(5., 5.01), std::pair(0., 5.)})
      rectangles[0].push_back(at(x, y));
    for(const auto& [x, y] : {std::pair(10., 0.), std::pair(20., 0.), std::pair(20., 5.), std::pair(10., 5.), std::pair(10., 5 * w)})
      rectangles[1].push_back(at(x, y));
    // below, two triangles sharing an edge that ends at a corner (an edge given twice is one
    // edge: counted twice, it made a group of its own, and the corner had three), and on
    // seeds where the middle of the first bottom piece is exactly on it, a triangle with its
    // apex there (a vertex inside another polygon's edge moves with that edge)
    std::vector<CGAL::Polygon_2<K>> polygons = rectangles;
    polygons.resize(4);
    for(const auto& [x, y] : {std::pair(10., 0.), std::pair(13., -4.), std::pair(8., -4.)}) polygons[2].push_back(at(x, y));
    for(const auto& [x, y] : {std::pair(10., 0.), std::pair(15., -2.), std::pair(13., -4.)}) polygons[3].push_back(at(x, y));
    const K::Point_2 a0 = at(0, 0), a1 = at(10 * t, 0), middle((a0.x() + a1.x()) / 2, (a0.y() + a1.y()) / 2);
    const bool t_junction = CGAL::collinear(a0, a1, middle); // exact predicate
    if(t_junction) {
      polygons.emplace_back();
      for(const K::Point_2& q : {middle, at(5 * t - 1, -2), at(5 * t + 1, -2)}) polygons.back().push_back(q);
    }
    ++scenes;
    invalid_without +=
      PPS::line_partition_from_polygons_2(polygons, PPS::parameters::collinearity_distance(0.)).is_valid() ? 0 : 1;
    Partition p = PPS::line_partition_from_polygons_2(polygons);
    assert(p.is_valid());
    // y = 0, x = 0, x = 10, x = 20, y = 5 (right roof), the two halves of the bent left roof;
    // 5 for the two triangles, 3 for the third
    assert(p.number_of_lines() == (t_junction ? 15u : 12u) && p.number_of_cells() == polygons.size());
    std::vector<Partition::Polygon_with_holes_2> cells;
    p.cells(std::back_inserter(cells));
    double area = 0, expected = 0;
    for(const auto& cell : cells) area += cell.outer_boundary().area();
    for(const auto& polygon : polygons) expected += std::abs(polygon.area());
    assert(std::abs(area - expected) < 1e-9 * area);
    std::reverse(polygons.begin(), polygons.end());
    const Partition q = PPS::line_partition_from_polygons_2(polygons);
    assert(q.number_of_lines() == p.number_of_lines() && q.number_of_vertices() == p.number_of_vertices() &&
          q.number_of_edges() == p.number_of_edges());
    CGAL::simplify_polygon_partition_2(p); // a valid input is accepted
    if(seed == 1)
      expect_error(PPS::Input_error_code::INVALID_PARAMETER, [&] {
        PPS::line_partition_from_polygons_2(rectangles, PPS::parameters::collinearity_distance(-1.));
      });
  }
  std::cout << "nearly collinear polygon edges: " << invalid_without << " of " << scenes
            << " scenes invalid without moving the pieces onto one line" << std::endl;
  assert(invalid_without >= scenes / 2);
}

int main()
{
  test_simple_configurations();
  test_validity_check();
  test_removal_of_defective_edges();
  test_faces_against_arrangement();
  test_segment_grid();
  test_crossings_with_far_points();
  for(unsigned seed = 1; seed <= 6; ++seed) test_kinetic_rules(random_segments(40, seed));
  for(unsigned seed = 1; seed <= 2; ++seed) test_kinetic_rules(mixed_segments(seed));
  for(unsigned seed = 1; seed <= 3; ++seed) test_kinetic_rules(projected_segments(seed));
  test_crossing_distance_at_concurrent_lines();
  test_against_line_arrangement();
  test_cells_and_invariance();
  test_builders();
  test_bad_input();
  test_nearly_collinear_walls();
  test_nearly_collinear_polygon_edges();
  std::cout << "test_line_partition: all checks passed" << std::endl;
  return 0;
}
