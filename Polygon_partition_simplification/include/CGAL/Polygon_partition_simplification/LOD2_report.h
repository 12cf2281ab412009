// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_LOD2_REPORT_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_LOD2_REPORT_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <cstddef>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
What `lod2_building_reconstruction()` did: the size of each stage, its time, and the checks of
the model.
*/
struct LOD2_report
{
  std::size_t points = 0;          ///< input points
  std::size_t planes = 0;          ///< planes detected or read (ground and facades included)
  std::size_t roof_planes = 0;     ///< planes that can carry a roof (neither vertical nor the ground)
  std::size_t segments = 0;        ///< 2D segments given to the kinetic partition
  std::size_t facade_segments = 0; ///< of which along a facade
  std::size_t cells_before = 0;    ///< cells of the kinetic partition
  std::size_t cells_after = 0;     ///< cells after the simplification
  std::size_t buildings = 0;       ///< closed meshes in the model (one per building)
  std::size_t faces = 0;           ///< faces of the model
  std::size_t roof_faces = 0;      ///< of which roofs
  std::size_t wall_faces = 0;      ///< of which walls
  std::size_t repaired_buildings = 0; ///< buildings whose polygons met more than two at an edge or a corner and were made manifold by CGAL's `orient_polygon_soup()` (points duplicated)
  bool closed = false;             ///< every building is a closed 2-manifold (`is_closed()`)
  bool bounds_volume = false;      ///< every building, triangulated, has no self-intersection and bounds a volume
  std::size_t measured_points = 0; ///< points on the planes other than the ground, whose distances to the model are measured
  double rms_distance = 0;         ///< root mean square distance of the measured points to the model
  double maximum_distance = 0;     ///< largest distance of a measured point to the model (one-sided Hausdorff)
  double planes_seconds = 0;         ///< plane detection and regularization
  double segments_seconds = 0;       ///< 3D line segments
  double partition_seconds = 0;      ///< kinetic partition
  double simplification_seconds = 0; ///< simplification of the partition
  double lift_seconds = 0;           ///< labeling of the cells
  double extrusion_seconds = 0;      ///< extrusion, mesh and checks
  double seconds = 0;                ///< total
};

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_LOD2_REPORT_H
