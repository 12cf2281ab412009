// Open surfaces with an imposed boundary (thesis section 4.8.2):
// - a noisy height field with the footprint polygon outside gives one disk whose boundary
//   is exactly the polygon; dropping the skirt leaves the input points only;
// - the output does not depend on the order of the input points;
// - a Möbius strip bounded by its boundary curve: the Z2 optimum cannot be oriented (the
//   mesh is cut to orient it), the Q optimum is a different chain, orientable (Fig. 4.25);
// - a flat tile (all points coplanar) meshes with the footprint boundary;
// - a terrain on an integer lattice (exact ties of the order everywhere) gives the same
//   mesh whatever the order of its points and the number of threads;
// - a boundary through the cloud is refused, then repaired by removing the blocking points;
// - bad input gives the documented error and leaves the mesh untouched.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>

#include "test_support.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using DT = CGAL::Delaunay_triangulation_3<K>;
namespace LOC = CGAL::Lex_optimal_chains;
namespace PMP = CGAL::Polygon_mesh_processing;

// border edges of the mesh as point pairs (undirected)
std::set<std::pair<Point, Point>> border_edges(const Mesh& mesh)
{
  std::set<std::pair<Point, Point>> edges;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h)) {
      Point a = mesh.point(mesh.source(h)), b = mesh.point(mesh.target(h));
      if(b < a) std::swap(a, b);
      edges.emplace(a, b);
    }
  return edges;
}

// edges of a polyline as point pairs (undirected)
std::set<std::pair<Point, Point>> edges_of_polyline(const std::vector<Point>& polyline)
{
  std::set<std::pair<Point, Point>> edges;
  for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
    edges.emplace((std::min)(polyline[i], polyline[i + 1]), (std::max)(polyline[i], polyline[i + 1]));
  return edges;
}

std::size_t components(Mesh mesh)
{
  auto fcc = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  return PMP::connected_components(mesh, fcc);
}

long euler_characteristic(const Mesh& m)
{
  return long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
}

void test_height_field(CGAL::Random& rng)
{
  const std::vector<Point> points = height_field<Point>(rng, 4000, 0.02);
  const std::vector<Point> polygon = LOC::footprint_boundary(points);
  const std::set<std::pair<Point, Point>> polygon_edges = edges_of_polyline(polygon);
  const std::vector<std::vector<Point>> boundary{polygon};
  // scaled by a power of two, exactly, the footprint is the same polygon scaled, also where
  // squared distances in input units would overflow (2^600) or underflow (2^-900)
  for(const int e : {600, -900}) {
    std::vector<Point> scaled;
    for(const Point& p : points) scaled.emplace_back(std::ldexp(p.x(), e), std::ldexp(p.y(), e), std::ldexp(p.z(), e));
    const std::vector<Point> scaled_polygon = LOC::footprint_boundary(scaled);
    assert(scaled_polygon.size() == polygon.size());
    for(std::size_t i = 0; i < polygon.size(); ++i)
      assert(scaled_polygon[i] == Point(std::ldexp(polygon[i].x(), e), std::ldexp(polygon[i].y(), e),
                                        std::ldexp(polygon[i].z(), e)));
  }
  {
    const std::vector<Point> huge{Point(-1.7e308, 0, 0), Point(1.7e308, 1, 0), Point(0, 1e308, 1)};
    expect_error(LOC::Input_error_code::TOO_LARGE, [&] { LOC::footprint_boundary(huge); });
  }
  for(const auto field : {LOC::Coefficient_field::Q, LOC::Coefficient_field::Z2}) {
    Mesh mesh;
    const auto report = CGAL::lex_optimal_open_surface_reconstruction(points, boundary, mesh, LOC::parameters::coefficient_field(field));
    std::cout << "height field: " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces, "
              << report.number_of_swept_vertices << " swept vertices, " << report.number_of_representative_triangles
              << " representative triangles\n";
    assert(CGAL::is_valid_polygon_mesh(mesh));
    assert(components(mesh) == 1);
    // the boundary is the given polygon (an edge of four triangles of the optimum would be
    // split into border edges: there is none here)
    assert(report.non_manifold_edges == 0);
    assert(border_edges(mesh) == polygon_edges);
    assert(euler_characteristic(mesh) == 1);     // a disk
    assert(report.non_manifold_vertices == 0 && report.orientation_cuts == 0);
    assert(report.number_of_boundary_vertices == polygon.size() - 1);
    assert(mesh.number_of_vertices() <= points.size() + polygon.size() - 1);
    if(field == LOC::Coefficient_field::Q) {
      // oriented upward: the polygon turns counterclockwise seen from above
      double up = 0;
      for(auto f : mesh.faces()) {
        auto h = mesh.halfedge(f);
        const Point& a = mesh.point(mesh.source(h));
        const Point& b = mesh.point(mesh.target(h));
        const Point& c = mesh.point(mesh.target(mesh.next(h)));
        up += CGAL::cross_product(b - a, c - a).z();
      }
      assert(up > 0);
    }

    // without the skirt: input points only, the terrain as one piece
    Mesh terrain;
    const auto dropped = CGAL::lex_optimal_open_surface_reconstruction(
      points, boundary, terrain, LOC::parameters::drop_boundary_triangles(true, LOC::parameters::coefficient_field(field)));
    assert(dropped.dropped_triangles > 0);
    assert(terrain.number_of_faces() + dropped.dropped_triangles == mesh.number_of_faces());
    std::set<Point> inputs(points.begin(), points.end());
    for(auto v : terrain.vertices()) assert(inputs.count(terrain.point(v)));
    assert(CGAL::is_valid_polygon_mesh(terrain));
    assert(components(terrain) == 1);
    std::cout << "  terrain without the skirt: " << terrain.number_of_faces() << " faces, Euler characteristic "
              << euler_characteristic(terrain) << "\n";
  }

  // identical output for shuffled input and for two threads (with TBB)
  std::vector<Point> shuffled = points;
  CGAL::cpp98::random_shuffle(shuffled.begin(), shuffled.end(), rng);
  std::string off[3];
  for(int k = 0; k < 3; ++k) {
    Mesh mesh;
    CGAL::lex_optimal_open_surface_reconstruction(k == 0 ? points : shuffled, boundary, mesh,
                                                  LOC::parameters::number_of_threads(k == 2 ? 2u : 1u));
    std::ostringstream s;
    s.precision(17);
    s << mesh;
    off[k] = s.str();
  }
  assert(off[0] == off[1] && off[0] == off[2]);
}

