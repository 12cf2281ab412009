// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SPLIT_PINCHED_CELLS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SPLIT_PINCHED_CELLS_2_H

// Ends that meet at time 0 stop each other in the kinetic propagation, so that corners stay
// corners. A closed chain of such corners that touches the rest of the partition at a single
// point O (an "X" whose two lower ends are joined by a third segment: the triangle hangs at the
// crossing; two squares sharing a corner), or hangs on it by a single edge (a bridge, which the
// walk passes out and back: it arrives twice at the bridge's end O on the chain), leaves a face
// of the exact arrangement whose boundary walk passes twice through O: a cell that is not a
// simple polygon. Such a face is split by
// construction, in the arrangement, before the partition is read from it: one of the ends
// stopped at a corner of the walk goes on from its corner, straight into the face, to the
// first point of the face's boundary (as if it grew after every other end had stopped). The
// piece it adds is on the line of its segment.
//
// Why one such piece suffices: the walk is O, L1, O, L2 (two loops through O). A piece from a
// point of L1 to a point of L2 other than O splits the face into two faces whose walks pass once
// through O. At a vertex of the convex hull of a loop's block (the part of the partition the loop
// goes around), every extent ends (an extent through it would leave the hull), and the first of
// them to reach it is a segment's end stopped there at time 0; the end goes on away from its
// segment, out of the hull, which it never enters again, so it reaches L2 or another boundary of
// the face (a hole). The ends are tried in the order of the segments (which is canonical): the
// first that reaches the other loop is taken, or else the first that reaches a hole (the hole
// then joins the walk, and the next piece splits it); the faces are searched again after each
// piece.
//
// The partition's points are rounded to doubles afterwards, and points that come closer than
// the rounding's tolerance merge, or go onto an edge they nearly touch (merge_rounded_points_2.h).
// A walk that passes two vertices that merge, or a vertex and an edge that it goes onto, is
// pinched after the rounding: such vertices are grouped (Vertex_groups), and a passage along
// such an edge counts as a passage through the vertex's group (passages_along_edges()). A piece
// may then start at a vertex of the group (crossing the gap that the rounding closes, it
// collapses with it); a piece from elsewhere may not end in the group.

#include <CGAL/Polygon_partition_simplification/internal/Piece_arrangement_2.h>
#include <CGAL/Polygon_partition_simplification/internal/merge_rounded_points_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Union_find.h>

#include <CGAL/Kernel/global_functions_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// A growing end that stopped at its origin at time 0 (a corner): from `origin` along
// `direction`, on the line of the piece `piece` (the extent of its segment).
template <class EK>
struct Corner_ray
{
  typename EK::Point_2 origin;
  typename EK::Vector_2 direction;
  std::size_t piece;
};

// Where the partition's points are: the normalized frame of build_line_partition() and the
// tolerance below which round_points_apart() merges two points (merge_rounded_points_2.h).
struct Point_rounding
{
  double center_x = 0, center_y = 0, scale = 1, tolerance = 0;
  // the double coordinates of `p` in the normalized frame
  template <class Point>
  std::array<double, 2> operator()(const Point& p) const
  {
    return {(CGAL::to_double(p.x()) - center_x) / scale, (CGAL::to_double(p.y()) - center_y) / scale};
  }
  // could the rounding merge points at `p` and `q` (twice the tolerance, in each coordinate)?
  bool may_merge(const std::array<double, 2>& p, const std::array<double, 2>& q) const
  {
    return std::abs(p[0] - q[0]) <= 2 * tolerance && std::abs(p[1] - q[1]) <= 2 * tolerance;
  }
};

// The vertices of an arrangement in groups that the rounding may merge into one point: those
// that may_merge() pairs, transitively. A walk that passes through two vertices of one group
// (not joined by an edge of the walk) is pinched once the group is one point, as a walk that
// passes twice through one vertex is.
template <class EK>
class Vertex_groups
{
public:
  using Vertex = typename Piece_arrangement<EK>::Vertex_const_handle;
  Vertex_groups(const Piece_arrangement<EK>& arrangement, const Point_rounding& rounding)
  {
    std::vector<std::array<double, 2>> position;
    for(auto v = arrangement.vertices_begin(); v != arrangement.vertices_end(); ++v) {
      index_.emplace(&*v, position.size());
      position.push_back(rounding(v->point()));
    }
    const std::size_t n = position.size();
    std::vector<std::size_t> by_x(n);
    for(std::size_t v = 0; v < n; ++v) by_x[v] = v;
    std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return position[a] < position[b]; });
    Union_find<std::size_t> sets(n);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 1; j < n && position[by_x[j]][0] - position[by_x[i]][0] <= 2 * rounding.tolerance; ++j)
        if(rounding.may_merge(position[by_x[i]], position[by_x[j]])) sets.unite_at_smallest(by_x[i], by_x[j]);
    group_.resize(n);
    for(std::size_t v = 0; v < n; ++v) group_[v] = sets.find(v);
  }
  std::size_t operator()(Vertex v) const { return group_[index_.at(&*v)]; }

