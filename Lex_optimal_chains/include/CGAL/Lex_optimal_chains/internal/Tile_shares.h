// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_SHARES_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_SHARES_H

// The deal of the tiles to processes (Tile_share): longest processing time first, with the
// number of points of a tile as its cost. Only the counts decide, so every process that has
// the same counts makes the same deal.

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The share of each tile among `shares` shares: the tiles by decreasing `cost` (then by index),
// each to the share of the smallest total cost so far (then of the lowest index).
inline std::vector<std::size_t> deal_tiles(const std::vector<std::size_t>& cost, std::size_t shares)
{
  std::vector<std::size_t> order(cost.size()), share_of(cost.size(), 0);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  std::vector<std::size_t> load(shares, 0);
  for(std::size_t t : order) {
    const std::size_t s = std::size_t(std::min_element(load.begin(), load.end()) - load.begin());
    share_of[t] = s;
    load[s] += cost[t];
  }
  return share_of;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_SHARES_H
