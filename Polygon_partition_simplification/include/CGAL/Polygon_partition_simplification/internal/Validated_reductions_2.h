// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_VALIDATED_REDUCTIONS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_VALIDATED_REDUCTIONS_2_H

// The combinatorial part of a round of the simplification: the reductions after a descent
// (Partition_reducer), checked with exact predicates (partition_defect()) and redone until the
// partition is valid. After a rejected attempt, the lines of the defective edges (and the lines
// through their ends) get back the coordinates they had before the descent and may not merge
// (they are frozen); when they are all frozen already, the defect comes from a change further
// away (a point between the ends of an edge removed because another line moved or merged), and
// the lines within one more point of them are frozen too, ring after ring. When nothing more
// can be frozen, the round is undone: the partition is that of the start of the round, which is
// valid. So every round ends with a valid partition.

#include <CGAL/Polygon_partition_simplification/internal/Crossing_free_edges_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_reductions_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_validity_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Working_partition_2.h>

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// What the reductions of a round did.
struct Round_reductions
{
  Reduction_counts counts;            // of the accepted attempt (none when the round is undone)
  std::size_t rejected_attempts = 0;  // attempts that left an invalid partition
  bool undone = false;                // no valid attempt: the partition is the round's start
  std::vector<bool> changed_lines;    // lines of the result that the reductions changed (not undone)
};

// The edges of the partition at the start of a round, which is valid, as the reductions need
// them: the orientation of every edge along its line (the reductions collapse the edges that
// the descent reversed), and the edges with their grid (an edge of a reduced partition with the
// same ends as one of them crosses none of the others, so the crossing test of each attempt
// only tests the other edges, against this grid built once).
struct Round_start_edges
{
  std::vector<signed char> orientations;
  Crossing_free_edges crossing_free;

  explicit Round_start_edges(const Working_partition& start)
    : orientations(start.edges.size()), crossing_free(segments(start, orientations))
  {}

private:
  // the segments of the edges of `start`, with their orientations along their lines
  static std::vector<std::array<double, 4>> segments(const Working_partition& start, std::vector<signed char>& orientations)
  {
    std::vector<std::array<double, 2>> points(start.vertex_lines.size()); // finite: `start` is valid
    for(Index v = 0; v < points.size(); ++v) points[v] = start.point(v);
    std::vector<std::array<double, 4>> result(start.edges.size());
    for(std::size_t i = 0; i < start.edges.size(); ++i) {
      const auto& e = start.edges[i];
      const std::array<double, 2>& p = points[e[1]];
      const std::array<double, 2>& q = points[e[2]];
      orientations[i] = Partition_reducer::orientation_along(start.lines[e[0]].coefficients, p, q);
      result[i] = {{p[0], p[1], q[0], q[1]}};
    }
    return result;
  }
};

// The state an attempt of the reductions starts from: the partition at the start of the round
// with the coefficients of the descent (`moved`), but for the frozen lines, which keep theirs;
// every line is its own single member.
inline void moved_partition(Working_partition& x, const Working_partition& start, const std::vector<Vector_3d>& moved,
                            const std::vector<bool>& frozen)
{
  x = start;
  for(Index l = 0; l < x.lines.size(); ++l) {
    x.lines[l].members.assign(1, l);
    x.lines[l].is_frozen = frozen[l];
    if(!frozen[l]) x.lines[l].coefficients = moved[l];
  }
}

// The lines of the start of a round that the attempts keep back (frozen), and how this set grows
// after a rejected attempt. Fixed lines never move: they are never frozen.
class Round_freezing
{
public:
  explicit Round_freezing(const Working_partition& start) : start_(start), frozen_(start.lines.size(), false) {}

  const std::vector<bool>& frozen() const { return frozen_; }

  // After the rejected attempt `w` (its `conflicts` from the reducer, its `defective` edges from
  // the validity check): freezes the lines in conflict, then the lines of each defective edge
  // and the lines through its ends; if all were frozen already, the lines within one more ring
  // of points around them. Returns false when no line could be frozen: no attempt can do better.
  bool freeze_after_rejection(const Working_partition& w, const std::vector<Index>& conflicts,
                              const std::vector<std::size_t>& defective)
  {
    bool progress = false;
    for(Index l : conflicts) progress = freeze(l) || progress;
    for(std::size_t e : defective)
      for_each_line_of_edge(w, e, [&](Index l) { progress = freeze(l) || progress; });
    while(!progress && !defective.empty()) {
      ++ring_;
      const bool grew = freeze_ring(w, defective, progress);
      if(!grew) break; // the whole connected part is frozen
    }
    return progress;
  }

private:
  // freezes line l of the start; true if it was not frozen (nor fixed) before
  bool freeze(Index l)
  {
    if(frozen_[l] || start_.lines[l].is_fixed) return false;
    frozen_[l] = true;
    return true;
  }

