// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_MANIFOLD_CHAIN_REPAIR_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_MANIFOLD_CHAIN_REPAIR_3_H

// Makes a 2-chain of a 3D Delaunay triangulation manifold at its non-manifold vertices by
// local changes that keep its boundary: the chain C becomes C + boundary(D) for a 3-chain D
// of cells around the vertex, so a cycle stays a cycle (and separates the same constraints),
// and a chain bounded by a polyline keeps that boundary.
//
// Around a vertex v that is not on the boundary of the chain, the chain is locally the
// boundary of a level function w on the cells of the star of v (w(c') = w(c) - coefficient of
// the facet between them, oriented out of c; levels mod 2 over Z2). With two levels, the
// cells of level 1 form a region of the link of v (a triangulated sphere), and v is a
// manifold point of the chain iff both regions are edge-connected (Jordan's theorem: a pinch
// of one region would separate the other). The candidates at a non-manifold v are: one
// component of level 1 kept and every other cell set to 0; one component of level 0 kept
// and every other cell set to 1; all cells set to 0; all set to 1 (v leaves the chain).
// Among the candidates that are manifold at v and that only change cells the caller allows,
// the one whose chain is lexicographically smallest is applied: the facets where the
// candidate chains differ (all among those of the star's cells) are sorted by the order of
// the triangles, and the chains compared from the largest facet down, the smaller chain being
// the one without the first facet where they differ. The order is exact (Triangle_order_3.h),
// so the choice does not depend on the input order or on memory addresses.
//
// A change can make the vertices of the changed cells non-manifold; they are examined in
// the next round. Vertices are examined in the lexicographic order of their points in each
// round. A cell changes at most once (a candidate that would change a cell again is not
// allowed), so the repair ends after at most as many changes as there are cells, and cannot
// undo its own changes in a cycle. A vertex left non-manifold (on the boundary of the chain,
// in a multiply covered region, or with no allowed candidate) is left to the mesh builders,
// which split it, and counted there.
//
// `ChainAccess` gives and changes the chain:
//   bool oriented() const                       Q (levels in Z) or Z2 (levels mod 2)
//   int coefficient(const Cell* c, int i) const facet i of c, oriented out of c, in {-1, 0, 1}
//                                               (Z2: {0, 1}), or any other value for a
//                                               multiple facet
//   bool can_change(const Cell* c) const        whether boundary(c) may be added
//   void change(const Cell* c, int delta)       adds delta * boundary(c) (Z2: delta = 1)

#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>

#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

struct Manifold_repair_statistics
{
  std::size_t examined_vertices = 0;  // non-manifold vertices met (with repetitions across rounds)
  std::size_t repaired_vertices = 0;  // local changes applied
  std::size_t changed_cells = 0;      // cells whose level changed, over all the changes
  std::size_t rounds = 0;
};

template <class Triangulation, class ChainAccess>
class Manifold_chain_repair_3
{
public:
  using Vertex = typename Triangulation::Vertex;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Cell = typename Triangulation::Cell;
  using Cell_handle = typename Triangulation::Cell_handle;

  Manifold_chain_repair_3(const Triangulation& dt, ChainAccess& chain) : dt_(dt), chain_(chain) {}

  // Repairs around `vertices` (finite vertices of `dt`), then around the vertices that the
  // changes reach. `changed_facet(c, i)` is called with a facet whose membership in the chain
  // changed (possibly several times for one facet, under either of its names).
  template <class FacetCallback>
  Manifold_repair_statistics repair(std::vector<Vertex_handle> vertices, const FacetCallback& changed_facet)
  {
    Manifold_repair_statistics stats;
    for(; !vertices.empty(); ++stats.rounds) {
      sort_by_point(vertices);
      std::vector<Vertex_handle> reached;
      for(const Vertex_handle v : vertices)
        repair_vertex(v, stats, reached, changed_facet);
      vertices.swap(reached);
    }
    return stats;
  }

private:
  // The star of a vertex: its cells, the index of the vertex in each, the star positions of
  // the neighbors across the facets through the vertex (-1 across the facet opposite it) and
  // the levels.
  struct Star
  {
    std::vector<const Cell*> cells;
    std::vector<int> vertex_index;
    std::vector<std::array<int, 4>> across;
    std::vector<int> level;
  };

  // A facet that a candidate can change: facet `index` of star cell `cell`, with the star
  // cell across it (-1 if outside the star) and its coefficient in the chain.
  struct Star_facet
  {
    int cell, index, other;
    int coefficient;
  };

  void sort_by_point(std::vector<Vertex_handle>& vertices) const
  {
    std::sort(vertices.begin(), vertices.end(), [](const Vertex_handle a, const Vertex_handle b) {
      return CGAL::compare_xyz(a->point(), b->point()) == SMALLER;
    });
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  }

