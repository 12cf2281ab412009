// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_PLANES_3_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_PLANES_3_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
A plane of a building scene and the points on it (first stage of the LOD2 pipeline).
*/
template <class Kernel>
struct Building_plane_3
{
  typename Kernel::Plane_3 plane;   ///< the plane; its normal points up unless it is vertical
  std::vector<std::size_t> inliers; ///< indices of its points in the input range, increasing
  bool is_vertical = false;         ///< a facade: its normal is horizontal (after regularization)
};

/*!
\ingroup PkgPolygonPartitionSimplificationRef
The planes of a building scene: roofs, facades and the ground.
*/
template <class Kernel>
struct Building_planes_3
{
  std::vector<Building_plane_3<Kernel>> planes; ///< every detected plane (ground included)
  /// index of the ground in `planes` (among the planes within 20 degrees of horizontal that
  /// hold at least 2% of the points, the lowest); `planes.size()` when there is none, and the
  /// ground is then the horizontal plane `ground_level`
  std::size_t ground = 0;
  double ground_level = 0; ///< height of the lowest 5% of the points
  double spacing = 0;      ///< average distance of a point to its six nearest neighbours
};

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_PLANES_3_H
