// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_REPAIR_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_REPAIR_3_H

// The optimal 2-cycle of a closed surface made manifold (Manifold_chain_repair_3.h): the cycle
// is the boundary of the inside cells, so its levels are the inside flags, and a local change
// moves cells between the inside and the outside. The constraint cells (interior, exterior and
// infinite) never move, so the cycle still separates the constraints. A change can cut a
// few cells off their side (a bubble of inside cells, a pocket of outside ones, touching the
// rest by a vertex that the change removed): such a region holds no constraint cell of its
// side, unlike every region of the optimal cycle, and is moved to the other side.

#include <CGAL/Lex_optimal_chains/internal/Closed_surface_mesh_3.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Manifold_chain_repair_3.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The positions of the constraint cells, sorted: the interior ones (sources) and the exterior
// and infinite ones (sinks).
struct Constraint_cells
{
  std::vector<std::uint32_t> sources, sinks;

  bool is_source(std::uint32_t p) const { return std::binary_search(sources.begin(), sources.end(), p); }
  bool is_sink(std::uint32_t p) const { return std::binary_search(sinks.begin(), sinks.end(), p); }
};

// The cycle as the boundary of the inside cells, for Manifold_chain_repair_3.
template <class Triangulation>
class Inside_cells_chain
{
public:
  using Cell = typename Triangulation::Cell;

  Inside_cells_chain(const Handle_index_map<Cell>& cells, std::vector<bool>& inside, const Constraint_cells& constraints)
    : cells_(cells), inside_(inside), constraints_(constraints)
  {}

  bool oriented() const { return true; }
  int coefficient(const Cell* c, int i) const { return int(is_inside(c)) - int(is_inside(&*c->neighbor(i))); }
  bool can_change(const Cell* c) const
  {
    const std::uint32_t p = cells_.index(c);
    return !constraints_.is_source(p) && !constraints_.is_sink(p);
  }
  void change(const Cell* c, int)
  {
    const std::uint32_t p = cells_.index(c);
    inside_[p] = !inside_[p];
  }
  bool is_inside(const Cell* c) const { return inside_[cells_.index(c)]; }

private:
  const Handle_index_map<Cell>& cells_;
  std::vector<bool>& inside_;
  const Constraint_cells& constraints_;
};

struct Closed_surface_repair_result
{
  Manifold_repair_statistics statistics;
  std::size_t removed_facets = 0, added_facets = 0;
  std::size_t moved_pockets = 0; // regions cut off their side by the changes, moved
  std::vector<bool> removed;        // the facets taken out of their place, by position in the cycle given
  std::vector<std::uint32_t> added; // the facets put after the others (new, or reversed), in that order
  double surface_seconds = 0; // to make the surface of the given cycle (the rest: detection and resolution)
};

// The key of the facet `key` named from the cell across it.
template <class Triangulation>
std::uint32_t mirror_facet_key(const Handle_index_map<typename Triangulation::Cell>& cells, std::uint32_t key)
{
  using Cell = typename Triangulation::Cell;
  const Cell* c = cells.element(key >> 2);
  const Cell* n = &*c->neighbor(int(key & 3));
  int j = 0;
  while(&*n->neighbor(j) != c) ++j;
  return Closed_surface_mesh_3<Triangulation>::facet_key(cells.index(n), j);
}

