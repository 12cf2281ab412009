// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_MESH_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_MESH_3_H

// The boundary of a union of tetrahedra (the inside cells) as a closed, oriented,
// combinatorial 2-manifold. Non-manifold places are resolved as for an infinitesimally
// shrunk union: around a Delaunay edge shared by several inside wedges, each wedge gets its
// own copy of the edge (the twin of a boundary half-edge is found by turning around the
// edge through inside cells only; an edge of exactly two boundary facets, the common case,
// joins them directly); around a vertex, each umbrella (cycle of facets linked by twins)
// gets its own copy of the vertex.

#include <CGAL/Lex_optimal_chains/internal/Dense_numbers.h>
#include <CGAL/Lex_optimal_chains/internal/Edge_groups.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Large_array_allocator.h>
#include <CGAL/Lex_optimal_chains/internal/Parallel_blocks.h>
#include <CGAL/Lex_optimal_chains/internal/Prefetch.h>
#include <CGAL/Lex_optimal_chains/internal/Radix_sort.h>
#include <CGAL/Lex_optimal_chains/internal/Union_find.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Local indices of the vertices of facet i of a positively oriented cell, in the order
// that makes the facet's normal point out of the cell.
inline std::array<int, 3> outward_facet_vertices(int i)
{
  std::array<int, 3> v{{(i + 1) & 3, (i + 2) & 3, (i + 3) & 3}};
  if(i & 1) std::swap(v[1], v[2]);
  return v;
}

struct Closed_surface_statistics
{
  std::size_t vertices = 0, faces = 0, components = 0;
  std::size_t non_manifold_vertices = 0, non_manifold_edges = 0;
  long genus = 0;
};

template <class Triangulation>
class Closed_surface_mesh_3
{
public:
  using Vertex = typename Triangulation::Vertex;
  using Cell = typename Triangulation::Cell;
  using Point = typename Triangulation::Point;

  // From this many facets, the constructor reads them on several threads when it is given more
  // than one.
  static constexpr std::size_t minimum_facets_for_parallel_reading = 200000;

  // The key of facet i of the cell at position p in the cell numbering: 4 * p + i.
  static std::uint32_t facet_key(std::uint32_t cell_position, int i) { return (cell_position << 2) | std::uint32_t(i); }

  // Reads from the triangulation all that the surface needs, and keeps no reference to it: the
  // triangulation may be freed once this constructor returns (that is when the memory peaks).
  // `facet_keys`: the boundary facets in their canonical order, each as the `facet_key()` of
  // either of its two cells (emptied here), the facet being oriented out of the inside one
  // (the cut names a facet by the cell that owns its record, inside or not: naming it by its
  // inside cell would read the other cell, at random); `cells` numbers the cells and
  // `inside[cells.index(c)]` tells if a cell is inside; `vertex_positions` numbers the vertices.
  // `threads`: the number of threads that read the triangulation (the surface is the same for
  // any number).
  Closed_surface_mesh_3(std::vector<std::uint32_t>&& facet_keys, const Handle_index_map<Cell>& cells,
                        const Handle_index_map<Vertex>& vertex_positions, const std::vector<bool>& inside,
                        unsigned threads = 1)
  {
    const std::size_t nf = facet_keys.size();
    CGAL_precondition(nf < (std::size_t(1) << 30));
    // Internally the facets are kept in the order of their cells in memory, so that the
    // corners, edges and umbrellas are read nearby; `rank_of_` keeps the given (canonical)
    // order for the numbering of the output.
    {
      Large_vector<std::uint64_t> order(nf), buffer;
      for(std::size_t k = 0; k < nf; ++k) order[k] = (std::uint64_t(facet_keys[k]) << 32) | k;
      std::vector<std::uint32_t>().swap(facet_keys);
      radix_sort_high_words(order, buffer);
      Large_vector<std::uint64_t>().swap(buffer);
      keys_.resize(nf);
      rank_of_.resize(nf);
      for(std::size_t k = 0; k < nf; ++k) {
        keys_[k] = std::uint32_t(order[k] >> 32);
        rank_of_[k] = std::uint32_t(order[k]);
      }
    }
    const Triangulation_reader reader{keys_, cells, vertex_positions, inside};
    corners_.resize(3 * nf);
    Parallel_blocks parallel(threads, minimum_facets_for_parallel_reading);
    parallel.run(0, nf, std::size_t(1) << 14, nf,
                 [&](std::size_t, std::size_t first, std::size_t last) { read_corners(reader, first, last); });
    pair_twins(reader);
    // the points, by vertex number
    vertex_points_.resize(vertex_positions.size());
    for(std::uint32_t v = 0; v < vertex_positions.size(); ++v) vertex_points_[v] = vertex_positions.element(v)->point();
  }

