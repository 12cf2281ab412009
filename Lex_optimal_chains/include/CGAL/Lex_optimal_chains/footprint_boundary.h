// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_FOOTPRINT_BOUNDARY_H
#define CGAL_LEX_OPTIMAL_CHAINS_FOOTPRINT_BOUNDARY_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef

A closed polygon just outside the footprint of a terrain-like point cloud (aerial LiDAR,
photogrammetry tiles), to use as the imposed boundary of
`lex_optimal_open_surface_reconstruction()`.

Placement: the bounding rectangle of the points in the \f$xy\f$-plane is enlarged by a
margin of `margin` times its larger side on every side; each side is cut into
`vertices_per_side` edges whose vertices are pushed outward on a parabola (at most half the
margin at the middle of a side), so that the polygon is strictly convex. Each vertex is
draped at the height of the ground next to it: the 10th percentile of the heights of the 64
points nearest to it in the \f$xy\f$-plane (ties broken by height, so that the result does
not depend on the order of the points), which is below trees and roofs that cover most of
these points and above a few low outliers; then lowered by a thousandth of the larger side
(so that a flat tile is not coplanar with the polygon). The points then lie strictly inside the vertical prism
over the polygon, so every polygon vertex is a vertex, and every polygon edge an edge, of
the convex hull of the points and the polygon (a vertical plane through it leaves all the
rest on one side, whatever the heights), hence of their Delaunay triangulation: the
boundary is always in the triangulation. The polygon turns counterclockwise seen from
above, so that over Q the reconstructed surface is oriented upward. Its first vertex is
repeated at its end.

Why draped: a polygon at one height (below the lowest point, as in a first version) is far
below the high side of a steep tile, or of any tile with one low outlier; the large
triangles that then join it to the points can be lexicographically smaller than the
terrain itself, which the optimum then leaves out (half of a tile sloping at 45 degrees,
all of a LiDAR tile with one point 100 m below the ground). Draped, the skirt is a narrow
band of about the margin's width. The median of the 8 nearest points, tried first, followed
the slopes best but lifted the polygon onto trees and roofs at the border of a LiDAR tile,
where the surface then rose to meet it.

Cost: one pass over the points, each compared with every polygon vertex (64 by default).
A `CGAL::Orthogonal_k_neighbor_search` would first
build a tree over all the points for these few queries, and its ties would not be broken by
height.

The triangles that join the polygon to the points (the "skirt") are not part of the terrain:
drop them with `drop_boundary_triangles(true)`.

\tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
\param points the points
\param np optional `point_map`
\param margin the margin, relative to the larger side of the footprint
\param vertices_per_side the number of edges of each side of the polygon
\throws Input_error with code `EMPTY_INPUT`, `NON_FINITE_COORDINATE`,
`DEGENERATE_POINT_SET` when the footprint is a single point, or `TOO_LARGE` when the
footprint with its margin exceeds the range of doubles.
*/
template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
std::vector<typename boost::property_traits<typename GetPointMap<PointRange, NamedParameters>::const_type>::value_type>
footprint_boundary(const PointRange& points, const NamedParameters& np = parameters::default_values(),
                   double margin = 0.05, int vertices_per_side = 16)
{
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Point = typename boost::property_traits<Point_map>::value_type;
  const Point_map point_map = parameters::choose_parameter<Point_map>(parameters::get_parameter(np, CGAL::internal_np::point_map));
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin;
  double xmax = -xmin, ymax = -xmin;
  std::size_t n = 0;
  for(const auto& e : points) {
    const Point& p = get(point_map, e);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(Input_error_code::NON_FINITE_COORDINATE, "a point has a NaN or infinite coordinate");
    xmin = (std::min)(xmin, p.x()); xmax = (std::max)(xmax, p.x());
    ymin = (std::min)(ymin, p.y()); ymax = (std::max)(ymax, p.y());
    ++n;
  }
  if(n == 0) throw Input_error(Input_error_code::EMPTY_INPUT, "no input point");
  const double side = (std::max)(xmax - xmin, ymax - ymin);
  if(!(side > 0))
    throw Input_error(Input_error_code::DEGENERATE_POINT_SET, "all points have the same x and y: no footprint");
  if(!(margin > 0) || vertices_per_side < 1)
    throw Input_error(Input_error_code::DEGENERATE_POINT_SET, "the margin and the number of vertices per side must be positive");
  const double m = margin * side;
  // corners of the enlarged rectangle, counterclockwise, and the outward normal of each side
  const double cx[4] = {xmin - m, xmax + m, xmax + m, xmin - m};
  const double cy[4] = {ymin - m, ymin - m, ymax + m, ymax + m};
  if(!std::isfinite(side) || !std::isfinite(cx[0]) || !std::isfinite(cx[1]) || !std::isfinite(cy[0]) ||
     !std::isfinite(cy[2]))
    throw Input_error(Input_error_code::TOO_LARGE,
                      "the footprint with its margin exceeds the range of doubles: scale the points");
  // the squared distances below are taken in units of a power of two near the side (an exact
  // scaling), so that they neither overflow nor underflow and the nearest points do not change
  // when the input is scaled by a power of two
  int exponent = 0;
  std::frexp(side, &exponent);
  double unit = std::ldexp(1.0, -exponent);
  if(!std::isnormal(unit)) unit = exponent > 0 ? std::ldexp(1.0, -1022) : std::ldexp(1.0, 1022);
  const double nx[4] = {0, 1, 0, -1}, ny[4] = {-1, 0, 1, 0};
  std::vector<std::array<double, 2>> xy;
  for(int s = 0; s < 4; ++s) {
    const int e = (s + 1) % 4;
    for(int k = 0; k < vertices_per_side; ++k) {
      const double t = double(k) / vertices_per_side;
      const double bulge = 0.5 * m * 4 * t * (1 - t);
      xy.push_back({{cx[s] + t * (cx[e] - cx[s]) + bulge * nx[s], cy[s] + t * (cy[e] - cy[s]) + bulge * ny[s]}});
    }
  }
  // the 64 points nearest to each vertex in the xy-plane, as (squared distance, height) pairs
  // kept in a max-heap: the smallest pairs, whatever the order of the points
  constexpr std::size_t k = 64;
  std::vector<std::vector<std::pair<double, double>>> nearest(xy.size());
  for(const auto& e : points) {
    const Point& p = get(point_map, e);
    for(std::size_t v = 0; v < xy.size(); ++v) {
      const double dx = (p.x() - xy[v][0]) * unit, dy = (p.y() - xy[v][1]) * unit;
      const std::pair<double, double> candidate(dx * dx + dy * dy, p.z());
      std::vector<std::pair<double, double>>& heap = nearest[v];
      if(heap.size() < k) {
        heap.push_back(candidate);
        std::push_heap(heap.begin(), heap.end());
      } else if(candidate < heap.front()) {
        std::pop_heap(heap.begin(), heap.end());
        heap.back() = candidate;
        std::push_heap(heap.begin(), heap.end());
      }
    }
  }
  std::vector<Point> polygon;
  for(std::size_t v = 0; v < xy.size(); ++v) {
    std::vector<double> heights;
    for(const auto& c : nearest[v]) heights.push_back(c.second);
    std::sort(heights.begin(), heights.end());
    polygon.emplace_back(xy[v][0], xy[v][1], heights[heights.size() / 10] - 0.001 * side);
  }
  polygon.push_back(polygon.front());
  return polygon;
}

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_FOOTPRINT_BOUNDARY_H
