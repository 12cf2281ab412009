// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FACADE_EVIDENCE_3_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FACADE_EVIDENCE_3_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_planes_3.h>

#include <CGAL/Fuzzy_iso_box.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// Where the points of the facades put the walls of a 2.5D model: a facade point at height z
/// is on a wall when the model is lower than z in front of the facade and at least z behind it.
/// Each sample (x, y, z) says so at one place: `in_front`, the scanner saw through (x, y, z), so a
/// model higher than z there occupies empty space; `behind`, (x, y, z) is inside the building,
/// so a model lower than z there leaves out what the wall encloses.
struct Facade_evidence_3
{
  std::vector<std::array<double, 3>> in_front, behind;
};

/// The frame of a vertical plane on the ground: its point nearest to the centroid of its points,
/// its horizontal unit normal, and the extent of its points along it and in height.
struct Facade_frame_2
{
  std::array<double, 2> origin{{0, 0}}, normal{{0, 0}};
  double first = 0, last = 0;     ///< extent of the points along the facade (coordinate on the normal turned by +90 degrees)
  double bottom = 0, height = 0;  ///< 10th percentile of the heights of the points, and the 90th minus it

  double offset(double x, double y) const { return (x - origin[0]) * normal[0] + (y - origin[1]) * normal[1]; }
  double along(double x, double y) const { return -(x - origin[0]) * normal[1] + (y - origin[1]) * normal[0]; }
};

template <class Kernel>
Facade_frame_2 facade_frame(const std::vector<typename Kernel::Point_3>& points, const Building_plane_3<Kernel>& facade)
{
  Facade_frame_2 frame;
  const double a = CGAL::to_double(facade.plane.a()), b = CGAL::to_double(facade.plane.b());
  const double norm = std::hypot(a, b);
  if(norm == 0 || facade.inliers.empty()) return frame;
  frame.normal = {{a / norm, b / norm}};
  std::vector<double> heights;
  for(std::size_t i : facade.inliers) {
    frame.origin[0] += CGAL::to_double(points[i].x());
    frame.origin[1] += CGAL::to_double(points[i].y());
    heights.push_back(CGAL::to_double(points[i].z()));
  }
  frame.origin[0] /= double(facade.inliers.size());
  frame.origin[1] /= double(facade.inliers.size());
  // the centroid moved onto the plane (whose normal is horizontal, so its c is 0 or negligible)
  const double off = (a * frame.origin[0] + b * frame.origin[1] + CGAL::to_double(facade.plane.d())) / norm;
  frame.origin[0] -= off * frame.normal[0];
  frame.origin[1] -= off * frame.normal[1];
  frame.first = std::numeric_limits<double>::infinity();
  frame.last = -frame.first;
  for(std::size_t i : facade.inliers) {
    const double t = frame.along(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()));
    frame.first = std::min(frame.first, t);
    frame.last = std::max(frame.last, t);
  }
  std::sort(heights.begin(), heights.end());
  frame.bottom = heights[heights.size() / 10];
  frame.height = heights[(heights.size() * 9) / 10] - frame.bottom;
  return frame;
}

/// A kd-tree of the roof points (the points of the planes other than the ground and the facades).
using Roof_point_tree = CGAL::Kd_tree<CGAL::Search_traits_3<CGAL::Simple_cartesian<double>>>;

