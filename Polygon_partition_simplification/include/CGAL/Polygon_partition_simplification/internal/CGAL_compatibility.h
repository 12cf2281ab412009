// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CGAL_COMPATIBILITY_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CGAL_COMPATIBILITY_H

// What the package uses of CGAL differently in CGAL 5.5 and CGAL 6.0: the only place of the
// package that tests the version of CGAL.
// - the results of intersections and point locations: boost::optional / boost::variant in 5.5,
//   std::optional / std::variant in 6.0 (`get_if()`);
// - the property maps of `Surface_mesh` and `Point_set_3` looked up by name: a pair (map, found)
//   in 5.5, an optional map in 6.0 (`optional_property_map()`);
// - the AABB tree's traits and triangle primitive, renamed with a `_3` in 6.0;
// - the region growing on points, whose headers moved in 5.6 and whose classes take the item
//   type (here a point's index) instead of the input range since then (`Point_neighbors_3`,
//   `plane_regions_by_region_growing()`). CGAL's region growing needs Eigen (5.5 and 6.0): this
//   part is there when CGAL_EIGEN3_ENABLED is defined;
// - Boost's graph headers, which CGAL 6's Polygon_mesh_processing headers include: g++ 12 at -O3
//   warns that Boost 1.74's max flow (of the package's alpha-expansion and of CGAL's) may read
//   an uninitialized edge iterator and edge descriptor, false positives located in these
//   headers. They are silenced there only, which works when the headers are read here first:
//   the package's headers include this one before CGAL's.

#include <CGAL/license/Polygon_partition_simplification.h>

#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic pop
#endif

#include <CGAL/version_macros.h>

#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
#include <CGAL/AABB_traits_3.h>
#include <CGAL/AABB_triangle_primitive_3.h>
#else
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#endif

#ifdef CGAL_EIGEN3_ENABLED
#include <CGAL/Shape_detection/Region_growing/Region_growing.h>
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(5, 6, 0)
#include <CGAL/Shape_detection/Region_growing/Point_set/K_neighbor_query.h>
#include <CGAL/Shape_detection/Region_growing/Point_set/Least_squares_plane_fit_region.h>
#include <CGAL/Shape_detection/Region_growing/Point_set/Least_squares_plane_fit_sorting.h>
#include <boost/range/irange.hpp>
#else
#include <CGAL/Shape_detection/Region_growing/Region_growing_on_point_set/K_neighbor_query.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing_on_point_set/Least_squares_plane_fit_region.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing_on_point_set/Least_squares_plane_fit_sorting.h>
#endif
#include <CGAL/property_map.h>
#endif

#include <boost/optional.hpp>
#include <boost/variant.hpp>

#include <cstddef>
#include <iterator>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// \name The results of intersections and point locations
/// the `T` held by `result`, or `nullptr`: `result` is the variant of a point location or the
/// optional variant of an intersection, of Boost (CGAL 5.5) or of the standard library (CGAL 6)
/// @{
template <class T, class... Alternatives>
const T* get_if(const boost::variant<Alternatives...>& result)
{
  return boost::get<T>(&result);
}

template <class T, class... Alternatives>
const T* get_if(const std::variant<Alternatives...>& result)
{
  return std::get_if<T>(&result);
}

template <class T, class Variant>
const T* get_if(const boost::optional<Variant>& result)
{
  return result ? get_if<T>(*result) : nullptr;
}

template <class T, class Variant>
const T* get_if(const std::optional<Variant>& result)
{
  return result ? get_if<T>(*result) : nullptr;
}
/// @}

/// \name The property maps found by name
/// the map that `Surface_mesh::property_map()` or `Point_set_3::property_map()` found, or
/// nothing: they return a pair (map, found) in CGAL 5.5 and an optional map in CGAL 6
/// @{
template <class Map>
std::optional<Map> optional_property_map(const std::pair<Map, bool>& found)
{
  return found.second ? std::optional<Map>(found.first) : std::nullopt;
}

template <class Map>
std::optional<Map> optional_property_map(const std::optional<Map>& found)
{
  return found;
}
/// @}

/// \name The AABB tree of 3D primitives
/// @{
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
template <class GeomTraits, class Primitive>
using AABB_traits_3 = CGAL::AABB_traits_3<GeomTraits, Primitive>;
template <class GeomTraits, class Iterator>
using AABB_triangle_primitive_3 = CGAL::AABB_triangle_primitive_3<GeomTraits, Iterator>;
#else
template <class GeomTraits, class Primitive>
using AABB_traits_3 = CGAL::AABB_traits<GeomTraits, Primitive>;
template <class GeomTraits, class Iterator>
using AABB_triangle_primitive_3 = CGAL::AABB_triangle_primitive<GeomTraits, Iterator>;
#endif
/// @}

#ifdef CGAL_EIGEN3_ENABLED

/// The k nearest neighbours of the points of a vector, by index, as CGAL's region growing
/// finds them (`Shape_detection::Point_set::K_neighbor_query` on a k-d tree of the indices).
template <class Kernel>
class Point_neighbors_3
{
public:
  using Point_3 = typename Kernel::Point_3;