// Points on a Möbius strip and its boundary curve (which goes twice around).
void test_moebius(CGAL::Random& rng)
{
  const double w = 0.35;
  auto strip = [&](double u, double v) {
    return Point((1 + v * std::cos(u / 2)) * std::cos(u), (1 + v * std::cos(u / 2)) * std::sin(u), v * std::sin(u / 2));
  };
  std::vector<Point> points;
  const int around = 90, across = 7;
  for(int i = 0; i < around; ++i)
    for(int j = 1; j < across; ++j) {
      const double u = 2 * CGAL_PI * (i + rng.get_double(-0.1, 0.1)) / around;
      const double v = -w + 2 * w * (j + rng.get_double(-0.1, 0.1)) / across;
      points.push_back(strip(u, v));
    }
  // the boundary v = w for u in [0, 4 pi), densely sampled
  std::vector<Point> curve;
  const int samples = 4 * around;
  for(int i = 0; i < samples; ++i) curve.push_back(strip(4 * CGAL_PI * i / samples, w));
  curve.push_back(curve.front());
  const std::vector<std::vector<Point>> boundary{curve};

  Mesh z2, q;
  const auto rz = CGAL::lex_optimal_open_surface_reconstruction(
    points, boundary, z2, LOC::parameters::remove_blocking_points(true, LOC::parameters::coefficient_field(LOC::Coefficient_field::Z2)));
  const auto rq = CGAL::lex_optimal_open_surface_reconstruction(
    points, boundary, q, LOC::parameters::remove_blocking_points(true, LOC::parameters::coefficient_field(LOC::Coefficient_field::Q)));
  std::cout << "Moebius: Z2 " << rz.number_of_facets << " triangles (" << rz.orientation_cuts
            << " edges cut to orient it), Q " << rq.number_of_facets << " triangles ("
            << rq.number_of_multiple_facets << " with coefficient 2, " << rq.orientation_cuts << " edges cut); "
            << rz.number_of_removed_points << " points removed\n";
  // the Z2 optimum is the strip: not orientable, so orienting it cuts it
  assert(rz.orientation_cuts > 0);
  // the Q optimum is another chain, oriented
  assert(rq.number_of_facets != rz.number_of_facets || rq.number_of_multiple_facets > 0);
  assert(rq.orientation_cuts == 0);
  assert(CGAL::is_valid_polygon_mesh(q) && CGAL::is_valid_polygon_mesh(z2));
}

