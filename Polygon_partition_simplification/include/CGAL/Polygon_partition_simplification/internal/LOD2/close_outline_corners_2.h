// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_CLOSE_OUTLINE_CORNERS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_CLOSE_OUTLINE_CORNERS_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_segment_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// An end of a facade segment (a roof outline piece, or a line where a wall meets a roof): the
/// segment, which end (0 source, 1 target), the end and the unit direction the segment runs in
/// toward it.
struct Facade_end_2
{
  std::size_t segment;
  int end;
  std::array<double, 2> point, direction;
};

/// the end of another facade segment than `segment` nearest to `p`, within `radius`, among
/// `ends` sorted by x; ties go to the first in that order
inline std::optional<Facade_end_2> nearest_facade_end(const std::vector<Facade_end_2>& ends, std::size_t segment,
                                                      const std::array<double, 2>& p, double radius)
{
  std::optional<Facade_end_2> nearest;
  double best = radius * radius;
  auto e = std::lower_bound(ends.begin(), ends.end(), p[0] - radius,
                            [](const Facade_end_2& x, double v) { return x.point[0] < v; });
  for(; e != ends.end() && e->point[0] <= p[0] + radius; ++e) {
    if(e->segment == segment) continue;
    const double d = (e->point[0] - p[0]) * (e->point[0] - p[0]) + (e->point[1] - p[1]) * (e->point[1] - p[1]);
    if(d <= best && (!nearest || d < best)) { best = d; nearest = *e; }
  }
  return nearest;
}

/// The parameters (u, v) of the point p + u d = q + v e where two lines meet (unit directions
/// `d` and `e`), if they make at least 30 degrees.
inline std::optional<std::array<double, 2>> meeting_parameters(const std::array<double, 2>& p, const std::array<double, 2>& d,
                                                               const std::array<double, 2>& q, const std::array<double, 2>& e)
{
  const double cross = d[0] * e[1] - d[1] * e[0];
  if(std::abs(cross) < 0.5) return std::nullopt; // sin 30 degrees
  const double wx = q[0] - p[0], wy = q[1] - p[1];
  return std::array<double, 2>{{(wx * e[1] - wy * e[0]) / cross, (wx * d[1] - wy * d[0]) / cross}};
}

/// The corner where the lines of the ends `a` and `c` meet, if both ends run toward it (each end
/// is behind the corner along its direction), the two lines make at least 30 degrees, and the
/// corner is at most `reach` from each end.
inline std::optional<std::array<double, 2>> corner_ahead(const Facade_end_2& a, const Facade_end_2& c, double reach)
{
  const auto uv = meeting_parameters(a.point, a.direction, c.point, c.direction);
  if(!uv) return std::nullopt;
  const double u = (*uv)[0], v = (*uv)[1];
  if(!(u > 0 && v > 0 && u <= reach && v <= reach)) return std::nullopt;
  return std::array<double, 2>{{a.point[0] + u * a.direction[0], a.point[1] + u * a.direction[1]}};
}

/// Closes the corners that roof outlines cut off. The outline of a roof follows its points, and
/// where two sides of a building meet it often cuts the corner off with a short piece (the
/// points thin out toward a corner, and a hip or a gable splits them between two planes). The
/// kinetic partition then stops both sides on that piece, the corner is never a cell of its own,
/// and the model misses it. For each facade segment B
/// at most `longest` long, whose two ends are within `radius` of an end of another facade
/// segment (A and C, the nearest ends), the lines of A and C are extended to where they meet,
/// when both run toward that corner, they make at least 30 degrees and the corner is within the
/// length of B plus `radius` of each end: two segments are added, from the ends of A and C to
/// the corner, as facade segments of the planes of A and C. B stays, so the corner is a cell that
/// the graph cut gives to a roof or to the ground by its points: a true cut corner keeps its
/// cut. Deterministic: the segments are visited in their order, and the added ones are not
/// visited. The ends are sorted by x, so that each search scans the ends within `radius` in x.
template <class Kernel>
void close_outline_corners(std::vector<Building_segment_2<Kernel>>& segments, double radius, double longest)
{
  using Point = typename Kernel::Point_2;
  const auto point = [](const Point& p) { return std::array<double, 2>{{CGAL::to_double(p.x()), CGAL::to_double(p.y())}}; };
  std::vector<Facade_end_2> ends;
  std::vector<double> lengths(segments.size(), 0);
  for(std::size_t i = 0; i < segments.size(); ++i) {
    if(!segments[i].is_facade) continue;
    const std::array<double, 2> s = point(segments[i].segment.source()), t = point(segments[i].segment.target());
    const double length = std::hypot(t[0] - s[0], t[1] - s[1]);
    if(!(length > 0)) continue;
    lengths[i] = length;
    const std::array<double, 2> toward_target{{(t[0] - s[0]) / length, (t[1] - s[1]) / length}};
    ends.push_back({i, 0, s, {{-toward_target[0], -toward_target[1]}}});
    ends.push_back({i, 1, t, toward_target});
  }
  std::sort(ends.begin(), ends.end(), [](const Facade_end_2& x, const Facade_end_2& y) {
    return std::make_tuple(x.point[0], x.point[1], x.segment, x.end) < std::make_tuple(y.point[0], y.point[1], y.segment, y.end);
  });
  const std::size_t original = segments.size();
  for(std::size_t b = 0; b < original; ++b) {
    if(!(lengths[b] > 0) || lengths[b] > longest) continue;
    const std::optional<Facade_end_2> a = nearest_facade_end(ends, b, point(segments[b].segment.source()), radius);
    const std::optional<Facade_end_2> c = nearest_facade_end(ends, b, point(segments[b].segment.target()), radius);
    if(!a || !c || a->segment == c->segment) continue;
    const std::optional<std::array<double, 2>> corner = corner_ahead(*a, *c, lengths[b] + radius);
    if(!corner) continue;
    for(const Facade_end_2* e : {&*a, &*c}) {
      Building_segment_2<Kernel> added = segments[e->segment];
      added.segment = typename Kernel::Segment_2(Point(e->point[0], e->point[1]), Point((*corner)[0], (*corner)[1]));
      segments.push_back(added);
    }
  }
}

