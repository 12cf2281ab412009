// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_GEOM_TRAITS_CHECK_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_GEOM_TRAITS_CHECK_H

#include <type_traits>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The compile-time requirements on the geometric traits of the package, stated once. The
// order on triangles is evaluated from the double coordinates of the points, with certified
// error bounds and an exact fallback: the coordinates must be doubles. A triangulation that
// the package builds itself must also have exact predicates (filtered), or it would not be a
// Delaunay triangulation.
template <class Gt>
struct Has_double_coordinates
{
  static_assert(std::is_same<typename Gt::FT, double>::value,
                "Lex_optimal_chains needs geometric traits with double coordinates, such as "
                "CGAL::Exact_predicates_inexact_constructions_kernel (or Lex_optimal_chains_traits_3 of it): "
                "the order on triangles is evaluated exactly from the double coordinates of the points. "
                "A kernel with exact constructions (Epeck) is not supported: convert the points to Epick, "
                "which represents input doubles exactly.");
  static constexpr bool value = true;
};

template <class Gt>
struct Has_exact_predicates_and_double_coordinates
{
  static_assert(Has_double_coordinates<Gt>::value, "");
  static_assert(bool(Gt::Has_filtered_predicates),
                "Lex_optimal_chains builds its Delaunay triangulation with the predicates of the geometric traits: "
                "they must be exact (filtered), as those of CGAL::Exact_predicates_inexact_constructions_kernel.");
  static constexpr bool value = true;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_GEOM_TRAITS_CHECK_H
