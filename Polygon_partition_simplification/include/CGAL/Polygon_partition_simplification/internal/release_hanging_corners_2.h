// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_RELEASE_HANGING_CORNERS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_RELEASE_HANGING_CORNERS_2_H

// Ends that meet at time 0 stop each other in the kinetic propagation, so that corners stay
// corners. A closed chain of such corners that touches the rest of the partition at a single
// point (an "X" of two segments whose ends are joined by a third one: the triangle hangs at the
// crossing; two squares sharing a corner) makes a cell whose boundary is not a simple polygon.
// Then rays stopped at time 0 near a defective edge are released, each from its corner, and the
// propagation is run again: first each alone (the first four candidates, nearest first, then
// by index: the segments are in a canonical order), for a ray that leaves the chain into the
// cell around it and splits the cell; then one more at each run, the first candidate of the
// partition of the previous run. The first valid partition is returned; after 16 runs, the
// first partition (invalid, as documented).

#include <CGAL/Polygon_partition_simplification/internal/Kinetic_propagation_2.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// The rays of `propagation` stopped at time 0 at a point of `p` within 3 edges of a defective
// edge, by increasing distance, then index (the chain that hangs at a point of a defective edge
// may have its corners farther along). A ray's origin is at a point when their coordinates
// differ by at most `tolerance`.
template <class Partition, class Propagation>
std::vector<std::size_t> hanging_corner_rays(const Partition& p, const std::vector<std::size_t>& defective,
                                             const Propagation& propagation, double tolerance)
{
  constexpr std::size_t maximum_distance = 3, unreached = std::size_t(-1);
  std::vector<std::vector<std::size_t>> neighbours(p.number_of_vertices());
  for(const auto& e : p.edges()) {
    neighbours[e.source].push_back(e.target);
    neighbours[e.target].push_back(e.source);
  }
  std::vector<std::size_t> distance(p.number_of_vertices(), unreached), layer;
  for(std::size_t e : defective)
    for(std::size_t v : {p.edges()[e].source, p.edges()[e].target})
      if(distance[v] == unreached) { distance[v] = 0; layer.push_back(v); }
  std::vector<std::pair<std::array<double, 2>, std::size_t>> nearby; // point, distance
  for(std::size_t d = 0; !layer.empty(); ++d) {
    std::vector<std::size_t> next;
    for(std::size_t v : layer) {
      const auto q = p.point(v);
      nearby.push_back({{CGAL::to_double(q.x()), CGAL::to_double(q.y())}, d});
      if(d < maximum_distance)
        for(std::size_t w : neighbours[v])
          if(distance[w] == unreached) { distance[w] = d + 1; next.push_back(w); }
    }
    layer = std::move(next);
  }
  std::vector<std::pair<std::size_t, std::size_t>> rays; // distance, ray
  for(std::size_t r = 0; r < propagation.number_of_rays(); ++r) {
    if(!propagation.stopped_at_origin(r)) continue;
    const double x = CGAL::to_double(propagation.origin(r).x()), y = CGAL::to_double(propagation.origin(r).y());
    std::size_t closest = unreached;
    for(const auto& [q, d] : nearby)
      if(std::abs(q[0] - x) <= tolerance && std::abs(q[1] - y) <= tolerance) closest = std::min(closest, d);
    if(closest != unreached) rays.push_back({closest, r});
  }
  std::sort(rays.begin(), rays.end());
  std::vector<std::size_t> result;
  for(const auto& x : rays) result.push_back(x.second);
  return result;
}

// The kinetic partition, computed again with rays released while it has hanging corners (see
// above). `make_propagation()` returns a new `Kinetic_propagation_2<EK>` of the segments;
// `partition_of(propagation)` builds the partition of a propagation that has run. `runs` is set
// to the number of propagations run.
template <class MakePropagation, class PartitionOf>
auto propagate_releasing_hanging_corners(const MakePropagation& make_propagation, const PartitionOf& partition_of,
                                         double tolerance, std::size_t& runs)
{
  auto run = [&](const std::vector<std::size_t>& released, auto& propagation) {
    for(std::size_t r : released) propagation.release(r);
    propagation.run();
    return partition_of(propagation);
  };
  auto propagation = make_propagation();
  auto partition = run({}, propagation); // not const: moved out when returned
  runs = 1;
  const std::vector<std::size_t> defective = partition.defective_edges();
  if(defective.empty()) return partition;
  constexpr std::size_t maximum_runs = 16, maximum_single_runs = 5;
  const std::vector<std::size_t> first_candidates = hanging_corner_rays(partition, defective, propagation, tolerance);
  for(std::size_t r : first_candidates) {
    if(runs == maximum_single_runs) break;
    auto again = make_propagation();
    auto released = run({r}, again);
    ++runs;
    if(released.is_valid()) return released;
  }
  std::vector<std::size_t> released;
  std::vector<std::size_t> next = first_candidates;
  while(runs < maximum_runs) {
    const auto r = std::find_if(next.begin(), next.end(), [&](std::size_t x) {
      return std::find(released.begin(), released.end(), x) == released.end();
    });
    if(r == next.end()) break;
    released.push_back(*r);
    auto again = make_propagation();
    auto p = run(released, again);
    ++runs;
    const std::vector<std::size_t> d = p.defective_edges();
    if(d.empty()) return p;
    next = hanging_corner_rays(p, d, again, tolerance);
  }
  return partition;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_RELEASE_HANGING_CORNERS_2_H
