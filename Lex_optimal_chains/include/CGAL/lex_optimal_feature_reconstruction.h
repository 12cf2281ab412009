// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_FEATURE_RECONSTRUCTION_H
#define CGAL_LEX_OPTIMAL_FEATURE_RECONSTRUCTION_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Feature_reconstruction_report.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Feature_reconstruction_3.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Named_function_parameters.h>

namespace CGAL {

/*!
\ingroup PkgLexOptimalChainsRef

Reconstructs a surface from points through the critical basis of the relative 2-cycles of
their Delaunay triangulation \f$K\f$ around sharp features (thesis section 4.8.3, Fig. 4.29):
1. a set \f$S\f$ of feature points: given (`feature_points`), or the points on sharp feature
   edges by the Voronoi covariance measure (`CGAL::compute_vcm()` and
   `CGAL::vcm_is_on_feature_edge()` with `feature_threshold`);
2. the subcomplex \f$B\f$ of \f$K\f$ around \f$S\f$: the vertices within the offset
   \f$\epsilon\f$ (`feature_offset`) of \f$S\f$, and the edges and triangles of \f$K\f$ on
   them whose edges are at most \f$2\epsilon\f$ long;
3. the optimal 1-cycles of \f$B\f$ whose classes form a basis of \f$H_1(B)\f$ (the critical
   basis of \f$Z^{\min}_1(B)\f$, by the reduction of \f$B\f$ with sparse columns), \f$\beta\f$ of them;
4. for each, a representative 2-chain of \f$K\f$ bounded by it (Algorithm 11) made optimal
   (Algorithm 10): the smallest chain bounded by the cycle (absolute, the thesis's choice for
   its Fig. 4.31), or, with `relative_to_features`, the smallest chain of its class relative to
   \f$B\f$; as \f$H_2(K, B) \simeq H_1(B)\f$, the relative ones form a basis of
   \f$Z^{\min}_2(K, B)\f$ (the absolute ones are independent relative to \f$B\f$ too, but
   their parts outside \f$B\f$ need not be minimal in their classes);
5. the critical basis of their span (Observation 4.54, with sparse columns), in increasing
   order; the *largest* elements are the last ones in this order (the lexicographic order of
   their triangles), not those with the most triangles.

The mesh is the union of the elements of the critical basis but the `drop_largest_elements`
largest ones (dropping the largest elements opens the holes that they close, such as
occlusions, when the holes' rims are features: see `border_features`); each face is labelled with the index of the first element that holds it. The
coefficients are in \f$\mathbb{Z}_2\f$; the faces are oriented by a traversal, and
non-manifold edges and vertices are split as in the other reconstructions.

\tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
\tparam PolygonMesh a model of `MutableFaceGraph`

\param points the input points (duplicates are merged); not modified
\param mesh receives the result (its elements removed first, its property maps kept); on success only
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map giving the point of an element of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` with value type a `Point_3` with `double` coordinates}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{feature_points}
    \cgalParamDescription{the feature set \f$S\f$ (each point taken at the nearest input point)}
    \cgalParamType{a range of `Point_3`}
    \cgalParamDefault{the points on sharp edges by the VCM}
  \cgalParamNEnd
  \cgalParamNBegin{feature_threshold}
    \cgalParamDescription{the threshold of `CGAL::vcm_is_on_feature_edge()` (the ratio of the
                          middle eigenvalue of a point's covariance to their sum)}
    \cgalParamType{`double`}
    \cgalParamDefault{0.16}
  \cgalParamNEnd
  \cgalParamNBegin{vcm_offset_radius}
    \cgalParamDescription{the offset radius of `CGAL::compute_vcm()`}
    \cgalParamType{`double`}
    \cgalParamDefault{6 times the average spacing of the points}
  \cgalParamNEnd
  \cgalParamNBegin{vcm_convolution_radius}
    \cgalParamDescription{the convolution radius of `CGAL::compute_vcm()`}
    \cgalParamType{`double`}
    \cgalParamDefault{3 times the average spacing of the points}
  \cgalParamNEnd
  \cgalParamNBegin{border_features}
    \cgalParamDescription{adds to \f$S\f$ the points on the border of the sampled surface: the
                          rim of the scan and of its holes (occlusions), where the VCM marks
                          few points. A point is on the border when its 12 nearest neighbours,
                          projected on its tangent plane (by their covariance), leave an
                          angular gap of more than 75 degrees around it. With the borders in
                          \f$S\f$, a hole's rim is a cycle of \f$B\f$ and the hole's filling
                          one element, among the largest (if the hole is wider than twice the
                          offset, which B's edges do not span). Meant for evenly sampled
                          surfaces (grids, meshes' vertices): the 12 nearest neighbours of a
                          point of a random uniform sampling leave a gap above 75 degrees at
                          most inner points, and scan lines leave gaps too (the manual gives
                          figures)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{feature_offset}
    \cgalParamDescription{the offset \f$\epsilon\f$ of \f$S\f$ that bounds \f$B\f$}
    \cgalParamType{`double`}
    \cgalParamDefault{1.5 times the average spacing of the points}
  \cgalParamNEnd
  \cgalParamNBegin{relative_to_features}
    \cgalParamDescription{optimal 2-chains relative to \f$B\f$ (their boundaries may move in
                          \f$B\f$, and they have no triangle of \f$B\f$) instead of bounded
                          by the cycles}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{drop_largest_elements}
    \cgalParamDescription{the number of largest elements of the basis (the last ones in its
                          lexicographic order) left out of the mesh}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{face_element_map}
    \cgalParamDescription{receives the element of each face of the mesh}
    \cgalParamType{a model of `WritablePropertyMap` from `boost::graph_traits<PolygonMesh>::%face_descriptor` to `std::size_t`}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return what was done, with the size of every element

\throws Lex_optimal_chains::Input_error with code `EMPTY_INPUT`, `NON_FINITE_COORDINATE`,
`TOO_FEW_POINTS` or `DEGENERATE_POINT_SET` for points that span no tetrahedron,
`NON_FINITE_COORDINATE` for a feature point too, `INVALID_PARAMETER` for a non-positive offset, radius or threshold, `EMPTY_RESULT` when
\f$B\f$ has no cycle (no feature, or an offset too small to link the features) or every
element is dropped. `mesh` is then unchanged.
*/
template <class PointRange, class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Feature_reconstruction_report
lex_optimal_feature_reconstruction(const PointRange& points, PolygonMesh& mesh,
                                   const NamedParameters& np = parameters::default_values())
{
  return Lex_optimal_chains::internal::feature_reconstruction_of_points(points, mesh, np);
}

/*!
\ingroup PkgLexOptimalChainsRef

The same reconstruction on the Delaunay triangulation `dt` of the points, which is not
modified: its finite vertices are the points (the feature points are taken at the nearest
vertex), and its triangles are those of the chains and of the mesh. `point_map` is not used;
the other named parameters are those of the function on points. The report's Delaunay time
is 0. A class derived from `Delaunay_triangulation_3` must be passed as its base (the
overload on points would otherwise be chosen).

\tparam Gt the geometric traits of the triangulation, with `double` coordinates (its
predicates should be exact, as those of `CGAL::Exact_predicates_inexact_constructions_kernel`,
for `dt` to be a Delaunay triangulation; the function's own comparisons are exact)
\tparam Tds, LocationPolicy, LockDataStructure the other parameters of the triangulation
\tparam PolygonMesh a model of `MutableFaceGraph`

\param dt the triangulation of the points, of dimension 3; not modified
\param mesh receives the result (its elements removed first, its property maps kept); on success only
\param np optional named parameters, those of the function on points but `point_map`

\throws Lex_optimal_chains::Input_error with code `TOO_FEW_POINTS` or `DEGENERATE_POINT_SET`
for a triangulation of dimension below 3, and the other errors of the function on points.
`mesh` is then unchanged.
*/
template <class Gt, class Tds, class LocationPolicy, class LockDataStructure, class PolygonMesh,
          class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Feature_reconstruction_report
lex_optimal_feature_reconstruction(const Delaunay_triangulation_3<Gt, Tds, LocationPolicy, LockDataStructure>& dt,
                                   PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  return Lex_optimal_chains::internal::feature_reconstruction_of_triangulation(dt, mesh, np);
}

} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_FEATURE_RECONSTRUCTION_H
