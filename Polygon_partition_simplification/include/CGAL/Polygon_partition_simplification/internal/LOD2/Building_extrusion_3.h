// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_EXTRUSION_3_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_EXTRUSION_3_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_surface_type.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/Cell_arrangement_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/Height_functions.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/triangulate_rings_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Union_find.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The polygons of one building: roofs, walls and floor, with shared corners.
struct Building_soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<Building_surface_type> types; ///< per polygon
  std::vector<std::size_t> labels;          ///< per polygon: its roof label, the ground label otherwise
};

/// Extrusion of a labeled partition into one closed polygon soup per building.
///
/// Cells of the same label are merged into regions (their common edges removed); points of a
/// region boundary where two collinear edges meet and nothing else are dropped. A building is a
/// set of non-ground regions connected through edges. At each point of the partition, the
/// heights of the labels around it are sorted and those closer than `height_tolerance` made one
/// corner (so that two roofs meeting along a ridge get no wall). Every region gets its roof
/// polygon, every edge between two labels a wall between their heights (through every corner of
/// the point between them, so that walls, roofs and floors share their edges), split where the
/// two roofs cross; every building a floor on the ground. Regions with holes, or whose
/// boundary passes twice through a point, are triangulated. Polygons are oriented outward.
class Building_extrusion_3
{
  using Arrangement = Cell_arrangement_2::Arrangement;
  using Halfedge = Arrangement::Halfedge_const_handle;
  using Point_2 = Cell_arrangement_2::Point_2;
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

public:
  Building_extrusion_3(const Cell_arrangement_2& cells, const std::vector<std::size_t>& cell_labels,
                       const Height_functions& heights, double height_tolerance)
    : heights_(heights), tolerance_(height_tolerance), regions_(cells.arrangement)
  {
    merge_cells_into_regions(cell_labels);
    find_kept_points();
    find_buildings();
    for(std::size_t b = 0; b < number_of_buildings_; ++b) buildings_.emplace_back();
    for(auto f = regions_.faces_begin(); f != regions_.faces_end(); ++f)
      if(label_of(f) != Height_functions::ground_label) extrude_region(f);
    std::set<Halfedge> walked; // the footprint halfedges already in a ring
    for(auto h = regions_.halfedges_begin(); h != regions_.halfedges_end(); ++h)
      if(building_of(h->face()) != none && label_of(h->twin()->face()) == Height_functions::ground_label &&
         point_index_.count(h->source()->point()) > 0 && walked.count(h) == 0)
        add_floor_ring(h, walked);
    for(std::size_t b = 0; b < number_of_buildings_; ++b) add_floor(b);
  }

  /// the soups, one per building, in a deterministic order
  std::vector<Building_soup> take_buildings() { return std::move(buildings_); }

private:
  // ---- regions ----------------------------------------------------------------------------
  void merge_cells_into_regions(const std::vector<std::size_t>& cell_labels)
  {
    for(auto f = regions_.faces_begin(); f != regions_.faces_end(); ++f)
      f->set_data(f->data() == Cell_arrangement_2::no_cell ? Height_functions::ground_label : cell_labels[f->data()]);
    std::vector<Arrangement::Halfedge_handle> merged;
    for(auto e = regions_.edges_begin(); e != regions_.edges_end(); ++e)
      if(e->face()->data() == e->twin()->face()->data()) merged.push_back(e);
    for(auto e : merged) regions_.remove_edge(e, false, false);
    std::size_t index = 0;
    for(auto f = regions_.faces_begin(); f != regions_.faces_end(); ++f, ++index) {
      region_label_.push_back(f->data());
      f->set_data(index);
    }
  }

  std::size_t label_of(Arrangement::Face_const_handle f) const { return region_label_[f->data()]; }
  std::size_t building_of(Arrangement::Face_const_handle f) const { return region_building_[f->data()]; }

