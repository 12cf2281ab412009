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

#include <boost/container/small_vector.hpp>

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
  boost::container::small_vector<std::uint32_t, 2> members; // lines of the round's start merged into this one
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

// Entries xx, xy, x, yy, y, 1 of the metric of a line with its l_min term.
inline std::array<double, 6> effective_metric(const Line_state& l, const Energy_weights& w)
{
  std::array<double, 6> m;
  for(int r = 0, k = 0; r < 3; ++r)
    for(int c = r; c < 3; ++c) m[k++] = metric_entry(l, w, r, c);
  return m;
}

// Riemannian gradient (Eq. 3.13) of the line L with effective metric M from its derivative D.
inline Vector_3d riemannian_gradient(const Vector_3d& L, const std::array<double, 6>& M, const Vector_3d& d)
{
  const double a = L[0], b = L[1];
  // D' = D U, M' = U^T M U with U = [[-b, 0], [a, 0], [0, 1]]
  const double d0 = -b * d[0] + a * d[1], d1 = d[2];
  const double m00 = b * b * M[0] - 2 * a * b * M[1] + a * a * M[3];
  const double m01 = -b * M[2] + a * M[4];
  const double m11 = M[5];
  const double det = m00 * m11 - m01 * m01;
  const double g0 = (m11 * d0 - m01 * d1) / det, g1 = (-m01 * d0 + m00 * d1) / det;
  return {-b * g0, a * g0, g1};
}

inline Vector_3d riemannian_gradient(const Line_state& l, const Energy_weights& w, const Vector_3d& d)
{
  return riemannian_gradient(l.coefficients, effective_metric(l, w), d);
}

// A descent: the gradient steps of Eq. 3.14 with the combinatorial structure fixed. The
// terms are laid out per moving line (compressed rows: the two other lines of each triplet,
// in the cyclic order that gives det(L_i, L_j, L_k) its sign, and the other line of each
// pair), with the effective metric of each line (l_min term included), so that a step reads
// contiguous memory only. Lines move in turn, by decreasing spread of the segment endpoints
// of their metric (a quantity that rigid motions and scalings of the input do not change),
// then by index; each line sees the lines before it already moved (Gauss-Seidel order),
// which breaks symmetric configurations (the regular 360-gon of section 3.3.1)
// deterministically.
class Line_descent
{
public:
  // `resting` (if not empty): lines that do not move either
  Line_descent(const std::vector<Line_state>& lines, const Energy_terms& terms, const Energy_weights& w,
               const std::vector<bool>& resting = {})
    : w_(w), concurrency_{0, -w.concurrency_weight, w.concurrency_weight},
      orthogonality_{0, -w.orthogonality_weight, w.orthogonality_weight}, coefficients_(lines.size())
  {
    const std::size_t n = lines.size();
    for(std::size_t i = 0; i < n; ++i) coefficients_[i] = lines[i].coefficients;
    std::vector<std::uint32_t> triplet_count(n + 1, 0), pair_count(n + 1, 0);
    for(const auto& t : terms.triplets) for(std::uint32_t l : t) ++triplet_count[l + 1];
    for(const auto& p : terms.pairs) for(std::uint32_t l : p) ++pair_count[l + 1];
    for(std::size_t i = 0; i < n; ++i) {
      triplet_count[i + 1] += triplet_count[i];
      pair_count[i + 1] += pair_count[i];
    }
    std::vector<std::array<std::uint32_t, 2>> triplet_partners(triplet_count[n]);
    std::vector<std::uint32_t> pair_partners(pair_count[n]);
    {
      std::vector<std::uint32_t> next(triplet_count.begin(), triplet_count.end() - 1);
      for(const auto& t : terms.triplets)
        for(int at = 0; at < 3; ++at) triplet_partners[next[t[at]]++] = {t[(at + 1) % 3], t[(at + 2) % 3]};
      next.assign(pair_count.begin(), pair_count.end() - 1);
      for(const auto& p : terms.pairs) {
        pair_partners[next[p[0]]++] = p[1];
        pair_partners[next[p[1]]++] = p[0];
      }
    }
    std::vector<double> spread(n, 0);
    for(std::size_t i = 0; i < n; ++i) {
      const Line_metric& m = lines[i].metric;
      const double c = m(2, 2);
      if(c > 0) spread[i] = m(0, 0) + m(1, 1) - (m(0, 2) * m(0, 2) + m(1, 2) * m(1, 2)) / c;
    }
    std::vector<std::uint32_t> order;
    for(std::uint32_t i = 0; i < n; ++i)
      if(!lines[i].is_still() && (resting.empty() || !resting[i])) order.push_back(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return spread[x] > spread[y]; });
    // rows in the order of the moves
    for(std::uint32_t i : order) {
      Moving_line m;
      m.line = i;
      m.metric = effective_metric(lines[i], w);
      m.first_triplet = std::uint32_t(triplet_partners_.size());
      triplet_partners_.insert(triplet_partners_.end(), triplet_partners.begin() + triplet_count[i],
                               triplet_partners.begin() + triplet_count[i + 1]);
      m.first_pair = std::uint32_t(pair_partners_.size());
      pair_partners_.insert(pair_partners_.end(), pair_partners.begin() + pair_count[i],
                            pair_partners.begin() + pair_count[i + 1]);
      moving_.push_back(m);
    }
    end_triplets_ = std::uint32_t(triplet_partners_.size());
    end_pairs_ = std::uint32_t(pair_partners_.size());
  }

  // One gradient step of every free line, in turn. Returns false, with the lines from the
  // one whose gradient or new coordinates are not finite unchanged, if there is one.
  bool step(double alpha)
  {
    // Whether a term is constant (|det| >= eps) rarely changes from step to step: a branch on
    // it skips the constant terms, and the branch predictor learns the pattern while the
    // moving lines are few; with many, the pattern is too long to be learnt, and a lookup
    // without a branch is faster.
    return moving_.size() <= 2048 ? step_with<true>(alpha) : step_with<false>(alpha);
  }

  // D_i = dE/dL_i of the m-th moving line
  Vector_3d derivative(std::size_t m) const { return derivative_with<false>(m); }

  // the Riemannian gradient (Eq. 3.13) of the m-th moving line
  Vector_3d gradient(std::size_t m) const
  {
    return riemannian_gradient(coefficients_[moving_[m].line], moving_[m].metric, derivative(m));
  }

  std::size_t number_of_moving_lines() const { return moving_.size(); }
  std::size_t moving_line(std::size_t m) const { return moving_[m].line; }
  const std::vector<Vector_3d>& coefficients() const { return coefficients_; }

