// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CROSSING_FREE_EDGES_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CROSSING_FREE_EDGES_2_H

// The edges of a valid state of a partition (pairwise free of crossings) with their grid, for
// the crossing test of states that differ from it in a few edges (the attempts of the
// reductions of a round, which start from the valid partition of the round's start). An edge of
// such a state whose ends have the coordinates of a reference edge is that edge, so two of them
// cannot meet; only the pairs with another edge (a suspect) are tested:
// - a suspect against the reference edges near it, found in the reference grid built once, that
//   are still edges of the state;
// - the suspects among themselves, with crossing_edge_pairs() on them alone.
// The pairs found are those of crossing_edge_pairs() with `may_cross` true for the suspects,
// but the cost of a test is that of the suspects, not of the whole partition.

#include <CGAL/Polygon_partition_simplification/internal/First_value_map.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_validity_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Segment_grid_2.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

class Crossing_free_edges
{
public:
  // `segments`: (x0, y0, x1, y1), pairwise free of crossings
  explicit Crossing_free_edges(const std::vector<std::array<double, 4>>& segments)
    : coordinates_(segments.size()), core_(segments)
  {
    std::vector<std::array<double, 4>> inside_segments;
    for(std::size_t e = 0; e < segments.size(); ++e) {
      const auto& s = segments[e];
      coordinates_.insert({{s[0], s[1]}}, {{s[2], s[3]}});
      if(core_.contains(s)) {
        inside_.push_back(std::uint32_t(e));
        inside_segments.push_back(s);
      } else outside_.push_back(std::uint32_t(e));
    }
    grid_ = Segment_grid_2(inside_segments, core_.low, core_.high);
  }

  // The pairs of edges ((u, v) point pairs with coordinates `points`) that meet elsewhere than at
  // a common end, among the pairs with a suspect: an edge that is not a reference edge, or that
  // joins the same two points as another edge (sorted; one pair at most unless `all`).
  template <class PK>
  std::vector<std::pair<std::size_t, std::size_t>> crossing_pairs(const std::vector<std::array<double, 2>>& points,
                                                                  const std::vector<std::array<std::size_t, 2>>& edges,
                                                                  bool all) const
  {
    const std::size_t none = std::size_t(-1);
    std::vector<bool> suspect(edges.size(), false);
    std::vector<std::size_t> alive(coordinates_.size(), none); // reference edge -> edge of the state
    {
      First_value_map known; // sorted ends -> the first edge with these ends that is a reference edge
      known.clear(edges.size());
      for(std::size_t e = 0; e < edges.size(); ++e) {
        const std::uint32_t r = coordinates_.find(points[edges[e][0]], points[edges[e][1]]);
        if(r == First_value_map::no_value) { suspect[e] = true; continue; }
        const auto [u, v] = std::minmax(edges[e][0], edges[e][1]);
        const std::size_t first = known.insert((std::uint64_t(u) << 32) | v, std::uint32_t(e));
        if(first != e) suspect[first] = suspect[e] = true;
        else if(alive[r] == none) alive[r] = e;
        else suspect[alive[r]] = suspect[e] = true; // the same coordinates at other points
      }
    }
    std::vector<std::size_t> suspects;
    for(std::size_t e = 0; e < edges.size(); ++e) if(suspect[e]) suspects.push_back(e);
    std::vector<std::pair<std::size_t, std::size_t>> result;
    // the suspects among themselves
    {
      std::vector<std::array<std::size_t, 2>> suspect_edges;
      for(std::size_t e : suspects) suspect_edges.push_back(edges[e]);
      for(const auto& [i, j] : crossing_edge_pairs<PK>(points, suspect_edges, all, [](const auto&, const auto&) { return true; }))
        result.emplace_back(suspects[i], suspects[j]);
    }
    // each suspect against the reference edges near it that are edges of the state (not suspects)
    auto box = [&](std::size_t e) {
      const auto& a = points[edges[e][0]];
      const auto& b = points[edges[e][1]];
      return CGAL::Bbox_2(std::min(a[0], b[0]), std::min(a[1], b[1]), std::max(a[0], b[0]), std::max(a[1], b[1]));
    };
    std::vector<std::size_t> seen(edges.size(), none); // the last suspect that met an edge
    for(std::size_t i : suspects) {
      if(!all && !result.empty()) break;
      const CGAL::Bbox_2 box_i = box(i);
      auto consider = [&](std::uint32_t reference) {
        const std::size_t j = alive[reference];
        if(j == none || suspect[j] || seen[j] == i || (!all && !result.empty())) return;
        seen[j] = i;
        if(CGAL::do_overlap(box_i, box(j)) && edges_meet<PK>(points, edges[i], edges[j]))
          result.emplace_back(std::min(i, j), std::max(i, j));
      };
      const auto& p = points[edges[i][0]];
      const auto& q = points[edges[i][1]];
      grid_.for_each_cell({{p[0], p[1], q[0], q[1]}}, [&](std::size_t cell) {
        grid_.for_each_in_cell(cell, [&](std::uint32_t entry) { consider(inside_[entry]); });
      });
      for(std::uint32_t reference : outside_) consider(reference);
    }
    std::sort(result.begin(), result.end());
    return result;
  }

private:
  Segment_coordinate_set coordinates_;
  Core_rectangle core_;
  std::vector<std::uint32_t> inside_, outside_; // reference edges in the grid, and the others
  Segment_grid_2 grid_{{}, {{0, 0}}, {{0, 0}}};
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CROSSING_FREE_EDGES_2_H
