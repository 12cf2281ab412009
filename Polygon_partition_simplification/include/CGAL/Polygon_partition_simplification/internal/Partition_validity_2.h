// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_VALIDITY_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_VALIDITY_2_H

// The exact validity check of a partition in line representation (the points are computed in
// double precision from their lines, and every geometric decision on these points is exact):
// 1. combinatorics: every point has at least two lines, every edge joins two points of its line;
// 2. every point is finite and no two coincide;
// 3. no two edges meet elsewhere than at a common end: the edges near each other are found in
//    a grid (see Segment_grid_2.h), then decided with exact segment predicates;
// 4. every edge separates two different cells and every cell boundary is a simple polygon.
//    Once 2 and 3 hold, the edges form a plane graph whose faces are traced by the facial walks
//    of its rotation system: the edges around each point sorted by direction with exact
//    orientation predicates, and the walk leaves a point by the edge that follows, clockwise,
//    the edge it came in by. For each connected part of the graph, one walk goes around each of
//    its faces (for a face with holes, each hole is the walk of another part), so an edge bounds
//    the same face on both sides exactly when both its sides are on the same walk, and a cell
//    boundary is simple exactly when no walk passes twice through a point: the same decisions
//    as with the faces of CGAL's arrangement of the edges, without building it.
//
// A caller that knows that some segments are pairwise free of crossings (the edges of a valid
// state) only needs the pairs with an edge that is not one of them (or that joins the same two
// points as another edge): crossing_edge_pairs() with `may_cross(a, b)` false for those, or
// Crossing_free_edges (Crossing_free_edges_2.h), which keeps their grid from test to test.
//
// The predicates are those of `PK`, the exact predicates kernel of the geometric traits (double
// coordinates, exact predicates); the exact fallback of the area of a walk is computed in `ET`,
// the exact number type of its exact constructions kernel.

#include <CGAL/Polygon_partition_simplification/internal/First_value_map.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Segment_grid_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Union_find.h>

#include <CGAL/Polygon_partition_simplification/internal/nearest_double.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// A set of segments by the exact coordinates of their ends, either way round: the edges of a
// valid state, which cross none of each other, for the `may_cross` of the crossing test. A
// hash set on the bits of the coordinates; a segment whose digest another one took first is
// reported absent, which only makes it a suspect (the test stays exact).
class Segment_coordinate_set
{
public:
  explicit Segment_coordinate_set(std::size_t expected)
  {
    segments_.reserve(expected);
    map_.clear(expected);
  }

  void insert(const std::array<double, 2>& p, const std::array<double, 2>& q)
  {
    segments_.push_back(key(p, q));
    map_.insert(digest(segments_.back()), std::uint32_t(segments_.size() - 1));
  }

  bool contains(const std::array<double, 2>& p, const std::array<double, 2>& q) const
  {
    return find(p, q) != First_value_map::no_value;
  }

  // the rank of insertion of the segment from p to q (either way round), or
  // First_value_map::no_value if it is absent (or its digest was taken first by another one)
  std::uint32_t find(const std::array<double, 2>& p, const std::array<double, 2>& q) const
  {
    const std::array<double, 4> s = key(p, q);
    const std::uint32_t i = map_.find(digest(s));
    return i != First_value_map::no_value && segments_[i] == s ? i : First_value_map::no_value;
  }

  std::size_t size() const { return segments_.size(); }
  const std::array<double, 4>& segment(std::size_t i) const { return segments_[i]; }

private:
  static std::array<double, 4> key(const std::array<double, 2>& p, const std::array<double, 2>& q)
  {
    const auto [a, b] = std::minmax(p, q);
    return {{a[0], a[1], b[0], b[1]}};
  }
  static std::uint64_t digest(const std::array<double, 4>& s)
  {
    std::uint64_t h = 0;
    for(double c : s) {
      std::uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
      h ^= h >> 29;
    }
    return h == First_value_map::no_key ? h - 1 : h;
  }

