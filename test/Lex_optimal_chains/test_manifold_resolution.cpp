// The resolution of the non-manifold vertices of optimal chains (user manual, "Manifold
// output"), checked against oracles written elsewhere:
// - the detection of non-manifold vertices in a soup (internal/Umbrellas.h) and in the
//   closed surface builder agree with CGAL's PMP::orient_polygon_soup(), which duplicates
//   exactly the non-manifold points of a soup, on the boundaries of random unions of cells;
// - closed surfaces of noisy spheres and of CGAL's sphere_20k_normal.xyz: without
//   keep_non_manifold, a closed, valid, outward oriented 2-manifold (PMP finds no
//   non-manifold vertex, no point is used twice) that still encloses the interior point;
//   the chain changed by few facets, all near the non-manifold vertices of the optimum; the
//   same mesh for shuffled input and two threads;
// - open surfaces of a noisy terrain with two buildings and of CGAL's b9_training.ply: one
//   disk (one component, Euler characteristic 1, one boundary loop, the imposed polygon when
//   the skirt is kept), over Q and Z2, where the optimum has non-manifold edges;
// - points on integer lattices (exact ties of the order): 2-manifolds.
//   test_manifold_resolution [CGAL data directory]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Random.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_closed_surface.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_mesh_3.h>
#include <CGAL/Lex_optimal_chains/internal/Pinched_umbrella_trim.h>
#include <CGAL/Lex_optimal_chains/internal/Umbrellas.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using DT = CGAL::Delaunay_triangulation_3<K>;
using Triangle = std::array<Point, 3>; // sorted
namespace LOC = CGAL::Lex_optimal_chains;
namespace PMP = CGAL::Polygon_mesh_processing;

CGAL::Random rng(7);

Triangle sorted_triangle(const DT::Facet& f)
{
  Triangle t;
  for(int k = 1; k < 4; ++k) t[k - 1] = f.first->vertex((f.second + k) & 3)->point();
  std::sort(t.begin(), t.end());
  return t;
}

// The points that PMP::orient_polygon_soup() duplicates in the soup of `triangles`: the
// non-manifold points of the soup.
std::set<Point> non_manifold_points_by_pmp(const std::vector<Triangle>& triangles)
{
  std::map<Point, std::size_t> index;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  for(const Triangle& t : triangles) {
    std::vector<std::size_t> polygon;
    for(const Point& p : t) {
      const auto it = index.emplace(p, points.size());
      if(it.second) points.push_back(p);
      polygon.push_back(it.first->second);
    }
    polygons.push_back(polygon);
  }
  const std::size_t before = points.size();
  PMP::orient_polygon_soup(points, polygons);
  return std::set<Point>(points.begin() + before, points.end());
}

std::size_t components(Mesh mesh)
{
  auto fcc = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  return PMP::connected_components(mesh, fcc);
}

std::size_t border_loops(const Mesh& mesh)
{
  std::set<Mesh::Halfedge_index> seen;
  std::size_t loops = 0;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h) && !seen.count(h)) {
      ++loops;
      for(auto g = h; !seen.count(g); g = mesh.next(g)) seen.insert(g);
    }
  return loops;
}

long euler_characteristic(const Mesh& m)
{
  return long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
}

// A 2-manifold as a mesh can be: valid, no non-manifold vertex found by PMP, and no point on
// two vertices (a split vertex would have two).
void check_manifold_mesh(const Mesh& m)
{
  assert(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m));
  Mesh copy = m;
  assert(PMP::duplicate_non_manifold_vertices(copy) == 0);
  std::set<Point> points;
  for(auto v : m.vertices()) points.insert(m.point(v));
  assert(points.size() == m.number_of_vertices());
}

std::string as_off(const Mesh& m)
{
  std::ostringstream out;
  out.precision(17);
  out << m;
  return out.str();
}

