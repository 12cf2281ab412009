// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_OPEN_SURFACE_H
#define CGAL_LEX_OPTIMAL_OPEN_SURFACE_H

/// \file lex_optimal_open_surface.h
/// Open surface reconstruction with an imposed boundary (thesis section 4.8.2).

#include <CGAL/lex_optimal_homologous_chain.h>
#include <CGAL/Lex_optimal_chains/Coefficient_field.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_mesh.h>
#include <CGAL/Lex_optimal_chains/internal/Delaunay_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Open_surface_repair_3.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class Point>
std::string point_string(const Point& p)
{
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << " " << p.y() << " " << p.z() << ")";
  return s.str();
}

// Checks the boundary polylines: closed, finite, simple (no repeated vertex, no two
// segments meeting except consecutive ones at their common vertex), and near the points.
// Returns the polylines without their closing vertex.
template <class Kernel, class PolylineRange>
std::vector<std::vector<typename Kernel::Point_3>>
checked_polylines(const PolylineRange& polylines, const Bbox_3& points_box)
{
  using Point = typename Kernel::Point_3;
  using Segment = typename Kernel::Segment_3;
  std::vector<std::vector<Point>> result;
  for(const auto& polyline : polylines) {
    std::vector<Point> p(polyline.begin(), polyline.end());
    for(const Point& q : p)
      if(!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()))
        throw Input_error(Input_error_code::NON_FINITE_COORDINATE, "a boundary vertex has a NaN or infinite coordinate");
    if(p.size() < 2 || p.front() != p.back())
      throw Input_error(Input_error_code::OPEN_POLYLINE,
                        "boundary polyline " + std::to_string(result.size()) + " is not closed: its last vertex must repeat its first");
    p.pop_back();
    if(p.size() < 3)
      throw Input_error(Input_error_code::SELF_INTERSECTING_BOUNDARY,
                        "boundary polyline " + std::to_string(result.size()) + " has fewer than 3 vertices");
    result.push_back(std::move(p));
  }
  if(result.empty()) throw Input_error(Input_error_code::BOUNDARY_NOT_A_CYCLE, "no boundary polyline");

  // repeated vertices
  std::vector<Point> all;
  for(const auto& p : result) all.insert(all.end(), p.begin(), p.end());
  std::sort(all.begin(), all.end());
  const auto repeated = std::adjacent_find(all.begin(), all.end());
  if(repeated != all.end())
    throw Input_error(Input_error_code::SELF_INTERSECTING_BOUNDARY,
                      "the boundary passes twice through the vertex " + point_string(*repeated));

  // crossing segments: boxes first, then exact predicates
  struct Segment_id { std::size_t polyline, index; };
  using Box = Box_intersection_d::Box_with_info_d<double, 3, Segment_id>;
  std::vector<Box> boxes;
  for(std::size_t l = 0; l < result.size(); ++l)
    for(std::size_t i = 0; i < result[l].size(); ++i) {
      const Point& a = result[l][i];
      const Point& b = result[l][(i + 1) % result[l].size()];
      boxes.emplace_back(a.bbox() + b.bbox(), Segment_id{l, i});
    }
  auto segment = [&](const Segment_id& s) {
    return Segment(result[s.polyline][s.index], result[s.polyline][(s.index + 1) % result[s.polyline].size()]);
  };
  box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    const Segment_id s = x.info(), t = y.info();
    const std::size_t n = result[s.polyline].size();
    const bool consecutive = s.polyline == t.polyline && ((s.index + 1) % n == t.index || (t.index + 1) % n == s.index);
    bool crossing;
    if(consecutive && n > 3) {
      // they share a vertex b; they overlap iff the polyline turns back there
      const Segment_id first = (s.index + 1) % n == t.index ? s : t;
      const Point& a = result[first.polyline][first.index];
      const Point& b = result[first.polyline][(first.index + 1) % n];
      const Point& c = result[first.polyline][(first.index + 2) % n];
      crossing = collinear(a, b, c) && angle(a, b, c) == ACUTE;
    } else if(consecutive) { // a triangle: all its edges are consecutive
      const Point& a = result[s.polyline][0];
      const Point& b = result[s.polyline][1];
      const Point& c = result[s.polyline][2];
      crossing = collinear(a, b, c);
    } else {
      crossing = do_intersect(segment(s), segment(t));
    }
    if(crossing)
      throw Input_error(Input_error_code::SELF_INTERSECTING_BOUNDARY,
                        "boundary segments " + point_string(segment(s).source()) + " - " + point_string(segment(s).target()) +
                        " and " + point_string(segment(t).source()) + " - " + point_string(segment(t).target()) + " intersect");
  });

  // far from the points: farther from their bounding box than its diagonal
  const double diagonal = std::sqrt(square(points_box.xmax() - points_box.xmin()) + square(points_box.ymax() - points_box.ymin()) +
                                    square(points_box.zmax() - points_box.zmin()));
  for(const auto& p : result) {
    Bbox_3 box;
    for(const Point& q : p) box += q.bbox();
    double gap2 = 0;
    for(int d = 0; d < 3; ++d) {
      const double g = (std::max)({0.0, box.min(d) - points_box.max(d), points_box.min(d) - box.max(d)});
      gap2 += g * g;
    }
    if(std::sqrt(gap2) > diagonal)
      throw Input_error(Input_error_code::BOUNDARY_FAR_FROM_POINTS,
                        "a boundary polyline is " + std::to_string(std::sqrt(gap2)) +
                        " away from the bounding box of the points, more than its diagonal " + std::to_string(diagonal));
  }
  return result;
}

