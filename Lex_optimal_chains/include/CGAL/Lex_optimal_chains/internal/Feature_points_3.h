// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_POINTS_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_POINTS_3_H

// The feature set S of lex_optimal_feature_reconstruction(): the points on sharp feature
// edges by the Voronoi covariance measure, the thresholds of the border points, and the
// vertices of a Delaunay triangulation at the feature points.

#include <CGAL/number_type_config.h>
#include <CGAL/vcm_estimate_edges.h>
#include <CGAL/vcm_estimate_normals.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The points of `points` on sharp feature edges by the Voronoi covariance measure (CGAL's
// compute_vcm() and vcm_is_on_feature_edge()): offset radius R and convolution radius r.
template <class Point>
std::vector<Point> vcm_feature_points(const std::vector<Point>& points, double offset_radius,
                                      double convolution_radius, double threshold)
{
  std::vector<std::array<double, 6>> covariance;
  compute_vcm(points, covariance, offset_radius, convolution_radius);
  std::vector<Point> features;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(vcm_is_on_feature_edge(covariance[i], threshold)) features.push_back(points[i]);
  return features;
}

// The border points of `border_features`: the largest angular gap between a point's 12
// nearest neighbours above 75 degrees. A straight border leaves a gap of about 180 degrees,
// the corner of a rectangular hole about 90; the neighbours of an inner point of an even
// (jittered grid) sampling leave less than about 60, those of a random uniform sampling
// often more.
constexpr std::size_t border_neighbours = 12;
constexpr double border_gap = 75 * CGAL_PI / 180;

// The vertex of `dt` at each feature point (the nearest one for a point that is not a vertex,
// searched from the last one found), sorted and without duplicates.
template <class DT, class Point>
std::vector<typename DT::Vertex_handle> feature_vertices(const DT& dt, const std::vector<Point>& features)
{
  using Vertex_handle = typename DT::Vertex_handle;
  std::vector<Vertex_handle> by_point;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) by_point.push_back(v);
  auto less = [](Vertex_handle a, Vertex_handle b) { return a->point() < b->point(); };
  std::sort(by_point.begin(), by_point.end(), less);
  std::vector<Vertex_handle> result;
  typename DT::Cell_handle hint;
  for(const Point& p : features) {
    const auto it = std::lower_bound(by_point.begin(), by_point.end(), p, [](Vertex_handle v, const Point& q) { return v->point() < q; });
    const Vertex_handle v = it != by_point.end() && (*it)->point() == p ? *it : dt.nearest_vertex(p, hint);
    hint = v->cell();
    result.push_back(v);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_POINTS_3_H
