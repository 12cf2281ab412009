// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_DETECT_BUILDING_PLANES_3_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_DETECT_BUILDING_PLANES_3_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_planes_3.h>
#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>

#include <CGAL/Shape_regularization/regularize_planes.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/linear_least_squares_fitting_3.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The settings of the plane detection, in input units.
struct Plane_detection_settings
{
  double maximum_distance = 0;         ///< 0: three times the average spacing
  double maximum_angle = 20;           ///< degrees between a point's normal and its plane
  std::size_t minimum_region_size = 0; ///< 0: max(20, points / 2000)
  std::size_t neighbors = 12;          ///< k of the k-nearest-neighbour graph
  double vertical_angle = 10;          ///< planes within this angle of vertical (horizontal) are made so
  double regularization_angle = 5;     ///< tolerance of `regularize_planes()` (parallel, orthogonal)
};

/// the planes of the points `points` whose `plane_index` (if not empty) gives the plane of
/// each point (-1: none), grouped in increasing index order
template <class Kernel>
std::vector<std::vector<std::size_t>> regions_of_plane_index(const std::vector<int>& plane_index,
                                                             std::size_t minimum_size)
{
  std::map<int, std::vector<std::size_t>> by_index;
  for(std::size_t i = 0; i < plane_index.size(); ++i)
    if(plane_index[i] >= 0) by_index[plane_index[i]].push_back(i);
  std::vector<std::vector<std::size_t>> regions;
  for(auto& entry : by_index)
    if(entry.second.size() >= minimum_size) regions.push_back(std::move(entry.second));
  return regions;
}

/// the planes found by CGAL's region growing on the k-nearest-neighbour graph of the points;
/// the regions are given in the order the region growing finds them (seeds sorted by the
/// quality of their local plane fit), each with its points in increasing index order
template <class Kernel>
std::vector<std::vector<std::size_t>> regions_of_region_growing(const std::vector<typename Kernel::Point_3>& points,
                                                                std::vector<typename Kernel::Vector_3> normals,
                                                                const Plane_detection_settings& settings,
                                                                double maximum_distance, std::size_t minimum_size)
{
  using Point_3 = typename Kernel::Point_3;
  using Vector_3 = typename Kernel::Vector_3;
  using Point_with_normal = std::pair<Point_3, Vector_3>;
  std::vector<Point_with_normal> range(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) range[i].first = points[i];
  using Point_map = CGAL::First_of_pair_property_map<Point_with_normal>;
  using Normal_map = CGAL::Second_of_pair_property_map<Point_with_normal>;
  if(normals.size() == points.size()) {
    for(std::size_t i = 0; i < points.size(); ++i) range[i].second = normals[i];
  } else {
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
      range, settings.neighbors, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  }
  Plane_region_growing_settings growing;
  growing.neighbors = settings.neighbors;
  growing.maximum_distance = maximum_distance;
  growing.maximum_angle = settings.maximum_angle;
  growing.minimum_region_size = minimum_size;
  std::vector<std::vector<std::size_t>> regions = plane_regions_by_region_growing<Kernel>(range, growing);
  for(auto& region : regions) std::sort(region.begin(), region.end());
  return regions;
}

/// the plane through `inliers` (least squares), its normal pointing up
template <class Kernel>
typename Kernel::Plane_3 fit_plane(const std::vector<typename Kernel::Point_3>& points,
                                   const std::vector<std::size_t>& inliers)
{
  std::vector<typename Kernel::Point_3> selected;
  selected.reserve(inliers.size());
  for(std::size_t i : inliers) selected.push_back(points[i]);
  typename Kernel::Plane_3 plane;
  CGAL::linear_least_squares_fitting_3(selected.begin(), selected.end(), plane, CGAL::Dimension_tag<0>());
  if(plane.c() < 0) plane = plane.opposite();
  return plane;
}

/// makes the nearly vertical planes vertical and the nearly horizontal ones horizontal (each
/// through the centroid of its points), so that facades project to lines and flat roofs have
/// one height
template <class Kernel>
void snap_to_vertical_and_horizontal(const std::vector<typename Kernel::Point_3>& points,
                                     Building_plane_3<Kernel>& plane, double vertical_angle)
{
  using Vector_3 = typename Kernel::Vector_3;
  const Vector_3 normal = plane.plane.orthogonal_vector();
  const double length = std::sqrt(CGAL::to_double(normal.squared_length()));
  const double nz = CGAL::to_double(normal.z()) / length;
  const double limit = std::sin(vertical_angle * CGAL_PI / 180.0);
  std::vector<typename Kernel::Point_3> selected;
  for(std::size_t i : plane.inliers) selected.push_back(points[i]);
  const typename Kernel::Point_3 centroid = CGAL::centroid(selected.begin(), selected.end());
  if(std::abs(nz) < limit) {
    plane.plane = typename Kernel::Plane_3(centroid, Vector_3(normal.x(), normal.y(), 0));
    plane.is_vertical = true;
  } else if(std::abs(nz) > std::cos(vertical_angle * CGAL_PI / 180.0)) {
    plane.plane = typename Kernel::Plane_3(centroid, Vector_3(0, 0, 1));
  }
}

