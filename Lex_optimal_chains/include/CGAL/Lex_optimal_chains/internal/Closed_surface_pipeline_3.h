// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_PIPELINE_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_PIPELINE_3_H

#include <CGAL/Lex_optimal_chains/Closed_surface_report.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_cut_from_tree_3.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_cut_3.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_mesh_3.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_repair_3.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Cells (by position in the cell container) that hold the constraint points. `smoothed`: the
// triangulation is of the points smoothed by the robust mode, whose hull is smaller.
template <class Triangulation, class PointRange>
std::vector<std::uint32_t> constraint_cells(const Triangulation& dt,
                                            const Handle_index_map<typename Triangulation::Cell>& positions,
                                            const PointRange& points, bool interior, bool smoothed = false)
{
  std::vector<std::uint32_t> cells;
  for(const auto& p : points) {
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(Input_error_code::NON_FINITE_COORDINATE, "a constraint point has a NaN or infinite coordinate");
    typename Triangulation::Locate_type lt;
    int li, lj;
    const typename Triangulation::Cell_handle c = dt.locate(p, lt, li, lj);
    std::vector<typename Triangulation::Cell_handle> incident;
    switch(lt) {
      case Triangulation::CELL: incident.push_back(c); break;
      case Triangulation::FACET: incident.push_back(c); incident.push_back(c->neighbor(li)); break;
      case Triangulation::EDGE: {
        auto circ = dt.incident_cells(c, li, lj), done = circ;
        do { incident.push_back(circ); } while(++circ != done);
        break;
      }
      case Triangulation::VERTEX: dt.incident_cells(c->vertex(li), std::back_inserter(incident)); break;
      default: incident.push_back(c); break; // outside the convex hull: an infinite cell
    }
    for(const auto& ic : incident) {
      if(interior && dt.is_infinite(ic)) {
        std::ostringstream msg;
        msg << "interior point (" << p << ") is not inside the convex hull of the points";
        if(smoothed) msg << " as the robust mode smoothed them";
        throw Input_error(Input_error_code::CONSTRAINT_OUTSIDE_HULL, msg.str());
      }
      cells.push_back(positions.index(&*ic));
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

// The automatic interior is accepted when its persistence reaches `minimum_interior_persistence`
// if the user gave one. Otherwise it must stand out from the other voids: its ratio at least 2
// and at least the square of the second largest ratio (on a log scale, its bar at least twice
// as long), which noisy or unevenly sampled closed surfaces pass with interiors of low
// persistence while a partial scan has no such void. Without the robust mode, a ratio of 4 is
// also enough, as it was before the rule (several closed surfaces give several long bars).
// When the robust mode smoothed the points it is not: smoothing very noisy points can make
// pockets of similar persistence, one of which would be taken for the interior.
template <class NamedParameters>
void check_automatic_interior(const Automatic_interior& a, const NamedParameters& np, bool robust)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  constexpr bool adaptive =
    parameters::is_default_parameter<NamedParameters, Lex_optimal_chains::internal_np::minimum_interior_persistence_t>::value;
  const double minimum = choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::minimum_interior_persistence), 4.0);
  const bool stands_out = a.persistence >= 2 && a.persistence >= a.runner_up_persistence * a.runner_up_persistence;
  if(adaptive ? stands_out || (!robust && a.persistence >= minimum) : a.persistence >= minimum) return;
  std::ostringstream msg;
  msg << "no interior point given, and the most persistent void has a persistence of only " << a.persistence;
  if(adaptive && a.persistence < 2)
    msg << " (< 2)";
  else if(adaptive)
    msg << (robust ? " (" : " (< 4, and ") << "not the square of the second most persistent void's, "
        << a.runner_up_persistence << ": it does not stand out from the voids of the noise)";
  else
    msg << " (< " << minimum << ")";
  msg << ": the points do not seem to sample a closed surface; give an interior point";
  throw Input_error(Input_error_code::NO_INTERIOR_FOUND, msg.str());
}

