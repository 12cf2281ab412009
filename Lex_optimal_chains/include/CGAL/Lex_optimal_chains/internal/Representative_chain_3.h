// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_REPRESENTATIVE_CHAIN_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_REPRESENTATIVE_CHAIN_3_H

// Algorithms 11 and 12 of the thesis: a 2-chain of the (finite) Delaunay complex bounded by
// a given 1-cycle, over Z2 or, with orientations, over the integers.
//
// The cycle A is swept downward: its highest vertex a has all its A-neighbours in the lower
// link of a, which is contractible in a Delaunay complex (Lemma 4.43); a chain E of a
// spanning tree of the lower link joins them (Algorithm 12), the edges of A at a are replaced
// by E and the triangles a * E are added to the result. The highest vertex of A decreases
// strictly, so every vertex is handled at most once.
//
// Heights: vertices are ordered by (z, x, y) lexicographically, a symbolic perturbation of
// the height (z + eps x + eps^2 y) that satisfies the generic condition of the thesis
// (Condition 4: no two vertices at the same height) for any set of distinct points, and does
// not depend on the input order. Lemma 4.43 holds for the perturbed height as for any
// direction: the lower link is the nerve of the lower envelope of the Voronoi cell.

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class Vertex_handle, class Value>
struct Oriented_edge
{
  Vertex_handle source, target;
  Value coefficient; // of the edge oriented from source to target
};

template <class Vertex_handle, class Value>
struct Oriented_triangle
{
  std::array<Vertex_handle, 3> vertices; // the orientation of the coefficient
  Value coefficient;
};

// true if u is higher than v along (z, x, y)
template <class Vertex_handle>
bool is_higher(Vertex_handle u, Vertex_handle v)
{
  const auto& p = u->point();
  const auto& q = v->point();
  if(p.z() != q.z()) return p.z() > q.z();
  if(p.x() != q.x()) return p.x() > q.x();
  return p.y() > q.y();
}

template <class Triangulation, class Arithmetic>
class Representative_chain_3
{
public:
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Cell_handle = typename Triangulation::Cell_handle;
  using Value = typename Arithmetic::Value;
  using Edge = Oriented_edge<Vertex_handle, Value>;
  using Triangle = Oriented_triangle<Vertex_handle, Value>;

  // Computes a chain bounded by `cycle` (edges of `dt`, finite vertices). Throws Input_error
  // (INVALID_BOUNDARY) if an edge is not an edge of the triangulation or if `cycle` is not a
  // cycle.
  Representative_chain_3(const Triangulation& dt, const std::vector<Edge>& cycle) : dt_(dt)
  {
    for(const Edge& e : cycle) {
      check_edge(e.source, e.target);
      add_to_cycle(e.source, e.target, e.coefficient);
    }
    while(!cycle_.empty()) sweep_highest_vertex();
  }

  const std::vector<Triangle>& chain() const { return chain_; }
  std::size_t number_of_swept_vertices() const { return swept_; }

private:
  // An edge (high, low) of A, high above low, carrying the coefficient of high -> low.
  struct Descending
  {
    bool operator()(const std::pair<Vertex_handle, Vertex_handle>& a,
                    const std::pair<Vertex_handle, Vertex_handle>& b) const
    {
      if(a.first != b.first) return is_higher(a.first, b.first);
      if(a.second != b.second) return is_higher(a.second, b.second);
      return false;
    }
  };

  void check_edge(Vertex_handle u, Vertex_handle v) const
  {
    Cell_handle c;
    int i, j;
    if(u == Vertex_handle() || v == Vertex_handle() || dt_.is_infinite(u) || dt_.is_infinite(v) || u == v ||
       !dt_.is_edge(u, v, c, i, j)) {
      std::ostringstream msg;
      msg << "boundary edge ";
      if(u != Vertex_handle() && v != Vertex_handle() && !dt_.is_infinite(u) && !dt_.is_infinite(v))
        msg << "(" << u->point() << ") - (" << v->point() << ") ";
      msg << "is not an edge of the Delaunay triangulation";
      throw Input_error(Input_error_code::BOUNDARY_EDGE_NOT_IN_TRIANGULATION, msg.str());
    }
  }