// ---- detection: random unions of Delaunay cells, whose boundaries are orientable ----------------
void test_detection_on_unions_of_cells()
{
  std::vector<Point> points;
  for(int i = 0; i < 80; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  const DT dt(points.begin(), points.end());
  std::size_t soups_with_non_manifold_points = 0;
  for(int trial = 0; trial < 300; ++trial) {
    const double p = 0.2 + 0.6 * rng.get_double();
    std::map<DT::Cell_handle, bool> inside;
    for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) inside[c] = !dt.is_infinite(c) && rng.get_double() < p;
    std::vector<Triangle> triangles;
    std::vector<std::array<std::uint32_t, 3>> numbered;
    std::map<Point, std::uint32_t> number;
    std::vector<Point> by_number;
    for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
      for(int i = 0; i < 4; ++i)
        if(inside[c] && !inside[c->neighbor(i)]) {
          triangles.push_back(sorted_triangle(DT::Facet(c, i)));
          std::array<std::uint32_t, 3> t;
          for(int k = 0; k < 3; ++k) {
            const auto it = number.emplace(triangles.back()[k], std::uint32_t(by_number.size()));
            if(it.second) by_number.push_back(triangles.back()[k]);
            t[k] = it.first->second;
          }
          numbered.push_back(t);
        }
    const std::set<Point> expected = non_manifold_points_by_pmp(triangles);
    const std::vector<std::uint32_t> found = LOC::internal::vertices_with_several_umbrellas(
      by_number.size(), std::uint32_t(numbered.size()), [&](std::uint32_t c) { return numbered[c / 3][c % 3]; });
    std::set<Point> found_points;
    for(const std::uint32_t v : found) found_points.insert(by_number[v]);
    assert(found_points == expected);
    soups_with_non_manifold_points += !expected.empty();
  }
  std::cout << "detection: " << soups_with_non_manifold_points << " of 300 unions of cells have non-manifold points, "
            << "found as PMP finds them\n";
  assert(soups_with_non_manifold_points > 100);
}

