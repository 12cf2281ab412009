// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_SIMPLEX_ORDERS_H
#define CGAL_LEX_OPTIMAL_CHAINS_SIMPLEX_ORDERS_H

/// \file Simplex_orders.h
/// Total orders on the simplices of a `Simplicial_complex` whose vertices are points.

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Simplicial_complex.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef

The order of Lemma 4.14 on the triangles (2-simplices) of a complex whose vertex `i` is
the point `points[i]`, a `Point_2` (taken at \f$z=0\f$) or a `Point_3` with `double`
coordinates: the same exact comparison as `Lex_optimal_chains_traits_3`, with its symbolic
tie-break. A strict weak "less than" on `Simplicial_complex::Simplex`, for `sort_simplices()`.
*/
template <class Point>
class Triangle_order
{
public:
  /// the order on the triangles of a complex whose vertices are `points` (kept by address:
  /// they must outlive the order). \throws Input_error with code `NON_FINITE_COORDINATE`
  explicit Triangle_order(const std::vector<Point>& points) : points_(&points)
  {
    for(const Point& p : points)
      for(double c : coordinates(p, 0))
        if(!std::isfinite(c)) throw Input_error(Input_error_code::NON_FINITE_COORDINATE, "a point has a NaN or infinite coordinate");
  }
  Triangle_order(std::vector<Point>&&) = delete; // the points would not outlive the order

  /// true if triangle `a` comes before triangle `b`
  bool operator()(const Simplicial_complex::Simplex& a, const Simplicial_complex::Simplex& b) const
  {
    return internal::compare_triangle_order(coordinates(a), coordinates(b)) == SMALLER;
  }

  /// the comparison key of a triangle (its radii computed once), for `sort_simplices()`
  internal::Triangle_order_key_3 key(const Simplicial_complex::Simplex& s) const
  {
    return internal::Triangle_order_key_3(coordinates(s));
  }

private:
  internal::Triangle_coordinates_3 coordinates(const Simplicial_complex::Simplex& s) const
  {
    internal::Triangle_coordinates_3 t;
    for(int k = 0; k < 3; ++k) t[k] = coordinates((*points_)[s[k]], 0);
    return t;
  }
  // a Point_3 (chosen first: int matches 0 exactly) or a Point_2
  template <class P>
  static auto coordinates(const P& p, int) -> decltype(p.z(), internal::Coordinates_3())
  {
    return internal::Coordinates_3{{p.x(), p.y(), p.z()}};
  }
  template <class P>
  static internal::Coordinates_3 coordinates(const P& p, long)
  {
    return internal::Coordinates_3{{p.x(), p.y(), 0.0}};
  }
  const std::vector<Point>* points_;
};

/*!
\ingroup PkgLexOptimalChainsRef

The generalized order on the `k`-simplices of weighted points (thesis section 4.2.4), for
points in \f$\mathbb{R}^2\f$ or \f$\mathbb{R}^3\f$ (`Point_2` or `Point_3`) with weights
\f$w_i\f$ (the squared radii of the weighted points; zero weights give the Delaunay case).

For a simplex \f$\sigma\f$, \f$\mu_C(\tau)\f$ is the weight of the smallest sphere orthogonal to
the weighted vertices of a face \f$\tau\f$ (its *circumweight*; \f$R_C^2\f$ for zero weights),
\f$\mu_B(\sigma)\f$ the smallest weight of a sphere orthogonal or further to all its vertices
(the *bounding weight*; \f$R_B^2\f$ for zero weights), reached by the circumsphere of a
smallest face \f$\Theta(\sigma)\f$. The faces \f$\Theta_0 = \Theta(\sigma) \subset \Theta_1
\subset \dots \subset \sigma\f$ grow one vertex at a time, each time the face of smallest
circumweight, and \f$\mu_j = \mu_C(\Theta_j)\f$. Simplices are compared by \f$\mu_0\f$
ascending, then \f$\mu_1, \mu_2, \dots\f$ *descending* (a shorter sequence is continued by its
last value), then by their vertices sorted lexicographically by coordinates (a symbolic
tie-break that does not depend on the input order). A degenerate face (affinely dependent
vertices) has an infinite circumweight. With zero weights on triangles this is Lemma 4.14
(`Triangle_order`).

All values are computed exactly with `Exact_rational`, once per simplex (they are cached).
*/
template <class Point>
class Weighted_simplex_order
{
public:
  /// the order on the simplices of a complex whose vertex `i` is `points[i]` with weight `weights[i]`
  /// (kept by address: they must outlive the order). \throws Input_error with code
  /// `NON_FINITE_COORDINATE` on a NaN or infinite coordinate or weight, `INVALID_CHAIN` if the
  /// sizes differ.
  Weighted_simplex_order(const std::vector<Point>& points, const std::vector<double>& weights)
    : points_(&points), weights_(&weights), cache_(new Cache)
  {
    if(points.size() != weights.size())
      throw Input_error(Input_error_code::INVALID_CHAIN, "there must be one weight per point");
    for(std::uint32_t v = 0; v < points.size(); ++v)
      for(double c : point(v))
        if(!std::isfinite(c)) throw Input_error(Input_error_code::NON_FINITE_COORDINATE, "a point has a NaN or infinite coordinate");
    for(double w : weights)
      if(!std::isfinite(w)) throw Input_error(Input_error_code::NON_FINITE_COORDINATE, "a weight is NaN or infinite");
  }
  Weighted_simplex_order(std::vector<Point>&&, const std::vector<double>&) = delete; // would dangle
  Weighted_simplex_order(const std::vector<Point>&, std::vector<double>&&) = delete; // would dangle
  Weighted_simplex_order(std::vector<Point>&&, std::vector<double>&&) = delete;      // would dangle

