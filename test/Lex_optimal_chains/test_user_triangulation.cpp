// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The stages of the package on triangulations that the user built: custom vertex and cell
// bases (with info), Fast_location, the parallel tag, the package's traits class as geometric
// traits. Each mesh made on a user's triangulation must
// be the one made from the points (same oriented triangles), the facets of the raw functions
// must be the faces of the mesh, the triangulation and its vertex information must be left
// as they were, and an insertion of a boundary that fails must give the triangulation back
// with the vertices it had.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Lex_optimal_chains_traits_3.h>
#include <CGAL/lex_optimal_closed_surface.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>
#include <CGAL/Lex_optimal_chains/insert_boundary.h>

#include "test_support.h"

#include <array>
#include <cassert>
#include <cmath>
#include <iostream>
#include <iterator>
#include <map>
#include <set>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;
namespace PMP = CGAL::Polygon_mesh_processing;

using Info_vb = CGAL::Triangulation_vertex_base_with_info_3<std::size_t, K>;
using Info_cb = CGAL::Triangulation_cell_base_with_info_3<int, K, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Info_tds = CGAL::Triangulation_data_structure_3<Info_vb, Info_cb>;
using Info_DT = CGAL::Delaunay_triangulation_3<K, Info_tds>;
using Hierarchy_DT = CGAL::Delaunay_triangulation_3<K, CGAL::Default, CGAL::Fast_location>;
using Traits_DT = CGAL::Delaunay_triangulation_3<CGAL::Lex_optimal_chains_traits_3<K>>;
#ifdef CGAL_LINKED_WITH_TBB
using Parallel_tds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                                          CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag>;
using Parallel_DT = CGAL::Delaunay_triangulation_3<K, Parallel_tds>;
#endif

// A triangle as its points, rotated to start at the smallest: equal for equal oriented triangles.
using Oriented_triangle = std::array<Point, 3>;
Oriented_triangle oriented(const Point& a, const Point& b, const Point& c)
{
  if(b < a && b < c) return {{b, c, a}};
  if(c < a && c < b) return {{c, a, b}};
  return {{a, b, c}};
}

std::multiset<Oriented_triangle> faces_of(const Mesh& mesh)
{
  std::multiset<Oriented_triangle> faces;
  for(auto f : mesh.faces()) {
    std::vector<Point> p;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(mesh.point(v));
    assert(p.size() == 3);
    faces.insert(oriented(p[0], p[1], p[2]));
  }
  return faces;
}

// The facet (c, i) as the triangle oriented outward of c.
template <class DT>
Oriented_triangle triangle_of(const typename DT::Facet& f)
{
  const auto& c = f.first;
  const int i = f.second;
  const Point& a = c->vertex((i + 1) & 3)->point();
  const Point& b = c->vertex((i + 2) & 3)->point();
  const Point& d = c->vertex((i + 3) & 3)->point();
  return i & 1 ? oriented(a, d, b) : oriented(a, b, d);
}

std::vector<Point> sphere(CGAL::Random& rng, int n, double noise)
{
  std::vector<Point> points;
  for(int i = 0; i < n; ++i) {
    const double z = rng.get_double(-1, 1), t = rng.get_double(0, 6.283185307179586);
    const double r = 1 + rng.get_double(-noise, noise), s = std::sqrt(1 - z * z);
    points.emplace_back(r * s * std::cos(t), r * s * std::sin(t), r * z);
  }
  return points;
}

