// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_GEOM_TRAITS_OF_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_GEOM_TRAITS_OF_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification_traits_2.h>

#include <type_traits>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// The geometric traits that a template argument `T` of `Line_partition_2` stands for: `T` itself
// when it is a model of PolygonPartitionSimplificationTraits_2 (it has an
// `Exact_constructions_kernel`), `Polygon_partition_simplification_traits_2<T>` when it is a
// kernel.
template <class T, class = void>
struct Geom_traits_of
{
  using type = Polygon_partition_simplification_traits_2<T>;
};
template <class T>
struct Geom_traits_of<T, std::void_t<typename T::Exact_constructions_kernel>>
{
  using type = T;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_GEOM_TRAITS_OF_H
