// Tests of lex_optimal_tiled_surface_reconstruction() and merge_tile_meshes(): the tiles of a
// synthetic terrain with buildings and of CGAL's aerial scan b9_training.ply meet exactly at
// their seams (the union is one valid mesh with one boundary loop, every seam edge has a face
// of each tile); away from the seams the tiles give the triangles of the untiled surface; the
// result does not depend on the number of threads nor on the order of the points; a tile
// filter chooses the tiles without changing them; bad input is refused with its reason.
//   test_tiled_surface [CGAL data directory]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/lex_optimal_tiled_surface.h>
#include <CGAL/Lex_optimal_chains/internal/Gabriel_seams_3.h>

#include "dense_block_with_walls.h"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;
namespace PMP = CGAL::Polygon_mesh_processing;
using Triangle = std::array<Point, 3>;

// A terrain of side 100 (gentle hills) with flat-roofed buildings 6 to 15 high, sampled on a
// jittered grid of step 0.8 from above (as aerial LiDAR is: the walls get a few points only).
std::vector<Point> terrain_with_buildings(unsigned seed)
{
  CGAL::Random rng(seed);
  struct Box { double x0, y0, x1, y1, h; };
  std::vector<Box> boxes;
  for(int i = 0; i < 12; ++i) {
    const double x = rng.get_double(5, 85), y = rng.get_double(5, 85);
    boxes.push_back({x, y, x + rng.get_double(6, 12), y + rng.get_double(6, 12), rng.get_double(6, 15)});
  }
  auto ground = [](double x, double y) { return 2 * std::sin(0.05 * x) * std::cos(0.04 * y) + 0.02 * x; };
  std::vector<Point> points;
  const double step = 0.8;
  for(double x = 0; x <= 100; x += step)
    for(double y = 0; y <= 100; y += step) {
      const double px = x + rng.get_double(-0.3, 0.3) * step, py = y + rng.get_double(-0.3, 0.3) * step;
      double z = ground(px, py);
      for(const Box& b : boxes)
        if(px > b.x0 && px < b.x1 && py > b.y0 && py < b.y1) z = std::max(z, ground(b.x0, b.y0) + b.h);
      points.emplace_back(px, py, z + rng.get_double(-0.02, 0.02));
    }
  return points;
}

std::set<Triangle> triangles_of(const Mesh& mesh)
{
  std::set<Triangle> result;
  for(auto f : mesh.faces()) {
    Triangle t;
    int k = 0;
    for(auto v : mesh.vertices_around_face(mesh.halfedge(f))) t[k++] = mesh.point(v);
    std::sort(t.begin(), t.end());
    result.insert(t);
  }
  return result;
}

struct Topology { std::size_t components = 0, border_cycles = 0; };

Topology topology(Mesh mesh)
{
  Topology t;
  auto fcc = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  t.components = PMP::connected_components(mesh, fcc);
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  t.border_cycles = cycles.size();
  return t;
}