// Builds the triangulation of `points`; the info of a vertex is the index of its point.
template <class DT>
void fill(DT& dt, const std::vector<Point>& points)
{
  if constexpr(std::is_same<DT, Info_DT>::value) {
    std::vector<std::pair<Point, std::size_t>> indexed;
    for(std::size_t i = 0; i < points.size(); ++i) indexed.emplace_back(points[i], i);
    dt.insert(indexed.begin(), indexed.end());
#ifdef CGAL_LINKED_WITH_TBB
  } else if constexpr(std::is_same<DT, Parallel_DT>::value) {
    // built in parallel, with the lock grid left in place as a user would
    static typename Parallel_DT::Lock_data_structure locks(CGAL::Bbox_3(-2, -2, -2, 12, 12, 12), 8);
    dt.set_lock_data_structure(&locks);
    dt.insert(points.begin(), points.end());
#endif
  } else {
    dt.insert(points.begin(), points.end());
  }
}

// What must not change: the points of the vertices, and the infos with them.
template <class DT>
std::map<Point, std::size_t> vertices_of(const DT& dt)
{
  std::map<Point, std::size_t> result;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    std::size_t info = 0;
    if constexpr(std::is_same<DT, Info_DT>::value) info = v->info();
    result[v->point()] = info;
  }
  return result;
}

template <class DT>
void test_closed(const char* name, const std::vector<Point>& points, const std::multiset<Oriented_triangle>& expected)
{
  DT dt;
  fill(dt, points);
  const auto before = vertices_of(dt);
  Mesh mesh;
  const auto report = CGAL::lex_optimal_closed_surface_mesh(dt, mesh);
  std::cout << "  closed, " << name << ": " << mesh.number_of_faces() << " faces, "
            << report.resolved_non_manifold_vertices << " vertices resolved\n";
  assert(faces_of(mesh) == expected);
  assert(CGAL::is_closed(mesh) && CGAL::is_valid_polygon_mesh(mesh));
  assert(report.non_manifold_vertices == 0 && report.components == 1 && report.genus == 0);
  assert(vertices_of(dt) == before && dt.is_valid());

  // the facets of the raw function are the faces of the mesh
  std::vector<typename DT::Facet> facets;
  CGAL::lex_optimal_closed_surface(dt, std::back_inserter(facets));
  std::multiset<Oriented_triangle> raw;
  for(const auto& f : facets) raw.insert(triangle_of<DT>(f));
  assert(raw == expected);
}

void test_closed_surfaces(CGAL::Random& rng)
{
  const std::vector<Point> points = sphere(rng, 3000, 0.03);
  Mesh reference;
  CGAL::lex_optimal_closed_surface_reconstruction(points, reference);
  const auto expected = faces_of(reference);
  std::cout << "closed surface of a noisy sphere: " << expected.size() << " faces from the points\n";
  test_closed<CGAL::Delaunay_triangulation_3<K>>("Delaunay_triangulation_3<K>", points, expected);
  test_closed<Info_DT>("vertex and cell bases with info", points, expected);
  test_closed<Hierarchy_DT>("Fast_location", points, expected);
  test_closed<Traits_DT>("Lex_optimal_chains_traits_3 as geometric traits", points, expected);
  // the reconstruction with either traits
  Mesh with_kernel, with_traits;
  CGAL::lex_optimal_closed_surface_reconstruction(points, with_kernel, CGAL::parameters::geom_traits(K()));
  CGAL::lex_optimal_closed_surface_reconstruction(points, with_traits,
                                                  CGAL::parameters::geom_traits(CGAL::Lex_optimal_chains_traits_3<K>()));
  assert(faces_of(with_kernel) == expected && faces_of(with_traits) == expected);
#ifdef CGAL_LINKED_WITH_TBB
  test_closed<Parallel_DT>("Parallel_tag", points, expected);
#endif
  // dimension below 3: a typed error, nothing added to the mesh
  CGAL::Delaunay_triangulation_3<K> flat;
  for(int i = 0; i < 10; ++i) flat.insert(Point(i, i * i % 7, 0));
  Mesh mesh;
  expect_error(LOC::Input_error_code::DEGENERATE_POINT_SET, [&] { CGAL::lex_optimal_closed_surface_mesh(flat, mesh); });
  assert(mesh.is_empty());
}

