// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_NOISE_SMOOTHING_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_NOISE_SMOOTHING_3_H

// The denoising of the robust mode of the closed surface reconstruction: the points are moved
// onto jets (local quadrics, CGAL's `jet_smooth_point_set()`) fitted to their k nearest
// neighbours, pass after pass, until a pass moves them (median displacement) by less than 5%
// of what the first pass did. The first pass's median displacement is the noise estimate: the
// typical distance of a point from the smooth surface through its neighbours. Points whose
// noise estimate is below 5% of their average spacing are clean and left as they are. k is the user's,
// or CGAL's `estimate_global_k_neighbor_scale()` (the scale at which the noise is averaged out,
// Giraudot et al. 2013) but at least 24: below, the jets of a noisy sphere follow the noise
// and the surface zig-zags (see the user manual, section "Noisy scans").
//
// An interpolating surface through noisy points must zig-zag between them; through points put
// back on the smooth surface, it need not. The lexicographic order then runs on the smoothed
// points: the result is still the lexicographic optimal cycle, of another point set.

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <CGAL/compute_average_spacing.h>
#include <CGAL/tags.h>
#if defined(CGAL_EIGEN3_ENABLED)
// CGAL 5.5's compare_vertices.h names a template parameter MAP_TYPE, which <sys/mman.h>
// (internal/Large_array_allocator.h) defines as a macro: the scale estimate comes first
#include <CGAL/estimate_scale.h>
#include <CGAL/jet_smooth_point_set.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

struct Noise_smoothing_result
{
  std::size_t neighbors = 0;  // k of the jet fits
  std::size_t passes = 0;     // smoothing passes made
  double noise_estimate = 0;  // median displacement of the first pass
  double average_spacing = 0; // mean distance of a point to its 6 nearest neighbours, before
};

constexpr std::size_t minimum_smoothing_neighbors = 24;
constexpr std::size_t maximum_smoothing_passes = 6;
// below this noise estimate, in average spacings, the points are clean: a jet through 24
// neighbours or more would only round off their features
constexpr double clean_noise_ratio = 0.05;

// true if some 4 of the points span a tetrahedron (exact predicates): otherwise the jets of
// their neighbourhoods are not defined, and the triangulation reports the degeneracy
template <class Point>
bool spans_a_tetrahedron(const std::vector<Point>& points)
{
  std::size_t i = 1, j, k;
  while(i < points.size() && points[i] == points[0]) ++i;
  for(j = i + 1; j < points.size() && CGAL::collinear(points[0], points[i], points[j]); ++j) {}
  for(k = j + 1; k < points.size() && CGAL::coplanar(points[0], points[i], points[j], points[k]); ++k) {}
  return k < points.size();
}

template <class Point>
double median_displacement(const std::vector<Point>& before, const std::vector<Point>& after)
{
  std::vector<double> d(before.size());
  for(std::size_t i = 0; i < before.size(); ++i) d[i] = std::sqrt(CGAL::squared_distance(before[i], after[i]));
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return d[d.size() / 2];
}

// Smooths `points` in place. Duplicates are removed first (the triangulation merges them
// anyway, and a neighbourhood of copies of one point crashes CGAL 5.5's jet fit); the order of
// the points is then the lexicographic one. `neighbors` 0 chooses k from the data. Fewer than
// 16 distinct points, or points that span no tetrahedron, are left as they are: a quadric needs
// more neighbours than that to average anything, and a plane or a line has no jet. A point that
// a fit would send to a non-finite position stays where it was.
template <class Point>
Noise_smoothing_result smooth_noisy_points(std::vector<Point>& points, std::size_t neighbors, unsigned threads)
{
  Noise_smoothing_result result;
  if(neighbors > 0 && neighbors < 8) // a quadric has 6 coefficients: a fit needs more neighbours
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "smoothing_neighbors must be 0 (chosen from the points) or at least 8, not " + std::to_string(neighbors));
#if defined(CGAL_EIGEN3_ENABLED)
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if(points.size() < 16 || !spans_a_tetrahedron(points)) return result;
  result.average_spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(points, 6);
  result.neighbors = neighbors > 0 ? neighbors
                                   : (std::max)(minimum_smoothing_neighbors,
                                                std::size_t(CGAL::estimate_global_k_neighbor_scale(points)));
  result.neighbors = (std::min)(result.neighbors, points.size() - 1);
  std::vector<Point> before;
  for(std::size_t pass = 0; pass < maximum_smoothing_passes; ++pass) {
    before = points;
#if defined(CGAL_LINKED_WITH_TBB)
    if(threads > 1)
      CGAL::jet_smooth_point_set<CGAL::Parallel_tag>(points, unsigned(result.neighbors));
    else
#endif
      CGAL::jet_smooth_point_set<CGAL::Sequential_tag>(points, unsigned(result.neighbors));
    ++result.passes;
    for(std::size_t i = 0; i < points.size(); ++i)
      if(!(std::isfinite(points[i].x()) && std::isfinite(points[i].y()) && std::isfinite(points[i].z())))
        points[i] = before[i];
    const double moved = median_displacement(before, points);
    if(pass == 0) {
      result.noise_estimate = moved;
      if(moved < clean_noise_ratio * result.average_spacing) { // clean: left as it was
        points.swap(before);
        result.passes = 0;
        break;
      }
    }
    if(!(moved >= 0.05 * result.noise_estimate)) break; // also when the first pass moved nothing
  }
  (void)threads;
#else
  (void)neighbors;
  (void)threads;
  throw Input_error(Input_error_code::UNSUPPORTED_OPTION,
                    "the robust mode smooths the points by jet fitting, which needs Eigen: build with CGAL::Eigen3_support");
#endif
  return result;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_NOISE_SMOOTHING_3_H
