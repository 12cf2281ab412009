// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_KINETIC_PARTITION_REPORT_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_KINETIC_PARTITION_REPORT_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <cstddef>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
What `kinetic_partition_2()` did with its segments, filled when the named parameter `report`
points to one.
*/
struct Kinetic_partition_report
{
  std::size_t segments = 0;             ///< input segments
  std::size_t equal_segments = 0;       ///< input segments equal to another one (either way round), merged with it
  std::size_t overlapping_segments = 0; ///< other segments merged with a collinear segment they overlap (their union grows as one segment)
  std::size_t moved_segments = 0;       ///< segments moved onto the line of a longer one (`collinearity_distance`)
  std::size_t grown_segments = 0;       ///< segments grown by the propagation (after the merges)
  std::size_t extended_corner_ends = 0; ///< ends stopped at a corner that went on to split a cell around a chain of corners hanging at a point
  std::size_t removed_edges = 0;        ///< edges removed by the rounding to the double coordinates, to keep the partition valid (parts of features below the rounding tolerance, see the manual's section on the rounding)
  std::size_t events = 0;               ///< intersections examined by the last propagation
};

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_KINETIC_PARTITION_REPORT_H