// ---- the patching of a closed surface after a change of sides ------------------------------------
// The surface of a random union of cells, patched by replace_facets() after random cells
// changed sides (the resolution's path: only the changed edges are paired anew), must be the
// surface built afresh from the new union, with the facets in the same order: the same
// statistics (non-manifold edges and vertices included) and the same mesh.
void test_replaced_facets_on_unions_of_cells()
{
  using Surface = LOC::internal::Closed_surface_mesh_3<DT>;
  std::vector<Point> points;
  for(int i = 0; i < 80; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  const DT dt(points.begin(), points.end());
  const LOC::internal::Handle_index_map<DT::Cell> cells(dt.tds().cells().begin(), dt.tds().cells().end());
  const LOC::internal::Handle_index_map<DT::Vertex> vertices(dt.tds().vertices().begin(), dt.tds().vertices().end());
  auto boundary = [&](const std::vector<bool>& inside) { // keys named from the inside cells
    std::vector<std::uint32_t> keys;
    for(std::uint32_t p = 0; p < cells.size(); ++p)
      for(int i = 0; i < 4; ++i)
        if(inside[p] && !inside[cells.index(&*cells.element(p)->neighbor(i))]) keys.push_back(Surface::facet_key(p, i));
    return keys;
  };
  auto mesh_of = [&](Surface& surface, Mesh& mesh) {
    surface.complete();
    surface.build(mesh, get(CGAL::vertex_point, mesh));
    return surface.statistics();
  };
  std::size_t with_non_manifold_edges = 0;
  for(int trial = 0; trial < 200; ++trial) {
    std::vector<bool> before(cells.size(), false), after;
    for(std::uint32_t p = 0; p < cells.size(); ++p) before[p] = !cells.element(p)->has_vertex(dt.infinite_vertex()) && rng.get_double() < 0.5;
    after = before;
    for(std::uint32_t p = 0; p < cells.size(); ++p)
      if(!cells.element(p)->has_vertex(dt.infinite_vertex()) && rng.get_double() < 0.05) after[p] = !after[p];
    const std::vector<std::uint32_t> old_keys = boundary(before), new_keys = boundary(after);
    if(old_keys.empty() || new_keys.empty()) continue;
    // a facet is the same if its inside cell is: the keys name the inside cells
    const std::set<std::uint32_t> old_set(old_keys.begin(), old_keys.end()), new_set(new_keys.begin(), new_keys.end());
    std::vector<bool> removed(old_keys.size());
    std::vector<std::uint32_t> added, expected_keys;
    for(std::size_t r = 0; r < old_keys.size(); ++r)
      if(!(removed[r] = new_set.count(old_keys[r]) == 0)) expected_keys.push_back(old_keys[r]);
    for(const std::uint32_t k : new_keys)
      if(!old_set.count(k)) added.push_back(k), expected_keys.push_back(k);
    Surface patched(std::vector<std::uint32_t>(old_keys), cells, vertices, before);
    patched.replace_facets(removed, added, cells, vertices, after);
    Surface fresh(std::move(expected_keys), cells, vertices, after);
    Mesh m1, m2;
    const LOC::internal::Closed_surface_statistics s1 = mesh_of(patched, m1), s2 = mesh_of(fresh, m2);
    assert(s1.vertices == s2.vertices && s1.faces == s2.faces && s1.components == s2.components &&
           s1.non_manifold_edges == s2.non_manifold_edges && s1.non_manifold_vertices == s2.non_manifold_vertices &&
           s1.genus == s2.genus);
    for(const auto v : m1.vertices()) assert(m1.point(v) == m2.point(v));
    for(const auto h : m1.halfedges()) assert(m1.target(h) == m2.target(h) && m1.next(h) == m2.next(h));
    with_non_manifold_edges += s2.non_manifold_edges > 0;
  }
  std::cout << "patching: 200 changes of random unions of cells give the surface built afresh (" << with_non_manifold_edges
            << " with non-manifold edges)\n";
  assert(with_non_manifold_edges > 50);
}

// ---- closed surfaces ------------------------------------------------------------------------------
std::vector<Point> noisy_sphere(std::size_t n, double noise)
{
  std::vector<Point> pts;
  while(pts.size() < n) {
    const double x = rng.get_double(-1, 1), y = rng.get_double(-1, 1), z = rng.get_double(-1, 1);
    const double l = std::sqrt(x * x + y * y + z * z);
    if(l < 1e-3 || l > 1) continue;
    const double r = 1 + rng.get_double(-noise, noise);
    pts.emplace_back(x / l * r, y / l * r, z / l * r);
  }
  return pts;
}

// The optimal cycle and the resolved one on the same triangulation: the resolved one is a
// 2-manifold cycle (PMP: no duplicated point) whose changes are few and within `rings` edges
// of a non-manifold point of the optimum.
void check_closed_resolution(const std::vector<Point>& pts, const std::string& name)
{
  const DT dt(pts.begin(), pts.end());
  std::vector<DT::Facet> raw, resolved;
  const auto r0 = CGAL::lex_optimal_closed_surface(dt, std::back_inserter(raw), LOC::parameters::keep_non_manifold(true));
  const auto r1 = CGAL::lex_optimal_closed_surface(dt, std::back_inserter(resolved));
  std::vector<Triangle> raw_triangles, resolved_triangles;
  for(const auto& f : raw) raw_triangles.push_back(sorted_triangle(f));
  for(const auto& f : resolved) resolved_triangles.push_back(sorted_triangle(f));
  const std::set<Point> raw_bad = non_manifold_points_by_pmp(raw_triangles);
  assert(!raw_bad.empty()); // the test is about something
  assert(non_manifold_points_by_pmp(resolved_triangles).empty());
  assert(r0.resolved_non_manifold_vertices == 0 && r1.resolved_non_manifold_vertices > 0);

  // the symmetric difference: as counted, small, and near the non-manifold points
  std::set<Triangle> a(raw_triangles.begin(), raw_triangles.end()), b(resolved_triangles.begin(), resolved_triangles.end());
  assert(a.size() == raw_triangles.size() && b.size() == resolved_triangles.size());
  std::vector<Triangle> difference;
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(difference));
  assert(difference.size() == r1.resolution_changed_facets);
  std::map<Point, int> ring; // edge distance to a non-manifold point of the optimum
  std::vector<DT::Vertex_handle> front;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    if(raw_bad.count(v->point())) { ring[v->point()] = 0; front.push_back(v); }
  for(int d = 1; d <= 3; ++d) {
    std::vector<DT::Vertex_handle> next;
    for(const auto& v : front) {
      std::vector<DT::Vertex_handle> around;
      dt.finite_adjacent_vertices(v, std::back_inserter(around));
      for(const auto& w : around)
        if(ring.emplace(w->point(), d).second) next.push_back(w);
    }
    front.swap(next);
  }
  int farthest = 0;
  for(const Triangle& t : difference) {
    int nearest = 1000;
    for(const Point& p : t) if(ring.count(p)) nearest = (std::min)(nearest, ring[p]);
    farthest = (std::max)(farthest, nearest);
  }
  std::cout << name << ": " << raw_bad.size() << " non-manifold points in the optimum, " << r1.resolved_non_manifold_vertices
            << " resolved; " << difference.size() << " facets changed of " << raw.size()
            << ", all within " << farthest << " edges of a non-manifold point\n";
  assert(farthest <= 2);
  assert(difference.size() <= 12 * raw_bad.size() && difference.size() * 20 < raw.size());
}

