// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_SEGMENT_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_SEGMENT_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <cstddef>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
A 3D line segment of a building scene projected to the ground plane (section 3.2.1 of the
thesis): the intersection of two adjacent planes, or a piece of the outline of a roof plane's
points.
*/
template <class Kernel>
struct Building_segment_2
{
  typename Kernel::Segment_2 segment; ///< the segment, in the horizontal plane (x, y)
  /// the segment may lie along a facade: the intersection of a vertical plane with a
  /// non-vertical one, or a piece of a roof outline (where a roof ends, a wall goes down)
  bool is_facade = false;
  std::size_t first_plane = 0;  ///< a plane the segment comes from (index in the planes)
  std::size_t second_plane = 0; ///< the other plane of an intersection; `first_plane` for an outline
};

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_SEGMENT_2_H
