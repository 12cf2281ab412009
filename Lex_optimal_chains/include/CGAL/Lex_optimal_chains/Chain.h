// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_CHAIN_H
#define CGAL_LEX_OPTIMAL_CHAINS_CHAIN_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
A `k`-chain of a `Simplicial_complex`: pairs (index of a `k`-simplex, non-zero coefficient),
sorted by index. The coefficient of a simplex refers to its orientation by increasing vertices.
*/
template <class Field>
using Chain = std::vector<std::pair<std::uint32_t, typename Field::Value>>;

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_CHAIN_H
