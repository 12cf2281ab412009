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

/// The evidence of the facades (the vertical planes): for every point of a facade,
/// `samples_per_point` points on the horizontal ray from its projection on the plane, outwards,
/// at `step`, 2 `step`, ..., at the point's height, and as many on the ray inwards.
///
/// The outside of a facade is the side with fewer roof points (points of planes other than the
/// ground and the facades) above its mid-height, in the strip between `step` and `step` plus the
/// facade's height from its plane, along its extent: behind a facade is the roof it carries, in
/// front of it at most an overhanging eave, narrower than the wall is high, or a lower roof. A
/// facade with as many roof points on both sides gives no samples. The normals of the points are
/// not used, so the result is the same for oriented, unoriented or estimated normals.
///
/// `step` must exceed the distance from a facade's plane to the partition's line along it, so
/// that the first samples lie on the right side of the wall of the model; the pipeline uses the
/// largest distance of a point to its plane.
template <class Kernel>
Facade_evidence_3 facade_evidence(const std::vector<typename Kernel::Point_3>& points,
                                  const Building_planes_3<Kernel>& planes, double step, std::size_t samples_per_point = 2)
{
  using Tree_kernel = CGAL::Simple_cartesian<double>;
  using Traits = CGAL::Search_traits_3<Tree_kernel>;
  using Tree = CGAL::Kd_tree<Traits>;
  using Box = CGAL::Fuzzy_iso_box<Traits>;
  Tree roofs;
  for(std::size_t p = 0; p < planes.planes.size(); ++p)
    if(p != planes.ground && !planes.planes[p].is_vertical)
      for(std::size_t i : planes.planes[p].inliers)
        roofs.insert(Tree_kernel::Point_3(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()),
                                          CGAL::to_double(points[i].z())));
  Facade_evidence_3 samples;
  if(roofs.empty() || !(step > 0)) return samples;
  roofs.build();
  const double infinity = std::numeric_limits<double>::infinity();
  for(const auto& facade : planes.planes) {
    if(!facade.is_vertical) continue;
    const Facade_frame_2 frame = facade_frame<Kernel>(points, facade);
    if(!(frame.height > 0)) continue;
    // the bounding box of the two strips, then the points in each strip
    const double reach = step + frame.height;
    double box_min[2] = {infinity, infinity}, box_max[2] = {-infinity, -infinity};
    for(double t : {frame.first, frame.last})
      for(double s : {-reach, reach})
        for(int c = 0; c < 2; ++c) {
          const double v = frame.origin[c] + s * frame.normal[c] + t * (c == 0 ? -frame.normal[1] : frame.normal[0]);
          box_min[c] = std::min(box_min[c], v);
          box_max[c] = std::max(box_max[c], v);
        }
    const double low = frame.bottom + 0.5 * frame.height;
    std::vector<Tree_kernel::Point_3> found;
    roofs.search(std::back_inserter(found), Box(Tree_kernel::Point_3(box_min[0], box_min[1], low),
                                                Tree_kernel::Point_3(box_max[0], box_max[1], infinity)));
    std::size_t on_normal_side = 0, on_other_side = 0;
    for(const auto& q : found) {
      const double s = frame.offset(q.x(), q.y()), t = frame.along(q.x(), q.y());
      if(t < frame.first || t > frame.last || std::abs(s) <= step || std::abs(s) > reach) continue;
      ++(s > 0 ? on_normal_side : on_other_side);
    }
    if(on_normal_side == on_other_side) continue;
    const double sign = on_normal_side < on_other_side ? 1 : -1;
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
