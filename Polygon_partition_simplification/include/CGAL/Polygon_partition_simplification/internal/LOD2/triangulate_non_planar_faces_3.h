// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_TRIANGULATE_NON_PLANAR_FACES_3_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_TRIANGULATE_NON_PLANAR_FACES_3_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_surface_type.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// the largest distance of a vertex of `f` to the plane of Newell's normal through the
/// centroid of its vertices; infinity for a face without area
template <class Point>
double planarity_deviation(const Surface_mesh<Point>& mesh, typename Surface_mesh<Point>::Face_index f)
{
  std::vector<std::array<double, 3>> p;
  for(auto v : vertices_around_face(mesh.halfedge(f), mesh))
    p.push_back({{CGAL::to_double(mesh.point(v).x()), CGAL::to_double(mesh.point(v).y()), CGAL::to_double(mesh.point(v).z())}});
  std::array<double, 3> normal{{0, 0, 0}}, centroid{{0, 0, 0}};
  for(std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
    for(int c = 0; c < 3; ++c) centroid[c] += a[c] / double(p.size());
  }
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  if(!(length > 0)) return std::numeric_limits<double>::infinity();
  double deviation = 0;
  for(const auto& a : p) {
    double d = 0;
    for(int c = 0; c < 3; ++c) d += (a[c] - centroid[c]) * normal[c] / length;
    deviation = std::max(deviation, std::abs(d));
  }
  return deviation;
}

/// Copies the face properties of an LOD2 model (`f:surface_type`, `f:building`, `f:plane`) from a
/// face to the triangles that replace it.
template <class Point>
struct Face_property_copier : public CGAL::Polygon_mesh_processing::Triangulate_faces::Default_visitor<Surface_mesh<Point>>
{
  using Mesh = Surface_mesh<Point>;
  using Face = typename Mesh::Face_index;
  typename Mesh::template Property_map<Face, Building_surface_type> type;
  typename Mesh::template Property_map<Face, std::size_t> building, plane;
  Building_surface_type current_type = Building_surface_type::WALL;
  std::size_t current_building = 0, current_plane = 0;

  explicit Face_property_copier(Mesh& mesh)
    : type(*optional_property_map(mesh.template property_map<Face, Building_surface_type>("f:surface_type"))),
      building(*optional_property_map(mesh.template property_map<Face, std::size_t>("f:building"))),
      plane(*optional_property_map(mesh.template property_map<Face, std::size_t>("f:plane")))
  {}
  void before_subface_creations(Face f)
  {
    current_type = type[f];
    current_building = building[f];
    current_plane = plane[f];
  }
  void after_subface_created(Face f)
  {
    type[f] = current_type;
    building[f] = current_building;
    plane[f] = current_plane;
  }
};

/// the faces of an LOD2 model that are not planar within `tolerance` (the heights merged at a
/// corner by the extrusion bend them) split into triangles, which keep the face's properties;
/// false when a face cannot be triangulated
template <class Point>
bool triangulate_non_planar_faces(Surface_mesh<Point>& mesh, double tolerance)
{
  using Mesh = Surface_mesh<Point>;
  using Face = typename Mesh::Face_index;
  if(!optional_property_map(mesh.template property_map<Face, Building_surface_type>("f:surface_type")) ||
     !optional_property_map(mesh.template property_map<Face, std::size_t>("f:building")) ||
     !optional_property_map(mesh.template property_map<Face, std::size_t>("f:plane")))
    return false;
  std::vector<typename Mesh::Face_index> bent;
  for(auto f : mesh.faces())
    if(planarity_deviation(mesh, f) > tolerance) bent.push_back(f);
  if(bent.empty()) return true;
  Face_property_copier<Point> copier(mesh);
  return CGAL::Polygon_mesh_processing::triangulate_faces(bent, mesh, CGAL::parameters::visitor(copier));
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_TRIANGULATE_NON_PLANAR_FACES_3_H