  std::vector<std::array<double, 4>> segments_;
  First_value_map map_;
};

// The rectangle where the grid of the crossing test is laid: twice the span between the 1st and
// the 99th percentiles of the coordinates of the segment ends, on each axis, around their
// middle. A round whose reductions are rejected can have a few points sent very far (two nearly
// parallel lines); a grid over all the points would then have cells so large that nearly every
// edge falls in the same one, and the test would take quadratic time. The few segments that
// leave the rectangle are not in the grid: each is tested directly against the edges it may
// meet (all of them if it is a suspect, the suspects otherwise). Which segments are in the grid
// only changes the cost: `contains()` decides it exactly, and any rectangle is correct (an
// overflow in the bounds makes it infinite or empty).
struct Core_rectangle
{
  std::array<double, 2> low, high;

  explicit Core_rectangle(const std::vector<std::array<double, 4>>& segments)
  {
    low = high = {{0, 0}};
    if(segments.empty()) return;
    std::vector<double> values;
    values.reserve(2 * segments.size());
    for(int axis = 0; axis < 2; ++axis) {
      values.clear();
      for(const auto& s : segments) { values.push_back(s[axis]); values.push_back(s[axis + 2]); }
      const std::size_t n = values.size(), first = (n - 1) / 100, last = n - 1 - first;
      std::nth_element(values.begin(), values.begin() + first, values.end());
      const double a = values[first];
      std::nth_element(values.begin(), values.begin() + last, values.end());
      const double b = values[last];
      const double middle = 0.5 * (a + b), half = b - a; // twice the half span
      low[axis] = middle - half;
      high[axis] = middle + half;
    }
  }

  bool contains(const std::array<double, 4>& s) const
  {
    for(int axis = 0; axis < 2; ++axis)
      for(double x : {s[axis], s[axis + 2]})
        if(!(x >= low[axis] && x <= high[axis])) return false;
    return true;
  }
};

// Do the edges e and f ((u, v) point pairs, with `points` their coordinates, the ends of an
// edge distinct points) meet elsewhere than at a common end? Decided with the exact predicates
// of `PK`.
template <class PK>
bool edges_meet(const std::vector<std::array<double, 2>>& points, const std::array<std::size_t, 2>& e,
                const std::array<std::size_t, 2>& f)
{
  using Point = typename PK::Point_2;
  using Segment = typename PK::Segment_2;
  auto point = [&](std::size_t v) { return Point(points[v][0], points[v][1]); };
  std::size_t common = 0, shared = 0;
  for(std::size_t a : e)
    for(std::size_t b : f)
      if(a == b) { ++common; shared = a; }
  if(common == 0) return CGAL::do_intersect(Segment(point(e[0]), point(e[1])), Segment(point(f[0]), point(f[1])));
  if(common == 2) return true;
  // They share an end s and must not overlap, which they do exactly when they leave s in the
  // same direction: collinear, with other ends on the same side of s. The side is tested first:
  // consecutive edges along a line leave s in opposite directions, which the filtered sign of
  // (oe - s).(of - s) decides at once, whereas their orientation, nearly zero, needs the exact
  // arithmetic.
  const Point s = point(shared);
  const Point oe = point(e[0] == shared ? e[1] : e[0]), of = point(f[0] == shared ? f[1] : f[0]);
  return CGAL::angle(oe, s, of) == CGAL::ACUTE && CGAL::orientation(s, oe, of) == CGAL::COLLINEAR;
}

