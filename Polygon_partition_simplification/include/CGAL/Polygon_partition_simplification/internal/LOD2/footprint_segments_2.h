// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FOOTPRINT_SEGMENTS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FOOTPRINT_SEGMENTS_2_H

// A given footprint in the segments of a building: its edges are facade segments, and they
// replace the facade segments that stand for the same walls. A roof outline piece is drawn
// where the points of a roof plane end, and a wall plane meets a roof plane where the wall is:
// along a footprint edge either is that edge seen with the point spacing's error, and near a
// footprint corner a short outline piece cuts the corner off. Kept, such a piece makes thin
// cells between itself and the footprint edge, and a wedge cell that the lift can give to the
// wrong roof plane or to the ground (a ridge that stops short of the edge joins the far roof
// slope to the sliver beyond the near one). Only the parts along the footprint are removed: the
// wall of a step is often on the line of two footprint edges, and its middle stays. The ridges
// are extended to the footprint's boundary, where the roof ends.

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_segment_2.h>

#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

using Footprint_rings = std::vector<std::vector<std::array<double, 2>>>;

/// The parameter interval [t0, t1] of the points of segment (a, b), a + t (b - a), that are
/// within `distance` of the line of segment (p, q) and project onto (p, q) (empty when t0 > t1):
/// both conditions are linear in t.
inline std::array<double, 2> interval_along(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                            const std::array<double, 2>& p, const std::array<double, 2>& q,
                                            double distance)
{
  const double ex = q[0] - p[0], ey = q[1] - p[1], length = std::hypot(ex, ey);
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  std::array<double, 2> t{{0, 1}};
  // alpha + beta t in [low, high]
  auto restrict_to = [&t](double alpha, double beta, double low, double high) {
    if(beta == 0) {
      if(alpha < low || alpha > high) t = {{1, 0}};
      return;
    }
    double from = (low - alpha) / beta, to = (high - alpha) / beta;
    if(from > to) std::swap(from, to);
    t = {{std::max(t[0], from), std::min(t[1], to)}};
  };
  // the projection onto (p, q), in units of its length
  restrict_to(((a[0] - p[0]) * ex + (a[1] - p[1]) * ey) / length, (dx * ex + dy * ey) / length, 0, length);
  // the signed distance to the line of (p, q)
  restrict_to((ex * (a[1] - p[1]) - ey * (a[0] - p[0])) / length, (ex * dy - ey * dx) / length, -distance, distance);
  return t;
}

/// The parts of segment (a, b), as parameter intervals in increasing order, that are not along
/// an edge of `edges` (see `interval_along()`) at less than 15 degrees from it.
inline std::vector<std::array<double, 2>> parts_away_from(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                                          const std::vector<std::array<double, 4>>& edges, double distance)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
  std::vector<std::array<double, 2>> covered;
  for(const auto& e : edges) {
    const double ex = e[2] - e[0], ey = e[3] - e[1];
    if(std::abs(ex * dy - ey * dx) > std::sin(15 * CGAL_PI / 180) * std::hypot(ex, ey) * length) continue;
    const std::array<double, 2> t = interval_along(a, b, {{e[0], e[1]}}, {{e[2], e[3]}}, distance);
    if(t[0] <= t[1]) covered.push_back(t);
  }
  std::sort(covered.begin(), covered.end());
  std::vector<std::array<double, 2>> parts;
  double from = 0;
  for(const auto& t : covered) {
    if(t[0] > from) parts.push_back({{from, t[0]}});
    from = std::max(from, t[1]);
  }
  if(from < 1) parts.push_back({{from, 1}});
  return parts;
}

