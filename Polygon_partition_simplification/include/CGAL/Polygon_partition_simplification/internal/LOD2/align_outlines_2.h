// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_ALIGN_OUTLINES_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_ALIGN_OUTLINES_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_planes_3.h>
#include <CGAL/Polygon_partition_simplification/Building_segment_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// A facade as seen from above: the line of a vertical plane, its unit direction, and the span
/// of its points along that direction.
struct Facade_line_2
{
  std::array<double, 2> origin{{0, 0}}, direction{{1, 0}};
  double low = 0, high = 0;
  std::size_t points = 0;
};

/// the lines of the vertical planes, the planes with the most points first (ties: lower index)
template <class Kernel>
std::vector<Facade_line_2> facade_lines(const std::vector<typename Kernel::Point_3>& points,
                                        const Building_planes_3<Kernel>& planes)
{
  std::vector<Facade_line_2> lines;
  for(const auto& plane : planes.planes) {
    if(!plane.is_vertical || plane.inliers.empty()) continue;
    const double a = CGAL::to_double(plane.plane.a()), b = CGAL::to_double(plane.plane.b());
    const double d = CGAL::to_double(plane.plane.d()), norm = std::hypot(a, b);
    if(!(norm > 0)) continue;
    Facade_line_2 line;
    line.direction = {{-b / norm, a / norm}};
    line.origin = {{-d * a / (norm * norm), -d * b / (norm * norm)}}; // the point of the line nearest (0, 0)
    line.low = std::numeric_limits<double>::infinity();
    line.high = -line.low;
    for(std::size_t i : plane.inliers) {
      const double t = (CGAL::to_double(points[i].x()) - line.origin[0]) * line.direction[0] +
                       (CGAL::to_double(points[i].y()) - line.origin[1]) * line.direction[1];
      line.low = std::min(line.low, t);
      line.high = std::max(line.high, t);
    }
    line.points = plane.inliers.size();
    lines.push_back(line);
  }
  std::stable_sort(lines.begin(), lines.end(),
                   [](const Facade_line_2& l, const Facade_line_2& m) { return l.points > m.points; });
  return lines;
}

/// the sine of the angle between `u` and `v` (unit vectors) or `v` turned by 90 degrees,
/// whichever is smaller, and that direction
inline double angle_modulo_right(const std::array<double, 2>& u, const std::array<double, 2>& v,
                                 std::array<double, 2>& nearest)
{
  const double along = std::abs(u[0] * v[1] - u[1] * v[0]);  // sine to v
  const double across = std::abs(u[0] * v[0] + u[1] * v[1]); // sine to v turned
  if(along <= across) {
    const double sign = u[0] * v[0] + u[1] * v[1] < 0 ? -1 : 1;
    nearest = {{sign * v[0], sign * v[1]}};
    return along;
  }
  const std::array<double, 2> turned{{-v[1], v[0]}};
  const double sign = u[0] * turned[0] + u[1] * turned[1] < 0 ? -1 : 1;
  nearest = {{sign * turned[0], sign * turned[1]}};
  return across;
}

/// A roof outline piece turned to the direction of a facade: its segment in the list, its
/// unit direction (pointing up, or along +x when horizontal), its middle and its length.
struct Turned_outline_2
{
  std::size_t segment = 0;
  std::array<double, 2> direction{{1, 0}}, middle{{0, 0}};
  double length = 0;
  double offset() const { return middle[1] * direction[0] - middle[0] * direction[1]; }
};

/// the direction `d` pointing up, or along +x when horizontal
inline std::array<double, 2> canonical_direction(const std::array<double, 2>& d)
{
  return d[1] < 0 || (d[1] == 0 && d[0] < 0) ? std::array<double, 2>{{-d[0], -d[1]}} : d;
}

/// the roof outline pieces within `angle` degrees of the direction of a facade line, or of its
/// normal, turned about their middle to that direction (the line with the most points first)
template <class Kernel>
std::vector<Turned_outline_2> turned_outlines(const std::vector<Building_segment_2<Kernel>>& segments,
                                              const std::vector<Facade_line_2>& lines, double angle)
{
  const double limit = std::sin(angle * CGAL_PI / 180.0);
  std::vector<Turned_outline_2> turned;
  for(std::size_t i = 0; i < segments.size(); ++i) {
    const auto& s = segments[i];
    if(s.first_plane != s.second_plane) continue; // an intersection of two planes
    const std::array<double, 2> a{{CGAL::to_double(s.segment.source().x()), CGAL::to_double(s.segment.source().y())}};
    const std::array<double, 2> b{{CGAL::to_double(s.segment.target().x()), CGAL::to_double(s.segment.target().y())}};
    Turned_outline_2 piece;
    piece.segment = i;
    piece.length = std::hypot(b[0] - a[0], b[1] - a[1]);
    if(!(piece.length > 0)) continue;
    const std::array<double, 2> u{{(b[0] - a[0]) / piece.length, (b[1] - a[1]) / piece.length}};
    for(const Facade_line_2& line : lines) {
      std::array<double, 2> direction;
      if(angle_modulo_right(u, line.direction, direction) > limit) continue;
      piece.direction = canonical_direction(direction);
      piece.middle = {{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])}};
      turned.push_back(piece);
      break;
    }
  }
  return turned;
}