void test_flat_tile(CGAL::Random& rng)
{
  std::vector<Point> points;
  for(int i = 0; i < 500; ++i) points.emplace_back(rng.get_double(0, 10), rng.get_double(0, 10), 2.0);
  const std::vector<std::vector<Point>> boundary{LOC::footprint_boundary(points)};
  Mesh mesh;
  const auto report = CGAL::lex_optimal_open_surface_reconstruction(points, boundary, mesh, LOC::parameters::drop_boundary_triangles(true));
  // the flat points: the Delaunay triangulation of the plane, one disk
  assert(components(mesh) == 1 && euler_characteristic(mesh) == 1 && CGAL::is_valid_polygon_mesh(mesh));
  for(auto v : mesh.vertices()) assert(mesh.point(v).z() == 2.0);
  std::cout << "flat tile: " << mesh.number_of_faces() << " faces (" << report.dropped_triangles << " dropped)\n";
}

// A terrain sampled on an integer lattice, with integer heights: the triangles of its
// Delaunay triangulation tie by the thousands (equal R_B and R_C), so the result rests on the
// documented tie-break. It must not depend on the order of the points nor on the number of
// threads, over Z2 and over Q, and it must be a valid mesh bounded by the footprint polygon.
void test_lattice_terrain(CGAL::Random& rng)
{
  std::vector<Point> points;
  for(int i = 0; i < 24; ++i)
    for(int j = 0; j < 24; ++j) points.emplace_back(i, j, double(rng.get_int(0, 3)));
  const std::vector<Point> polygon = LOC::footprint_boundary(points);
  const std::set<std::pair<Point, Point>> polygon_edges = edges_of_polyline(polygon);
  const std::vector<std::vector<Point>> boundary{polygon};
  for(const auto field : {LOC::Coefficient_field::Z2, LOC::Coefficient_field::Q}) {
    std::string off[3];
    for(int k = 0; k < 3; ++k) {
      std::vector<Point> input = points;
      if(k > 0) CGAL::cpp98::random_shuffle(input.begin(), input.end(), rng);
      Mesh mesh;
      const auto report = CGAL::lex_optimal_open_surface_reconstruction(
        input, boundary, mesh, LOC::parameters::number_of_threads(k == 2 ? 2u : 1u, LOC::parameters::coefficient_field(field)));
      assert(CGAL::is_valid_polygon_mesh(mesh) && components(mesh) == 1);
      if(report.non_manifold_edges == 0 && report.non_manifold_vertices == 0) assert(border_edges(mesh) == polygon_edges);
      if(k == 0)
        std::cout << "lattice terrain (" << (field == LOC::Coefficient_field::Q ? "Q" : "Z2") << "): "
                  << mesh.number_of_faces() << " faces, " << report.number_of_triangles_in_close_runs
                  << " triangles in runs the keys cannot order, " << report.number_of_exactly_ordered_triangles
                  << " ordered exactly\n";
      std::ostringstream s;
      s.precision(17);
      s << mesh;
      off[k] = s.str();
    }
    assert(off[0] == off[1] && off[0] == off[2]);
  }
}