template <class DT>
void test_open(const char* name, const std::vector<Point>& points, const std::vector<std::vector<Point>>& boundary,
               const std::multiset<Oriented_triangle>& expected)
{
  DT dt;
  fill(dt, points);
  const auto before = vertices_of(dt);
  const LOC::Inserted_boundary<DT> inserted = LOC::insert_boundary(dt, boundary);
  assert(inserted.new_vertices.size() == boundary[0].size() - 1 && inserted.removed_points.empty());
  assert(inserted.edges.size() == boundary[0].size() - 1);
  for(std::size_t i = 0; i < inserted.edges.size(); ++i)
    assert(inserted.edges[i].first->point() == boundary[0][i] && inserted.edges[i].second->point() == boundary[0][i + 1]);
  for(const auto& v : inserted.new_vertices) assert(!before.count(v->point()));
  const auto with_boundary = vertices_of(dt);
  for(const auto& pi : before) assert(with_boundary.count(pi.first) && with_boundary.at(pi.first) == pi.second);

  Mesh mesh;
  const auto report = CGAL::lex_optimal_open_surface_mesh(dt, inserted.edges, mesh);
  std::cout << "  open, " << name << ": " << mesh.number_of_faces() << " faces, "
            << report.resolved_non_manifold_vertices << " vertices resolved\n";
  assert(faces_of(mesh) == expected);
  assert(CGAL::is_valid_polygon_mesh(mesh) && report.non_manifold_vertices == 0 && report.non_manifold_edges == 0);
  assert(vertices_of(dt) == with_boundary && dt.is_valid());
  // Z2: the same triangles (a disk is orientable)
  Mesh z2;
  CGAL::lex_optimal_open_surface_mesh(dt, inserted.edges, z2,
                                      LOC::parameters::coefficient_field(LOC::Coefficient_field::Z2));
  assert(z2.number_of_faces() == mesh.number_of_faces());
}

template <class DT>
void test_blocked_boundary(const char* name, const std::vector<Point>& points, const std::vector<std::vector<Point>>& boundary,
                           const std::multiset<Oriented_triangle>& expected)
{
  DT dt;
  fill(dt, points);
  const auto before = vertices_of(dt);
  // refused: the triangulation gets its vertices back
  expect_error(LOC::Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION, [&] { LOC::insert_boundary(dt, boundary); });
  assert(vertices_of(dt).size() == before.size() && dt.is_valid());
  for(const auto& pi : before) assert(vertices_of(dt).count(pi.first));
  // with the removal of the blocking points: the mesh of the points route
  const auto inserted = LOC::insert_boundary(dt, boundary, LOC::parameters::remove_blocking_points(true));
  assert(!inserted.removed_points.empty());
  for(const auto& p : inserted.removed_points) assert(before.count(p));
  assert(dt.number_of_vertices() == before.size() + inserted.new_vertices.size() - inserted.removed_points.size());
  Mesh mesh;
  CGAL::lex_optimal_open_surface_mesh(dt, inserted.edges, mesh);
  std::cout << "  boundary through the cloud, " << name << ": " << inserted.removed_points.size() << " points removed, "
            << mesh.number_of_faces() << " faces\n";
  assert(faces_of(mesh) == expected);
}

