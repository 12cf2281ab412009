// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_SIMPLICIAL_COMPLEX_H
#define CGAL_LEX_OPTIMAL_CHAINS_SIMPLICIAL_COMPLEX_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef

An abstract simplicial complex for the matrix algorithms of the package (thesis section 4.3):
its vertices are the integers \f$0,\dots,n-1\f$ and each \f$k\f$-simplex is the sorted tuple
of its \f$k+1\f$ vertices. The \f$k\f$-simplices are numbered \f$0,\dots,m_k-1\f$ in the
lexicographic order of their tuples; this numbering is only a name, the algorithms take the
order on simplices as a separate argument.

The complex is closed under faces: it is built from maximal simplices (`add_simplex()` adds
a simplex with all its faces). Adding simplices after a query renumbers the simplices: build
the complex first, then number, order and compute. The queries finalize the numbering on
first use, so a complex shared between threads must be queried once before. Simplices have
dimension 15 at most. The boundary of the simplex \f$[v_0,\dots,v_k]\f$ is
\f$\sum_i (-1)^i [v_0,\dots,\hat{v_i},\dots,v_k]\f$ (orientation by increasing vertices).
*/
class Simplicial_complex
{
public:
  /// A simplex: its vertices, increasing.
  typedef std::vector<std::uint32_t> Simplex;

  /// An empty complex on `number_of_vertices` vertices (which are 0-simplices).
  explicit Simplicial_complex(std::uint32_t number_of_vertices = 0) : n_(number_of_vertices)
  {
    for(std::uint32_t v = 0; v < n_; ++v) add_simplex(Simplex{v});
  }

  /// Adds the simplex with the given vertices (in any order, distinct, below the number of
  /// vertices) and all its faces. \throws Input_error with code `INVALID_CHAIN` otherwise,
  /// `TOO_LARGE` for a dimension above 15.
  void add_simplex(Simplex s)
  {
    std::sort(s.begin(), s.end());
    if(s.empty() || std::adjacent_find(s.begin(), s.end()) != s.end() || s.back() >= n_)
      throw Input_error(Input_error_code::INVALID_CHAIN, "a simplex must have distinct vertices below the number of vertices");
    if(s.size() > 16) throw Input_error(Input_error_code::TOO_LARGE, "simplices of dimension 16 or more are not supported (2^17 faces)");
    const std::size_t k = s.size() - 1;
    if(pending_.size() <= k) pending_.resize(k + 1);
    if(!pending_[k].insert(s).second) return;
    finalized_ = false;
    if(k == 0) return;
    for(std::size_t i = 0; i <= k; ++i) {
      Simplex face = s;
      face.erase(face.begin() + i);
      add_simplex(face);
    }
  }

  /// The number of vertices.
  std::uint32_t number_of_vertices() const { return n_; }

  /// The largest dimension of a simplex (-1 if there is none).
  int dimension() const { return int(pending_.size()) - 1; }

  /// The number of `k`-simplices.
  std::size_t number_of_simplices(int k) const
  {
    finalize();
    return k >= 0 && k < int(simplices_.size()) ? simplices_[k].size() : 0;
  }

  /// The `i`-th `k`-simplex.
  /// \pre `0 <= k <= dimension()` and `i < number_of_simplices(k)`
  const Simplex& simplex(int k, std::size_t i) const
  {
    finalize();
    CGAL_precondition(k >= 0 && k < int(simplices_.size()) && i < simplices_[k].size());
    return simplices_[k][i];
  }

  /// The index of the `k`-simplex with the given (increasing) vertices, or -1.
  long index(const Simplex& s) const
  {
    finalize();
    const std::size_t k = s.size() - 1;
    if(s.empty() || k >= simplices_.size()) return -1;
    const auto it = std::lower_bound(simplices_[k].begin(), simplices_[k].end(), s);
    return it != simplices_[k].end() && *it == s ? long(it - simplices_[k].begin()) : -1;
  }

  /// The boundary of the `i`-th `k`-simplex: pairs (index of a `(k-1)`-face, sign).
  /// \pre `0 <= k <= dimension()` and `i < number_of_simplices(k)`
  std::vector<std::pair<std::uint32_t, int>> boundary(int k, std::size_t i) const
  {
    std::vector<std::pair<std::uint32_t, int>> b;
    if(k == 0) return b;
    const Simplex& s = simplex(k, i);
    for(int j = 0; j <= k; ++j) {
      Simplex face = s;
      face.erase(face.begin() + j);
      b.emplace_back(std::uint32_t(index(face)), j % 2 == 0 ? 1 : -1);
    }
    return b;
  }

  /// The full `d`-complex over `n` vertices: every simplex of dimension at most `d` (in [0, 15]).
  static Simplicial_complex full(std::uint32_t n, int d)
  {
    if(d < 0 || d > 15) throw Input_error(Input_error_code::TOO_LARGE, "the dimension of a full complex must be in [0, 15]");
    Simplicial_complex c(n);
    Simplex s;
    // enumerate the (d+1)-subsets (they carry all smaller simplices as faces); smaller
    // complexes when n <= d
    const std::uint32_t size = std::uint32_t((std::min)(std::size_t(d) + 1, std::size_t(n)));
    if(size == 0) return c;
    for(std::uint32_t i = 0; i < size; ++i) s.push_back(i);
    for(;;) {
      c.add_simplex(s);
      int j = int(size) - 1;
      while(j >= 0 && s[j] == n - size + std::uint32_t(j)) --j;
      if(j < 0) break;
      ++s[j];
      for(std::uint32_t l = std::uint32_t(j) + 1; l < size; ++l) s[l] = s[l - 1] + 1;
    }
    return c;
  }

private:
  void finalize() const
  {
    if(finalized_) return;
    simplices_.assign(pending_.size(), {});
    for(std::size_t k = 0; k < pending_.size(); ++k)
      simplices_[k].assign(pending_[k].begin(), pending_[k].end());
    finalized_ = true;
  }

  std::uint32_t n_;
  std::vector<std::set<Simplex>> pending_;               // by dimension, while building
  mutable std::vector<std::vector<Simplex>> simplices_;  // by dimension, sorted
  mutable bool finalized_ = false;
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_SIMPLICIAL_COMPLEX_H