// The pairs of edges (indices into `edges`: (u, v) point pairs) that meet elsewhere than at a
// common end, among the pairs with an edge for which `may_cross(a, b)` (its ends' coordinates)
// is true; stops at a pair found (whichever the search meets first) unless `all`. `points`:
// the coordinates (finite for the ends of every edge given).
template <class PK, class MayCross>
std::vector<std::pair<std::size_t, std::size_t>>
crossing_edge_pairs(const std::vector<std::array<double, 2>>& points,
                    const std::vector<std::array<std::size_t, 2>>& edges, bool all, const MayCross& may_cross)
{
  using Point = typename PK::Point_2;
  std::vector<std::pair<std::size_t, std::size_t>> result;
  if(edges.empty()) return result;
  auto point = [&](std::size_t v) { return Point(points[v][0], points[v][1]); };
  std::vector<std::array<double, 4>> segments(edges.size());
  std::vector<CGAL::Bbox_2> boxes(edges.size());
  for(std::size_t e = 0; e < edges.size(); ++e) {
    const auto& a = points[edges[e][0]];
    const auto& b = points[edges[e][1]];
    segments[e] = {{a[0], a[1], b[0], b[1]}};
    boxes[e] = point(edges[e][0]).bbox() + point(edges[e][1]).bbox();
  }
  const Core_rectangle core(segments);
  // the suspects; an edge joining the same two points as another is one
  std::vector<bool> suspect(edges.size());
  {
    First_value_map known; // sorted ends -> the first edge known free of crossings with these ends
    known.clear(edges.size());
    for(std::size_t e = 0; e < edges.size(); ++e) {
      suspect[e] = may_cross(points[edges[e][0]], points[edges[e][1]]);
      if(suspect[e]) continue;
      const auto [u, v] = std::minmax(edges[e][0], edges[e][1]);
      // u < v (the caller checks that an edge joins two points), both below 2^32 - 1 (point
      // indices are 32-bit numbers in this package): the key is not First_value_map::no_key
      const std::size_t first = known.insert((std::uint64_t(u) << 32) | v, std::uint32_t(e));
      if(first != e) suspect[first] = suspect[e] = true;
    }
  }
  // Two edges that meet share a point, which lies in a cell where both are listed: each suspect
  // inside the core is tested against the edges listed in its cells whose boxes meet its box
  // (once per pair); each edge outside the core directly (see Core_rectangle).
  std::vector<std::uint32_t> inside; // grid entry -> edge
  std::vector<std::array<double, 4>> inside_segments;
  std::vector<std::size_t> outside;
  for(std::size_t e = 0; e < edges.size(); ++e) {
    if(core.contains(segments[e])) {
      inside.push_back(std::uint32_t(e));
      inside_segments.push_back(segments[e]);
    } else outside.push_back(e);
  }
  auto consider = [&](std::size_t i, std::size_t j) {
    if(CGAL::do_overlap(boxes[i], boxes[j]) && edges_meet<PK>(points, edges[i], edges[j]))
      result.emplace_back(std::min(i, j), std::max(i, j));
  };
  const Segment_grid_2 grid(inside_segments, core.low, core.high);
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> seen(edges.size(), none); // the last suspect that met an edge
  for(std::size_t k = 0; k < inside.size() && (all || result.empty()); ++k) {
    const std::size_t i = inside[k];
    if(!suspect[i]) continue;
    grid.for_each_cell(segments[i], [&](std::size_t cell) {
      grid.for_each_in_cell(cell, [&](std::uint32_t entry) {
        const std::size_t j = inside[entry];
        if(j == i || seen[j] == i || (suspect[j] && j < i)) return; // a pair of suspects once
        seen[j] = i;
        if(all || result.empty()) consider(i, j);
      });
    });
  }
  // each edge outside against the edges inside and the edges outside after it (once per pair),
  // among them only the suspects if it is not one
  std::vector<bool> is_outside(edges.size(), false);
  for(std::size_t f : outside) is_outside[f] = true;
  std::vector<std::size_t> suspects;
  if(!outside.empty())
    for(std::size_t e = 0; e < edges.size(); ++e) if(suspect[e]) suspects.push_back(e);
  for(std::size_t f : outside) {
    auto pair_with = [&](std::size_t j) {
      if(j != f && (!is_outside[j] || j > f) && (all || result.empty())) consider(f, j);
    };
    if(suspect[f]) for(std::size_t j = 0; j < edges.size(); ++j) pair_with(j);
    else for(std::size_t j : suspects) pair_with(j);
  }
  std::sort(result.begin(), result.end());
  return result;
}

