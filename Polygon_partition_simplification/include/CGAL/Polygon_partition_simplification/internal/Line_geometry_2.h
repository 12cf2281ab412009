// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_GEOMETRY_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_GEOMETRY_2_H

// Homogeneous line and point arithmetic in double precision (section 3.3.2 of the thesis):
// a line is (a, b, c) with a x + b y + c = 0, kept in Euclidean normal form a^2 + b^2 = 1;
// the intersection of two lines is their cross product.

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

using Vector_3d = std::array<double, 3>;

inline Vector_3d cross(const Vector_3d& u, const Vector_3d& v)
{
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

inline double dot(const Vector_3d& u, const Vector_3d& v)
{
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

/// det(L_i, L_j, L_k) = (L_i x L_j) . L_k
inline double determinant(const Vector_3d& u, const Vector_3d& v, const Vector_3d& w)
{
  return dot(cross(u, v), w);
}

/// Euclidean normal form: divides by sqrt(a^2 + b^2).
inline Vector_3d normalized_line(const Vector_3d& l)
{
  const double n = std::sqrt(l[0] * l[0] + l[1] * l[1]);
  return {l[0] / n, l[1] / n, l[2] / n};
}

/// The line through two points, in normal form, oriented so that (p, q) runs along (-b, a).
inline Vector_3d line_through(double px, double py, double qx, double qy)
{
  return normalized_line({py - qy, qx - px, px * qy - py * qx});
}

/// Distance between two normalized lines as points of R^3, the smaller over the two
/// orientations (a line and its opposite are the same line).
inline double line_distance(const Vector_3d& u, const Vector_3d& v)
{
  double plus = 0, minus = 0;
  for(int c = 0; c < 3; ++c) {
    plus += (u[c] - v[c]) * (u[c] - v[c]);
    minus += (u[c] + v[c]) * (u[c] + v[c]);
  }
  return std::sqrt(std::min(plus, minus));
}

/// The point of a set of lines: their intersection for two lines, the least-squares point
/// (minimizing the sum of squared distances to the lines) for more (lines merged at a point
/// are not exactly concurrent). A fixed line (`is_fixed(id)`: a side of the bounding
/// rectangle, which never moves) keeps its points: on two fixed lines the point is their
/// intersection, on one it is the point of that line nearest to the others (least squares
/// along it), so that the cells still tile the rectangle.
template <class IndexRange, class LineAccess, class FixedAccess>
std::array<double, 2> point_of_lines(const IndexRange& ids, const LineAccess& line, const FixedAccess& is_fixed)
{
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  auto meet = [](const Vector_3d& u, const Vector_3d& v) -> std::array<double, 2> {
    const Vector_3d p = cross(u, v);
    return {p[0] / p[2], p[1] / p[2]};
  };
  if(ids.size() == 2) return meet(line(ids[0]), line(ids[1]));
  std::size_t fixed[2], nfixed = 0;
  for(std::size_t i = 0; i < ids.size() && nfixed < 2; ++i)
    if(is_fixed(ids[i])) fixed[nfixed++] = i;
  if(nfixed == 2) return meet(line(ids[fixed[0]]), line(ids[fixed[1]]));
  if(nfixed == 1) {
    // p(t) = p0 + t d on the fixed line f; each other line g is at signed distance
    // g(p0) + t g(d) (g normalized): t minimizes the sum of their squares
    const Vector_3d& f = line(ids[fixed[0]]);
    const double nn = f[0] * f[0] + f[1] * f[1];
    const double p0[2] = {-f[2] * f[0] / nn, -f[2] * f[1] / nn};
    const double d[2] = {-f[1], f[0]};
    double sab = 0, sbb = 0;
    for(auto id : ids) {
      if(id == ids[fixed[0]]) continue;
      const Vector_3d& g = line(id);
      const double a = g[0] * p0[0] + g[1] * p0[1] + g[2], b = g[0] * d[0] + g[1] * d[1];
      sab += a * b;
      sbb += b * b;
    }
    if(sbb == 0) return {nan, nan}; // all the lines parallel
    const double t = -sab / sbb;
    return {p0[0] + t * d[0], p0[1] + t * d[1]};
  }
  double saa = 0, sab = 0, sbb = 0, sac = 0, sbc = 0;
  for(auto id : ids) {
    const Vector_3d& l = line(id);
    saa += l[0] * l[0]; sab += l[0] * l[1]; sbb += l[1] * l[1];
    sac += l[0] * l[2]; sbc += l[1] * l[2];
  }
  const double det = saa * sbb - sab * sab;
  if(det == 0) return {nan, nan};
  return {(-sac * sbb + sbc * sab) / det, (-sbc * saa + sac * sab) / det};
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_GEOMETRY_2_H
