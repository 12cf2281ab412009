// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILES_IN_MEMORY_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILES_IN_MEMORY_3_H

// lex_optimal_tiled_surface_reconstruction() of points in memory: the points sorted and
// without duplicates, the seams, the points of each tile, then the tiles.

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Tiled_surface_report.h>
#include <CGAL/Lex_optimal_chains/internal/Delaunay_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_seams_3.h>
#include <CGAL/Lex_optimal_chains/internal/Tiled_reconstruction_3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class PointRange, class PolygonMesh, class NamedParameters>
Tiled_surface_report tiled_reconstruction_in_memory(const PointRange& points, double tile_size,
                                                    std::vector<PolygonMesh>& tile_meshes, const NamedParameters& np)
{
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Point = typename boost::property_traits<Point_map>::value_type;
  const Point_map point_map =
    CGAL::parameters::choose_parameter<Point_map>(CGAL::parameters::get_parameter(np, CGAL::internal_np::point_map));
  const Tile_settings<PolygonMesh> settings = tile_settings<PolygonMesh>(np);

  Tiled_surface_report report;
  Stopwatch total, watch;
  std::vector<Point> pts = finite_points<Point>(points, point_map);
  // Sorted and without duplicates: each tile gets its points in one order whatever the input's
  // (the test gives the points shuffled, and each twice).
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if(pts.size() < 4) throw Input_error(Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");
  const Bbox_3 box = bbox_3(pts.begin(), pts.end());
  set_tile_grid(box, pts.size(), tile_size, settings.seam_spacing, report);

  // the seams, and the points of each tile (its region's, then its cycle's seam points)
  const Tile_seams_3<Point> seams(pts, tile_size, report.seam_spacing);
  report.columns = seams.columns();
  report.rows = seams.rows();
  report.number_of_seam_points = seams.seam_points().size();
  std::vector<std::vector<Point>> tile_points(seams.number_of_tiles());
  for(const Point& p : pts)
    if(!seams.is_seam_point(p)) tile_points[seams.tile_of(p)].push_back(p);
  std::vector<Point>().swap(pts);
  const std::vector<std::vector<Point>> cycles = tile_cycles(seams);
  std::vector<std::size_t> points_per_tile(seams.number_of_tiles());
  for(std::size_t t = 0; t < cycles.size(); ++t) {
    append_cycle_seam_points(seams, cycles[t], tile_points[t]);
    points_per_tile[t] = tile_points[t].size();
  }
  report.seam_seconds = watch.lap();

  std::vector<PolygonMesh> meshes;
  reconstruct_tiles(seams, cycles, points_per_tile, [&](std::size_t t) { return std::move(tile_points[t]); }, settings,
                    meshes, report);
  report.tiles_seconds = watch.lap();
  tile_meshes = std::move(meshes);
  report.total_seconds = total.lap();
  return report;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILES_IN_MEMORY_3_H
