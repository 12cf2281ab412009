// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_OPEN_SURFACE_H
#define CGAL_LEX_OPTIMAL_OPEN_SURFACE_H

/// \file lex_optimal_open_surface.h
/// Open surface reconstruction with an imposed boundary (thesis section 4.8.2).

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/lex_optimal_homologous_chain.h>
#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/Coefficient_field.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Open_surface_report.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Geom_traits_check.h>
#include <CGAL/Lex_optimal_chains/internal/Delaunay_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Imposed_boundary_3.h>
#include <CGAL/Lex_optimal_chains/internal/Open_surface_pipeline_3.h>
#include <CGAL/Lex_optimal_chains/internal/Optimal_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cstdint>
#include <functional>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgLexOptimalChainsRef

Reconstructs an open surface from a point cloud and its boundary: builds the 3D Delaunay
triangulation of the points and of the vertices of the boundary polylines, and adds to
`mesh` the lexicographic optimal 2-chain bounded by the polylines (see
`lex_optimal_chain_with_boundary()`; thesis section 4.8.2).

The boundary edges must be edges of the triangulation. This holds for a polygon outside the
cloud on its convex hull, such as the one of `Lex_optimal_chains::footprint_boundary()`; for
a boundary through the cloud (the border of a neighbouring tile, for instance), the input
points that lie in the closed diametral ball of a missing edge keep it out of the
triangulation, and can be removed with `remove_blocking_points(true)` (once these balls are
empty the edges are Gabriel edges, hence Delaunay edges).

The non-manifold vertices of the chain are resolved by local changes that keep its
boundary, chosen by the lexicographic order (see the user manual, section "Manifold output"),
unless `keep_non_manifold` is set. The mesh is the chain made a valid polygon mesh: an edge
of three triangles or more that is left is split, one copy per triangle, and a vertex gets one
copy per umbrella (per fan of its triangles joined by edges); these are counted in the report. Over Q the faces keep the
orientation of the chain, whose boundary is the polylines with their orientation; over Z2
the triangles are oriented by a traversal across edges, and a non-orientable optimum (a
Möbius strip) is cut along the edges where the orientation disagrees (`orientation_cuts`). A triangle whose coefficient is not 1 or -1 (possible only
over Q, when the boundary winds more than once) appears once; such triangles are counted.

\tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
\tparam PolylineRange a range of ranges of `Point_3`
\tparam PolygonMesh a model of `MutableFaceGraph` whose points are of the type of the input
        points (its vertex point map is written with them)
\param points the input points (duplicates are merged); not modified
\param polylines the boundary: closed polylines (last vertex equal to the first), simple and
disjoint, each edge oriented from a vertex to the next
\param mesh the output; the surface is added to it only on success
\param np the named parameters of `lex_optimal_homologous_chain()` (but `relative_facets`), and:
\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map giving the point of an element of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` with value type a `Point_3` with `double` coordinates}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{the geometric traits with which the Delaunay triangulation is built}
    \cgalParamType{a model of `LexOptimalChainsTraits_3` whose `Point_3` is the point type}
    \cgalParamDefault{the kernel of the points (`CGAL::Kernel_traits`)}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{threads used for the Delaunay triangulation (with TBB, from 100,000 points: below, the parallel construction is slower) and for the contraction of the dual graph and the keys and the sort of its triangles (from 200,000 cells); the result does not depend on it}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{remove_blocking_points}
    \cgalParamDescription{removes the input points in the diametral balls of the boundary edges that are not Delaunay edges}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`: such an edge is an error}
  \cgalParamNEnd
  \cgalParamNBegin{keep_non_manifold}
    \cgalParamDescription{if `true`, the optimal chain is meshed as it is (its non-manifold vertices and edges split); otherwise its non-manifold vertices are resolved first}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{drop_boundary_triangles}
    \cgalParamDescription{drops the triangles that touch a boundary vertex that is not an input point (Fig. 4.26 of the thesis: the skirt joining an outer polygon to a terrain), and then, unless `keep_non_manifold`, the fans of triangles that this drop leaves pinched at an input point, all but one per point}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Lex_optimal_chains::Input_error with code `EMPTY_INPUT`, `NON_FINITE_COORDINATE`,
