// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SNAP_COLLINEAR_SEGMENTS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SNAP_COLLINEAR_SEGMENTS_2_H

// Segments that are collinear up to rounding (a straight wall given in several pieces whose
// vertices are not exactly on one line in double precision, which is the rule for a wall at an
// angle) have supporting lines that differ by a tiny angle. The kinetic partition of such
// segments is exact, but its points are then computed in double from nearly identical lines,
// where the intersection of two lines is ill-conditioned: the partition can then have crossing
// edges, points at infinity or a point with the same line twice. Such segments are moved onto
// one exact line first: the line of the longest segment of the group, on which the endpoints
// of the others are projected with exact constructions. Then they share one line, as exactly
// collinear segments do.
//
// A segment joins the group of a longer one when both its endpoints are within `distance` of
// that segment's line (a segment shorter than 4 `distance`: within 1e-6 of its own length, so
// that only nearly identical lines are merged). Segments are taken by decreasing length (ties by their sorted
// coordinates), so the groups do not depend on the input order. Candidates are found among
// the longer segments whose direction is close enough (sorted by angle): a segment of length
// l with both endpoints within d of a line makes an angle of at most asin(2 d / l) with it.

#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_partition_simplification/internal/Union_find.h>

#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// For each segment of `input` (x0, y0, x1, y1 each), the index of the longest segment of its
// group (itself for the longest; for every segment when `distance` is not positive).
inline std::vector<std::size_t> collinear_groups(const std::vector<std::array<double, 4>>& input, double distance)
{
  const std::size_t n = input.size();
  std::vector<std::size_t> reference(n);
  std::iota(reference.begin(), reference.end(), std::size_t(0));
  if(!(distance > 0) || n < 2) return reference;

  const double pi = 3.14159265358979323846;
  std::vector<double> length(n), angle(n);
  std::vector<std::array<double, 4>> sorted_ends(n); // endpoints in lexicographic order: tie-break
  for(std::size_t i = 0; i < n; ++i) {
    const auto& c = input[i];
    const double dx = c[2] - c[0], dy = c[3] - c[1];
    length[i] = std::hypot(dx, dy);
    double a = std::atan2(dy, dx);
    if(a < 0) a += pi;
    if(a >= pi) a -= pi;
    angle[i] = a;
    sorted_ends[i] = std::make_pair(c[0], c[1]) <= std::make_pair(c[2], c[3]) ? c : std::array<double, 4>{{c[2], c[3], c[0], c[1]}};
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    if(length[x] != length[y]) return length[x] > length[y];
    return sorted_ends[x] < sorted_ends[y];
  });
  // distance of (x, y) to the line of segment r
  auto off_line = [&](std::size_t r, double x, double y) {
    const auto& c = input[r];
    return std::abs((c[2] - c[0]) * (y - c[1]) - (c[3] - c[1]) * (x - c[0])) / length[r];
  };
  // The references are found by angle and by offset: a segment whose endpoints q are within
  // `distance` of a line at an angle within `window` of its own has offsets (signed distances of
  // the lines from a center, along the normal of the angle) that differ by at most
  // distance + window |q - center|. By angle alone, the search would be quadratic for a street
  // grid at an angle (thousands of parallel lines). Bins of angles, in each the references by
  // offset.
  double center[2] = {0, 0};
  for(const auto& c : input) { center[0] += (c[0] + c[2]) / (2. * double(n)); center[1] += (c[1] + c[3]) / (2. * double(n)); }
  auto offset = [&](double a, double x, double y) { return -std::sin(a) * (x - center[0]) + std::cos(a) * (y - center[1]); };
  const double bin_width = 1e-3;
  auto bin_of = [&](double a) { return static_cast<long long>(std::floor(a / bin_width)); };
  std::map<long long, std::multimap<double, std::size_t>> references; // angle bin -> offset -> rank in `order`
  for(std::size_t rank = 0; rank < n; ++rank) {
    const std::size_t s = order[rank];
    // a segment not much longer than the distance has no meaningful direction at that distance:
    // it joins a group only when its endpoints are within 1e-6 of its length of the group's line
    // (nearly the same line: the points computed from two such lines would be ill-conditioned);
    // the segments are taken by decreasing length, so only shorter ones can join its group
    const bool is_long = length[s] > 4 * distance;
    const double reach = is_long ? distance : std::min(distance, 1e-6 * length[s]);
    const double window = std::asin(std::min(1., 2 * reach / length[s])) + 1e-12;
    const auto& c = input[s];
    const double own_offset = offset(angle[s], c[0], c[1]);
    const double radius = (std::max)(std::hypot(c[0] - center[0], c[1] - center[1]),
                                     std::hypot(c[2] - center[0], c[3] - center[1]));
    const double slack = (reach + window * radius) * (1 + 1e-9) + 1e-12 * (radius + std::abs(center[0]) + std::abs(center[1]));
    std::size_t best = n; // the longest matching reference (smallest rank)
    // the references with an angle in [low, high] and an offset within `slack` of `around`
    auto scan = [&](double low, double high, double around) {
      for(auto bin = references.lower_bound(bin_of(low)); bin != references.end() && bin->first <= bin_of(high); ++bin)
        for(auto it = bin->second.lower_bound(around - slack); it != bin->second.end() && it->first <= around + slack; ++it) {
          if(it->second >= best) continue;
          const std::size_t r = order[it->second];
          if(angle[r] < low || angle[r] > high) continue;
          if(off_line(r, c[0], c[1]) <= reach && off_line(r, c[2], c[3]) <= reach) best = it->second;
        }
    };
    scan(angle[s] - window, angle[s] + window, own_offset);
    // across the angle pi, normals are opposite: so are offsets
    if(angle[s] - window < 0) scan(angle[s] - window + pi, pi, -own_offset);
    if(angle[s] + window >= pi) scan(0, angle[s] + window - pi, -own_offset);
    if(best != n) reference[s] = order[best];
    else references[bin_of(angle[s])].emplace(offset(angle[s], c[0], c[1]), rank);
  }
  return reference;
}