// The common part: constraints, contracted and sorted dual graph, Algorithm 8. Returns the facets of the
// optimal cycle in decreasing order, each as the key 4 * p + i of facet i of the cell at
// position p in the numbering `cells` (`Closed_surface_mesh_3::facet_key()`) that owns its
// record, which may be the inside or the outside one (naming every facet by its inside cell
// would read the other cell, at random); fills `cells`
// and `inside`, indexed by it, and `constraints` with the positions of the constraint cells.
template <class Triangulation, class NamedParameters>
std::vector<std::uint32_t>
closed_surface_facets(const Triangulation& dt, const NamedParameters& np,
                      const std::function<bool(double)>& callback, double progress_from,
                      Closed_surface_report& report, std::vector<bool>& inside,
                      Handle_index_map<typename Triangulation::Cell>& cells, Constraint_cells& constraints)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Point = typename Triangulation::Point;

  if(dt.dimension() < 3)
    throw Input_error(dt.number_of_vertices() < 4 ? Input_error_code::TOO_FEW_POINTS
                                                  : Input_error_code::DEGENERATE_POINT_SET,
                      dt.number_of_vertices() < 4
                        ? "fewer than 4 distinct points: no closed surface can be built"
                        : "all points are coplanar: the triangulation has no tetrahedron");
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const double span = 1.0 - progress_from;
  Stopwatch watch;

  using Graph = Sorted_dual_graph_3<Triangulation>;
  cells = Handle_index_map<typename Triangulation::Cell>(dt.tds().cells().begin(), dt.tds().cells().end());
  report.number_of_vertices = dt.number_of_vertices();
  report.number_of_triangles = Graph::number_of_finite_facets(dt);

  std::vector<std::uint32_t> infinite;
  {
    std::vector<typename Triangulation::Cell_handle> hull;
    dt.incident_cells(dt.infinite_vertex(), std::back_inserter(hull));
    for(const auto& c : hull) infinite.push_back(cells.index(&*c));
  }
  // the ranges are used within the full expressions that read them: CGAL 5.5 returns
  // copyable parameters by value
  const std::vector<Point> no_points;
  std::vector<std::uint32_t> sources = constraint_cells(
    dt, cells, choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::interior_points), no_points), true, report.robust);
  std::vector<std::uint32_t> sinks = constraint_cells(
    dt, cells, choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::exterior_points), no_points), false);
  sinks.insert(sinks.end(), infinite.begin(), infinite.end());
  std::sort(sinks.begin(), sinks.end());
  sinks.erase(std::unique(sinks.begin(), sinks.end()), sinks.end());
  for(std::uint32_t s : sources)
    if(std::binary_search(sinks.begin(), sinks.end(), s))
      throw Input_error(Input_error_code::CONFLICTING_CONSTRAINTS,
                        "an interior point and an exterior point lie in the same Delaunay cell");

  // the contraction of every cell with the cell across its largest facet, and the sorted
  // facets between the components (internal/Closed_surface_cut_3.h)
  Contracted_dual_graph_3<Triangulation> contracted(dt, cells, sources, sinks,
                                                    Stage_progress{&callback, progress_from, progress_from + 0.6 * span},
                                                    choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::number_of_threads), 1u));
  const Graph& graph = contracted.graph(); // released after the cut
  report_order_statistics(contracted, watch.lap(), report);
  if(verbose)
    std::cerr << "Lex_optimal_chains: contracted the cells across their largest facets ("
              << contracted.number_of_exact_comparisons() << " comparisons made exactly), then ordered the "
              << graph.records().size() << " triangles between components (" << graph.number_of_records_in_runs()
              << " in close runs, " << graph.number_of_exactly_sorted_records() << " exactly) in "
              << report.order_seconds << " s (keys " << graph.key_seconds() << " s, radix sort "
              << graph.sort_seconds() << " s, exact runs " << graph.repair_seconds() << " s)\n";

  const Stage_progress cut_progress{&callback, progress_from + 0.6 * span, progress_from + 0.8 * span};
  Dual_edge_records cut;
  if(sources.empty()) {
    Dense_numbers components; // of the contraction
    std::vector<std::uint32_t> spanning_tree;
    const Automatic_interior a = most_persistent_void(contracted, components, spanning_tree);
    report.automatic_interior = true;
    report.interior_persistence = a.persistence;
    report.runner_up_persistence = a.runner_up_persistence;
    check_automatic_interior(a, np, report.robust); // robust: the points were smoothed
    if(verbose)
      std::cerr << "Lex_optimal_chains: automatic interior cell, persistence " << a.persistence << ", in "
                << watch.elapsed() << " s (" << spanning_tree.size() << " tree facets between components)\n";
    // the Kruskal pass of the persistence also gave the spanning tree: Algorithm 8 needs no
    // second pass over the triangles
    cut = lexicographic_closed_cut_from_tree(contracted, components, spanning_tree, a.cell, sinks, inside, cut_progress);
    sources.push_back(a.cell);
  } else {
    cut = lexicographic_closed_cut(contracted, inside, cut_progress);
  }
  contracted.release_graph();
  std::vector<std::uint32_t> facets(cut.size());
  for(std::size_t i = 0; i < cut.size(); ++i)
    facets[i] = Closed_surface_mesh_3<Triangulation>::facet_key(Graph::owner_position(cut[i]), Graph::facet_index(cut[i]));
  report.cut_seconds = watch.lap();
  if(verbose)
    std::cerr << "Lex_optimal_chains: cut " << facets.size() << " facets in " << report.cut_seconds << " s\n";
  constraints.sources = std::move(sources); // sorted
  constraints.sinks = std::move(sinks);
  report.number_of_facets = facets.size();
  return facets;
}