  // Replaces the facets of ranks flagged in `removed` (by rank in the order given to the
  // constructor) by the facets `added` (keys of either cell), which follow the facets kept in
  // the canonical order; `inside` is the new side of the cells. Only the added facets are read
  // from the triangulation, and only the edges of the removed and added facets are paired
  // anew: around any other edge no cell changed side (a cell that does changes all its
  // facets), so its twins are those it had. Before `complete()`.
  void replace_facets(const std::vector<bool>& removed, const std::vector<std::uint32_t>& added,
                      const Handle_index_map<Cell>& cells, const Handle_index_map<Vertex>& vertex_positions,
                      const std::vector<bool>& inside)
  {
    CGAL_precondition(!completed_ && removed.size() == rank_of_.size());
    Large_vector<std::uint32_t> new_rank(removed.size()); // of the facets kept, in the given order
    std::uint32_t kept = 0;
    for(std::size_t r = 0; r < removed.size(); ++r) new_rank[r] = removed[r] ? UINT32_MAX : kept++;
    Large_vector<std::uint32_t> new_position(keys_.size(), UINT32_MAX); // memory order: old -> new
    std::vector<std::uint64_t> changed_edges; // of the removed and the added facets
    std::size_t n = 0;
    for(std::size_t k = 0; k < keys_.size(); ++k) {
      if(removed[rank_of_[k]]) { // its corners are still in place: only positions up to n < k were written
        add_edges_of_facet(k, changed_edges);
        continue;
      }
      new_position[k] = std::uint32_t(n);
      keys_[n] = keys_[k];
      rank_of_[n] = new_rank[rank_of_[k]];
      for(int e = 0; e < 3; ++e) corners_[3 * n + e] = corners_[3 * k + e];
      ++n;
    }
    keys_.resize(n + added.size());
    rank_of_.resize(n + added.size());
    corners_.resize(3 * (n + added.size()));
    for(std::size_t i = 0; i < added.size(); ++i) {
      keys_[n + i] = added[i];
      rank_of_[n + i] = std::uint32_t(kept + i);
    }
    const Triangulation_reader reader{keys_, cells, vertex_positions, inside};
    read_corners(reader, n, keys_.size());
    for(std::size_t k = n; k < keys_.size(); ++k) add_edges_of_facet(k, changed_edges);
    std::sort(changed_edges.begin(), changed_edges.end());
    changed_edges.erase(std::unique(changed_edges.begin(), changed_edges.end()), changed_edges.end());
    pair_changed_twins(reader, new_position, changed_edges);
  }

  // The numbers of the non-manifold vertices, in increasing order: the ends of the
  // non-manifold edges, and the vertices around which the facets form several umbrellas
  // (cycles of facets linked by twins). Before `complete()`.
  std::vector<std::uint32_t> non_manifold_vertices() const
  {
    CGAL_precondition(!completed_);
    std::vector<bool> seen(corners_.size(), false);
    std::vector<std::uint8_t> umbrellas(vertex_points_.size(), 0);
    std::vector<std::uint32_t> result(non_manifold_edge_ends_);
    for(std::uint32_t c = 0; c < corners_.size(); ++c) {
      if(seen[c]) continue;
      std::uint32_t x = c;
      do {
        seen[x] = true;
        x = next_corner_around_vertex(x);
      } while(x != c);
      std::uint8_t& n = umbrellas[corners_[c]];
      if(n < 2 && ++n == 2) result.push_back(corners_[c]);
    }
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }

  // Finishes the surface without the triangulation, which may have been freed: one vertex
  // copy per umbrella, the statistics, and the canonical numbering that `build()` follows.
  // Must be called once, before `statistics()` and `build()`.
  void complete()
  {
    CGAL_precondition(!completed_);
    completed_ = true;
    Large_vector<std::uint32_t>().swap(keys_);
    const std::size_t nf = rank_of_.size();
    // one vertex copy per umbrella (the cycle of corners around a vertex linked by twins).
    // Umbrellas are walked in the memory order of the facets (their corners are then
    // nearby), and the copies are numbered afterwards in the canonical order: by the first
    // corner (3 * rank + e) of each umbrella in the given order of the facets.
    corner_vertex_.assign(3 * nf, UINT32_MAX);
    Large_vector<std::uint32_t> copies; // vertex number of each copy, in the canonical order
    {
      Large_vector<std::uint32_t> first_corner; // of each copy, in walk order
      for(std::uint32_t c = 0; c < 3 * nf; ++c) {
        if(corner_vertex_[c] != UINT32_MAX) continue;
        const std::uint32_t id = std::uint32_t(first_corner.size());
        first_corner.push_back(c);
        std::uint32_t x = c;
        do {
          corner_vertex_[x] = id;
          x = next_corner_around_vertex(x);
        } while(x != c);
      }
      // the first canonical corner of each copy, in a pass in memory order (in the walks, the
      // ranks were one more read at random per step)
      Large_vector<std::uint32_t> first(first_corner.size(), UINT32_MAX);
      for(std::uint32_t c = 0; c < 3 * nf; ++c) {
        std::uint32_t& f = first[corner_vertex_[c]];
        f = (std::min)(f, 3 * rank_of_[c / 3] + c % 3);
      }
      Large_vector<std::uint64_t> canonical(first.size()); // (first canonical corner << 32) | walk id
      for(std::uint32_t id = 0; id < first.size(); ++id) canonical[id] = (std::uint64_t(first[id]) << 32) | id;
      Large_vector<std::uint32_t>().swap(first);
      Large_vector<std::uint64_t> buffer;
      radix_sort_high_words(canonical, buffer);
      Large_vector<std::uint64_t>().swap(buffer);
      Large_vector<std::uint32_t> number(canonical.size());
      copies.resize(canonical.size());
      for(std::size_t i = 0; i < canonical.size(); ++i) {
        const std::uint32_t id = std::uint32_t(canonical[i]);
        number[id] = std::uint32_t(i);
        copies[i] = corners_[first_corner[id]];
      }
      for(std::uint32_t& v : corner_vertex_) v = number[v];
    }
    Large_vector<std::uint32_t>().swap(corners_);

    // statistics: vertices split in several copies (split edges were counted with the twins)
    stats_.vertices = copies.size();
    stats_.faces = nf;
    {
      std::vector<std::uint8_t> copies_of(vertex_points_.size(), 0);
      for(const std::uint32_t v : copies) {
        std::uint8_t& n = copies_of[v];
        if(n == 1) ++stats_.non_manifold_vertices;
        n = std::uint8_t((std::min)(int(n) + 1, 2));
      }
    }
    points_.reserve(copies.size());
    for(const std::uint32_t v : copies) points_.push_back(vertex_points_[v]);
    Large_vector<Point>().swap(vertex_points_);
    Large_vector<std::uint32_t>().swap(copies);

    // components and the sum of their genera: every component is a closed oriented surface,
    // of even Euler characteristic V - E + F = V - F/2 (E = 3F/2), and genus (2 - chi) / 2, so
    // the sum is the number of components minus half the total characteristic
    {
      Union_find components(nf);
      for(std::uint32_t h = 0; h < 3 * nf; ++h)
        if(h < twin_[h]) components.unite(h / 3, twin_[h] / 3); // each edge once
      for(std::uint32_t k = 0; k < nf; ++k)
        if(components.find(k) == k) ++stats_.components;
      const std::int64_t chi = std::int64_t(points_.size()) - std::int64_t(nf) / 2;
      CGAL_assertion(nf % 2 == 0 && chi % 2 == 0);
      stats_.genus = long(std::int64_t(stats_.components) - chi / 2);
    }

    // half-edges and corners renumbered in the canonical order of the facets (3 * rank + e),
    // which `build()` follows
    {
      // read in memory order (a twin is nearby), written at random
      Large_vector<std::uint32_t> twin(3 * nf), corner_vertex(3 * nf);
      for(std::uint32_t k = 0; k < nf; ++k)
        for(std::uint32_t e = 0; e < 3; ++e) {
          const std::uint32_t h = 3 * k + e, t = twin_[h];
          twin[3 * rank_of_[k] + e] = 3 * rank_of_[t / 3] + t % 3;
          corner_vertex[3 * rank_of_[k] + e] = corner_vertex_[h];
        }
      twin_.swap(twin);
      corner_vertex_.swap(corner_vertex);
      Large_vector<std::uint32_t>().swap(rank_of_);
    }
  }

