// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The oracle of the data sweep: whether a mesh that a program of the packages wrote is a valid
// oriented 2-manifold, judged by CGAL's Polygon Mesh Processing alone (no code of the packages).
//   check_output_mesh MESH [--closed | --disk] [--split-points N]
// MESH (.off, .ply or .obj) must be readable, have at least one face, finite coordinates, no
// vertex that no face uses, and be a polygon mesh (PMP::is_polygon_soup_a_polygon_mesh: every
// edge in at most two faces, consistently oriented, every vertex a single umbrella). Its
// triangles are not degenerate and, after its faces are triangulated, no two faces intersect
// other than at a shared vertex or edge (PMP::does_self_intersect). With --closed it has no
// border and every connected component bounds a positive volume (outward normals); with --disk
// it is one topological disk: connected, one border cycle, Euler characteristic 1.
// A mesh may have several vertices at one point only where the program said so: with
// --split-points N, exactly N points carry several vertices (the feature-guided
// reconstruction splits the points where elements of the basis meet, one vertex per umbrella,
// and reports how many); these meshes are not tested for self-intersection, since the faces
// around a split point meet there without sharing a vertex.
// Prints one line, "ok: ..." (exit code 0) or "defect: ..." (exit code 1); 2 on a usage error.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;

namespace {

struct Options
{
  std::string file;
  bool closed = false;
  bool disk = false;
  std::size_t split_points = 0;
};

[[noreturn]] void defect(const std::string& what)
{
  std::cout << "defect: " << what << std::endl;
  std::exit(1);
}

bool parse(int argc, char** argv, Options& options)
{
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--closed")
      options.closed = true;
    else if(arg == "--disk")
      options.disk = true;
    else if(arg == "--split-points" && i + 1 < argc) {
      std::istringstream in(argv[++i]);
      if(!(in >> options.split_points) || !in.eof()) return false;
    } else if(options.file.empty() && !arg.empty() && arg[0] != '-')
      options.file = arg;
    else
      return false;
  }
  return !options.file.empty() && !(options.closed && options.disk);
}

// The number of points that carry several vertices of the soup.
std::size_t number_of_split_points(const std::vector<Point>& points)
{
  std::map<Point, std::size_t> copies;
  for(const Point& p : points) ++copies[p];
  return std::count_if(copies.begin(), copies.end(), [](const auto& entry) { return entry.second > 1; });
}

void check_soup(const std::vector<Point>& points, const std::vector<Polygon>& polygons, const Options& options)
{
  if(polygons.empty()) defect("no face");
  std::vector<bool> used(points.size(), false);
  for(const Polygon& polygon : polygons) {
    if(polygon.size() < 3) defect("a face with fewer than 3 vertices");
    for(std::size_t v : polygon) used[v] = true;
  }
  if(std::find(used.begin(), used.end(), false) != used.end()) defect("a vertex that no face uses");
  for(const Point& p : points)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) defect("a coordinate is not finite");
  const std::size_t split = number_of_split_points(points);
  if(split != options.split_points)
    defect(std::to_string(split) + " points carry several vertices (" + std::to_string(options.split_points) + " said)");
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    defect("not an oriented 2-manifold (an edge of three faces or more, a pinched vertex, or inconsistent orientations)");
}

void check_mesh(Mesh& mesh, const Options& options)
{
  if(!CGAL::is_valid_polygon_mesh(mesh)) defect("not a valid polygon mesh");
  for(auto f : faces(mesh))
    if(CGAL::is_triangle(halfedge(f, mesh), mesh) && PMP::is_degenerate_triangle_face(f, mesh))
      defect("a degenerate triangle");
  if(options.closed && !CGAL::is_closed(mesh)) defect("not closed");
  if(options.disk) {
    std::vector<Mesh::Halfedge_index> cycles;
    PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
    auto components = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
    const std::size_t count = PMP::connected_components(mesh, components);
    const long euler = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
    if(count != 1 || cycles.size() != 1 || euler != 1)
      defect("not a disk: " + std::to_string(count) + " components, " + std::to_string(cycles.size()) +
             " border cycles, Euler characteristic " + std::to_string(euler));
  }
  Mesh triangles = mesh;
  if(!CGAL::is_triangle_mesh(triangles) && !PMP::triangulate_faces(triangles))
    defect("a face that cannot be triangulated");
  if(options.split_points == 0 && PMP::does_self_intersect(triangles))
    defect("faces intersect away from their shared vertices and edges");
  if(options.closed) {
    std::vector<Mesh> components;
    PMP::split_connected_components(triangles, components);
    for(const Mesh& component : components)
      if(!(PMP::volume(component) > 0)) defect("a component does not bound a positive volume (inward normals)");
  }
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  if(!parse(argc, argv, options)) {
    std::cerr << "usage: " << argv[0] << " MESH [--closed | --disk] [--split-points N]" << std::endl;
    return 2;
  }
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  if(!CGAL::IO::read_polygon_soup(options.file, points, polygons)) defect("unreadable: " + options.file);
  check_soup(points, polygons, options);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  check_mesh(mesh, options);
  std::cout << "ok: " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces"
            << (CGAL::is_closed(mesh) ? ", closed" : ", with a border")
            << (options.split_points ? ", " + std::to_string(options.split_points) + " split points" : std::string())
            << std::endl;
  return 0;
}