// The regions of at most `bound` cells, reached from the cells `seeds`, that hold no
// constraint of their side (a source inside, a sink outside) are moved to the other side, until
// none is left; `changed_facet(c, i)` is called with the facets that this changes. Returns the
// number of regions moved. A larger region is assumed to hold its constraint.
template <class Triangulation, class FacetCallback>
std::size_t move_unconstrained_regions(const Handle_index_map<typename Triangulation::Cell>& cells,
                                       Inside_cells_chain<Triangulation>& chain, const Constraint_cells& constraints,
                                       std::vector<const typename Triangulation::Cell*> seeds,
                                       const FacetCallback& changed_facet, std::size_t bound = 256)
{
  using Cell = typename Triangulation::Cell;
  std::size_t moved = 0;
  std::vector<bool> constrained(cells.size(), false); // in a region found to hold its constraint (or large)
  std::vector<const Cell*> region;
  while(!seeds.empty()) {
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    std::vector<const Cell*> next;
    for(const Cell* seed : seeds) {
      if(constrained[cells.index(seed)]) continue;
      const bool side = chain.is_inside(seed);
      region.assign(1, seed);
      bool holds = false;
      for(std::size_t q = 0; q < region.size() && !holds; ++q) {
        const std::uint32_t p = cells.index(region[q]);
        holds = constrained[p] || (side ? constraints.is_source(p) : constraints.is_sink(p)) || region.size() > bound;
        for(int i = 0; i < 4 && !holds; ++i) {
          const Cell* n = &*region[q]->neighbor(i);
          if(chain.is_inside(n) == side && std::find(region.begin(), region.end(), n) == region.end()) region.push_back(n);
        }
      }
      if(holds) {
        for(const Cell* c : region) constrained[cells.index(c)] = true;
        continue;
      }
      ++moved; // a region cut off: to the other side, where it may cut off another (nested)
      for(const Cell* c : region)
        for(int i = 0; i < 4; ++i) {
          const Cell* n = &*c->neighbor(i);
          if(chain.is_inside(n) != side) {
            changed_facet(c, i);
            next.push_back(n);
          }
        }
      for(const Cell* c : region) chain.change(c, side ? -1 : 1);
    }
    seeds.swap(next);
  }
  return moved;
}

// Replaces, in the cycle `facets` (in decreasing order), the facets whose keys (both) are in
// `touched` (sorted) by those of them that bound the inside cells now: the facets not touched
// stay in their order, the touched ones that bound the inside cells follow in decreasing order
// (a touched facet may stay in the cycle reversed, its two cells having changed sides).
template <class Triangulation>
void update_cycle(const Handle_index_map<typename Triangulation::Cell>& cells, const Inside_cells_chain<Triangulation>& chain,
                  const std::vector<std::uint32_t>& touched, std::vector<std::uint32_t>& facets,
                  Closed_surface_repair_result& result)
{
  using Cell = typename Triangulation::Cell;
  auto cell_of = [&](std::uint32_t key) { return cells.element(key >> 2); };
  auto mirror_key = [&](std::uint32_t key) { return mirror_facet_key<Triangulation>(cells, key); };
  auto is_member = [&](std::uint32_t key) {
    const Cell* c = cell_of(key);
    return chain.is_inside(c) != chain.is_inside(&*c->neighbor(int(key & 3)));
  };
  std::vector<bool> touched_cell(cells.size(), false); // a filter before the search
  for(const std::uint32_t key : touched) touched_cell[key >> 2] = true;
  std::vector<std::uint32_t> were_in; // the touched facets of the given cycle, by their smaller key
  std::size_t kept = 0;
  result.removed.assign(facets.size(), false);
  for(std::size_t i = 0; i < facets.size(); ++i) {
    const std::uint32_t key = facets[i];
    if(touched_cell[key >> 2] && std::binary_search(touched.begin(), touched.end(), key)) {
      result.removed[i] = true;
      were_in.push_back((std::min)(key, mirror_key(key)));
      continue;
    }
    facets[kept++] = key;
  }
  facets.resize(kept);
  std::sort(were_in.begin(), were_in.end());
  std::vector<std::pair<Triangle_order_key_3, std::uint32_t>> added;
  for(const std::uint32_t key : touched) {
    if(key > mirror_key(key)) continue; // each facet once
    const bool was_in = std::binary_search(were_in.begin(), were_in.end(), key), is_in = is_member(key);
    result.removed_facets += was_in && !is_in;
    result.added_facets += is_in && !was_in;
    if(!is_in) continue;
    const Cell* c = cell_of(key);
    Triangle_coordinates_3 t;
    for(int k = 1; k < 4; ++k) {
      const auto& p = c->vertex((int(key & 3) + k) & 3)->point();
      t[k - 1] = {{p.x(), p.y(), p.z()}};
    }
    added.emplace_back(Triangle_order_key_3(t), key);
  }
  std::sort(added.begin(), added.end(), [](const auto& a, const auto& b) { return b.first < a.first; });
  for(const auto& a : added) result.added.push_back(a.second);
  facets.insert(facets.end(), result.added.begin(), result.added.end());
}

