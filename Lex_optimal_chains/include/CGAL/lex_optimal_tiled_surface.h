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
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_buckets.h>
#include <CGAL/Lex_optimal_chains/internal/Tile_seams_3.h>
#include <CGAL/Lex_optimal_chains/internal/Tiled_reconstruction_3.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iterator>
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
seam spacing out of its range, a grid of more than one tile per 4 points, a share with no
tiles (`count` 0, or `index` not below it), a tile corner with no input point near it: the seams run
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
  const LOC::internal::Tile_settings<PolygonMesh> settings = LOC::internal::tile_settings<PolygonMesh>(np);

  LOC::Tiled_surface_report report;
  report.share = settings.share;
  LOC::internal::Stopwatch total, watch;
  std::vector<Point> pts = LOC::internal::finite_points<Point>(points, point_map);
  // Sorted and without duplicates: each tile gets its points in one order whatever the input's
  // (the test gives the points shuffled, and each twice).
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if(pts.size() < 4) throw LOC::Input_error(LOC::Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");
  const Bbox_3 box = bbox_3(pts.begin(), pts.end());
  LOC::internal::set_tile_grid(box, pts.size(), tile_size, settings.seam_spacing, report);

  // the seams, and the points of each tile (its region's, then its cycle's seam points)
  const LOC::internal::Tile_seams_3<Point> seams(pts, tile_size, report.seam_spacing);
  report.columns = seams.columns();
  report.rows = seams.rows();
  report.number_of_seam_points = seams.seam_points().size();
  std::vector<std::vector<Point>> tile_points(seams.number_of_tiles());
  for(const Point& p : pts)
    if(!seams.is_seam_point(p)) tile_points[seams.tile_of(p)].push_back(p);
  std::vector<Point>().swap(pts);
  const std::vector<std::vector<Point>> cycles = LOC::internal::tile_cycles(seams);
  std::vector<std::size_t> cost(seams.number_of_tiles());
  for(std::size_t t = 0; t < cycles.size(); ++t) {
    LOC::internal::append_cycle_seam_points(seams, cycles[t], tile_points[t]);
    cost[t] = tile_points[t].size();
  }
  report.seam_seconds = watch.lap();

  std::vector<PolygonMesh> meshes;
  LOC::internal::reconstruct_tiles(seams, cycles, cost, [&](std::size_t t) { return std::move(tile_points[t]); },
                                   settings, meshes, report);
  report.tiles_seconds = watch.lap();
  tile_meshes = std::move(meshes);
  report.total_seconds = total.lap();
  return report;
}

