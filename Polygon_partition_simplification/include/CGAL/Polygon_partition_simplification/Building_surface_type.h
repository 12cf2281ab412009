// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_SURFACE_TYPE_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_SURFACE_TYPE_H

#include <CGAL/license/Polygon_partition_simplification.h>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
What a face of an LOD2 building model is: the semantic surface types of CityGML and CityJSON
(`RoofSurface`, `WallSurface`, `GroundSurface`), in the face property map `"f:surface_type"` of
the meshes written by `IO::write_CityJSON()`.
*/
enum class Building_surface_type : unsigned char
{
  ROOF = 0,   ///< a face of the roof (the lifted cells of the partition)
  WALL = 1,   ///< a vertical face, between two roof heights or between a roof and the ground
  GROUND = 2  ///< the floor of the building, where it stands on the ground
};

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_BUILDING_SURFACE_TYPE_H
