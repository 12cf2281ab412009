// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CLOSED_SURFACE_H
#define CGAL_LEX_OPTIMAL_CLOSED_SURFACE_H

/// \file lex_optimal_closed_surface.h
/// Closed surface reconstruction as a lexicographic optimal 2-cycle (thesis section 4.8.1).

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_cut_3.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_mesh_3.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_repair_3.h>
#include <CGAL/Lex_optimal_chains/internal/Delaunay_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
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

/*!
\ingroup PkgLexOptimalChainsRef
What a closed surface reconstruction did: sizes, the automatic interior, timings and the
topology of the output. Fields that a function does not compute stay at zero.
*/
struct Closed_surface_report
{
  std::size_t number_of_input_points = 0;      ///< points given (reconstruction only)
  std::size_t number_of_vertices = 0;          ///< vertices of the triangulation
  std::size_t number_of_triangles = 0;         ///< finite facets of the triangulation (dual edges)
  std::size_t number_of_triangles_in_close_runs = 0;  ///< triangles whose fast keys were too close to be ordered by them (among the triangles sorted: those left between components by the contraction along the largest triangles of the cells)
  std::size_t number_of_exactly_ordered_triangles = 0; ///< triangles ordered by the exact comparator in that sort, plus the comparisons of the contraction made exactly
  std::size_t number_of_facets = 0;            ///< facets of the output 2-cycle (the optimal one after the resolution of its non-manifold vertices)
  std::size_t resolved_non_manifold_vertices = 0; ///< local changes of the cycle that made a non-manifold vertex manifold
  std::size_t resolution_changed_facets = 0;   ///< facets in the symmetric difference of the optimal cycle and the output cycle
  bool automatic_interior = false;             ///< true if the interior cell was chosen automatically
  double interior_persistence = 0;             ///< persistence ratio of the automatic interior
  double delaunay_seconds = 0;                 ///< time to build the Delaunay triangulation
  double order_seconds = 0;                    ///< time to order the triangles (largest triangle of each cell, contraction, sort of the others)
  double cut_seconds = 0;                      ///< time of the automatic interior and of Algorithm 8
  double resolution_seconds = 0;               ///< time to find and resolve the non-manifold vertices of the cycle
  double output_seconds = 0;                   ///< time to build the mesh
  double total_seconds = 0;                    ///< time of the whole call
  std::size_t mesh_vertices = 0;               ///< vertices of the output mesh (reconstruction only)
  std::size_t mesh_faces = 0;                  ///< faces of the output mesh (reconstruction only)
  std::size_t components = 0;                  ///< connected components of the output mesh
  std::size_t non_manifold_vertices = 0;       ///< triangulation vertices split in several mesh vertices (none unless `keep_non_manifold`, or a resolution failed)
  std::size_t non_manifold_edges = 0;          ///< triangulation edges split in several mesh edges (likewise)
  long genus = 0;                              ///< sum of the genera of the components
};

namespace internal {

// Cells (by position in the cell container) that hold the constraint points.
template <class Triangulation, class PointRange>
std::vector<std::uint32_t> constraint_cells(const Triangulation& dt,
                                            const Handle_index_map<typename Triangulation::Cell>& positions,
                                            const PointRange& points, bool interior)
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
        throw Input_error(Input_error_code::CONSTRAINT_OUTSIDE_HULL, msg.str());
      }
      cells.push_back(positions.index(&*ic));
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
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
    dt, cells, choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::interior_points), no_points), true);
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
                                                    Stage_progress{&callback, progress_from, progress_from + 0.6 * span});
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
  std::vector<Dual_edge_record> cut;
  if(sources.empty()) {
    const double minimum = choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::minimum_interior_persistence), 4.0);
    Dense_numbers components; // of the contraction
    std::vector<std::uint32_t> spanning_tree;
    const Automatic_interior a = most_persistent_void(contracted, components, spanning_tree);
    report.automatic_interior = true;
    report.interior_persistence = a.persistence;
    if(!(a.persistence >= minimum)) {
      std::ostringstream msg;
      msg << "no interior point given, and the most persistent void has a persistence of only "
          << a.persistence << " (< " << minimum << "): the points do not seem to sample a closed "
          << "surface; give an interior point";
      throw Input_error(Input_error_code::NO_INTERIOR_FOUND, msg.str());
    }
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
    manifold_closed_surface(dt, cells, vertices, inside, constraints, keep, facets, r);
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

} // namespace internal
} // namespace Lex_optimal_chains

