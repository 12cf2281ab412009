// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILES_OUT_OF_CORE_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILES_OUT_OF_CORE_3_H

// lex_optimal_tiled_surface_reconstruction_out_of_core(): the points stream through twice,
// into bucket files of the cells of the grid of the tiles; the seams are made from the points
// near the inner border lines, and each tile reads its bucket. The tiles get the points, in
// the order, that lex_optimal_tiled_surface_reconstruction() gives them.

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Tiled_surface_report.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_buckets.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_seams_3.h>
#include <CGAL/Lex_optimal_chains/internal/Tiled_reconstruction_3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Pass 1: the bounding box and the number of the points of `for_each_point`, checked as
// lex_optimal_tiled_surface_reconstruction() checks its points (fewer than 4 distinct points
// are known by the first 4 distinct ones).
template <class Point, class PointSource>
std::size_t first_pass(const PointSource& for_each_point, Bbox_3& box)
{
  std::size_t count = 0;
  std::vector<Point> first_distinct;
  for_each_point([&](const Point& p) {
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(Input_error_code::NON_FINITE_COORDINATE,
                        "point " + std::to_string(count) + " has a NaN or infinite coordinate");
    box += p.bbox();
    ++count;
    if(first_distinct.size() < 4 && std::find(first_distinct.begin(), first_distinct.end(), p) == first_distinct.end())
      first_distinct.push_back(p);
  });
  if(count == 0) throw Input_error(Input_error_code::EMPTY_INPUT, "no input point");
  if(first_distinct.size() < 4) throw Input_error(Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");
  return count;
}

// Pass 2: each point appended to the bucket of its cell of `grid` (the source must give the
// points of pass 1 again: `count` of them, in `box`); then each bucket sorted, without
// duplicates (which share a cell). Returns the number of distinct points of each cell.
template <class Point, class PointSource>
std::vector<std::size_t> bucket_points(const PointSource& for_each_point, const Bbox_3& box, std::size_t count,
                                       const Tile_grid& grid, Tile_buckets<Point>& buckets)
{
  std::size_t second_count = 0;
  for_each_point([&](const Point& p) {
    if(!(p.x() >= box.xmin() && p.x() <= box.xmax() && p.y() >= box.ymin() && p.y() <= box.ymax() &&
         p.z() >= box.zmin() && p.z() <= box.zmax()) || ++second_count > count)
      throw Input_error(Input_error_code::INVALID_PARAMETER,
                        "the point source gave other points in its second pass than in its first");
    const Point q(p.x() + 0.0, p.y() + 0.0, p.z() + 0.0); // -0 + 0 = +0, as for the points in memory
    buckets.add(grid.cell_of(q.x(), q.y()), q);
  });
  if(second_count != count)
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "the point source gave " + std::to_string(second_count) + " points in its second pass, " +
                        std::to_string(count) + " in its first");
  buckets.flush();
  std::vector<std::size_t> distinct(grid.number_of_tiles());
  for(std::size_t cell = 0; cell < distinct.size(); ++cell) {
    std::vector<Point> points = buckets.read(cell);
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    buckets.replace(cell, points);
    distinct[cell] = points.size();
  }
  return distinct;
}

// The points of the buckets near the inner border lines of `grid` (within `spacing`), sorted:
// the seams need only these.
template <class Point>
std::vector<Point> band_points(const Tile_buckets<Point>& buckets, const Tile_grid& grid, double spacing)
{
  std::vector<Point> band;
  for(std::size_t cell = 0; cell < grid.number_of_tiles(); ++cell)
    for(const Point& p : buckets.read(cell))
      if(Tile_seams_3<Point>::in_band(grid, p, spacing)) band.push_back(p);
  std::sort(band.begin(), band.end());
  return band;
}

template <class PointSource, class PolygonMesh, class NamedParameters>
Tiled_surface_report tiled_reconstruction_out_of_core(const PointSource& for_each_point, double tile_size,
                                                      const std::string& bucket_directory,
                                                      std::vector<PolygonMesh>& tile_meshes, const NamedParameters& np)
{
  using Point = typename boost::property_traits<typename boost::property_map<PolygonMesh, vertex_point_t>::const_type>::value_type;
  const Tile_settings<PolygonMesh> settings = tile_settings<PolygonMesh>(np);
  Tiled_surface_report report;
  Stopwatch total, watch;
  std::error_code directory_error;
  if(!std::filesystem::is_directory(bucket_directory, directory_error))
    throw Input_error(Input_error_code::INVALID_PARAMETER, "the bucket directory '" + bucket_directory + "' is not a directory");

  Bbox_3 box;
  const std::size_t count = first_pass<Point>(for_each_point, box);
  // the tile size and a given spacing checked before the buckets are written
  set_tile_grid(box, count, tile_size, settings.seam_spacing, report);
  const Tile_grid grid(box, tile_size);
  Tile_buckets<Point> buckets(bucket_directory, grid.number_of_tiles());
  const std::vector<std::size_t> points_per_cell = bucket_points(for_each_point, box, count, grid, buckets);
  std::size_t distinct = 0;
  for(std::size_t n : points_per_cell) distinct += n;
  if(distinct < 4) throw Input_error(Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");
  set_tile_grid(box, distinct, tile_size, settings.seam_spacing, report);

  // the seams, from the points near the inner border lines
  std::vector<Point> band = band_points(buckets, grid, report.seam_spacing);
  const Tile_seams_3<Point> seams(box, band, tile_size, report.seam_spacing);
  report.columns = seams.columns();
  report.rows = seams.rows();
  report.number_of_seam_points = seams.seam_points().size();
  // the points near a seam that fall in another tile than their cell's, per tile (sorted)
  std::vector<std::vector<Point>> moved(seams.number_of_tiles());
  for(const Point& p : band) {
    const std::size_t t = seams.tile_of(p);
    if(t != grid.cell_of(p.x(), p.y()) && !seams.is_seam_point(p)) moved[t].push_back(p);
  }
  std::vector<Point>().swap(band);
  const std::vector<std::vector<Point>> cycles = tile_cycles(seams);
  report.seam_seconds = watch.lap();

  // the points of a tile: those of its bucket that stay in it, and those that move into it, in
  // order, then its cycle's seam points (as in memory)
  auto points_of = [&](std::size_t t) {
    std::vector<Point> own = buckets.read(t);
    own.erase(std::remove_if(own.begin(), own.end(),
                             [&](const Point& p) { return seams.is_seam_point(p) || seams.tile_of(p) != t; }),
              own.end());
    std::vector<Point> points;
    points.reserve(own.size() + moved[t].size());
    std::merge(own.begin(), own.end(), moved[t].begin(), moved[t].end(), std::back_inserter(points));
    std::vector<Point>().swap(moved[t]);
    append_cycle_seam_points(seams, cycles[t], points);
    return points;
  };
  std::vector<PolygonMesh> meshes;
  reconstruct_tiles(seams, cycles, points_per_cell, points_of, settings, meshes, report);
  report.tiles_seconds = watch.lap();
  tile_meshes = std::move(meshes);
  report.total_seconds = total.lap();
  return report;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILES_OUT_OF_CORE_3_H
