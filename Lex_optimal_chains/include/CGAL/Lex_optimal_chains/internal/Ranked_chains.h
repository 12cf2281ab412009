// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RANKED_CHAINS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RANKED_CHAINS_H

// Chains of triangles, given by the indices of their vertices in sorted points, as the ranks
// of their triangles in the package's order on triangles: the columns that the critical
// basis over Z2 (Sparse_critical_basis.h) reduces.

#include <CGAL/Lex_optimal_chains/Simplex_orders.h>
#include <CGAL/Lex_optimal_chains/internal/Sparse_critical_basis.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// A triangle as the indices of its vertices in the sorted points, increasing.
using Triangle_key = std::array<std::uint32_t, 3>;

// The key of the triangle of the facet `f` of a triangulation whose vertices are the sorted
// points `points`.
template <class Point, class Facet>
Triangle_key triangle_key(const std::vector<Point>& points, const Facet& f)
{
  Triangle_key k;
  for(int j = 0; j < 3; ++j)
    k[j] = std::uint32_t(std::lower_bound(points.begin(), points.end(), f.first->vertex((f.second + 1 + j) & 3)->point()) -
                         points.begin());
  std::sort(k.begin(), k.end());
  return k;
}

// The triangles of `chains` (keys into the sorted `points`) ranked in the package's order on
// triangles: `triangles` sorted by key, `by_order[r]` the triangle of rank r, and each chain as
// the increasing ranks of its triangles, whole (`absolute`) and without those of `b_triangles`
// (sorted keys: `relative`).
template <class Point>
struct Ranked_chains
{
  std::vector<Triangle_key> triangles;
  std::vector<std::uint32_t> by_order;
  std::vector<Z2_chain> absolute, relative;

  Ranked_chains(const std::vector<Point>& points, const std::vector<std::vector<Triangle_key>>& chains,
                const std::vector<Triangle_key>& b_triangles)
    : absolute(chains.size()), relative(chains.size())
  {
    for(const auto& c : chains) triangles.insert(triangles.end(), c.begin(), c.end());
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
    const Triangle_order<Point> order(points);
    using Key = decltype(order.key({0, 1, 2}));
    std::vector<std::pair<Key, std::uint32_t>> keyed; // the radii computed once per triangle
    for(std::uint32_t i = 0; i < triangles.size(); ++i)
      keyed.emplace_back(order.key({triangles[i][0], triangles[i][1], triangles[i][2]}), i);
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return compare(a.first, b.first) == SMALLER; });
    std::vector<std::uint32_t> rank(triangles.size());
    for(std::uint32_t r = 0; r < keyed.size(); ++r) {
      by_order.push_back(keyed[r].second);
      rank[keyed[r].second] = r;
    }
    for(std::size_t i = 0; i < chains.size(); ++i) {
      for(const Triangle_key& t : chains[i]) {
        const std::uint32_t r = rank[std::size_t(std::lower_bound(triangles.begin(), triangles.end(), t) - triangles.begin())];
        absolute[i].push_back(r);
        if(!std::binary_search(b_triangles.begin(), b_triangles.end(), t)) relative[i].push_back(r);
      }
      std::sort(absolute[i].begin(), absolute[i].end());
      std::sort(relative[i].begin(), relative[i].end());
    }
  }
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RANKED_CHAINS_H
