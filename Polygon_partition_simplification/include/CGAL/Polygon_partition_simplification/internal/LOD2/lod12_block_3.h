// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD12_BLOCK_3_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD12_BLOCK_3_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_surface_type.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/triangulate_rings_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/convex_hull_2.h>

#include <array>
#include <map>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// A footprint: its outer ring counterclockwise and its holes clockwise (x, y).
using Footprint_rings = std::vector<std::vector<std::array<double, 2>>>;

/// the rings of the floor of an LOD2 solid, seen from above: the border of its `GROUND` faces,
/// turned so that the floor lies on the left; none when a corner is on two rings or twice on one
template <class Point>
std::optional<Footprint_rings> floor_rings(const Surface_mesh<Point>& solid)
{
  using Mesh = Surface_mesh<Point>;
  const auto type =
    optional_property_map(solid.template property_map<typename Mesh::Face_index, Building_surface_type>("f:surface_type"));
  if(!type) return std::nullopt;
  auto is_floor = [&](typename Mesh::Face_index f) {
    return f != Mesh::null_face() && (*type)[f] == Building_surface_type::GROUND;
  };
  // a floor face is seen clockwise from above: its border halfedges, reversed, turn counterclockwise
  std::map<typename Mesh::Vertex_index, typename Mesh::Halfedge_index> leaving; // border, reversed, by its source
  for(auto h : solid.halfedges()) {
    if(!is_floor(solid.face(h)) || is_floor(solid.face(solid.opposite(h)))) continue;
    const auto reversed = solid.opposite(h);
    if(!leaving.emplace(solid.source(reversed), reversed).second) return std::nullopt;
  }
  Footprint_rings rings;
  std::map<typename Mesh::Vertex_index, bool> used;
  for(const auto& [start, first] : leaving) {
    if(used[start]) continue;
    std::vector<std::array<double, 2>> ring;
    for(auto h = first;;) {
      const auto v = solid.source(h);
      if(used[v]) return std::nullopt;
      used[v] = true;
      ring.push_back({{CGAL::to_double(solid.point(v).x()), CGAL::to_double(solid.point(v).y())}});
      const auto next = leaving.find(solid.target(h));
      if(next == leaving.end()) return std::nullopt;
      if(next->first == start) break;
      h = next->second;
    }
    rings.push_back(std::move(ring));
  }
  if(rings.empty()) return std::nullopt;
  return rings;
}

/// the convex hull of the points, seen from above, as one counterclockwise ring
template <class PointRange>
Footprint_rings convex_hull_ring(const PointRange& points)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_2> projected, hull;
  for(const auto& p : points) projected.emplace_back(p[0], p[1]);
  CGAL::convex_hull_2(projected.begin(), projected.end(), std::back_inserter(hull));
  std::vector<std::array<double, 2>> ring;
  for(const K::Point_2& p : hull) ring.push_back({{p.x(), p.y()}});
  return {ring};
}

/// the footprint extruded from `bottom` to `top`: a closed, outward oriented prism whose floor
/// and roof are triangulated, with the faces maps `"f:surface_type"` and `"f:building"` (`building`)
template <class Point>
Surface_mesh<Point> extruded_block(const Footprint_rings& rings, double bottom, double top, std::size_t building)
{
  using Mesh = Surface_mesh<Point>;
  using Face = typename Mesh::Face_index;
  Mesh block;
  auto type = block.template add_property_map<Face, Building_surface_type>("f:surface_type", Building_surface_type::WALL).first;
  auto owner = block.template add_property_map<Face, std::size_t>("f:building", building).first;
  std::vector<std::vector<Ring_corner>> corners;
  std::vector<typename Mesh::Vertex_index> low, high;
  for(const auto& ring : rings) {
    corners.emplace_back();
    for(const auto& p : ring) {
      corners.back().push_back({low.size(), p[0], p[1]});
      low.push_back(block.add_vertex(Point(p[0], p[1], bottom)));
      high.push_back(block.add_vertex(Point(p[0], p[1], top)));
    }
  }
  auto add = [&](std::vector<typename Mesh::Vertex_index> vertices, Building_surface_type t) {
    const Face f = block.add_face(vertices);
    if(f == Mesh::null_face()) return false;
    type[f] = t;
    owner[f] = building;
    return true;
  };
  bool ok = true;
  for(const auto& t : triangulate_rings(corners)) {
    ok = ok && add({high[t[0]], high[t[1]], high[t[2]]}, Building_surface_type::ROOF);
    ok = ok && add({low[t[0]], low[t[2]], low[t[1]]}, Building_surface_type::GROUND);
  }
  for(const auto& ring : corners)
    for(std::size_t i = 0; i < ring.size(); ++i) {
      const std::size_t a = ring[i].id, b = ring[(i + 1) % ring.size()].id;
      ok = ok && add({low[a], low[b], high[b], high[a]}, Building_surface_type::WALL);
    }
  if(!ok) block.clear();
  return block;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD12_BLOCK_3_H