// Tiles the points, merges the tiles and checks the union: valid, one component with one
// boundary loop (the outer one): no crack along the seams.
LOC::Tiled_surface_report check_seams(const std::vector<Point>& points, double tile_size, unsigned threads,
                                      std::vector<Mesh>& tiles, Mesh& merged)
{
  const LOC::Tiled_surface_report r =
    CGAL::lex_optimal_tiled_surface_reconstruction(points, tile_size, tiles, LOC::parameters::number_of_threads(threads));
  std::cout << "  " << r.columns << " x " << r.rows << " tiles of " << r.tile_width << " x " << r.tile_height << ", "
            << r.number_of_seam_points << " seam points (spacing " << r.seam_spacing << "), seams " << r.seam_seconds
            << " s, tiles " << r.tiles_seconds << " s on " << r.number_of_threads << " thread(s)" << std::endl;
  assert(tiles.size() == r.columns * r.rows && r.tiles.size() == tiles.size());
  // the faces of each edge, per tile
  std::map<std::pair<Point, Point>, std::map<std::size_t, int>> edge_faces;
  for(std::size_t t = 0; t < tiles.size(); ++t) {
    assert(tiles[t].number_of_faces() > 0 && tiles[t].is_valid());
    for(auto h : tiles[t].halfedges())
      if(!tiles[t].is_border(h))
        ++edge_faces[std::minmax(tiles[t].point(tiles[t].source(h)), tiles[t].point(tiles[t].target(h)))][t];
  }
  std::size_t seam_edges = 0;
  for(const auto& [edge, per_tile] : edge_faces) {
    if(per_tile.size() < 2) continue;
    ++seam_edges;
    assert(per_tile.size() == 2);
  }
  const LOC::Tile_merge_report m = LOC::merge_tile_meshes(tiles, merged);
  const Topology top = topology(merged);
  std::cout << "  merged: " << m.mesh_vertices << " vertices, " << m.mesh_faces << " faces, " << seam_edges
            << " seam edges, " << top.components << " component(s), " << top.border_cycles << " boundary loop(s), "
            << m.non_manifold_vertices << " non-manifold vertices, " << m.cancelled_faces << " faces cancelled, "
            << m.removed_closed_components << " closed pockets (" << m.removed_closed_faces << " faces) removed" << std::endl;
  assert(merged.is_valid());
  assert(seam_edges > 0);
  assert(top.components == 1 && top.border_cycles == 1);
  return r;
}

// The faces of a mesh in its order, each as the points of its corners from its half-edge.
std::vector<Triangle> faces_in_order(const Mesh& mesh)
{
  std::vector<Triangle> result;
  for(auto f : mesh.faces()) {
    Triangle t;
    int k = 0;
    for(auto v : mesh.vertices_around_face(mesh.halfedge(f))) t[k++] = mesh.point(v);
    result.push_back(t);
  }
  return result;
}

// The out-of-core reconstruction of `points` (given `copies` times, in another order each
// time) gives the tiles of the reconstruction in memory, face for face, and leaves no file.
void check_out_of_core(const std::vector<Point>& points, double tile_size, const std::vector<Mesh>& tiles,
                       const LOC::Tiled_surface_report& r, int copies)
{
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("test_tiled_surface_buckets_" + std::to_string(std::random_device()()));
  fs::create_directories(dir);
  std::size_t passes = 0;
  auto source = [&](const auto& f) {
    ++passes;
    for(int c = 0; c < copies; ++c)
      for(std::size_t i = 0; i < points.size(); ++i) f(points[c % 2 == 0 ? i : points.size() - 1 - i]);
  };
  std::vector<Mesh> streamed;
  std::vector<std::size_t> points_per_cell; // what the tile filter gets: the distinct points of each cell
  auto every_tile = [&](const std::vector<std::size_t>& p) {
    points_per_cell = p;
    return std::vector<bool>(p.size(), true);
  };
  const LOC::Tiled_surface_report s = CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(
    source, tile_size, dir.string(), streamed,
    LOC::parameters::number_of_threads(2u, LOC::parameters::tile_filter(every_tile)));
  assert(passes == 2);
  std::size_t in_cells = 0;
  for(std::size_t n : points_per_cell) in_cells += n;
  assert(points_per_cell.size() == tiles.size() && in_cells == r.number_of_input_points);
  assert(s.number_of_input_points == r.number_of_input_points && s.seam_spacing == r.seam_spacing);
  assert(s.number_of_seam_points == r.number_of_seam_points && streamed.size() == tiles.size());
  for(std::size_t t = 0; t < tiles.size(); ++t) {
    assert(s.tiles[t].number_of_points == r.tiles[t].number_of_points);
    assert(faces_in_order(streamed[t]) == faces_in_order(tiles[t]));
  }
  assert(fs::is_empty(dir)); // the bucket files are gone
  fs::remove(dir);
  std::cout << "  out of core (points given " << copies << " times): the same " << tiles.size()
            << " tiles, face for face, seams " << s.seam_seconds << " s" << std::endl;
}

