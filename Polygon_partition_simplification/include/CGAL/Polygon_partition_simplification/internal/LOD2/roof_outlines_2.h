// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_ROOF_OUTLINES_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_ROOF_OUTLINES_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// the indices of the polyline `points[first..last]` kept by Douglas-Peucker with `tolerance`
/// (first and last always kept), in order
template <class Point_2>
void douglas_peucker(const std::vector<Point_2>& points, std::size_t first, std::size_t last, double tolerance,
                     std::vector<std::size_t>& kept)
{
  std::vector<std::pair<std::size_t, std::size_t>> stack{{first, last}};
  std::vector<bool> keep(points.size(), false);
  keep[first] = keep[last] = true;
  while(!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const double ax = CGAL::to_double(points[a].x()), ay = CGAL::to_double(points[a].y());
    const double dx = CGAL::to_double(points[b].x()) - ax, dy = CGAL::to_double(points[b].y()) - ay;
    const double length = std::sqrt(dx * dx + dy * dy);
    double farthest = tolerance;
    std::size_t split = a;
    for(std::size_t i = a + 1; i < b; ++i) {
      const double px = CGAL::to_double(points[i].x()) - ax, py = CGAL::to_double(points[i].y()) - ay;
      const double distance = length > 0 ? std::abs(dx * py - dy * px) / length : std::sqrt(px * px + py * py);
      if(distance > farthest) {
        farthest = distance;
        split = i;
      }
    }
    if(split == a) continue;
    keep[split] = true;
    stack.push_back({a, split});
    stack.push_back({split, b});
  }
  for(std::size_t i = first; i <= last; ++i)
    if(keep[i]) kept.push_back(i);
}

/// the chains of the boundary edges of a regularized alpha shape, as lists of vertex ids; a
/// chain is closed (first id repeated at the end) or runs between vertices of degree other
/// than two. Chains start at their smallest id, so that they do not depend on the order in
/// which the edges are given.
inline std::vector<std::vector<std::size_t>> boundary_chains(std::vector<std::array<std::size_t, 2>> edges)
{
  std::map<std::size_t, std::vector<std::size_t>> around;
  for(const auto& e : edges) {
    around[e[0]].push_back(e[1]);
    around[e[1]].push_back(e[0]);
  }
  for(auto& entry : around) std::sort(entry.second.begin(), entry.second.end());
  std::map<std::pair<std::size_t, std::size_t>, bool> used;
  auto take = [&used](std::size_t a, std::size_t b) {
    bool& flag = used[{std::min(a, b), std::max(a, b)}];
    const bool was = flag;
    flag = true;
    return !was;
  };
  std::vector<std::vector<std::size_t>> chains;
  auto walk = [&](std::size_t start, std::size_t next) {
    std::vector<std::size_t> chain{start};
    std::size_t previous = start, current = next;
    while(true) {
      chain.push_back(current);
      const auto& neighbors = around[current];
      if(neighbors.size() != 2 || current == start) break;
      const std::size_t following = neighbors[0] == previous ? neighbors[1] : neighbors[0];
      if(!take(current, following)) break;
      previous = current;
      current = following;
    }
    chains.push_back(std::move(chain));
  };
  for(const auto& entry : around) // open chains first: from the vertices of degree other than two
    if(entry.second.size() != 2)
      for(std::size_t next : entry.second)
        if(take(entry.first, next)) walk(entry.first, next);
  for(const auto& entry : around) // then the loops
    for(std::size_t next : entry.second)
      if(take(entry.first, next)) walk(entry.first, next);
  return chains;
}

/// the outline of the points `inliers` projected to the horizontal plane: the boundary of
/// their regularized alpha shape of radius `alpha`, simplified by Douglas-Peucker with
/// `tolerance`, as segments at least `minimum_length` long
template <class Kernel>
std::vector<typename Kernel::Segment_2> roof_outline_segments(const std::vector<typename Kernel::Point_3>& points,
                                                              const std::vector<std::size_t>& inliers, double alpha,
                                                              double tolerance, double minimum_length)
{
  using Point_2 = typename Kernel::Point_2;
  using Vb = CGAL::Alpha_shape_vertex_base_2<Kernel, CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Kernel>>;
  using Fb = CGAL::Alpha_shape_face_base_2<Kernel>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Alpha_shape = CGAL::Alpha_shape_2<CGAL::Delaunay_triangulation_2<Kernel, Tds>>;

  std::vector<Point_2> projected;
  for(std::size_t i : inliers) projected.emplace_back(points[i].x(), points[i].y());
  std::sort(projected.begin(), projected.end());
  projected.erase(std::unique(projected.begin(), projected.end()), projected.end());
  std::vector<typename Kernel::Segment_2> segments;
  if(projected.size() < 3) return segments;
  Alpha_shape shape(projected.begin(), projected.end(), typename Kernel::FT(alpha * alpha), Alpha_shape::REGULARIZED);
  for(auto v = shape.finite_vertices_begin(); v != shape.finite_vertices_end(); ++v)
    v->info() = std::size_t(std::lower_bound(projected.begin(), projected.end(), v->point()) - projected.begin());
  std::vector<std::array<std::size_t, 2>> edges;
  for(auto e = shape.alpha_shape_edges_begin(); e != shape.alpha_shape_edges_end(); ++e) {
    const auto f = e->first;
    const int i = e->second;
    edges.push_back({f->vertex(f->cw(i))->info(), f->vertex(f->ccw(i))->info()});
  }
  for(const auto& chain : boundary_chains(edges)) {
    std::vector<Point_2> polyline;
    for(std::size_t id : chain) polyline.push_back(projected[id]);
    std::vector<std::size_t> kept;
    if(chain.front() == chain.back() && polyline.size() > 3) {
      // a loop: split it at the point farthest from its start
      std::size_t far = 0;
      for(std::size_t i = 1; i < polyline.size(); ++i)
        if(CGAL::squared_distance(polyline[i], polyline[0]) > CGAL::squared_distance(polyline[far], polyline[0]))
          far = i;
      douglas_peucker(polyline, 0, far, tolerance, kept);
      kept.pop_back();
      douglas_peucker(polyline, far, polyline.size() - 1, tolerance, kept);
    } else {
      douglas_peucker(polyline, 0, polyline.size() - 1, tolerance, kept);
    }
    for(std::size_t k = 0; k + 1 < kept.size(); ++k) {
      const Point_2& p = polyline[kept[k]];
      const Point_2& q = polyline[kept[k + 1]];
      if(CGAL::to_double(CGAL::squared_distance(p, q)) >= minimum_length * minimum_length)
        segments.emplace_back(p, q);
    }
  }
  return segments;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_ROOF_OUTLINES_2_H
