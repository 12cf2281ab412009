// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_MESHES_3_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_MESHES_3_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_surface_type.h>
#include <CGAL/Polygon_partition_simplification/LOD2_report.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/Building_extrusion_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/Height_functions.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// the face properties of an LOD2 model
template <class Point>
struct Building_face_maps
{
  using Mesh = CGAL::Surface_mesh<Point>;
  using Face = typename Mesh::Face_index;
  typename Mesh::template Property_map<Face, Building_surface_type> surface_type;
  typename Mesh::template Property_map<Face, std::size_t> building;
  typename Mesh::template Property_map<Face, std::size_t> plane;

  explicit Building_face_maps(Mesh& mesh)
    : surface_type(mesh.template add_property_map<Face, Building_surface_type>("f:surface_type",
                                                                             Building_surface_type::WALL).first),
      building(mesh.template add_property_map<Face, std::size_t>("f:building", 0).first),
      plane(mesh.template add_property_map<Face, std::size_t>("f:plane", std::numeric_limits<std::size_t>::max()).first)
  {}
};

/// true when the closed mesh `building`, triangulated, does not intersect itself and bounds a volume
template <class Point>
bool bounds_a_volume(const CGAL::Surface_mesh<Point>& building)
{
  CGAL::Surface_mesh<Point> triangles = building;
  if(!CGAL::Polygon_mesh_processing::triangulate_faces(triangles)) return false;
  return !CGAL::Polygon_mesh_processing::does_self_intersect(triangles) &&
         CGAL::Polygon_mesh_processing::does_bound_a_volume(triangles);
}

/// adds the building soups to `mesh` (one connected closed component each), with the face
/// properties `f:surface_type`, `f:building` and `f:plane` (index of the roof's plane,
/// `std::size_t(-1)` for walls and floors), and fills the counts and checks of `report`
template <class Point>
void add_buildings_to_mesh(std::vector<Building_soup>& soups, const Height_functions& heights,
                           CGAL::Surface_mesh<Point>& mesh, LOD2_report& report)
{
  using Mesh = CGAL::Surface_mesh<Point>;
  namespace PMP = CGAL::Polygon_mesh_processing;
  Building_face_maps<Point> maps(mesh);
  report.closed = report.bounds_volume = true;
  for(std::size_t b = 0; b < soups.size(); ++b) {
    Building_soup& soup = soups[b];
    std::vector<Point> points;
    for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
    if(!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons)) {
      PMP::orient_polygon_soup(points, soup.polygons);
      ++report.repaired_buildings;
    }
    Mesh building;
    PMP::polygon_soup_to_polygon_mesh(points, soup.polygons, building);
    CGAL_assertion(building.number_of_faces() == soup.polygons.size());
    report.closed = report.closed && CGAL::is_closed(building);
    report.bounds_volume = report.bounds_volume && CGAL::is_closed(building) && bounds_a_volume(building);
    const std::size_t first_vertex = mesh.number_of_vertices();
    for(auto v : building.vertices()) mesh.add_vertex(building.point(v));
    std::vector<typename Mesh::Vertex_index> corners;
    std::size_t polygon = 0;
    for(auto f : building.faces()) {
      corners.clear();
      for(auto v : CGAL::vertices_around_face(building.halfedge(f), building))
        corners.push_back(typename Mesh::Vertex_index(typename Mesh::size_type(first_vertex + std::size_t(v))));
      const auto face = mesh.add_face(corners);
      CGAL_assertion(face != Mesh::null_face());
      maps.surface_type[face] = soup.types[polygon];
      maps.building[face] = b;
      if(soup.types[polygon] == Building_surface_type::ROOF) {
        maps.plane[face] = heights.plane_of_label[soup.labels[polygon]];
        ++report.roof_faces;
      } else if(soup.types[polygon] == Building_surface_type::WALL) {
        ++report.wall_faces;
      }
      ++polygon;
    }
  }
  report.buildings = soups.size();
  report.faces = mesh.number_of_faces();
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_MESHES_3_H