  // a point is dropped when it joins two collinear edges and nothing else
  void find_kept_points()
  {
    for(auto v = regions_.vertices_begin(); v != regions_.vertices_end(); ++v) {
      if(v->is_isolated()) continue;
      bool kept = v->degree() != 2;
      if(!kept) { // the two edges at v: kept unless they are collinear
        const auto h = v->incident_halfedges();
        kept = CGAL::orientation(h->source()->point(), v->point(), std::next(h)->source()->point()) != CGAL::COLLINEAR;
      }
      if(kept) {
        const std::size_t index = kept_points_.size();
        kept_points_.push_back(v);
        point_index_[v->point()] = index;
      }
    }
    corners_.resize(kept_points_.size());
    for(std::size_t i = 0; i < kept_points_.size(); ++i) make_corners(i);
  }

  // the corners at point `i`: the heights of the labels around it, sorted, those closer than
  // the tolerance made one (at their mean)
  void make_corners(std::size_t i)
  {
    std::vector<std::pair<double, std::size_t>> heights; // (height, label)
    const std::array<double, 2> xy{{kept_points_[i]->point().x(), kept_points_[i]->point().y()}};
    auto h = kept_points_[i]->incident_halfedges(), start = h;
    do {
      const std::size_t label = label_of(h->face());
      heights.push_back({heights_.height(label, xy), label});
    } while(++h != start);
    std::sort(heights.begin(), heights.end());
    heights.erase(std::unique(heights.begin(), heights.end()), heights.end());
    Point_corners& corners = corners_[i];
    std::size_t first = 0;
    for(std::size_t k = 1; k <= heights.size(); ++k) {
      if(k < heights.size() && heights[k].first - heights[k - 1].first <= tolerance_) continue;
      double sum = 0;
      for(std::size_t j = first; j < k; ++j) sum += heights[j].first;
      corners.heights.push_back(sum / double(k - first));
      for(std::size_t j = first; j < k; ++j) corners.corner_of_label[heights[j].second] = corners.heights.size() - 1;
      first = k;
    }
  }

  void find_buildings()
  {
    Union_find<> regions(region_label_.size());
    for(auto e = regions_.edges_begin(); e != regions_.edges_end(); ++e)
      if(label_of(e->face()) != Height_functions::ground_label &&
         label_of(e->twin()->face()) != Height_functions::ground_label)
        regions.unite(e->face()->data(), e->twin()->face()->data());
    region_building_.assign(region_label_.size(), none);
    std::map<std::size_t, std::size_t> building_of_root;
    for(std::size_t r = 0; r < region_label_.size(); ++r) {
      if(region_label_[r] == Height_functions::ground_label) continue;
      const auto inserted = building_of_root.insert({regions.find(r), building_of_root.size()});
      region_building_[r] = inserted.first->second;
    }
    number_of_buildings_ = building_of_root.size();
  }

  // ---- corners and soup points --------------------------------------------------------------
  struct Point_corners
  {
    std::vector<double> heights;                   // increasing
    std::map<std::size_t, std::size_t> corner_of_label;
    std::map<std::size_t, std::size_t> soup_id;    // per building: corner -> id, as building * size + corner
  };

  std::size_t kept_index(Arrangement::Vertex_const_handle v) const { return point_index_.at(v->point()); }

  std::size_t corner(std::size_t point, std::size_t label) const { return corners_[point].corner_of_label.at(label); }

  std::size_t soup_point(std::size_t building, std::size_t point, std::size_t corner_index)
  {
    Point_corners& corners = corners_[point];
    const std::size_t key = building * corners.heights.size() + corner_index;
    const auto found = corners.soup_id.find(key);
    if(found != corners.soup_id.end()) return found->second;
    Building_soup& soup = buildings_[building];
    const auto& p = kept_points_[point]->point();
    soup.points.push_back({{p.x(), p.y(), corners.heights[corner_index]}});
    corners.soup_id[key] = soup.points.size() - 1;
    return soup.points.size() - 1;
  }

  // the halfedge after `h` along its face that ends at a kept point (a reduced edge runs from
  // `h`'s source to that halfedge's target)
  Halfedge reduced_edge_end(Halfedge h) const
  {
    while(point_index_.find(h->target()->point()) == point_index_.end()) h = h->next();
    return h;
  }