void test_boundary_through_the_cloud(CGAL::Random& rng)
{
  const std::vector<Point> points = height_field<Point>(rng, 3000, 0.02);
  // a square well inside the footprint, on the surface, with short edges: points of the
  // cloud lie in the diametral balls of some of them (a tile border)
  const double cx[4] = {2, 8, 8, 2}, cy[4] = {2, 2, 8, 8};
  std::vector<Point> square;
  for(int s = 0; s < 4; ++s)
    for(int k = 0; k < 24; ++k) {
      const double x = cx[s] + (cx[(s + 1) % 4] - cx[s]) * k / 24.0, y = cy[s] + (cy[(s + 1) % 4] - cy[s]) * k / 24.0;
      square.emplace_back(x, y, std::sin(0.7 * x) * std::cos(0.5 * y) + 0.3 * x / 10);
    }
  square.push_back(square.front());
  const std::vector<std::vector<Point>> boundary{square};
  Mesh mesh;
  expect_error(LOC::Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION,
               [&] { CGAL::lex_optimal_open_surface_reconstruction(points, boundary, mesh); });
  assert(mesh.is_empty());
  const auto report = CGAL::lex_optimal_open_surface_reconstruction(points, boundary, mesh, LOC::parameters::remove_blocking_points(true));
  std::cout << "boundary through the cloud: " << report.number_of_removed_points << " points removed, "
            << mesh.number_of_faces() << " faces\n";
  assert(report.number_of_removed_points > 0 && report.number_of_removed_points < points.size() / 10);
  std::set<std::pair<Point, Point>> expected;
  for(std::size_t i = 0; i + 1 < square.size(); ++i)
    expected.emplace((std::min)(square[i], square[i + 1]), (std::max)(square[i], square[i + 1]));
  assert(border_edges(mesh) == expected);
  assert(CGAL::is_valid_polygon_mesh(mesh));
}

void test_bad_input(CGAL::Random& rng)
{
  const std::vector<Point> points = height_field<Point>(rng, 500, 0.02);
  const std::vector<Point> polygon = LOC::footprint_boundary(points);
  Mesh mesh;
  auto run = [&](const std::vector<Point>& pts, const std::vector<std::vector<Point>>& b) {
    CGAL::lex_optimal_open_surface_reconstruction(pts, b, mesh);
  };
  std::vector<Point> open(polygon.begin(), polygon.end() - 1);
  expect_error(LOC::Input_error_code::OPEN_POLYLINE, [&] { run(points, {open}); });
  const std::vector<Point> eight{Point(-1, -1, 0), Point(11, 11, 0), Point(11, -1, 0), Point(-1, 11, 0), Point(-1, -1, 0)};
  expect_error(LOC::Input_error_code::SELF_INTERSECTING_BOUNDARY, [&] { run(points, {eight}); });
  std::vector<Point> twice = polygon;
  twice.insert(twice.begin() + 5, polygon[2]);
  expect_error(LOC::Input_error_code::SELF_INTERSECTING_BOUNDARY, [&] { run(points, {twice}); });
  const std::vector<Point> back{Point(-1, -1, 0), Point(11, -1, 0), Point(5, -1, 0), Point(5, 11, 0), Point(-1, -1, 0)};
  expect_error(LOC::Input_error_code::SELF_INTERSECTING_BOUNDARY, [&] { run(points, {back}); });
  std::vector<Point> far;
  for(const Point& p : polygon) far.emplace_back(p.x() + 1000, p.y(), p.z());
  expect_error(LOC::Input_error_code::BOUNDARY_FAR_FROM_POINTS, [&] { run(points, {far}); });
  expect_error(LOC::Input_error_code::EMPTY_INPUT, [&] { run({}, {polygon}); });
  expect_error(LOC::Input_error_code::BOUNDARY_NOT_A_CYCLE, [&] { run(points, {}); });
  std::vector<Point> nan_points = points;
  nan_points[3] = Point(std::nan(""), 0, 0);
  expect_error(LOC::Input_error_code::NON_FINITE_COORDINATE, [&] { run(nan_points, {polygon}); });
  expect_error(LOC::Input_error_code::EMPTY_INPUT, [&] { LOC::footprint_boundary(std::vector<Point>()); });
  // a callback that says no at the start, half-way or at the very end (progress 1) cancels,
  // before the mesh is touched
  for(double stop : {0.0, 0.5})
    expect_cancelled([&] {
      CGAL::lex_optimal_open_surface_reconstruction(points, std::vector<std::vector<Point>>{polygon}, mesh,
        LOC::parameters::callback(std::function<bool(double)>([stop](double x) { return x < stop; })));
    });
  expect_cancelled([&] {
    CGAL::lex_optimal_open_surface_reconstruction(points, std::vector<std::vector<Point>>{polygon}, mesh,
      LOC::parameters::callback(std::function<bool(double)>([](double x) { return x < 1; })));
  });
  assert(mesh.is_empty()); // nothing was added on error
}

