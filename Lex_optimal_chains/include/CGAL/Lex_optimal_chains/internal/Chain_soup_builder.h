// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_SOUP_BUILDER_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_SOUP_BUILDER_H

#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Radix_sort.h>
#include <CGAL/Lex_optimal_chains/internal/Umbrellas.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <set>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The soup of a chain, its vertices sorted by coordinates and its triangles sorted, so that
// the output does not depend on the input order or on memory addresses. The facets of the
// chain are given one by one (`add()`, as an output iterator receives them), so that the
// chain itself is never stored: this runs at the peak of memory.
template <class Triangulation>
class Chain_soup_builder
{
public:
  using Vertex = typename Triangulation::Vertex;
  using Facet = typename Triangulation::Facet;
  using Point = typename Triangulation::Point;

  // `expected_size`, if not null, is read at the first `add()`: the number of facets to come.
  Chain_soup_builder(const typename Triangulation::Triangulation_data_structure& tds, bool oriented,
                     const std::set<typename Triangulation::Vertex_handle>& drop, const std::size_t* expected_size)
    : dense_(tds.vertices().begin(), tds.vertices().end()), oriented_(oriented), expected_size_(expected_size)
  {
    for(const auto& h : drop) dropped_vertices_.push_back(dense_.index(&*h));
    std::sort(dropped_vertices_.begin(), dropped_vertices_.end());
  }

  // the facet (c, i) with coefficient k > 0: the triangle outward of c
  void add(const Facet& f, std::int64_t)
  {
    if(!reserved_ && expected_size_ != nullptr) triangles_.reserve(*expected_size_);
    reserved_ = true;
    const auto& c = f.first;
    const int i = f.second;
    std::array<std::uint32_t, 3> t{{dense_.index(&*c->vertex((i + 1) & 3)), dense_.index(&*c->vertex((i + 2) & 3)),
                                    dense_.index(&*c->vertex((i + 3) & 3))}};
    if(i & 1) std::swap(t[1], t[2]);
    if(!dropped_vertices_.empty() && (is_dropped(t[0]) || is_dropped(t[1]) || is_dropped(t[2]))) {
      ++dropped_;
      return;
    }
    triangles_.push_back(t); // by dense vertex numbers, renumbered by `finish()`
  }

  // The vertices at which the triangles added so far are not manifold (Umbrellas.h), in
  // increasing dense number.
  std::vector<typename Triangulation::Vertex_handle> non_manifold_vertices(const typename Triangulation::Triangulation_data_structure& tds) const
  {
    const std::vector<std::uint32_t> numbers = vertices_with_several_umbrellas(
      dense_.size(), std::uint32_t(triangles_.size()), [this](std::uint32_t c) { return triangles_[c / 3][c % 3]; });
    std::vector<typename Triangulation::Vertex_handle> result;
    for(const std::uint32_t v : numbers) result.push_back(tds.vertices().iterator_to(*const_cast<Vertex*>(dense_.element(v))));
    return result;
  }

  // Removes the triangle of the facet f added before (its orientation does not matter); the
  // removals take effect at `apply_removals()`.
  void remove(const Facet& f)
  {
    std::array<std::uint32_t, 3> t;
    for(int k = 1; k < 4; ++k) t[k - 1] = dense_.index(&*f.first->vertex((f.second + k) & 3));
    if(!dropped_vertices_.empty() && (is_dropped(t[0]) || is_dropped(t[1]) || is_dropped(t[2]))) {
      --dropped_;
      return;
    }
    std::sort(t.begin(), t.end());
    removals_.push_back(t);
  }