  const Closed_surface_statistics& statistics() const
  {
    CGAL_precondition(completed_);
    return stats_;
  }

  // Adds the surface to `mesh` (a model of `MutableFaceGraph`), after `complete()`.
  template <class PolygonMesh, class VertexPointMap>
  void build(PolygonMesh& mesh, VertexPointMap vpm) const
  {
    CGAL_precondition(completed_);
    using GT = boost::graph_traits<PolygonMesh>;
    using vertex_descriptor = typename GT::vertex_descriptor;
    using halfedge_descriptor = typename GT::halfedge_descriptor;
    using face_descriptor = typename GT::face_descriptor;

    reserve(mesh, static_cast<typename GT::vertices_size_type>(num_vertices(mesh) + points_.size()),
            static_cast<typename GT::edges_size_type>(num_edges(mesh) + twin_.size() / 2),
            static_cast<typename GT::faces_size_type>(num_faces(mesh) + twin_.size() / 3));
    std::vector<vertex_descriptor> vd(points_.size());
    for(std::size_t i = 0; i < points_.size(); ++i) {
      vd[i] = add_vertex(mesh);
      put(vpm, vd[i], points_[i]);
    }
    // half-edge h = 3 * rank + e of facet `rank` in the canonical order; edges are created
    // in that order, at the first of their two half-edges
    const std::uint32_t nh = std::uint32_t(twin_.size());
    std::vector<halfedge_descriptor> hd(nh);
    for(std::uint32_t h = 0; h < nh; ++h)
      if(h < twin_[h]) {
        const halfedge_descriptor a = halfedge(add_edge(mesh), mesh);
        hd[h] = a;
        hd[twin_[h]] = opposite(a, mesh);
      }
    // the half-edge of a vertex is the one entering it in its first facet
    for(std::uint32_t h = nh; h-- > 0;) {
      const vertex_descriptor v = vd[corner_vertex_[3 * (h / 3) + (h % 3 + 1) % 3]];
      set_target(hd[h], v, mesh);
      set_halfedge(v, hd[h], mesh);
    }
    for(std::uint32_t h = 0; h < nh; h += 3) {
      const face_descriptor f = add_face(mesh);
      for(std::uint32_t e = 0; e < 3; ++e) {
        set_next(hd[h + e], hd[h + (e + 1) % 3], mesh);
        set_face(hd[h + e], f, mesh);
      }
      set_halfedge(f, hd[h], mesh);
    }
  }

private:
  // The triangulation as the constructor reads it: the facets (in memory order) by their keys.
  struct Triangulation_reader
  {
    const Large_vector<std::uint32_t>& keys;
    const Handle_index_map<Cell>& cells;
    const Handle_index_map<Vertex>& vertices;
    const std::vector<bool>& inside;

    const Cell* cell(std::size_t k) const { return cells.element(keys[k] >> 2); }
    int index(std::size_t k) const { return int(keys[k] & 3); }
    bool is_inside(const Cell* c) const { return inside[cells.index(c)]; }
    bool named_from_inside(std::size_t k) const { return inside[keys[k] >> 2]; }
    // facet k as (its inside cell, its index there)
    std::pair<const Cell*, int> from_inside(std::size_t k) const
    {
      const Cell* c = cell(k);
      if(named_from_inside(k)) return std::make_pair(c, index(k));
      const Cell* n = &*c->neighbor(index(k));
      int j = 0;
      while(&*n->neighbor(j) != c) ++j;
      return std::make_pair(n, j);
    }
  };

