// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_BORDER_POINTS_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_BORDER_POINTS_3_H

// The points on the border of a sampled surface (the rim of a scan, of an occlusion hole):
// those whose k nearest neighbours, projected on the point's tangent plane (the plane of
// their covariance's two largest eigenvectors, through the point), leave an angular gap of
// more than `minimum_gap` around it. Inside a surface sampled without holes the neighbours
// surround the point and the largest gap is small if the sampling is even (a jittered grid:
// below about pi/3; a random uniform sampling leaves larger gaps); on a straight border it is
// about pi, at the corner of a rectangular hole about pi/2. Sharp edges inside the surface keep their
// neighbours on both sides (the tangent plane is then the bisector), so they are not borders;
// the VCM finds those.

#include <CGAL/Default_diagonalize_traits.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_type_config.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The largest angle between consecutive directions of `angles` (radians, any order) around
// the full circle.
inline double largest_angular_gap(std::vector<double>& angles)
{
  if(angles.empty()) return 2 * CGAL_PI;
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * CGAL_PI - angles.back();
  for(std::size_t i = 1; i < angles.size(); ++i) gap = (std::max)(gap, angles[i] - angles[i - 1]);
  return gap;
}

// The points of `points` (distinct) on the border of the surface they sample, by their `k`
// nearest neighbours and the `minimum_gap` (radians).
template <class Point>
std::vector<Point> border_points(const std::vector<Point>& points, std::size_t k, double minimum_gap)
{
  using Kernel = typename Kernel_traits<Point>::Kernel;
  using Search = Orthogonal_k_neighbor_search<Search_traits_3<Kernel>>;
  typename Search::Tree tree(points.begin(), points.end());
  std::vector<Point> result;
  std::vector<double> angles;
  for(const Point& p : points) {
    Search search(tree, p, unsigned(k + 1)); // p itself is the first
    std::vector<std::array<double, 3>> offsets;
    for(const auto& neighbour : search)
      if(neighbour.first != p)
        offsets.push_back({neighbour.first.x() - p.x(), neighbour.first.y() - p.y(), neighbour.first.z() - p.z()});
    if(offsets.size() < 3) continue;
    std::array<double, 3> mean{0, 0, 0};
    for(const auto& o : offsets) for(int j = 0; j < 3; ++j) mean[j] += o[j] / double(offsets.size());
    std::array<double, 6> covariance{0, 0, 0, 0, 0, 0}; // xx xy xz yy yz zz
    for(const auto& o : offsets) {
      const double x = o[0] - mean[0], y = o[1] - mean[1], z = o[2] - mean[2];
      covariance[0] += x * x; covariance[1] += x * y; covariance[2] += x * z;
      covariance[3] += y * y; covariance[4] += y * z; covariance[5] += z * z;
    }
    std::array<double, 3> eigenvalues;
    std::array<double, 9> eigenvectors; // increasing eigenvalues, one vector per 3 entries
    if(!Default_diagonalize_traits<double, 3>::diagonalize_selfadjoint_covariance_matrix(covariance, eigenvalues, eigenvectors))
      continue;
    const double* u = &eigenvectors[6]; // the two largest: the tangent plane
    const double* v = &eigenvectors[3];
    angles.clear();
    for(const auto& o : offsets)
      angles.push_back(std::atan2(o[0] * v[0] + o[1] * v[1] + o[2] * v[2], o[0] * u[0] + o[1] * u[1] + o[2] * u[2]));
    if(largest_angular_gap(angles) > minimum_gap) result.push_back(p);
  }
  return result;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_BORDER_POINTS_3_H