/*!
\ingroup PkgLexOptimalChainsRef

Computes the lexicographic optimal 2-cycle of the Delaunay triangulation `dt` completed to
\f$S^3\f$ by its infinite vertex that separates the interior constraint from the exterior
one (Algorithm 8 of the thesis on the dual graph, triangles ordered by Lemma 4.14).

The result is the boundary of a union of finite tetrahedra (the *inside* cells). Unless
`keep_non_manifold` is set, its non-manifold vertices are then resolved: around each, cells
move between the inside and the outside (never the constraint cells), the change chosen
among a few local candidates as the one giving the lexicographically smallest cycle (see the
user manual, section "Manifold output"); the result is a 2-manifold wherever such a change
exists. Each facet is written to `facets` as a `DT::Facet` `(c, i)` where `c` is the inside
cell: the facets of the optimal cycle that the resolution left as they were, in decreasing
triangle order, then the facets that it added or reversed, in decreasing triangle order. The triangle
`c->vertex((i+1)&3), c->vertex((i+2)&3), c->vertex((i+3)&3)`, with its last two vertices
swapped when `i` is odd, is oriented outward.

\tparam DT a `Delaunay_triangulation_3` whose points have `double` coordinates
\param dt the triangulation; it is not modified
\param facets output iterator accepting `DT::Facet`
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{interior_points}
    \cgalParamDescription{points inside the surface; the cells that hold them form the interior constraint}
    \cgalParamType{a range of `DT::Point`}
    \cgalParamDefault{empty: the interior is chosen automatically as the most persistent void}
  \cgalParamNEnd
  \cgalParamNBegin{exterior_points}
    \cgalParamDescription{points outside the surface, added to the exterior constraint}
    \cgalParamType{a range of `DT::Point`}
    \cgalParamDefault{empty: the exterior is the infinite vertex only}
  \cgalParamNEnd
  \cgalParamNBegin{keep_non_manifold}
    \cgalParamDescription{if `true`, the optimal cycle is returned as it is; otherwise its non-manifold
                          vertices are resolved by local changes (see the user manual)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_interior_persistence}
    \cgalParamDescription{the automatic interior is refused below this persistence ratio}
    \cgalParamType{`double`}
    \cgalParamDefault{4}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{called with the progress in [0,1]; returning `false` cancels (the last
                          call, with 1, comes before anything is written to `facets`)}
    \cgalParamType{`std::function<bool(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{prints the stages and their timings to `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a report; only its triangulation, order and cut fields are filled.
\throws Lex_optimal_chains::Input_error on a triangulation of dimension below 3, an interior
point outside the convex hull, conflicting constraints, or when no interior can be chosen.
*/
template <class DT, class OutputIterator, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Closed_surface_report
lex_optimal_closed_surface(const DT& dt, OutputIterator facets,
                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static_assert(std::is_same<typename DT::Geom_traits::FT, double>::value,
                "lex_optimal_closed_surface needs a triangulation with double coordinates (e.g. Epick)");
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  Lex_optimal_chains::Closed_surface_report report;
  Lex_optimal_chains::internal::Stopwatch total;
  std::vector<bool> inside;
  Lex_optimal_chains::internal::Handle_index_map<typename DT::Cell> cells;
  Lex_optimal_chains::internal::Constraint_cells constraints;
  std::vector<std::uint32_t> result =
    Lex_optimal_chains::internal::closed_surface_facets(dt, np, callback, 0.0, report, inside, cells, constraints);
  // the surface is made only to find the non-manifold vertices: not with keep_non_manifold
  if(!choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::keep_non_manifold), false)) {
    double surface_seconds = 0;
    Lex_optimal_chains::internal::resolved_closed_surface(dt, np, cells, inside, constraints, result, report, surface_seconds);
  }
  Lex_optimal_chains::internal::report_progress(callback, 1.0); // before anything is written
  for(const std::uint32_t key : result) {
    const auto cell = dt.tds().cells().iterator_to(*const_cast<typename DT::Cell*>(cells.element(key >> 2)));
    const typename DT::Facet f(cell, int(key & 3));
    *facets++ = inside[key >> 2] ? f : dt.mirror_facet(f); // named from the inside cell
  }
  report.total_seconds = total.lap();
  return report;
}