  // The corners of the facets at the positions [from, nf) (in memory order): the vertex
  // numbers of the outward vertices of each facet, rotated to start at the lexicographically
  // smallest point, so that the output does not depend on the vertex order in the cells.
  // Writes the corners of these facets only.
  void read_corners(const Triangulation_reader& reader, std::size_t from, std::size_t nf)
  {
    // the cells (in increasing address, but far apart) and then their vertices are fetched
    // early: the reads of successive facets overlap instead of waiting one after the other
    constexpr std::size_t cells_ahead = 16, vertices_ahead = 8;
    for(std::size_t k = from; k < nf; ++k) {
      if(k + cells_ahead < nf) prefetch_object(reader.cell(k + cells_ahead));
      if(k + vertices_ahead < nf) {
        const Cell* a = reader.cell(k + vertices_ahead);
        for(const int i : outward_facet_vertices(reader.index(k + vertices_ahead))) prefetch_object(&*a->vertex(i));
      }
      const Cell* c = reader.cell(k);
      auto ov = outward_facet_vertices(reader.index(k));
      if(!reader.named_from_inside(k)) std::swap(ov[1], ov[2]); // out of the other cell
      const Vertex* v[3];
      for(int i = 0; i < 3; ++i) v[i] = &*c->vertex(ov[i]);
      int first = 0;
      for(int i = 1; i < 3; ++i)
        if(CGAL::compare_xyz(v[i]->point(), v[first]->point()) == SMALLER) first = i;
      for(int i = 0; i < 3; ++i) corners_[3 * k + i] = reader.vertices.index(v[(first + i) % 3]);
    }
  }

  // The twins of all the half-edges. An edge of the triangulation with exactly two boundary
  // facets joins them (the boundary of a union of cells is a cycle, so no other facet can be
  // met when turning around it); they are found by bucketing the half-edges by their smaller
  // vertex.
  void pair_twins(const Triangulation_reader& reader)
  {
    const std::size_t nf = keys_.size();
    twin_.assign(3 * nf, UINT32_MAX);
    if(pair_twins_by_vertices(reader.vertices.size()) == 3 * nf) return;
    std::vector<std::uint32_t> unpaired; // positions (in memory order) of these facets
    for(std::uint32_t k = 0; k < nf; ++k)
      if(twin_[3 * k] == UINT32_MAX || twin_[3 * k + 1] == UINT32_MAX || twin_[3 * k + 2] == UINT32_MAX)
        unpaired.push_back(k);
    pair_around_non_manifold_edges(reader, unpaired);
  }

  // The twins of the half-edges of the facets at the positions `unpaired` (increasing) that
  // have none: these lie on non-manifold edges (four or more boundary facets), around which
  // we turn through the inside cells. The facet met there has its half-edge on that edge
  // unpaired too, so the table holds only the facets with an unpaired half-edge (a few, not
  // all of them: a table of all the facets would be another array of the size of the surface).
  void pair_around_non_manifold_edges(const Triangulation_reader& reader, const std::vector<std::uint32_t>& unpaired)
  {
    Dense_numbers table(unpaired.size()); // their keys, named from their inside cells
    for(const std::uint32_t k : unpaired) {
      const auto f = reader.from_inside(k);
      table.insert(facet_key(reader.cells.index(f.first), f.second)); // number i: unpaired[i]
    }
    CGAL_assertion(table.size() == unpaired.size()); // distinct facets, distinct keys
    for(const std::uint32_t k : unpaired)
      for(int e = 0; e < 3; ++e) {
        const std::uint32_t h = std::uint32_t(3 * k + e);
        if(twin_[h] != UINT32_MAX) continue;
        const std::uint32_t t = find_twin(reader, table, unpaired, k, e);
        CGAL_assertion(twin_[t] == UINT32_MAX);
        twin_[h] = t;
        twin_[t] = h;
      }
  }

  // The edge of half-edge h as (smaller vertex << 32) | larger vertex.
  std::uint64_t edge_of(std::uint32_t h) const
  {
    const std::uint32_t u = corners_[h], v = corners_[3 * (h / 3) + (h % 3 + 1) % 3];
    return (std::uint64_t((std::min)(u, v)) << 32) | (std::max)(u, v);
  }

  void add_edges_of_facet(std::size_t k, std::vector<std::uint64_t>& edges) const
  {
    for(std::uint32_t e = 0; e < 3; ++e) edges.push_back(edge_of(std::uint32_t(3 * k + e)));
  }

