// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TRIANGLE_ORDER_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TRIANGLE_ORDER_3_H

// The total order on triangles of Lemma 4.14 (thesis l.2871), evaluated exactly:
//   sigma1 < sigma2  iff  R_B(sigma1) < R_B(sigma2),
//                      or R_B equal and R_C(sigma1) > R_C(sigma2),
//                      or both radii equal and the lexicographically sorted vertex
//                         triple of sigma1 is smaller (symbolic tie-break).
// R_B is the radius of the smallest enclosing ball, R_C the circumradius. Everything is
// compared on squared radii written as fractions of polynomials in the coordinates, first
// with interval arithmetic, then, when the intervals cannot decide, exactly (the fractions are
// compared by cross products: ring operations, exact in CGAL's exact ring type for doubles).

#include <CGAL/Number_types/internal/Exact_type_selector.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

using Coordinates_3 = std::array<double, 3>;
using Triangle_coordinates_3 = std::array<Coordinates_3, 3>;

// Squared radii as fractions: rb2 = rb_num / rb_den (rb_den > 0), rc2 = rc_num / rc_den
// (rc_den >= 0, zero for a degenerate triangle, whose circumradius is infinite).
// `longest` is the index of the longest edge of an obtuse triangle (edge i is opposite
// vertex i), -1 for an acute or right one. With Interval_nt, the obtuse test may throw
// Uncertain_conversion_exception.
template <class FT>
struct Squared_radii_3
{
  FT rb_num, rb_den, rc_num, rc_den;
  int longest;
};

template <class FT>
Squared_radii_3<FT> squared_radii(const Triangle_coordinates_3& t)
{
  const Coordinates_3 &p = t[0], &q = t[1], &r = t[2];
  // edge vectors: e0 = r - q (opposite p), e1 = r - p (opposite q), e2 = q - p (opposite r)
  FT e2[3], e1[3], e0[3];
  for(int i = 0; i < 3; ++i) {
    e2[i] = FT(q[i]) - FT(p[i]);
    e1[i] = FT(r[i]) - FT(p[i]);
    e0[i] = FT(r[i]) - FT(q[i]);
  }
  const FT l0 = e0[0] * e0[0] + e0[1] * e0[1] + e0[2] * e0[2];
  const FT l1 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
  const FT l2 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
  const FT nx = e2[1] * e1[2] - e2[2] * e1[1];
  const FT ny = e2[2] * e1[0] - e2[0] * e1[2];
  const FT nz = e2[0] * e1[1] - e2[1] * e1[0];

  Squared_radii_3<FT> res;
  res.rc_num = l0 * l1 * l2;
  res.rc_den = FT(4) * (nx * nx + ny * ny + nz * nz);
  res.rb_den = FT(4);
  if(l0 > l1 + l2)      { res.longest = 0; res.rb_num = l0; }
  else if(l1 > l0 + l2) { res.longest = 1; res.rb_num = l1; }
  else if(l2 > l0 + l1) { res.longest = 2; res.rb_num = l2; }
  else { // acute or right: the smallest enclosing ball is the circumball
    res.longest = -1;
    res.rb_num = res.rc_num;
    res.rb_den = res.rc_den;
  }
  return res;
}

inline bool same_point(const Coordinates_3& a, const Coordinates_3& b) { return a == b; }

// true if edge `i` of `s` and edge `j` of `t` join the same two points
inline bool same_edge(const Triangle_coordinates_3& s, int i, const Triangle_coordinates_3& t, int j)
{
  const Coordinates_3 &a = s[(i + 1) % 3], &b = s[(i + 2) % 3];
  const Coordinates_3 &c = t[(j + 1) % 3], &d = t[(j + 2) % 3];
  return (same_point(a, c) && same_point(b, d)) || (same_point(a, d) && same_point(b, c));
}

template <class FT>
Comparison_result compare_fractions(const FT& n1, const FT& d1, const FT& n2, const FT& d2)
{
  return make_certain(CGAL::compare(n1 * d2, n2 * d1));
}

