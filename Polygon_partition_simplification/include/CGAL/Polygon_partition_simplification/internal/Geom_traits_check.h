// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_GEOM_TRAITS_CHECK_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_GEOM_TRAITS_CHECK_H

// The compile-time requirements on the geometric traits of the package
// (PolygonPartitionSimplificationTraits_2), stated once, each with a message that says why.
// - The user-facing kernel (FT, Point_2, Segment_2) is only read and written: its coordinates
//   must convert to double; its predicates are never used (a kernel with inexact predicates such
//   as Simple_cartesian<double> is fine: every decision is taken in the two kernels below).
// - Exact_constructions_kernel: the kinetic propagation, the snapping of nearly collinear
//   segments and the arrangements construct intersection points and projections and decide on
//   them: its number type must be an exact field type.
// - Exact_predicates_kernel: the points of a partition are computed in double from its lines and
//   every decision on them (validity, cells) is taken with its predicates: double coordinates,
//   exact (filtered) predicates.

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Real_embeddable_traits.h>
#include <CGAL/tags.h>

#include <type_traits>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

template <class EK>
struct Has_exact_constructions
{
  using FT = typename EK::FT;
  static constexpr bool value =
    bool(CGAL::Algebraic_structure_traits<FT>::Is_exact::value) &&
    std::is_base_of<CGAL::Field_tag, typename CGAL::Algebraic_structure_traits<FT>::Algebraic_category>::value;
};

template <class PK>
struct Has_exact_predicates_on_doubles
{
  static constexpr bool value = std::is_same<typename PK::FT, double>::value && bool(PK::Has_filtered_predicates);
};

// The types of a model of PolygonPartitionSimplificationTraits_2, checked.
template <class FT, class ExactConstructionsKernel, class ExactPredicatesKernel>
struct Are_geom_traits_types_checked
{
  static_assert(bool(CGAL::Real_embeddable_traits<FT>::Is_real_embeddable::value),
                "Polygon_partition_simplification: the coordinates (FT) of the geometric traits must convert "
                "to double (CGAL::to_double): the partition is normalized and simplified in double precision.");
  static_assert(Has_exact_constructions<ExactConstructionsKernel>::value,
                "Polygon_partition_simplification: the Exact_constructions_kernel of the geometric traits must "
                "have exact constructions (an exact field number type, as "
                "CGAL::Exact_predicates_exact_constructions_kernel): the kinetic propagation, the snapping of "
                "collinear segments and the arrangements construct intersection points and decide on them. "
                "A kernel with inexact constructions (Epick, Simple_cartesian<double>) is refused here; it can be "
                "the user-facing kernel, though.");
  static_assert(Has_exact_predicates_on_doubles<ExactPredicatesKernel>::value,
                "Polygon_partition_simplification: the Exact_predicates_kernel of the geometric traits must have "
                "double coordinates and exact predicates (Has_filtered_predicates), as "
                "CGAL::Exact_predicates_inexact_constructions_kernel: the points of a partition are computed in "
                "double from its lines and every decision on them (validity, cells) must be exact.");
  static constexpr bool value = true;
};

// A model of PolygonPartitionSimplificationTraits_2, checked.
template <class Gt>
struct Is_geom_traits_checked
  : Are_geom_traits_types_checked<typename Gt::FT, typename Gt::Exact_constructions_kernel,
                                  typename Gt::Exact_predicates_kernel>
{};

// The input of a function whose geometric traits are `Gt` is made of objects of type `Input`,
// expected to be `Expected` (a type of `Gt`).
template <class Input, class Expected>
struct Is_input_of_geom_traits
{
  static_assert(std::is_same<Input, Expected>::value,
                "Polygon_partition_simplification: the input must be made of the Point_2 or Segment_2 of the "
                "geometric traits (named parameter geom_traits); by default the traits are deduced from the "
                "kernel of the input.");
  static constexpr bool value = true;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_GEOM_TRAITS_CHECK_H