  // The twins after `replace_facets()`: the old twin of a half-edge of a kept facet (at the
  // position `new_position` gives) unless its edge is one of `changed_edges` (sorted); the
  // half-edges on these edges are paired as in `pair_twins()`, and the non-manifold edges
  // among them replace those that were counted there.
  void pair_changed_twins(const Triangulation_reader& reader, const Large_vector<std::uint32_t>& new_position,
                          const std::vector<std::uint64_t>& changed_edges)
  {
    std::vector<bool> touched(reader.vertices.size(), false); // the ends of the changed edges
    for(const std::uint64_t edge : changed_edges) touched[edge >> 32] = touched[std::uint32_t(edge)] = true;
    auto is_changed = [&](std::uint32_t h) {
      return touched[corners_[h]] && touched[corners_[3 * (h / 3) + (h % 3 + 1) % 3]] &&
             std::binary_search(changed_edges.begin(), changed_edges.end(), edge_of(h));
    };
    Large_vector<std::uint32_t> old_twin;
    old_twin.swap(twin_);
    twin_.assign(corners_.size(), UINT32_MAX);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> reset; // (edge, half-edge) to pair anew
    for(std::size_t k = 0; k < new_position.size(); ++k) {
      if(new_position[k] == UINT32_MAX) continue;
      for(std::uint32_t e = 0; e < 3; ++e) {
        const std::uint32_t h = 3 * new_position[k] + e;
        if(is_changed(h)) {
          reset.emplace_back(edge_of(h), h);
          continue;
        }
        const std::uint32_t t = old_twin[3 * k + e];
        CGAL_assertion(new_position[t / 3] != UINT32_MAX); // a removed facet changes its edges
        twin_[h] = 3 * new_position[t / 3] + t % 3;
      }
    }
    Large_vector<std::uint32_t>().swap(old_twin);
    const std::uint32_t first_added = 3 * std::uint32_t(std::count_if(new_position.begin(), new_position.end(),
                                                                       [](std::uint32_t p) { return p != UINT32_MAX; }));
    for(std::uint32_t h = first_added; h < corners_.size(); ++h) reset.emplace_back(edge_of(h), h);
    std::sort(reset.begin(), reset.end());

    // the non-manifold edges that did not change stay counted
    std::size_t ends = 0;
    for(std::size_t i = 0; i + 1 < non_manifold_edge_ends_.size(); i += 2) {
      const std::uint32_t u = non_manifold_edge_ends_[i], v = non_manifold_edge_ends_[i + 1];
      const std::uint64_t edge = (std::uint64_t((std::min)(u, v)) << 32) | (std::max)(u, v);
      if(std::binary_search(changed_edges.begin(), changed_edges.end(), edge)) continue;
      non_manifold_edge_ends_[ends++] = u;
      non_manifold_edge_ends_[ends++] = v;
    }
    non_manifold_edge_ends_.resize(ends);
    stats_.non_manifold_edges = ends / 2;
    std::vector<std::uint32_t> unpaired;
    for(std::size_t i = 0; i < reset.size();) {
      std::size_t j = i + 1;
      while(j < reset.size() && reset[j].first == reset[i].first) ++j;
      if(j - i == 2) {
        const std::uint32_t a = reset[i].second, b = reset[i + 1].second;
        CGAL_assertion(corners_[a] == corners_[3 * (b / 3) + (b % 3 + 1) % 3]); // opposite ways
        twin_[a] = b;
        twin_[b] = a;
      } else { // a non-manifold edge (four or more): split
        ++stats_.non_manifold_edges;
        non_manifold_edge_ends_.push_back(std::uint32_t(reset[i].first >> 32));
        non_manifold_edge_ends_.push_back(std::uint32_t(reset[i].first));
        for(std::size_t g = i; g < j; ++g) unpaired.push_back(reset[g].second / 3);
      }
      i = j;
    }
    std::sort(unpaired.begin(), unpaired.end());
    unpaired.erase(std::unique(unpaired.begin(), unpaired.end()), unpaired.end());
    pair_around_non_manifold_edges(reader, unpaired);
  }