private:
  std::unordered_map<const void*, std::size_t> index_; // by the address of the vertex
  std::vector<std::size_t> group_;
};

// A boundary walk (a connected component of the boundary of a bounded face) that passes twice
// through a group of vertices: its half-edges in order, and the positions of the two half-edges
// that arrive at the group. The half-edges from `first` + 1 to `second` form the loop L2.
template <class EK>
struct Pinched_walk
{
  typename Piece_arrangement<EK>::Face_const_handle face;
  std::vector<typename Piece_arrangement<EK>::Halfedge_const_handle> walk;
  std::size_t first = 0, second = 0;
  std::size_t component = 0; // 0: the face's outer boundary, k: its k-th hole
  std::vector<std::size_t> pinches; // the groups passed twice or more
  std::vector<std::array<double, 2>> pinch_points; // the points of their vertices, normalized
  std::vector<typename Piece_arrangement<EK>::Vertex_const_handle> passed_twice; // vertices arrived at twice
};

// Appends to `arrivals` (group, position) the passages of `walk` (of `face`) along an edge that
// comes within the rounding's reach of a vertex of the walk that it does not join: the
// rounding puts that vertex on the edge (merge_rounded_points_2.h), and the walk then passes
// there a second time. The vertices are sorted by x, and each edge looks only at those within
// its x range.
template <class EK, class Halfedge, class Groups>
void passages_along_edges(const std::vector<Halfedge>& walk, typename Piece_arrangement<EK>::Face_const_handle face,
                          const Groups& group, const Point_rounding& rounding,
                          std::vector<std::pair<std::size_t, std::size_t>>& arrivals)
{
  const double reach = 2 * rounding.tolerance;
  std::vector<std::pair<std::array<double, 2>, std::size_t>> points; // position, walk position
  for(std::size_t k = 0; k < walk.size(); ++k) points.push_back({rounding(walk[k]->target()->point()), k});
  std::sort(points.begin(), points.end());
  for(std::size_t k = 0; k < walk.size(); ++k) {
    const auto& h = walk[k];
    if(h->twin()->face() == face) continue;
    const std::array<double, 2> s = rounding(h->source()->point()), t = rounding(h->target()->point());
    const std::array<double, 2> low{std::min(s[0], t[0]) - reach, -HUGE_VAL};
    for(auto it = std::lower_bound(points.begin(), points.end(), std::make_pair(low, std::size_t(0)));
        it != points.end() && it->first[0] <= std::max(s[0], t[0]) + reach; ++it) {
      const auto& p = it->first;
      if(p[1] < std::min(s[1], t[1]) - reach || p[1] > std::max(s[1], t[1]) + reach) continue;
      const auto v = walk[it->second]->target();
      const std::size_t g = group(v);
      if(g == group(h->source()) || g == group(h->target())) continue;
      if(parameter_near_segment(p, s, t, reach, 0)) arrivals.push_back({g, k});
    }
  }
}

// The half-edges (by address) of the antennas of `arrangement`: the trees that hang from the
// rest of its edges, found by removing the vertices of degree 1 until none is left. An edge with
// the same face on both sides that is not in an antenna is a bridge between two parts with
// cycles (a closed chain of corners that hangs on the rest by an edge): the cell is not a simple
// polygon and the bridge, a piece of an input segment, would be dropped with it.
template <class EK>
std::unordered_set<const void*> antenna_halfedges(const Piece_arrangement<EK>& arrangement)
{
  std::unordered_map<const void*, std::size_t> degree;
  std::vector<typename Piece_arrangement<EK>::Vertex_const_handle> leaves;
  for(auto v = arrangement.vertices_begin(); v != arrangement.vertices_end(); ++v) {
    degree[&*v] = v->degree();
    if(v->degree() == 1) leaves.push_back(v);
  }
  std::unordered_set<const void*> result;
  while(!leaves.empty()) {
    const auto v = leaves.back();
    leaves.pop_back();
    auto h = v->incident_halfedges(); // halfedges into v
    const auto first = h;
    do {
      if(!result.count(&*h)) {
        result.insert(&*h);
        result.insert(&*h->twin());
        const auto u = h->source();
        if(--degree[&*u] == 1) leaves.push_back(u);
      }
    } while(++h != first);
  }
  return result;
}

