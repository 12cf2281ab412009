// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_TILED_SURFACE_H
#define CGAL_LEX_OPTIMAL_TILED_SURFACE_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/Coefficient_field.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Tiled_surface_report.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_merge_3.h>
#include <CGAL/Lex_optimal_chains/internal/Tiles_in_memory_3.h>
#include <CGAL/Lex_optimal_chains/internal/Tiles_out_of_core_3.h>

#include <CGAL/Named_function_parameters.h>

#include <string>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgLexOptimalChainsRef

Reconstructs a terrain-like cloud (aerial LiDAR of a city, a digital surface model) tile by
tile, so that the meshes of neighbouring tiles coincide exactly at their common border (the
scheme of Fig. 4.27 of the thesis, made automatic; see the user manual, section "Tiles").

The bounding rectangle of the points in the \f$xy\f$-plane is cut into columns \f$\times\f$
rows tiles of equal size, at most `tile_size` on a side. Between neighbouring tiles runs a
seam, a polyline of input points: at each inner corner of the grid the point nearest to it,
and along each border, in each slice of about `seam_spacing`, the point nearest to the slice's
centre within half the spacing of the border. Around the whole cloud runs a frame, a
rectangle just outside it. Each tile is then an open surface
(`lex_optimal_open_surface_reconstruction()` with `remove_blocking_points` and
`drop_boundary_triangles`) of the points of its region and of its seam points, bounded by its
seams and the frame. Two tiles that share a seam have it as a border of both meshes, with the
same vertices: `Lex_optimal_chains::merge_tile_meshes()` welds them into one mesh without
cracks. The tiles are independent once the seams are known: they are reconstructed in
parallel, and the result does not depend on the number of threads nor on the order of the
points.

\tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
\tparam PolygonMesh a model of `MutableFaceGraph` whose points are of the type of the input points

\param points the input points (duplicates are merged); not modified
\param tile_size the largest side of a tile, in the units of the points; positive, at most
       the larger side of the bounding rectangle of the points (one tile is the untiled surface:
       call `lex_optimal_open_surface_reconstruction()` instead)
\param tile_meshes receives one mesh per tile, row after row (tile `(column, row)` at
       `column + columns * row`); on success only