`TOO_FEW_POINTS`, `DEGENERATE_POINT_SET`, `OPEN_POLYLINE` (a polyline does not end where it
starts), `SELF_INTERSECTING_BOUNDARY` (a repeated vertex, segments that meet),
`BOUNDARY_FAR_FROM_POINTS` (a polyline farther from the bounding box of the points than its
diagonal), `BOUNDARY_EDGE_NOT_IN_TRIANGULATION` (the message names the edge), `EMPTY_RESULT`
(with `drop_boundary_triangles`, when every triangle is dropped: a vertical wall, a few
points, no terrain). `mesh` is then unchanged.
\throws Lex_optimal_chains::Cancelled when the callback returns `false`; `mesh` is then unchanged.
*/
template <class PointRange, class PolylineRange, class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Open_surface_report
lex_optimal_open_surface_reconstruction(const PointRange& points, const PolylineRange& polylines, PolygonMesh& mesh,
                                        const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace LOC = Lex_optimal_chains;
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Point = typename boost::property_traits<Point_map>::value_type;
  using Kernel = typename Kernel_traits<Point>::Kernel;
  using Geom_traits = typename CGAL::internal_np::Lookup_named_param_def<
    CGAL::internal_np::geom_traits_t, NamedParameters, Kernel>::type;
  static_assert(Lex_optimal_chains::internal::Has_exact_predicates_and_double_coordinates<Geom_traits>::value, "");
  const Geom_traits traits = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));

  const Point_map point_map = choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map));
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  const unsigned threads = choose_parameter(get_parameter(np, LOC::internal_np::number_of_threads), 1u);
  const bool remove = choose_parameter(get_parameter(np, LOC::internal_np::remove_blocking_points), false);
  const bool drop = choose_parameter(get_parameter(np, LOC::internal_np::drop_boundary_triangles), false);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);

  LOC::Open_surface_report report;
  LOC::internal::Stopwatch total, watch;
  std::vector<Point> pts = LOC::internal::finite_points<Point>(points, point_map);
  report.number_of_input_points = pts.size();
  const auto boundary = LOC::internal::checked_polylines<Kernel>(polylines, bbox_3(pts.begin(), pts.end()));
  LOC::internal::report_progress(callback, 0.0);

  std::vector<Point> soup_points;
  std::vector<std::array<std::uint32_t, 3>> soup;
  LOC::internal::with_delaunay_triangulation(pts, traits, threads, [&](auto& dt) {
    using Triangulation = std::remove_reference_t<decltype(dt)>;
    std::vector<Point>().swap(pts); // freed as soon as possible: peak memory
    std::set<typename Triangulation::Vertex_handle> boundary_only;
    std::vector<Point> removed;
    const auto cycle = LOC::internal::insert_boundary(dt, boundary, remove, boundary_only, removed);
    report.number_of_boundary_vertices = boundary_only.size();
    report.number_of_removed_points = removed.size();
    try {
      LOC::internal::check_dimension(dt);
    } catch(const LOC::Input_error& e) {
      if(removed.empty()) throw;
      throw LOC::Input_error(e.code(), std::string(e.what()) + ", after the removal of " + std::to_string(removed.size()) +
                                         " input points that kept boundary edges out of it (remove_blocking_points): "
                                         "the boundary passes through the cloud nearly everywhere");
    }
    report.delaunay_seconds = watch.lap();
    if(verbose)
      std::cerr << "Lex_optimal_chains: Delaunay triangulation of " << dt.number_of_vertices() << " vertices in "
                << report.delaunay_seconds << " s (" << removed.size() << " points removed)\n";
    const std::set<typename Triangulation::Vertex_handle> none;
    LOC::internal::open_surface_soup(dt, cycle, drop ? boundary_only : none, np, callback, 0.35, [&dt] { dt.clear(); },
                                     report, soup_points, soup);
  });
  LOC::internal::add_open_surface_soup(soup_points, soup, mesh, np, callback, report);
  report.total_seconds = total.lap();
  return report;
}

/*!
\ingroup PkgLexOptimalChainsRef

Adds to `mesh` the open surface of a user's Delaunay triangulation bounded by `cycle`: the
lexicographic optimal 2-chain of `lex_optimal_chain_with_boundary()`, its non-manifold
vertices resolved unless `keep_non_manifold` is set, as a triangle mesh with the vertices of
`dt` that it touches. This is `lex_optimal_open_surface_reconstruction()` on a triangulation
that the caller built (with its own vertex and cell bases, location policy or concurrency
tag), the boundary inserted with `Lex_optimal_chains::insert_boundary()` or made of edges of
`dt`; the mesh is made as described there.

\tparam DT a `Delaunay_triangulation_3` whose points have `double` coordinates
\tparam EdgeRange a range of `std::pair<DT::Vertex_handle, DT::Vertex_handle>`
\tparam PolygonMesh a model of `MutableFaceGraph` whose points are of the type `DT::Point`
\param dt the triangulation; it is not modified
\param cycle the boundary, as in `lex_optimal_chain_with_boundary()` (for instance the
`edges` of the result of `Lex_optimal_chains::insert_boundary()`)
\param mesh the output; the surface is added to it only on success
\param np the named parameters of `lex_optimal_homologous_chain()` (but `relative_facets`),
and `keep_non_manifold` (see `lex_optimal_open_surface_reconstruction()`)

\returns a report; its triangulation, representative, order, optimal chain, resolution and
mesh fields are filled.
\throws Lex_optimal_chains::Input_error as `lex_optimal_chain_with_boundary()`.
\throws Lex_optimal_chains::Cancelled when the callback returns `false`; `mesh` is then unchanged.
*/
template <class DT, class EdgeRange, class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Open_surface_report
lex_optimal_open_surface_mesh(const DT& dt, const EdgeRange& cycle, PolygonMesh& mesh,
                              const NamedParameters& np = parameters::default_values())
{
  namespace LOC = Lex_optimal_chains;
  static_assert(Lex_optimal_chains::internal::Has_double_coordinates<typename DT::Geom_traits>::value, "");
  const std::function<bool(double)> callback = parameters::choose_parameter(
    parameters::get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  LOC::Open_surface_report report;
  LOC::internal::Stopwatch total;
  LOC::internal::check_dimension(dt);
  std::vector<typename DT::Point> soup_points;
  std::vector<std::array<std::uint32_t, 3>> soup;
  const std::set<typename DT::Vertex_handle> none;
  LOC::internal::open_surface_soup(dt, cycle, none, np, callback, 0.0, [] {}, report, soup_points, soup);
  LOC::internal::add_open_surface_soup(soup_points, soup, mesh, np, callback, report);
  report.total_seconds = total.lap();
  return report;
}

} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_OPEN_SURFACE_H
