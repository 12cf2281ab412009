// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DELAUNAY_BUILDER_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DELAUNAY_BUILDER_H

// Builds the 3D Delaunay triangulation of points, in parallel with TBB when asked, and hands
// it to the rest of a reconstruction (the triangulation type differs with the concurrency
// tag, hence the callback).

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Delaunay_triangulation_3.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Copies the points given through `point_map`, refusing NaN and infinite coordinates. A zero
// coordinate is copied as +0: the triangulation merges duplicates and keeps the first one
// inserted, so a point given as both (0, y, z) and (-0, y, z) would otherwise be output with
// the sign of whichever comes first in the input.
template <class Point, class PointRange, class PointMap>
std::vector<Point> finite_points(const PointRange& points, const PointMap& point_map)
{
  // Not reserved: grown by doubling, the copy frees blocks of up to half its size on the way.
  // With glibc, freeing a block that had a mapping of its own raises the size from which a
  // block gets one (128 KiB at first, at most 32 MiB): the blocks of the triangulation built
  // next and the arrays of the reconstruction then come from the heap, where the memory freed
  // by one stage is reused by the next, instead of fresh mappings whose pages fault when they
  // are first touched (the manual, section "Complexity and Performance", gives the times).
  std::vector<Point> pts;
  for(const auto& e : points) {
    const Point& p = get(point_map, e);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(Input_error_code::NON_FINITE_COORDINATE,
                        "point " + std::to_string(pts.size()) + " has a NaN or infinite coordinate");
    pts.push_back(Point(p.x() + 0.0, p.y() + 0.0, p.z() + 0.0)); // -0 + 0 = +0, x + 0 = x otherwise
  }
  if(pts.empty()) throw Input_error(Input_error_code::EMPTY_INPUT, "no input point");
  return pts;
}

// Below this number of points the parallel construction costs more than it saves (the
// start of the threads and the grid of locks): the triangulation is built sequentially (the
// manual, section "Complexity and Performance", gives the measurements).
constexpr std::size_t minimum_points_for_parallel_delaunay = 100000;

// Calls `then(dt)` with the Delaunay triangulation of `points`, with the predicates of
// `traits`, built with `threads` threads
// (one without TBB, or for fewer than `minimum_points_for_parallel_delaunay` points). The
// triangulation is sequential after its construction; it does not depend on the number of
// threads (the Delaunay triangulation of a point set is unique with CGAL's symbolic
// perturbation).
template <class Geom_traits, class Point, class Then>
void with_delaunay_triangulation(const std::vector<Point>& points, const Geom_traits& traits, unsigned threads,
                                 const Then& then)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(threads > 1 && points.size() >= minimum_points_for_parallel_delaunay) {
    using Vb = Triangulation_vertex_base_3<Geom_traits>;
    using Cb = Delaunay_triangulation_cell_base_3<Geom_traits>;
    using Tds = Triangulation_data_structure_3<Vb, Cb, Parallel_tag>;
    using DT = Delaunay_triangulation_3<Geom_traits, Tds>;
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Bbox_3 box = bbox_3(points.begin(), points.end());
    typename DT::Lock_data_structure locks(box, 50);
    DT dt(points.begin(), points.end(), traits, &locks);
    dt.set_lock_data_structure(nullptr);
    then(dt);
    return;
  }
#endif
  (void)threads;
  Delaunay_triangulation_3<Geom_traits> dt(points.begin(), points.end(), traits);
  then(dt);
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DELAUNAY_BUILDER_H
