// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_CELL_ARRANGEMENT_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_CELL_ARRANGEMENT_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>

#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_batched_point_location.h>
#include <CGAL/Arr_non_caching_segment_basic_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The cells of a partition as the faces of a CGAL arrangement, each face knowing its cell.
/// The points of the cells are doubles and their edges do not cross, so the arrangement needs
/// exact predicates only, which Epick's filtered predicates give on the doubles.
struct Cell_arrangement_2
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point_2 = Kernel::Point_2;
  using Traits = CGAL::Arr_non_caching_segment_basic_traits_2<Kernel>;
  /// face data: the cell of the face, `no_cell` for the unbounded face
  using Dcel = CGAL::Arr_face_extended_dcel<Traits, std::size_t>;
  using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;
  static constexpr std::size_t no_cell = std::numeric_limits<std::size_t>::max();

  Arrangement arrangement;
  std::vector<std::vector<std::vector<Point_2>>> rings; ///< per cell: outer ring (counterclockwise), holes (clockwise)

  /// the arrangement of `cells` (polygons with holes of any CGAL kernel, the cells of a valid
  /// partition: they meet only along their edges)
  template <class PolygonWithHolesRange>
  explicit Cell_arrangement_2(const PolygonWithHolesRange& cells)
  {
    std::map<std::pair<Point_2, Point_2>, std::size_t> cell_left_of;
    std::vector<Traits::X_monotone_curve_2> segments;
    auto add_ring = [&](const auto& polygon, std::size_t cell, bool reverse) {
      std::vector<Point_2> ring;
      for(auto p = polygon.vertices_begin(); p != polygon.vertices_end(); ++p)
        ring.emplace_back(CGAL::to_double(p->x()), CGAL::to_double(p->y()));
      if(reverse) std::reverse(ring.begin(), ring.end());
      for(std::size_t i = 0; i < ring.size(); ++i) {
        const Point_2& a = ring[i];
        const Point_2& b = ring[(i + 1) % ring.size()];
        cell_left_of[{a, b}] = cell;
        if(cell_left_of.find({b, a}) == cell_left_of.end()) segments.emplace_back(a, b);
      }
      rings.back().push_back(std::move(ring));
    };
    std::size_t cell = 0;
    for(const auto& polygon : cells) {
      rings.emplace_back();
      const bool outer_clockwise = polygon.outer_boundary().orientation() == CGAL::CLOCKWISE;
      add_ring(polygon.outer_boundary(), cell, outer_clockwise);
      for(auto h = polygon.holes_begin(); h != polygon.holes_end(); ++h)
        add_ring(*h, cell, h->orientation() == CGAL::COUNTERCLOCKWISE);
      ++cell;
    }
    CGAL::insert_non_intersecting_curves(arrangement, segments.begin(), segments.end());
    for(auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) f->set_data(no_cell);
    for(auto h = arrangement.halfedges_begin(); h != arrangement.halfedges_end(); ++h) {
      const auto found = cell_left_of.find({h->source()->point(), h->target()->point()});
      if(found != cell_left_of.end()) h->face()->set_data(found->second);
    }
  }

  std::size_t number_of_cells() const { return rings.size(); }

  /// the cell of each point (x, y, z) of `points`, `no_cell` outside every cell; a point on an edge
  /// or a vertex goes to a cell incident to it (the face of the edge's halfedge directed from
  /// the smaller endpoint, the first cell found around the vertex). The points are located by
  /// plane sweeps (CGAL's batched point location) of max(8192, m) points at a time for m edges,
  /// which cost O((n + m) log(n + m)) in all for n points and use memory in O(m); a walk from
  /// the nearest landmark per point cost more on points near the edges, as the samples of the
  /// facades are.
  std::vector<std::size_t> locate(const std::vector<std::array<double, 3>>& points) const
  {
    using Location = typename CGAL::Arr_point_location_result<Arrangement>::Type;
    using Located = std::pair<Point_2, Location>;
    auto by_point = [](const Located& a, const Located& b) { return a.first < b.first; };
    // in chunks, so that the memory of the sweep is bounded whatever the number of points
    const std::size_t chunk = std::max<std::size_t>(1 << 13, arrangement.number_of_edges());
    std::vector<Point_2> queries;
    std::vector<Located> located;
    std::vector<std::size_t> result;
    result.reserve(points.size());
    for(std::size_t first = 0; first < points.size(); first += chunk) {
      const std::size_t last = std::min(points.size(), first + chunk);
      queries.clear();
      for(std::size_t i = first; i < last; ++i) queries.emplace_back(points[i][0], points[i][1]);
      located.clear();
      CGAL::locate(arrangement, queries.begin(), queries.end(), std::back_inserter(located));
      std::sort(located.begin(), located.end(), by_point);
      for(const Point_2& q : queries) {
        const auto found = std::lower_bound(located.begin(), located.end(), std::make_pair(q, Location()), by_point);
        result.push_back(found != located.end() && found->first == q ? cell_at(found->second) : no_cell);
      }
    }
    return result;
  }

private:
  template <class Location>
  static std::size_t cell_at(const Location& where)
  {
    if(const auto* face = get_if<typename Arrangement::Face_const_handle>(where)) return (*face)->data();
    if(const auto* edge = get_if<typename Arrangement::Halfedge_const_handle>(where)) {
      auto h = *edge;
      if(h->source()->point() > h->target()->point()) h = h->twin();
      return h->face()->data() != no_cell ? h->face()->data() : h->twin()->face()->data();
    }
    if(const auto* vertex = get_if<typename Arrangement::Vertex_const_handle>(where)) {
      if((*vertex)->is_isolated()) return no_cell;
      auto around = (*vertex)->incident_halfedges(), start = around;
      do {
        if(around->face()->data() != no_cell) return around->face()->data();
      } while(++around != start);
    }
    return no_cell;
  }
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_CELL_ARRANGEMENT_2_H