void test_closed_surfaces(const std::string& data)
{
  const std::vector<Point> sphere = noisy_sphere(30000, 0.02);
  check_closed_resolution(sphere, "noisy sphere");
  Mesh m, raw;
  const auto r = CGAL::lex_optimal_closed_surface_reconstruction(sphere, m);
  const auto r0 = CGAL::lex_optimal_closed_surface_reconstruction(sphere, raw, LOC::parameters::keep_non_manifold(true));
  assert(r0.non_manifold_vertices > 0 && r0.non_manifold_edges > 0); // split, as documented
  check_manifold_mesh(m);
  assert(CGAL::is_closed(m) && PMP::is_outward_oriented(m));
  assert(r.non_manifold_vertices == 0 && r.non_manifold_edges == 0 && r.components == 1 && components(m) == 1);
  const CGAL::Side_of_triangle_mesh<Mesh, K> side(m);
  assert(side(Point(0, 0, 0)) == CGAL::ON_BOUNDED_SIDE && side(Point(3, 0, 0)) == CGAL::ON_UNBOUNDED_SIDE);
  // independent of the input order and of the number of threads
  std::vector<Point> shuffled = sphere;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(5));
  Mesh m2, m3;
  CGAL::lex_optimal_closed_surface_reconstruction(shuffled, m2);
  CGAL::lex_optimal_closed_surface_reconstruction(shuffled, m3, LOC::parameters::number_of_threads(2u));
  assert(as_off(m) == as_off(m2) && as_off(m) == as_off(m3));
  // with an interior point, the cell that holds it stays inside
  Mesh with_interior;
  CGAL::lex_optimal_closed_surface_reconstruction(sphere, with_interior,
                                                  LOC::parameters::interior_points(std::vector<Point>{Point(0.1, 0.2, 0)}));
  check_manifold_mesh(with_interior);
  const CGAL::Side_of_triangle_mesh<Mesh, K> side_of_it(with_interior);
  assert(side_of_it(Point(0.1, 0.2, 0)) == CGAL::ON_BOUNDED_SIDE);

  if(data.empty()) return;
  std::vector<Point> scan;
  const bool read = CGAL::IO::read_points(data + "/points_3/sphere_20k_normal.xyz", std::back_inserter(scan));
  assert(read && !scan.empty());
  check_closed_resolution(scan, "sphere_20k_normal.xyz");
  Mesh s;
  const auto rs = CGAL::lex_optimal_closed_surface_reconstruction(scan, s);
  check_manifold_mesh(s);
  assert(CGAL::is_closed(s) && rs.components == 1 && rs.genus == 0);
}