// Resolves the non-manifold vertices of the cycle `facets` (unless `keep_non_manifold`) and
// returns its surface; fills the resolution fields of the report, and `surface_seconds` with
// the time taken to make the surface of the optimal cycle.
template <class Triangulation, class NamedParameters>
std::unique_ptr<Closed_surface_mesh_3<Triangulation>>
resolved_closed_surface(const Triangulation& dt, const NamedParameters& np,
                        const Handle_index_map<typename Triangulation::Cell>& cells, std::vector<bool>& inside,
                        const Constraint_cells& constraints, std::vector<std::uint32_t>& facets,
                        Closed_surface_report& report, double& surface_seconds)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Stopwatch watch;
  const bool keep = choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::keep_non_manifold), false);
  const Handle_index_map<typename Triangulation::Vertex> vertices(dt.tds().vertices().begin(), dt.tds().vertices().end());
  Closed_surface_repair_result r;
  std::unique_ptr<Closed_surface_mesh_3<Triangulation>> surface =
    manifold_closed_surface(dt, cells, vertices, inside, constraints, keep, facets, r,
                            choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::number_of_threads), 1u));
  report.resolved_non_manifold_vertices = r.statistics.repaired_vertices;
  report.resolution_changed_facets = r.removed_facets + r.added_facets;
  report.number_of_facets = facets.size();
  report.resolution_seconds = watch.lap() - r.surface_seconds;
  surface_seconds = r.surface_seconds;
  if(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false))
    std::cerr << "Lex_optimal_chains: surface of " << facets.size() << " facets made, "
              << r.statistics.repaired_vertices << " non-manifold vertices resolved (" << r.statistics.changed_cells
              << " cells moved, " << r.removed_facets << " facets removed, " << r.added_facets << " added, "
              << r.statistics.rounds << " rounds, " << r.moved_pockets << " regions cut off moved back) in " << report.resolution_seconds << " s\n";
  return surface;
}


// Adds the closed surface of `dt` to `mesh`: the optimal cycle, the resolution of its
// non-manifold vertices, the mesh. `release_triangulation()` is called as soon as the
// triangulation is no longer read (the reconstruction frees its own triangulation there, for
// the peak memory); `progress_from` is the progress reported when the call starts.
template <class Triangulation, class PolygonMesh, class NamedParameters, class ReleaseTriangulation>
void add_closed_surface_mesh(const Triangulation& dt, PolygonMesh& mesh, const NamedParameters& np,
                             const std::function<bool(double)>& callback, double progress_from,
                             Closed_surface_report& report, const ReleaseTriangulation& release_triangulation)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Stopwatch watch;
  std::vector<bool> inside;
  std::unique_ptr<Closed_surface_mesh_3<Triangulation>> surface;
  double extraction_seconds = 0; // the surface of the optimal cycle (its resolution is timed apart)
  {
    Handle_index_map<typename Triangulation::Cell> cells; // as used by `inside`
    Constraint_cells constraints;
    std::vector<std::uint32_t> facets = closed_surface_facets(dt, np, callback, progress_from, report, inside, cells, constraints);
    watch.lap();
    surface = resolved_closed_surface(dt, np, cells, inside, constraints, facets, report, extraction_seconds);
    watch.lap();
  }
  report_progress(callback, progress_from + 0.85 * (1.0 - progress_from));
  std::vector<bool>().swap(inside);
  release_triangulation(); // the rest of the surface reads no triangulation
  const double clear_seconds = watch.lap();
  surface->complete();
  const double completion_seconds = watch.lap();
  report_progress(callback, 1.0); // the last chance to cancel: the mesh is not modified before
  surface->build(mesh, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh)));
  const Closed_surface_statistics& s = surface->statistics();
  report.mesh_vertices = s.vertices;
  report.mesh_faces = s.faces;
  report.components = s.components;
  report.non_manifold_vertices = s.non_manifold_vertices;
  report.non_manifold_edges = s.non_manifold_edges;
  report.genus = s.genus;
  const double build_seconds = watch.lap();
  report.output_seconds = extraction_seconds + clear_seconds + completion_seconds + build_seconds;
  if(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false))
    std::cerr << "Lex_optimal_chains: surface read from the triangulation in " << extraction_seconds
              << " s, triangulation released in " << clear_seconds << " s, vertex copies and statistics in "
              << completion_seconds << " s, mesh built in " << build_seconds << " s\n";
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_PIPELINE_3_H
