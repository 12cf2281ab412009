// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_SOLID_DEFECT_3_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_SOLID_DEFECT_3_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_surface_type.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The tolerances of the validity check of a solid, as val3dity's defaults (in metres).
struct Solid_tolerances
{
  double snap = 0.001;     ///< vertices closer than this are one (val3dity's snap_tol)
  double planarity = 0.01; ///< largest distance of a face's vertex to the face's plane (planarity_d2p_tol)
};

/// A face's vertices after snapping: ids of the snapped points, and the points.
struct Snapped_soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;
  std::vector<std::size_t> source; ///< the face of the mesh of each face
};

/// the faces of `mesh` on the points snapped to a grid of side `snap` (vertices in one grid cell
/// are one, at the first of them), with repeated consecutive vertices removed; the faces left
/// with fewer than 3 vertices are dropped, as the CityJSON writers drop them
template <class Point>
Snapped_soup snapped_soup(const Surface_mesh<Point>& mesh, double snap)
{
  Snapped_soup soup;
  std::map<std::array<long long, 3>, std::size_t> index;
  for(auto f : mesh.faces()) {
    std::vector<std::size_t> face;
    for(auto v : vertices_around_face(mesh.halfedge(f), mesh)) {
      const Point& p = mesh.point(v);
      const std::array<double, 3> c{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
      std::array<long long, 3> key;
      for(int i = 0; i < 3; ++i) key[i] = std::llround(c[i] / snap);
      const auto inserted = index.emplace(key, soup.points.size());
      if(inserted.second) soup.points.push_back(c);
      if(face.empty() || face.back() != inserted.first->second) face.push_back(inserted.first->second);
    }
    while(face.size() > 1 && face.back() == face.front()) face.pop_back();
    if(face.size() < 3) continue;
    soup.faces.push_back(std::move(face));
    soup.source.push_back(std::size_t(f));
  }
  return soup;
}

/// `mesh` made of its snapped soup (vertices closer than `snap` merged, collapsed faces
/// dropped), its face properties `f:surface_type`, `f:building` and `f:plane` kept; unchanged
/// when the soup is not a polygon mesh (then `solid_defect()` says why)
template <class Point>
void snap_solid(Surface_mesh<Point>& mesh, double snap)
{
  using Mesh = Surface_mesh<Point>;
  using Face = typename Mesh::Face_index;
  const Snapped_soup soup = snapped_soup(mesh, snap);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.faces)) return;
  std::vector<Point> points;
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  Mesh snapped;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.faces, snapped);
  auto copy = [&](const char* name, auto value) {
    using T = decltype(value);
    const auto from = optional_property_map(mesh.template property_map<Face, T>(name));
    if(!from) return;
    auto to = snapped.template add_property_map<Face, T>(name, value).first;
    std::size_t i = 0;
    for(Face f : snapped.faces()) to[f] = (*from)[Face(typename Mesh::size_type(soup.source[i++]))];
  };
  copy("f:surface_type", Building_surface_type::WALL);
  copy("f:building", std::size_t(0));
  copy("f:plane", std::size_t(0));
  mesh = std::move(snapped);
}

/// why the face `face` of `soup` is not a valid polygon (empty when it is): it repeats a vertex,
/// has no area, or is not planar within the tolerance (its plane: Newell's normal through its centroid)
inline std::string face_defect(const Snapped_soup& soup, std::size_t f, const Solid_tolerances& tolerances)
{
  const std::vector<std::size_t>& face = soup.faces[f];
  const std::string name = "face " + std::to_string(f);
  std::vector<std::size_t> sorted = face;
  std::sort(sorted.begin(), sorted.end());
  if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return name + " passes twice through a vertex";
  if(face.size() < 3) return name + " has fewer than 3 distinct vertices";
  std::array<double, 3> normal{{0, 0, 0}}, centroid{{0, 0, 0}};
  for(std::size_t i = 0; i < face.size(); ++i) {
    const auto& p = soup.points[face[i]];
    const auto& q = soup.points[face[(i + 1) % face.size()]];
    normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
    normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
    normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
    for(int c = 0; c < 3; ++c) centroid[c] += p[c] / double(face.size());
  }
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  if(!(0.5 * length > tolerances.snap * tolerances.snap)) return name + " has no area";
  for(std::size_t v : face) {
    const auto& p = soup.points[v];
    double distance = 0;
    for(int c = 0; c < 3; ++c) distance += (p[c] - centroid[c]) * normal[c] / length;
    if(std::abs(distance) > tolerances.planarity)
      return name + " is not planar (a vertex " + std::to_string(std::abs(distance)) + " off its plane)";
  }
  return {};
}

/// why `mesh` is not a valid solid as val3dity checks one (empty when it is): after snapping its
/// vertices, every face a planar polygon of nonzero area without a repeated vertex; the faces
/// one closed 2-manifold shell (every edge in two faces of opposite orientations, every vertex
/// one umbrella), without self-intersection, bounding a positive volume (outward orientation)
template <class Point>
std::string solid_defect(const Surface_mesh<Point>& mesh, const Solid_tolerances& tolerances = {})
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  if(mesh.number_of_faces() == 0) return "no face";
  const Snapped_soup soup = snapped_soup(mesh, tolerances.snap);
  for(std::size_t f = 0; f < soup.faces.size(); ++f) {
    const std::string defect = face_defect(soup, f, tolerances);
    if(!defect.empty()) return defect;
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(soup.faces))
    return "not a 2-manifold: an edge in more than two faces, or in two of the same orientation, or a vertex where two sheets meet";
  std::vector<K::Point_3> points;
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  Surface_mesh<K::Point_3> shell;
  PMP::polygon_soup_to_polygon_mesh(points, soup.faces, shell);
  if(!CGAL::is_closed(shell)) return "not closed: it has a border";
  auto component = shell.add_property_map<Surface_mesh<K::Point_3>::Face_index, std::size_t>("f:component").first;
  const std::size_t shells = PMP::connected_components(shell, component);
  if(shells != 1) return std::to_string(shells) + " shells, not one";
  if(!PMP::triangulate_faces(shell)) return "a face cannot be triangulated";
  if(PMP::does_self_intersect(shell)) return "it intersects itself";
  if(!(PMP::volume(shell) > 0)) return "its faces are oriented inwards (negative volume)";
  return {};
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_SOLID_DEFECT_3_H