  void apply_removals()
  {
    if(removals_.empty()) return;
    std::sort(removals_.begin(), removals_.end());
    std::vector<bool> on_removed(dense_.size(), false); // a filter before the search
    for(const auto& t : removals_) on_removed[t[0]] = on_removed[t[1]] = on_removed[t[2]] = true;
    std::size_t kept = 0;
    for(const auto& t : triangles_) {
      if(on_removed[t[0]] && on_removed[t[1]] && on_removed[t[2]]) {
        std::array<std::uint32_t, 3> s = t;
        std::sort(s.begin(), s.end());
        if(std::binary_search(removals_.begin(), removals_.end(), s)) continue;
      }
      triangles_[kept++] = t;
    }
    CGAL_assertion(triangles_.size() - kept == removals_.size());
    triangles_.resize(kept);
    removals_.clear();
  }

  // Copies the points of the vertices that the triangles use, after the last `add()`: the
  // triangulation can then be freed before `finish()`, whose sorts and copies of the soup
  // would otherwise add to it at the peak of memory.
  void take_points()
  {
    constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();
    number_.assign(dense_.size(), unused);
    std::size_t count = 0; // counted first: a growing vector would hold two copies at once
    for(const auto& t : triangles_)
      for(const std::uint32_t v : t)
        if(number_[v] == unused) { number_[v] = 0; ++count; }
    used_.reserve(count);
    for(const auto& t : triangles_)
      for(const std::uint32_t v : t)
        if(number_[v] == 0) { // its first use
          number_[v] = 1;
          used_.push_back({dense_.element(v)->point(), v});
        }
  }

  // The points of the used vertices (sorted) and the triangles on them (sorted); the number
  // of triangles dropped because they touch a dropped vertex. After `take_points()`; does not
  // read the triangulation.
  void finish(std::vector<Point>& points, std::vector<std::array<std::uint32_t, 3>>& triangles, std::size_t& dropped)
  {
    // the used vertices, numbered in the order of their points (copied next to their vertex
    // numbers, so that the sort reads contiguous memory)
    std::sort(used_.begin(), used_.end(), [](const Used_vertex& a, const Used_vertex& b) { return a.point < b.point; });
    points.clear();
    points.reserve(used_.size());
    for(std::uint32_t k = 0; k < used_.size(); ++k) {
      number_[used_[k].vertex] = k;
      points.push_back(used_[k].point);
    }
    std::vector<Used_vertex>().swap(used_);
    for(auto& t : triangles_) {
      for(std::uint32_t& v : t) v = number_[v];
      if(oriented_) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end()); // keeps the orientation
      else std::sort(t.begin(), t.end());
    }
    std::vector<std::uint32_t>().swap(number_);
    // sorted lexicographically: distributed by first vertex (a counting sort), then each
    // vertex's few triangles sorted by the other two
    triangles.assign(triangles_.size(), std::array<std::uint32_t, 3>{});
    const Large_vector<std::uint32_t> first = counting_sort_by_key(
      points.size(), std::uint32_t(triangles_.size()), [this](std::uint32_t i) { return triangles_[i][0]; },
      [&](std::uint32_t i, std::uint32_t at) { triangles[at] = triangles_[i]; });
    std::vector<std::array<std::uint32_t, 3>>().swap(triangles_);
    for(std::size_t v = 0; v < points.size(); ++v)
      if(first[v + 1] - first[v] > 1) std::sort(triangles.begin() + first[v], triangles.begin() + first[v + 1]);
    dropped = dropped_;
  }

private:
  bool is_dropped(std::uint32_t v) const { return std::binary_search(dropped_vertices_.begin(), dropped_vertices_.end(), v); }

  Handle_index_map<Vertex> dense_;
  bool oriented_;
  const std::size_t* expected_size_;
  bool reserved_ = false;
  std::vector<std::uint32_t> dropped_vertices_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<std::array<std::uint32_t, 3>> removals_; // sorted vertex numbers
  std::size_t dropped_ = 0;
  struct Used_vertex
  {
    Point point;
    std::uint32_t vertex; // dense number
  };
  std::vector<Used_vertex> used_;     // by `take_points()`
  std::vector<std::uint32_t> number_; // dense number -> number of the used vertex
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_SOUP_BUILDER_H