void test_synthetic_terrain()
{
  std::cout << "synthetic terrain with buildings, 3 x 3 tiles" << std::endl;
  const std::vector<Point> points = terrain_with_buildings(7);
  std::vector<Mesh> tiles;
  Mesh merged;
  const LOC::Tiled_surface_report r = check_seams(points, 34, 2, tiles, merged);
  assert(r.columns == 3 && r.rows == 3);

  // Away from the seams (farther than 3 spacings from an inner border line) and from the frame,
  // most triangles of the tiles are those of the untiled surface of the same points.
  std::vector<Mesh> whole_tiles;
  const double side = 100, margin = std::max(r.seam_spacing, 0.01 * side);
  const double zf = -5;
  const std::vector<Point> frame{Point(-margin, -margin, zf), Point(side + margin, -margin, zf),
                                 Point(side + margin, side + margin, zf), Point(-margin, side + margin, zf),
                                 Point(-margin, -margin, zf)};
  Mesh whole;
  CGAL::lex_optimal_open_surface_reconstruction(
    points, std::vector<std::vector<Point>>{frame}, whole,
    LOC::parameters::remove_blocking_points(true, LOC::parameters::drop_boundary_triangles(true)));
  const std::set<Triangle> untiled = triangles_of(whole);
  auto away = [&](const Point& p) {
    const double d = 3 * r.seam_spacing;
    for(int axis = 0; axis < 2; ++axis) {
      const double c = axis == 0 ? p.x() : p.y(), width = axis == 0 ? r.tile_width : r.tile_height;
      if(c < d || c > side - d) return false; // near the frame
      for(std::size_t i = 1; i < 3; ++i) if(std::abs(c - double(i) * width) < d) return false;
    }
    return true;
  };
  std::size_t compared = 0, same = 0;
  for(const Triangle& t : triangles_of(merged))
    if(away(t[0]) && away(t[1]) && away(t[2])) {
      ++compared;
      same += untiled.count(t);
    }
  std::cout << "  away from the seams: " << same << " of " << compared << " triangles as in the untiled surface ("
            << whole.number_of_faces() << " faces)" << std::endl;
  assert(compared > 5000 && same >= 0.99 * double(compared));

  // the same tiles on one thread, and from the points in another order
  std::vector<Point> shuffled = points;
  CGAL::Random rng(3);
  for(std::size_t i = shuffled.size(); i > 1; --i) std::swap(shuffled[i - 1], shuffled[rng.get_int(0, int(i))]);
  std::vector<Mesh> again;
  CGAL::lex_optimal_tiled_surface_reconstruction(shuffled, 34, again);
  for(std::size_t t = 0; t < tiles.size(); ++t) assert(triangles_of(again[t]) == triangles_of(tiles[t]));
  std::cout << "  same tiles on one thread from shuffled points" << std::endl;
  // every point twice (the seam points included): the same tiles
  shuffled.insert(shuffled.end(), points.begin(), points.end());
  CGAL::lex_optimal_tiled_surface_reconstruction(shuffled, 34, again);
  for(std::size_t t = 0; t < tiles.size(); ++t) assert(triangles_of(again[t]) == triangles_of(tiles[t]));
  std::cout << "  same tiles from every point given twice" << std::endl;
  check_out_of_core(points, 34, tiles, r, 1);
  check_out_of_core(points, 34, tiles, r, 2);

  // Dealt out to 2 and to 3 processes by tile_filter (round robin): every tile reconstructed
  // by exactly one call, with the mesh of the call with every tile; the filter is called once,
  // before any tile, with the number of points of each tile.
  for(std::size_t count : {2u, 3u}) {
    std::vector<int> times_made(tiles.size(), 0);
    for(std::size_t index = 0; index < count; ++index) {
      std::size_t filter_calls = 0, visited = 0;
      auto filter = [&](const std::vector<std::size_t>& points_per_tile) {
        ++filter_calls;
        assert(visited == 0 && points_per_tile.size() == tiles.size());
        std::vector<bool> keep(points_per_tile.size());
        for(std::size_t t = 0; t < keep.size(); ++t) {
          assert(points_per_tile[t] == r.tiles[t].number_of_points);
          keep[t] = t % count == index;
        }
        return keep;
      };
      std::vector<Mesh> part;
      const LOC::Tiled_surface_report s = CGAL::lex_optimal_tiled_surface_reconstruction(
        points, 34, part,
        LOC::parameters::tile_filter(filter, LOC::parameters::tile_visitor([&](const LOC::Tile_report&, Mesh&) { ++visited; })));
      assert(filter_calls == 1 && part.size() == tiles.size());
      for(std::size_t t = 0; t < tiles.size(); ++t) {
        assert(s.tiles[t].reconstructed == (t % count == index));
        if(!s.tiles[t].reconstructed) {
          assert(part[t].is_empty() && s.tiles[t].mesh_faces == 0 && s.tiles[t].number_of_points == 0);
          continue;
        }
        assert(s.tiles[t].number_of_points == r.tiles[t].number_of_points);
        ++times_made[t];
        assert(triangles_of(part[t]) == triangles_of(tiles[t]));
      }
      std::size_t kept = 0;
      for(const LOC::Tile_report& t : s.tiles) kept += t.reconstructed ? 1 : 0;
      assert(kept > 0 && visited == kept); // the visitor sees the kept tiles only
    }
    assert(std::count(times_made.begin(), times_made.end(), 1) == long(tiles.size()));
    std::cout << "  dealt to " << count << " processes by the tile filter: every tile once, the same meshes" << std::endl;
  }
  // a filter that keeps no tile: no error, every tile empty
  std::vector<Mesh> none;
  const LOC::Tiled_surface_report n = CGAL::lex_optimal_tiled_surface_reconstruction(
    points, 34, none, LOC::parameters::tile_filter([](const std::vector<std::size_t>& p) { return std::vector<bool>(p.size(), false); }));
  assert(none.size() == tiles.size());
  for(std::size_t t = 0; t < tiles.size(); ++t) assert(!n.tiles[t].reconstructed && none[t].is_empty());
}