  // Fills the star of v and its levels; false if v is on the boundary of the chain (the
  // levels are inconsistent), in a multiply covered region, or if a facet is multiple.
  bool make_star(const Vertex_handle v, Star& star) const
  {
    std::vector<Cell_handle> cells;
    dt_.incident_cells(v, std::back_inserter(cells));
    star.cells.clear();
    for(const Cell_handle& c : cells) star.cells.push_back(&*c);
    std::sort(star.cells.begin(), star.cells.end());
    const std::size_t n = star.cells.size();
    star.vertex_index.assign(n, -1);
    star.across.assign(n, std::array<int, 4>{{-1, -1, -1, -1}});
    star.level.assign(n, 0);
    for(std::size_t s = 0; s < n; ++s) {
      const Cell* c = star.cells[s];
      star.vertex_index[s] = c->index(v);
      for(int j = 0; j < 4; ++j)
        if(j != star.vertex_index[s]) star.across[s][j] = position(star, &*c->neighbor(j));
    }
    // levels by a traversal across the facets through v
    std::vector<char> seen(n, 0);
    std::vector<int> queue{0};
    seen[0] = 1;
    for(std::size_t q = 0; q < queue.size(); ++q) {
      const int s = queue[q];
      for(int j = 0; j < 4; ++j) {
        const int t = star.across[s][j];
        if(t < 0) continue;
        const int k = chain_.coefficient(star.cells[s], j);
        if(k < -1 || k > 1 || (!chain_.oriented() && k < 0)) return false;
        const int expected = chain_.oriented() ? star.level[s] - k : (star.level[s] ^ k);
        if(!seen[t]) {
          seen[t] = 1;
          star.level[t] = expected;
          queue.push_back(t);
        } else if(star.level[t] != expected) {
          return false; // v is on the boundary of the chain
        }
      }
    }
    const auto range = std::minmax_element(star.level.begin(), star.level.end());
    const int lowest = *range.first;
    if(*range.second - lowest > 1) return false;
    for(int& l : star.level) l -= lowest;
    return true;
  }

  static int position(const Star& star, const Cell* c)
  {
    const auto it = std::lower_bound(star.cells.begin(), star.cells.end(), c);
    return (it != star.cells.end() && *it == c) ? int(it - star.cells.begin()) : -1;
  }

  // The edge-connected components of the cells of level `value` in `levels` (the others get -1).
  static int components(const Star& star, const std::vector<int>& levels, int value, std::vector<int>& component)
  {
    const std::size_t n = star.cells.size();
    component.assign(n, -1);
    int count = 0;
    std::vector<int> queue;
    for(std::size_t start = 0; start < n; ++start) {
      if(levels[start] != value || component[start] >= 0) continue;
      component[start] = count;
      queue.assign(1, int(start));
      for(std::size_t q = 0; q < queue.size(); ++q)
        for(const int t : star.across[queue[q]])
          if(t >= 0 && levels[t] == value && component[t] < 0) {
            component[t] = count;
            queue.push_back(t);
          }
      ++count;
    }
    return count;
  }

  static bool is_manifold(const Star& star, const std::vector<int>& levels)
  {
    std::vector<int> component;
    return components(star, levels, 0, component) <= 1 && components(star, levels, 1, component) <= 1;
  }

  // The candidate levels of a non-manifold star (see the header comment).
  static std::vector<std::vector<int>> candidates(const Star& star)
  {
    std::vector<std::vector<int>> result;
    std::vector<int> component;
    for(int value = 0; value < 2; ++value) {
      const int count = components(star, star.level, value, component);
      for(int k = 0; k < count; ++k) {
        std::vector<int> levels(star.cells.size());
        for(std::size_t s = 0; s < levels.size(); ++s) levels[s] = (component[s] == k) ? value : 1 - value;
        result.push_back(std::move(levels));
      }
    }
    result.emplace_back(star.cells.size(), 0);
    result.emplace_back(star.cells.size(), 1);
    return result;
  }

  // The finite facets of the star's cells, each once.
  std::vector<Star_facet> star_facets(const Star& star) const
  {
    std::vector<Star_facet> facets;
    for(std::size_t s = 0; s < star.cells.size(); ++s) {
      const Cell* c = star.cells[s];
      for(int j = 0; j < 4; ++j) {
        const int t = star.across[s][j];
        if(t >= 0 && t < int(s)) continue; // named from the smaller position
        bool finite = true;
        for(int k = 1; k < 4 && finite; ++k) finite = !dt_.is_infinite(c->vertex((j + k) & 3));
        if(finite) facets.push_back(Star_facet{int(s), j, t, chain_.coefficient(c, j)}); // else never in the chain
      }
    }
    return facets;
  }

