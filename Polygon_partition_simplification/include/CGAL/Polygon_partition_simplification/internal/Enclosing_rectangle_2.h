// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_ENCLOSING_RECTANGLE_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_ENCLOSING_RECTANGLE_2_H

// The smallest-area enclosing rectangle of a point set (CGAL::min_rectangle_2 on its convex
// hull). It moves with the points under rigid motions and scalings, so the normalized frame
// and the bounding box of a kinetic partition do too. `PK`: the exact predicates kernel of the
// geometric traits (double coordinates, exact predicates).

#include <CGAL/convex_hull_2.h>
#include <CGAL/min_quadrilateral_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

struct Enclosing_rectangle_2
{
  std::array<double, 2> center{{0, 0}};
  std::array<double, 2> axis{{1, 0}};          // unit direction of the first side
  std::array<double, 2> half_extent{{0, 0}};   // along axis, along its normal
  double half_diagonal() const { return std::hypot(half_extent[0], half_extent[1]); }

  // the four corners, counterclockwise, after moving the sides across the axis outward by
  // `margin` and the two others by `margin_across`
  std::array<std::array<double, 2>, 4> corners(double margin, double margin_across) const
  {
    const double u0 = axis[0], u1 = axis[1];
    const double hu = half_extent[0] + margin, hv = half_extent[1] + margin_across;
    std::array<std::array<double, 2>, 4> result;
    const double su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
    for(int i = 0; i < 4; ++i)
      result[i] = {center[0] + su[i] * hu * u0 - sv[i] * hv * u1,
                   center[1] + su[i] * hu * u1 + sv[i] * hv * u0};
    return result;
  }
};

// The corners of `rectangle` with its sides moved out by `margin`, and the margin of the sides
// across its axis. A segment's line through a corner (a diagonal of a square), or within
// rounding errors of it, would meet the rectangle at a point that its corner rounds to, or
// next to it: the sides across the axis are moved out a little farther (up to 16 times 1/8 of
// their margin) until every corner is at least 1e-6 half-diagonals from the line of every
// segment that does not pass exactly through it. A corner moves along the sides of the axis,
// which no line near it is parallel to (the segments are inside the rectangle).
template <class PK>
std::pair<std::array<std::array<double, 2>, 4>, double>
corners_off_lines(const Enclosing_rectangle_2& rectangle, double margin, const std::vector<std::array<double, 4>>& segments)
{
  using K = PK;
  const double half_diagonal = rectangle.half_diagonal();
  double margin_across = margin;
  auto corners = rectangle.corners(margin, margin_across);
  auto near_a_line = [&]() {
    for(const auto& q : corners)
      for(const auto& c : segments) {
        const double dx = c[2] - c[0], dy = c[3] - c[1];
        if(std::abs(dx * (q[1] - c[1]) - dy * (q[0] - c[0])) <= 1e-6 * half_diagonal * std::hypot(dx, dy) &&
           CGAL::orientation(typename K::Point_2(c[0], c[1]), typename K::Point_2(c[2], c[3]),
                             typename K::Point_2(q[0], q[1])) != CGAL::COLLINEAR)
          return true;
      }
    return false;
  };
  for(int attempt = 0; attempt < 16 && near_a_line(); ++attempt) {
    margin_across *= 1.125;
    corners = rectangle.corners(margin, margin_across);
  }
  return {corners, margin_across};
}

// Whether `r` holds every point of `hull` (up to 1e-9 of its half-diagonal). CGAL's
// min_rectangle_2() constructs the corners in double: with tiny coordinates (products that
// underflow) they can leave points out.
template <class Point>
bool holds(const Enclosing_rectangle_2& r, const std::vector<Point>& hull)
{
  const double slack = 1e-9 * r.half_diagonal();
  for(const Point& q : hull) {
    const double x = q.x() - r.center[0], y = q.y() - r.center[1];
    const double s = x * r.axis[0] + y * r.axis[1], t = -x * r.axis[1] + y * r.axis[0];
    if(!(std::abs(s) <= r.half_extent[0] + slack && std::abs(t) <= r.half_extent[1] + slack)) return false;
  }
  return true;
}