namespace Lex_optimal_chains {
namespace internal {

// Everything after the Delaunay triangulation of `points` (both freed here, as soon as
// possible, for the peak memory).
template <class Triangulation, class Point, class PolygonMesh, class NamedParameters>
void reconstruct_in(Triangulation& dt, std::vector<Point>& points, PolygonMesh& mesh, const NamedParameters& np,
                    const std::function<bool(double)>& callback, Closed_surface_report& report,
                    Stopwatch& watch)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  std::vector<Point>().swap(points);
  report.delaunay_seconds = watch.lap();
  std::vector<bool> inside;
  std::unique_ptr<Closed_surface_mesh_3<Triangulation>> surface;
  double extraction_seconds = 0; // the surface of the optimal cycle (its resolution is timed apart)
  {
    Handle_index_map<typename Triangulation::Cell> cells; // as used by `inside`
    Constraint_cells constraints;
    std::vector<std::uint32_t> facets = closed_surface_facets(dt, np, callback, 0.35, report, inside, cells, constraints);
    watch.lap();
    surface = resolved_closed_surface(dt, np, cells, inside, constraints, facets, report, extraction_seconds);
    watch.lap();
  }
  report_progress(callback, 0.9);
  // the triangulation (ours) is freed before the rest of the surface is made: peak memory
  std::vector<bool>().swap(inside);
  dt.clear();
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
              << " s, triangulation freed in " << clear_seconds << " s, vertex copies and statistics in "
              << completion_seconds << " s, mesh built in " << build_seconds << " s\n";
}

} // namespace internal
} // namespace Lex_optimal_chains

/*!
\ingroup PkgLexOptimalChainsRef

Reconstructs a closed surface from a point cloud: builds the 3D Delaunay triangulation of the
points, computes the lexicographic optimal 2-cycle that separates the interior from the
outside (see `lex_optimal_closed_surface()`), and adds it to `mesh` as a closed, oriented
(outward) triangle mesh. The non-manifold vertices of the cycle are resolved first, unless
`keep_non_manifold` is set; non-manifold edges and vertices left in the boundary of the union
of inside tetrahedra are split, one copy per wedge around an edge and one per umbrella around
a vertex, as for an infinitesimally shrunk union; their numbers are reported.

\tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
\tparam PolygonMesh a model of `MutableFaceGraph` whose points are of the type of the input
        points (its vertex point map is written with them)
\param points the input points (duplicates are merged); not modified
\param mesh the output; the surface is added to it only on success
\param np the named parameters of `lex_optimal_closed_surface()`, and:
\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map giving the point of an element of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` with value type a `Point_3` of an `Epick`-like kernel}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{threads used for the Delaunay triangulation (with TBB, from 100,000 points: below, the parallel construction is slower); the result does not depend on it}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{1}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Lex_optimal_chains::Input_error on empty input, NaN or infinite coordinates, fewer than
4 distinct points, coplanar points, and the errors of `lex_optimal_closed_surface()`.
*/
template <class PointRange, class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Closed_surface_report
lex_optimal_closed_surface_reconstruction(const PointRange& points, PolygonMesh& mesh,
                                          const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Point = typename boost::property_traits<Point_map>::value_type;
  using Kernel = typename Kernel_traits<Point>::Kernel;
  static_assert(std::is_same<typename Kernel::FT, double>::value && bool(Kernel::Has_filtered_predicates),
                "lex_optimal_closed_surface_reconstruction needs points of a kernel with double coordinates and exact (filtered) "
                "predicates, such as Epick: the Delaunay triangulation is built with its predicates");
  using Input_error = Lex_optimal_chains::Input_error;
  using Code = Lex_optimal_chains::Input_error_code;

  const Point_map point_map = choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map));
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  const unsigned threads = choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::number_of_threads), 1u);

  Lex_optimal_chains::Closed_surface_report report;
  Lex_optimal_chains::internal::Stopwatch total, watch;
  std::vector<Point> pts = Lex_optimal_chains::internal::finite_points<Point>(points, point_map);
  report.number_of_input_points = pts.size();
  if(callback && !callback(0.0)) throw Input_error(Code::CANCELLED, "cancelled by the callback");
  Lex_optimal_chains::internal::with_delaunay_triangulation<Kernel>(pts, threads, [&](auto& dt) {
    Lex_optimal_chains::internal::reconstruct_in(dt, pts, mesh, np, callback, report, watch);
  });
  report.total_seconds = total.lap();
  return report;
}

} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CLOSED_SURFACE_H
