// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILED_RECONSTRUCTION_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILED_RECONSTRUCTION_3_H

// What the two tiled reconstructions (points in memory, points streamed into bucket files)
// share: the settings read from the named parameters, the size of the tiles and the spacing
// of the seams from the bounding box and the number of distinct points, and the loop that
// reconstructs the tiles that the tile filter keeps once the seams are known, whatever holds
// their points.

#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Tiled_surface_report.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Optimal_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Parallel_blocks.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_seams_3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <iomanip>
#include <mutex>
#include <new>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The named parameters of the tiled reconstructions, but the point map.
template <class PolygonMesh>
struct Tile_settings
{
  unsigned threads = 1;
  Coefficient_field field = Coefficient_field::Z2;
  bool keep_non_manifold = false;
  double seam_spacing = 0; // 0: from the data
  std::function<std::vector<bool>(const std::vector<std::size_t>&)> filter; // empty: every tile
  std::function<void(const Tile_report&, PolygonMesh&)> visitor;
};

template <class PolygonMesh, class NamedParameters>
Tile_settings<PolygonMesh> tile_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Tile_settings<PolygonMesh> s;
  s.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 1u);
  s.field = coefficient_field_of(np);
  s.keep_non_manifold = choose_parameter(get_parameter(np, internal_np::keep_non_manifold), false);
  s.seam_spacing = choose_parameter(get_parameter(np, internal_np::seam_spacing), 0.);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::tile_filter_t>::value)
    s.filter = get_parameter(np, internal_np::tile_filter);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::tile_visitor_t>::value)
    s.visitor = get_parameter(np, internal_np::tile_visitor);
  return s;
}

// The sides of the tiles and the seam spacing of a cloud of `number_of_points` distinct points
// in `box`, into `report`; throws for a tile size or a spacing out of range.
inline void set_tile_grid(const Bbox_3& box, std::size_t number_of_points, double tile_size, double spacing,
                          Tiled_surface_report& report)
{
  const double width = box.xmax() - box.xmin(), height = box.ymax() - box.ymin();
  if(!(tile_size > 0) || !std::isfinite(tile_size))
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "the tile size must be positive and finite (it is " + std::to_string(tile_size) + ")");
  if(!(tile_size < (std::max)(width, height)))
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "the tile size " + std::to_string(tile_size) + " is not smaller than the cloud (" +
                        std::to_string(width) + " x " + std::to_string(height) +
                        "): one tile is the untiled surface (lex_optimal_open_surface_reconstruction)");
  const double columns = std::ceil(width / tile_size), rows = std::ceil(height / tile_size);
  // (a grid finer than the points is a mistake, and its tiles would not fit in memory)
  const double tiles = (std::max)(columns, 1.) * (std::max)(rows, 1.);
  if(tiles > double(number_of_points) / 4) {
    std::ostringstream what;
    what << "the tile size " << tile_size << " gives " << std::fixed << std::setprecision(0) << tiles << " tiles for "
         << number_of_points << " points: a tile needs at least 4 points";
    throw Input_error(Input_error_code::INVALID_PARAMETER, what.str());
  }
  const double tile_width = width / columns, tile_height = height / rows;
  // the sides of the tiles along the axes that are cut: at least 4 seam spacings
  const double smallest_side = (std::min)(width > tile_size ? tile_width : HUGE_VAL, height > tile_size ? tile_height : HUGE_VAL);
  if(spacing == 0)
    spacing = (std::min)(3 * std::sqrt((std::max)(width, 1e-300) * (std::max)(height, 1e-300) / double(number_of_points)),
                         smallest_side / 4);
  if(!(spacing > 0) || !(spacing <= smallest_side / 4))
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "the seam spacing " + std::to_string(spacing) + " must be positive and at most " +
                        std::to_string(smallest_side / 4) + ", a quarter of the side of a tile");
  report.number_of_input_points = number_of_points;
  report.tile_width = tile_width;
  report.tile_height = tile_height;
  report.seam_spacing = spacing;
}

// The cycles of the tiles, and the seam points of tile t that lie on its cycle (which its
// points get after their own).
template <class Point>
std::vector<std::vector<Point>> tile_cycles(const Tile_seams_3<Point>& seams)
{
  std::vector<std::vector<Point>> cycles(seams.number_of_tiles());
  for(std::size_t t = 0; t < cycles.size(); ++t) cycles[t] = seams.cycle(t % seams.columns(), t / seams.columns());
  return cycles;
}

