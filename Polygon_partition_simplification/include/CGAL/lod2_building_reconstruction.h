// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LOD2_BUILDING_RECONSTRUCTION_H
#define CGAL_LOD2_BUILDING_RECONSTRUCTION_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_planes_3.h>
#include <CGAL/Polygon_partition_simplification/Building_segment_2.h>
#include <CGAL/Polygon_partition_simplification/Building_surface_type.h>
#include <CGAL/Polygon_partition_simplification/LOD2_report.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/LOD2_pipeline.h>

#include <CGAL/Surface_mesh.h>

namespace CGAL {

/*!
\ingroup PkgPolygonPartitionSimplificationRef

detects the planes of a building scene (first stage of the LOD2 pipeline, section 3.2.1 of the
thesis): from `plane_index_map` when it is given (for instance the `segment_index` property of
CGAL's `points_3/building.ply`), otherwise with CGAL's region growing on the k-nearest-neighbour
graph (`Shape_detection`, normals estimated by `pca_estimate_normals()` when `normal_map` is not
given). The planes are regularized by CGAL's `regularize_planes()` (parallelism, orthogonality and
coplanarity within 5 degrees; not its symmetry about the vertical, which tilts flat roofs and the
ground toward the slopes of pitched roofs), then those within 10 degrees of vertical are made
vertical (facades) and those within 10 degrees of horizontal horizontal. The ground is, among
the planes within 20 degrees of horizontal that hold at least 2% of the points, the one of the
lowest median height; it keeps its own least-squares fit (terrain slopes). When there is none,
the ground is the horizontal plane at the height of the lowest 5% of the points.

\tparam PointRange a range of points of a CGAL kernel `K`
\param points the points
\param np named parameters among `point_map`, `normal_map`, `plane_index_map`,
`maximum_distance`, `maximum_normal_deviation`, `minimum_region_size` (see
`lod2_building_reconstruction()`)
\throws Polygon_partition_simplification::Input_error on an empty or non-finite input
*/
template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
auto detect_building_planes_3(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  using namespace Polygon_partition_simplification::internal;
  const LOD2_input<PointRange, NamedParameters> input(points, np);
  return detect_building_planes<typename LOD2_input<PointRange, NamedParameters>::Kernel>(
    input.points, input.normals, input.plane_index, input.settings.planes);
}

/*!
\ingroup PkgPolygonPartitionSimplificationRef

the 2D segments of a building scene (section 3.2.1): for every two adjacent planes (their points
are nearest neighbours), the segment of their intersection line spanned by their points near
it, projected to the ground plane and marked as a facade when one plane is vertical and the other
is not; and, since aerial scans see few walls, the outline of each roof plane's points (a
regularized alpha shape, simplified by Douglas-Peucker), marked as facades, without the parts
that run along an intersection of the plane (within `maximum_distance`, over the intersection's
extent; parts beyond it shorter than 8 times the spacing are left out too). The outline pieces
within 5 degrees of the direction of a facade plane (or of its normal) take that direction, and
those then within twice the spacing of one line (a facade's, or each other's) are put on it.

\param points the points given to `detect_building_planes_3()`
\param planes its result
\param np the named parameters given to `detect_building_planes_3()`
*/
template <class PointRange, class Kernel, class NamedParameters = parameters::Default_named_parameters>
std::vector<Polygon_partition_simplification::Building_segment_2<Kernel>>
building_segments_2(const PointRange& points, const Polygon_partition_simplification::Building_planes_3<Kernel>& planes,
                    const NamedParameters& np = parameters::default_values())
{
  using namespace Polygon_partition_simplification::internal;
  const LOD2_input<PointRange, NamedParameters> input(points, np);
  return building_segments<Kernel>(input.points, planes, input.settings.segments_for(planes));
}

/*!
\ingroup PkgPolygonPartitionSimplificationRef

reconstructs LOD2 building models from a point cloud of buildings and the ground around them
(chapter 3 of the thesis): planes (`detect_building_planes_3()`), 2D segments
(`building_segments_2()`), their kinetic partition (`kinetic_partition_2()`), its simplification
(`simplify_polygon_partition_2()`), the lift of the cells and the extrusion. The named parameters
of `kinetic_partition_2()` and `simplify_polygon_partition_2()` are passed on; unless given,
`collinearity_distance` is twice the average spacing.

<b>Lift</b> (section 3.2.3). Every cell of the simplified partition gets a label: the ground or
a roof plane (a detected plane neither vertical nor the ground), minimizing
\f$ \sum_C E_C(L(C)) + \mu \sum_e V_e(L(C_i), L(C_j)) \f$ by alpha-expansion, with
\f$ E_C(\Pi) = \frac{A_C}{|P \cap C|} \sum_{p \in P \cap C} \min(\epsilon, |p_z - \Pi(p_x, p_y)|) \f$
over the points whose projection falls in the cell (points of facades excluded) and
\f$ V_e = p_e\, \mathrm{length}(e)\, \frac{1}{2} \sum_{i=1,2} |\Pi_k(x_i, y_i) - \Pi_l(x_i, y_i)| \f$
(Eq. 3.1 and 3.2). Where the thesis calls \f$p_e\f$ a prior that the edge is a facade, it multiplies
the cost of a height step, so here it is `facade_weight` (below 1) on edges along a facade
segment and 1 elsewhere. A cell without points costs nothing as ground and
\f$\epsilon A_C\f$ as roof. A roof plane less than `minimum_building_height` above the ground at
a corner of a cell is not a label of that cell. The outside of the partition is ground.

<b>Facades</b> (with `walls_at_facades`, beyond the thesis, whose data term sees the points
from above, so that a roof overhanging its facade pulls the wall to the roof's edge). A facade
point at height \f$z\f$ is on a wall of a 2.5D model when the model is lower than \f$z\f$ in
front of the facade and at least \f$z\f$ behind it. Every point of a vertical plane gives two
samples \f$q\f$ on the horizontal ray from its projection on the plane, outwards, at once and
twice `maximum_distance`, and two on the ray inwards, at the point's height; they enter
\f$E_C\f$ as points do (each counted in \f$|P \cap C|\f$), a sample in front costing
\f$\min(\epsilon, \max(0, \Pi(q_x, q_y) - q_z))\f$ and one behind \f$\min(\epsilon, \max(0, q_z - \Pi(q_x, q_y)))\f$. The inside of a facade is
the side where the roof points above its mid-height run on farther from it without a gap, up
to its height away; a facade that this does not orient gives no samples (normals are not used).

<b>Extrusion</b>. Cells of one label are merged; each connected set of roof cells is one
building: its roofs (the cells at their plane's height), walls between two heights or down to
the ground along every edge between two labels, and a floor on the ground. Heights closer than
`height_tolerance` at a point of the partition are made equal (a ridge gets no wall).
Every building is a closed, outward oriented 2-manifold (checked, and reported in
`LOD2_report::closed` and `LOD2_report::bounds_volume`); roofs with holes are triangulated.

\tparam PointRange a range of points of a CGAL kernel `K`
\tparam Point the point type of the output mesh

\param points the point cloud; its z axis is vertical
\param mesh the output, empty on input: the model, one connected component per building, with
the face properties `"f:surface_type"` (`Polygon_partition_simplification::Building_surface_type`),
`"f:building"` (`std::size_t`) and `"f:plane"` (`std::size_t`: the index of a roof face's plane
in the planes of `detect_building_planes_3()`, `std::size_t(-1)` for walls and floors)
\param np optional named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map associating points to the elements of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of the iterator of `PointRange` and whose value type is `K::Point_3`}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{normal_map}
    \cgalParamDescription{a property map associating normals to the elements of `points`,
                          used by the region growing}
    \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of the iterator of `PointRange` and whose value type is `K::Vector_3`}
    \cgalParamDefault{normals estimated by `pca_estimate_normals()` (12 neighbours)}
  \cgalParamNEnd
  \cgalParamNBegin{plane_index_map}
    \cgalParamDescription{a property map associating to the elements of `points` the index of
                          their plane (`int`, -1 for none), instead of the region growing}
    \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of the iterator of `PointRange` and whose value type is `int`}
    \cgalParamDefault{planes detected}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_distance}
    \cgalParamDescription{largest distance of a point to its plane (region growing), and of
                          the points that bound an intersection segment to its line}
    \cgalParamType{`double`}
    \cgalParamDefault{3 times the average spacing (distance to the 6 nearest neighbours)}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_normal_deviation}
    \cgalParamDescription{largest angle in degrees between a point's normal and its plane's
                          (`maximum_angle` is the simplification's \f$\alpha_{max}\f$)}
    \cgalParamType{`double`}
    \cgalParamDefault{20}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_region_size}
    \cgalParamDescription{smallest number of points of a plane}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{the larger of 20 and the number of points / 2000}
  \cgalParamNEnd
  \cgalParamNBegin{concurrency_weight, orthogonality_weight, collapse_distance}
    \cgalParamDescription{\f$\lambda_1\f$, \f$\lambda_2\f$, \f$\epsilon\f$ of the simplification
                          (`simplify_polygon_partition_2()`, whose other parameters are passed on too)}
    \cgalParamType{`double`}
    \cgalParamDefault{those of `simplify_polygon_partition_2()`}
  \cgalParamNEnd
  \cgalParamNBegin{height_threshold}
    \cgalParamDescription{\f$\epsilon\f$ of the data term: the vertical distance beyond which a
                          point counts the same}
    \cgalParamType{`double`}
    \cgalParamDefault{5 times the average spacing}
  \cgalParamNEnd
  \cgalParamNBegin{regularization_length}
    \cgalParamDescription{\f$\mu\f$, a length: the smallest feature to keep}
    \cgalParamType{`double`}
    \cgalParamDefault{2 times the average spacing}
  \cgalParamNEnd
  \cgalParamNBegin{facade_weight}
    \cgalParamDescription{\f$p_e\f$ on the edges along a facade segment (1 on the others)}
    \cgalParamType{`double`}
    \cgalParamDefault{0.25}
  \cgalParamNEnd
  \cgalParamNBegin{walls_at_facades}
    \cgalParamDescription{if `true`, the facade points tell the lift where the walls are (lower
                          in front of them, higher behind), so the walls stand on the facades;
                          if `false`, the lift sees the points from above only (as the thesis),
                          and walls stand at the roofs' edges}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_building_height}
    \cgalParamDescription{smallest height of a roof above the ground}
    \cgalParamType{`double`}
    \cgalParamDefault{10 times the average spacing}
  \cgalParamNEnd
  \cgalParamNBegin{height_tolerance}
    \cgalParamDescription{heights closer than this at a point of the partition are made one
                          (no wall between them); at most half of `minimum_building_height`}
    \cgalParamType{`double`}
    \cgalParamDefault{the average spacing}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what was done, with the time of each stage
\throws Polygon_partition_simplification::Input_error when the input is empty, has a non-finite
coordinate, has no horizontal extent, gives no roof plane or no segment, or a parameter is out
of range; `mesh` is then unchanged
\throws std::logic_error, with `mesh` unchanged, when the kinetic partition comes out invalid
(a defect of this package, found on no test input; see the manual's limitations)
*/
template <class PointRange, class Point, class NamedParameters = parameters::Default_named_parameters>
Polygon_partition_simplification::LOD2_report
lod2_building_reconstruction(const PointRange& points, Surface_mesh<Point>& mesh,
                             const NamedParameters& np = parameters::default_values())
{
  return Polygon_partition_simplification::internal::reconstruct_lod2(points, mesh, np);
}

} // namespace CGAL

#endif // CGAL_LOD2_BUILDING_RECONSTRUCTION_H