\param np optional named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map giving the point of an element of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` with value type a `Point_3` with `double` coordinates}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{seam_spacing}
    \cgalParamDescription{the distance between consecutive seam points, and the width of the
                          band around a border where they are taken; positive, at most a
                          quarter of the side of a tile}
    \cgalParamType{`double`}
    \cgalParamDefault{3 times the mean spacing of the points in the \f$xy\f$-plane (the side of
                      the bounding rectangle's area shared among the points), at most a quarter
                      of the side of a tile}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{tiles reconstructed at once (needs TBB); the result does not depend on it}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{tile_visitor}
    \cgalParamDescription{called as `visitor(report, mesh)` with each tile as soon as it is
                          reconstructed (`report` its `Lex_optimal_chains::Tile_report`, `mesh`
                          its mesh, which the visitor may move from or clear: what it leaves is
                          the tile's entry of `tile_meshes`), one call at a time, from the
                          thread that reconstructed the tile; to write the tiles as they come
                          and keep the memory to that of the tiles being reconstructed. An
                          exception it throws is the error of that tile}
    \cgalParamType{a callable `void(const Lex_optimal_chains::Tile_report&, PolygonMesh&)`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{tile_filter}
    \cgalParamDescription{which tiles to reconstruct, for example when the tiles are dealt out to
                          several processes (MPI ranks, machines): called once, from the calling
                          thread, after the seams are computed and before any tile is
                          reconstructed, with the number of points of each tile in the order of
                          `tile_meshes` (its points and its seam points, as
                          `Tile_report::number_of_points`); it returns, in that order, whether
                          to reconstruct each. The others are left empty, and their
                          `Tile_report` says so (`reconstructed` is `false`). A tile's mesh does
                          not depend on which others are reconstructed: calls with the same
                          points and parameters that reconstruct disjoint sets of tiles give,
                          together, the tiles of one call that reconstructs them all. An
                          exception it throws is thrown by the call}
    \cgalParamType{a callable `std::vector<bool>(const std::vector<std::size_t>&)`}
    \cgalParamDefault{every tile}
  \cgalParamNEnd
  \cgalParamNBegin{coefficient_field}
    \cgalParamDescription{the coefficients of the chains of the tiles (see `lex_optimal_open_surface_reconstruction()`)}
    \cgalParamType{`Lex_optimal_chains::Coefficient_field`}
    \cgalParamDefault{`Lex_optimal_chains::Coefficient_field::Z2`}
  \cgalParamNEnd
  \cgalParamNBegin{keep_non_manifold}
    \cgalParamDescription{as in `lex_optimal_open_surface_reconstruction()`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return what was done, tile by tile

\throws Lex_optimal_chains::Input_error with code `EMPTY_INPUT`, `NON_FINITE_COORDINATE`,
`TOO_FEW_POINTS`, `INVALID_PARAMETER` (a tile size that is not positive or gives one tile, a
seam spacing out of its range, a grid of more than one tile per 4 points, a `tile_filter` that
does not return one value per tile, a tile corner with no input point near it: the seams run
through the points), or the error of the first tile (in the order of the tiles) that cannot
be reconstructed, its tile named in the message (an exception of the visitor becomes a
`std::runtime_error` naming the tile). `tile_meshes` is then unchanged.
*/
template <class PointRange, class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Tiled_surface_report
lex_optimal_tiled_surface_reconstruction(const PointRange& points, double tile_size,
                                         std::vector<PolygonMesh>& tile_meshes,
                                         const NamedParameters& np = parameters::default_values())
{
  return Lex_optimal_chains::internal::tiled_reconstruction_in_memory(points, tile_size, tile_meshes, np);
}

/*!
\ingroup PkgLexOptimalChainsRef

The tiled reconstruction of `lex_optimal_tiled_surface_reconstruction()` for clouds too large
for memory: the points stream through twice, and are bucketed into files, one per tile, so
that the memory holds the points near the seams and the tiles being reconstructed, not the
cloud. The tiles, their seams and their meshes are those of
`lex_optimal_tiled_surface_reconstruction()` on the same points, tile for tile (the order of
their faces included). Only the numbers of points given to `tile_filter` differ: they are
those of the cells of the grid of the tiles (the distinct points of each cell), counted before
the seams move the points near them to their tiles.

The passes:
1. `for_each_point` is called a first time: the bounding box of the points, and their check;
2. a second time: each point is appended to the bucket file of the cell of the grid that
   holds it;
3. each bucket is read, sorted and cleared of duplicates (the number of distinct points sets
   the default seam spacing);
4. each bucket is read again for its points near the inner border lines of the grid, from
   which the seams are made (in memory: a band of the width of the seam spacing along every
   inner border line);
5. each tile reads its bucket and takes the points near the seams that fall on its side.

\tparam PointSource a callable such that `for_each_point(f)` calls `f(p)` for every point `p`
        of the cloud, a `Point_3` with `double` coordinates, the same points on every call
        (their order does not matter)
\tparam PolygonMesh a model of `MutableFaceGraph` whose points are of the type of the input points

\param for_each_point the source of the points, called twice
\param tile_size as in `lex_optimal_tiled_surface_reconstruction()`
\param bucket_directory an existing directory where a fresh directory is made for the bucket
       files (24 bytes a point), and removed with them at the end, on an error too
\param tile_meshes as in `lex_optimal_tiled_surface_reconstruction()`; to keep the memory
       bounded, give a `tile_visitor` that writes each tile and clears its mesh
\param np the named parameters of `lex_optimal_tiled_surface_reconstruction()` but `point_map`

\return what was done, tile by tile

\throws Lex_optimal_chains::Input_error as `lex_optimal_tiled_surface_reconstruction()` does, and
with code `INVALID_PARAMETER` for a bucket directory that does not exist (checked first) or a
source that gives other points in its second call, `WRITE_FAILED` for bucket files that
cannot be written or read back. `tile_meshes` is then unchanged.
*/
template <class PointSource, class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Tiled_surface_report
lex_optimal_tiled_surface_reconstruction_out_of_core(const PointSource& for_each_point, double tile_size,
                                                     const std::string& bucket_directory,
                                                     std::vector<PolygonMesh>& tile_meshes,
                                                     const NamedParameters& np = parameters::default_values())
{
  return Lex_optimal_chains::internal::tiled_reconstruction_out_of_core(for_each_point, tile_size, bucket_directory,
                                                                       tile_meshes, np);
}

namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef

Welds the meshes of `lex_optimal_tiled_surface_reconstruction()` into one: border vertices at
the same point become one (the seam points, which both tiles of a seam share on their
borders), two faces on the
same three points cancel out (the union is the sum of the chains of the tiles: where a seam
makes a narrow excursion, up a wall and down again, both tiles span it; where they span it with
different triangles, their sum is a closed pocket, and closed components are removed), and the
result is
made a valid polygon mesh as the meshes of the tiles are (an edge of more than two faces is
cut, a vertex gets one copy per umbrella; over Z2 the faces are oriented by a traversal,
over Q they keep their orientation, which is that of the counterclockwise cycles of the tiles,
upwards). The faces must be triangles.

\param tile_meshes the meshes of the tiles
\param merged receives the union (it is cleared first; with a `Surface_mesh`, the faces of the
       closed components removed are garbage until `collect_garbage()`)
\param field the coefficient field the tiles were reconstructed with
\return what was done
*/
template <class PolygonMesh>
Tile_merge_report merge_tile_meshes(const std::vector<PolygonMesh>& tile_meshes, PolygonMesh& merged,
                                    Coefficient_field field = Coefficient_field::Z2)
{
  return internal::merge_tiles(tile_meshes, merged, field);
}

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_TILED_SURFACE_H