// Repairs the cycle `facets` (keys `Closed_surface_mesh_3::facet_key()` of either of their
// cells, in decreasing order) bounding the cells flagged in `inside`, around the vertices
// numbered `suspects` in `vertices`, then moves the regions that this cut off their side. On
// return `facets` holds the repaired cycle (see `update_cycle()`).
template <class Triangulation>
Closed_surface_repair_result
repair_closed_surface(const Triangulation& dt, const Handle_index_map<typename Triangulation::Cell>& cells,
                      const Handle_index_map<typename Triangulation::Vertex>& vertices, std::vector<bool>& inside,
                      const Constraint_cells& constraints, const std::vector<std::uint32_t>& suspects,
                      std::vector<std::uint32_t>& facets)
{
  using Cell = typename Triangulation::Cell;
  using Vertex = typename Triangulation::Vertex;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  Closed_surface_repair_result result;
  std::vector<Vertex_handle> start;
  for(const std::uint32_t v : suspects)
    start.push_back(dt.tds().vertices().iterator_to(*const_cast<Vertex*>(vertices.element(v))));
  Inside_cells_chain<Triangulation> chain(cells, inside, constraints);
  std::vector<std::uint32_t> touched; // both keys of each facet changed
  std::vector<const Cell*> seeds;     // the cells on both sides of these facets
  auto record = [&](const Cell* c, int i) {
    const std::uint32_t k = Closed_surface_mesh_3<Triangulation>::facet_key(cells.index(c), i);
    touched.push_back(k);
    touched.push_back(mirror_facet_key<Triangulation>(cells, k));
    seeds.push_back(c);
    seeds.push_back(&*c->neighbor(i));
  };
  Manifold_chain_repair_3<Triangulation, Inside_cells_chain<Triangulation>> repair(dt, chain);
  result.statistics = repair.repair(start, record);
  result.moved_pockets = move_unconstrained_regions<Triangulation>(cells, chain, constraints, seeds, record);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  update_cycle(cells, chain, touched, facets, result);
  return result;
}

// The surface of the cycle `facets` (see `repair_closed_surface()`), its non-manifold
// vertices resolved first unless `keep_non_manifold`; `facets` becomes the cycle of the
// surface. The surface's own twins find the non-manifold vertices, so a manifold cycle costs
// a walk around the vertices more than its surface; after a resolution, the surface reads only
// the facets added, and pairs the twins anew. The surface reads the triangulation on `threads`
// threads.
template <class Triangulation>
std::unique_ptr<Closed_surface_mesh_3<Triangulation>>
manifold_closed_surface(const Triangulation& dt, const Handle_index_map<typename Triangulation::Cell>& cells,
                        const Handle_index_map<typename Triangulation::Vertex>& vertices, std::vector<bool>& inside,
                        const Constraint_cells& constraints, bool keep_non_manifold,
                        std::vector<std::uint32_t>& facets, Closed_surface_repair_result& result,
                        unsigned threads = 1)
{
  using Surface = Closed_surface_mesh_3<Triangulation>;
  Stopwatch watch;
  std::unique_ptr<Surface> surface(new Surface(std::vector<std::uint32_t>(facets), cells, vertices, inside, threads));
  const double surface_seconds = watch.lap();
  if(keep_non_manifold) {
    result.surface_seconds = surface_seconds;
    return surface;
  }
  const std::vector<std::uint32_t> suspects = surface->non_manifold_vertices();
  result.surface_seconds = surface_seconds;
  if(suspects.empty()) return surface;
  result = repair_closed_surface(dt, cells, vertices, inside, constraints, suspects, facets);
  result.surface_seconds = surface_seconds;
  surface->replace_facets(result.removed, result.added, cells, vertices, inside);
  return surface;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_REPAIR_3_H
