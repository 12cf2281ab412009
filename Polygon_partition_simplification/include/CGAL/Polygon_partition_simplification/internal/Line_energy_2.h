// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_ENERGY_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_ENERGY_2_H

// The energy of section 3.3.3 and its Riemannian gradient (section 3.3.4):
//   E(L) = 1/2 sum_i L_i^T M_i L_i + lambda1 sum_T min(eps, |det(L_i, L_j, L_k)|)
//                                 + lambda2 sum_P min(sin alpha_max, |a_i a_j + b_i b_j|)
// M_i carries the l_min^2 term of Eq. 3.5 (once per segment accumulated in the metric).
// The gradient of line i on the cylinder a^2 + b^2 = 1 is U_i (U_i^T M_i U_i)^-1 U_i^T D_i^T
// with U_i = [[-b, 0], [a, 0], [0, 1]] and D_i = dE/dL_i (Eq. 3.13); a step is
// L_i <- normalize(L_i - alpha grad_i) (Eq. 3.14). Fixed (and frozen) lines do not move.

#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

struct Energy_weights
{
  double concurrency_weight = 0;   // lambda1
  double orthogonality_weight = 0; // lambda2
  double collapse_distance = 0;    // epsilon (normalized frame)
  double sin_maximum_angle = 0;    // sin(alpha_max)
  double minimum_length = 0;       // l_min (normalized frame)
};

// The terms of the energy, from the combinatorial structure.
struct Energy_terms
{
  std::vector<std::array<std::uint32_t, 3>> triplets; // (i, j, k): points P_ij and P_ik on line i
  std::vector<std::array<std::uint32_t, 2>> pairs;    // lines meeting at a point
};

struct Line_state
{
  Vector_3d coefficients;
  Line_metric metric;
  std::size_t number_of_segments = 0;
  bool is_fixed = false;
  bool is_frozen = false;     // kept still for one round (it took part in an invalid move)
  std::vector<std::uint32_t> members; // lines of the round's start merged into this one
  bool is_still() const { return is_fixed || is_frozen; }
};

inline double metric_entry(const Line_state& l, const Energy_weights& w, int r, int c)
{
  double m = l.metric(r, c);
  if(r == c && r < 2) m += 0.5 * w.minimum_length * w.minimum_length * double(l.number_of_segments);
  return m;
}

inline double fidelity(const Line_state& l, const Energy_weights& w)
{
  double e = 0;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c)
      e += l.coefficients[r] * metric_entry(l, w, r, c) * l.coefficients[c];
  return 0.5 * e;
}

inline double energy(const std::vector<Line_state>& lines, const Energy_terms& terms,
                     const Energy_weights& w)
{
  double fid = 0, conc = 0, orth = 0;
  for(const Line_state& l : lines) fid += fidelity(l, w);
  for(const auto& t : terms.triplets)
    conc += std::min(w.collapse_distance,
                     std::abs(determinant(lines[t[0]].coefficients, lines[t[1]].coefficients,
                                          lines[t[2]].coefficients)));
  for(const auto& p : terms.pairs) {
    const Vector_3d& a = lines[p[0]].coefficients;
    const Vector_3d& b = lines[p[1]].coefficients;
    orth += std::min(w.sin_maximum_angle, std::abs(a[0] * b[0] + a[1] * b[1]));
  }
  return fid + w.concurrency_weight * conc + w.orthogonality_weight * orth;
}

// D_i = dE/dL_i for every line (Euclidean derivative in homogeneous coordinates).
inline void derivative(const std::vector<Line_state>& lines, const Energy_terms& terms,
                       const Energy_weights& w, std::vector<Vector_3d>& d)
{
  d.assign(lines.size(), Vector_3d{{0, 0, 0}});
  for(std::size_t i = 0; i < lines.size(); ++i)
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c)
        d[i][r] += metric_entry(lines[i], w, r, c) * lines[i].coefficients[c];
  for(const auto& t : terms.triplets) {
    const Vector_3d& a = lines[t[0]].coefficients;
    const Vector_3d& b = lines[t[1]].coefficients;
    const Vector_3d& c = lines[t[2]].coefficients;
    const Vector_3d bc = cross(b, c);
    const double det = dot(a, bc);
    if(!(std::abs(det) < w.collapse_distance) || det == 0) continue;
    const double s = det > 0 ? w.concurrency_weight : -w.concurrency_weight;
    const Vector_3d ca = cross(c, a), ab = cross(a, b);
    for(int r = 0; r < 3; ++r) {
      d[t[0]][r] += s * bc[r];
      d[t[1]][r] += s * ca[r];
      d[t[2]][r] += s * ab[r];
    }
  }
  for(const auto& p : terms.pairs) {
    const Vector_3d& a = lines[p[0]].coefficients;
    const Vector_3d& b = lines[p[1]].coefficients;
    const double dotp = a[0] * b[0] + a[1] * b[1];
    if(!(std::abs(dotp) < w.sin_maximum_angle) || dotp == 0) continue;
    const double s = dotp > 0 ? w.orthogonality_weight : -w.orthogonality_weight;
    d[p[0]][0] += s * b[0]; d[p[0]][1] += s * b[1];
    d[p[1]][0] += s * a[0]; d[p[1]][1] += s * a[1];
  }
}