  /// `points` must outlive the object (CGAL 5.5 reads them at each query)
  Point_neighbors_3(const std::vector<Point_3>& points, std::size_t k)
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(5, 6, 0)
    : query_(boost::irange<std::size_t>(0, points.size()),
             CGAL::parameters::k_neighbors(k).point_map(CGAL::make_property_map(points)))
#else
    : query_(points, k, Point_map())
#endif
  {}

  /// the indices of the `k` points nearest to point `i` (`i` included)
  void operator()(std::size_t i, std::vector<std::size_t>& neighbors) const { query_(i, neighbors); }

private:
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(5, 6, 0)
  using Point_map = typename CGAL::Pointer_property_map<Point_3>::const_type;
  CGAL::Shape_detection::Point_set::K_neighbor_query<Kernel, std::size_t, Point_map> query_;
#else
  using Point_map = CGAL::Identity_property_map<Point_3>;
  CGAL::Shape_detection::Point_set::K_neighbor_query<Kernel, std::vector<Point_3>, Point_map> query_;
#endif
};

/// The settings of `plane_regions_by_region_growing()`, in input units.
struct Plane_region_growing_settings
{
  std::size_t neighbors = 12;          ///< k of the k-nearest-neighbour graph
  double maximum_distance = 1;         ///< from a point to the plane of its region
  double maximum_angle = 25;           ///< degrees between a point's normal and its plane
  std::size_t minimum_region_size = 3; ///< smaller regions are dropped
};

/// the planes found by CGAL's region growing on the k-nearest-neighbour graph of the points with
/// normals `points`, seeds sorted by the quality of their local plane fit: the regions, each a
/// vector of point indices, in the order the region growing finds them
template <class Kernel>
std::vector<std::vector<std::size_t>>
plane_regions_by_region_growing(const std::vector<std::pair<typename Kernel::Point_3, typename Kernel::Vector_3>>& points,
                                const Plane_region_growing_settings& settings)
{
  using Point_with_normal = std::pair<typename Kernel::Point_3, typename Kernel::Vector_3>;
  namespace RG = CGAL::Shape_detection;
  std::vector<std::vector<std::size_t>> regions;
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(5, 6, 0)
  using Item = std::size_t;
  using Pair_map = typename CGAL::Pointer_property_map<Point_with_normal>::const_type;
  using Point_map = CGAL::Compose_property_map<Pair_map, CGAL::First_of_pair_property_map<Point_with_normal>>;
  using Normal_map = CGAL::Compose_property_map<Pair_map, CGAL::Second_of_pair_property_map<Point_with_normal>>;
  using Neighbor_query = RG::Point_set::K_neighbor_query<Kernel, Item, Point_map>;
  using Region_type = RG::Point_set::Least_squares_plane_fit_region<Kernel, Item, Point_map, Normal_map>;
  using Sorting = RG::Point_set::Least_squares_plane_fit_sorting<Kernel, Item, Neighbor_query, Point_map, Normal_map>;
  using Region_growing = RG::Region_growing<Neighbor_query, Region_type>;
  const auto items = boost::irange<std::size_t>(0, points.size());
  const Point_map point_map(CGAL::make_property_map(points));
  const Normal_map normal_map(CGAL::make_property_map(points));
  Neighbor_query neighbor_query(items, CGAL::parameters::k_neighbors(settings.neighbors).point_map(point_map));
  Region_type region_type(CGAL::parameters::maximum_distance(settings.maximum_distance)
                            .maximum_angle(settings.maximum_angle)
                            .minimum_region_size(settings.minimum_region_size)
                            .point_map(point_map)
                            .normal_map(normal_map));
  Sorting sorting(items, neighbor_query, CGAL::parameters::point_map(point_map).normal_map(normal_map));
  sorting.sort();
  Region_growing region_growing(items, sorting.ordered(), neighbor_query, region_type);
  std::vector<typename Region_growing::Primitive_and_region> found;
  region_growing.detect(std::back_inserter(found));
  for(auto& plane_and_region : found) regions.push_back(std::move(plane_and_region.second));
#else
  using Point_map = CGAL::First_of_pair_property_map<Point_with_normal>;
  using Normal_map = CGAL::Second_of_pair_property_map<Point_with_normal>;
  using Input_range = std::vector<Point_with_normal>;
  using Neighbor_query = RG::Point_set::K_neighbor_query<Kernel, Input_range, Point_map>;
  using Region_type = RG::Point_set::Least_squares_plane_fit_region<Kernel, Input_range, Point_map, Normal_map>;
  using Sorting = RG::Point_set::Least_squares_plane_fit_sorting<Kernel, Input_range, Neighbor_query, Point_map>;
  using Region_growing = RG::Region_growing<Input_range, Neighbor_query, Region_type, typename Sorting::Seed_map>;
  Neighbor_query neighbor_query(points, settings.neighbors, Point_map());
  Region_type region_type(points, settings.maximum_distance, settings.maximum_angle, settings.minimum_region_size,
                          Point_map(), Normal_map());
  Sorting sorting(points, neighbor_query, Point_map());
  sorting.sort();
  Region_growing region_growing(points, neighbor_query, region_type, sorting.seed_map());
  region_growing.detect(std::back_inserter(regions));
#endif
  return regions;
}

#endif // CGAL_EIGEN3_ENABLED

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CGAL_COMPATIBILITY_H
