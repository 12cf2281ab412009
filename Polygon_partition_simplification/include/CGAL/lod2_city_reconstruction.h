// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LOD2_CITY_RECONSTRUCTION_H
#define CGAL_LOD2_CITY_RECONSTRUCTION_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/City_building.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/reconstruct_city.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <vector>

namespace CGAL {

/*!
\ingroup PkgPolygonPartitionSimplificationRef

reconstructs the buildings of a classified aerial LiDAR tile one at a time, as LoD 2.2 solids
by the pipeline of `lod2_building_reconstruction()` and LoD 1.2 blocks, in parallel.

<b>Buildings.</b> With `footprints`, a building is the building points inside its footprint
(a point in several footprints goes to the first). Without, the building points are split by
2D connectivity: two points are in one building when a chain of occupied grid cells of side
3 times the spacing, touching by a side or a corner, joins them (buildings that touch, as
terraced houses do, come out as one block); a cluster of fewer than 50 points is no building.
The spacing is that of the building points, from their density (the median count of points
in grid cells).

<b>One building.</b> The pipeline of `lod2_building_reconstruction()` runs on the building's
points and the ground points within 10 spacings of their bounding box, with the named
parameters of this call (the lengths left to their defaults are set from the spacing of each
building). Faces bent by the heights merged at their corners are split into triangles, and
vertices closer than 1 mm are merged (as the CityJSON writers merge them). Its model is checked as val3dity checks a solid (vertices snapped at 1 mm; every
face planar within 1 cm, of nonzero area, without a repeated vertex; one closed 2-manifold
shell, without self-intersection, oriented outwards). The LoD 1.2 block is the footprint (given,
or the floor of the LoD 2.2 solid, or the convex hull of the points when neither gives a valid
block) extruded from the median height of the ground points to the 70th percentile of the
heights of the building points (at least 1 unit above the ground). When the pipeline fails on
a building, makes more than one solid, or makes an invalid one, the building keeps its LoD 1.2
block and `City_building::reason` says why; no such failure stops the others.

<b>Determinism.</b> Buildings are numbered by their footprints, or by the lowest grid cell of
their points; each runs alone on its own points, sorted first. The result depends on neither
the number of threads nor the order of the points.

\tparam PointRange a range of points of a CGAL kernel
\tparam Point the point type of the output meshes

\param points the points of the tile; z is vertical
\param buildings the output, one element per building, by increasing `City_building::id`
\param np named parameters among those of `lod2_building_reconstruction()` (but
`plane_index_map`) and the ones listed below; `classification_map`, `footprints` or both must be given

\cgalNamedParamsBegin
  \cgalParamNBegin{classification_map}
    \cgalParamDescription{a property map associating to the elements of `points` their class (an
                          integer, as the ASPRS classes of LAS files)}
    \cgalParamType{a model of `ReadablePropertyMap` whose value type converts to `int`}
    \cgalParamDefault{none: every point is a building point, and those outside every footprint are the ground}
  \cgalParamNEnd
  \cgalParamNBegin{ground_classes}
    \cgalParamDescription{the classes of the ground points}
    \cgalParamType{`std::vector<int>`}
    \cgalParamDefault{`{2}` (ASPRS ground)}
  \cgalParamNEnd
  \cgalParamNBegin{building_classes}
    \cgalParamDescription{the classes of the building points; the points of other classes
                          (vegetation, water, unclassified) are left out}
    \cgalParamType{`std::vector<int>`}
    \cgalParamDefault{`{6}` (ASPRS building)}
  \cgalParamNEnd
  \cgalParamNBegin{footprints}
    \cgalParamDescription{the footprints of the buildings, as 3DBAG's BAG footprints or
                          OpenStreetMap give them: the edges of a building's footprint are facade
                          segments of its partition (they replace the roof outline pieces
                          along them) and the cells whose bulk is inside it are roofs, those
                          outside it ground, so the model fills it; a footprint holding fewer than 50
                          building points gives no building (counted in
                          `LOD2_city_report::footprints_without_points`)}
    \cgalParamType{a random access range of `Polygon_with_holes_2`}
    \cgalParamDefault{none: buildings found by connectivity}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{number of threads modelling buildings (with TBB); 0 for all cores}
    \cgalParamType{int}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{building_filter}
    \cgalParamDescription{which buildings to model, for example when the buildings of a tile are
                          dealt out to several processes (MPI ranks, machines): called once, after
                          the split into buildings and before any building is modelled, with the
                          ids of all the buildings by increasing id and, in the same order, their
                          numbers of building points; it returns, in that order, whether to model
                          each. The others are not in `buildings`, nor in the counts and times of
                          the buildings in the report (`points`, `building_points`,
                          `ground_points`, `spacing`, `cluster_distance`, `clusters_too_small` and
                          `footprints_without_points` are those of the whole tile). A building's
                          model does not depend on which others are modelled: calls that model
                          disjoint sets of buildings give, together, the buildings of one call
                          that models them all}
    \cgalParamType{a callable `std::vector<bool>(const std::vector<std::size_t>& ids, const std::vector<std::size_t>& points)`}
    \cgalParamDefault{every building}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the counts and the time of each stage summed over the buildings
\throws Polygon_partition_simplification::Input_error, with `buildings` unchanged, when a point
has a non-finite coordinate, a parameter is out of range, a footprint is not a simple polygon,
`building_filter` does not return one value per building, or the tile holds no building (code
`NO_BUILDING`; a filter that keeps no building is no error: `buildings` is then empty)
*/
template <class PointRange, class Point, class NamedParameters = parameters::Default_named_parameters>
Polygon_partition_simplification::LOD2_city_report
lod2_city_reconstruction(const PointRange& points,
                         std::vector<Polygon_partition_simplification::City_building<Point>>& buildings,
                         const NamedParameters& np = parameters::default_values())
{
  std::vector<Polygon_partition_simplification::City_building<Point>> result;
  const auto report = Polygon_partition_simplification::internal::reconstruct_city(points, result, np);
  buildings = std::move(result);
  return report;
}

} // namespace CGAL

#endif // CGAL_LOD2_CITY_RECONSTRUCTION_H
