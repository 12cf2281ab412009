// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_FEATURE_RECONSTRUCTION_H
#define CGAL_LEX_OPTIMAL_FEATURE_RECONSTRUCTION_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/lex_optimal_homologous_chain.h>
#include <CGAL/Lex_optimal_chains/Feature_reconstruction_report.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Simplex_orders.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Border_points_3.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_mesh.h>
#include <CGAL/Lex_optimal_chains/internal/Delaunay_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Feature_subcomplex_3.h>
#include <CGAL/Lex_optimal_chains/internal/Geom_traits_check.h>
#include <CGAL/Lex_optimal_chains/internal/Sparse_critical_basis.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/vcm_estimate_edges.h>
#include <CGAL/vcm_estimate_normals.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The points of `points` on sharp feature edges by the Voronoi covariance measure (CGAL's
// compute_vcm() and vcm_is_on_feature_edge()): offset radius R and convolution radius r.
template <class Point>
std::vector<Point> vcm_feature_points(const std::vector<Point>& points, double offset_radius,
                                      double convolution_radius, double threshold)
{
  std::vector<std::array<double, 6>> covariance;
  compute_vcm(points, covariance, offset_radius, convolution_radius);
  std::vector<Point> features;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(vcm_is_on_feature_edge(covariance[i], threshold)) features.push_back(points[i]);
  return features;
}

// A triangle as the indices of its vertices in the sorted points, increasing.
using Triangle_key = std::array<std::uint32_t, 3>;

// The vertex of `dt` at each feature point (the nearest one for a point that is not a vertex,
// searched from the last one found).
template <class DT, class Point>
std::vector<typename DT::Vertex_handle> feature_vertices(const DT& dt, const std::vector<Point>& features)
{
  using Vertex_handle = typename DT::Vertex_handle;
  std::vector<Vertex_handle> by_point;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) by_point.push_back(v);
  auto less = [](Vertex_handle a, Vertex_handle b) { return a->point() < b->point(); };
  std::sort(by_point.begin(), by_point.end(), less);
  std::vector<Vertex_handle> result;
  typename DT::Cell_handle hint;
  for(const Point& p : features) {
    const auto it = std::lower_bound(by_point.begin(), by_point.end(), p, [](Vertex_handle v, const Point& q) { return v->point() < q; });
    const Vertex_handle v = it != by_point.end() && (*it)->point() == p ? *it : dt.nearest_vertex(p, hint);
    hint = v->cell();
    result.push_back(v);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

// Replaces the elements of `mesh` (keeping its property maps: the element map may be one) by
// the triangle soup `soup` of `points`, oriented by a traversal, and puts in `element_map` the
// label of each face, `label` giving it by the sorted points of the face.
template <class Point, class PolygonMesh, class ElementMapPointer>
void mesh_with_elements(const std::vector<Point>& points, std::vector<std::array<std::uint32_t, 3>>& soup,
                        const std::map<std::array<Point, 3>, std::size_t>& label, PolygonMesh& mesh,
                        ElementMapPointer element_map) // a pointer, or nullptr
{
  using Face = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  PolygonMesh result;
  add_chain_soup(points, soup, false, result);
  // the descriptors first: a range of a mesh with removed elements skips them at every begin()
  const std::vector<Face> old_faces(faces(mesh).begin(), faces(mesh).end());
  for(Face f : old_faces) remove_face(f, mesh);
  const std::vector<typename boost::graph_traits<PolygonMesh>::edge_descriptor> old_edges(edges(mesh).begin(), edges(mesh).end());
  for(auto e : old_edges) remove_edge(e, mesh);
  const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> old_vertices(vertices(mesh).begin(),
                                                                                                vertices(mesh).end());
  for(auto v : old_vertices) remove_vertex(v, mesh);
  std::vector<std::pair<Face, Face>> face_pairs;
  copy_face_graph(result, mesh, parameters::face_to_face_output_iterator(std::back_inserter(face_pairs)));
  if constexpr(!std::is_same<ElementMapPointer, std::nullptr_t>::value) {
    const auto vpm = get(vertex_point, result);
    for(const auto& [from, to] : face_pairs) {
      std::array<Point, 3> corners;
      std::size_t k = 0;
      for(auto v : vertices_around_face(halfedge(from, result), result)) corners[k++] = get(vpm, v);
      std::sort(corners.begin(), corners.end());
      put(*element_map, to, label.at(corners));
    }
  }
}

// The triangles of `chains` (keys into the sorted `points`) ranked in the package's order on
// triangles: `triangles` sorted by key, `by_order[r]` the triangle of rank r, and each chain as
// the increasing ranks of its triangles, whole (`absolute`) and without those of `b_triangles`
// (sorted keys: `relative`).
template <class Point>
struct Ranked_chains
{
  std::vector<Triangle_key> triangles;
  std::vector<std::uint32_t> by_order;
  std::vector<Z2_chain> absolute, relative;

  Ranked_chains(const std::vector<Point>& points, const std::vector<std::vector<Triangle_key>>& chains,
                const std::vector<Triangle_key>& b_triangles)
    : absolute(chains.size()), relative(chains.size())
  {
    for(const auto& c : chains) triangles.insert(triangles.end(), c.begin(), c.end());
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
    const Triangle_order<Point> order(points);
    using Key = decltype(order.key({0, 1, 2}));
    std::vector<std::pair<Key, std::uint32_t>> keyed; // the radii computed once per triangle
    for(std::uint32_t i = 0; i < triangles.size(); ++i)
      keyed.emplace_back(order.key({triangles[i][0], triangles[i][1], triangles[i][2]}), i);
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return compare(a.first, b.first) == SMALLER; });
    std::vector<std::uint32_t> rank(triangles.size());
    for(std::uint32_t r = 0; r < keyed.size(); ++r) {
      by_order.push_back(keyed[r].second);
      rank[keyed[r].second] = r;
    }
    for(std::size_t i = 0; i < chains.size(); ++i) {
      for(const Triangle_key& t : chains[i]) {
        const std::uint32_t r = rank[std::size_t(std::lower_bound(triangles.begin(), triangles.end(), t) - triangles.begin())];
        absolute[i].push_back(r);
        if(!std::binary_search(b_triangles.begin(), b_triangles.end(), t)) relative[i].push_back(r);
      }
      std::sort(absolute[i].begin(), absolute[i].end());
      std::sort(relative[i].begin(), relative[i].end());
    }
  }
};

