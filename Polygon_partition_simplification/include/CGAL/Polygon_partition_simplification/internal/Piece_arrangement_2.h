// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PIECE_ARRANGEMENT_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PIECE_ARRANGEMENT_2_H

// The exact arrangement of the pieces (segments) a partition is built from, each of its edges
// carrying the index of its supporting line, and the points and edges of the partition it
// makes: the edges that bound no cell (dangling, or with the same face on both sides) are
// dropped, the points are the vertices on at least two lines, and the edges are the chains of
// arrangement edges between two points (through the vertices on a single line, where two
// collinear edges meet).

#include <CGAL/Polygon_partition_simplification/Input_error.h>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// The data of a curve: the index of its line (overlapping pieces are on one line, so the data
// of an edge is that line, whichever pieces overlap there). `EK`: the exact constructions kernel
// of the geometric traits.
template <class EK>
using Piece_traits = CGAL::Arr_consolidated_curve_data_traits_2<CGAL::Arr_segment_traits_2<EK>, std::size_t>;
template <class EK>
using Piece_arrangement = CGAL::Arrangement_2<Piece_traits<EK>>;

// The graph of an arrangement: its vertices, and its edges with their line and whether they
// still bound a cell (`alive`).
template <class EK>
struct Piece_graph
{
  struct Edge { std::size_t u, v, line; bool alive; };
  std::vector<typename Piece_arrangement<EK>::Vertex_const_handle> vertices;
  std::vector<Edge> edges;
  std::vector<std::vector<std::size_t>> incident; // per vertex, its edges (alive or not)
};

// The graph of `arrangement`; an edge with the same face on both sides (a bridge or an antenna)
// bounds no cell and is not alive.
template <class EK>
Piece_graph<EK> piece_graph(const Piece_arrangement<EK>& arrangement)
{
  Piece_graph<EK> g;
  std::map<typename Piece_arrangement<EK>::Vertex_const_handle, std::size_t> vertex_index;
  for(auto v = arrangement.vertices_begin(); v != arrangement.vertices_end(); ++v) {
    vertex_index.emplace(v, g.vertices.size());
    g.vertices.push_back(v);
  }
  g.incident.resize(g.vertices.size());
  for(auto h = arrangement.edges_begin(); h != arrangement.edges_end(); ++h) {
    const std::size_t u = vertex_index.at(h->source()), v = vertex_index.at(h->target());
    g.incident[u].push_back(g.edges.size());
    g.incident[v].push_back(g.edges.size());
    g.edges.push_back({u, v, h->curve().data().front(), h->face() != h->twin()->face()});
  }
  return g;
}

// Kills the edges that dangle: repeatedly, the alive edge at a vertex with one alive edge.
template <class EK>
void prune_dangling_edges(Piece_graph<EK>& g)
{
  std::vector<std::size_t> degree(g.incident.size());
  std::vector<std::size_t> stack;
  for(std::size_t v = 0; v < g.incident.size(); ++v) {
    degree[v] = 0;
    for(std::size_t e : g.incident[v]) degree[v] += g.edges[e].alive ? 1 : 0;
    if(degree[v] == 1) stack.push_back(v);
  }
  while(!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    for(std::size_t e : g.incident[v]) {
      if(!g.edges[e].alive) continue;
      g.edges[e].alive = false;
      for(std::size_t w : {g.edges[e].u, g.edges[e].v})
        if(--degree[w] == 1) stack.push_back(w);
    }
  }
}

// The points and edges of a partition from the alive edges of `g`.
template <class Partition>
struct Points_and_edges
{
  std::vector<typename Partition::Vertex> vertices;
  std::vector<typename Partition::Edge> edges;
};

// Points: the vertices on at least two lines (of alive edges), numbered in the order of their
// sorted line sets, then of their exact coordinates, which does not depend on the order of the
// input. Edges: the chains of alive edges from a point to the next through vertices on a
// single line, sorted by (line, points). Throws Input_error (NO_CELL) when there is none.
template <class Partition, class EK>
Points_and_edges<Partition> points_and_chained_edges(const Piece_graph<EK>& g)
{
  const std::size_t n = g.incident.size();
  std::vector<std::vector<std::size_t>> vertex_lines(n);
  for(std::size_t v = 0; v < n; ++v) {
    for(std::size_t e : g.incident[v])
      if(g.edges[e].alive) vertex_lines[v].push_back(g.edges[e].line);
    std::sort(vertex_lines[v].begin(), vertex_lines[v].end());
    vertex_lines[v].erase(std::unique(vertex_lines[v].begin(), vertex_lines[v].end()), vertex_lines[v].end());
  }
  std::vector<std::size_t> point_vertices;
  for(std::size_t v = 0; v < n; ++v)
    if(vertex_lines[v].size() >= 2) point_vertices.push_back(v);
  std::sort(point_vertices.begin(), point_vertices.end(), [&](std::size_t x, std::size_t y) {
    if(vertex_lines[x] != vertex_lines[y]) return vertex_lines[x] < vertex_lines[y];
    return g.vertices[x]->point() < g.vertices[y]->point();
  });
  Points_and_edges<Partition> result;
  std::vector<std::size_t> point_index(n, std::size_t(-1));
  for(std::size_t v : point_vertices) {
    point_index[v] = result.vertices.size();
    result.vertices.push_back({vertex_lines[v]});
  }
  std::vector<bool> visited(g.edges.size(), false);
  for(std::size_t start : point_vertices)
    for(std::size_t e0 : g.incident[start]) {
      if(!g.edges[e0].alive || visited[e0]) continue;
      std::size_t v = start, e = e0;
      for(;;) {
        visited[e] = true;
        v = g.edges[e].u == v ? g.edges[e].v : g.edges[e].u;
        if(point_index[v] != std::size_t(-1)) break;
        std::size_t next = std::size_t(-1); // a single-line vertex has exactly one other edge
        for(std::size_t f : g.incident[v])
          if(g.edges[f].alive && f != e) next = f;
        e = next;
      }
      std::size_t s = point_index[start], t = point_index[v];
      if(s > t) std::swap(s, t);
      result.edges.push_back({g.edges[e0].line, s, t});
    }
  std::sort(result.edges.begin(), result.edges.end(), [](const auto& x, const auto& y) {
    return std::tie(x.line, x.source, x.target) < std::tie(y.line, y.source, y.target);
  });
  if(result.edges.empty())
    throw Input_error(Input_error_code::NO_CELL,
                      "the input bounds no cell: every edge dangles; give closed polygons or "
                      "segments that meet");
  return result;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PIECE_ARRANGEMENT_2_H