// Riemannian gradient of line i (Eq. 3.13) from its derivative D_i.
inline Vector_3d riemannian_gradient(const Line_state& l, const Energy_weights& w, const Vector_3d& d)
{
  const double a = l.coefficients[0], b = l.coefficients[1];
  // D' = D U, M' = U^T M U with U = [[-b, 0], [a, 0], [0, 1]]
  const double d0 = -b * d[0] + a * d[1], d1 = d[2];
  const double m00 = b * b * metric_entry(l, w, 0, 0) - 2 * a * b * metric_entry(l, w, 0, 1) +
                     a * a * metric_entry(l, w, 1, 1);
  const double m01 = -b * metric_entry(l, w, 0, 2) + a * metric_entry(l, w, 1, 2);
  const double m11 = metric_entry(l, w, 2, 2);
  const double det = m00 * m11 - m01 * m01;
  const double g0 = (m11 * d0 - m01 * d1) / det, g1 = (-m01 * d0 + m00 * d1) / det;
  return {-b * g0, a * g0, g1};
}

// The terms each line takes part in, and the order in which lines move (built once per
// descent): by decreasing spread of the segment endpoints of their metric (a quantity that
// rigid motions and scalings of the input do not change), then by index.
struct Line_incidence
{
  std::vector<std::vector<std::uint32_t>> triplets, pairs; // indices into the terms, per line
  std::vector<std::uint32_t> order;

  Line_incidence(const std::vector<Line_state>& lines, const Energy_terms& terms)
    : triplets(lines.size()), pairs(lines.size()), order(lines.size())
  {
    for(std::uint32_t t = 0; t < terms.triplets.size(); ++t)
      for(std::uint32_t l : terms.triplets[t]) triplets[l].push_back(t);
    for(std::uint32_t p = 0; p < terms.pairs.size(); ++p)
      for(std::uint32_t l : terms.pairs[p]) pairs[l].push_back(p);
    std::vector<double> spread(lines.size(), 0);
    for(std::size_t i = 0; i < lines.size(); ++i) {
      const Line_metric& m = lines[i].metric;
      const double n = m(2, 2);
      if(n > 0) spread[i] = m(0, 0) + m(1, 1) - (m(0, 2) * m(0, 2) + m(1, 2) * m(1, 2)) / n;
    }
    for(std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return spread[x] > spread[y]; });
  }
};

// D_i = dE/dL_i for one line.
inline Vector_3d line_derivative(const std::vector<Line_state>& lines, const Energy_terms& terms,
                                 const Line_incidence& incidence, const Energy_weights& w, std::size_t i)
{
  Vector_3d d{{0, 0, 0}};
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) d[r] += metric_entry(lines[i], w, r, c) * lines[i].coefficients[c];
  for(std::uint32_t t : incidence.triplets[i]) {
    const auto& x = terms.triplets[t];
    // det(L_i, L_j, L_k) up to the sign of the permutation: use the cyclic order from i
    const std::size_t at = x[0] == i ? 0 : (x[1] == i ? 1 : 2);
    const Vector_3d& b = lines[x[(at + 1) % 3]].coefficients;
    const Vector_3d& c = lines[x[(at + 2) % 3]].coefficients;
    const Vector_3d bc = cross(b, c);
    const double det = dot(lines[i].coefficients, bc);
    if(!(std::abs(det) < w.collapse_distance) || det == 0) continue;
    const double s = det > 0 ? w.concurrency_weight : -w.concurrency_weight;
    for(int r = 0; r < 3; ++r) d[r] += s * bc[r];
  }
  for(std::uint32_t p : incidence.pairs[i]) {
    const auto& x = terms.pairs[p];
    const Vector_3d& a = lines[i].coefficients;
    const Vector_3d& b = lines[x[0] == i ? x[1] : x[0]].coefficients;
    const double dotp = a[0] * b[0] + a[1] * b[1];
    if(!(std::abs(dotp) < w.sin_maximum_angle) || dotp == 0) continue;
    const double s = dotp > 0 ? w.orthogonality_weight : -w.orthogonality_weight;
    d[0] += s * b[0];
    d[1] += s * b[1];
  }
  return d;
}

// One gradient step (Eq. 3.14) of every free line, in turn (`incidence.order`): each line
// sees the lines before it already moved (Gauss-Seidel order). This breaks symmetric configurations
// (the regular 360-gon of section 3.3.1) deterministically. Returns false, with the line
// unchanged, if a gradient is not finite.
inline bool gradient_step(std::vector<Line_state>& lines, const Energy_terms& terms,
                          const Line_incidence& incidence, const Energy_weights& w, double step)
{
  for(std::size_t i : incidence.order) {
    if(lines[i].is_still()) continue;
    const Vector_3d g = riemannian_gradient(lines[i], w, line_derivative(lines, terms, incidence, w, i));
    if(!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2])) return false;
    Vector_3d& l = lines[i].coefficients;
    l = normalized_line({l[0] - step * g[0], l[1] - step * g[1], l[2] - step * g[2]});
  }
  return true;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_ENERGY_2_H