  /// true if `a` comes before `b` (simplices of the same dimension)
  bool operator()(const Simplicial_complex::Simplex& a, const Simplicial_complex::Simplex& b) const
  {
    if(a == b) return false;
    const Key& ka = key(a);
    const Key& kb = key(b);
    if(compare(ka.mu[0], kb.mu[0]) != 0) return compare(ka.mu[0], kb.mu[0]) < 0;
    for(std::size_t j = 1; j < (std::max)(ka.mu.size(), kb.mu.size()); ++j) {
      const int c = compare(at(ka.mu, j), at(kb.mu, j));
      if(c != 0) return c > 0; // descending
    }
    return ka.sorted_points < kb.sorted_points;
  }

private:
  using FT = Exact_rational;
  using Value = std::optional<FT>; // none: infinite
  struct Key
  {
    std::vector<Value> mu;
    std::vector<std::array<double, 3>> sorted_points;
  };
  struct Cache { std::map<Simplicial_complex::Simplex, Key> keys; };

  static int popcount(unsigned x) { int c = 0; for(; x != 0; x &= x - 1) ++c; return c; }
  static const Value& at(const std::vector<Value>& v, std::size_t j) { return j < v.size() ? v[j] : v.back(); }
  static int compare(const Value& a, const Value& b)
  {
    if(!a && !b) return 0;
    if(!a) return 1; // infinite
    if(!b) return -1;
    return *a < *b ? -1 : (*b < *a ? 1 : 0);
  }

  std::array<double, 3> point(std::uint32_t v) const { return coordinates((*points_)[v], 0); }
  template <class P>
  static auto coordinates(const P& p, int) -> decltype(p.z(), std::array<double, 3>())
  {
    return {{p.x(), p.y(), p.z()}};
  }
  template <class P>
  static std::array<double, 3> coordinates(const P& p, long)
  {
    return {{p.x(), p.y(), 0.0}};
  }