// Whether the facial walk from half-edge `start` turns clockwise (negative area): the walks of
// the bounded faces turn counterclockwise, the outer boundary of each connected part clockwise.
// The area is summed in double with an error bound, and again exactly when the bound does not
// decide (in `ET`, an exact field number type).
template <class ET, class Source, class Target, class Next>
bool is_clockwise_walk(const std::vector<std::array<double, 2>>& points, std::size_t start, const Source& source,
                       const Target& target, const Next& next)
{
  const auto& o = points[source(start)];
  double twice_area = 0, magnitude = 0;
  std::size_t terms = 0;
  std::size_t h = start;
  do {
    const auto& a = points[source(h)];
    const auto& b = points[target(h)];
    const double x = (a[0] - o[0]) * (b[1] - o[1]), y = (a[1] - o[1]) * (b[0] - o[0]);
    twice_area += x - y;
    magnitude += std::abs(x) + std::abs(y);
    ++terms;
    h = next(h);
  } while(h != start);
  // each product has a relative error of 3u (two differences, one product); the sum adds u per term
  const double bound = double(terms + 4) * 4 * std::numeric_limits<double>::epsilon() * magnitude;
  if(twice_area < -bound) return true;
  if(twice_area > bound) return false;
  using FT = ET;
  FT exact = 0;
  h = start;
  do {
    const auto& a = points[source(h)];
    const auto& b = points[target(h)];
    exact += (FT(a[0]) - o[0]) * (FT(b[1]) - o[1]) - (FT(a[1]) - o[1]) * (FT(b[0]) - o[0]);
    h = next(h);
  } while(h != start);
  return CGAL::is_negative(exact);
}

// The connected parts of the edges (a label per point) and, for a point, whether it lies inside
// the outer boundary of another part (then in one of its cells): the ray from it towards +x
// crosses the outer boundary of that part an odd number of times (half-open rule on y, exact
// orientation tests). `on_outer_boundary`: the edges with exactly one side on the outer
// boundary (clockwise walk) of their part; the others (between two cells, or dangling, or
// bridging, with one face on both sides) would spoil the parity: a point in the left cell of a
// square cut in two crosses the middle edge and the right side. Built when first needed.
template <class PK>
class Part_containment
{
public:
  Part_containment(const std::vector<std::array<double, 2>>& points, const std::vector<std::array<std::size_t, 2>>& edges,
                   std::vector<bool> on_outer_boundary)
    : points_(points), edges_(edges), on_outer_boundary_(std::move(on_outer_boundary)), part_(points.size()),
      odd_(points.size(), false)
  {
    Union_find<std::size_t> parts(points.size());
    for(const auto& e : edges) parts.unite(e[0], e[1]);
    for(std::size_t x = 0; x < part_.size(); ++x) part_[x] = parts.find(x);
  }