// Gabriel_seams_3 on seams made to fail: a vertical seam along x = 0 that climbs a wall
// (points a millimetre apart in xy, a metre apart in z) and zigzags in the noise, crossed by a
// horizontal one at its node. Afterwards no seam point lies in the closed diametral ball of a
// seam edge (brute force, exact), every original point is kept in order with its node, and the
// added points lie on the original edges (in the xy-plane, exactly between their ends).
void test_gabriel_seams()
{
  using Line = LOC::internal::Seam_polyline<Point>;
  Line vertical, horizontal;
  vertical.points = {Point(0, -10, 0), Point(0.01, 0, 0), Point(0.011, 0.001, 1), Point(-0.01, 0.13, 0.02),
                     Point(0, 0.26, 0.9), Point(0.02, 0.39, 0.1), Point(0, 0.52, 0.1), Point(0, 10, 0)};
  vertical.nodes = {0, 6, 7};
  horizontal.points = {Point(-10, 0.52, 0), Point(-0.13, 0.5, 0.5), Point(0, 0.52, 0.1), Point(0.13, 0.53, 0.12),
                       Point(10, 0.52, 0)};
  horizontal.nodes = {0, 2, 4};
  const Line vertical_before = vertical, horizontal_before = horizontal;
  auto in_some_ball = [](const std::vector<const Line*>& lines) {
    std::size_t count = 0;
    for(const Line* l : lines)
      for(std::size_t k = 1; k + 2 < l->points.size(); ++k)
        for(const Line* m : lines)
          for(const Point& t : m->points)
            if(t != l->points[k] && t != l->points[k + 1] &&
               Kernel::Side_of_bounded_sphere_3()(l->points[k], l->points[k + 1], t) != CGAL::ON_UNBOUNDED_SIDE)
              ++count;
    return count;
  };
  const std::size_t before = in_some_ball({&vertical, &horizontal});
  const std::size_t added =
    LOC::internal::Gabriel_seams_3<Point>({&vertical, &horizontal}, 0.13).split_until_gabriel();
  std::cout << "Gabriel seams: " << before << " seam points in diametral balls, " << added << " points added, "
            << in_some_ball({&vertical, &horizontal}) << " left" << std::endl;
  assert(before > 0 && added > 0 && in_some_ball({&vertical, &horizontal}) == 0);
  for(const auto& [after, original] : {std::make_pair(&vertical, &vertical_before), std::make_pair(&horizontal, &horizontal_before)}) {
    std::size_t k = 0;
    for(std::size_t i = 0; i < original->points.size(); ++i) {
      while(after->points[k] != original->points[i]) { // an added point, on the edge i - 1, i
        const Point &a = original->points[i - 1], &b = original->points[i], &m = after->points[k];
        assert(CGAL::collinear(a, b, m) || CGAL::squared_distance(Kernel::Segment_3(a, b), m) < 1e-20);
        auto between = [](double u, double v, double w) { return (std::min)(u, v) <= w && w <= (std::max)(u, v); };
        assert(between(a.x(), b.x(), m.x()) && between(a.y(), b.y(), m.y()));
        ++k;
      }
      ++k;
    }
    assert(k == after->points.size() && after->nodes.size() == original->nodes.size());
    for(std::size_t n = 0; n < original->nodes.size(); ++n)
      assert(after->points[after->nodes[n]] == original->points[original->nodes[n]]);
  }
  // A seam that runs along a wall, through the noise of its points (a dense scan whose wall lies
  // on a tile boundary): two steep edges 3 to 4 mm apart in x and 8 cm apart in z, each with
  // the other's top in its ball, projected at 0.995 along it. A split kept 1% away from the
  // ends left that top in the ball of the longer part, round after round (60 rounds were not
  // enough); at the projection it is out.
  Line wall;
  const double y = 22.360679774997898;
  wall.points = {Point(20, -10, 0.7), Point(20.5, y, 0.7), Point(21.0045176828879, y, 0.72215738882684644),
                 Point(21.0075454957503, y, 0.636134055224571), Point(21.0112336483336, y, 0.72249763549482582),
                 Point(21.0149, y, 0.6361), Point(21.5, y, 0.7), Point(22, y + 10, 0.7)};
  wall.nodes = {0, 7};
  const std::size_t wall_before = in_some_ball({&wall});
  const std::size_t wall_added = LOC::internal::Gabriel_seams_3<Point>({&wall}, 0.13).split_until_gabriel();
  std::cout << "seam along a wall: " << wall_before << " seam points in diametral balls, " << wall_added
            << " points added, " << in_some_ball({&wall}) << " left" << std::endl;
  assert(wall_before > 0 && wall_added > 0 && in_some_ball({&wall}) == 0);
}