// The input segments of a partition by line (`input_on_line[l]`: those on line l), whose parts
// are to stay edges of the partition, as opposed to the extents that only grew from them.
template <class EK>
using Input_on_line = std::vector<std::vector<typename EK::Segment_2>>;

// Whether the edge of `h` overlaps an input segment of its line (with a positive length).
template <class EK, class Halfedge>
bool overlaps_input(const Halfedge& h, const Input_on_line<EK>& input_on_line)
{
  const std::size_t line = h->curve().data().front();
  if(line >= input_on_line.size()) return false;
  auto sorted = [](const typename EK::Point_2& a, const typename EK::Point_2& b) {
    return CGAL::compare_xy(a, b) == CGAL::SMALLER ? std::make_pair(a, b) : std::make_pair(b, a);
  };
  const auto [p, q] = sorted(h->source()->point(), h->target()->point());
  for(const auto& s : input_on_line[line]) {
    const auto [a, b] = sorted(s.source(), s.target()); // on the same line: ordered along it
    if(CGAL::compare_xy(p, b) == CGAL::SMALLER && CGAL::compare_xy(a, q) == CGAL::SMALLER) return true;
  }
  return false;
}

// The walk of the boundary component `ccb` of `face` (`component`: see above), if it is pinched.
// Only the half-edges between two groups count as passages (an edge within a group collapses),
// and only those with another face on their other side (an antenna's tip and its base are
// passed on the way out and back); a walk pinched nowhere else is pinched at a bridge that
// overlaps an input segment when it passes one (`is_input_bridge(h)`). The pinches at points go
// first: the piece that splits one of them often ends a bridge too (the bridge left by a piece
// that joined a hole to the walk). A bridge that is only an extent's extension is left to be
// dropped with the other edges that bound no cell.
template <class EK, class Circulator, class IsInputBridge>
std::optional<Pinched_walk<EK>> pinched_walk(typename Piece_arrangement<EK>::Face_const_handle face, Circulator ccb,
                                            std::size_t component, const Vertex_groups<EK>& group,
                                            const Point_rounding& rounding, const IsInputBridge& is_input_bridge)
{
  std::vector<typename Piece_arrangement<EK>::Halfedge_const_handle> walk;
  Circulator c = ccb;
  do walk.push_back(c); while(++c != ccb);
  const bool passes_a_bridge = std::any_of(walk.begin(), walk.end(), [&](const auto& h) {
    return h->twin()->face() == face && is_input_bridge(h);
  });
  for(const bool bridges : {false, true}) {
    if(bridges && !passes_a_bridge) break;
    Pinched_walk<EK> w;
    w.face = face;
    w.component = component;
    w.walk = walk;
    std::vector<std::pair<std::size_t, std::size_t>> arrivals; // group, position
    for(std::size_t k = 0; k < walk.size(); ++k) {
      const auto& h = walk[k];
      const bool passage = h->twin()->face() != face || (bridges && is_input_bridge(h));
      if(passage && group(h->source()) != group(h->target())) arrivals.push_back({group(h->target()), k});
    }
    passages_along_edges<EK>(w.walk, face, group, rounding, arrivals);
    std::sort(arrivals.begin(), arrivals.end());
    for(std::size_t k = 1; k < arrivals.size(); ++k)
      if(arrivals[k].first == arrivals[k - 1].first) {
        if(w.pinches.empty()) { w.first = arrivals[k - 1].second; w.second = arrivals[k].second; }
        if(w.pinches.empty() || w.pinches.back() != arrivals[k].first) w.pinches.push_back(arrivals[k].first);
        if(arrivals[k].second != arrivals[k - 1].second &&
           w.walk[arrivals[k].second]->target() == w.walk[arrivals[k - 1].second]->target())
          w.passed_twice.push_back(w.walk[arrivals[k].second]->target());
      }
    if(w.pinches.empty()) continue;
    if(w.first > w.second) std::swap(w.first, w.second);
    for(const auto& h : w.walk)
      if(std::find(w.pinches.begin(), w.pinches.end(), group(h->target())) != w.pinches.end())
        w.pinch_points.push_back(rounding(h->target()->point()));
    return w;
  }
  return std::nullopt;
}

