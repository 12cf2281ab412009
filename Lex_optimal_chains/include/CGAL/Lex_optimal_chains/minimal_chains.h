// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_MINIMAL_CHAINS_H
#define CGAL_LEX_OPTIMAL_CHAINS_MINIMAL_CHAINS_H

/// \file minimal_chains.h
/// Lexicographic optimal chains on arbitrary simplicial complexes by matrix reduction
/// (thesis sections 4.3 and 4.7).

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Chain.h>
#include <CGAL/Lex_optimal_chains/Chain_fields.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Simplicial_complex.h>
#include <CGAL/Lex_optimal_chains/internal/Minimal_chain_reduction.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
The `k`-simplices of `complex` sorted increasingly by the strict total order `less`, a
functor called on two simplices (`const Simplicial_complex::Simplex&`, their increasing
vertices). The result is the *order* argument of the functions of this header.
\throws Input_error with code `INVALID_CHAIN` if `less` is not a strict total order on them
(two simplices neither smaller than the other).
*/
template <class Less>
std::vector<std::uint32_t> sort_simplices(const Simplicial_complex& complex, int k, const Less& less)
{
  std::vector<std::uint32_t> order(complex.number_of_simplices(k));
  for(std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  internal::sort_by_keys(complex, k, less, order, 0);
  for(std::size_t i = 1; i < order.size(); ++i)
    if(!less(complex.simplex(k, order[i - 1]), complex.simplex(k, order[i])))
      throw Input_error(Input_error_code::INVALID_CHAIN, "the order is not a strict total order on the simplices");
  return order;
}

/*!
\ingroup PkgLexOptimalChainsRef

Lex-OHCP (Problem 4 of the thesis; Algorithms 2 and 3): the lexicographic minimal `k`-chain
homologous to `gamma0` in `complex`, or relative to the subcomplex `relative` when it is not
null (simplices of \f$B\f$ then have no coefficient, in the input as in the output).

\tparam Field `Z2_field`, `Zp_field<p>` or `Q_field`
\param complex the simplicial complex
\param k the dimension of the chains
\param order the `k`-simplices sorted increasingly (see `sort_simplices()`)
\param gamma0 the given chain
\param relative a subcomplex \f$B\f$ of `complex` (same vertices), or null

Complexity: \f$O(m n^2)\f$ for \f$m\f$ `k`-simplices and \f$n\f$ `(k+1)`-simplices in the worst
case, with sparse columns.
\throws Input_error with code `INVALID_CHAIN` if `order` is not a permutation of the
`k`-simplices, an index of `gamma0` is out of range, or \f$B\f$ is not in `complex`.
*/
template <class Field>
Chain<Field> minimal_homologous_chain(const Simplicial_complex& complex, int k, const std::vector<std::uint32_t>& order,
                                      const Chain<Field>& gamma0, const Simplicial_complex* relative = nullptr)
{
  const std::size_t m = complex.number_of_simplices(k);
  const std::vector<std::uint32_t> rank = internal::ranks_of(order, m);
  const std::vector<char> in_b_k = internal::simplices_in(complex, k, relative);
  const std::vector<char> in_b_k1 = internal::simplices_in(complex, k + 1, relative);
  const internal::Column_reduction<Field> r(internal::boundary_by_rank<Field>(complex, k, rank, in_b_k, in_b_k1), m, false);
  std::vector<typename Field::Value> g = internal::dense<Field>(gamma0, rank, m, in_b_k);
  r.totally_reduce(g);
  return internal::sparse<Field>(g, order);
}

/*!
\ingroup PkgLexOptimalChainsRef

Problem 5 of the thesis (Algorithms 4, 6 and 5): the lexicographic minimal `k`-chain whose
boundary is the `(k-1)`-chain `boundary`, relative to `relative` when it is not null; none if
`boundary` is not a boundary.

\tparam Field `Z2_field`, `Zp_field<p>` or `Q_field`
\param complex the simplicial complex
\param k the dimension of the chains (at least 1)
\param order the `k`-simplices sorted increasingly
\param boundary a `(k-1)`-chain
\param relative a subcomplex \f$B\f$ of `complex`, or null
\throws Input_error as `minimal_homologous_chain()`, and with code `BOUNDARY_NOT_A_CYCLE`
if `boundary` is not a cycle.
*/
template <class Field>
std::optional<Chain<Field>> minimal_chain_with_boundary(const Simplicial_complex& complex, int k,
                                                        const std::vector<std::uint32_t>& order,
                                                        const Chain<Field>& boundary,
                                                        const Simplicial_complex* relative = nullptr)
{
  if(k < 1) throw Input_error(Input_error_code::INVALID_CHAIN, "chains with a boundary have dimension 1 or more");
  if(k >= 2) { // the boundary must be a cycle
    std::vector<typename Field::Value> b(complex.number_of_simplices(k - 2), Field::zero());
    for(const auto& e : boundary) {
      if(e.first >= complex.number_of_simplices(k - 1))
        throw Input_error(Input_error_code::INVALID_CHAIN, "a simplex index of the chain is out of range");
      for(const auto& fs : complex.boundary(k - 1, e.first))
        b[fs.first] = Field::add(b[fs.first], Field::multiply(Field::from_integer(fs.second), e.second));
    }
    const std::vector<char> in_b_km2 = internal::simplices_in(complex, k - 2, relative);
    for(std::size_t i = 0; i < b.size(); ++i)
      if(!Field::is_zero(b[i]) && !in_b_km2[i])
        throw Input_error(Input_error_code::BOUNDARY_NOT_A_CYCLE, "the given boundary is not a (relative) cycle");
  }
  const std::vector<char> in_b_k = internal::simplices_in(complex, k, relative);
  const std::vector<char> in_b_km1 = internal::simplices_in(complex, k - 1, relative);
  const std::vector<char> in_b_k1 = internal::simplices_in(complex, k + 1, relative);
  const std::vector<std::uint32_t> rank = internal::ranks_of(order, complex.number_of_simplices(k));
  // the boundaries of the (k+1)-simplices, reduced, clear most columns of the k-simplices
  const internal::Column_reduction<Field> higher(internal::boundary_by_rank<Field>(complex, k, rank, in_b_k, in_b_k1),
                                                 complex.number_of_simplices(k), false);
  const internal::Cycle_basis_reduction<Field> basis(complex, k, order, in_b_k, in_b_km1, &higher);
  const auto& reduction = *basis.reduction;
  // Algorithm 6: a representative, by eliminating the boundary with the reduced columns
  const std::size_t rows = complex.number_of_simplices(k - 1);
  std::vector<std::uint32_t> identity(rows);
  for(std::uint32_t i = 0; i < rows; ++i) identity[i] = i;
  std::vector<typename Field::Value> a = internal::dense<Field>(boundary, identity, rows, in_b_km1);
  std::vector<typename Field::Value> gamma(basis.simplex_of_column.size(), Field::zero());
  reduction.totally_reduce(a, &gamma);
  for(const auto& x : a)
    if(!Field::is_zero(x)) return std::nullopt;
  // Algorithm 5: minimized with the kernel columns of V, whose lows are their own columns
  for(std::size_t p = gamma.size(); p-- > 0;) {
    if(Field::is_zero(gamma[p]) || !reduction.reduced(p).empty()) continue;
    const auto& v = reduction.transformation(p);
    const typename Field::Value f = Field::divide(gamma[p], v.back().second);
    for(const auto& e : v) gamma[e.first] = Field::subtract(gamma[e.first], Field::multiply(f, e.second));
  }
  return internal::sparse<Field>(gamma, basis.simplex_of_column);
}

/*!
\ingroup PkgLexOptimalChainsRef

The critical basis of \f$Z^{\min}_k(K, B)\f$ (thesis section 4.7, Definition 4.47): the
lexicographic minimal cycles of their homology classes form a linear space isomorphic to
\f$H_k(K, B)\f$; its critical basis \f$b_1 \sqsubset \dots \sqsubset b_m\f$ is built
greedily, each \f$b_{i+1}\f$ the smallest element outside the span of the previous ones,
with coefficient 1 on its largest simplex \f$\mathrm{crit}(b_{i+1})\f$. It verifies
\f$b_j(\mathrm{crit}(b_i)) = \delta_{ij}\f$ (Lemma 4.50).

Computed as in Observation 4.54: a basis of the `k`-cycles (Algorithm 4), of which the
essential ones (their largest simplex is not the low of a reduced boundary; the others add
nothing to the span) are made minimal in their classes (Algorithm 3); the matrix of these is
reduced, its columns normalized and sorted lexicographically, and each one totally reduced by
the previous ones.

\tparam Field `Z2_field`, `Zp_field<p>` or `Q_field`
\returns the basis, in increasing order; its size is the `k`-th Betti number of \f$(K,B)\f$.
*/
template <class Field>
std::vector<Chain<Field>> critical_basis(const Simplicial_complex& complex, int k, const std::vector<std::uint32_t>& order,
                                         const Simplicial_complex* relative = nullptr)
{
  using Column = internal::Sparse_column<Field>;
  const std::size_t m = complex.number_of_simplices(k);
  const std::vector<std::uint32_t> rank = internal::ranks_of(order, m);
  const std::vector<char> in_b_k = internal::simplices_in(complex, k, relative);
  const std::vector<char> in_b_k1 = internal::simplices_in(complex, k + 1, relative);
  // The cycles: kernel columns of V (all k-simplices are cycles when k = 0). A cycle whose
  // largest simplex (its low) is the low of a reduced boundary is left out: for k >= 1 it is
  // that boundary (the clearing of Cycle_basis_reduction), which reduces to zero; for k = 0
  // it reduces to a sum of smaller vertices, which the kept ones span (the set of lows of the
  // boundaries does not depend on the order of the columns). Only the essential cycles (as
  // many as the Betti number) are then made minimal, each by one total reduction.
  std::vector<Column> minimal; // minimal cycles, rows = ranks
  const internal::Column_reduction<Field> boundaries(internal::boundary_by_rank<Field>(complex, k, rank, in_b_k, in_b_k1), m, false);
  auto is_boundary_low = [&](std::uint32_t s) { return boundaries.pivot(rank[s]) != boundaries.none; };
  auto add_minimal = [&](std::vector<typename Field::Value>& g) {
    boundaries.totally_reduce(g);
    Column c;
    for(std::uint32_t r = 0; r < m; ++r) if(!Field::is_zero(g[r])) c.emplace_back(r, g[r]);
    if(!c.empty()) minimal.push_back(std::move(c));
  };
  if(k == 0) {
    for(std::uint32_t s = 0; s < m; ++s) {
      if(in_b_k[s] || is_boundary_low(s)) continue;
      std::vector<typename Field::Value> g(m, Field::zero());
      g[rank[s]] = Field::one();
      add_minimal(g);
    }
  } else {
    const std::vector<char> in_b_km1 = internal::simplices_in(complex, k - 1, relative);
    const internal::Cycle_basis_reduction<Field> cycles(complex, k, order, in_b_k, in_b_km1, &boundaries);
    for(std::size_t p = 0; p < cycles.simplex_of_column.size(); ++p) {
      if(!cycles.reduction->reduced(p).empty() || is_boundary_low(cycles.simplex_of_column[p])) continue;
      std::vector<typename Field::Value> g(m, Field::zero());
      for(const auto& e : cycles.reduction->transformation(p)) g[rank[cycles.simplex_of_column[e.first]]] = e.second;
      add_minimal(g);
    }
  }
  // Observation 4.54: unique lows, normalized, sorted, then each reduced by the previous ones
  const internal::Column_reduction<Field> spanning(std::move(minimal), m, false);
  std::vector<Column> independent;
  for(std::size_t j = 0; j < spanning.number_of_columns(); ++j) {
    Column c = spanning.reduced(j);
    if(c.empty()) continue;
    const typename Field::Value lead = c.back().second;
    for(auto& e : c) e.second = Field::divide(e.second, lead);
    independent.push_back(std::move(c));
  }
  std::sort(independent.begin(), independent.end(), internal::lexicographically_smaller<Field>);
  std::vector<Chain<Field>> basis;
  std::vector<std::uint32_t> previous_of_low(m, std::uint32_t(-1));
  for(std::size_t i = 0; i < independent.size(); ++i) {
    std::vector<typename Field::Value> g(m, Field::zero());
    for(const auto& e : independent[i]) g[e.first] = e.second;
    const std::uint32_t crit = independent[i].back().first;
    for(std::uint32_t r = crit; r-- > 0;) { // the critical simplex stays: lower rows only
      if(Field::is_zero(g[r]) || previous_of_low[r] == std::uint32_t(-1)) continue;
      const Column& c = independent[previous_of_low[r]];
      const typename Field::Value f = Field::divide(g[r], c.back().second);
      for(const auto& e : c) g[e.first] = Field::subtract(g[e.first], Field::multiply(f, e.second));
    }
    previous_of_low[crit] = std::uint32_t(i);
    basis.push_back(internal::sparse<Field>(g, order));
  }
  return basis;
}

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_MINIMAL_CHAINS_H