// The untiled surface of `points` (side `side`, from 0) in the frame of the tiles: the open
// surface bounded by a rectangle just outside the cloud, its skirt dropped; whether it is one
// disk (connected, one boundary loop, Euler characteristic 1, no split vertex).
bool untiled_surface_is_disk(const std::vector<Point>& points, double side, double margin)
{
  const double zf = -5;
  const std::vector<Point> frame{Point(-margin, -margin, zf), Point(side + margin, -margin, zf),
                                 Point(side + margin, side + margin, zf), Point(-margin, side + margin, zf),
                                 Point(-margin, -margin, zf)};
  Mesh whole;
  const auto r = CGAL::lex_optimal_open_surface_reconstruction(
    points, std::vector<std::vector<Point>>{frame}, whole,
    LOC::parameters::remove_blocking_points(true, LOC::parameters::drop_boundary_triangles(true)));
  const Topology top = topology(whole);
  const long euler = long(whole.number_of_vertices()) - long(whole.number_of_edges()) + long(whole.number_of_faces());
  std::cout << "  untiled: " << top.components << " component(s), " << top.border_cycles << " boundary loop(s), Euler characteristic "
            << euler << ", " << r.non_manifold_vertices << " split vertices" << std::endl;
  return top.components == 1 && top.border_cycles == 1 && euler == 1 && r.non_manifold_vertices == 0;
}

