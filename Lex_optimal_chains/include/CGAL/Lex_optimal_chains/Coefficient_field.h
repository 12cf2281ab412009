// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_COEFFICIENT_FIELD_H
#define CGAL_LEX_OPTIMAL_CHAINS_COEFFICIENT_FIELD_H

#include <CGAL/license/Lex_optimal_chains.h>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
The coefficients of the chains of the open-surface functions.

With `Z2` a chain is a set of triangles: orientation is ignored and the optimal chain may be
non-orientable (a Möbius strip). With `Q` chains are oriented: a triangle has a signed
coefficient relative to an orientation, the optimal chain is oriented and its boundary is the
given cycle with its orientation. Algorithms 10 and 11 of the thesis only add and subtract
coefficients, so an integral input gives an integral result: rational coefficients are
computed exactly as integers. The chains have 64-bit coefficients; the intersection products
kept by the disjoint sets are 32-bit (for speed and memory: one 8-byte node per cell), so a
product beyond \f$2^{31}-1\f$ in absolute value throws `Input_error` with code `TOO_LARGE`.
The products are sums of input coefficients along paths: with coefficients \f$\pm1\f$ (a
polyline boundary) this needs billions of triangles in the representative chain.
*/
enum class Coefficient_field
{
  Z2, ///< the field with two elements: unoriented chains
  Q   ///< the rationals: oriented chains (computed exactly with integers)
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_COEFFICIENT_FIELD_H