// The exact segments of `input`, those of a group (`reference`, from collinear_groups())
// moved onto the line of its longest segment (their endpoints projected on it), in `EK`, a
// kernel with exact constructions.
template <class EK>
std::vector<typename EK::Segment_2>
snap_collinear_segments(const std::vector<std::array<double, 4>>& input, const std::vector<std::size_t>& reference)
{
  std::vector<typename EK::Segment_2> result;
  result.reserve(input.size());
  for(const auto& c : input) result.emplace_back(typename EK::Point_2(c[0], c[1]), typename EK::Point_2(c[2], c[3]));
  for(std::size_t s = 0; s < input.size(); ++s) {
    if(reference[s] == s) continue;
    const auto& c = input[reference[s]];
    const typename EK::Line_2 line(typename EK::Point_2(c[0], c[1]), typename EK::Point_2(c[2], c[3]));
    const typename EK::Point_2& p = result[s].source();
    const typename EK::Point_2& q = result[s].target();
    if(line.has_on(p) && line.has_on(q)) continue;
    result[s] = typename EK::Segment_2(line.projection(p), line.projection(q));
  }
  return result;
}

// Segments on one line that overlap (share more than a point; equal segments among them) are
// merged into their union: a segment given twice, or a wall given by two detections that
// overlap, is one segment of the partition. Overlapping pairs are found among the pairs whose
// bounding boxes meet (CGAL's box intersection), then decided with exact predicates: both
// segments on one line (by construction when they are in the same group of
// collinear_groups(), `group`), and their common part of positive length. Returns the merged
// segments (the union of each set of overlapping segments, each segment that overlaps none)
// with the group of their first member, oriented from their smaller endpoint (lexicographic
// order), sorted by their endpoints, and no two equal: an order that does not depend on the
// input order. `merged` is set to the number of segments merged into another one.
template <class EK>
std::vector<std::pair<typename EK::Segment_2, std::size_t>>
merge_overlapping_segments(const std::vector<typename EK::Segment_2>& segments, const std::vector<std::size_t>& group,
                           std::size_t& merged)
{
  using Segment = typename EK::Segment_2;
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;
  const std::size_t n = segments.size();
  std::vector<Box> boxes;
  boxes.reserve(n);
  for(std::size_t i = 0; i < n; ++i) boxes.emplace_back(segments[i].bbox(), i);
  // the parameter of p along s, in units of |s|^2
  auto along = [](const Segment& s, const typename EK::Point_2& p) { return (p - s.source()) * (s.target() - s.source()); };
  Union_find<std::size_t> sets(n);
  auto overlap = [&](const Box& a, const Box& b) {
    const std::size_t i = a.info(), j = b.info();
    const Segment& s = segments[i];
    const Segment& t = segments[j];
    if(group[i] != group[j] && !(CGAL::collinear(s.source(), s.target(), t.source()) &&
                                 CGAL::collinear(s.source(), s.target(), t.target())))
      return;
    // [t0, t1] and [0, |s|^2] share more than a point
    const auto t0 = along(s, t.source()), t1 = along(s, t.target());
    const bool increasing = CGAL::compare(t0, t1) == CGAL::SMALLER;
    const auto& low = increasing ? t0 : t1;
    const auto& high = increasing ? t1 : t0;
    if(CGAL::sign(high) == CGAL::POSITIVE && CGAL::compare(low, s.squared_length()) == CGAL::SMALLER)
      sets.unite_at_smallest(i, j);
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), overlap);
  // the union of each set: its smallest and largest endpoints (lexicographic order; they are
  // on one line)
  std::vector<std::pair<Segment, std::size_t>> result;
  std::vector<std::size_t> slot(n, n);
  for(std::size_t i = 0; i < n; ++i) {
    const typename EK::Point_2 &p = segments[i].source(), &q = segments[i].target();
    const bool reversed = CGAL::compare_xy(p, q) == CGAL::LARGER;
    const Segment s = reversed ? Segment(q, p) : segments[i];
    const std::size_t r = sets.find(i);
    if(slot[r] == n) { slot[r] = result.size(); result.emplace_back(s, group[i]); continue; }
    Segment& u = result[slot[r]].first;
    const bool lower = CGAL::compare_xy(s.source(), u.source()) == CGAL::SMALLER;
    const bool higher = CGAL::compare_xy(s.target(), u.target()) == CGAL::LARGER;
    if(lower || higher) u = Segment(lower ? s.source() : u.source(), higher ? s.target() : u.target());
  }
  merged = n - result.size();
  std::sort(result.begin(), result.end(), [](const auto& a, const auto& b) {
    const CGAL::Comparison_result c = CGAL::compare_xy(a.first.source(), b.first.source());
    return c == CGAL::SMALLER || (c == CGAL::EQUAL && CGAL::compare_xy(a.first.target(), b.first.target()) == CGAL::SMALLER);
  });
  return result;
}