/// Adds the edges of `footprint` to `segments` as facades, after removing
/// - the roof outline pieces that go from a footprint edge to the next one within 4 `distance`
///   of the corner between them (the footprint says that the building fills the corner);
/// - the parts of the facade segments (roof outline pieces, lines where a wall plane meets a
///   roof plane) that run along a footprint edge: within `distance` of its line, beside it, at
///   less than 15 degrees;
/// - then the facade pieces shorter than 2 `distance` with an end within `distance` of the
///   footprint's boundary.
/// Ridges stay whole; a facade segment cut in parts is replaced by them, in place.
template <class Kernel>
void replace_outlines_by_footprint(const Footprint_rings& footprint, double distance,
                                   std::vector<Building_segment_2<Kernel>>& segments)
{
  if(footprint.empty()) return;
  using Point = typename Kernel::Point_2;
  std::vector<std::array<double, 4>> edges;
  for(const auto& ring : footprint)
    for(std::size_t i = 0; i < ring.size(); ++i) {
      const auto& p = ring[i];
      const auto& q = ring[(i + 1) % ring.size()];
      if(p != q) edges.push_back({{p[0], p[1], q[0], q[1]}});
    }
  auto near = [&](const Point& x, const std::array<double, 2>& p, const std::array<double, 2>& q) {
    const typename Kernel::Segment_2 edge(Point(p[0], p[1]), Point(q[0], q[1]));
    return CGAL::to_double(CGAL::squared_distance(x, edge)) <= distance * distance;
  };
  auto near_boundary = [&](const std::array<double, 2>& x) {
    return std::any_of(edges.begin(), edges.end(), [&](const std::array<double, 4>& e) {
      return near(Point(x[0], x[1]), {{e[0], e[1]}}, {{e[2], e[3]}});
    });
  };
  // a roof outline piece from a footprint edge to the next one, near their corner
  auto cuts_a_corner = [&](const Building_segment_2<Kernel>& s) {
    if(s.first_plane != s.second_plane) return false;
    const Point& p = s.segment.source();
    const Point& q = s.segment.target();
    for(const auto& ring : footprint)
      for(std::size_t i = 0; i < ring.size(); ++i) {
        const auto& before = ring[(i + ring.size() - 1) % ring.size()];
        const auto& corner = ring[i];
        const auto& after = ring[(i + 1) % ring.size()];
        if(((near(p, before, corner) && near(q, corner, after)) || (near(q, before, corner) && near(p, corner, after))) &&
           CGAL::to_double(CGAL::squared_distance(Point(corner[0], corner[1]), s.segment)) <= 16 * distance * distance)
          return true;
      }
    return false;
  };
  std::vector<Building_segment_2<Kernel>> kept;
  for(const Building_segment_2<Kernel>& s : segments) {
    if(!s.is_facade) {
      kept.push_back(s);
      continue;
    }
    if(cuts_a_corner(s)) continue;
    const std::array<double, 2> a{{CGAL::to_double(s.segment.source().x()), CGAL::to_double(s.segment.source().y())}};
    const std::array<double, 2> b{{CGAL::to_double(s.segment.target().x()), CGAL::to_double(s.segment.target().y())}};
    const std::vector<std::array<double, 2>> parts = parts_away_from(a, b, edges, distance);
    for(const auto& t : parts) {
      const std::array<double, 2> p{{a[0] + t[0] * (b[0] - a[0]), a[1] + t[0] * (b[1] - a[1])}};
      const std::array<double, 2> q{{a[0] + t[1] * (b[0] - a[0]), a[1] + t[1] * (b[1] - a[1])}};
      if(std::hypot(q[0] - p[0], q[1] - p[1]) < 2 * distance && (near_boundary(p) || near_boundary(q))) continue;
      Building_segment_2<Kernel> piece = s;
      if(parts.size() != 1 || t[0] != 0 || t[1] != 1)
        piece.segment = typename Kernel::Segment_2(t[0] == 0 ? s.segment.source() : Point(p[0], p[1]),
                                                   t[1] == 1 ? s.segment.target() : Point(q[0], q[1]));
      kept.push_back(piece);
    }
  }
  segments = std::move(kept);
  for(const auto& e : edges) {
    Building_segment_2<Kernel> s;
    s.segment = typename Kernel::Segment_2(Point(e[0], e[1]), Point(e[2], e[3]));
    s.is_facade = true;
    segments.push_back(s);
  }
}

/// The chord of the line through (a, b) inside `footprint` that contains the middle of (a, b),
/// as parameters [t0, t1] of a + t (b - a); empty (t0 > t1) when the middle is outside. An edge
/// counts as crossed when its ends are on different sides of the line, one side closed, so that
/// a line through a corner crosses once or twice as the boundary does.
inline std::array<double, 2> chord_in_footprint(const Footprint_rings& footprint, const std::array<double, 2>& a,
                                                const std::array<double, 2>& b)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  std::vector<double> crossings;
  for(const auto& ring : footprint)
    for(std::size_t i = 0; i < ring.size(); ++i) {
      const auto& p = ring[i];
      const auto& q = ring[(i + 1) % ring.size()];
      const double side_p = dx * (p[1] - a[1]) - dy * (p[0] - a[0]);
      const double side_q = dx * (q[1] - a[1]) - dy * (q[0] - a[0]);
      if((side_p >= 0) == (side_q >= 0)) continue;
      const double u = side_p / (side_p - side_q); // where (p, q) meets the line
      const double x = p[0] + u * (q[0] - p[0]), y = p[1] + u * (q[1] - p[1]);
      crossings.push_back(((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy));
    }
  const std::size_t before = std::size_t(std::count_if(crossings.begin(), crossings.end(), [](double t) { return t < 0.5; }));
  if(before % 2 == 0) return {{1, 0}};
  std::array<double, 2> chord{{-HUGE_VAL, HUGE_VAL}};
  for(double t : crossings) {
    if(t < 0.5)
      chord[0] = std::max(chord[0], t);
    else
      chord[1] = std::min(chord[1], t);
  }
  return chord;
}

/// Extends (or shortens) every ridge of `segments` (the line where two roof planes meet) to the
/// chord of its line inside `footprint`. A ridge found from its points stops short of the walls,
/// and a roof outline piece that its extension then meets first joins the corner beyond to the
/// wrong slope's cell; the footprint says where the roof ends.
template <class Kernel>
void extend_ridges_to_footprint(const Footprint_rings& footprint, std::vector<Building_segment_2<Kernel>>& segments)
{
  if(footprint.empty()) return;
  using Point = typename Kernel::Point_2;
  for(Building_segment_2<Kernel>& s : segments) {
    if(s.is_facade || s.first_plane == s.second_plane) continue;
    const std::array<double, 2> a{{CGAL::to_double(s.segment.source().x()), CGAL::to_double(s.segment.source().y())}};
    const std::array<double, 2> b{{CGAL::to_double(s.segment.target().x()), CGAL::to_double(s.segment.target().y())}};
    if(a == b) continue;
    const std::array<double, 2> t = chord_in_footprint(footprint, a, b);
    if(!(t[0] < t[1])) continue;
    s.segment = typename Kernel::Segment_2(Point(a[0] + t[0] * (b[0] - a[0]), a[1] + t[0] * (b[1] - a[1])),
                                           Point(a[0] + t[1] * (b[0] - a[0]), a[1] + t[1] * (b[1] - a[1])));
  }
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FOOTPRINT_SEGMENTS_2_H