// Dense scans with walls, at several densities and noise levels up to those of a 500 points per
// square metre survey: every seam edge is imposed (no tile stops), and the union of the tiles is
// one disk without split vertices whenever the untiled surface of the same points is.
void test_dense_seams()
{
  for(const double density : {250., 500.})
    for(const double noise : {0.005, 0.05, 0.15}) {
      const std::vector<Point> points = dense_block_with_walls<Point>(10, density, noise, unsigned(density + 1000 * noise));
      std::cout << "dense block with walls, " << points.size() << " points (" << density << " a square metre, noise "
                << noise << "), tiles of 3.5" << std::endl;
      std::vector<Mesh> tiles;
      const LOC::Tiled_surface_report r =
        CGAL::lex_optimal_tiled_surface_reconstruction(points, 3.5, tiles, LOC::parameters::number_of_threads(2));
      Mesh merged;
      const LOC::Tile_merge_report m = LOC::merge_tile_meshes(tiles, merged);
      const Topology top = topology(merged);
      const long euler = long(merged.number_of_vertices()) - long(merged.number_of_edges()) + long(merged.number_of_faces());
      std::cout << "  " << r.number_of_seam_points << " seam points; union: " << top.components << " component(s), "
                << top.border_cycles << " boundary loop(s), Euler characteristic " << euler << ", "
                << m.non_manifold_vertices << " split vertices" << std::endl;
      assert(merged.is_valid());
      const bool union_is_disk = top.components == 1 && top.border_cycles == 1 && euler == 1 && m.non_manifold_vertices == 0;
      if(!union_is_disk) assert(!untiled_surface_is_disk(points, 10, std::max(r.seam_spacing, 0.1)));
    }
}

// A flat cloud (all heights 0, a parking lot): the frame is below it, so the tiles are not
// coplanar with their cycles.
void test_flat_cloud()
{
  std::cout << "flat cloud, 2 x 3 tiles" << std::endl;
  CGAL::Random rng(5);
  std::vector<Point> points;
  for(int i = 0; i < 6000; ++i) points.emplace_back(rng.get_double(0, 40), rng.get_double(0, 60), 0.);
  std::vector<Mesh> tiles;
  Mesh merged;
  const LOC::Tiled_surface_report r = check_seams(points, 21, 2, tiles, merged);
  assert(r.columns == 2 && r.rows == 3);
  for(auto v : merged.vertices()) assert(merged.point(v).z() == 0); // no frame point left
  check_out_of_core(points, 21, tiles, r, 1);
}

void test_aerial_scan(const std::string& data)
{
  std::cout << "b9_training.ply (aerial LiDAR of buildings), 2 x 2 tiles" << std::endl;
  std::vector<Point> points;
  if(!CGAL::IO::read_points(data + "/points_3/b9_training.ply", std::back_inserter(points))) {
    std::cerr << "cannot read " << data << "/points_3/b9_training.ply" << std::endl;
    std::exit(1);
  }
  std::vector<Mesh> tiles;
  Mesh merged;
  const LOC::Tiled_surface_report r = check_seams(points, 60, 2, tiles, merged);
  check_out_of_core(points, 60, tiles, r, 1);
}