/*!
\ingroup PkgLexOptimalChainsRef

The tiled reconstruction of `lex_optimal_tiled_surface_reconstruction()` for clouds too large
for memory: the points stream through twice, and are bucketed into files, one per tile, so
that the memory holds the points near the seams and the tiles being reconstructed, not the
cloud. The tiles, their seams and their meshes are those of
`lex_optimal_tiled_surface_reconstruction()` on the same points, tile for tile (the order of
their faces included); only the deal of the tiles to shares (`tile_share`) may differ, since it
counts the points of a tile before the seams move the points near them.

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
  namespace LOC = Lex_optimal_chains;
  using Point = typename boost::property_traits<typename boost::property_map<PolygonMesh, vertex_point_t>::const_type>::value_type;
  const LOC::internal::Tile_settings<PolygonMesh> settings = LOC::internal::tile_settings<PolygonMesh>(np);
  LOC::Tiled_surface_report report;
  report.share = settings.share;
  LOC::internal::Stopwatch total, watch;

  std::error_code directory_error;
  if(!std::filesystem::is_directory(bucket_directory, directory_error))
    throw LOC::Input_error(LOC::Input_error_code::INVALID_PARAMETER,
                           "the bucket directory '" + bucket_directory + "' is not a directory");

  // pass 1: the box, and the points checked as lex_optimal_tiled_surface_reconstruction() does
  // (fewer than 4 distinct points are known by the first 4 distinct ones)
  Bbox_3 box;
  std::size_t count = 0;
  std::vector<Point> first_distinct;
  for_each_point([&](const Point& p) {
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw LOC::Input_error(LOC::Input_error_code::NON_FINITE_COORDINATE,
                             "point " + std::to_string(count) + " has a NaN or infinite coordinate");
    box += p.bbox();
    ++count;
    if(first_distinct.size() < 4 && std::find(first_distinct.begin(), first_distinct.end(), p) == first_distinct.end())
      first_distinct.push_back(p);
  });
  if(count == 0) throw LOC::Input_error(LOC::Input_error_code::EMPTY_INPUT, "no input point");
  if(first_distinct.size() < 4) throw LOC::Input_error(LOC::Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");
  // the tile size and a given spacing checked before the buckets are written
  LOC::internal::set_tile_grid(box, count, tile_size, settings.seam_spacing, report);
  const LOC::internal::Tile_grid grid(box, tile_size);

  // pass 2: the buckets (the source must give the points of pass 1 again); then each one
  // sorted, without duplicates (which share a cell)
  LOC::internal::Tile_buckets<Point> buckets(bucket_directory, grid.number_of_tiles());
  std::size_t second_count = 0;
  for_each_point([&](const Point& p) {
    if(!(p.x() >= box.xmin() && p.x() <= box.xmax() && p.y() >= box.ymin() && p.y() <= box.ymax() &&
         p.z() >= box.zmin() && p.z() <= box.zmax()) || ++second_count > count)
      throw LOC::Input_error(LOC::Input_error_code::INVALID_PARAMETER,
                             "the point source gave other points in its second pass than in its first");
    const Point q(p.x() + 0.0, p.y() + 0.0, p.z() + 0.0); // -0 + 0 = +0, as for the points in memory
    buckets.add(grid.cell_of(q.x(), q.y()), q);
  });
  if(second_count != count)
    throw LOC::Input_error(LOC::Input_error_code::INVALID_PARAMETER,
                           "the point source gave " + std::to_string(second_count) + " points in its second pass, " +
                             std::to_string(count) + " in its first");
  buckets.flush();
  std::vector<std::size_t> cost(grid.number_of_tiles());
  std::size_t distinct = 0;
  for(std::size_t cell = 0; cell < cost.size(); ++cell) {
    std::vector<Point> points = buckets.read(cell);
    std::sort(points.begin(), points.end());
    const auto end = std::unique(points.begin(), points.end());
    points.erase(end, points.end());
    buckets.replace(cell, points);
    cost[cell] = points.size();
    distinct += points.size();
  }
  if(distinct < 4) throw LOC::Input_error(LOC::Input_error_code::TOO_FEW_POINTS, "fewer than 4 distinct points");
  LOC::internal::set_tile_grid(box, distinct, tile_size, settings.seam_spacing, report);

  // the seams, from the points near the inner border lines
  std::vector<Point> band;
  for(std::size_t cell = 0; cell < cost.size(); ++cell)
    for(const Point& p : buckets.read(cell))
      if(LOC::internal::Tile_seams_3<Point>::in_band(grid, p, report.seam_spacing)) band.push_back(p);
  std::sort(band.begin(), band.end());
  const LOC::internal::Tile_seams_3<Point> seams(box, band, tile_size, report.seam_spacing);
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
  const std::vector<std::vector<Point>> cycles = LOC::internal::tile_cycles(seams);
  report.seam_seconds = watch.lap();

  // the points of a tile: those of its bucket that stay in it, and those that move into it, in
  // order, then its cycle's seam points (as in lex_optimal_tiled_surface_reconstruction())
  auto points_of = [&](std::size_t t) {
    std::vector<Point> own = buckets.read(t);
    own.erase(std::remove_if(own.begin(), own.end(),
                             [&](const Point& p) { return seams.is_seam_point(p) || seams.tile_of(p) != t; }),
              own.end());
    std::vector<Point> points;
    points.reserve(own.size() + moved[t].size());
    std::merge(own.begin(), own.end(), moved[t].begin(), moved[t].end(), std::back_inserter(points));
    std::vector<Point>().swap(moved[t]);
    LOC::internal::append_cycle_seam_points(seams, cycles[t], points);
    return points;
  };
  std::vector<PolygonMesh> meshes;
  LOC::internal::reconstruct_tiles(seams, cycles, cost, points_of, settings, meshes, report);
  report.tiles_seconds = watch.lap();
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
