// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_CITY_BUILDING_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_CITY_BUILDING_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/LOD2_report.h>

#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
Which model of a building of a city tile is its best: the LOD2 pipeline's, or the LoD 1.2 block
that replaces it when the pipeline fails or gives no valid solid.
*/
enum class Building_model_status : unsigned char
{
  LOD22,          ///< a valid LoD 2.2 solid made by the LOD2 pipeline
  LOD12_FALLBACK  ///< only the LoD 1.2 block: `City_building::reason` says why
};

/*!
\ingroup PkgPolygonPartitionSimplificationRef
One building of `lod2_city_reconstruction()`: its models and what is known of it.

Both meshes carry the face property `"f:surface_type"` (`Building_surface_type`) and
`"f:building"` (`std::size_t`, equal to `id`), so that `IO::write_CityJSON()` writes them.
*/
template <class Point>
struct City_building
{
  std::size_t id = 0;                      ///< index of the building in the tile (clusters or footprints, in a fixed order)
  Building_model_status status = Building_model_status::LOD12_FALLBACK; ///< which model is valid
  std::string reason;                      ///< why the LoD 2.2 model is missing (empty when `status` is `LOD22`)
  Surface_mesh<Point> lod22;               ///< the LoD 2.2 solid: one closed, outward oriented 2-manifold; empty on fallback
  Surface_mesh<Point> lod12;               ///< the LoD 1.2 block: the footprint extruded from the ground to `roof_height_70p`
  std::size_t points = 0;                  ///< building points of the building
  std::size_t ground_points = 0;           ///< ground points around it given to the pipeline
  double ground_height = 0;                ///< median height of those ground points
  double roof_height_50p = 0;              ///< median height of the building points
  double roof_height_70p = 0;              ///< 70th percentile of the heights of the building points (as 3DBAG's LoD 1.2)
  double roof_height_max = 0;              ///< highest building point
  double rms_distance = 0;                 ///< RMS distance of the points on its roof and wall planes to the LoD 2.2 model
  LOD2_report report;                      ///< the LOD2 pipeline's report on this building (sizes and times of its stages)
};

/*!
\ingroup PkgPolygonPartitionSimplificationRef
What `lod2_city_reconstruction()` did: counts, and the time of each stage summed over the buildings.
*/
struct LOD2_city_report
{
  std::size_t points = 0;                  ///< input points
  std::size_t building_points = 0;         ///< of which in a building class
  std::size_t ground_points = 0;           ///< of which in a ground class
  std::size_t buildings = 0;               ///< buildings modelled (one `City_building` each)
  std::size_t buildings_valid = 0;         ///< of which with a valid LoD 2.2 solid
  std::size_t buildings_lod12_fallback = 0;///< of which with the LoD 1.2 block only
  std::size_t clusters_too_small = 0;      ///< clusters of building points too small to be a building (left out)
  std::size_t footprints_without_points = 0; ///< footprints that hold no building point (left out)
  double spacing = 0;                      ///< average spacing of the building points, from their density
  double cluster_distance = 0;             ///< building points closer than this are one building (without footprints)
  double split_seconds = 0;                ///< classes, spacing and the split into buildings
  double planes_seconds = 0;               ///< plane detection, summed over the buildings
  double segments_seconds = 0;             ///< 3D segments, summed over the buildings
  double partition_seconds = 0;            ///< kinetic partitions, summed over the buildings
  double simplification_seconds = 0;       ///< simplifications, summed over the buildings
  double lift_seconds = 0;                 ///< lifts, summed over the buildings
  double extrusion_seconds = 0;            ///< extrusions, summed over the buildings
  double validation_seconds = 0;           ///< validity checks and LoD 1.2 blocks, summed over the buildings
  double buildings_seconds = 0;            ///< wall-clock time of the buildings (all threads)
  double seconds = 0;                      ///< total wall-clock time
};

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_CITY_BUILDING_H
