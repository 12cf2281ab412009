// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_TRAITS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_TRAITS_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/internal/Geom_traits_check.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <type_traits>

namespace CGAL {

/*!
\ingroup PkgPolygonPartitionSimplificationRef

The model of `PolygonPartitionSimplificationTraits_2` that the package uses by default: the
kernel `K` for the input and the output (points, segments, cells), `ExactConstructionsKernel`
for the exact constructions, and `Exact_predicates_inexact_constructions_kernel` for the exact
predicates on the double points of a partition. It derives from `K`, so it is also a model of
`Kernel`.

`Line_partition_2<K>`, for a kernel `K`, is `Line_partition_2` with the traits
`Polygon_partition_simplification_traits_2<K>`; the functions of the package deduce `K` from
their input with `Kernel_traits` when the named parameter `geom_traits` is not given.

\tparam K a CGAL kernel (a model of `Kernel`); its predicates need not be exact and its
constructions may be exact (`Simple_cartesian<double>`, `Exact_predicates_inexact_constructions_kernel`,
`Exact_predicates_exact_constructions_kernel`)
\tparam ExactConstructionsKernel a CGAL kernel with exact constructions (an exact field number
type); another kernel (`Exact_predicates_inexact_constructions_kernel`) is refused at compile
time with a message that says why. The lazy kernel of the default is the fast one;
`Simple_cartesian<Exact_rational>` gives the same results, more slowly.

\cgalModels `PolygonPartitionSimplificationTraits_2`
*/
template <class K, class ExactConstructionsKernel = Exact_predicates_exact_constructions_kernel>
class Polygon_partition_simplification_traits_2 : public K
{
public:
  /// \name Types
  /// @{

  /// the kernel `K`
  typedef K Kernel;
  /// the number type of `K`
  typedef typename K::FT FT;
  /// the point type of `K`
  typedef typename K::Point_2 Point_2;
  /// the segment type of `K`
  typedef typename K::Segment_2 Segment_2;
  /// `CGAL::Polygon_2<K>`
  typedef CGAL::Polygon_2<K> Polygon_2;
  /// `CGAL::Polygon_with_holes_2<K>`
  typedef CGAL::Polygon_with_holes_2<K> Polygon_with_holes_2;
  /// `ExactConstructionsKernel`
  typedef ExactConstructionsKernel Exact_constructions_kernel;
  /// `Exact_predicates_inexact_constructions_kernel`
  typedef Exact_predicates_inexact_constructions_kernel Exact_predicates_kernel;

  /// @}

  /// \name Creation
  /// @{

  /// the traits of the kernel `k` (its functors, from which those of the concept come)
  Polygon_partition_simplification_traits_2(const K& k = K()) : K(k) {}

  /// @}

private:
  static_assert(Polygon_partition_simplification::internal::Are_geom_traits_types_checked<
                  FT, Exact_constructions_kernel, Exact_predicates_kernel>::value, "");
};

} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_TRAITS_2_H