template <class Point>
void append_cycle_seam_points(const Tile_seams_3<Point>& seams, const std::vector<Point>& cycle, std::vector<Point>& points)
{
  for(std::size_t k = 0; k + 1 < cycle.size(); ++k)
    if(seams.is_seam_point(cycle[k])) points.push_back(cycle[k]);
}

// The tiles to reconstruct, increasing: those that `filter` keeps (called once with the number
// of points of each tile), every tile without a filter.
inline std::vector<std::size_t> kept_tiles(const std::function<std::vector<bool>(const std::vector<std::size_t>&)>& filter,
                                           const std::vector<std::size_t>& points_per_tile)
{
  std::vector<std::size_t> kept;
  if(!filter) {
    kept.resize(points_per_tile.size());
    std::iota(kept.begin(), kept.end(), std::size_t(0));
    return kept;
  }
  const std::vector<bool> keep = filter(points_per_tile);
  if(keep.size() != points_per_tile.size())
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "tile_filter returned " + std::to_string(keep.size()) + " values for " +
                        std::to_string(points_per_tile.size()) + " tiles: it must return one per tile");
  for(std::size_t t = 0; t < keep.size(); ++t)
    if(keep[t]) kept.push_back(t);
  return kept;
}

// Reconstructs the tiles that the filter of `s` keeps (called with `points_per_tile`), each
// on one thread, into `meshes` and `report.tiles`. `points_of(t)` gives the points of tile t
// (its region's, sorted, then its cycle's seam points); it is called once per tile, from the
// thread of the tile. The first error in the order of the tiles is thrown, naming its tile.
template <class Point, class PolygonMesh, class PointsOf>
void reconstruct_tiles(const Tile_seams_3<Point>& seams, const std::vector<std::vector<Point>>& cycles,
                       const std::vector<std::size_t>& points_per_tile, const PointsOf& points_of,
                       const Tile_settings<PolygonMesh>& s, std::vector<PolygonMesh>& meshes, Tiled_surface_report& report)
{
  const std::vector<std::size_t> mine = kept_tiles(s.filter, points_per_tile);
  meshes.assign(seams.number_of_tiles(), PolygonMesh());
  std::vector<Tile_report> tiles(seams.number_of_tiles());
  for(std::size_t t = 0; t < tiles.size(); ++t) {
    tiles[t].column = t % seams.columns();
    tiles[t].row = t / seams.columns();
    tiles[t].number_of_cycle_vertices = cycles[t].size() - 1;
  }
  std::vector<std::exception_ptr> errors(seams.number_of_tiles());
  std::mutex visitor_mutex;
  Parallel_blocks parallel(s.threads, 2);
  report.number_of_threads = parallel.is_parallel(mine.size()) ? s.threads : 1;
  parallel.run(0, mine.size(), 1, mine.size(), [&](std::size_t m, std::size_t, std::size_t) {
    const std::size_t t = mine[m];
    Stopwatch tile_watch;
    Tile_report& r = tiles[t];
    try {
      {
        const std::vector<Point> points = points_of(t);
        r.number_of_points = points.size();
        const auto open = lex_optimal_open_surface_reconstruction(
          points, std::vector<std::vector<Point>>{cycles[t]}, meshes[t],
          parameters::remove_blocking_points(
            true, parameters::drop_boundary_triangles(
                    true, parameters::coefficient_field(s.field, parameters::keep_non_manifold(s.keep_non_manifold)))));
        r.reconstructed = true;
        r.number_of_removed_points = open.number_of_removed_points;
        r.mesh_vertices = open.mesh_vertices;
        r.mesh_faces = open.mesh_faces;
      }
      r.seconds = tile_watch.lap();
      if(s.visitor) {
        std::lock_guard<std::mutex> lock(visitor_mutex);
        s.visitor(r, meshes[t]);
      }
    } catch(...) {
      errors[t] = std::current_exception();
    }
  });
  for(std::size_t t = 0; t < errors.size(); ++t) {
    if(!errors[t]) continue;
    const std::string where = "tile (" + std::to_string(t % seams.columns()) + ", " + std::to_string(t / seams.columns()) + "): ";
    try {
      std::rethrow_exception(errors[t]);
    } catch(const Input_error& e) {
      throw Input_error(e.code(), where + e.what());
    } catch(const std::bad_alloc&) { // out of memory: as it is
      throw;
    } catch(const std::exception& e) { // from the visitor
      throw std::runtime_error(where + e.what());
    }
  }
  report.tiles = std::move(tiles);
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILED_RECONSTRUCTION_3_H