// Steep tiles and a tile with a low outlier, bounded by footprint_boundary() without their
// skirt: the input points are vertices of the terrain, but for a few near the border whose
// every triangle touches the polygon (a polygon below the lowest point left out half of the
// 45-degree tile and all of the tile with the outlier).
void test_footprint_of_steep_and_noisy_tiles(CGAL::Random& rng)
{
  auto check_tile = [](const std::vector<Point>& points, std::size_t expected_vertices, std::size_t percent,
                       const char* what) {
    Mesh mesh;
    const auto report = CGAL::lex_optimal_open_surface_reconstruction(
      points, std::vector<std::vector<Point>>{LOC::footprint_boundary(points)}, mesh,
      LOC::parameters::drop_boundary_triangles(true));
    std::cout << what << ": " << mesh.number_of_vertices() << " of " << points.size() << " points, "
              << mesh.number_of_faces() << " faces, " << report.dropped_triangles << " skirt triangles dropped\n";
    assert(CGAL::is_valid_polygon_mesh(mesh));
    assert(mesh.number_of_vertices() <= expected_vertices && mesh.number_of_vertices() >= expected_vertices * percent / 100);
    assert(components(mesh) == 1);
  };
  for(const double slope : {1.0, 2.0}) {
    std::vector<Point> points;
    for(int i = 0; i < 3000; ++i) {
      const double x = rng.get_double(0, 100), y = rng.get_double(0, 100);
      points.emplace_back(x, y, slope * x + 0.5 * std::sin(y / 7) + rng.get_double(-0.05, 0.05));
    }
    // the polygon is a little below the ground on the high side of a steep tile
    check_tile(points, points.size(), slope == 1 ? 99 : 90, slope == 1 ? "tile sloping at 45 degrees" : "tile sloping at 63 degrees");
  }
  std::vector<Point> points = height_field<Point>(rng, 3000, 0.02);
  points.emplace_back(5, 5, -100); // far below the ground, inside the footprint
  check_tile(points, points.size() - 1, 99, "tile with a low outlier");
}

// Points that do not span the footprint polygon as a surface: every triangle is skirt.
void test_no_terrain(CGAL::Random& rng)
{
  std::vector<Point> wall;
  for(int i = 0; i < 500; ++i) wall.emplace_back(3, rng.get_double(0, 10), rng.get_double(0, 10));
  const std::vector<Point> three{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0.5)};
  for(const std::vector<Point>* points : std::vector<const std::vector<Point>*>{&wall, &three}) {
    Mesh mesh;
    expect_error(LOC::Input_error_code::EMPTY_RESULT, [&] {
      CGAL::lex_optimal_open_surface_reconstruction(*points, std::vector<std::vector<Point>>{LOC::footprint_boundary(*points)},
                                                    mesh, LOC::parameters::drop_boundary_triangles(true));
    });
    assert(mesh.number_of_faces() == 0);
  }
}

// A duplicate given as (0, y, z) and (-0, y, z): the output does not depend on which comes first.
void test_signed_zero_duplicates(CGAL::Random& rng)
{
  std::vector<Point> points = height_field<Point>(rng, 300, 0.02);
  points.emplace_back(0.0, 5, 0.2);
  points.emplace_back(-0.0, 5, 0.2);
  const std::vector<std::vector<Point>> boundary{LOC::footprint_boundary(points)};
  std::string first;
  for(int order = 0; order < 2; ++order) {
    if(order == 1) std::swap(points[points.size() - 1], points[points.size() - 2]);
    Mesh mesh;
    CGAL::lex_optimal_open_surface_reconstruction(points, boundary, mesh);
    std::ostringstream out;
    out.precision(17);
    for(auto v : mesh.vertices()) {
      const Point& p = mesh.point(v);
      out << std::signbit(p.x()) << std::signbit(p.y()) << std::signbit(p.z()) << ' ' << p << '\n';
    }
    if(order == 0) first = out.str();
    else assert(out.str() == first);
  }
}

int main()
{
  CGAL::Random rng(5);
  test_height_field(rng);
  test_moebius(rng);
  test_flat_tile(rng);
  test_lattice_terrain(rng);
  test_boundary_through_the_cloud(rng);
  test_bad_input(rng);
  test_footprint_of_steep_and_noisy_tiles(rng);
  test_no_terrain(rng);
  test_signed_zero_duplicates(rng);
  std::cout << "test_open_surface: OK\n";
  return 0;
}