// Compares the radii part of the order (no tie-break). May throw with Interval_nt.
template <class FT>
Comparison_result compare_radii(const Triangle_coordinates_3& s, const Squared_radii_3<FT>& a,
                                const Triangle_coordinates_3& t, const Squared_radii_3<FT>& b)
{
  // Obtuse triangles that share their longest edge have exactly the same R_B.
  const bool same_rb = a.longest >= 0 && b.longest >= 0 && same_edge(s, a.longest, t, b.longest);
  if(!same_rb) {
    const Comparison_result c = compare_fractions(a.rb_num, a.rb_den, b.rb_num, b.rb_den);
    if(c != EQUAL) return c;
  }
  // R_C reversed; an infinite circumradius (degenerate triangle) is the largest.
  const bool ia = make_certain(CGAL::is_zero(a.rc_den));
  const bool ib = make_certain(CGAL::is_zero(b.rc_den));
  if(ia || ib) return ia == ib ? EQUAL : (ia ? SMALLER : LARGER);
  return compare_fractions(b.rc_num, b.rc_den, a.rc_num, a.rc_den);
}

// Deterministic tie-break: lexicographic comparison of the sorted vertex triples.
inline Comparison_result compare_sorted_vertices(Triangle_coordinates_3 s, Triangle_coordinates_3 t)
{
  std::sort(s.begin(), s.end());
  std::sort(t.begin(), t.end());
  if(s < t) return SMALLER;
  if(t < s) return LARGER;
  return EQUAL;
}

// A triangle with its radii evaluated once with intervals (and once exactly, when a comparison
// needs it), for repeated comparisons.
class Triangle_order_key_3
{
public:
  using Interval = Interval_nt<false>;
  // the exact evaluations use only ring operations on doubles: a floating-point type with an
  // exact multiprecision mantissa (CGAL::Mpzf where available) is exact for them, and much
  // faster than rationals, which reduce every result by a gcd
  using Exact = CGAL::internal::Exact_ring_selector<double>::Type;

  Triangle_order_key_3() = default;

  explicit Triangle_order_key_3(const Triangle_coordinates_3& t) : coordinates_(t)
  {
    Protect_FPU_rounding<true> protection;
    try {
      radii_ = squared_radii<Interval>(t);
      filtered_ = true;
    } catch(Uncertain_conversion_exception&) {
      filtered_ = false; // nearly right triangle: decided exactly at comparison time
    }
  }

  friend Comparison_result compare(const Triangle_order_key_3& a, const Triangle_order_key_3& b)
  {
    // (two keys evaluated exactly already: most likely a tie, which the intervals would only
    // detect by throwing)
    if(a.filtered_ && b.filtered_ && !(a.exact_ && b.exact_)) {
      Protect_FPU_rounding<true> protection;
      try {
        const Comparison_result c = compare_radii(a.coordinates_, a.radii_, b.coordinates_, b.radii_);
        if(c != EQUAL) return c;
        return compare_sorted_vertices(a.coordinates_, b.coordinates_);
      } catch(Uncertain_conversion_exception&) {}
    }
    const Comparison_result c = compare_radii(a.coordinates_, a.exact(), b.coordinates_, b.exact());
    if(c != EQUAL) return c;
    return compare_sorted_vertices(a.coordinates_, b.coordinates_);
  }

  friend bool operator<(const Triangle_order_key_3& a, const Triangle_order_key_3& b)
  {
    return compare(a, b) == SMALLER;
  }

private:
  // the exact radii, computed at the first comparison that the intervals cannot decide
  const Squared_radii_3<Exact>& exact() const
  {
    if(!exact_) exact_ = squared_radii<Exact>(coordinates_);
    return *exact_;
  }

  Triangle_coordinates_3 coordinates_;
  Squared_radii_3<Interval> radii_;
  bool filtered_ = false;
  mutable std::optional<Squared_radii_3<Exact>> exact_;
};

inline Comparison_result compare_triangle_order(const Triangle_coordinates_3& s,
                                                const Triangle_coordinates_3& t)
{
  return compare(Triangle_order_key_3(s), Triangle_order_key_3(t));
}

// ---------------------------------------------------------------------------------------
// Fast approximation of both squared radii in plain double arithmetic, with certified
// relative error bounds, for the sort of millions of triangles. A bound is infinite when it
// cannot be given (needle-like or flat triangles, overflow, underflow): such comparisons
// must then be made by the exact comparator.
// Error analysis (u = 2^-53, every operation rounded to nearest): each coordinate
// difference has relative error <= u; a sum of three squares <= 6u; the cross-product
// component n_x = a_y b_z - a_z b_y has absolute error <= 3u(|a_y b_z| + |a_z b_y|) + u|n_x|;
// |n|^2 then has relative error <= (2 sum |n_i| e_i + sum e_i^2) / |n|^2 + 4u; the
// circumradius l0 (l1 (l2 / (4 |n|^2))) adds 20u. The bounds below are doubled for safety.
struct Approximate_radii_3
{
  double rb2 = 0, rb_error = std::numeric_limits<double>::infinity();
  double rc2 = 0, rc_error = std::numeric_limits<double>::infinity();
  int longest = -1; // index of the vertex opposite the longest edge if certainly obtuse, else -1
};

