// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_LEXICOGRAPHIC_MIN_CUT_H
#define CGAL_LEX_OPTIMAL_CHAINS_LEXICOGRAPHIC_MIN_CUT_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Union_find.h>

#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef

Algorithm 8 of the thesis (lexicographic minimum cut), as an incremental state machine.

The vertices of the graph are the integers `[0, n)`. The sources are merged into one
vertex \f$\alpha_1\f$ and the sinks into one vertex \f$\alpha_2\f$. The edges must then be
given to `process()` in *decreasing* order of the total order on edges: an edge is cut when
it joins the component of \f$\alpha_1\f$ to that of \f$\alpha_2\f$; otherwise its end
points are united. After all edges, the cut is the set of edges between the final component
of \f$\alpha_1\f$ and the rest, and it is the lexicographic minimal set of edges whose
removal disconnects the sources from the sinks.

Cost: \f$O(m\,\alpha(n))\f$ for \f$m\f$ edges (union by rank and path halving).
*/
class Lexicographic_min_cut
{
public:
  /// index of a vertex of the graph
  using Vertex_index = std::uint32_t;

  /// Sets up `n` vertices with the given sources and sinks (ranges of vertex indices).
  /// \throws Input_error (`INVALID_GRAPH`) if a range is empty, an index is out of range,
  ///         or a vertex is both a source and a sink.
  template <class SourceRange, class SinkRange>
  Lexicographic_min_cut(std::size_t n, const SourceRange& sources, const SinkRange& sinks)
    : sets_(n)
  {
    if(n > std::size_t(UINT32_MAX))
      throw Input_error(Input_error_code::INVALID_GRAPH, "graph has more than 2^32-1 vertices");
    source_root_ = merge_all(sources, "source");
    sink_root_ = merge_all(sinks, "sink");
    source_root_ = sets_.find(source_root_); // merging the sinks may have moved it
    if(source_root_ == sink_root_)
      throw Input_error(Input_error_code::INVALID_GRAPH,
                        "a vertex is both a source and a sink: the cut is not defined");
  }

  /// Processes the edge `(u,v)`, the next one in decreasing order; returns `true` if it is cut.
  bool process(Vertex_index u, Vertex_index v)
  {
    const Vertex_index ru = sets_.find(u), rv = sets_.find(v);
    if(ru == rv) return false;
    if((ru == source_root_ && rv == sink_root_) || (ru == sink_root_ && rv == source_root_))
      return true;
    const Vertex_index r = sets_.link_roots(ru, rv);
    if(ru == source_root_ || rv == source_root_) source_root_ = r;
    else if(ru == sink_root_ || rv == sink_root_) sink_root_ = r;
    return false;
  }

  /// Hints that the edge `(u,v)` will be processed soon: its end points are looked up in memory
  /// ahead of time (a performance hint only).
  void prefetch(Vertex_index u, Vertex_index v) const
  {
    sets_.prefetch(u);
    sets_.prefetch(v);
  }

  /// `true` if `v` is (now) connected to the sources.
  bool is_on_source_side(Vertex_index v) { return sets_.find(v) == source_root_; }

  /// representative of the component of the sources
  Vertex_index sources_root() const { return source_root_; }
  /// representative of the component of the sinks
  Vertex_index sinks_root() const { return sink_root_; }

  /// Representative of the set that holds `v`.
  Vertex_index find(Vertex_index v) { return sets_.find(v); }

  /// Number of vertices.
  std::size_t number_of_vertices() const { return sets_.size(); }

private:
  template <class Range>
  Vertex_index merge_all(const Range& range, const char* what)
  {
    bool any = false;
    Vertex_index root = 0;
    for(const auto& v : range) {
      if(std::size_t(v) >= sets_.size())
        throw Input_error(Input_error_code::INVALID_GRAPH,
                          std::string(what) + " index " + std::to_string(std::size_t(v)) +
                          " is not a vertex of the graph");
      if(!any) { root = sets_.find(Vertex_index(v)); any = true; }
      else root = sets_.unite(root, Vertex_index(v));
    }
    if(!any)
      throw Input_error(Input_error_code::INVALID_GRAPH, std::string("no ") + what + " given");
    return root;
  }

  internal::Union_find sets_;
  Vertex_index source_root_ = 0;
  Vertex_index sink_root_ = 0;
};

/*!
\ingroup PkgLexOptimalChainsRef

Lexicographic minimum cut (Algorithm 8) of a graph whose edges are given in *decreasing*
order: writes to `cut` the positions (0-based, in the given range) of the edges of the cut,
in decreasing order. `edges` is a range of pairs (anything with `first` and `second`)
of vertex indices in `[0, number_of_vertices)`.

\throws Input_error (`INVALID_GRAPH`) on an index out of range or overlapping terminals.
*/
template <class EdgeRange, class SourceRange, class SinkRange, class OutputIterator>
OutputIterator lexicographic_min_cut(std::size_t number_of_vertices,
                                     const EdgeRange& edges_in_decreasing_order,
                                     const SourceRange& sources,
                                     const SinkRange& sinks,
                                     OutputIterator cut)
{
  Lexicographic_min_cut state(number_of_vertices, sources, sinks);
  std::size_t position = 0;
  for(const auto& e : edges_in_decreasing_order) {
    if(std::size_t(e.first) >= number_of_vertices || std::size_t(e.second) >= number_of_vertices)
      throw Input_error(Input_error_code::INVALID_GRAPH,
                        "edge " + std::to_string(position) + " has an end point out of range");
    if(state.process(Lexicographic_min_cut::Vertex_index(e.first),
                     Lexicographic_min_cut::Vertex_index(e.second)))
      *cut++ = position;
    ++position;
  }
  return cut;
}

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_LEXICOGRAPHIC_MIN_CUT_H