/// the ground: among the planes within 20 degrees of horizontal that hold at least 2% of the
/// points, the one of the lowest median height (ties: the lower index)
template <class Kernel>
std::size_t find_ground(const std::vector<typename Kernel::Point_3>& points,
                        const std::vector<Building_plane_3<Kernel>>& planes)
{
  std::size_t ground = planes.size();
  double lowest = std::numeric_limits<double>::infinity();
  const double cos_limit = std::cos(20.0 * CGAL_PI / 180.0);
  for(std::size_t p = 0; p < planes.size(); ++p) {
    const auto normal = planes[p].plane.orthogonal_vector();
    const double nz = CGAL::to_double(normal.z()) / std::sqrt(CGAL::to_double(normal.squared_length()));
    if(planes[p].is_vertical || nz < cos_limit || 50 * planes[p].inliers.size() < points.size()) continue;
    std::vector<double> heights;
    for(std::size_t i : planes[p].inliers) heights.push_back(CGAL::to_double(points[i].z()));
    std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
    if(heights[heights.size() / 2] < lowest) {
      lowest = heights[heights.size() / 2];
      ground = p;
    }
  }
  return ground;
}

/// the planes of a building scene (section 3.2.1): from `plane_index` when it is not empty,
/// otherwise by region growing; regularized with CGAL's `regularize_planes` (parallelism,
/// orthogonality, coplanarity; its symmetry about the vertical is off: it clustered flat roofs
/// and the ground with pitched roofs), then nearly vertical planes made
/// vertical and nearly horizontal ones horizontal; the ground identified.
template <class Kernel>
Building_planes_3<Kernel> detect_building_planes(const std::vector<typename Kernel::Point_3>& points,
                                                 const std::vector<typename Kernel::Vector_3>& normals,
                                                 const std::vector<int>& plane_index,
                                                 const Plane_detection_settings& settings)
{
  Building_planes_3<Kernel> result;
  result.spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(points, 6);
  const double maximum_distance =
    settings.maximum_distance > 0 ? settings.maximum_distance : 3 * result.spacing;
  const std::size_t minimum_size = settings.minimum_region_size > 0
                                     ? settings.minimum_region_size
                                     : std::max<std::size_t>(20, points.size() / 2000);
  std::vector<std::vector<std::size_t>> regions =
    plane_index.empty() ? regions_of_region_growing<Kernel>(points, normals, settings, maximum_distance, minimum_size)
                        : regions_of_plane_index<Kernel>(plane_index, minimum_size);
  std::vector<typename Kernel::Plane_3> planes;
  std::vector<int> index_of_point(points.size(), -1);
  for(std::size_t r = 0; r < regions.size(); ++r) {
    planes.push_back(fit_plane<Kernel>(points, regions[r]));
    for(std::size_t i : regions[r]) index_of_point[i] = int(r);
  }
  if(!planes.empty())
    CGAL::Shape_regularization::Planes::regularize_planes(
      points, CGAL::Identity_property_map<typename Kernel::Point_3>(), planes,
      CGAL::Identity_property_map<typename Kernel::Plane_3>(), CGAL::make_property_map(index_of_point), Kernel(),
      true, true, true, false, settings.regularization_angle, maximum_distance);
  for(std::size_t r = 0; r < regions.size(); ++r) {
    Building_plane_3<Kernel> plane;
    plane.plane = planes[r].c() < 0 ? planes[r].opposite() : planes[r];
    plane.inliers = std::move(regions[r]);
    snap_to_vertical_and_horizontal<Kernel>(points, plane, settings.vertical_angle);
    result.planes.push_back(std::move(plane));
  }
  std::vector<double> heights;
  for(const auto& p : points) heights.push_back(CGAL::to_double(p.z()));
  std::nth_element(heights.begin(), heights.begin() + heights.size() / 20, heights.end());
  const double low_height = heights[heights.size() / 20];
  result.ground = find_ground<Kernel>(points, result.planes);
  // the ground keeps its own fit: terrain slopes, and neither the regularization (which
  // clusters it with flat roofs) nor the snapping to horizontal should tilt the floors
  if(result.ground < result.planes.size())
    result.planes[result.ground].plane = fit_plane<Kernel>(points, result.planes[result.ground].inliers);
  result.ground_level = low_height;
  return result;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_DETECT_BUILDING_PLANES_3_H
