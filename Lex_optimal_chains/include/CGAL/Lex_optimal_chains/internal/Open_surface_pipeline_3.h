// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPEN_SURFACE_PIPELINE_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPEN_SURFACE_PIPELINE_3_H

#include <CGAL/Lex_optimal_chains/Coefficient_field.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Open_surface_report.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_mesh.h>
#include <CGAL/Lex_optimal_chains/internal/Open_surface_repair_3.h>
#include <CGAL/Lex_optimal_chains/internal/Optimal_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Pinched_umbrella_trim.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <iostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The output chain of an open surface as a soup, vertices and triangles sorted (see
// Chain_soup_builder): the optimal chain of `dt` bounded by `cycle`, its non-manifold vertices
// resolved unless `keep_non_manifold`, without the triangles that touch a vertex of `dropped`
// (and then, unless `keep_non_manifold`, without the fans that this drop leaves pinched at a
// point: Pinched_umbrella_trim.h).
// `release_triangulation()` is called as soon as the triangulation is no longer read (the
// reconstruction frees its own triangulation there, before the soup is sorted: peak memory).
template <class Triangulation, class EdgeRange, class NamedParameters, class ReleaseTriangulation>
void open_surface_soup(const Triangulation& dt, const EdgeRange& cycle,
                       const std::set<typename Triangulation::Vertex_handle>& dropped, const NamedParameters& np,
                       const std::function<bool(double)>& callback, double progress_from,
                       const ReleaseTriangulation& release_triangulation, Open_surface_report& report,
                       std::vector<typename Triangulation::Point>& soup_points,
                       std::vector<std::array<std::uint32_t, 3>>& soup)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const bool keep = choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::keep_non_manifold), false);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const bool oriented = coefficient_field_of(np) == Coefficient_field::Q;
  Stopwatch watch;
  // the facets go straight into the soup (the number of facets is in the report before the
  // first one is written)
  Chain_soup_builder<Triangulation> builder(dt.tds(), oriented, dropped, &report.number_of_facets);
  auto write_chain = [&](const auto& add) {
    auto sink = boost::make_function_output_iterator(
      [&add](const std::pair<typename Triangulation::Facet, std::int64_t>& fk) { add(fk.first, fk.second); });
    if(oriented)
      optimal_chain_with_boundary<Integer_arithmetic>(dt, cycle, np, callback, progress_from, sink, report);
    else
      optimal_chain_with_boundary<Z2_arithmetic>(dt, cycle, np, callback, progress_from, sink, report);
    watch.lap();
  };
  const Open_surface_repair_result resolution = resolved_open_chain(dt, oriented, keep, builder, write_chain);
  report.resolved_non_manifold_vertices = resolution.statistics.repaired_vertices;
  report.resolution_changed_facets = resolution.changed_facets;
  report.resolution_seconds = watch.lap();
  if(verbose)
    std::cerr << "Lex_optimal_chains: " << resolution.statistics.repaired_vertices << " non-manifold vertices resolved ("
              << resolution.statistics.changed_cells << " cells changed, " << resolution.changed_facets
              << " facets changed, " << resolution.statistics.rounds << " rounds) in " << report.resolution_seconds << " s\n";
  builder.take_points();
  release_triangulation();
  builder.finish(soup_points, soup, report.dropped_triangles);
  if(report.dropped_triangles > 0 && !keep)
    report.trimmed_triangles = trim_pinched_umbrellas(soup_points.size(), soup);
  if(soup.empty() && report.dropped_triangles > 0)
    throw Input_error(Input_error_code::EMPTY_RESULT,
                      "all " + std::to_string(report.dropped_triangles) +
                        " triangles of the optimal surface touch a boundary vertex that is not an input "
                        "point and were dropped (drop_boundary_triangles): the points do not span the "
                        "boundary as a surface (for footprint_boundary(), the points must be a terrain-like "
                        "tile, a height field over their xy-footprint)");
  report.output_seconds += watch.lap(); // the writing of the chain into the soup
}

// Adds the soup to `mesh` (Chain_soup_mesh.h) after the last chance to cancel, and reports it.
template <class Point, class PolygonMesh, class NamedParameters>
void add_open_surface_soup(const std::vector<Point>& soup_points, std::vector<std::array<std::uint32_t, 3>>& soup,
                           PolygonMesh& mesh, const NamedParameters& np, const std::function<bool(double)>& callback,
                           Open_surface_report& report)
{
  Stopwatch watch;
  report_progress(callback, 1.0); // the mesh is not modified before
  const std::size_t vertices_before = num_vertices(mesh), faces_before = num_faces(mesh);
  const Chain_soup_statistics stats =
    add_chain_soup(soup_points, soup, coefficient_field_of(np) == Coefficient_field::Q, mesh);
  report.non_manifold_vertices = stats.vertex_copies;
  report.non_manifold_edges = stats.non_manifold_edges;
  report.orientation_cuts = stats.orientation_cuts;
  report.mesh_vertices = num_vertices(mesh) - vertices_before;
  report.mesh_faces = num_faces(mesh) - faces_before;
  const double build_seconds = watch.lap();
  if(parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::verbose), false))
    std::cerr << "Lex_optimal_chains: soup written in " << report.output_seconds << " s, mesh built in " << build_seconds
              << " s\n";
  report.output_seconds += build_seconds;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPEN_SURFACE_PIPELINE_3_H
