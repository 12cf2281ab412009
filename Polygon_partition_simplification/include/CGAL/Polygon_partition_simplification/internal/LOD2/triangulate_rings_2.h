// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_TRIANGULATE_RINGS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_TRIANGULATE_RINGS_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <list>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// A corner of a ring: its id in a polygon soup and its horizontal position.
struct Ring_corner
{
  std::size_t id;
  double x, y;
};

/// the triangles (ids, counterclockwise in the horizontal plane) of the region bounded by
/// `rings` (an outer ring and holes, which may pass twice through a corner): a constrained
/// Delaunay triangulation of the ring edges, its faces at odd nesting depth
inline std::vector<std::array<std::size_t, 3>> triangulate_rings(const std::vector<std::vector<Ring_corner>>& rings)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
  using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

  Cdt cdt;
  for(const auto& ring : rings) {
    std::vector<typename Cdt::Vertex_handle> vertices;
    for(const Ring_corner& corner : ring) {
      vertices.push_back(cdt.insert(K::Point_2(corner.x, corner.y)));
      vertices.back()->info() = corner.id;
    }
    for(std::size_t i = 0; i < vertices.size(); ++i)
      if(vertices[i] != vertices[(i + 1) % vertices.size()])
        cdt.insert_constraint(vertices[i], vertices[(i + 1) % vertices.size()]);
  }
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  // nesting depth by flooding from the infinite face, crossing one constraint per level
  std::list<typename Cdt::Edge> border;
  auto flood = [&cdt, &border](typename Cdt::Face_handle start, int depth) {
    if(start->info() != -1) return;
    std::list<typename Cdt::Face_handle> queue{start};
    while(!queue.empty()) {
      const auto f = queue.front();
      queue.pop_front();
      if(f->info() != -1) continue;
      f->info() = depth;
      for(int i = 0; i < 3; ++i) {
        const auto n = f->neighbor(i);
        if(n->info() != -1) continue;
        if(cdt.is_constrained(typename Cdt::Edge(f, i))) border.push_back(typename Cdt::Edge(f, i));
        else queue.push_back(n);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while(!border.empty()) {
    const auto e = border.front();
    border.pop_front();
    const auto n = e.first->neighbor(e.second);
    if(n->info() == -1) flood(n, e.first->info() + 1);
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->info() % 2 == 1)
      triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return triangles;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_TRIANGULATE_RINGS_2_H