// The radii of the triangle (p, q, r) from the rounded differences a = q - p and b = r - p and
// the squared lengths l0 = |r - q|^2, l1 = |b|^2, l2 = |a|^2, each computed as in
// `approximate_radii()` (the signs of a and b do not matter: they only change the sign of
// the normal).
inline Approximate_radii_3 approximate_radii_from_edges(double ax, double ay, double az, double bx, double by,
                                                        double bz, double l0, double l1, double l2)
{
  constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
  constexpr double inf = std::numeric_limits<double>::infinity();
  int longest = 0;
  double m = l0;
  if(l1 > m) { m = l1; longest = 1; }
  if(l2 > m) { m = l2; longest = 2; }
  const double s = l0 + l1 + l2 - m;

  const double t1 = ay * bz, t2 = az * by, t3 = az * bx, t4 = ax * bz, t5 = ax * by, t6 = ay * bx;
  const double nx = t1 - t2, ny = t3 - t4, nz = t5 - t6;
  const double ex = 3 * u * (std::abs(t1) + std::abs(t2)) + u * std::abs(nx);
  const double ey = 3 * u * (std::abs(t3) + std::abs(t4)) + u * std::abs(ny);
  const double ez = 3 * u * (std::abs(t5) + std::abs(t6)) + u * std::abs(nz);
  const double d = nx * nx + ny * ny + nz * nz;
  const double dn = 2 * (std::abs(nx) * ex + std::abs(ny) * ey + std::abs(nz) * ez) + ex * ex + ey * ey + ez * ez;

  Approximate_radii_3 res;
  const bool in_range = m > 1e-250 && m < 1e250;
  // d must be a normal number well above the subnormal range (the error terms of its products
  // are relative ones). The circumradius is computed in the order that keeps every intermediate
  // near 1/l, 1 and l (l0 l1 l2 would overflow for coordinates beyond about 1e51).
  if(in_range && d > 1e-290 && d < inf && dn < 0.25 * d) {
    res.rc2 = l0 * (l1 * (l2 / (4 * d)));
    if(res.rc2 > 1e-250 && res.rc2 < 1e250) res.rc_error = 2 * (dn / d + 32 * u);
  }
  if(m > s * (1 + 64 * u)) { // certainly obtuse: m > s beyond their errors (6u, 8u)
    res.longest = longest;
    res.rb2 = m * 0.25;
    res.rb_error = in_range ? 16 * u : inf;
  } else if(m < s * (1 - 64 * u)) { // certainly acute
    res.rb2 = res.rc2;
    res.rb_error = res.rc_error;
  } else { // nearly right: R_B^2 is m/4 or R_C^2, which are then close
    res.rb2 = m * 0.25;
    res.rb_error = in_range ? std::abs(res.rc2 - res.rb2) / res.rb2 + res.rc_error + 16 * u : inf;
  }
  if(!(res.rb_error < 0.25)) res.rb_error = inf;
  return res;
}

inline Approximate_radii_3 approximate_radii(const Triangle_coordinates_3& t)
{
  const Coordinates_3 &p = t[0], &q = t[1], &r = t[2];
  const double ax = q[0] - p[0], ay = q[1] - p[1], az = q[2] - p[2];
  const double bx = r[0] - p[0], by = r[1] - p[1], bz = r[2] - p[2];
  const double cx = r[0] - q[0], cy = r[1] - q[1], cz = r[2] - q[2];
  const double l2 = ax * ax + ay * ay + az * az; // opposite r
  const double l1 = bx * bx + by * by + bz * bz; // opposite q
  const double l0 = cx * cx + cy * cy + cz * cz; // opposite p
  return approximate_radii_from_edges(ax, ay, az, bx, by, bz, l0, l1, l2);
}

// R_B^2 with a relative error below `max_relative_error`, or false.
inline bool approximate_squared_rb(const Triangle_coordinates_3& t, double max_relative_error,
                                   double& rb2, double& relative_error)
{
  const Approximate_radii_3 a = approximate_radii(t);
  rb2 = a.rb2;
  relative_error = a.rb_error;
  return a.rb_error < max_relative_error;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TRIANGLE_ORDER_3_H
