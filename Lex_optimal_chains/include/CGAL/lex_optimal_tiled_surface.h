// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_TILED_SURFACE_H
#define CGAL_LEX_OPTIMAL_TILED_SURFACE_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Tiled_surface_report.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_mesh.h>
#include <CGAL/Lex_optimal_chains/internal/Delaunay_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Optimal_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Parallel_blocks.h>
#include <CGAL/Lex_optimal_chains/internal/Peak_memory.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_seams_3.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_shares.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <boost/functional/hash.hpp>

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
  \cgalParamNBegin{tile_share}
    \cgalParamDescription{the share of the tiles that this call reconstructs, when the tiles are
                          dealt out to several processes (`Lex_optimal_chains::Tile_share`): the
                          other tiles are left empty, and their `Tile_report` says so. Each
                          process calls the function with the same points and parameters and
                          its own share; the union of the shares is the result of one call with
                          every tile, tile for tile}
    \cgalParamType{`Lex_optimal_chains::Tile_share`}
    \cgalParamDefault{every tile (`Tile_share{0, 1}`)}
  \cgalParamNEnd
  \cgalParamNBegin{measure_tile_memory}
    \cgalParamDescription{if `true` and the tiles run one at a time (one thread), the peak resident
                          size of the process is measured during each tile
                          (`Tile_report::peak_memory_bytes`) and over the call
                          (`Tiled_surface_report::peak_memory_bytes`). On Linux only: the peak
                          is reset before each tile (`/proc/self/clear_refs`), so the peak that
                          the process reports afterwards (`getrusage()`) no longer includes what
                          came before the first tile; `Tiled_surface_report::peak_memory_bytes`
                          does}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
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
seam spacing out of its range, a share with no tiles (`count` 0, or `index` not below it), a tile corner with no input point near it: the seams run
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
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace LOC = Lex_optimal_chains;
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Point = typename boost::property_traits<Point_map>::value_type;
  const Point_map point_map = choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map));
  const unsigned threads = choose_parameter(get_parameter(np, LOC::internal_np::number_of_threads), 1u);
  const LOC::Coefficient_field field = LOC::internal::coefficient_field_of(np);
  const bool keep = choose_parameter(get_parameter(np, LOC::internal_np::keep_non_manifold), false);
  std::function<void(const LOC::Tile_report&, PolygonMesh&)> visitor;
  if constexpr(!parameters::is_default_parameter<NamedParameters, LOC::internal_np::tile_visitor_t>::value)
    visitor = get_parameter(np, LOC::internal_np::tile_visitor);
  std::mutex visitor_mutex;
  const LOC::Tile_share share = choose_parameter(get_parameter(np, LOC::internal_np::tile_share), LOC::Tile_share());
  if(share.count == 0 || share.index >= share.count)
    throw LOC::Input_error(LOC::Input_error_code::INVALID_PARAMETER,
                           "the tile share " + std::to_string(share.index) + " of " + std::to_string(share.count) +
                             " does not exist (shares 0 to count - 1, count at least 1)");
  const bool measure_memory = choose_parameter(get_parameter(np, LOC::internal_np::measure_tile_memory), false);

  LOC::Tiled_surface_report report;
  report.share = share;
  LOC::internal::Stopwatch total, watch;
  std::vector<Point> pts = LOC::internal::finite_points<Point>(points, point_map);
  // Sorted and without duplicates: each tile gets its points in one order whatever the input's
  // (the test gives the points shuffled, and each twice).
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  report.number_of_input_points = pts.size();
  if(pts.size() < 4) throw LOC::Input_error(LOC::Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");

  const Bbox_3 box = bbox_3(pts.begin(), pts.end());
  const double width = box.xmax() - box.xmin(), height = box.ymax() - box.ymin();
  if(!(tile_size > 0) || !std::isfinite(tile_size))
    throw LOC::Input_error(LOC::Input_error_code::INVALID_PARAMETER,
                           "the tile size must be positive and finite (it is " + std::to_string(tile_size) + ")");
  if(!(tile_size < std::max(width, height)))
    throw LOC::Input_error(LOC::Input_error_code::INVALID_PARAMETER,
                           "the tile size " + std::to_string(tile_size) + " is not smaller than the cloud (" +
                             std::to_string(width) + " x " + std::to_string(height) +
                             "): one tile is the untiled surface (lex_optimal_open_surface_reconstruction)");
  const double tile_width = width / std::ceil(width / tile_size), tile_height = height / std::ceil(height / tile_size);
  // the sides of the tiles along the axes that are cut: at least 4 seam spacings
  const double smallest_side = std::min(width > tile_size ? tile_width : HUGE_VAL, height > tile_size ? tile_height : HUGE_VAL);
  double spacing = choose_parameter(get_parameter(np, LOC::internal_np::seam_spacing), 0.);
  if(spacing == 0) spacing = std::min(3 * std::sqrt(std::max(width, 1e-300) * std::max(height, 1e-300) / double(pts.size())),
                                      smallest_side / 4);
  if(!(spacing > 0) || !(spacing <= smallest_side / 4))
    throw LOC::Input_error(LOC::Input_error_code::INVALID_PARAMETER,
                           "the seam spacing " + std::to_string(spacing) + " must be positive and at most " +
                             std::to_string(smallest_side / 4) + ", a quarter of the side of a tile");
  report.tile_width = tile_width;
  report.tile_height = tile_height;
  report.seam_spacing = spacing;

  // the seams, and the points of each tile (its region's, then its cycle's seam points)
  const LOC::internal::Tile_seams_3<Point> seams(pts, tile_size, spacing);
  report.columns = seams.columns();
  report.rows = seams.rows();
  report.number_of_seam_points = seams.seam_points().size();
  std::vector<std::vector<Point>> tile_points(seams.number_of_tiles());
  for(const Point& p : pts)
    if(!seams.is_seam_point(p)) tile_points[seams.tile_of(p)].push_back(p);
  std::vector<Point>().swap(pts);
  std::vector<std::vector<Point>> cycles(seams.number_of_tiles());
  for(std::size_t t = 0; t < cycles.size(); ++t) {
    cycles[t] = seams.cycle(t % seams.columns(), t / seams.columns());
    for(std::size_t k = 0; k + 1 < cycles[t].size(); ++k)
      if(seams.is_seam_point(cycles[t][k])) tile_points[t].push_back(cycles[t][k]);
  }
  report.seam_seconds = watch.lap();

  // the tiles of this call's share, independently (each on one thread); the first error in the
  // order of the tiles wins
  std::vector<std::size_t> tile_cost(seams.number_of_tiles());
  for(std::size_t t = 0; t < tile_cost.size(); ++t) tile_cost[t] = tile_points[t].size();
  const std::vector<std::size_t> share_of = LOC::internal::deal_tiles(tile_cost, share.count);
  std::vector<std::size_t> mine;
  for(std::size_t t = 0; t < share_of.size(); ++t)
    if(share_of[t] == share.index) mine.push_back(t);
  std::vector<PolygonMesh> meshes(seams.number_of_tiles());
  std::vector<LOC::Tile_report> tiles(seams.number_of_tiles());
  for(std::size_t t = 0; t < tiles.size(); ++t) {
    tiles[t].column = t % seams.columns();
    tiles[t].row = t / seams.columns();
    tiles[t].number_of_points = tile_points[t].size();
    tiles[t].number_of_cycle_vertices = cycles[t].size() - 1;
    tiles[t].share = share_of[t];
  }
  std::vector<std::exception_ptr> errors(seams.number_of_tiles());
  LOC::internal::Parallel_blocks parallel(threads, 2);
  report.number_of_threads = parallel.is_parallel(mine.size()) ? threads : 1;
  // the peak of each tile: only when they run one at a time (the peak is the process's)
  const bool measure = measure_memory && !parallel.is_parallel(mine.size()) && LOC::internal::peak_resident_bytes() > 0;
  if(measure) report.peak_memory_bytes = LOC::internal::peak_resident_bytes();
  parallel.run(0, mine.size(), 1, mine.size(), [&](std::size_t m, std::size_t, std::size_t) {
    const std::size_t t = mine[m];
    LOC::internal::Stopwatch tile_watch;
    const bool measured = measure && LOC::internal::reset_peak_resident_bytes();
    LOC::Tile_report& r = tiles[t];
    try {
      const auto open = lex_optimal_open_surface_reconstruction(
        tile_points[t], std::vector<std::vector<Point>>{cycles[t]}, meshes[t],
        LOC::parameters::remove_blocking_points(
          true, LOC::parameters::drop_boundary_triangles(
                  true, LOC::parameters::coefficient_field(field, LOC::parameters::keep_non_manifold(keep)))));
      r.reconstructed = true;
      r.number_of_removed_points = open.number_of_removed_points;
      r.mesh_vertices = open.mesh_vertices;
      r.mesh_faces = open.mesh_faces;
      std::vector<Point>().swap(tile_points[t]);
      r.seconds = tile_watch.lap();
      if(measured) {
        r.peak_memory_bytes = LOC::internal::peak_resident_bytes();
        report.peak_memory_bytes = (std::max)(report.peak_memory_bytes, r.peak_memory_bytes);
      }
      if(visitor) {
        std::lock_guard<std::mutex> lock(visitor_mutex);
        visitor(r, meshes[t]);
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
    } catch(const LOC::Input_error& e) {
      throw LOC::Input_error(e.code(), where + e.what());
    } catch(const std::exception& e) { // from the visitor
      throw std::runtime_error(where + e.what());
    }
  }
  report.tiles_seconds = watch.lap();
  report.tiles = std::move(tiles);
  tile_meshes = std::move(meshes);
  report.total_seconds = total.lap();
  return report;
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
  using Point = typename boost::property_traits<typename boost::property_map<PolygonMesh, vertex_point_t>::const_type>::value_type;
  internal::Stopwatch watch;
  Tile_merge_report report;
  // one index per distinct point of the borders (hashed), and the number of tiles where it is a vertex
  struct Point_hash
  {
    std::size_t operator()(const Point& p) const
    {
      std::size_t seed = 0;
      boost::hash_combine(seed, p.x());
      boost::hash_combine(seed, p.y());
      boost::hash_combine(seed, p.z());
      return seed;
    }
  };
  std::unordered_map<Point, std::uint32_t, Point_hash> index_of;
  std::vector<Point> distinct;
  std::vector<std::uint32_t> last_tile, tiles_of_point;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for(std::size_t t = 0; t < tile_meshes.size(); ++t) {
    const PolygonMesh& m = tile_meshes[t];
    const auto vpm = get(vertex_point, m);
    auto global = get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), m);
    for(auto v : vertices(m)) {
      // Only a border vertex can be shared with another tile (a seam point is on the cycle of
      // its tiles): the others get their own index without a lookup.
      if(!CGAL::is_border(v, m)) {
        put(global, v, std::uint32_t(distinct.size()));
        distinct.push_back(get(vpm, v));
        last_tile.push_back(std::uint32_t(t));
        tiles_of_point.push_back(1);
        continue;
      }
      const auto inserted = index_of.emplace(get(vpm, v), std::uint32_t(distinct.size()));
      if(inserted.second) {
        distinct.push_back(get(vpm, v));
        last_tile.push_back(std::uint32_t(t));
        tiles_of_point.push_back(1);
      } else if(last_tile[inserted.first->second] != t) {
        last_tile[inserted.first->second] = std::uint32_t(t);
        ++tiles_of_point[inserted.first->second];
      }
      put(global, v, inserted.first->second);
    }
    for(auto f : faces(m)) {
      std::array<std::uint32_t, 3> tri;
      int k = 0;
      for(auto h : halfedges_around_face(halfedge(f, m), m)) {
        if(k == 3) throw Input_error(Input_error_code::INVALID_PARAMETER, "a face of a tile mesh is not a triangle");
        tri[k++] = get(global, target(h, m));
      }
      if(k != 3) throw Input_error(Input_error_code::INVALID_PARAMETER, "a face of a tile mesh is not a triangle");
      triangles.push_back(tri);
    }
  }
  // The union is the sum of the chains of the tiles: a triangle that two tiles both have (where
  // a seam makes a narrow excursion, up a wall and down again, both tiles span it, each with the
  // orientation of its own cycle) cancels out, as the seam itself does. Only a triangle whose
  // three points are vertices of several tiles can be one.
  {
    std::vector<std::pair<std::array<std::uint32_t, 3>, std::size_t>> candidates;
    for(std::size_t i = 0; i < triangles.size(); ++i) {
      std::array<std::uint32_t, 3> key = triangles[i];
      if(tiles_of_point[key[0]] < 2 || tiles_of_point[key[1]] < 2 || tiles_of_point[key[2]] < 2) continue;
      std::sort(key.begin(), key.end());
      candidates.emplace_back(key, i);
    }
    std::sort(candidates.begin(), candidates.end());
    std::vector<bool> kept(triangles.size(), true);
    for(std::size_t i = 0, j; i < candidates.size(); i = j) {
      for(j = i + 1; j < candidates.size() && candidates[j].first == candidates[i].first; ++j) {}
      // pairs cancel: an odd count leaves the first one
      for(std::size_t k = (j - i) % 2; k < j - i; ++k) kept[candidates[i + k].second] = false;
    }
    std::size_t n = 0;
    for(std::size_t i = 0; i < triangles.size(); ++i)
      if(kept[i]) triangles[n++] = triangles[i];
    report.cancelled_faces = triangles.size() - n;
    triangles.resize(n);
  }
  clear(merged);
  const internal::Chain_soup_statistics stats = internal::add_chain_soup(distinct, triangles, field == Coefficient_field::Q, merged);
  // Where a seam makes an excursion (up a wall and down again), both tiles may also span the
  // narrow curtain under it, each with its own triangles: their sum is a closed pocket. A closed
  // component has no boundary: without it the union has the same boundary and is smaller in
  // the lexicographic order. Closed components are removed while one with a boundary is left.
  {
    auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), merged);
    const std::size_t n = Polygon_mesh_processing::connected_components(merged, component);
    std::vector<bool> bounded(n, false);
    std::vector<std::size_t> size(n, 0);
    for(auto h : halfedges(merged))
      if(is_border(h, merged)) bounded[get(component, face(opposite(h, merged), merged))] = true;
    for(auto f : faces(merged)) ++size[get(component, f)];
    std::vector<std::size_t> closed;
    for(std::size_t c = 0; c < n; ++c)
      if(!bounded[c]) closed.push_back(c);
    if(closed.size() < n && !closed.empty()) {
      Polygon_mesh_processing::remove_connected_components(merged, closed, component);
      report.removed_closed_components = closed.size();
      for(std::size_t c : closed) report.removed_closed_faces += size[c];
    }
  }
  report.mesh_vertices = std::size_t(std::distance(vertices(merged).begin(), vertices(merged).end()));
  report.mesh_faces = std::size_t(std::distance(faces(merged).begin(), faces(merged).end()));
  report.non_manifold_vertices = stats.vertex_copies;
  report.non_manifold_edges = stats.non_manifold_edges;
  report.orientation_cuts = stats.orientation_cuts;
  report.seconds = watch.lap();
  return report;
}

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_TILED_SURFACE_H
