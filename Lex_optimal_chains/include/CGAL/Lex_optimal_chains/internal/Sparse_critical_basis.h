// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_SPARSE_CRITICAL_BASIS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_SPARSE_CRITICAL_BASIS_H

// The critical basis of the span of given lexicographic minimal cycles (thesis Observation
// 4.54), over Z2, with sparse columns: a chain is the increasing list of the ranks of its
// simplices in the total order. The columns are reduced (each low made unique), sorted
// lexicographically (by their largest simplex, then the next largest, ...), and each one is
// reduced totally by the previous ones (every row below its low that is the low of a previous
// column is cleared). The relative part of a chain (its simplices outside a subcomplex B)
// decides every step; the same sums are made of the whole chains, so that each basis element
// is also given as a sum of the input chains. O(beta^2 m) for beta chains of at most m
// simplices, where the dense version needs the whole complex in every column.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

using Z2_chain = std::vector<std::uint32_t>; // increasing ranks

// a + b over Z2 (symmetric difference of increasing lists)
inline Z2_chain z2_sum(const Z2_chain& a, const Z2_chain& b)
{
  Z2_chain c;
  c.reserve(a.size() + b.size());
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(c));
  return c;
}

// a < b in the lexicographic order of chains: at the largest simplex where they differ, b has it
inline bool z2_lexicographically_smaller(const Z2_chain& a, const Z2_chain& b)
{
  auto i = a.rbegin(), j = b.rbegin();
  for(; i != a.rend() && j != b.rend(); ++i, ++j)
    if(*i != *j) return *i < *j;
  return i == a.rend() && j != b.rend();
}

struct Z2_critical_basis
{
  std::vector<Z2_chain> elements;                    // relative parts, in increasing order
  std::vector<std::vector<std::uint32_t>> sums_of;   // the input chains (indices) whose sum each one is
};

// `relative[i]`: the part of the i-th input chain outside B (the simplices that decide);
// their span has the dimension of the result. `rows`: an upper bound of the ranks.
inline Z2_critical_basis z2_critical_basis(std::vector<Z2_chain> relative, std::size_t rows)
{
  constexpr std::uint32_t none = std::uint32_t(-1);
  const std::size_t beta = relative.size();
  std::vector<Z2_chain> sums(beta);
  for(std::size_t i = 0; i < beta; ++i) sums[i] = {std::uint32_t(i)};
  // reduction: unique lows
  std::vector<std::uint32_t> column_of_low(rows, none);
  std::vector<std::size_t> independent;
  for(std::size_t j = 0; j < beta; ++j) {
    while(!relative[j].empty() && column_of_low[relative[j].back()] != none) {
      const std::uint32_t k = column_of_low[relative[j].back()];
      relative[j] = z2_sum(relative[j], relative[k]);
      sums[j] = z2_sum(sums[j], sums[k]);
    }
    if(relative[j].empty()) continue; // in the span of the previous ones
    column_of_low[relative[j].back()] = std::uint32_t(j);
    independent.push_back(j);
  }
  // sorted lexicographically, then each one totally reduced by the previous ones
  std::sort(independent.begin(), independent.end(),
            [&](std::size_t a, std::size_t b) { return z2_lexicographically_smaller(relative[a], relative[b]); });
  Z2_critical_basis basis;
  std::fill(column_of_low.begin(), column_of_low.end(), none);
  for(std::size_t j : independent) {
    Z2_chain c = std::move(relative[j]);
    Z2_chain s = std::move(sums[j]);
    const std::uint32_t crit = c.back();
    // rows below crit from the top: a sum with a previous element (whose simplices are all at
    // most its low) changes only rows at most that low
    std::uint32_t bound = crit;
    for(;;) {
      auto it = std::lower_bound(c.begin(), c.end(), bound); // first row >= bound
      std::uint32_t row = none;
      while(it != c.begin()) {
        --it;
        if(column_of_low[*it] != none) { row = *it; break; }
      }
      if(row == none) break;
      const std::uint32_t k = column_of_low[row];
      c = z2_sum(c, basis.elements[k]);
      s = z2_sum(s, basis.sums_of[k]);
      bound = row;
    }
    column_of_low[crit] = std::uint32_t(basis.elements.size());
    basis.elements.push_back(std::move(c));
    basis.sums_of.push_back(std::move(s));
  }
  return basis;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_SPARSE_CRITICAL_BASIS_H
