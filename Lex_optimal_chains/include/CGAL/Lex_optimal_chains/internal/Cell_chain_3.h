// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CELL_CHAIN_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CELL_CHAIN_3_H

// A 2-chain of a 3D triangulation stored on the cells: one byte per cell, two bits per facet
// holding the coefficient of the facet oriented out of the cell (0, 1, -1, or "multiple":
// another value, which the repair leaves alone). Both cells of a facet hold it (over Q with
// opposite signs). It is the chain as Manifold_chain_repair_3 reads and changes it (the
// `ChainAccess` there).

#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>

#include <CGAL/assertions.h>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class Triangulation>
class Cell_chain_3
{
public:
  using Cell = typename Triangulation::Cell;
  using Cell_handle = typename Triangulation::Cell_handle;
  using Facet = typename Triangulation::Facet;

  // `oriented`: coefficients in Q (signed) rather than Z2
  Cell_chain_3(const Triangulation& dt, bool oriented)
    : dt_(dt), cells_(dt.tds().cells().begin(), dt.tds().cells().end()), codes_(cells_.size(), 0), oriented_(oriented)
  {}

  // Adds the facet (c, i) with the coefficient k > 0, oriented out of c (Z2: k = 1), once.
  void add(const Facet& f, std::int64_t k)
  {
    const Cell* c = &*f.first;
    const Cell* n = &*c->neighbor(f.second);
    const int j = n->index(f.first);
    if(k == 1 || !oriented_) {
      set(c, f.second, 1);
      set(n, j, oriented_ ? -1 : 1);
    } else {
      set(c, f.second, multiple);
      set(n, j, multiple);
    }
  }

  bool oriented() const { return oriented_; }

  // Facet i of c oriented out of c: 0, 1, -1 (Z2: 0, 1), or 2 for a multiple facet.
  int coefficient(const Cell* c, int i) const
  {
    const int code = (codes_[cells_.index(c)] >> (2 * i)) & 3;
    return code == 3 ? -1 : code;
  }

  // Boundaries of infinite cells have infinite facets: they cannot be added.
  bool can_change(const Cell* c) const { return !dt_.is_infinite(Cell_handle(const_cast<Cell*>(c))); }

  // Adds delta times the boundary of c (Z2: delta = 1). No facet may become multiple.
  void change(const Cell* c, int delta)
  {
    for(int i = 0; i < 4; ++i) {
      const int k = coefficient(c, i);
      CGAL_precondition(k != multiple);
      const int updated = oriented_ ? k + delta : (k ^ 1);
      CGAL_precondition(updated >= -1 && updated <= 1);
      const Cell* n = &*c->neighbor(i);
      set(c, i, updated);
      set(n, n->index(Cell_handle(const_cast<Cell*>(c))), oriented_ ? -updated : updated);
    }
  }

private:
  static constexpr int multiple = 2;

  void set(const Cell* c, int i, int k)
  {
    std::uint8_t& code = codes_[cells_.index(c)];
    code = std::uint8_t((code & ~(3 << (2 * i))) | ((k & 3) << (2 * i))); // -1 is 3 in two bits
  }

  const Triangulation& dt_;
  Handle_index_map<Cell> cells_;
  std::vector<std::uint8_t> codes_;
  bool oriented_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CELL_CHAIN_3_H