  // circumcenter (in the affine hull) and circumweight of the face, exactly; none if degenerate
  struct Sphere { std::array<FT, 3> center; FT weight; };
  std::optional<Sphere> circumsphere(const std::vector<std::uint32_t>& face) const
  {
    const std::array<double, 3> p0 = point(face[0]);
    const FT w0 = (*weights_)[face[0]];
    const std::size_t t = face.size() - 1;
    std::vector<std::array<FT, 3>> e(t);
    std::vector<std::vector<FT>> g(t, std::vector<FT>(t + 1));
    for(std::size_t i = 0; i < t; ++i) {
      const std::array<double, 3> pi = point(face[i + 1]);
      for(int d = 0; d < 3; ++d) e[i][d] = FT(pi[d]) - FT(p0[d]);
    }
    for(std::size_t i = 0; i < t; ++i) {
      for(std::size_t j = 0; j < t; ++j) g[i][j] = 2 * (e[i][0] * e[j][0] + e[i][1] * e[j][1] + e[i][2] * e[j][2]);
      g[i][t] = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2] - FT((*weights_)[face[i + 1]]) + w0;
    }
    // Gauss-Jordan elimination, exact
    for(std::size_t c = 0; c < t; ++c) {
      std::size_t p = c;
      while(p < t && g[p][c] == 0) ++p;
      if(p == t) return std::nullopt; // affinely dependent
      std::swap(g[p], g[c]);
      for(std::size_t r = 0; r < t; ++r) {
        if(r == c || g[r][c] == 0) continue;
        const FT f = g[r][c] / g[c][c];
        for(std::size_t k = c; k <= t; ++k) g[r][k] -= f * g[c][k];
      }
    }
    Sphere s;
    for(int d = 0; d < 3; ++d) s.center[d] = FT(p0[d]);
    for(std::size_t i = 0; i < t; ++i) {
      const FT lambda = g[i][t] / g[i][i];
      for(int d = 0; d < 3; ++d) s.center[d] += lambda * e[i][d];
    }
    s.weight = power(s.center, face[0]);
    return s;
  }

  // |c - p_v|^2 - w_v
  FT power(const std::array<FT, 3>& c, std::uint32_t v) const
  {
    const std::array<double, 3> p = point(v);
    FT s = -FT((*weights_)[v]);
    for(int d = 0; d < 3; ++d) s += (c[d] - FT(p[d])) * (c[d] - FT(p[d]));
    return s;
  }

  // tie-break between faces of equal circumweight: their sorted points
  std::vector<std::array<double, 3>> sorted_points(const std::vector<std::uint32_t>& face) const
  {
    std::vector<std::array<double, 3>> s;
    for(std::uint32_t v : face) s.push_back(point(v));
    std::sort(s.begin(), s.end());
    return s;
  }

  const Key& key(const Simplicial_complex::Simplex& s) const
  {
    auto it = cache_->keys.find(s);
    if(it != cache_->keys.end()) return it->second;
    const std::size_t n = s.size();
    // every face, by its bit mask over the vertices of s
    std::vector<std::optional<Sphere>> spheres(std::size_t(1) << n);
    auto face_of = [&](unsigned mask) {
      std::vector<std::uint32_t> f;
      for(std::size_t i = 0; i < n; ++i) if(mask >> i & 1) f.push_back(s[i]);
      return f;
    };
    for(unsigned mask = 1; mask < (1u << n); ++mask) spheres[mask] = circumsphere(face_of(mask));
    auto weight = [&](unsigned mask) { return spheres[mask] ? Value(spheres[mask]->weight) : Value(); };
    // a smaller circumweight, or an equal one with fewer vertices, or then smaller sorted points
    auto better = [&](unsigned a, unsigned b) {
      const int c = compare(weight(a), weight(b));
      if(c != 0) return c < 0;
      if(popcount(a) != popcount(b)) return popcount(a) < popcount(b);
      return sorted_points(face_of(a)) < sorted_points(face_of(b));
    };
    // Theta: the best face whose circumsphere is orthogonal or further to every vertex
    unsigned theta = 0;
    for(unsigned mask = 1; mask < (1u << n); ++mask) {
      if(!spheres[mask]) continue;
      bool encloses = true;
      for(std::size_t i = 0; i < n && encloses; ++i)
        if(!(mask >> i & 1) && power(spheres[mask]->center, s[i]) > spheres[mask]->weight) encloses = false;
      if(encloses && (theta == 0 || better(mask, theta))) theta = mask;
    }
    Key k;
    const unsigned all = (1u << n) - 1;
    if(theta == 0) theta = all; // only for a degenerate simplex: no finite enclosing face
    k.mu.push_back(weight(theta));
    while(theta != all) { // grow one vertex at a time, the face of smallest circumweight
      unsigned next = 0;
      for(std::size_t i = 0; i < n; ++i) {
        if(theta >> i & 1) continue;
        const unsigned m = theta | (1u << i);
        if(next == 0 || better(m, next)) next = m;
      }
      theta = next;
      k.mu.push_back(weight(theta));
    }
    k.sorted_points = sorted_points(std::vector<std::uint32_t>(s.begin(), s.end()));
    return cache_->keys.emplace(s, std::move(k)).first->second;
  }

  const std::vector<Point>* points_;
  const std::vector<double>* weights_;
  std::shared_ptr<Cache> cache_;
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_SIMPLEX_ORDERS_H