void test_bad_input()
{
  std::cout << "bad input" << std::endl;
  CGAL::Random rng(1);
  const std::vector<Point> points = height_field<Point>(rng, 3000, 0.01);
  std::vector<Mesh> tiles(1);
  using Code = LOC::Input_error_code;
  expect_error(Code::INVALID_PARAMETER, [&] { CGAL::lex_optimal_tiled_surface_reconstruction(points, 0., tiles); });
  expect_error(Code::INVALID_PARAMETER, [&] { CGAL::lex_optimal_tiled_surface_reconstruction(points, -2., tiles); });
  expect_error(Code::INVALID_PARAMETER,
               [&] { CGAL::lex_optimal_tiled_surface_reconstruction(points, std::numeric_limits<double>::quiet_NaN(), tiles); });
  expect_error(Code::INVALID_PARAMETER, [&] { CGAL::lex_optimal_tiled_surface_reconstruction(points, 10., tiles); });
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_tiled_surface_reconstruction(points, 5., tiles, LOC::parameters::seam_spacing(2.));
  });
  // a hole around the corner of the four tiles: the seams meet at a point of their own there,
  // and the tiles bridge the hole as the untiled surface does
  std::vector<Point> holed;
  for(const Point& p : points)
    if(std::abs(p.x() - 5) > 1 || std::abs(p.y() - 5) > 1) holed.push_back(p);
  {
    std::vector<Mesh> holed_tiles;
    Mesh holed_merged;
    check_seams(holed, 5., 1, holed_tiles, holed_merged);
  }
  // no point at all near the two border lines through a corner: nothing to run the seams through
  std::vector<Point> split_cloud;
  for(const Point& p : points)
    if(std::abs(p.x() - 5) > 1 && std::abs(p.y() - 5) > 1) split_cloud.push_back(p);
  expect_error(Code::INVALID_PARAMETER, [&] { CGAL::lex_optimal_tiled_surface_reconstruction(split_cloud, 5., tiles); });
  // a tile filter that does not return one value per tile
  auto one_more = [](const std::vector<std::size_t>& p) { return std::vector<bool>(p.size() + 1, true); };
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_tiled_surface_reconstruction(points, 5., tiles, LOC::parameters::tile_filter(one_more));
  });
  expect_error(Code::EMPTY_INPUT, [&] { CGAL::lex_optimal_tiled_surface_reconstruction(std::vector<Point>(), 5., tiles); });
  std::vector<Point> nan = points;
  nan[7] = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  expect_error(Code::NON_FINITE_COORDINATE, [&] { CGAL::lex_optimal_tiled_surface_reconstruction(nan, 5., tiles); });
  assert(tiles.size() == 1 && tiles[0].is_empty()); // unchanged

  // out of core: the same errors, and a bucket directory that does not exist; no file left
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("test_tiled_surface_bad_" + std::to_string(std::random_device()()));
  fs::create_directories(dir);
  auto from = [](const std::vector<Point>& v) { return [&v](const auto& f) { for(const Point& p : v) f(p); }; };
  const std::string d = dir.string();
  expect_error(Code::INVALID_PARAMETER, [&] { CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(from(points), 0., d, tiles); });
  expect_error(Code::INVALID_PARAMETER, [&] { CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(from(points), 10., d, tiles); });
  expect_error(Code::INVALID_PARAMETER, [&] { CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(from(split_cloud), 5., d, tiles); });
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(from(points), 5., d, tiles, LOC::parameters::tile_filter(one_more));
  });
  expect_error(Code::EMPTY_INPUT, [&] {
    const std::vector<Point> none;
    CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(from(none), 5., d, tiles);
  });
  expect_error(Code::NON_FINITE_COORDINATE, [&] { CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(from(nan), 5., d, tiles); });
  const std::vector<Point> three(points.begin(), points.begin() + 3);
  std::vector<Point> repeated;
  for(int k = 0; k < 50; ++k) repeated.insert(repeated.end(), three.begin(), three.end());
  for(double size : {0.01, 5.}) { // what the tile size would be does not matter: as in memory
    expect_error(Code::TOO_FEW_POINTS, [&] { CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(from(repeated), size, d, tiles); });
    expect_error(Code::TOO_FEW_POINTS, [&] { CGAL::lex_optimal_tiled_surface_reconstruction(repeated, size, tiles); });
  }
  // sources that give one point less, or one point elsewhere, in their second call
  for(int change = 0; change < 2; ++change) {
    int call = 0;
    auto changing = [&](const auto& f) {
      const bool second = ++call == 2;
      for(std::size_t i = 0; i < points.size(); ++i) {
        if(second && change == 0 && i == 0) continue;
        f(second && change == 1 && i == 0 ? Point(100, 100, 0) : points[i]);
      }
    };
    expect_error(Code::INVALID_PARAMETER, [&] { CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(changing, 5., d, tiles); });
  }
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(from(points), 5., (dir / "missing").string(), tiles);
  });
  assert(fs::is_empty(dir));
  fs::remove(dir);
  assert(tiles.size() == 1 && tiles[0].is_empty()); // unchanged
}

int main(int argc, char** argv)
{
  test_bad_input();
  test_synthetic_terrain();
  test_flat_cloud();
  test_gabriel_seams();
  test_dense_seams();
  test_aerial_scan(argc > 1 ? argv[1] : CGAL::data_file_path(""));
  std::cout << "done" << std::endl;
  return 0;
}