  // calls f(l) for the lines of the start merged into the line of edge e of `w` and into the
  // lines through its two ends
  template <class F>
  static void for_each_line_of_edge(const Working_partition& w, std::size_t e, const F& f)
  {
    for(Index l : w.lines[w.edges[e][0]].members) f(l);
    for(int end = 1; end <= 2; ++end)
      for(Index line : w.vertex_lines[w.edges[e][end]])
        for(Index l : w.lines[line].members) f(l);
  }

  // Freezes the lines of the start within `ring_` points (along the lines of the start) of the
  // lines of the defective edges; sets `progress` if one was not frozen. Returns whether the
  // last ring reached a new line (false: the rings cover the whole connected part).
  bool freeze_ring(const Working_partition& w, const std::vector<std::size_t>& defective, bool& progress)
  {
    if(line_points_.empty()) { // the points of every line of the start, built once
      line_points_.resize(start_.lines.size());
      for(Index v = 0; v < start_.vertex_lines.size(); ++v)
        for(Index l : start_.vertex_lines[v]) line_points_[l].push_back(v);
    }
    std::vector<bool> reached(start_.lines.size(), false);
    std::vector<Index> layer;
    for(std::size_t e : defective)
      for_each_line_of_edge(w, e, [&](Index l) {
        if(!reached[l]) { reached[l] = true; layer.push_back(l); }
      });
    bool grew = true;
    for(std::size_t step = 0; step < ring_ && grew; ++step) {
      std::vector<Index> next;
      for(Index l : layer)
        for(Index v : line_points_[l])
          for(Index m : start_.vertex_lines[v])
            if(!reached[m]) { reached[m] = true; next.push_back(m); }
      grew = !next.empty();
      layer = std::move(next);
    }
    for(Index l = 0; l < start_.lines.size(); ++l)
      if(reached[l] && freeze(l)) progress = true;
    return grew;
  }

  const Working_partition& start_;
  std::vector<bool> frozen_;
  std::size_t ring_ = 0; // how far around a defect lines are frozen (grows when freezing stalls)
  std::vector<std::vector<Index>> line_points_;
};

// The lines of `w` (an attempt's state before the reductions) whose coordinates differ from
// those of `start`: the reducer makes the edges of the other lines again only around merges.
inline std::vector<bool> moved_lines(const Working_partition& w, const Working_partition& start)
{
  std::vector<bool> result(w.lines.size());
  for(Index l = 0; l < w.lines.size(); ++l) result[l] = w.lines[l].coefficients != start.lines[l].coefficients;
  return result;
}

// The reductions of a round on `w`, from the round's start `start` (valid) and the coefficients
// of its descent `moved` (`first_round`: `start` is the input, whose edges the reducer makes
// again everywhere): attempts with more and more lines frozen until the result is valid and
// free of conflicts; `w` is that result, or `start` when the round is undone. The validity is
// checked with the predicates of `GeomTraits` (see partition_defect()).
template <class GeomTraits>
Round_reductions reduce_until_valid(Working_partition& w, const Working_partition& start,
                                           const std::vector<Vector_3d>& moved, const Reduction_thresholds& thresholds,
                                           bool first_round)
{
  Round_reductions result;
  const Round_start_edges start_edges(start);
  auto crossing_pairs = [&](const std::vector<std::array<double, 2>>& points,
                            const std::vector<std::array<std::size_t, 2>>& ends, bool all) {
    return start_edges.crossing_free.crossing_pairs<typename GeomTraits::Exact_predicates_kernel>(points, ends, all);
  };
  Round_freezing freezing(start);
  for(;;) {
    moved_partition(w, start, moved, freezing.frozen());
    Partition_reducer reducer(w, thresholds);
    result.counts = reducer.run(start_edges.orientations, first_round ? std::vector<bool>() : moved_lines(w, start));
    std::vector<std::size_t> defective;
    const std::string defect = partition_defect<GeomTraits>(Working_partition_view{w}, &defective, crossing_pairs);
    if(defect.empty() && reducer.conflicts().empty()) break;
    ++result.rejected_attempts;
    if(!freezing.freeze_after_rejection(w, reducer.conflicts(), defective)) {
      w = start;
      result.undone = true;
      result.counts = {};
      return result;
    }
  }
  // the lines changed: those of the result that differ from the state the reductions started from
  Working_partition before;
  moved_partition(before, start, moved, freezing.frozen());
  result.changed_lines = changed_lines(before, w);
  return result;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_VALIDATED_REDUCTIONS_2_H
