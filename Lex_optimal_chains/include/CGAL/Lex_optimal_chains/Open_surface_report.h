// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_OPEN_SURFACE_REPORT_H
#define CGAL_LEX_OPTIMAL_CHAINS_OPEN_SURFACE_REPORT_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <cstddef>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
What an open-surface computation did: sizes, timings and the topology of the output. Fields
that a function does not compute stay at zero.
*/
struct Open_surface_report
{
  std::size_t number_of_input_points = 0;        ///< points given (reconstruction only)
  std::size_t number_of_boundary_vertices = 0;   ///< boundary vertices that are not input points (reconstruction only)
  std::size_t number_of_removed_points = 0;      ///< input points removed so that the boundary is in the triangulation
  std::size_t number_of_vertices = 0;            ///< vertices of the triangulation
  std::size_t number_of_triangles = 0;           ///< finite facets of the triangulation (dual edges)
  std::size_t number_of_triangles_in_close_runs = 0;   ///< triangles whose fast keys were too close to be ordered by them
  std::size_t number_of_exactly_ordered_triangles = 0; ///< of those, triangles ordered by the exact comparator
  std::size_t number_of_relative_triangles = 0;  ///< triangles of the subcomplex B
  std::size_t number_of_swept_vertices = 0;      ///< vertices handled by Algorithm 11
  std::size_t number_of_representative_triangles = 0; ///< triangles of the representative chain
  std::size_t number_of_facets = 0;              ///< triangles of the optimal chain
  std::size_t number_of_multiple_facets = 0;     ///< of those, triangles whose coefficient is not 1 or -1 (Q only)
  std::size_t resolved_non_manifold_vertices = 0; ///< local changes of the chain that made a non-manifold vertex manifold (reconstruction and `lex_optimal_open_surface_mesh()`)
  std::size_t resolution_changed_facets = 0;     ///< triangles in the symmetric difference of the optimal chain and the output chain (reconstruction and `lex_optimal_open_surface_mesh()`)
  double delaunay_seconds = 0;                   ///< time to build the Delaunay triangulation
  double representative_seconds = 0;             ///< time of Algorithm 11
  double order_seconds = 0;                      ///< time to contract the dual graph and sort the triangles left
  double optimal_chain_seconds = 0;              ///< time of Algorithm 10
  double resolution_seconds = 0;                 ///< time to find and resolve the non-manifold vertices (reconstruction and `lex_optimal_open_surface_mesh()`)
  double output_seconds = 0;                     ///< time to write the chain (and to build the mesh, for the reconstruction and `lex_optimal_open_surface_mesh()`)
  double total_seconds = 0;                      ///< time of the whole call
  std::size_t mesh_vertices = 0;                 ///< vertices of the output mesh (reconstruction and `lex_optimal_open_surface_mesh()`)
  std::size_t mesh_faces = 0;                    ///< faces of the output mesh (reconstruction and `lex_optimal_open_surface_mesh()`)
  std::size_t dropped_triangles = 0;             ///< triangles dropped because they touch a boundary-only vertex
  std::size_t trimmed_triangles = 0;             ///< triangles dropped after them, unless `keep_non_manifold`: the fans that the drop left pinched at an input point (all but one per point: the one in the largest part of the surface)
  std::size_t non_manifold_vertices = 0;         ///< vertex copies added to separate umbrellas: the non-manifold vertices left by the resolution, or all with `keep_non_manifold` (reconstruction and `lex_optimal_open_surface_mesh()`)
  std::size_t non_manifold_edges = 0;            ///< edges of more than two triangles of the output chain, split in the mesh (reconstruction and `lex_optimal_open_surface_mesh()`)
  std::size_t orientation_cuts = 0;              ///< edges cut to orient the mesh: over Z2, where the chain is not orientable (reconstruction and `lex_optimal_open_surface_mesh()`)
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_OPEN_SURFACE_REPORT_H