// The rectangle of `hull` along `axis` (a unit vector): the extents of the projections of the
// points, measured from the first point (differences of nearby coordinates are exact), widened
// by 8 units in the last place of the largest coordinate (the rounding of the center to the
// doubles moves the sides by that much) and 1e-8 of the extent, and again, doubled, until it
// holds every point.
template <class Point>
Enclosing_rectangle_2 rectangle_along(const std::array<double, 2>& axis, const std::vector<Point>& hull)
{
  const double x0 = hull[0].x(), y0 = hull[0].y();
  double low[2] = {0, 0}, high[2] = {0, 0};
  for(const Point& q : hull) {
    const double x = q.x() - x0, y = q.y() - y0;
    const double st[2] = {x * axis[0] + y * axis[1], -x * axis[1] + y * axis[0]};
    for(int k = 0; k < 2; ++k) { low[k] = std::min(low[k], st[k]); high[k] = std::max(high[k], st[k]); }
  }
  double largest = 0;
  for(const Point& q : hull) largest = std::max({largest, std::abs(double(q.x())), std::abs(double(q.y()))});
  double widening = 8 * (std::nextafter(largest, HUGE_VAL) - largest) +
                    1e-8 * std::max(high[0] - low[0], high[1] - low[1]);
  Enclosing_rectangle_2 r;
  r.axis = axis;
  const double s = (low[0] + high[0]) / 2, t = (low[1] + high[1]) / 2;
  r.center = {x0 + s * axis[0] - t * axis[1], y0 + s * axis[1] + t * axis[0]};
  for(int attempt = 0; attempt < 16; ++attempt, widening *= 2) {
    r.half_extent = {(high[0] - low[0]) / 2 + widening, (high[1] - low[1]) / 2 + widening};
    if(holds(r, hull)) break;
  }
  return r;
}

template <class PK>
Enclosing_rectangle_2 enclosing_rectangle(const std::vector<std::array<double, 2>>& points)
{
  using K = PK;
  std::vector<typename K::Point_2> p, hull;
  p.reserve(points.size());
  for(const auto& q : points) p.emplace_back(q[0], q[1]);
  CGAL::convex_hull_2(p.begin(), p.end(), std::back_inserter(hull));
  Enclosing_rectangle_2 r;
  if(hull.size() >= 3) {
    std::vector<typename K::Point_2> c;
    CGAL::min_rectangle_2(hull.begin(), hull.end(), std::back_inserter(c));
    const double dx = c[1].x() - c[0].x(), dy = c[1].y() - c[0].y(), n = std::hypot(dx, dy);
    const double m = std::hypot(c[2].x() - c[1].x(), c[2].y() - c[1].y());
    // A nearly flat hull (points collinear but for the roundings of their coordinates) can
    // give a rectangle whose first side rounds to a point (its corners are constructed in
    // double): then it is treated as the flat case below.
    if(n > 0 && std::isfinite(n) && std::isfinite(m)) {
      r.axis = {dx / n, dy / n};
      r.center = {(c[0].x() + c[2].x()) / 2, (c[0].y() + c[2].y()) / 2};
      r.half_extent = {n / 2, m / 2};
      return holds(r, hull) ? r : rectangle_along(r.axis, hull);
    }
  }
  // collinear points (or nearly): the rectangle of their extreme points, flat
  const auto [lo, hi] = std::minmax_element(p.begin(), p.end());
  const double dx = hi->x() - lo->x(), dy = hi->y() - lo->y(), n = std::hypot(dx, dy);
  r.center = {(lo->x() + hi->x()) / 2, (lo->y() + hi->y()) / 2};
  if(n > 0) r.axis = {dx / n, dy / n};
  r.half_extent = {n / 2, 0};
  return r;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_ENCLOSING_RECTANGLE_2_H