  // A += k (u -> v)
  void add_to_cycle(Vertex_handle u, Vertex_handle v, Value k)
  {
    if(k == Arithmetic::zero()) return;
    const bool up = is_higher(u, v);
    const auto key = up ? std::make_pair(u, v) : std::make_pair(v, u);
    const Value signed_k = up ? k : Arithmetic::negate(k);
    auto it = cycle_.find(key);
    if(it == cycle_.end()) {
      cycle_.emplace(key, signed_k);
    } else {
      it->second = Arithmetic::add(it->second, signed_k);
      if(it->second == Arithmetic::zero()) cycle_.erase(it);
    }
  }

  void sweep_highest_vertex()
  {
    ++swept_;
    const Vertex_handle a = cycle_.begin()->first.first;
    // lower link of a: its vertices (local indices) and edges
    std::vector<Vertex_handle> vertices;
    std::vector<std::pair<int, int>> edges;
    auto local = [&](Vertex_handle v) {
      auto it = std::find(vertices.begin(), vertices.end(), v);
      if(it != vertices.end()) return int(it - vertices.begin());
      vertices.push_back(v);
      return int(vertices.size()) - 1;
    };
    std::vector<Cell_handle> cells;
    dt_.finite_incident_cells(a, std::back_inserter(cells));
    for(const Cell_handle& c : cells) {
      std::array<Vertex_handle, 3> lower;
      int k = 0;
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != a && is_higher(a, c->vertex(i))) lower[k++] = c->vertex(i);
      for(int i = 0; i < k; ++i) local(lower[i]);
      for(int i = 0; i < k; ++i)
        for(int j = i + 1; j < k; ++j) {
          int x = local(lower[i]), y = local(lower[j]);
          if(x > y) std::swap(x, y);
          edges.emplace_back(x, y);
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    const int m = int(vertices.size());

    // the demand: the edges of A at a are a -> v with coefficient c; E must have boundary
    // sum(-c v) (see the sign derivation in the manual's section on Algorithm 11)
    std::vector<Value> demand(m, Arithmetic::zero());
    while(!cycle_.empty() && cycle_.begin()->first.first == a) {
      const auto it = cycle_.begin();
      const int v = local(it->first.second);
      if(v >= m) not_a_cycle(a); // an A-neighbour outside the lower link cannot happen for a valid edge
      demand[v] = Arithmetic::add(demand[v], Arithmetic::negate(it->second));
      cycle_.erase(it);
    }

    // Algorithm 12: breadth-first spanning tree of the lower link (rank = visiting order),
    // then the demand is pushed from the highest rank to the root
    std::vector<std::vector<int>> adjacent(m);
    for(const auto& e : edges) {
      adjacent[e.first].push_back(e.second);
      adjacent[e.second].push_back(e.first);
    }
    std::vector<int> parent(m, -1), order;
    order.reserve(m);
    std::vector<char> seen(m, 0);
    for(int root = 0; root < m; ++root) { // the lower link is connected; other components would show a bug
      if(seen[root]) continue;
      seen[root] = 1;
      order.push_back(root);
      for(std::size_t q = order.size() - 1; q < order.size(); ++q)
        for(int w : adjacent[order[q]])
          if(!seen[w]) { seen[w] = 1; parent[w] = order[q]; order.push_back(w); }
    }
    for(int rank = m - 1; rank >= 0; --rank) {
      const int v = order[rank];
      const Value c = demand[v];
      if(c == Arithmetic::zero()) continue;
      const int p = parent[v];
      if(p < 0) not_a_cycle(a); // the demand of a component does not sum to zero
      demand[p] = Arithmetic::add(demand[p], c);
      demand[v] = Arithmetic::zero();
      // E += c (p -> v): triangle c (a, p, v), and A -= c (p -> v)
      chain_.push_back(Triangle{{{a, vertices[p], vertices[v]}}, c});
      add_to_cycle(vertices[p], vertices[v], Arithmetic::negate(c));
    }
  }

  [[noreturn]] void not_a_cycle(Vertex_handle a) const
  {
    std::ostringstream msg;
    msg << "the boundary is not a cycle: its edges at vertex (" << a->point() << ") do not close up";
    throw Input_error(Input_error_code::BOUNDARY_NOT_A_CYCLE, msg.str());
  }

  const Triangulation& dt_;
  std::map<std::pair<Vertex_handle, Vertex_handle>, Value, Descending> cycle_;
  std::vector<Triangle> chain_;
  std::size_t swept_ = 0;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_REPRESENTATIVE_CHAIN_3_H