// The pinched walks of the bounded faces of `arrangement`.
template <class EK>
std::vector<Pinched_walk<EK>> pinched_walks(const Piece_arrangement<EK>& arrangement, const Vertex_groups<EK>& group,
                                            const Point_rounding& rounding, const Input_on_line<EK>& input_on_line)
{
  std::vector<Pinched_walk<EK>> result;
  std::optional<std::unordered_set<const void*>> antennas; // found when first needed
  auto is_input_bridge = [&](const auto& h) {
    if(!overlaps_input<EK>(h, input_on_line)) return false;
    if(!antennas) antennas = antenna_halfedges(arrangement);
    return antennas->count(&*h) == 0;
  };
  for(auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    if(f->is_unbounded()) continue;
    if(auto w = pinched_walk<EK>(f, f->outer_ccb(), 0, group, rounding, is_input_bridge)) result.push_back(std::move(*w));
    std::size_t component = 1;
    for(auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole, ++component)
      if(auto w = pinched_walk<EK>(f, *hole, component, group, rounding, is_input_bridge)) result.push_back(std::move(*w));
  }
  return result;
}

// Where the ray from `origin` along `direction` first meets the segment from `p` to `q`
// after its origin: the parameter t (the point is origin + t direction), if it does.
template <class EK>
std::optional<typename EK::FT> first_parameter_on(const typename EK::Point_2& origin, const typename EK::Vector_2& direction,
                                                  const typename EK::Point_2& p, const typename EK::Point_2& q)
{
  using FT = typename EK::FT;
  const typename EK::Point_2 ahead = origin + direction;
  const CGAL::Orientation op = CGAL::orientation(origin, ahead, p), oq = CGAL::orientation(origin, ahead, q);
  if(op == oq && op != CGAL::COLLINEAR) return std::nullopt;
  if(op == CGAL::COLLINEAR && oq == CGAL::COLLINEAR) { // along the ray's line: its nearer end ahead
    std::optional<FT> best;
    for(const auto& x : {p, q}) {
      const FT t = ((x - origin) * direction) / direction.squared_length();
      if(CGAL::is_positive(t) && (!best || t < *best)) best = t;
    }
    return best;
  }
  const typename EK::Vector_2 e = q - p, w = p - origin;
  const FT t = (w.x() * e.y() - w.y() * e.x()) / (direction.x() * e.y() - direction.y() * e.x());
  if(!CGAL::is_positive(t)) return std::nullopt;
  return t;
}

// How a piece from a vertex of a pinched walk would end: at the other loop (it splits the
// walk), at another boundary component of the face (it joins them), or elsewhere.
enum class Piece_end { SPLITS, JOINS, NEITHER };

// The piece that `ray` would add from the vertex at `position` of the pinched walk `w`: its
// end, and how it ends; none if the ray does not go into the face there.
template <class EK>
std::optional<std::pair<typename EK::Point_2, Piece_end>>
piece_from(const Pinched_walk<EK>& w, std::size_t position, const Corner_ray<EK>& ray, const Point_rounding& rounding,
           bool from_pinch)
{
  using Point = typename EK::Point_2;
  using Direction = typename EK::Direction_2;
  const auto in = w.walk[position], out = w.walk[(position + 1) % w.walk.size()];
  const Point& v = in->target()->point();
  // the face is on the left of the walk: its angle at v turns counterclockwise from `out` to
  // the way back along `in`
  if(!Direction(ray.direction).counterclockwise_in_between(Direction(out->target()->point() - v),
                                                           Direction(in->source()->point() - v)))
    return std::nullopt;
  std::optional<typename EK::FT> nearest;
  Piece_end end = Piece_end::NEITHER;
  auto meet = [&](const auto& h, Piece_end if_nearest) {
    const auto t = first_parameter_on<EK>(v, ray.direction, h->source()->point(), h->target()->point());
    if(!t || (nearest && !(*t < *nearest))) return false;
    nearest = t;
    end = if_nearest;
    return true;
  };
  auto on_l2 = [&](std::size_t k) { return w.first < k && k <= w.second; };
  for(std::size_t k = 0; k < w.walk.size(); ++k) {
    const auto& h = w.walk[k];
    const bool across = on_l2(k) != on_l2(position) && h->twin()->face() != w.face;
    if(meet(h, across ? Piece_end::SPLITS : Piece_end::NEITHER) && across) {
      // not to a point that the rounding merges with the pinch (the piece would leave the walk
      // pinched there), unless it starts there too (it then crosses the gap that the rounding
      // closes, and collapses with it)
      const std::array<double, 2> hit = rounding(Point(v + *nearest * ray.direction));
      if(!from_pinch)
        for(const auto& x : w.pinch_points)
          if(rounding.may_merge(x, hit)) end = Piece_end::NEITHER;
    }
  }
  const auto f = w.face;
  if(w.component != 0) {
    auto c = f->outer_ccb();
    do meet(c, Piece_end::JOINS); while(++c != f->outer_ccb());
  }
  std::size_t component = 1;
  for(auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole, ++component)
    if(component != w.component) {
      auto c = *hole;
      do meet(c, Piece_end::JOINS); while(++c != *hole);
    }
  if(!nearest) return std::nullopt;
  return std::make_pair(Point(v + *nearest * ray.direction), end);
}