void test_open_surfaces(CGAL::Random& rng)
{
  const std::vector<Point> points = height_field<Point>(rng, 3000, 0.02);
  const std::vector<std::vector<Point>> footprint{LOC::footprint_boundary(points)};
  Mesh reference;
  CGAL::lex_optimal_open_surface_reconstruction(points, footprint, reference);
  const auto expected = faces_of(reference);
  std::cout << "open surface of a terrain in its footprint: " << expected.size() << " faces from the points\n";
  test_open<CGAL::Delaunay_triangulation_3<K>>("Delaunay_triangulation_3<K>", points, footprint, expected);
  test_open<Info_DT>("vertex and cell bases with info", points, footprint, expected);
  test_open<Hierarchy_DT>("Fast_location", points, footprint, expected);
  test_open<Traits_DT>("Lex_optimal_chains_traits_3 as geometric traits", points, footprint, expected);
  Mesh with_kernel;
  CGAL::lex_optimal_open_surface_reconstruction(points, footprint, with_kernel, CGAL::parameters::geom_traits(K()));
  assert(faces_of(with_kernel) == expected);
#ifdef CGAL_LINKED_WITH_TBB
  test_open<Parallel_DT>("Parallel_tag", points, footprint, expected);
#endif

  // a square through the cloud with short edges: points of the cloud block some of them
  std::vector<Point> square;
  const double cx[4] = {2, 8, 8, 2}, cy[4] = {2, 2, 8, 8};
  for(int s = 0; s < 4; ++s)
    for(int k = 0; k < 24; ++k) {
      const double x = cx[s] + (cx[(s + 1) % 4] - cx[s]) * k / 24.0, y = cy[s] + (cy[(s + 1) % 4] - cy[s]) * k / 24.0;
      square.emplace_back(x, y, std::sin(0.7 * x) * std::cos(0.5 * y) + 0.3 * x / 10);
    }
  square.push_back(square.front());
  const std::vector<std::vector<Point>> well{square};
  Mesh through;
  CGAL::lex_optimal_open_surface_reconstruction(points, well, through, LOC::parameters::remove_blocking_points(true));
  const auto expected_through = faces_of(through);
  test_blocked_boundary<CGAL::Delaunay_triangulation_3<K>>("Delaunay_triangulation_3<K>", points, well, expected_through);
  test_blocked_boundary<Info_DT>("vertex and cell bases with info", points, well, expected_through);
  test_blocked_boundary<Hierarchy_DT>("Fast_location", points, well, expected_through);
#ifdef CGAL_LINKED_WITH_TBB
  test_blocked_boundary<Parallel_DT>("Parallel_tag", points, well, expected_through);
#endif

  // bad polylines: refused before anything is inserted
  CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end());
  const std::size_t n = dt.number_of_vertices();
  std::vector<std::vector<Point>> open_polyline{footprint[0]};
  open_polyline[0].pop_back();
  expect_error(LOC::Input_error_code::OPEN_POLYLINE, [&] { LOC::insert_boundary(dt, open_polyline); });
  std::vector<std::vector<Point>> far{{Point(100, 100, 0), Point(101, 100, 0), Point(101, 101, 0), Point(100, 100, 0)}};
  expect_error(LOC::Input_error_code::BOUNDARY_FAR_FROM_POINTS, [&] { LOC::insert_boundary(dt, far); });
  assert(dt.number_of_vertices() == n);
  // a cycle of three vertices of the cloud far from each other: not edges of the triangulation
  const auto a = dt.nearest_vertex(Point(1, 1, 0)), b = dt.nearest_vertex(Point(9, 1, 0)), c = dt.nearest_vertex(Point(5, 9, 0));
  auto is_edge = [&dt](auto u, auto v) {
    CGAL::Delaunay_triangulation_3<K>::Cell_handle cell;
    int i, j;
    return dt.is_edge(u, v, cell, i, j);
  };
  assert(!is_edge(a, b) && !is_edge(b, c) && !is_edge(c, a));
  const std::vector<std::pair<CGAL::Delaunay_triangulation_3<K>::Vertex_handle, CGAL::Delaunay_triangulation_3<K>::Vertex_handle>>
    triangle{{a, b}, {b, c}, {c, a}};
  Mesh mesh;
  expect_error(LOC::Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION,
               [&] { CGAL::lex_optimal_open_surface_mesh(dt, triangle, mesh); });
  assert(mesh.is_empty());
}

