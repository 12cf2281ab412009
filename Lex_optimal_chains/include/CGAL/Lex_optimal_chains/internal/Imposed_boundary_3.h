// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_IMPOSED_BOUNDARY_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_IMPOSED_BOUNDARY_3_H

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/assertions.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class Point>
std::string point_string(const Point& p)
{
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << " " << p.y() << " " << p.z() << ")";
  return s.str();
}

// Checks the boundary polylines: closed, finite, simple (no repeated vertex, no two
// segments meeting except consecutive ones at their common vertex), and near the points.
// Returns the polylines without their closing vertex.
template <class Kernel, class PolylineRange>
std::vector<std::vector<typename Kernel::Point_3>>
checked_polylines(const PolylineRange& polylines, const Bbox_3& points_box)
{
  using Point = typename Kernel::Point_3;
  using Segment = typename Kernel::Segment_3;
  std::vector<std::vector<Point>> result;
  for(const auto& polyline : polylines) {
    std::vector<Point> p(polyline.begin(), polyline.end());
    for(const Point& q : p)
      if(!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()))
        throw Input_error(Input_error_code::NON_FINITE_COORDINATE, "a boundary vertex has a NaN or infinite coordinate");
    if(p.size() < 2 || p.front() != p.back())
      throw Input_error(Input_error_code::OPEN_POLYLINE,
                        "boundary polyline " + std::to_string(result.size()) + " is not closed: its last vertex must repeat its first");
    p.pop_back();
    if(p.size() < 3)
      throw Input_error(Input_error_code::SELF_INTERSECTING_BOUNDARY,
                        "boundary polyline " + std::to_string(result.size()) + " has fewer than 3 vertices");
    result.push_back(std::move(p));
  }
  if(result.empty()) throw Input_error(Input_error_code::BOUNDARY_NOT_A_CYCLE, "no boundary polyline");

  // repeated vertices
  std::vector<Point> all;
  for(const auto& p : result) all.insert(all.end(), p.begin(), p.end());
  std::sort(all.begin(), all.end());
  const auto repeated = std::adjacent_find(all.begin(), all.end());
  if(repeated != all.end())
    throw Input_error(Input_error_code::SELF_INTERSECTING_BOUNDARY,
                      "the boundary passes twice through the vertex " + point_string(*repeated));

  // crossing segments: boxes first, then exact predicates
  struct Segment_id { std::size_t polyline, index; };
  using Box = Box_intersection_d::Box_with_info_d<double, 3, Segment_id>;
  std::vector<Box> boxes;
  for(std::size_t l = 0; l < result.size(); ++l)
    for(std::size_t i = 0; i < result[l].size(); ++i) {
      const Point& a = result[l][i];
      const Point& b = result[l][(i + 1) % result[l].size()];
      boxes.emplace_back(a.bbox() + b.bbox(), Segment_id{l, i});
    }
  auto segment = [&](const Segment_id& s) {
    return Segment(result[s.polyline][s.index], result[s.polyline][(s.index + 1) % result[s.polyline].size()]);
  };
  box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    const Segment_id s = x.info(), t = y.info();
    const std::size_t n = result[s.polyline].size();
    const bool consecutive = s.polyline == t.polyline && ((s.index + 1) % n == t.index || (t.index + 1) % n == s.index);
    bool crossing;
    if(consecutive && n > 3) {
      // they share a vertex b; they overlap iff the polyline turns back there
      const Segment_id first = (s.index + 1) % n == t.index ? s : t;
      const Point& a = result[first.polyline][first.index];
      const Point& b = result[first.polyline][(first.index + 1) % n];
      const Point& c = result[first.polyline][(first.index + 2) % n];
      crossing = collinear(a, b, c) && angle(a, b, c) == ACUTE;
    } else if(consecutive) { // a triangle: all its edges are consecutive
      const Point& a = result[s.polyline][0];
      const Point& b = result[s.polyline][1];
      const Point& c = result[s.polyline][2];
      crossing = collinear(a, b, c);
    } else {
      crossing = do_intersect(segment(s), segment(t));
    }
    if(crossing)
      throw Input_error(Input_error_code::SELF_INTERSECTING_BOUNDARY,
                        "boundary segments " + point_string(segment(s).source()) + " - " + point_string(segment(s).target()) +
                        " and " + point_string(segment(t).source()) + " - " + point_string(segment(t).target()) + " intersect");
  });

  // far from the points: farther from their bounding box than its diagonal
  const double diagonal = std::sqrt(square(points_box.xmax() - points_box.xmin()) + square(points_box.ymax() - points_box.ymin()) +
                                    square(points_box.zmax() - points_box.zmin()));
  for(const auto& p : result) {
    Bbox_3 box;
    for(const Point& q : p) box += q.bbox();
    double gap2 = 0;
    for(int d = 0; d < 3; ++d) {
      const double g = (std::max)({0.0, box.min(d) - points_box.max(d), points_box.min(d) - box.max(d)});
      gap2 += g * g;
    }
    if(std::sqrt(gap2) > diagonal)
      throw Input_error(Input_error_code::BOUNDARY_FAR_FROM_POINTS,
                        "a boundary polyline is " + std::to_string(std::sqrt(gap2)) +
                        " away from the bounding box of the points, more than its diagonal " + std::to_string(diagonal));
  }
  return result;
}