/// The line of a facade segment along a wall (the intersection of a wall's plane with a roof or
/// the ground): the wall's plane, the segment's source, its unit direction and its length.
struct Wall_line_2
{
  std::size_t wall;
  std::array<double, 2> source, direction;
  double length;
};

/// the wall line of `lines` nearest to `p` whose line passes within `radius` of `p` with `p`'s
/// projection within `reach` of the segment; ties go to the first
inline std::optional<Wall_line_2> nearest_wall_line(const std::vector<Wall_line_2>& lines, const std::array<double, 2>& p,
                                                    double radius, double reach)
{
  std::optional<Wall_line_2> nearest;
  double best = radius;
  for(const Wall_line_2& line : lines) {
    const double wx = p[0] - line.source[0], wy = p[1] - line.source[1];
    const double distance = std::abs(line.direction[0] * wy - line.direction[1] * wx);
    const double along = line.direction[0] * wx + line.direction[1] * wy;
    if(distance <= best && (!nearest || distance < best) && along >= -reach && along <= line.length + reach) {
      best = distance;
      nearest = line;
    }
  }
  return nearest;
}

/// Removes the pieces of roof outlines that cut across a corner of two walls whose planes are
/// detected. The segments along both walls (their intersections with the roof and the ground)
/// give the corner; a piece B of a roof's outline at most `longest` long whose two ends lie
/// within `radius` of the lines of such segments of two different walls, which meet at 30
/// degrees or more within the length of B plus `radius` of both ends, only cuts that corner off:
/// the roof's points thin out toward a convex corner, and an alpha shape bridges a concave one.
/// Kept, B makes a small corner cell whose few points weigh less in the graph cut than its two
/// walls against the one along B, so the model loses a convex corner or fills a concave one.
/// Without B, the walls' lines meet at the corner in the kinetic partition. A true cut corner of
/// a building whose walls are seen has a wall of its own. `is_vertical` tells, per plane index,
/// whether the plane is a wall. The order of the other segments is kept.
template <class Kernel>
void remove_corner_chords(std::vector<Building_segment_2<Kernel>>& segments, const std::vector<bool>& is_vertical,
                          double radius, double longest)
{
  const auto point = [](const typename Kernel::Point_2& p) {
    return std::array<double, 2>{{CGAL::to_double(p.x()), CGAL::to_double(p.y())}};
  };
  auto vertical = [&is_vertical](std::size_t plane) { return plane < is_vertical.size() && is_vertical[plane]; };
  std::vector<Wall_line_2> lines;
  for(const Building_segment_2<Kernel>& w : segments) {
    if(!w.is_facade || w.first_plane == w.second_plane || vertical(w.first_plane) == vertical(w.second_plane)) continue;
    const std::array<double, 2> s = point(w.segment.source()), t = point(w.segment.target());
    const double length = std::hypot(t[0] - s[0], t[1] - s[1]);
    if(!(length > 0)) continue;
    lines.push_back({vertical(w.first_plane) ? w.first_plane : w.second_plane, s,
                     {{(t[0] - s[0]) / length, (t[1] - s[1]) / length}}, length});
  }
  std::vector<bool> chord(segments.size(), false);
  for(std::size_t b = 0; b < segments.size(); ++b) {
    const Building_segment_2<Kernel>& piece = segments[b];
    if(!piece.is_facade || piece.first_plane != piece.second_plane) continue;
    const std::array<double, 2> s = point(piece.segment.source()), t = point(piece.segment.target());
    const double length = std::hypot(t[0] - s[0], t[1] - s[1]);
    if(!(length > 0) || length > longest) continue;
    const double reach = length + radius;
    const std::optional<Wall_line_2> a = nearest_wall_line(lines, s, radius, reach);
    const std::optional<Wall_line_2> c = nearest_wall_line(lines, t, radius, reach);
    if(!a || !c || a->wall == c->wall) continue;
    const auto uv = meeting_parameters(a->source, a->direction, c->source, c->direction);
    if(!uv) continue;
    const std::array<double, 2> corner{{a->source[0] + (*uv)[0] * a->direction[0], a->source[1] + (*uv)[0] * a->direction[1]}};
    chord[b] = std::hypot(corner[0] - s[0], corner[1] - s[1]) <= reach &&
               std::hypot(corner[0] - t[0], corner[1] - t[1]) <= reach;
  }
  std::size_t kept = 0;
  for(std::size_t i = 0; i < segments.size(); ++i)
    if(!chord[i]) segments[kept++] = segments[i];
  segments.resize(kept);
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_CLOSE_OUTLINE_CORNERS_2_H
