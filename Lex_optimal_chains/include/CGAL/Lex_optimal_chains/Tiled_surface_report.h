// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_TILED_SURFACE_REPORT_H
#define CGAL_LEX_OPTIMAL_CHAINS_TILED_SURFACE_REPORT_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
What `lex_optimal_tiled_surface_reconstruction()` did with one tile.
*/
struct Tile_report
{
  std::size_t column = 0;           ///< column of the tile (along x, from 0)
  std::size_t row = 0;              ///< row of the tile (along y, from 0)
  std::size_t number_of_points = 0; ///< input points of the tile, its seam points included (0 if this call did not reconstruct it)
  std::size_t number_of_cycle_vertices = 0; ///< vertices of its boundary cycle (seam points and frame vertices)
  std::size_t number_of_removed_points = 0; ///< points removed so that the cycle is in its triangulation
  std::size_t mesh_vertices = 0;    ///< vertices of its mesh
  std::size_t mesh_faces = 0;       ///< faces of its mesh
  double seconds = 0;               ///< time of its reconstruction
  bool reconstructed = false;       ///< whether this call reconstructed it (`tile_filter` kept it); if not, its mesh is empty and the counts of its mesh 0
};

/*!
\ingroup PkgLexOptimalChainsRef
What `lex_optimal_tiled_surface_reconstruction()` did.
*/
struct Tiled_surface_report
{
  std::size_t number_of_input_points = 0; ///< points given (duplicates merged)
  std::size_t columns = 0;                ///< tiles along x
  std::size_t rows = 0;                   ///< tiles along y
  double tile_width = 0;                  ///< side of the tiles along x (at most the tile size)
  double tile_height = 0;                 ///< side of the tiles along y (at most the tile size)
  double seam_spacing = 0;                ///< spacing of the seam points used
  std::size_t number_of_seam_points = 0;  ///< input points on the seams
  std::size_t number_of_threads = 0;      ///< threads used for the tiles
  std::vector<Tile_report> tiles;         ///< per tile, row after row
  double seam_seconds = 0;                ///< time to compute the seams and sort the points into tiles
  double tiles_seconds = 0;               ///< time to reconstruct the tiles
  double total_seconds = 0;               ///< time of the whole call
};

/*!
\ingroup PkgLexOptimalChainsRef
What `merge_tile_meshes()` did.
*/
struct Tile_merge_report
{
  std::size_t mesh_vertices = 0;         ///< vertices of the merged mesh
  std::size_t mesh_faces = 0;            ///< faces of the merged mesh
  std::size_t cancelled_faces = 0;       ///< faces that two tiles both had, removed in pairs
  std::size_t removed_closed_components = 0; ///< closed components (pockets under seam excursions) removed
  std::size_t removed_closed_faces = 0;  ///< their faces
  std::size_t non_manifold_vertices = 0; ///< vertex copies added to separate umbrellas
  std::size_t non_manifold_edges = 0;    ///< edges of more than two faces, cut
  std::size_t orientation_cuts = 0;      ///< edges cut to orient the mesh (Z2)
  double seconds = 0;                    ///< time of the merge
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_TILED_SURFACE_REPORT_H