// Splits the pinched faces of `arrangement` with pieces from the ends of `rays` (see above),
// each on the line `piece_line[ray.piece]`, while a face is pinched and some end splits it or
// joins it to a hole (each end is used once). `input_on_line`: the input segments by line (see
// Input_on_line). Returns the number of pieces added.
template <class EK>
std::size_t split_pinched_cells(Piece_arrangement<EK>& arrangement, const std::vector<Corner_ray<EK>>& rays,
                                const std::vector<std::size_t>& piece_line, const Point_rounding& rounding,
                                const Input_on_line<EK>& input_on_line)
{
  if(rays.empty()) return 0;
  std::vector<std::size_t> by_origin(rays.size()); // the rays by origin, to find those at a vertex
  for(std::size_t r = 0; r < rays.size(); ++r) by_origin[r] = r;
  std::stable_sort(by_origin.begin(), by_origin.end(), [&](std::size_t a, std::size_t b) {
    return CGAL::compare_xy(rays[a].origin, rays[b].origin) == CGAL::SMALLER;
  });
  std::vector<bool> used(rays.size(), false);
  // the end that splits the pinched walk `w` (the first in the order of the rays), or else the
  // first that joins it to a hole: (ray, end of its piece)
  auto piece_for = [&](const Pinched_walk<EK>& w, const Vertex_groups<EK>& group) {
    std::optional<std::pair<std::size_t, typename EK::Point_2>> split, join;
    for(std::size_t k = 0; k < w.walk.size(); ++k) {
      const auto v = w.walk[k]->target();
      if(std::find(w.passed_twice.begin(), w.passed_twice.end(), v) != w.passed_twice.end()) continue;
      const bool in_pinch = std::find(w.pinches.begin(), w.pinches.end(), group(v)) != w.pinches.end();
      auto at = std::lower_bound(by_origin.begin(), by_origin.end(), v, [&](std::size_t r, const auto& x) {
        return CGAL::compare_xy(rays[r].origin, x->point()) == CGAL::SMALLER;
      });
      for(; at != by_origin.end() && rays[*at].origin == v->point(); ++at) {
        if(used[*at] || (split && split->first < *at)) continue;
        const auto piece = piece_from(w, k, rays[*at], rounding, in_pinch);
        if(!piece) continue;
        if(piece->second == Piece_end::SPLITS) split = std::make_pair(*at, piece->first);
        if(piece->second == Piece_end::JOINS && (!join || *at < join->first)) join = std::make_pair(*at, piece->first);
      }
    }
    return split ? split : join;
  };
  std::size_t added = 0;
  for(bool again = true; again;) {
    again = false;
    const Vertex_groups<EK> group(arrangement, rounding);
    for(const Pinched_walk<EK>& w : pinched_walks<EK>(arrangement, group, rounding, input_on_line)) {
      const auto chosen = piece_for(w, group);
      if(!chosen) continue; // not split here (see the manual's known limits)
      const Corner_ray<EK>& ray = rays[chosen->first];
      used[chosen->first] = true;
      CGAL::insert(arrangement, typename Piece_traits<EK>::Curve_2(typename EK::Segment_2(ray.origin, chosen->second),
                                                                   piece_line.at(ray.piece)));
      ++added;
      again = true; // the faces have changed: search them again
      break;
    }
  }
  return added;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SPLIT_PINCHED_CELLS_2_H