// Inserts the boundary vertices, makes sure that the boundary edges are edges of `dt`
// (removing the input points in the diametral balls of the missing ones if `remove` is set)
// and returns the cycle as oriented vertex pairs. `boundary_only` receives the boundary
// vertices that were not vertices of `dt`, `removed` the points of the vertices removed.
template <class Triangulation, class Point>
std::vector<std::pair<typename Triangulation::Vertex_handle, typename Triangulation::Vertex_handle>>
insert_boundary(Triangulation& dt, const std::vector<std::vector<Point>>& polylines, bool remove,
                std::set<typename Triangulation::Vertex_handle>& boundary_only, std::vector<Point>& removed)
{
  using Vertex_handle = typename Triangulation::Vertex_handle;
  std::set<Point> boundary_points;
  for(const auto& p : polylines) {
    for(const Point& q : p) {
      boundary_points.insert(q);
      typename Triangulation::Locate_type lt;
      int li, lj;
      const auto c = dt.locate(q, lt, li, lj);
      if(lt == Triangulation::VERTEX) continue;
      boundary_only.insert(dt.insert(q, lt, c, li, lj));
    }
  }
  auto handle = [&](const Point& q) {
    typename Triangulation::Locate_type lt;
    int li, lj;
    const auto c = dt.locate(q, lt, li, lj);
    CGAL_assertion(lt == Triangulation::VERTEX);
    return c->vertex(li);
  };
  // the handles of the boundary-only vertices are stable: only input points are removed
  using Traits = Search_traits_3<typename Kernel_traits<Point>::Kernel>;
  std::unique_ptr<Kd_tree<Traits>> tree;
  for(;;) {
    std::vector<std::pair<Vertex_handle, Vertex_handle>> cycle;
    std::vector<std::pair<Point, Point>> missing;
    for(const auto& p : polylines)
      for(std::size_t i = 0; i < p.size(); ++i) {
        const Vertex_handle u = handle(p[i]), v = handle(p[(i + 1) % p.size()]);
        typename Triangulation::Cell_handle c;
        int a, b;
        if(dt.is_edge(u, v, c, a, b)) cycle.emplace_back(u, v);
        else missing.emplace_back(p[i], p[(i + 1) % p.size()]);
      }
    if(missing.empty()) return cycle;
    const std::string which = "the boundary edge " + point_string(missing.front().first) + " - " +
                              point_string(missing.front().second) + " (and " + std::to_string(missing.size() - 1) +
                              " other) is not an edge of the Delaunay triangulation";
    if(!remove)
      throw Input_error(Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION,
                        which + "; the input points near the boundary can be removed (remove_blocking_points)");
    if(!tree) {
      tree.reset(new Kd_tree<Traits>());
      for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        if(!boundary_points.count(v->point())) tree->insert(v->point());
      tree->build();
    }
    // the closed diametral ball of a missing edge holds the points that keep it out: once
    // it is empty the edge is Gabriel, hence Delaunay
    const std::size_t before = removed.size();
    for(const auto& e : missing) {
      const Point center = midpoint(e.first, e.second);
      const double radius = std::sqrt(squared_distance(e.first, e.second)) / 2;
      std::vector<Point> inside;
      tree->search(std::back_inserter(inside), Fuzzy_sphere<Traits>(center, radius * (1 + 1e-12) + 1e-300, 0.));
      for(const Point& q : inside) {
        typename Triangulation::Locate_type lt;
        int li, lj;
        const auto c = dt.locate(q, lt, li, lj);
        if(lt != Triangulation::VERTEX) continue; // already removed
        dt.remove(c->vertex(li));
        removed.push_back(q);
      }
    }
    if(removed.size() == before)
      throw Input_error(Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION,
                        which + ", and no input point blocks it: other boundary vertices do");
  }
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_IMPOSED_BOUNDARY_3_H