// Inserts the boundary vertices, makes sure that the boundary edges are edges of `dt`
// (removing the input points in the diametral balls of the missing ones if `remove` is set)
// and returns the cycle as oriented vertex pairs. `boundary_only` receives the boundary
// vertices that are not input points.
template <class Triangulation, class Point>
std::vector<std::pair<typename Triangulation::Vertex_handle, typename Triangulation::Vertex_handle>>
insert_boundary(Triangulation& dt, const std::vector<std::vector<Point>>& polylines, bool remove,
                std::set<typename Triangulation::Vertex_handle>& boundary_only, std::size_t& removed)
{
  using Vertex_handle = typename Triangulation::Vertex_handle;
  std::set<Point> boundary_points;
  for(const auto& p : polylines) {
    for(const Point& q : p) {
      boundary_points.insert(q);
      typename Triangulation::Locate_type lt;
      int li, lj;
      const auto c = dt.locate(q, lt, li, lj);
      if(lt == Triangulation::VERTEX) continue;
      boundary_only.insert(dt.insert(q, lt, c, li, lj));
    }
  }
  auto handle = [&](const Point& q) {
    typename Triangulation::Locate_type lt;
    int li, lj;
    const auto c = dt.locate(q, lt, li, lj);
    CGAL_assertion(lt == Triangulation::VERTEX);
    return c->vertex(li);
  };
  // the handles of the boundary-only vertices are stable: only input points are removed
  using Traits = Search_traits_3<typename Kernel_traits<Point>::Kernel>;
  std::unique_ptr<Kd_tree<Traits>> tree;
  removed = 0;
  for(;;) {
    std::vector<std::pair<Vertex_handle, Vertex_handle>> cycle;
    std::vector<std::pair<Point, Point>> missing;
    for(const auto& p : polylines)
      for(std::size_t i = 0; i < p.size(); ++i) {
        const Vertex_handle u = handle(p[i]), v = handle(p[(i + 1) % p.size()]);
        typename Triangulation::Cell_handle c;
        int a, b;
        if(dt.is_edge(u, v, c, a, b)) cycle.emplace_back(u, v);
        else missing.emplace_back(p[i], p[(i + 1) % p.size()]);
      }
    if(missing.empty()) return cycle;
    const std::string which = "the boundary edge " + point_string(missing.front().first) + " - " +
                              point_string(missing.front().second) + " (and " + std::to_string(missing.size() - 1) +
                              " other) is not an edge of the Delaunay triangulation";
    if(!remove)
      throw Input_error(Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION,
                        which + "; the input points near the boundary can be removed (remove_blocking_points)");
    if(!tree) {
      tree.reset(new Kd_tree<Traits>());
      for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        if(!boundary_points.count(v->point())) tree->insert(v->point());
      tree->build();
    }
    // the closed diametral ball of a missing edge holds the points that keep it out: once
    // it is empty the edge is Gabriel, hence Delaunay
    std::size_t before = removed;
    for(const auto& e : missing) {
      const Point center = midpoint(e.first, e.second);
      const double radius = std::sqrt(squared_distance(e.first, e.second)) / 2;
      std::vector<Point> inside;
      tree->search(std::back_inserter(inside), Fuzzy_sphere<Traits>(center, radius * (1 + 1e-12) + 1e-300, 0.));
      for(const Point& q : inside) {
        typename Triangulation::Locate_type lt;
        int li, lj;
        const auto c = dt.locate(q, lt, li, lj);
        if(lt != Triangulation::VERTEX) continue; // already removed
        dt.remove(c->vertex(li));
        ++removed;
      }
    }
    if(removed == before)
      throw Input_error(Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION,
                        which + ", and no input point blocks it: other boundary vertices do");
  }
}

} // namespace internal
} // namespace Lex_optimal_chains

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
    \cgalParamType{a model of `ReadablePropertyMap` with value type a `Point_3` of an `Epick`-like kernel}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{threads used for the Delaunay triangulation (with TBB, from 100,000 points: below, the parallel construction is slower); the result does not depend on it}
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
    \cgalParamDescription{drops the triangles that touch a boundary vertex that is not an input point (Fig. 4.26 of the thesis: the skirt joining an outer polygon to a terrain)}
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
points, no terrain) or `CANCELLED`.
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
  static_assert(std::is_same<typename Kernel::FT, double>::value && bool(Kernel::Has_filtered_predicates),
                "lex_optimal_open_surface_reconstruction needs points of a kernel with double coordinates and exact (filtered) "
                "predicates, such as Epick: the Delaunay triangulation is built with its predicates");

  const Point_map point_map = choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map));
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  const unsigned threads = choose_parameter(get_parameter(np, LOC::internal_np::number_of_threads), 1u);
  const bool remove = choose_parameter(get_parameter(np, LOC::internal_np::remove_blocking_points), false);
  const bool drop = choose_parameter(get_parameter(np, LOC::internal_np::drop_boundary_triangles), false);
  const bool keep = choose_parameter(get_parameter(np, LOC::internal_np::keep_non_manifold), false);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const LOC::Coefficient_field field = LOC::internal::coefficient_field_of(np);

  LOC::Open_surface_report report;
  LOC::internal::Stopwatch total, watch;
  std::vector<Point> pts = LOC::internal::finite_points<Point>(points, point_map);
  report.number_of_input_points = pts.size();
  const auto boundary = LOC::internal::checked_polylines<Kernel>(polylines, bbox_3(pts.begin(), pts.end()));
  if(callback && !callback(0.0)) throw LOC::Input_error(LOC::Input_error_code::CANCELLED, "cancelled by the callback");

  std::vector<Point> soup_points;
  std::vector<std::array<std::uint32_t, 3>> soup;
  LOC::internal::with_delaunay_triangulation<Kernel>(pts, threads, [&](auto& dt) {
    using Triangulation = std::remove_reference_t<decltype(dt)>;
    std::vector<Point>().swap(pts);
    std::set<typename Triangulation::Vertex_handle> boundary_only;
    const auto cycle = LOC::internal::insert_boundary(dt, boundary, remove, boundary_only, report.number_of_removed_points);
    report.number_of_boundary_vertices = boundary_only.size();
    try {
      LOC::internal::check_dimension(dt);
    } catch(const LOC::Input_error& e) {
      if(report.number_of_removed_points == 0) throw;
      throw LOC::Input_error(e.code(), std::string(e.what()) + ", after the removal of " +
                                         std::to_string(report.number_of_removed_points) +
                                         " input points that kept boundary edges out of it (remove_blocking_points): "
                                         "the boundary passes through the cloud nearly everywhere");
    }
    report.delaunay_seconds = watch.lap();
    if(verbose)
      std::cerr << "Lex_optimal_chains: Delaunay triangulation of " << dt.number_of_vertices() << " vertices in "
                << report.delaunay_seconds << " s (" << report.number_of_removed_points << " points removed)\n";
    const std::set<typename Triangulation::Vertex_handle> none;
    // the facets go straight into the soup (the number of facets is in the report before the
    // first one is written)
    LOC::internal::Chain_soup_builder<Triangulation> builder(dt.tds(), field == LOC::Coefficient_field::Q,
                                                             drop ? boundary_only : none, &report.number_of_facets);
    auto write_chain = [&](const auto& add) {
      auto sink = boost::make_function_output_iterator(
        [&add](const std::pair<typename Triangulation::Facet, std::int64_t>& fk) { add(fk.first, fk.second); });
      if(field == LOC::Coefficient_field::Z2)
        LOC::internal::optimal_chain_with_boundary<LOC::internal::Z2_arithmetic>(dt, cycle, np, callback, 0.35, sink, report);
      else
        LOC::internal::optimal_chain_with_boundary<LOC::internal::Integer_arithmetic>(dt, cycle, np, callback, 0.35, sink, report);
      watch.lap();
    };
    const LOC::internal::Open_surface_repair_result resolution =
      LOC::internal::resolved_open_chain(dt, field == LOC::Coefficient_field::Q, keep, builder, write_chain);
    report.resolved_non_manifold_vertices = resolution.statistics.repaired_vertices;
    report.resolution_changed_facets = resolution.changed_facets;
    report.resolution_seconds = watch.lap();
    if(verbose)
      std::cerr << "Lex_optimal_chains: " << resolution.statistics.repaired_vertices << " non-manifold vertices resolved ("
                << resolution.statistics.changed_cells << " cells changed, " << resolution.changed_facets
                << " facets changed, " << resolution.statistics.rounds << " rounds) in " << report.resolution_seconds << " s\n";
    builder.take_points();
    dt.clear(); // before the soup is sorted: peak memory
    builder.finish(soup_points, soup, report.dropped_triangles);
    if(soup.empty() && report.dropped_triangles > 0)
      throw LOC::Input_error(LOC::Input_error_code::EMPTY_RESULT,
                             "all " + std::to_string(report.dropped_triangles) +
                               " triangles of the optimal surface touch a boundary vertex that is not an input "
                               "point and were dropped (drop_boundary_triangles): the points do not span the "
                               "boundary as a surface (for footprint_boundary(), the points must be a terrain-like "
                               "tile, a height field over their xy-footprint)");
    report.output_seconds += watch.lap(); // after the writing of the chain into the soup
  });
  LOC::internal::report_progress(callback, 1.0); // the last chance to cancel: the mesh is not modified before
  const std::size_t vertices_before = num_vertices(mesh), faces_before = num_faces(mesh);
  const LOC::internal::Chain_soup_statistics stats =
    LOC::internal::add_chain_soup(soup_points, soup, field == LOC::Coefficient_field::Q, mesh);
  report.non_manifold_vertices = stats.vertex_copies;
  report.non_manifold_edges = stats.non_manifold_edges;
  report.orientation_cuts = stats.orientation_cuts;
  report.mesh_vertices = num_vertices(mesh) - vertices_before;
  report.mesh_faces = num_faces(mesh) - faces_before;
  const double build_seconds = watch.lap();
  if(verbose)
    std::cerr << "Lex_optimal_chains: soup and triangulation freed in " << report.output_seconds
              << " s, mesh built in " << build_seconds << " s\n";
  report.output_seconds += build_seconds;
  report.total_seconds = total.lap();
  return report;
}

} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_OPEN_SURFACE_H