/// +1 when the outside of the facade is on the side of its normal, -1 on the other side, 0 when
/// the roof points do not tell. Behind a facade, the roof it carries runs on from the wall; in
/// front of it there is at most an overhanging eave before a gap (a street, a courtyard, a
/// garden), or a lower roof. So on each side the roof points above the facade's mid-height, along
/// its extent and between `step` and `step` plus its height from its plane, are counted in strips
/// of width `step` (at most 1024 strips) parallel to it; a strip is filled when it holds at least
/// a quarter of the points of the fullest strip of both sides, and the inside is the side whose
/// filled strips run farther from the wall without a gap.
inline int outward_sign(const Facade_frame_2& frame, const Roof_point_tree& roofs, double step)
{
  using Point = Roof_point_tree::Point_d;
  const double infinity = std::numeric_limits<double>::infinity();
  const double reach = step + frame.height;
  // the bounding box of the two sides, then the points on each side
  double box_min[2] = {infinity, infinity}, box_max[2] = {-infinity, -infinity};
  for(double t : {frame.first, frame.last})
    for(double s : {-reach, reach})
      for(int c = 0; c < 2; ++c) {
        const double v = frame.origin[c] + s * frame.normal[c] + t * (c == 0 ? -frame.normal[1] : frame.normal[0]);
        box_min[c] = std::min(box_min[c], v);
        box_max[c] = std::max(box_max[c], v);
      }
  std::vector<Point> found;
  roofs.search(std::back_inserter(found),
               CGAL::Fuzzy_iso_box<Roof_point_tree::Traits>(Point(box_min[0], box_min[1], frame.bottom + 0.5 * frame.height),
                                                            Point(box_max[0], box_max[1], infinity)));
  // strips of width `step`, or wider when `step` is tiny against the facade (at most 1024 strips)
  const double width = std::max(step, frame.height / 1024);
  const std::size_t strips = std::max<std::size_t>(1, std::size_t(std::ceil(frame.height / width)));
  std::array<std::vector<std::size_t>, 2> count{{std::vector<std::size_t>(strips, 0), std::vector<std::size_t>(strips, 0)}};
  for(const Point& q : found) {
    const double s = frame.offset(q.x(), q.y()), t = frame.along(q.x(), q.y());
    if(t < frame.first || t > frame.last || std::abs(s) < step || std::abs(s) >= reach) continue;
    ++count[s > 0 ? 0 : 1][std::min(strips - 1, std::size_t((std::abs(s) - step) / width))];
  }
  std::size_t fullest = 0;
  for(const auto& side : count) fullest = std::max(fullest, *std::max_element(side.begin(), side.end()));
  if(fullest == 0) return 0;
  std::array<std::size_t, 2> run{{0, 0}};
  for(int side = 0; side < 2; ++side)
    while(run[side] < strips && 4 * count[side][run[side]] >= fullest) ++run[side];
  return run[0] == run[1] ? 0 : run[0] < run[1] ? 1 : -1;
}

/// The evidence of the facades (the vertical planes): for every point of a facade,
/// `samples_per_point` points on the horizontal ray from its projection on the plane, outwards,
/// at `step`, 2 `step`, ..., at the point's height, and as many on the ray inwards.
///
/// The outside of a facade is given by `outward_sign()`; a facade it cannot orient, or with no
/// height, gives no samples. The normals of the points are not used, so the result is the same
/// for oriented, unoriented or estimated normals.
///
/// `step` should exceed the distance from a facade's plane to the partition's line along it, so
/// that the first samples lie on the right side of the wall of the model; the pipeline uses
/// `maximum_distance` (3 times the spacing by default, more than the 2 spacings within which the
/// kinetic partition puts segments on one line).
template <class Kernel>
Facade_evidence_3 facade_evidence(const std::vector<typename Kernel::Point_3>& points,
                                  const Building_planes_3<Kernel>& planes, double step, std::size_t samples_per_point = 2)
{
  Roof_point_tree roofs;
  for(std::size_t p = 0; p < planes.planes.size(); ++p)
    if(p != planes.ground && !planes.planes[p].is_vertical)
      for(std::size_t i : planes.planes[p].inliers)
        roofs.insert(Roof_point_tree::Point_d(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()),
                                              CGAL::to_double(points[i].z())));
  Facade_evidence_3 samples;
  if(roofs.empty() || !(step > 0)) return samples;
  roofs.build();
  for(const auto& facade : planes.planes) {
    if(!facade.is_vertical) continue;
    const Facade_frame_2 frame = facade_frame<Kernel>(points, facade);
    if(!(frame.height > 0)) continue;
    const int sign = outward_sign(frame, roofs, step);
    if(sign == 0) continue;
    const double nx = sign * frame.normal[0], ny = sign * frame.normal[1];
    for(std::size_t i : facade.inliers) {
      const double x = CGAL::to_double(points[i].x()), y = CGAL::to_double(points[i].y());
      const double s = sign * frame.offset(x, y);
      const double z = CGAL::to_double(points[i].z());
      for(std::size_t k = 1; k <= samples_per_point; ++k) {
        const double out = double(k) * step - s, in = -double(k) * step - s;
        samples.in_front.push_back({{x + out * nx, y + out * ny, z}});
        samples.behind.push_back({{x + in * nx, y + in * ny, z}});
      }
    }
  }
  return samples;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FACADE_EVIDENCE_3_H
