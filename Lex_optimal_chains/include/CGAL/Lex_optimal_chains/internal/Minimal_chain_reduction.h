// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_MINIMAL_CHAIN_REDUCTION_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_MINIMAL_CHAIN_REDUCTION_H

// The pieces of the functions of minimal_chains.h: simplices sorted by an order (on keys when
// the order has them), the boundary matrix by rank of the order, chains between their sparse
// and dense forms, and the lexicographic comparison of sparse columns.

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Chain.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Simplicial_complex.h>
#include <CGAL/Lex_optimal_chains/internal/Column_reduction.h>

#include <CGAL/enum.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {
// orders with a `key()` (computed once per simplex) are sorted on their keys
template <class Less>
auto sort_by_keys(const Simplicial_complex& complex, int k, const Less& less, std::vector<std::uint32_t>& order, int)
  -> decltype(less.key(complex.simplex(k, 0)), void())
{
  using Key = decltype(less.key(complex.simplex(k, 0)));
  std::vector<std::pair<Key, std::uint32_t>> keyed;
  keyed.reserve(order.size());
  for(std::uint32_t i : order) keyed.emplace_back(less.key(complex.simplex(k, i)), i);
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return compare(a.first, b.first) == SMALLER; });
  for(std::size_t r = 0; r < keyed.size(); ++r) order[r] = keyed[r].second;
}
template <class Less>
void sort_by_keys(const Simplicial_complex& complex, int k, const Less& less, std::vector<std::uint32_t>& order, long)
{
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return less(complex.simplex(k, a), complex.simplex(k, b));
  });
}


// which k-simplices of `complex` are in the subcomplex `relative` (none if null)
inline std::vector<char> simplices_in(const Simplicial_complex& complex, int k, const Simplicial_complex* relative)
{
  std::vector<char> in(complex.number_of_simplices(k), 0);
  if(relative == nullptr) return in;
  for(std::size_t i = 0; i < relative->number_of_simplices(k); ++i) {
    const long j = complex.index(relative->simplex(k, i));
    if(j < 0) throw Input_error(Input_error_code::INVALID_CHAIN, "a simplex of the subcomplex B is not in the complex");
    in[j] = 1;
  }
  return in;
}

inline std::vector<std::uint32_t> ranks_of(const std::vector<std::uint32_t>& order, std::size_t m)
{
  if(order.size() != m)
    throw Input_error(Input_error_code::INVALID_CHAIN, "the order must list every simplex of the dimension once");
  std::vector<std::uint32_t> rank(m, std::uint32_t(-1));
  for(std::uint32_t r = 0; r < m; ++r) {
    if(order[r] >= m || rank[order[r]] != std::uint32_t(-1))
      throw Input_error(Input_error_code::INVALID_CHAIN, "the order must list every simplex of the dimension once");
    rank[order[r]] = r;
  }
  return rank;
}

// The boundary columns of the (k+1)-simplices not in B (in index order), rows = ranks of
// the k-simplices, rows of B removed.
template <class Field>
std::vector<Sparse_column<Field>> boundary_by_rank(const Simplicial_complex& complex, int k,
                                                   const std::vector<std::uint32_t>& rank,
                                                   const std::vector<char>& in_b_k, const std::vector<char>& in_b_k1)
{
  std::vector<Sparse_column<Field>> columns;
  for(std::size_t j = 0; j < complex.number_of_simplices(k + 1); ++j) {
    if(in_b_k1[j]) continue;
    Sparse_column<Field> c;
    for(const auto& fs : complex.boundary(k + 1, j))
      if(!in_b_k[fs.first]) c.emplace_back(rank[fs.first], Field::from_integer(fs.second));
    std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    columns.push_back(std::move(c));
  }
  return columns;
}

template <class Field>
std::vector<typename Field::Value> dense(const Chain<Field>& chain, const std::vector<std::uint32_t>& position,
                                         std::size_t size, const std::vector<char>& in_b)
{
  std::vector<typename Field::Value> g(size, Field::zero());
  for(const auto& e : chain) {
    if(e.first >= position.size())
      throw Input_error(Input_error_code::INVALID_CHAIN, "a simplex index of the chain is out of range");
    if(!in_b[e.first]) g[position[e.first]] = Field::add(g[position[e.first]], e.second);
  }
  return g;
}

template <class Field>
Chain<Field> sparse(const std::vector<typename Field::Value>& g, const std::vector<std::uint32_t>& simplex_at)
{
  Chain<Field> c;
  for(std::size_t p = 0; p < g.size(); ++p)
    if(!Field::is_zero(g[p])) c.emplace_back(simplex_at[p], g[p]);
  std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return c;
}

// The k-simplices not in B, by increasing rank: the columns of the reduction of the
// boundary matrix of dimension k (Algorithm 4), and the V matrix of that reduction.
template <class Field>
struct Cycle_basis_reduction
{
  std::vector<std::uint32_t> simplex_of_column, column_of_simplex;
  std::optional<Column_reduction<Field>> reduction;

  // Clearing: the reduced boundary matrix of the (k+1)-simplices (rows = ranks of the
  // k-simplices) gives, for each of its non-zero columns, a cycle whose lowest simplex is that
  // column's low: the column of that simplex reduces to zero and takes this cycle as V.
  Cycle_basis_reduction(const Simplicial_complex& complex, int k, const std::vector<std::uint32_t>& order,
                        const std::vector<char>& in_b_k, const std::vector<char>& in_b_km1,
                        const Column_reduction<Field>* higher = nullptr)
  {
    const std::size_t m = complex.number_of_simplices(k);
    column_of_simplex.assign(m, std::uint32_t(-1));
    std::vector<Sparse_column<Field>> columns;
    for(std::uint32_t s : order) {
      if(in_b_k[s]) continue;
      column_of_simplex[s] = std::uint32_t(simplex_of_column.size());
      simplex_of_column.push_back(s);
      Sparse_column<Field> c;
      for(const auto& fs : complex.boundary(k, s))
        if(!in_b_km1[fs.first]) c.emplace_back(fs.first, Field::from_integer(fs.second));
      std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      columns.push_back(std::move(c));
    }
    std::vector<std::pair<std::uint32_t, Sparse_column<Field>>> cleared;
    if(higher != nullptr) {
      for(std::size_t j = 0; j < higher->number_of_columns(); ++j) {
        const Sparse_column<Field>& c = higher->reduced(j);
        if(c.empty()) continue;
        Sparse_column<Field> v; // rows: ranks -> column positions (increasing with the rank)
        for(const auto& e : c) v.emplace_back(column_of_simplex[order[e.first]], e.second);
        cleared.emplace_back(v.back().first, std::move(v));
      }
    }
    reduction.emplace(std::move(columns), complex.number_of_simplices(k - 1), true, std::move(cleared));
  }
};

// lexicographic comparison of two chains given densely by rank: true if a is smaller
template <class Field>
bool lexicographically_smaller(const Sparse_column<Field>& a, const Sparse_column<Field>& b)
{
  // supports compared from the largest rank down
  std::size_t i = a.size(), j = b.size();
  while(i > 0 && j > 0) {
    if(a[i - 1].first != b[j - 1].first) return a[i - 1].first < b[j - 1].first;
    --i, --j;
  }
  return i < j;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_MINIMAL_CHAIN_REDUCTION_H