  // The corner after `c` around its vertex: the twin of the half-edge that enters the vertex
  // in the facet of `c` starts at that vertex in the next facet.
  std::uint32_t next_corner_around_vertex(std::uint32_t c) const { return twin_[3 * (c / 3) + (c % 3 + 2) % 3]; }

  // Sets the twins of the half-edges whose edge bounds exactly two facets and counts the
  // edges of more facets; returns how many half-edges got their twin.
  std::size_t pair_twins_by_vertices(std::size_t number_of_vertices)
  {
    const std::uint32_t nh = std::uint32_t(corners_.size());
    const Large_vector<std::uint32_t>& id = corners_; // vertex number of each corner
    std::size_t paired = 0;
    for_each_edge_group(number_of_vertices, nh, [&](std::uint32_t c) { return id[c]; },
                        [&](const std::uint32_t* first, const std::uint32_t* last) {
                          if(last - first != 2) { // a non-manifold edge (four or more): split
                            ++stats_.non_manifold_edges;
                            non_manifold_edge_ends_.push_back(id[first[0]]);
                            non_manifold_edge_ends_.push_back(id[3 * (first[0] / 3) + (first[0] % 3 + 1) % 3]);
                            return;
                          }
                          const std::uint32_t a = first[0], b = first[1];
                          CGAL_assertion(id[a] == id[3 * (b / 3) + (b % 3 + 1) % 3]); // opposite ways
                          twin_[a] = b;
                          twin_[b] = a;
                          paired += 2;
                        });
    return paired;
  }

  // Half-edge 3k+e goes from outward vertex e to outward vertex e+1 of facet k. Its twin is
  // the boundary half-edge met first when turning around that edge through inside cells.
  // `table` numbers the keys of the facets at the positions `unpaired`, named from their inside
  // cells.
  std::uint32_t find_twin(const Triangulation_reader& reader, const Dense_numbers& table,
                          const std::vector<std::uint32_t>& unpaired, std::size_t k, int e) const
  {
    const std::uint32_t u = corners_[3 * k + e], v = corners_[3 * k + (e + 1) % 3];
    const Vertex* const u_vertex = reader.vertices.element(u);
    const Vertex* const v_vertex = reader.vertices.element(v);
    const auto start = reader.from_inside(k);
    const Cell* cur = start.first;
    const Vertex* behind = &*cur->vertex(start.second); // we "arrive" through the facet opposite it
    for(std::size_t guard = 0;; ++guard) {
      CGAL_assertion(guard < 100000);
      int q = -1;
      for(int i = 0; i < 4; ++i) {
        const Vertex* w = &*cur->vertex(i);
        if(w != u_vertex && w != v_vertex && w != behind) { q = i; break; }
      }
      CGAL_assertion(q >= 0);
      const Cell* next = &*cur->neighbor(q);
      if(!reader.is_inside(next)) {
        const std::uint32_t k2 = unpaired[table[facet_key(reader.cells.index(cur), q)]];
        for(std::uint32_t e2 = 0; e2 < 3; ++e2)
          if(corners_[3 * k2 + e2] == v && corners_[3 * k2 + (e2 + 1) % 3] == u) return 3 * k2 + e2;
        CGAL_error_msg("inconsistent orientation around an edge");
      }
      int back = 0; // the index of `cur` in `next`: the vertex of `next` facing away from `cur`
      while(&*next->neighbor(back) != cur) ++back;
      behind = &*next->vertex(back);
      cur = next;
    }
  }

  bool completed_ = false;
  Large_vector<std::uint32_t> keys_;          // of the facets, in memory order (until `complete()`)
  Large_vector<std::uint32_t> rank_of_;       // memory order -> canonical rank (until `complete()`)
  Large_vector<std::uint32_t> corners_;       // vertex numbers, 3 per facet (until `complete()`)
  Large_vector<Point> vertex_points_;         // by vertex number (until `complete()`)
  Large_vector<std::uint32_t> twin_;          // of each half-edge
  std::vector<std::uint32_t> non_manifold_edge_ends_; // vertex numbers, with repetitions
  Large_vector<std::uint32_t> corner_vertex_; // mesh vertex of each corner (after `complete()`)
  Large_vector<Point> points_;                // of the mesh vertices (after `complete()`)
  Closed_surface_statistics stats_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_MESH_3_H
