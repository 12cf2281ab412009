// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CLOSED_SURFACE_H
#define CGAL_LEX_OPTIMAL_CLOSED_SURFACE_H

/// \file lex_optimal_closed_surface.h
/// Closed surface reconstruction as a lexicographic optimal 2-cycle (thesis section 4.8.1).

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/Closed_surface_report.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Noise_smoothing_3.h>
#include <CGAL/Lex_optimal_chains/internal/Geom_traits_check.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_pipeline_3.h>
#include <CGAL/Lex_optimal_chains/internal/Delaunay_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>
#include <type_traits>
#include <vector>

namespace CGAL {

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
    \cgalParamDefault{none: the interior is accepted when it stands out from the other voids (a ratio of at
                      least 2 and at least the square of the second largest ratio), or from a ratio of 4
                      unless the points were smoothed (`robust` of the reconstruction)}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{called with the progress in [0,1]; returning `false` cancels (the last
                          call, with 1, comes before anything is written to `facets`)}
    \cgalParamType{`std::function<bool(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{threads (with TBB) for the contraction of the cells across their largest facets and for the keys and the sort of the triangles, from 200,000 cells; the result does not depend on it}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{1}
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
\throws Lex_optimal_chains::Cancelled when the callback returns `false`; nothing is then
written to `facets`.
*/
template <class DT, class OutputIterator, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Closed_surface_report
lex_optimal_closed_surface(const DT& dt, OutputIterator facets,
                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static_assert(Lex_optimal_chains::internal::Has_double_coordinates<typename DT::Geom_traits>::value, "");
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

/*!
\ingroup PkgLexOptimalChainsRef

Adds to `mesh` the closed surface of a user's Delaunay triangulation: the lexicographic
optimal 2-cycle of `lex_optimal_closed_surface()`, its non-manifold vertices resolved unless
`keep_non_manifold` is set, as a closed triangle mesh oriented outward, with the vertices of
`dt` that it touches. This is `lex_optimal_closed_surface_reconstruction()` on a triangulation
that the caller built, with its own vertex and cell bases, location policy or concurrency tag;
what is left non-manifold is split as described there.

\tparam DT a `Delaunay_triangulation_3` whose points have `double` coordinates
\tparam PolygonMesh a model of `MutableFaceGraph` whose points are of the type `DT::Point`
\param dt the triangulation; it is not modified
\param mesh the output; the surface is added to it only on success
\param np the named parameters of `lex_optimal_closed_surface()`

\returns a report; its triangulation, order, cut, resolution and mesh fields are filled.
\throws Lex_optimal_chains::Input_error as `lex_optimal_closed_surface()`.
\throws Lex_optimal_chains::Cancelled when the callback returns `false`; `mesh` is then unchanged.
*/
template <class DT, class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Closed_surface_report
lex_optimal_closed_surface_mesh(const DT& dt, PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static_assert(Lex_optimal_chains::internal::Has_double_coordinates<typename DT::Geom_traits>::value, "");
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  Lex_optimal_chains::Closed_surface_report report;
  Lex_optimal_chains::internal::Stopwatch total;
  Lex_optimal_chains::internal::add_closed_surface_mesh(dt, mesh, np, callback, 0.0, report, [] {});
  report.total_seconds = total.lap();
  return report;
}

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
    \cgalParamType{a model of `ReadablePropertyMap` with value type a `Point_3` with `double` coordinates}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{the geometric traits with which the Delaunay triangulation is built}
    \cgalParamType{a model of `LexOptimalChainsTraits_3` whose `Point_3` is the point type}
    \cgalParamDefault{the kernel of the points (`CGAL::Kernel_traits`)}
  \cgalParamNEnd
  \cgalParamNBegin{robust}
    \cgalParamDescription{if `true`, the points are first smoothed for noise: each moved onto a jet (a local
                          quadric) fitted to its nearest neighbours, pass after pass until a pass moves them
                          by less than 5% of what the first did (at most 6 passes; points whose first pass
                          moved them by less than 5% of their spacing are left as they were; see the user
                          manual, section "Noisy scans"); the surface goes through the smoothed points. The
                          automatic interior must then stand out from the other voids (see
                          `minimum_interior_persistence`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{smoothing_neighbors}
    \cgalParamDescription{the number of neighbours of the jet fits of the robust mode (0, or at least 8)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{0: CGAL's `estimate_global_k_neighbor_scale()` of the points, at least 24}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{threads used for the Delaunay triangulation (with TBB, from 100,000 points: below, the parallel construction is slower), for the smoothing of the robust mode, and for the contraction of the dual graph and the keys and the sort of its triangles (from 200,000 cells); the result does not depend on it}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{1}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Lex_optimal_chains::Input_error on empty input, NaN or infinite coordinates, fewer than
4 distinct points, coplanar points, `robust` without Eigen, `smoothing_neighbors` from 1 to 7,
and the errors of
`lex_optimal_closed_surface()`.
\throws Lex_optimal_chains::Cancelled when the callback returns `false`; `mesh` is then unchanged.
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
  using Geom_traits = typename CGAL::internal_np::Lookup_named_param_def<
    CGAL::internal_np::geom_traits_t, NamedParameters, Kernel>::type;
  static_assert(Lex_optimal_chains::internal::Has_exact_predicates_and_double_coordinates<Geom_traits>::value, "");
  const Geom_traits traits = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));

  const Point_map point_map = choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map));
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  const unsigned threads = choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::number_of_threads), 1u);

  Lex_optimal_chains::Closed_surface_report report;
  Lex_optimal_chains::internal::Stopwatch total, watch;
  std::vector<Point> pts = Lex_optimal_chains::internal::finite_points<Point>(points, point_map);
  report.number_of_input_points = pts.size();
  Lex_optimal_chains::internal::report_progress(callback, 0.0);
  if(choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::robust), false)) {
    watch.lap(); // reading the points is not smoothing
    const Lex_optimal_chains::internal::Noise_smoothing_result s = Lex_optimal_chains::internal::smooth_noisy_points(
      pts, choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::smoothing_neighbors), std::size_t(0)), threads);
    report.robust = true;
    report.smoothing_neighbors = s.neighbors;
    report.smoothing_passes = s.passes;
    report.noise_estimate = s.noise_estimate;
    report.average_spacing = s.average_spacing;
    report.smoothing_seconds = watch.lap();
  }
  Lex_optimal_chains::internal::with_delaunay_triangulation(pts, traits, threads, [&](auto& dt) {
    std::vector<Point>().swap(pts); // freed as soon as possible: peak memory
    report.delaunay_seconds = watch.lap();
    Lex_optimal_chains::internal::add_closed_surface_mesh(dt, mesh, np, callback, 0.35, report, [&dt] { dt.clear(); });
  });
  report.total_seconds = total.lap();
  return report;
}

} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CLOSED_SURFACE_H
