// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETERS_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETERS_H

#include <CGAL/license/Polygon_partition_simplification.h>

// Named parameters of this package that CGAL 5.5 does not have. Each `foo(x)` starts a
// pack and `foo(x, np)` appends to one; CGAL's own parameters are re-exported, so
// `Polygon_partition_simplification::parameters::maximum_angle(5)` works as well.

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal_np {

enum concurrency_weight_t { concurrency_weight };
enum orthogonality_weight_t { orthogonality_weight };
enum collapse_distance_t { collapse_distance };
enum point_merge_distance_t { point_merge_distance };
enum line_merge_distance_t { line_merge_distance };
enum initial_step_t { initial_step };
enum step_ratio_t { step_ratio };
enum minimum_step_t { minimum_step };
enum maximum_number_of_crossings_t { maximum_number_of_crossings };
enum crossing_distance_t { crossing_distance };
enum bounding_box_margin_t { bounding_box_margin };
enum collinearity_distance_t { collinearity_distance };
enum maximum_distance_t { maximum_distance };
enum minimum_region_size_t { minimum_region_size };
enum height_threshold_t { height_threshold };
enum regularization_length_t { regularization_length };
enum facade_weight_t { facade_weight };
enum minimum_building_height_t { minimum_building_height };
enum height_tolerance_t { height_tolerance };
enum remove_far_points_t { remove_far_points };
enum walls_at_facades_t { walls_at_facades };
enum report_t { report };
enum classification_map_t { classification_map };
enum ground_classes_t { ground_classes };
enum building_classes_t { building_classes };
enum footprints_t { footprints };
enum number_of_threads_t { number_of_threads };
enum building_filter_t { building_filter };

} // namespace internal_np

namespace parameters {

using namespace CGAL::parameters;

#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(NAME)                                    \
  template <class T>                                                                              \
  Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& t)                           \
  {                                                                                               \
    return Named_function_parameters<T, internal_np::NAME##_t>(t);                                \
  }                                                                                               \
  template <class T, class U, class Tag, class Base>                                              \
  Named_function_parameters<T, internal_np::NAME##_t, Named_function_parameters<U, Tag, Base>>    \
  NAME(const T& t, const Named_function_parameters<U, Tag, Base>& np)                            \
  {                                                                                               \
    return Named_function_parameters<T, internal_np::NAME##_t,                                    \
                                     Named_function_parameters<U, Tag, Base>>(t, np);             \
  }

/// \f$\lambda_1\f$, weight of the concurrency (edge collapse) term
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(concurrency_weight)
/// \f$\lambda_2\f$, weight of the orthogonality term
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(orthogonality_weight)
/// \f$\epsilon\f$, the largest length of an edge whose collapse is wanted (input units)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(collapse_distance)
/// \f$d_P\f$, distance below which two points are merged (input units)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(point_merge_distance)
/// \f$d_L\f$, distance below which two normalized lines are merged
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(line_merge_distance)
/// \f$\alpha_0\f$, the first gradient step of each descent
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(initial_step)
/// \f$r\f$, ratio of the geometric step sequence \f$\alpha_k = \alpha_0 r^k\f$
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(step_ratio)
/// \f$\alpha_{min}\f$, the step at which a descent stops
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(minimum_step)
/// number of initial segments a growing segment may cross before the next one stops it
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(maximum_number_of_crossings)
/// a growing segment crosses instead of stopping when its next intersection is closer than this
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(crossing_distance)
/// margin of the bounding rectangle of a kinetic partition, relative to its half-diagonal
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(bounding_box_margin)
/// segments within this distance of the line of a longer one are moved onto it before a
/// kinetic partition (input units)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(collinearity_distance)

/// largest distance of a point to its plane in a plane detection (input units)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(maximum_distance)
/// smallest number of points of a detected plane
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(minimum_region_size)
/// \f$\epsilon\f$ of the lift's data term (Eq. 3.1): vertical distance beyond which a point
/// counts the same (input units)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(height_threshold)
/// \f$\mu\f$ of the lift (a length: the smallest feature to keep)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(regularization_length)
/// factor of the lift's smoothness term on edges along facade segments (in [0, 1])
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(facade_weight)
/// smallest height of a roof above the ground (input units)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(minimum_building_height)
/// roof heights closer than this at a point of the partition are made equal (no wall between them)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(height_tolerance)
/// case (b2) of the thesis: remove a point sent outside the disk of the partition with its edges
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(remove_far_points)
/// the lift puts the walls on the facades whose points were seen (not at the edges of overhanging roofs)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(walls_at_facades)
/// a pointer to a report that the function fills (`Kinetic_partition_report` for `kinetic_partition_2()`)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(report)
/// property map from the points to their class (an integer, as the ASPRS classes of LAS files)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(classification_map)
/// the classes of the ground points (`std::vector<int>`)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(ground_classes)
/// the classes of the building points (`std::vector<int>`)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(building_classes)
/// the footprints of the buildings (a range of `Polygon_with_holes_2`)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(footprints)
/// number of threads of the parallel stages
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(number_of_threads)
/// which buildings of a city tile to model, chosen from the ids and sizes of all of them (a callable)
CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER(building_filter)

#undef CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETER

} // namespace parameters
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_PARAMETERS_H