  Triangle_coordinates_3 coordinates(const Star& star, const Star_facet& f) const
  {
    Triangle_coordinates_3 t;
    for(int k = 1; k < 4; ++k) {
      const auto& p = star.cells[f.cell]->vertex((f.index + k) & 3)->point();
      t[k - 1] = {{p.x(), p.y(), p.z()}};
    }
    return t;
  }

  // The candidate (index in `supports`, the memberships of `facets` in each candidate chain)
  // whose chain is lexicographically smallest: the facets where the candidates differ are
  // sorted by the order of the triangles, and the chains compared from the largest facet
  // down, the smaller one being without the first facet where they differ. Equal chains: the
  // first candidate.
  std::size_t smallest_chain(const Star& star, const std::vector<Star_facet>& facets,
                             const std::vector<std::vector<char>>& supports) const
  {
    if(supports.size() == 1) return 0;
    std::vector<std::size_t> differing;
    for(std::size_t i = 0; i < facets.size(); ++i)
      for(std::size_t k = 1; k < supports.size(); ++k)
        if(supports[k][i] != supports[0][i]) { differing.push_back(i); break; }
    std::vector<Triangle_order_key_3> keys;
    for(const std::size_t i : differing) keys.emplace_back(coordinates(star, facets[i]));
    std::vector<std::size_t> order(differing.size()); // positions in `differing`, from the largest facet
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[b] < keys[a]; });
    std::size_t best = 0;
    for(std::size_t k = 1; k < supports.size(); ++k)
      for(const std::size_t o : order) {
        const std::size_t i = differing[o];
        if(supports[k][i] != supports[best][i]) {
          if(supports[k][i] == 0) best = k;
          break;
        }
      }
    return best;
  }

  // The coefficient of a facet once the star's levels change from `star.level` to `levels`.
  int new_coefficient(const Star& star, const Star_facet& f, const std::vector<int>& levels) const
  {
    const int ds = levels[f.cell] - star.level[f.cell];
    const int dt = f.other >= 0 ? levels[f.other] - star.level[f.other] : 0;
    if(chain_.oriented()) return f.coefficient + ds - dt;
    return f.coefficient ^ (ds & 1) ^ (dt & 1);
  }

  // Whether a candidate is allowed: manifold at v, changing allowed cells only, making no
  // multiple facet. Fills `support` with the membership of the sorted facets.
  bool admissible(const Star& star, const std::vector<Star_facet>& facets, const std::vector<int>& levels,
                  std::vector<char>& support) const
  {
    for(std::size_t s = 0; s < levels.size(); ++s)
      if(levels[s] != star.level[s] && (!chain_.can_change(star.cells[s]) || is_changed(star.cells[s]))) return false;
    if(!is_manifold(star, levels)) return false;
    support.resize(facets.size());
    for(std::size_t i = 0; i < facets.size(); ++i) {
      const int k = new_coefficient(star, facets[i], levels);
      if(k < -1 || k > 1) return false;
      support[i] = k != 0;
    }
    return true;
  }

  template <class FacetCallback>
  void repair_vertex(const Vertex_handle v, Manifold_repair_statistics& stats, std::vector<Vertex_handle>& reached,
                     const FacetCallback& changed_facet)
  {
    Star star;
    if(!make_star(v, star) || is_manifold(star, star.level)) return;
    ++stats.examined_vertices;
    const std::vector<Star_facet> facets = star_facets(star);
    std::vector<std::vector<int>> allowed;
    std::vector<std::vector<char>> supports;
    std::vector<char> support;
    for(std::vector<int>& levels : candidates(star))
      if(admissible(star, facets, levels, support)) {
        allowed.push_back(std::move(levels));
        supports.push_back(support);
      }
    if(allowed.empty()) return;
    const std::size_t chosen = smallest_chain(star, facets, supports);
    const std::vector<int>& best = allowed[chosen];
    ++stats.repaired_vertices;
    for(std::size_t i = 0; i < facets.size(); ++i)
      if(supports[chosen][i] != (facets[i].coefficient != 0)) changed_facet(star.cells[facets[i].cell], facets[i].index);
    for(std::size_t s = 0; s < best.size(); ++s) {
      const int delta = best[s] - star.level[s];
      if(delta == 0) continue;
      ++stats.changed_cells;
      chain_.change(star.cells[s], chain_.oriented() ? delta : 1);
      changed_.insert(star.cells[s]);
      for(int k = 0; k < 4; ++k) {
        const Vertex_handle w = star.cells[s]->vertex(k);
        if(w != v && !dt_.is_infinite(w)) reached.push_back(w);
      }
    }
  }

  bool is_changed(const Cell* c) const { return changed_.count(c) != 0; }

  const Triangulation& dt_;
  ChainAccess& chain_;
  std::unordered_set<const Cell*> changed_; // the cells changed once already
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_MANIFOLD_CHAIN_REPAIR_3_H