// The border points of `border_features`: the largest angular gap between a point's 12
// nearest neighbours above 75 degrees. A straight border leaves a gap of about 180 degrees,
// the corner of a rectangular hole about 90; the neighbours of an inner point of an even
// (jittered grid) sampling leave less than about 60, those of a random uniform sampling
// often more.
constexpr std::size_t border_neighbours = 12;
constexpr double border_gap = 75 * CGAL_PI / 180;

// The named parameters of lex_optimal_feature_reconstruction(), checked, with their defaults
// for the average spacing of the points.
struct Feature_settings
{
  double offset, threshold, offset_radius, convolution_radius;
  bool relative, borders;
  std::size_t drop;
};

template <class NamedParameters>
Feature_settings feature_settings(const NamedParameters& np, double spacing)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto positive = [](double value, const char* name) {
    if(!(value > 0) || !std::isfinite(value))
      throw Input_error(Input_error_code::INVALID_PARAMETER,
                        std::string("the ") + name + " must be positive and finite (it is " + std::to_string(value) + ")");
    return value;
  };
  Feature_settings f;
  f.offset = positive(choose_parameter(get_parameter(np, internal_np::feature_offset), 1.5 * spacing), "feature offset");
  f.threshold = positive(choose_parameter(get_parameter(np, internal_np::feature_threshold), 0.16), "feature threshold");
  f.offset_radius = positive(choose_parameter(get_parameter(np, internal_np::vcm_offset_radius), 6 * spacing), "VCM offset radius");
  f.convolution_radius =
    positive(choose_parameter(get_parameter(np, internal_np::vcm_convolution_radius), 3 * spacing), "VCM convolution radius");
  f.relative = choose_parameter(get_parameter(np, internal_np::relative_to_features), false);
  f.borders = choose_parameter(get_parameter(np, internal_np::border_features), false);
  f.drop = choose_parameter(get_parameter(np, internal_np::drop_largest_elements), std::size_t(0));
  return f;
}