// ---- open surfaces --------------------------------------------------------------------------------
// a noisy terrain with two flat-roofed buildings (the walls make the non-manifold places)
std::vector<Point> terrain_with_buildings(std::size_t n)
{
  std::vector<Point> pts;
  for(std::size_t i = 0; i < n; ++i) {
    const double x = rng.get_double(0, 100), y = rng.get_double(0, 100);
    double z = 3 * std::sin(x / 15) * std::cos(y / 20);
    if(x > 20 && x < 40 && y > 25 && y < 45) z += 10;
    if(x > 60 && x < 85 && y > 55 && y < 75) z += 15;
    pts.emplace_back(x, y, z + rng.get_double(-0.1, 0.1));
  }
  return pts;
}

void check_open_disk(const std::vector<Point>& pts, const std::string& name)
{
  const std::vector<Point> polygon = LOC::footprint_boundary(pts);
  const std::vector<std::vector<Point>> boundary{polygon};
  for(const auto field : {LOC::Coefficient_field::Q, LOC::Coefficient_field::Z2}) {
    const char* field_name = field == LOC::Coefficient_field::Q ? "Q" : "Z2";
    for(const bool drop : {true, false}) {
      Mesh raw, m;
      const auto r0 = CGAL::lex_optimal_open_surface_reconstruction(
        pts, boundary, raw,
        LOC::parameters::keep_non_manifold(true, LOC::parameters::drop_boundary_triangles(drop, LOC::parameters::coefficient_field(field))));
      const auto r = CGAL::lex_optimal_open_surface_reconstruction(
        pts, boundary, m, LOC::parameters::drop_boundary_triangles(drop, LOC::parameters::coefficient_field(field)));
      std::cout << name << " (" << field_name << (drop ? ", skirt dropped" : "") << "): the optimum has "
                << r0.non_manifold_edges << " non-manifold edges and " << border_loops(raw) << " boundary loops; resolved: "
                << r.resolved_non_manifold_vertices << " vertices, " << r.resolution_changed_facets << " triangles changed, "
                << components(m) << " component, " << border_loops(m) << " boundary loop, Euler characteristic "
                << euler_characteristic(m) << "\n";
      assert(r0.non_manifold_edges > 0 && border_loops(raw) > 1); // the test is about something
      check_manifold_mesh(m);
      assert(r.non_manifold_vertices == 0 && r.non_manifold_edges == 0 && r.orientation_cuts == 0);
      assert(components(m) == 1 && border_loops(m) == 1 && euler_characteristic(m) == 1);
      assert(r.resolution_changed_facets > 0 && r.resolution_changed_facets <= 12 * r0.non_manifold_vertices);
      if(!drop) { // the boundary is the imposed polygon
        std::set<std::pair<Point, Point>> border, expected;
        for(auto h : m.halfedges())
          if(m.is_border(h)) border.emplace((std::min)(m.point(m.source(h)), m.point(m.target(h))),
                                            (std::max)(m.point(m.source(h)), m.point(m.target(h))));
        for(std::size_t i = 0; i + 1 < polygon.size(); ++i)
          expected.emplace((std::min)(polygon[i], polygon[i + 1]), (std::max)(polygon[i], polygon[i + 1]));
        assert(border == expected);
      }
    }
  }
  // independent of the input order
  std::vector<Point> shuffled = pts;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(9));
  Mesh a, b;
  CGAL::lex_optimal_open_surface_reconstruction(pts, boundary, a, LOC::parameters::drop_boundary_triangles(true));
  CGAL::lex_optimal_open_surface_reconstruction(shuffled, boundary, b, LOC::parameters::drop_boundary_triangles(true));
  assert(as_off(a) == as_off(b));
}