/// Moves the turned pieces of one direction onto common lines: sorted by offset, the pieces
/// and facade lines within `distance` of the first of a run form one line, at the offset of its
/// facade with the most points if it has one, else at the length-weighted mean offset of its
/// pieces.
inline void make_collinear(std::vector<Turned_outline_2*>& pieces, const std::vector<Facade_line_2>& lines,
                           double distance)
{
  const std::array<double, 2> d = pieces.front()->direction;
  struct Member { double offset; Turned_outline_2* piece; std::size_t points; };
  std::vector<Member> members;
  for(Turned_outline_2* p : pieces) members.push_back({p->offset(), p, 0});
  for(const Facade_line_2& line : lines)
    if(std::abs(line.direction[0] * d[1] - line.direction[1] * d[0]) < 1e-6)
      members.push_back({line.origin[1] * d[0] - line.origin[0] * d[1], nullptr, line.points});
  std::sort(members.begin(), members.end(), [](const Member& m, const Member& n) {
    return m.offset < n.offset || (m.offset == n.offset && m.points > n.points);
  });
  for(std::size_t first = 0, last = 0; first < members.size(); first = last) {
    double weighted = 0, weights = 0, anchor = 0;
    std::size_t anchor_points = 0;
    for(last = first; last < members.size() && members[last].offset <= members[first].offset + distance; ++last) {
      if(members[last].piece == nullptr) {
        if(members[last].points > anchor_points) anchor = members[last].offset, anchor_points = members[last].points;
      } else {
        weighted += members[last].piece->length * members[last].offset;
        weights += members[last].piece->length;
      }
    }
    const double offset = anchor_points > 0 ? anchor : weighted / weights;
    for(std::size_t m = first; m < last; ++m) {
      Turned_outline_2* p = members[m].piece;
      if(p == nullptr) continue;
      const double shift = offset - members[m].offset; // along the normal (-d[1], d[0])
      p->middle = {{p->middle[0] - shift * d[1], p->middle[1] + shift * d[0]}};
    }
  }
}

/// The outlines of the roofs follow the facades. A roof outline (the Douglas-Peucker pieces of
/// an alpha shape, section 3.2.1) has the direction of its few boundary points; the facade
/// planes are fitted to many points and regularized (parallel, orthogonal). Every outline piece
/// within `angle` degrees of the direction of a facade plane, or of its normal, is turned about
/// its middle to that direction; the turned pieces of one direction within `distance` of each
/// other or of a facade line are then moved onto one line (`make_collinear()`), as the offsets
/// of the segment regularization of Bauchet and Lafarge [BL19] do. Without these moves, the
/// ragged outline of a roof becomes a staircase of short parallel walls, and the outline of a
/// lower roof and the facade above it leave a strip between them that the partition joins to
/// the ground, cutting a stepped building in two. Intersections of planes and footprint edges
/// are not moved.
template <class Kernel>
void align_outlines_with_facades(const std::vector<typename Kernel::Point_3>& points,
                                 const Building_planes_3<Kernel>& planes,
                                 std::vector<Building_segment_2<Kernel>>& segments, double angle, double distance)
{
  using Point_2 = typename Kernel::Point_2;
  const std::vector<Facade_line_2> lines = facade_lines<Kernel>(points, planes);
  if(lines.empty()) return;
  std::vector<Turned_outline_2> turned = turned_outlines<Kernel>(segments, lines, angle);
  std::vector<Turned_outline_2*> by_direction;
  for(Turned_outline_2& piece : turned) by_direction.push_back(&piece);
  auto slope = [](const Turned_outline_2* p) { return std::atan2(p->direction[1], p->direction[0]); };
  std::stable_sort(by_direction.begin(), by_direction.end(),
                   [&](const Turned_outline_2* p, const Turned_outline_2* q) { return slope(p) < slope(q); });
  for(std::size_t first = 0, last = 0; first < by_direction.size(); first = last) {
    std::vector<Turned_outline_2*> group;
    for(last = first; last < by_direction.size() && slope(by_direction[last]) - slope(by_direction[first]) < 1e-6; ++last) {
      by_direction[last]->direction = by_direction[first]->direction;
      group.push_back(by_direction[last]);
    }
    make_collinear(group, lines, distance);
  }
  for(const Turned_outline_2& p : turned) {
    const double h = 0.5 * p.length;
    segments[p.segment].segment =
      typename Kernel::Segment_2(Point_2(p.middle[0] - h * p.direction[0], p.middle[1] - h * p.direction[1]),
                                 Point_2(p.middle[0] + h * p.direction[0], p.middle[1] + h * p.direction[1]));
  }
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_ALIGN_OUTLINES_2_H