  // the point where the heights of the two labels of a reduced edge cross, if they do
  std::size_t crossing(std::size_t building, std::size_t a, std::size_t b, std::size_t label_a, std::size_t label_b)
  {
    const double da = corners_[a].heights[corner(a, label_a)] - corners_[a].heights[corner(a, label_b)];
    const double db = corners_[b].heights[corner(b, label_a)] - corners_[b].heights[corner(b, label_b)];
    if(!((da > 0 && db < 0) || (da < 0 && db > 0))) return none;
    const auto key = std::make_tuple(building, std::min(a, b), std::max(a, b));
    const auto found = crossings_.find(key);
    if(found != crossings_.end()) return found->second;
    const double t = da / (da - db);
    const auto& pa = kept_points_[a]->point();
    const auto& pb = kept_points_[b]->point();
    const double za = corners_[a].heights[corner(a, label_a)], zb = corners_[b].heights[corner(b, label_a)];
    Building_soup& soup = buildings_[building];
    soup.points.push_back({{pa.x() + t * (pb.x() - pa.x()), pa.y() + t * (pb.y() - pa.y()), za + t * (zb - za)}});
    crossings_[key] = soup.points.size() - 1;
    return soup.points.size() - 1;
  }

  // ---- roofs and walls ------------------------------------------------------------------------
  void extrude_region(Arrangement::Face_const_handle f)
  {
    const std::size_t building = building_of(f);
    std::vector<std::vector<Ring_corner>> rings;
    rings.push_back(region_ring(f->outer_ccb(), f));
    for(auto hole = f->holes_begin(); hole != f->holes_end(); ++hole) rings.push_back(region_ring(*hole, f));
    add_horizontal_face(building, rings, Building_surface_type::ROOF, label_of(f), false);
  }

  template <class Circulator>
  std::vector<Ring_corner> region_ring(Circulator start, Arrangement::Face_const_handle f)
  {
    const std::size_t building = building_of(f), label = label_of(f);
    Halfedge h = start;
    while(point_index_.find(h->source()->point()) == point_index_.end()) h = h->next();
    const Halfedge first = h;
    std::vector<Ring_corner> ring;
    do {
      const Halfedge last = reduced_edge_end(h);
      const std::size_t a = kept_index(h->source()), b = kept_index(last->target());
      const std::size_t other = label_of(h->twin()->face());
      const auto& p = h->source()->point();
      ring.push_back({soup_point(building, a, corner(a, label)), p.x(), p.y()});
      const std::size_t x = crossing(building, a, b, label, other);
      if(x != none) ring.push_back({x, buildings_[building].points[x][0], buildings_[building].points[x][1]});
      const bool other_side_walks = other != Height_functions::ground_label;
      if(!other_side_walks || f->data() < h->twin()->face()->data()) add_wall(building, a, b, label, other, x);
      h = last->next();
    } while(h != first);
    return ring;
  }

  // the corners at `point` from the height of label `from` to that of label `to`, both included
  std::vector<std::size_t> column(std::size_t building, std::size_t point, std::size_t from, std::size_t to)
  {
    const std::size_t c0 = corner(point, from), c1 = corner(point, to);
    std::vector<std::size_t> ids;
    if(c0 <= c1) for(std::size_t c = c0; c <= c1; ++c) ids.push_back(soup_point(building, point, c));
    else for(std::size_t c = c0 + 1; c-- > c1;) ids.push_back(soup_point(building, point, c));
    return ids;
  }

  // the wall along the reduced edge a -> b between label `left` (on its left) and `right`,
  // split at the crossing `x` (or `none`); outward toward the lower side
  void add_wall(std::size_t building, std::size_t a, std::size_t b, std::size_t left, std::size_t right, std::size_t x)
  {
    const std::vector<std::size_t> column_a = column(building, a, right, left);
    const std::vector<std::size_t> column_b = column(building, b, right, left);
    const double da = corners_[a].heights[corner(a, left)] - corners_[a].heights[corner(a, right)];
    const double db = corners_[b].heights[corner(b, left)] - corners_[b].heights[corner(b, right)];
    if(x == none) {
      add_wall_piece(building, column_a, column_b, da != 0 ? da > 0 : db > 0);
    } else {
      add_wall_piece(building, column_a, {x}, da > 0);
      add_wall_piece(building, {x}, column_b, db > 0);
    }
  }

