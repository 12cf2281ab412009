// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_CLOSED_SURFACE_REPORT_H
#define CGAL_LEX_OPTIMAL_CHAINS_CLOSED_SURFACE_REPORT_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <cstddef>

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
  double runner_up_persistence = 0;            ///< persistence ratio of the second most persistent void (1 if none), with the automatic interior
  bool robust = false;                         ///< true if the points were smoothed first (`robust`; reconstruction only)
  std::size_t smoothing_neighbors = 0;         ///< k of the jet fits of the robust mode
  std::size_t smoothing_passes = 0;            ///< smoothing passes of the robust mode
  double noise_estimate = 0;                   ///< median distance by which the first smoothing pass moved the points (robust mode)
  double average_spacing = 0;                  ///< mean distance of an input point to its 6 nearest neighbours (robust mode)
  double smoothing_seconds = 0;                ///< time of the smoothing (robust mode)
  double delaunay_seconds = 0;                 ///< time to build the Delaunay triangulation
  double order_seconds = 0;                    ///< time to order the triangles (largest triangle of each cell, contraction, sort of the others)
  double cut_seconds = 0;                      ///< time of the automatic interior and of Algorithm 8
  double resolution_seconds = 0;               ///< time to find and resolve the non-manifold vertices of the cycle
  double output_seconds = 0;                   ///< time to build the mesh
  double total_seconds = 0;                    ///< time of the whole call
  std::size_t mesh_vertices = 0;               ///< vertices of the output mesh (reconstruction and `lex_optimal_closed_surface_mesh()`)
  std::size_t mesh_faces = 0;                  ///< faces of the output mesh (reconstruction and `lex_optimal_closed_surface_mesh()`)
  std::size_t components = 0;                  ///< connected components of the output mesh
  std::size_t non_manifold_vertices = 0;       ///< triangulation vertices split in several mesh vertices (none unless `keep_non_manifold`, or a resolution failed)
  std::size_t non_manifold_edges = 0;          ///< triangulation edges split in several mesh edges (likewise)
  long genus = 0;                              ///< sum of the genera of the components
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_CLOSED_SURFACE_REPORT_H