  bool lies_in_another_part(std::size_t v)
  {
    using Point = typename PK::Point_2;
    const Point p(points_[v][0], points_[v][1]);
    touched_.clear();
    for(std::size_t i = 0; i < edges_.size(); ++i) {
      if(!on_outer_boundary_[i]) continue;
      const auto& e = edges_[i];
      const std::size_t part = part_[e[0]];
      if(part == part_[v]) continue;
      const auto& a = points_[e[0]];
      const auto& b = points_[e[1]];
      if((a[1] > p.y()) == (b[1] > p.y())) continue;
      // the edge goes across the line y = p.y: does it cross it to the right of p?
      const auto& low = a[1] < b[1] ? a : b;
      const auto& high = a[1] < b[1] ? b : a;
      if(CGAL::orientation(Point(low[0], low[1]), Point(high[0], high[1]), p) != CGAL::LEFT_TURN) continue;
      odd_[part] = !odd_[part];
      touched_.push_back(part);
    }
    bool inside = false;
    for(std::size_t part : touched_) { inside = inside || odd_[part]; odd_[part] = false; }
    return inside;
  }

private:
  const std::vector<std::array<double, 2>>& points_;
  const std::vector<std::array<std::size_t, 2>>& edges_;
  std::vector<bool> on_outer_boundary_;
  std::vector<std::size_t> part_; // per point, the representative of its connected part
  std::vector<bool> odd_;
  std::vector<std::size_t> touched_;
};

