// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPEN_SURFACE_REPAIR_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPEN_SURFACE_REPAIR_3_H

// The optimal chain of an open surface written into its soup, its non-manifold vertices
// resolved first (Manifold_chain_repair_3.h). The chain is kept on the cells while it is
// repaired (Cell_chain_3.h); its boundary does not change, and the vertices of the boundary
// are left as they are (the levels around them are not defined).

#include <CGAL/Lex_optimal_chains/internal/Cell_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_builder.h>
#include <CGAL/Lex_optimal_chains/internal/Manifold_chain_repair_3.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <utility>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

struct Open_surface_repair_result
{
  Manifold_repair_statistics statistics;
  std::size_t changed_facets = 0; // in the symmetric difference of the optimal and the output chains
};

// Calls `write_chain(add)`, which must call `add(facet, k)` for every facet of the chain with
// its coefficient k > 0 out of the facet's cell, and puts the chain into `builder`; unless
// `keep_non_manifold`, the non-manifold vertices of the soup are then resolved, and the
// facets that the resolution changed are replaced in `builder`.
template <class Triangulation, class WriteChain>
Open_surface_repair_result resolved_open_chain(const Triangulation& dt, bool oriented, bool keep_non_manifold,
                                               Chain_soup_builder<Triangulation>& builder, const WriteChain& write_chain)
{
  using Facet = typename Triangulation::Facet;
  using Cell = typename Triangulation::Cell;
  using Vertex = typename Triangulation::Vertex;
  Open_surface_repair_result result;
  if(keep_non_manifold) {
    write_chain([&builder](const Facet& f, std::int64_t k) { builder.add(f, k); });
    return result;
  }
  Cell_chain_3<Triangulation> chain(dt, oriented);
  write_chain([&](const Facet& f, std::int64_t k) {
    builder.add(f, k);
    chain.add(f, k);
  });
  const auto suspects = builder.non_manifold_vertices(dt.tds());
  if(suspects.empty()) return result;

  // the facets changed, by their vertices, with a name and their coefficient before (out of
  // the cell of that name)
  std::map<std::array<const Vertex*, 3>, std::pair<Facet, int>> changed;
  auto record = [&](const Cell* c, int i) {
    std::array<const Vertex*, 3> v;
    for(int k = 1; k < 4; ++k) v[k - 1] = &*c->vertex((i + k) & 3);
    std::sort(v.begin(), v.end());
    const Facet f(dt.tds().cells().iterator_to(*const_cast<Cell*>(c)), i);
    changed.emplace(v, std::make_pair(f, chain.coefficient(c, i)));
  };
  Manifold_chain_repair_3<Triangulation, Cell_chain_3<Triangulation>> repair(dt, chain);
  result.statistics = repair.repair(suspects, record);
  // the soup gets the facets whose coefficient changed: removed, added, or reversed (its two
  // cells having changed levels in opposite ways); the removals first, as they go by vertices
  for(const auto& entry : changed) {
    const Facet& f = entry.second.first;
    const int before = entry.second.second, now = chain.coefficient(&*f.first, f.second);
    if(now != before && before != 0) builder.remove(f);
    result.changed_facets += (now != 0) != (before != 0);
  }
  builder.apply_removals();
  for(const auto& entry : changed) {
    const Facet& f = entry.second.first;
    const int before = entry.second.second, now = chain.coefficient(&*f.first, f.second);
    if(now == before) continue;
    if(now == 1) builder.add(f, 1);
    else if(now == -1) builder.add(dt.mirror_facet(f), 1); // -1 out of f's cell: 1 out of the other
  }
  return result;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPEN_SURFACE_REPAIR_3_H