// ---- the fans that the drop of boundary triangles leaves pinched --------------------------------
// Soups by hand: the umbrella kept is in the largest part, then the largest, then the one with
// the smallest triangle; several pinches go in one round; an edge of three triangles is not a
// pinch.
void test_trim_of_pinched_umbrellas()
{
  using Soup = std::vector<std::array<std::uint32_t, 3>>;
  // a fan of 3 triangles around vertex 0 (on 1..4) and one triangle (0, 5, 6) pinched at 0
  Soup soup{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 5, 6}};
  assert(LOC::internal::trim_pinched_umbrellas(7, soup) == 1);
  assert((soup == Soup{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  // two single triangles at 0: the one with the smallest triangle stays
  soup = Soup{{0, 3, 4}, {0, 1, 2}};
  assert(LOC::internal::trim_pinched_umbrellas(5, soup) == 1 && (soup == Soup{{0, 3, 4}}));
  // the larger part wins over the larger umbrella: at 0, an umbrella of 2 triangles whose part
  // has 2, and one of 1 triangle (0, 5, 6) whose part goes on through edge (5, 6) to 5 more
  soup = Soup{{0, 1, 2}, {0, 2, 3}, {0, 5, 6}, {5, 7, 6}, {5, 8, 7}, {5, 9, 8}, {5, 10, 9}, {5, 11, 10}};
  assert(LOC::internal::trim_pinched_umbrellas(12, soup) == 2);
  assert(soup.size() == 6 && soup[0] == (std::array<std::uint32_t, 3>{0, 5, 6}));
  // several pinches in one round: at 0, the fan on 1..4 (part of 3 triangles, 3 at 0) and the
  // fan (0, 5, 6), (0, 6, 7) (part of 3 with (6, 8, 7), 2 at 0): the latter goes, and (6, 8, 7)
  // stays alone; at 4, (0, 3, 4) (part of 3) goes for the fan of 4 triangles on 9..13
  soup = Soup{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 5, 6}, {0, 6, 7}, {6, 8, 7}, {4, 9, 10}, {4, 10, 11}, {4, 11, 12}, {4, 12, 13}};
  assert(LOC::internal::trim_pinched_umbrellas(14, soup) == 3);
  assert((soup == Soup{{0, 1, 2}, {0, 2, 3}, {6, 8, 7}, {4, 9, 10}, {4, 10, 11}, {4, 11, 12}, {4, 12, 13}}));
  assert(LOC::internal::vertices_with_several_umbrellas(14, std::uint32_t(soup.size()),
                                                        [&](std::uint32_t c) { return soup[c / 3][c % 3]; })
           .empty());
  // a cascade: at 0, the fan on 1, 2, 3, 4, 12, 13, 14 stays and (5, 6, 0), (5, 0, 10) go; that
  // pinches 5, where their neighbours (5, 7, 8), (5, 8, 6) and (5, 10, 11) met through them: the
  // next round drops (5, 10, 11), the smaller part
  soup = Soup{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 12}, {0, 12, 13}, {0, 13, 14},
              {0, 5, 6}, {0, 10, 5}, {5, 7, 8}, {5, 8, 6}, {5, 10, 11}};
  assert(LOC::internal::trim_pinched_umbrellas(15, soup) == 3);
  assert((soup == Soup{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 12}, {0, 12, 13}, {0, 13, 14}, {5, 7, 8}, {5, 8, 6}}));
  // three triangles on the edge (0, 1): one umbrella at 0 and 1, nothing to trim
  soup = Soup{{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
  assert(LOC::internal::trim_pinched_umbrellas(5, soup) == 0 && soup.size() == 3);
}

// CGAL's poste_france.xyz under its footprint, the skirt dropped: the drop pinches the
// surface at three points; the trim makes it a 2-manifold; with keep_non_manifold, the pinches
// are split instead (the test is about something).
void check_trimmed_drop(const std::vector<Point>& pts, const std::string& name)
{
  const std::vector<std::vector<Point>> boundary{LOC::footprint_boundary(pts)};
  Mesh kept, trimmed, shuffled_trimmed;
  const auto rk = CGAL::lex_optimal_open_surface_reconstruction(
    pts, boundary, kept, LOC::parameters::drop_boundary_triangles(true, LOC::parameters::keep_non_manifold(true)));
  const auto r = CGAL::lex_optimal_open_surface_reconstruction(pts, boundary, trimmed, LOC::parameters::drop_boundary_triangles(true));
  std::cout << name << ", skirt dropped: " << rk.non_manifold_vertices << " vertex copies when kept; " << r.trimmed_triangles
            << " triangles trimmed, " << r.non_manifold_vertices << " copies\n";
  assert(rk.non_manifold_vertices > 0 && rk.trimmed_triangles == 0);
  assert(r.trimmed_triangles > 0 && r.non_manifold_vertices == 0 && r.non_manifold_edges == 0);
  check_manifold_mesh(trimmed);
  std::vector<Point> shuffled = pts;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(3));
  CGAL::lex_optimal_open_surface_reconstruction(shuffled, boundary, shuffled_trimmed, LOC::parameters::drop_boundary_triangles(true));
  assert(as_off(trimmed) == as_off(shuffled_trimmed));
}