// The same for the edges of polygons, whose endpoints are shared: an edge cannot be moved
// alone without opening its ring. A vertex is moved instead, onto the line of the group of each
// edge it bounds: the projection on the one such line, or the intersection of two. When that
// is not possible (three lines, or two whose intersection is farther than 4 `distance` from
// the vertex: two walls that meet at a very flat angle), the groups of the longest references
// are kept (two, or one) and the others dissolved (their edges keep their own lines), and the
// placement is done again, until every vertex is placed. The edges must not cross nor touch
// away from their common endpoints (the edges of an arrangement): a vertex lying inside another
// edge would not move with it. Vertices are identified by their exact coordinates: rings that share a vertex stay
// joined. Returns the number of edges moved onto the line of another; edges reduced to a point
// are removed. `EK`: a kernel with exact constructions.
template <class EK>
std::size_t snap_collinear_edges(std::vector<typename EK::Segment_2>& edges, double distance)
{
  std::vector<std::array<double, 4>> input;
  input.reserve(edges.size());
  for(const auto& e : edges)
    input.push_back({CGAL::to_double(e.source().x()), CGAL::to_double(e.source().y()),
                     CGAL::to_double(e.target().x()), CGAL::to_double(e.target().y())});
  std::vector<std::size_t> reference = collinear_groups(input, distance);
  const std::size_t n = edges.size();

  // the vertices, and the edges at each
  std::map<typename EK::Point_2, std::size_t> vertex_index;
  std::vector<typename EK::Point_2> vertices;
  std::vector<std::array<std::size_t, 2>> ends(n);
  for(std::size_t e = 0; e < n; ++e)
    for(int k = 0; k < 2; ++k) {
      const typename EK::Point_2& p = k == 0 ? edges[e].source() : edges[e].target();
      auto [it, inserted] = vertex_index.emplace(p, vertices.size());
      if(inserted) vertices.push_back(p);
      ends[e][k] = it->second;
    }
  std::vector<std::vector<std::size_t>> incident(vertices.size());
  for(std::size_t e = 0; e < n; ++e)
    for(std::size_t v : ends[e]) incident[v].push_back(e);

  // reference segments by decreasing length, then by their sorted endpoints (not by index:
  // the result does not depend on the input order)
  auto longer = [&](std::size_t a, std::size_t b) {
    auto key = [&](std::size_t r) {
      const auto& c = input[r];
      const std::array<double, 4> sorted =
        std::make_pair(c[0], c[1]) <= std::make_pair(c[2], c[3]) ? c : std::array<double, 4>{{c[2], c[3], c[0], c[1]}};
      return std::make_pair(-std::hypot(c[2] - c[0], c[3] - c[1]), sorted);
    };
    return key(a) < key(b);
  };
  std::vector<typename EK::Point_2> placed;
  for(;;) {
    // a group of one edge leaves its edge where it is (an edge given twice, by the two rings
    // it separates, is one edge)
    std::vector<std::size_t> members(n, 0);
    {
      std::vector<std::array<std::size_t, 3>> distinct_edges;
      for(std::size_t e = 0; e < n; ++e)
        distinct_edges.push_back({reference[e], (std::min)(ends[e][0], ends[e][1]), (std::max)(ends[e][0], ends[e][1])});
      std::sort(distinct_edges.begin(), distinct_edges.end());
      distinct_edges.erase(std::unique(distinct_edges.begin(), distinct_edges.end()), distinct_edges.end());
      for(const auto& d : distinct_edges) ++members[d[0]];
    }
    auto group_of = [&](std::size_t e) { return members[reference[e]] > 1 ? reference[e] : n; };
    placed = vertices;
    bool all_placed = true;
    std::vector<bool> dissolved(n, false);
    for(std::size_t v = 0; v < vertices.size(); ++v) {
      std::vector<std::size_t> groups;
      for(std::size_t e : incident[v])
        if(group_of(e) != n) groups.push_back(group_of(e));
      std::sort(groups.begin(), groups.end());
      groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
      if(groups.empty()) continue;
      auto line_of = [&](std::size_t r) {
        const auto& c = input[r];
        return typename EK::Line_2(typename EK::Point_2(c[0], c[1]), typename EK::Point_2(c[2], c[3]));
      };
      // the groups of the longest edges are kept: the vertex goes to the intersection of the
      // first two lines when it is close, else onto the first line; the others are dissolved
      std::sort(groups.begin(), groups.end(), [&](std::size_t a, std::size_t b) { return longer(a, b); });
      std::size_t kept = 1;
      if(groups.size() >= 2) {
        const auto x = CGAL::intersection(line_of(groups[0]), line_of(groups[1]));
        const typename EK::Point_2* p = get_if<typename EK::Point_2>(x);
        if(p != nullptr && CGAL::to_double(CGAL::squared_distance(*p, vertices[v])) <= 16 * distance * distance) {
          placed[v] = *p;
          kept = 2;
        }
      }
      if(kept == 1) {
        const typename EK::Line_2 l = line_of(groups[0]);
        if(!l.has_on(vertices[v])) placed[v] = l.projection(vertices[v]);
      }
      if(groups.size() > kept) {
        all_placed = false;
        for(std::size_t g = kept; g < groups.size(); ++g) dissolved[groups[g]] = true;
      }
    }
    if(all_placed) break;
    for(std::size_t f = 0; f < n; ++f)
      if(dissolved[reference[f]]) reference[f] = f;
  }
  std::size_t moved = 0;
  std::vector<typename EK::Segment_2> result;
  result.reserve(n);
  for(std::size_t e = 0; e < n; ++e) {
    if(reference[e] != e) ++moved;
    const typename EK::Point_2& p = placed[ends[e][0]];
    const typename EK::Point_2& q = placed[ends[e][1]];
    if(p != q) result.emplace_back(p, q);
  }
  edges.swap(result);
  return moved;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SNAP_COLLINEAR_SEGMENTS_2_H