// The contraction runs on several threads from `minimum_cells_for_parallel_contraction`
// cells: the chains must be the same, facet for facet and in the same order, as on one thread.
void test_threads(CGAL::Random& rng)
{
#ifndef CGAL_LINKED_WITH_TBB
  std::cout << "without TBB the contraction has one thread: the comparison of thread counts is skipped\n";
  (void)rng;
  return;
#endif
  using DT = CGAL::Delaunay_triangulation_3<K>;
  const std::vector<Point> points = sphere(rng, 40000, 0.02);
  const DT dt(points.begin(), points.end());
  assert(dt.number_of_cells() >= LOC::internal::minimum_cells_for_parallel_contraction);
  std::vector<Oriented_triangle> closed[2];
  for(unsigned threads : {1u, 2u}) {
    std::vector<DT::Facet> facets;
    const auto report = CGAL::lex_optimal_closed_surface(dt, std::back_inserter(facets),
                                                         LOC::parameters::number_of_threads(threads));
    for(const auto& f : facets) closed[threads - 1].push_back(triangle_of<DT>(f));
    std::cout << "closed surface on " << threads << " thread(s): " << facets.size() << " facets, "
              << report.number_of_exactly_ordered_triangles << " ordered exactly\n";
  }
  assert(!closed[0].empty() && closed[0] == closed[1]);

  // the mesh, with the key pass, the radix sort and the reading of the surface on two threads
  // too (each from 200,000 cells, records or facets): the same vertices and faces, in the same
  // order
  const std::vector<Point> big = sphere(rng, 110000, 0.002);
  const DT big_dt(big.begin(), big.end());
  Mesh meshes[2];
  for(unsigned threads : {1u, 2u}) {
    CGAL::lex_optimal_closed_surface_mesh(big_dt, meshes[threads - 1], LOC::parameters::number_of_threads(threads));
    std::cout << "closed mesh on " << threads << " thread(s): " << meshes[threads - 1].number_of_faces() << " faces\n";
  }
  assert(meshes[0].number_of_faces() >= LOC::internal::Closed_surface_mesh_3<DT>::minimum_facets_for_parallel_reading);
  assert(meshes[0].number_of_vertices() == meshes[1].number_of_vertices() &&
         meshes[0].number_of_faces() == meshes[1].number_of_faces());
  for(const auto v : meshes[0].vertices()) assert(meshes[0].point(v) == meshes[1].point(v));
  for(const auto f : meshes[0].faces()) {
    auto h0 = meshes[0].halfedge(f), h1 = meshes[1].halfedge(f);
    for(int e = 0; e < 3; ++e, h0 = meshes[0].next(h0), h1 = meshes[1].next(h1))
      assert(meshes[0].target(h0) == meshes[1].target(h1));
  }

  const std::vector<Point> terrain = height_field<Point>(rng, 40000, 0.02);
  DT tdt(terrain.begin(), terrain.end());
  const auto inserted = LOC::insert_boundary(tdt, std::vector<std::vector<Point>>{LOC::footprint_boundary(terrain)});
  assert(tdt.number_of_cells() >= LOC::internal::minimum_cells_for_parallel_contraction);
  std::vector<std::pair<Oriented_triangle, std::int64_t>> open[2];
  for(unsigned threads : {1u, 2u}) {
    std::vector<std::pair<DT::Facet, std::int64_t>> chain;
    CGAL::lex_optimal_chain_with_boundary(tdt, inserted.edges, std::back_inserter(chain),
                                          LOC::parameters::number_of_threads(threads));
    for(const auto& fk : chain) open[threads - 1].emplace_back(triangle_of<DT>(fk.first), fk.second);
    std::cout << "open surface on " << threads << " thread(s): " << chain.size() << " facets\n";
  }
  assert(!open[0].empty() && open[0] == open[1]);
}

int main()
{
  CGAL::Random rng(7);
  test_closed_surfaces(rng);
  test_open_surfaces(rng);
  test_threads(rng);
  std::cout << "OK\n";
  return 0;
}