// The facial walks of a plane graph (no crossing, distinct points): appends to `bridges` the
// edges with the same walk on both sides and to `pinched` the edges around the points that a
// walk passes twice (the edges in and out of both passages), except for the walks that bound
// only the unbounded face (two cells touching at a corner). With `on_side` (per edge: whether
// it lies on a side of the bounding rectangle of a kinetic partition; empty if there is
// none), appends to `outside` the other edges on the boundary of the unbounded face: the
// cells tile the rectangle exactly when there is none (a cell that went out through a side,
// or a point on a side sent past a corner, puts its edges there, although no edges need to
// cross).
template <class PK, class ET>
void facial_walk_defects(const std::vector<std::array<double, 2>>& points,
                         const std::vector<std::array<std::size_t, 2>>& edges,
                         std::vector<std::size_t>& bridges, std::vector<std::size_t>& pinched,
                         const std::vector<bool>& on_side = {}, std::vector<std::size_t>* outside = nullptr)
{
  using Point = typename PK::Point_2;
  const std::size_t nv = points.size(), nh = 2 * edges.size();
  // half-edge h = 2e + s goes from edges[e][s] to edges[e][1 - s]
  auto source = [&](std::size_t h) { return edges[h / 2][h % 2]; };
  auto target = [&](std::size_t h) { return edges[h / 2][1 - h % 2]; };
  std::vector<std::uint32_t> first(nv + 1, 0);
  for(std::size_t h = 0; h < nh; ++h) ++first[source(h) + 1];
  for(std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<std::uint32_t> around(nh); // outgoing half-edges, point by point
  {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for(std::size_t h = 0; h < nh; ++h) around[next[source(h)]++] = std::uint32_t(h);
  }
  // counterclockwise order around each point, from the direction of the positive x axis
  // (exact: coordinate comparisons and orientation predicates on the double points)
  for(std::size_t v = 0; v < nv; ++v) {
    const Point p(points[v][0], points[v][1]);
    auto upper = [&](std::size_t h) { // direction in [0, pi)
      const auto& q = points[target(h)];
      return q[1] > points[v][1] || (q[1] == points[v][1] && q[0] > points[v][0]);
    };
    std::sort(around.begin() + first[v], around.begin() + first[v + 1], [&](std::uint32_t a, std::uint32_t b) {
      const bool ua = upper(a), ub = upper(b);
      if(ua != ub) return ua;
      const auto& qa = points[target(a)];
      const auto& qb = points[target(b)];
      return CGAL::orientation(p, Point(qa[0], qa[1]), Point(qb[0], qb[1])) == CGAL::LEFT_TURN;
    });
  }
  std::vector<std::uint32_t> position(nh);
  for(std::size_t v = 0; v < nv; ++v)
    for(std::uint32_t i = first[v]; i < first[v + 1]; ++i) position[around[i]] = i;
  // next(h): at the target of h, the half-edge that follows the twin of h clockwise
  auto next = [&](std::size_t h) -> std::size_t {
    const std::size_t twin = h ^ 1, v = source(twin);
    const std::uint32_t i = position[twin];
    return around[i == first[v] ? first[v + 1] - 1 : i - 1];
  };
  const std::uint32_t none = std::uint32_t(-1);
  std::vector<std::uint32_t> walk_of(nh, none);
  std::vector<std::uint32_t> last_walk(nv, none), arrival(nv, none); // per point, in the current walk
  std::uint32_t walks = 0;
  std::vector<std::size_t> walk_pinches;
  std::vector<std::pair<std::size_t, std::vector<std::size_t>>> pinched_walks; // first half-edge, pinch edges
  std::vector<std::size_t> walk_start;
  for(std::size_t start = 0; start < nh; ++start) {
    if(walk_of[start] != none) continue;
    std::size_t h = start;
    walk_pinches.clear();
    do {
      walk_of[h] = walks;
      const std::size_t v = target(h);
      if(last_walk[v] == walks) // a second passage through v
        for(std::size_t in : {std::size_t(arrival[v]), h}) {
          walk_pinches.push_back(in / 2);
          walk_pinches.push_back(next(in) / 2);
        }
      last_walk[v] = walks;
      arrival[v] = std::uint32_t(h);
      h = next(h);
    } while(h != start);
    // A pinched walk bounds a cell that is not a simple polygon, unless it is the outer
    // boundary of a connected part (clockwise) that lies in no cell of another part: it then
    // bounds the unbounded face only (two cells that touch at a corner).
    if(!walk_pinches.empty()) pinched_walks.emplace_back(start, walk_pinches);
    walk_start.push_back(start);
    ++walks;
  }
  // The walks that turn clockwise (outer boundaries of the connected parts), computed when
  // first needed, and the containment test on them.
  std::vector<signed char> clockwise(walks, -1);
  auto is_clockwise = [&](std::uint32_t k) {
    if(clockwise[k] < 0) clockwise[k] = is_clockwise_walk<ET>(points, walk_start[k], source, target, next) ? 1 : 0;
    return clockwise[k] == 1;
  };
  std::optional<Part_containment<PK>> parts;
  auto lies_in_another_part = [&](std::size_t v) {
    if(!parts) {
      std::vector<bool> on_outer_boundary(edges.size());
      for(std::size_t e = 0; e < edges.size(); ++e)
        on_outer_boundary[e] = is_clockwise(walk_of[2 * e]) != is_clockwise(walk_of[2 * e + 1]);
      parts.emplace(points, edges, std::move(on_outer_boundary));
    }
    return parts->lies_in_another_part(v);
  };
  for(const auto& [start, pinches] : pinched_walks) {
    const bool outer = is_clockwise(walk_of[start]) && !lies_in_another_part(source(start));
    if(!outer) pinched.insert(pinched.end(), pinches.begin(), pinches.end());
  }
  for(std::size_t e = 0; e < edges.size(); ++e)
    if(walk_of[2 * e] == walk_of[2 * e + 1]) bridges.push_back(e);
  if(outside == nullptr || on_side.empty()) return;
  // The walks around the unbounded face are the clockwise walks (outer boundaries of the
  // connected parts) in no cell of another part. Only the walks with an edge off the sides
  // matter: the outer boundary of the rectangle has none, and every other clockwise walk (the
  // outer boundary of a ring left inside a cell) costs a test against all edges.
  std::vector<bool> off_side(walks, false); // the walks with an edge off the sides
  for(std::size_t h = 0; h < nh; ++h)
    if(!on_side[h / 2]) off_side[walk_of[h]] = true;
  std::vector<bool> unbounded(walks, false);
  for(std::uint32_t k = 0; k < walks; ++k)
    if(off_side[k] && is_clockwise(k)) unbounded[k] = !lies_in_another_part(source(walk_start[k]));
  for(std::size_t e = 0; e < edges.size(); ++e)
    if(!on_side[e] && (unbounded[walk_of[2 * e]] || unbounded[walk_of[2 * e + 1]])) outside->push_back(e);
}

// The number of bounded faces of a plane graph (no crossing, distinct points) with
// `number_of_points` points and the given edges ((u, v) point pairs), by Euler's formula:
// V - E + F = 1 + C for C connected parts, so F - 1 = E - V + C.
template <class Edges>
std::size_t number_of_bounded_faces(std::size_t number_of_points, const Edges& edges)
{
  Union_find<std::size_t> parts(number_of_points);
  for(const auto& e : edges) parts.unite(e[0], e[1]);
  return edges.size() + parts.number_of_sets() - number_of_points;
}

// The crossing test of partition_defect() with every pair of edges tested.
template <class PK>
struct All_crossing_pairs
{
  std::vector<std::pair<std::size_t, std::size_t>> operator()(const std::vector<std::array<double, 2>>& points,
                                                              const std::vector<std::array<std::size_t, 2>>& ends,
                                                              bool all) const
  {
    return crossing_edge_pairs<PK>(points, ends, all, [](const auto&, const auto&) { return true; });
  }
};

// The first defect of a partition (empty if it is valid); with `defective`, the edges of all
// defects of the first kind found (sorted, distinct). `View` gives number_of_lines(),
// coefficients(l), number_of_vertices(), vertex_lines(v) (sorted indices), number_of_edges()
// and edge(e) = {line, u, v}. `crossing_pairs(points, ends, all)` returns the pairs of edges
// ((u, v) point pairs) that meet elsewhere than at a common end, as crossing_edge_pairs() does
// (all of them, or one if `all` is false); a caller that knows some edges to be free of
// crossings may leave out the pairs of two of them (see crossing_edge_pairs() and
// Crossing_free_edges). `GeomTraits`: a model of `PolygonPartitionSimplificationTraits_2`, whose
// kernels give the predicates.
template <class GeomTraits, class View, class CrossingPairs>
std::string partition_defect(const View& view, std::vector<std::size_t>* defective, const CrossingPairs& crossing_pairs)
{
  using PK = typename GeomTraits::Exact_predicates_kernel;
  using ET = Exact_number<typename GeomTraits::Exact_constructions_kernel>;
  const std::size_t nl = view.number_of_lines(), nv = view.number_of_vertices(), ne = view.number_of_edges();
  std::string first;
  auto finish = [&](std::string what) {
    if(defective) {
      std::sort(defective->begin(), defective->end());
      defective->erase(std::unique(defective->begin(), defective->end()), defective->end());
    }
    return what;
  };
  auto report = [&](const std::string& what) { if(first.empty()) first = what; return defective == nullptr; };
  auto all_edges = [&] { if(defective) for(std::size_t e = 0; e < ne; ++e) defective->push_back(e); };
  if(ne == 0) return finish("the partition has no edge");
  std::vector<std::array<std::size_t, 2>> ends(ne);
  for(std::size_t e = 0; e < ne; ++e) {
    const auto edge = view.edge(e);
    if(edge[1] == edge[2] || edge[1] >= nv || edge[2] >= nv) {
      all_edges();
      return finish("edge " + std::to_string(e) + " does not join two points");
    }
    ends[e] = {edge[1], edge[2]};
  }
  std::vector<std::size_t> first_incident, incident; // edges around each point, built at the first defect
  auto mark = [&](std::size_t v) { // the edges at point v
    if(!defective) return;
    if(first_incident.empty()) {
      first_incident.assign(nv + 1, 0);
      for(const auto& end : ends) { ++first_incident[end[0] + 1]; ++first_incident[end[1] + 1]; }
      for(std::size_t u = 0; u < nv; ++u) first_incident[u + 1] += first_incident[u];
      incident.resize(2 * ne);
      std::vector<std::size_t> next(first_incident.begin(), first_incident.end() - 1);
      for(std::size_t e = 0; e < ne; ++e) {
        incident[next[ends[e][0]]++] = e;
        incident[next[ends[e][1]]++] = e;
      }
    }
    defective->insert(defective->end(), incident.begin() + first_incident[v], incident.begin() + first_incident[v + 1]);
  };
  std::vector<std::array<double, 2>> points(nv);
  for(std::size_t v = 0; v < nv; ++v) {
    const auto& l = view.vertex_lines(v);
    for(std::size_t i = 0; i < l.size(); ++i)
      if(l[i] >= nl || (i > 0 && l[i - 1] >= l[i])) {
        all_edges();
        return finish("point " + std::to_string(v) + " has invalid line indices");
      }
    if(l.size() < 2) {
      mark(v);
      if(report("point " + std::to_string(v) + " has fewer than two lines")) return finish(first);
      continue;
    }
    points[v] = point_of_lines(l, [&](std::size_t x) -> const Vector_3d& { return view.coefficients(x); },
                               [&](std::size_t x) { return view.is_fixed(x); });
    if(!std::isfinite(points[v][0]) || !std::isfinite(points[v][1])) {
      mark(v);
      if(report("point " + std::to_string(v) + " is at infinity")) return finish(first);
    }
  }
  for(std::size_t e = 0; e < ne; ++e)
    for(std::size_t v : ends[e]) {
      const auto& l = view.vertex_lines(v);
      if(!std::binary_search(l.begin(), l.end(), view.edge(e)[0])) {
        all_edges();
        return finish("edge " + std::to_string(e) + " ends at a point off its line");
      }
    }
  if(!first.empty()) return finish(first); // no geometry with points at infinity
  {
    std::vector<std::pair<std::array<double, 2>, std::size_t>> sorted;
    sorted.reserve(nv);
    for(std::size_t v = 0; v < nv; ++v) sorted.emplace_back(points[v], v);
    std::sort(sorted.begin(), sorted.end());
    for(std::size_t i = 1; i < sorted.size(); ++i)
      if(sorted[i].first == sorted[i - 1].first) {
        mark(sorted[i].second);
        mark(sorted[i - 1].second);
        if(report("points " + std::to_string(sorted[i - 1].second) + " and " +
                  std::to_string(sorted[i].second) + " coincide")) return finish(first);
      }
  }
  if(!first.empty()) return finish(first); // the walks need distinct points
  const std::vector<std::pair<std::size_t, std::size_t>> crossings = crossing_pairs(points, ends, defective != nullptr);
  if(!crossings.empty()) {
    if(defective)
      for(const auto& [e, f] : crossings) { defective->push_back(e); defective->push_back(f); }
    return finish("edges " + std::to_string(crossings[0].first) + " and " + std::to_string(crossings[0].second) +
                  " cross, overlap or pass through a point");
  }
  std::vector<std::size_t> bridges, pinched, outside;
  std::vector<bool> on_side; // with fixed lines (a kinetic partition), the edges on them
  for(std::size_t l = 0; l < nl; ++l)
    if(view.is_fixed(l)) {
      on_side.resize(ne);
      for(std::size_t e = 0; e < ne; ++e) on_side[e] = view.is_fixed(view.edge(e)[0]);
      break;
    }
  facial_walk_defects<PK, ET>(points, ends, bridges, pinched, on_side, &outside);
  if(!outside.empty()) {
    if(defective) defective->insert(defective->end(), outside.begin(), outside.end());
    if(report("the cells do not tile the bounding rectangle: an edge off its sides bounds the "
              "unbounded face")) return finish(first);
  }
  if(!bridges.empty()) {
    if(defective) defective->insert(defective->end(), bridges.begin(), bridges.end());
    if(report("an edge dangles or bridges inside a cell")) return finish(first);
  }
  if(!pinched.empty()) {
    if(defective) defective->insert(defective->end(), pinched.begin(), pinched.end());
    report("a cell boundary is not a simple polygon");
  }
  return finish(first);
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_VALIDITY_2_H