void test_open_surfaces(const std::string& data)
{
  test_trim_of_pinched_umbrellas();
  check_open_disk(terrain_with_buildings(40000), "terrain with two buildings");
  if(data.empty()) return;
  std::vector<Point> b9;
  const bool read = CGAL::IO::read_points(data + "/points_3/b9_training.ply", std::back_inserter(b9));
  assert(read && !b9.empty());
  check_open_disk(b9, "b9_training.ply");
  std::vector<Point> poste;
  const bool read_poste = CGAL::IO::read_points(data + "/points_3/poste_france.xyz", std::back_inserter(poste));
  assert(read_poste && !poste.empty());
  check_trimmed_drop(poste, "poste_france.xyz");
}

// ---- exact ties: points on integer lattices (a rounded sphere, a stepped terrain) -----------------
// Many triangles of equal radii: the candidates are compared with the exact order and its
// symbolic tie-break. Every output is a 2-manifold; the closed ones stay closed.
void test_lattice_inputs()
{
  std::size_t resolved = 0;
  for(int seed = 0; seed < 4; ++seed) {
    CGAL::Random r(seed);
    std::vector<Point> sphere, terrain;
    while(sphere.size() < 1500) { // radius 12 with radial noise 1, rounded
      const double x = r.get_double(-1, 1), y = r.get_double(-1, 1), z = r.get_double(-1, 1);
      const double l = std::sqrt(x * x + y * y + z * z), s = 12 + r.get_double(-1, 1);
      if(l > 1e-3) sphere.emplace_back(std::round(x / l * s), std::round(y / l * s), std::round(z / l * s));
    }
    for(int i = 0; i < 1500; ++i) { // a block 6 high on a 30 x 30 grid, heights jittered by 0 to 3
      const int x = r.get_int(0, 30), y = r.get_int(0, 30);
      terrain.emplace_back(x, y, (x > 8 && x < 20 && y > 8 && y < 20 ? 6 : 0) + r.get_int(0, 3));
    }
    Mesh closed;
    const auto rc = CGAL::lex_optimal_closed_surface_reconstruction(sphere, closed,
                                                                    LOC::parameters::minimum_interior_persistence(1.01));
    check_manifold_mesh(closed);
    assert(CGAL::is_closed(closed) && rc.non_manifold_vertices == 0);
    resolved += rc.resolved_non_manifold_vertices;
    const std::vector<std::vector<Point>> boundary{LOC::footprint_boundary(terrain)};
    for(const auto field : {LOC::Coefficient_field::Q, LOC::Coefficient_field::Z2}) {
      Mesh open;
      const auto ro = CGAL::lex_optimal_open_surface_reconstruction(terrain, boundary, open,
                                                                    LOC::parameters::coefficient_field(field));
      check_manifold_mesh(open);
      assert(ro.non_manifold_vertices == 0 && ro.non_manifold_edges == 0);
      resolved += ro.resolved_non_manifold_vertices;
    }
  }
  std::cout << "lattice inputs: " << resolved << " non-manifold vertices resolved, every output a 2-manifold\n";
  assert(resolved > 0);
}

int main(int argc, char** argv)
{
  std::cout << std::unitbuf;
  const std::string data = argc > 1 ? argv[1] : "";
  test_detection_on_unions_of_cells();
  test_replaced_facets_on_unions_of_cells();
  test_closed_surfaces(data);
  test_open_surfaces(data);
  test_lattice_inputs();
  if(data.empty()) std::cout << "no data directory given: the checks on CGAL's scans are skipped\n";
  std::cout << "all manifold resolution checks passed\n";
  return 0;
}