  // a wall piece between two columns (from the right label's corner to the left label's one),
  // P before Q along the edge; `left_higher`: the left side is inside, the normal goes right
  void add_wall_piece(std::size_t building, const std::vector<std::size_t>& p, const std::vector<std::size_t>& q,
                      bool left_higher)
  {
    if(p.size() == 1 && q.size() == 1) return;
    std::vector<std::size_t> polygon;
    if(left_higher) { // P_right, Q_right .. Q_left, P_left .. (above P_right)
      polygon.push_back(p.front());
      polygon.insert(polygon.end(), q.begin(), q.end());
      polygon.insert(polygon.end(), p.rbegin(), std::prev(p.rend()));
    } else { // Q_left, P_left .. P_right, Q_right .. (below Q_left)
      polygon.push_back(q.back());
      polygon.insert(polygon.end(), p.rbegin(), p.rend());
      polygon.insert(polygon.end(), q.begin(), std::prev(q.end()));
    }
    Building_soup& soup = buildings_[building];
    soup.polygons.push_back(std::move(polygon));
    soup.types.push_back(Building_surface_type::WALL);
    soup.labels.push_back(Height_functions::ground_label);
  }

  // a roof (counterclockwise seen from above) or a floor (clockwise): one polygon, or triangles
  // when there are holes or a ring passes twice through a point
  void add_horizontal_face(std::size_t building, const std::vector<std::vector<Ring_corner>>& rings,
                           Building_surface_type type, std::size_t label, bool downward)
  {
    Building_soup& soup = buildings_[building];
    std::vector<std::vector<std::size_t>> polygons;
    bool simple = rings.size() == 1;
    if(simple) {
      std::vector<std::size_t> ids;
      for(const Ring_corner& c : rings.front()) ids.push_back(c.id);
      std::vector<std::size_t> sorted = ids;
      std::sort(sorted.begin(), sorted.end());
      simple = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
      if(simple) polygons.push_back(std::move(ids));
    }
    if(!simple)
      for(const auto& t : triangulate_rings(rings)) polygons.push_back({t[0], t[1], t[2]});
    for(auto& polygon : polygons) {
      if(downward) std::reverse(polygon.begin(), polygon.end());
      soup.polygons.push_back(std::move(polygon));
      soup.types.push_back(type);
      soup.labels.push_back(label);
    }
  }

  // ---- floors ----------------------------------------------------------------------------------
  // the footprint boundary: halfedges with the building on the left and the ground on the
  // right; around a point, the next one is found by turning inside the building
  Halfedge next_on_footprint(Halfedge h) const
  {
    const std::size_t building = building_of(h->face());
    Halfedge next = h->next();
    while(building_of(next->twin()->face()) == building) next = next->twin()->next();
    return next;
  }

  void add_floor_ring(Halfedge first, std::set<Halfedge>& walked)
  {
    const std::size_t building = building_of(first->face());
    std::vector<Ring_corner> ring;
    Halfedge h = first;
    do {
      if(point_index_.find(h->source()->point()) != point_index_.end()) {
        const std::size_t a = kept_index(h->source());
        const auto& p = h->source()->point();
        ring.push_back({soup_point(building, a, corner(a, Height_functions::ground_label)), p.x(), p.y()});
      }
      walked.insert(h);
      h = next_on_footprint(h);
    } while(h != first);
    floor_rings_[building].push_back(std::move(ring));
  }

  void add_floor(std::size_t building)
  {
    add_horizontal_face(building, floor_rings_[building], Building_surface_type::GROUND, Height_functions::ground_label,
                        true);
  }

  const Height_functions& heights_;
  double tolerance_;
  Arrangement regions_;
  std::vector<std::size_t> region_label_, region_building_;
  std::size_t number_of_buildings_ = 0;
  std::vector<Arrangement::Vertex_const_handle> kept_points_;
  std::map<Point_2, std::size_t> point_index_;
  std::vector<Point_corners> corners_;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::size_t> crossings_;
  std::map<std::size_t, std::vector<std::vector<Ring_corner>>> floor_rings_;
  std::vector<Building_soup> buildings_;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_EXTRUSION_3_H