// The stages after the triangulation, on the Delaunay triangulation `dt` of the points `pts`
// (sorted and distinct: the triangles are keyed by indices into them): the feature set S, B
// and its cycles, their chains, the critical basis and the mesh.
template <class DT, class Point, class PolygonMesh, class NamedParameters>
void reconstruct_with_features(const DT& dt, const std::vector<Point>& pts, const Feature_settings& settings,
                               PolygonMesh& mesh, const NamedParameters& np, Feature_reconstruction_report& report,
                               Stopwatch& watch)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  std::vector<Point> features;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::feature_points_t>::value) {
    for(const Point& p : get_parameter(np, internal_np::feature_points)) {
      if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        throw Input_error(Input_error_code::NON_FINITE_COORDINATE,
                               "feature point " + std::to_string(features.size()) + " has a NaN or infinite coordinate");
      features.push_back(p);
    }
  } else {
    features = vcm_feature_points(pts, settings.offset_radius, settings.convolution_radius, settings.threshold);
  }
  if(settings.borders) { // the rims of the scan and of its occlusion holes
    const std::vector<Point> borders = border_points(pts, border_neighbours, border_gap);
    report.number_of_border_points = borders.size();
    features.insert(features.end(), borders.begin(), borders.end());
  }
  report.feature_seconds = watch.lap();
  const auto vertices_of_s = internal::feature_vertices(dt, features);
  report.number_of_feature_points = vertices_of_s.size();

  // B and its optimal 1-cycles
  const internal::Feature_subcomplex_3<DT> b(dt, vertices_of_s, settings.offset);
  report.subcomplex_vertices = b.vertices.size();
  report.subcomplex_edges = b.number_of_edges;
  report.subcomplex_triangles = b.facets.size();
  const auto cycles = b.optimal_cycles();
  report.number_of_cycles = cycles.size();
  report.subcomplex_seconds = watch.lap();
  if(cycles.empty())
    throw Input_error(Input_error_code::EMPTY_RESULT,
                           "the subcomplex around the " + std::to_string(vertices_of_s.size()) +
                             " feature points has no cycle: no feature found, or an offset too small to link them");

  // a basis of Z^min_2(K, B): the optimal 2-chain of each cycle, as triangle keys
  auto key_of = [&](const typename DT::Facet& f) {
    Triangle_key k;
    for(int j = 0; j < 3; ++j)
      k[j] = std::uint32_t(std::lower_bound(pts.begin(), pts.end(), f.first->vertex((f.second + 1 + j) & 3)->point()) - pts.begin());
    std::sort(k.begin(), k.end());
    return k;
  };
  // all the cycles' chains in runs of 64 (internal/Optimal_chain_3.h)
  const auto facet_chains = settings.relative
    ? internal::optimal_chains_with_boundaries(dt, cycles, parameters::relative_facets(b.facets))
    : internal::optimal_chains_with_boundaries(dt, cycles, CGAL::parameters::default_values());
  std::vector<std::vector<Triangle_key>> chains;
  for(const auto& facets : facet_chains) {
    std::vector<Triangle_key> keys;
    for(const auto& f : facets) keys.push_back(key_of(f));
    std::sort(keys.begin(), keys.end());
    chains.push_back(std::move(keys));
  }
  report.chain_seconds = watch.lap();

  // the triangles of the chains ranked in the order of the package; the critical basis
  std::vector<Triangle_key> b_triangles;
  for(const auto& f : b.facets) b_triangles.push_back(key_of(f));
  std::sort(b_triangles.begin(), b_triangles.end());
  internal::Ranked_chains<Point> ranked(pts, chains, b_triangles);
  const internal::Z2_critical_basis basis = internal::z2_critical_basis(std::move(ranked.relative), ranked.triangles.size());
  report.basis_seconds = watch.lap();

  // the mesh: the elements but the largest ones, each face labelled by its first element
  const std::size_t kept = basis.elements.size() > settings.drop ? basis.elements.size() - settings.drop : 0;
  report.number_of_dropped_elements = basis.elements.size() - kept;
  if(kept == 0)
    throw Input_error(Input_error_code::EMPTY_RESULT, "every element of the critical basis is dropped");
  std::vector<std::uint32_t> element_of(ranked.triangles.size(), std::uint32_t(-1));
  for(std::size_t e = 0; e < basis.elements.size(); ++e) {
    internal::Z2_chain whole;
    for(std::uint32_t j : basis.sums_of[e]) whole = internal::z2_sum(whole, ranked.absolute[j]);
    report.element_sizes.push_back(whole.size());
    if(e >= kept) continue;
    for(std::uint32_t r : whole)
      if(element_of[r] == std::uint32_t(-1)) element_of[r] = std::uint32_t(e);
  }
  std::vector<std::array<std::uint32_t, 3>> soup;
  std::map<std::array<Point, 3>, std::size_t> label;
  for(std::uint32_t r = 0; r < ranked.by_order.size(); ++r) {
    if(element_of[r] == std::uint32_t(-1)) continue;
    const Triangle_key& t = ranked.triangles[ranked.by_order[r]];
    soup.push_back({t[0], t[1], t[2]});
    label[{pts[t[0]], pts[t[1]], pts[t[2]]}] = element_of[r];
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::face_element_map_t>::value) {
    const auto element_map = get_parameter(np, internal_np::face_element_map);
    internal::mesh_with_elements(pts, soup, label, mesh, &element_map);
  } else {
    internal::mesh_with_elements(pts, soup, label, mesh, nullptr);
  }
  report.mesh_vertices = std::size_t(std::distance(vertices(mesh).begin(), vertices(mesh).end()));
  report.mesh_faces = std::size_t(std::distance(faces(mesh).begin(), faces(mesh).end()));
  report.mesh_seconds = watch.lap();
}

} // namespace internal
} // namespace Lex_optimal_chains

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
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace LOC = Lex_optimal_chains;
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Point = typename boost::property_traits<Point_map>::value_type;
  using Kernel = typename Kernel_traits<Point>::Kernel;
  static_assert(LOC::internal::Has_exact_predicates_and_double_coordinates<Kernel>::value, "");
  using DT = Delaunay_triangulation_3<Kernel>;
  LOC::Feature_reconstruction_report report;
  LOC::internal::Stopwatch total, watch;
  std::vector<Point> pts = LOC::internal::finite_points<Point>(points, choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map)));
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  report.number_of_input_points = pts.size();
  if(pts.size() < 4) throw LOC::Input_error(LOC::Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");
  report.average_spacing = compute_average_spacing<Sequential_tag>(pts, 6);
  const LOC::internal::Feature_settings settings = LOC::internal::feature_settings(np, report.average_spacing);
  report.offset = settings.offset;
  const DT dt(pts.begin(), pts.end());
  LOC::internal::check_dimension(dt);
  report.delaunay_seconds = watch.lap();
  LOC::internal::reconstruct_with_features(dt, pts, settings, mesh, np, report, watch);
  report.total_seconds = total.lap();
  return report;
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
  namespace LOC = Lex_optimal_chains;
  static_assert(LOC::internal::Has_double_coordinates<Gt>::value, "");
  LOC::Feature_reconstruction_report report;
  LOC::internal::Stopwatch total, watch;
  LOC::internal::check_dimension(dt);
  std::vector<typename Gt::Point_3> pts;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) pts.push_back(v->point());
  std::sort(pts.begin(), pts.end());
  report.number_of_input_points = pts.size();
  report.average_spacing = compute_average_spacing<Sequential_tag>(pts, 6);
  const LOC::internal::Feature_settings settings = LOC::internal::feature_settings(np, report.average_spacing);
  report.offset = settings.offset;
  watch.lap();
  LOC::internal::reconstruct_with_features(dt, pts, settings, mesh, np, report, watch);
  report.total_seconds = total.lap();
  return report;
}

} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_FEATURE_RECONSTRUCTION_H
