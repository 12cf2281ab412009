// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_RECONSTRUCTION_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_RECONSTRUCTION_3_H

// lex_optimal_feature_reconstruction(): its named parameters, and its stages on the Delaunay
// triangulation of the points: the feature set S, the subcomplex B around it and B's optimal
// 1-cycles, their optimal 2-chains, the critical basis of their span and the mesh of its
// elements.

#include <CGAL/Lex_optimal_chains/Feature_reconstruction_report.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Border_points_3.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_mesh.h>
#include <CGAL/Lex_optimal_chains/internal/Delaunay_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Feature_points_3.h>
#include <CGAL/Lex_optimal_chains/internal/Feature_subcomplex_3.h>
#include <CGAL/Lex_optimal_chains/internal/Geom_traits_check.h>
#include <CGAL/Lex_optimal_chains/internal/Optimal_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Ranked_chains.h>
#include <CGAL/Lex_optimal_chains/internal/Sparse_critical_basis.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/compute_average_spacing.h>

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

// The feature set S of the points `pts`: the given `feature_points` (checked), or the points
// on sharp edges by the VCM; with `border_features`, and the border points.
template <class Point, class NamedParameters>
std::vector<Point> feature_set(const std::vector<Point>& pts, const Feature_settings& settings, const NamedParameters& np,
                               Feature_reconstruction_report& report)
{
  std::vector<Point> features;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::feature_points_t>::value) {
    for(const Point& p : parameters::get_parameter(np, internal_np::feature_points)) {
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
  return features;
}

// The number of points that have several vertices in `mesh` (one per umbrella).
template <class PolygonMesh>
std::size_t number_of_split_points(const PolygonMesh& mesh)
{
  const auto vpm = get(vertex_point, mesh);
  std::vector<typename boost::property_traits<decltype(vpm)>::value_type> corners;
  for(auto v : vertices(mesh)) corners.push_back(get(vpm, v));
  std::sort(corners.begin(), corners.end());
  std::size_t split = 0;
  for(std::size_t i = 1; i < corners.size(); ++i)
    if(corners[i] == corners[i - 1] && (i == 1 || corners[i - 1] != corners[i - 2])) ++split;
  return split;
}

// Replaces the elements of `mesh` (keeping its property maps: the element map may be one) by
// the triangle soup `soup` of `points`, oriented by a traversal, and puts in `element_map` the
// label of each face, `label` giving it by the sorted points of the face. The points and edges
// where the elements do not meet as a 2-manifold are split and counted in `report`.
template <class Point, class PolygonMesh, class ElementMapPointer>
void mesh_with_elements(const std::vector<Point>& points, std::vector<std::array<std::uint32_t, 3>>& soup,
                        const std::map<std::array<Point, 3>, std::size_t>& label, PolygonMesh& mesh,
                        ElementMapPointer element_map, // a pointer, or nullptr
                        Feature_reconstruction_report& report)
{
  using Face = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  PolygonMesh result;
  report.non_manifold_edges = add_chain_soup(points, soup, false, result).non_manifold_edges;
  report.non_manifold_vertices = number_of_split_points(result);
  // the descriptors first: a range of a mesh with removed elements skips them at every begin()
  const std::vector<Face> old_faces(faces(mesh).begin(), faces(mesh).end());
  for(Face f : old_faces) remove_face(f, mesh);
  const std::vector<typename boost::graph_traits<PolygonMesh>::edge_descriptor> old_edges(edges(mesh).begin(), edges(mesh).end());
  for(auto e : old_edges) remove_edge(e, mesh);
  const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> old_vertices(vertices(mesh).begin(),
                                                                                                vertices(mesh).end());
  for(auto v : old_vertices) remove_vertex(v, mesh);
  std::vector<std::pair<Face, Face>> face_pairs;
  copy_face_graph(result, mesh, CGAL::parameters::face_to_face_output_iterator(std::back_inserter(face_pairs)));
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

// The mesh of the elements of the critical basis `basis` of the chains `ranked` but the
// `settings.drop` largest ones, each face labelled with the first element that holds it (into
// the named parameter `face_element_map`, if given), and the size of every element.
template <class Point, class PolygonMesh, class NamedParameters>
void mesh_of_basis(const std::vector<Point>& pts, const Ranked_chains<Point>& ranked, const Z2_critical_basis& basis,
                   const Feature_settings& settings, PolygonMesh& mesh, const NamedParameters& np,
                   Feature_reconstruction_report& report)
{
  const std::size_t kept = basis.elements.size() > settings.drop ? basis.elements.size() - settings.drop : 0;
  report.number_of_dropped_elements = basis.elements.size() - kept;
  if(kept == 0)
    throw Input_error(Input_error_code::EMPTY_RESULT, "every element of the critical basis is dropped");
  std::vector<std::uint32_t> element_of(ranked.triangles.size(), std::uint32_t(-1));
  for(std::size_t e = 0; e < basis.elements.size(); ++e) {
    Z2_chain whole;
    for(std::uint32_t j : basis.sums_of[e]) whole = z2_sum(whole, ranked.absolute[j]);
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
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::face_element_map_t>::value) {
    const auto element_map = parameters::get_parameter(np, internal_np::face_element_map);
    mesh_with_elements(pts, soup, label, mesh, &element_map, report);
  } else {
    mesh_with_elements(pts, soup, label, mesh, nullptr, report);
  }
  report.mesh_vertices = std::size_t(std::distance(vertices(mesh).begin(), vertices(mesh).end()));
  report.mesh_faces = std::size_t(std::distance(faces(mesh).begin(), faces(mesh).end()));
}

// The stages after the triangulation, on the Delaunay triangulation `dt` of the points `pts`
// (sorted and distinct: the triangles are keyed by indices into them): the feature set S, B
// and its cycles, their chains, the critical basis and the mesh.
template <class DT, class Point, class PolygonMesh, class NamedParameters>
void reconstruct_with_features(const DT& dt, const std::vector<Point>& pts, const Feature_settings& settings,
                               PolygonMesh& mesh, const NamedParameters& np, Feature_reconstruction_report& report,
                               Stopwatch& watch)
{
  const std::vector<Point> features = feature_set(pts, settings, np, report);
  report.feature_seconds = watch.lap();
  const auto vertices_of_s = feature_vertices(dt, features);
  report.number_of_feature_points = vertices_of_s.size();

  // B and its optimal 1-cycles
  const Feature_subcomplex_3<DT> b(dt, vertices_of_s, settings.offset);
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

  // a basis of Z^min_2(K, B): the optimal 2-chain of each cycle, as triangle keys, all the
  // cycles' chains in runs of 64 (internal/Optimal_chain_3.h)
  const auto facet_chains = settings.relative
    ? optimal_chains_with_boundaries(dt, cycles, parameters::relative_facets(b.facets))
    : optimal_chains_with_boundaries(dt, cycles, CGAL::parameters::default_values());
  std::vector<std::vector<Triangle_key>> chains;
  for(const auto& facets : facet_chains) {
    std::vector<Triangle_key> keys;
    for(const auto& f : facets) keys.push_back(triangle_key(pts, f));
    std::sort(keys.begin(), keys.end());
    chains.push_back(std::move(keys));
  }
  report.chain_seconds = watch.lap();

  // the triangles of the chains ranked in the order of the package; the critical basis
  std::vector<Triangle_key> b_triangles;
  for(const auto& f : b.facets) b_triangles.push_back(triangle_key(pts, f));
  std::sort(b_triangles.begin(), b_triangles.end());
  Ranked_chains<Point> ranked(pts, chains, b_triangles);
  const Z2_critical_basis basis = z2_critical_basis(std::move(ranked.relative), ranked.triangles.size());
  report.basis_seconds = watch.lap();

  // the mesh: the elements but the largest ones, each face labelled by its first element
  mesh_of_basis(pts, ranked, basis, settings, mesh, np, report);
  report.mesh_seconds = watch.lap();
}

// lex_optimal_feature_reconstruction() of points: their Delaunay triangulation, then the
// stages of reconstruct_with_features().
template <class PointRange, class PolygonMesh, class NamedParameters>
Feature_reconstruction_report feature_reconstruction_of_points(const PointRange& points, PolygonMesh& mesh,
                                                               const NamedParameters& np)
{
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Point = typename boost::property_traits<Point_map>::value_type;
  using Kernel = typename Kernel_traits<Point>::Kernel;
  static_assert(Has_exact_predicates_and_double_coordinates<Kernel>::value, "");
  using DT = Delaunay_triangulation_3<Kernel>;
  Feature_reconstruction_report report;
  Stopwatch total, watch;
  std::vector<Point> pts = finite_points<Point>(
    points, CGAL::parameters::choose_parameter<Point_map>(CGAL::parameters::get_parameter(np, CGAL::internal_np::point_map)));
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  report.number_of_input_points = pts.size();
  if(pts.size() < 4) throw Input_error(Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");
  report.average_spacing = compute_average_spacing<Sequential_tag>(pts, 6);
  const Feature_settings settings = feature_settings(np, report.average_spacing);
  report.offset = settings.offset;
  const DT dt(pts.begin(), pts.end());
  check_dimension(dt);
  report.delaunay_seconds = watch.lap();
  reconstruct_with_features(dt, pts, settings, mesh, np, report, watch);
  report.total_seconds = total.lap();
  return report;
}

// lex_optimal_feature_reconstruction() on a user's Delaunay triangulation `dt`, which is not
// modified: its sorted points, then the stages of reconstruct_with_features().
template <class DT, class PolygonMesh, class NamedParameters>
Feature_reconstruction_report feature_reconstruction_of_triangulation(const DT& dt, PolygonMesh& mesh,
                                                                      const NamedParameters& np)
{
  static_assert(Has_double_coordinates<typename DT::Geom_traits>::value, "");
  Feature_reconstruction_report report;
  Stopwatch total, watch;
  check_dimension(dt);
  std::vector<typename DT::Point> pts;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) pts.push_back(v->point());
  std::sort(pts.begin(), pts.end());
  report.number_of_input_points = pts.size();
  report.average_spacing = compute_average_spacing<Sequential_tag>(pts, 6);
  const Feature_settings settings = feature_settings(np, report.average_spacing);
  report.offset = settings.offset;
  watch.lap();
  reconstruct_with_features(dt, pts, settings, mesh, np, report, watch);
  report.total_seconds = total.lap();
  return report;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_RECONSTRUCTION_3_H