private:
  // which weight a term min(threshold, |x|) gives its derivative: 0 (constant term, or x = 0:
  // no direction), 1 (-lambda, x < 0) or 2 (+lambda, x > 0)
  static int term_case(double x, double threshold)
  {
    return int(std::abs(x) < threshold) * (2 * int(x > 0) + int(x < 0));
  }

  template <bool skip_constant_terms>
  bool step_with(double alpha)
  {
    for(std::size_t m = 0; m < moving_.size(); ++m) {
      const Vector_3d g = riemannian_gradient(coefficients_[moving_[m].line], moving_[m].metric,
                                              derivative_with<skip_constant_terms>(m));
      Vector_3d& l = coefficients_[moving_[m].line];
      const Vector_3d moved = normalized_line({l[0] - alpha * g[0], l[1] - alpha * g[1], l[2] - alpha * g[2]});
      if(!std::isfinite(moved[0]) || !std::isfinite(moved[1]) || !std::isfinite(moved[2])) return false;
      l = moved;
    }
    return true;
  }

  // The same sums with or without a branch on the constant terms (adding 0 changes nothing).
  // The sign of an active term by a lookup, not a branch: it changes from step to step in the
  // kinks of |det|, where a branch on it would often be mispredicted.
  template <bool skip_constant_terms>
  Vector_3d derivative_with(std::size_t m) const
  {
    const Moving_line& row = moving_[m];
    const Vector_3d& L = coefficients_[row.line];
    const auto& M = row.metric; // xx xy x yy y 1
    Vector_3d d{{M[0] * L[0] + M[1] * L[1] + M[2] * L[2], M[1] * L[0] + M[3] * L[1] + M[4] * L[2],
                 M[2] * L[0] + M[4] * L[1] + M[5] * L[2]}};
    const std::uint32_t end_t = m + 1 < moving_.size() ? moving_[m + 1].first_triplet : end_triplets_;
    for(std::uint32_t t = row.first_triplet; t < end_t; ++t) {
      const Vector_3d bc = cross(coefficients_[triplet_partners_[t][0]], coefficients_[triplet_partners_[t][1]]);
      const double det = dot(L, bc);
      double s;
      if constexpr(skip_constant_terms) {
        if(!(std::abs(det) < w_.collapse_distance) || det == 0) continue;
        s = concurrency_[1 + int(det > 0)];
      } else s = concurrency_[term_case(det, w_.collapse_distance)];
      d[0] += s * bc[0]; d[1] += s * bc[1]; d[2] += s * bc[2];
    }
    const std::uint32_t end_p = m + 1 < moving_.size() ? moving_[m + 1].first_pair : end_pairs_;
    for(std::uint32_t p = row.first_pair; p < end_p; ++p) {
      const Vector_3d& b = coefficients_[pair_partners_[p]];
      const double dotp = L[0] * b[0] + L[1] * b[1];
      double s;
      if constexpr(skip_constant_terms) {
        if(!(std::abs(dotp) < w_.sin_maximum_angle) || dotp == 0) continue;
        s = orthogonality_[1 + int(dotp > 0)];
      } else s = orthogonality_[term_case(dotp, w_.sin_maximum_angle)];
      d[0] += s * b[0]; d[1] += s * b[1];
    }
    return d;
  }

  struct Moving_line
  {
    std::array<double, 6> metric; // effective metric: xx xy x yy y 1
    std::uint32_t line = 0;
    std::uint32_t first_triplet = 0, first_pair = 0;
  };
  Energy_weights w_;
  double concurrency_[3], orthogonality_[3]; // 0, -lambda, +lambda (indexed by term_case)
  std::vector<Vector_3d> coefficients_;
  std::vector<Moving_line> moving_;
  std::vector<std::array<std::uint32_t, 2>> triplet_partners_;
  std::vector<std::uint32_t> pair_partners_;
  std::uint32_t end_triplets_ = 0, end_pairs_ = 0;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_ENERGY_2_H
