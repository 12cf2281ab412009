// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_TRAITS_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_TRAITS_3_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/internal/Geom_traits_check.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>

#include <CGAL/enum.h>

namespace CGAL {

/*!
\ingroup PkgLexOptimalChainsRef

A model of `LexOptimalChainsTraits_3`: the kernel `K`, which gives the predicates of the
Delaunay triangulation, with the total order on triangles of Lemma 4.14 of the thesis, the
order that the algorithms of the package use (they evaluate it with the same exact
arithmetic), for the user's own code.

A triangle \f$\sigma_1\f$ comes before \f$\sigma_2\f$ if
- the radius \f$R_B\f$ of its smallest enclosing ball is smaller, or
- the radii \f$R_B\f$ are equal and its circumradius \f$R_C\f$ is *larger* (a degenerate
  triangle has an infinite circumradius), or
- both radii are equal and its three vertices, sorted lexicographically by \f$(x,y,z)\f$,
  form a lexicographically smaller triple (a symbolic tie-break that does not depend on the
  order of the input nor on the order of the vertices in the triangle).

\f$R_B\f$ equals \f$R_C\f$ for acute and right triangles and half the longest edge for obtuse
ones, so obtuse triangles sharing their longest edge have exactly the same \f$R_B\f$.
All comparisons are exact: squared radii are compared as fractions of polynomials in the
coordinates, first with interval arithmetic and, when the intervals do not decide, exactly
(cross products of the fractions, in CGAL's exact ring type for doubles, `Mpzf` where available).

\tparam K a CGAL kernel whose `FT` is `double`, with exact predicates (e.g.
`Exact_predicates_inexact_constructions_kernel`); another kernel is refused at compile time
with a message that says why.

\cgalModels `LexOptimalChainsTraits_3`
*/
template <class K>
class Lex_optimal_chains_traits_3 : public K
{
  static_assert(Lex_optimal_chains::internal::Has_exact_predicates_and_double_coordinates<K>::value, "");

public:
  /// The kernel.
  typedef K Kernel;
  /// The point type.
  typedef typename K::Point_3 Point_3;

  /// Compares two triangles given by their vertices along the total order.
  struct Compare_triangle_order_3
  {
    /// returns `SMALLER` if the triangle `(p1,q1,r1)` comes before `(p2,q2,r2)`, `LARGER` if
    /// after, and `EQUAL` only if both have the same vertices.
    Comparison_result operator()(const Point_3& p1, const Point_3& q1, const Point_3& r1,
                                 const Point_3& p2, const Point_3& q2, const Point_3& r2) const
    {
      return Lex_optimal_chains::internal::compare_triangle_order(coordinates(p1, q1, r1),
                                                                   coordinates(p2, q2, r2));
    }

  private:
    static Lex_optimal_chains::internal::Triangle_coordinates_3
    coordinates(const Point_3& p, const Point_3& q, const Point_3& r)
    {
      return {{{{p.x(), p.y(), p.z()}}, {{q.x(), q.y(), q.z()}}, {{r.x(), r.y(), r.z()}}}};
    }
  };

  /// builds the traits from a kernel object.
  Lex_optimal_chains_traits_3(const K& k = K()) : K(k) {}

  /// The comparison functor.
  Compare_triangle_order_3 compare_triangle_order_3_object() const { return Compare_triangle_order_3(); }
};

} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_TRAITS_3_H
