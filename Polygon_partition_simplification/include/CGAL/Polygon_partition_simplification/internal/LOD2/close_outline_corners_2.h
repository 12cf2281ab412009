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

/// The corner where the lines of the ends `a` and `c` meet, if both ends run toward it (each end
/// is behind the corner along its direction), the two lines make at least 30 degrees, and the
/// corner is at most `reach` from each end.
inline std::optional<std::array<double, 2>> corner_ahead(const Facade_end_2& a, const Facade_end_2& c, double reach)
{
  const double cross = a.direction[0] * c.direction[1] - a.direction[1] * c.direction[0];
  if(std::abs(cross) < 0.5) return std::nullopt; // sin 30 degrees
  // a.point + u a.direction = c.point + v c.direction
  const double wx = c.point[0] - a.point[0], wy = c.point[1] - a.point[1];
  const double u = (wx * c.direction[1] - wy * c.direction[0]) / cross;
  const double v = (wx * a.direction[1] - wy * a.direction[0]) / cross;
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

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_CLOSE_OUTLINE_CORNERS_2_H
