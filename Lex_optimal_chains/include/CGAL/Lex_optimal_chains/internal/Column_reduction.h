// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_COLUMN_REDUCTION_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_COLUMN_REDUCTION_H

// Sparse column reduction over a field (Algorithms 2 and 4 of the thesis, the standard
// persistence reduction): columns are added left to right until their lowest non-zero rows
// are unique; V (R = D V) is kept when asked. Columns are vectors of (row, value) sorted by
// row; a table gives the column of each low row in O(1). Total reduction (Algorithms 3 and
// 5) eliminates a dense vector from its highest row down with the reduced columns.

#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class Field>
using Sparse_column = std::vector<std::pair<std::uint32_t, typename Field::Value>>;

// a -= f b
template <class Field>
void subtract_multiple(Sparse_column<Field>& a, const Sparse_column<Field>& b, const typename Field::Value& f)
{
  Sparse_column<Field> out;
  out.reserve(a.size() + b.size());
  std::size_t i = 0, j = 0;
  while(i < a.size() || j < b.size()) {
    if(j == b.size() || (i < a.size() && a[i].first < b[j].first)) {
      out.push_back(a[i++]);
    } else if(i == a.size() || b[j].first < a[i].first) {
      out.emplace_back(b[j].first, Field::subtract(Field::zero(), Field::multiply(f, b[j].second)));
      ++j;
    } else {
      const typename Field::Value v = Field::subtract(a[i].second, Field::multiply(f, b[j].second));
      if(!Field::is_zero(v)) out.emplace_back(a[i].first, v);
      ++i, ++j;
    }
  }
  a.swap(out);
}

template <class Field>
class Column_reduction
{
public:
  using Value = typename Field::Value;
  using Column = Sparse_column<Field>;
  static constexpr std::uint32_t none = std::uint32_t(-1);

  // Reduces `columns` (rows below `rows`); keeps V if `track_v`. `cleared` lists columns
  // known to reduce to zero with the given V column (the clearing of persistence
  // libraries): they are not reduced.
  Column_reduction(std::vector<Column> columns, std::size_t rows, bool track_v,
                   std::vector<std::pair<std::uint32_t, Column>> cleared = {})
    : r_(std::move(columns)), pivot_(rows, none)
  {
    std::vector<char> skip(r_.size(), 0);
    if(track_v) {
      v_.resize(r_.size());
      for(std::size_t j = 0; j < r_.size(); ++j) v_[j].emplace_back(std::uint32_t(j), Field::one());
    }
    for(auto& c : cleared) {
      skip[c.first] = 1;
      r_[c.first].clear();
      if(track_v) v_[c.first] = std::move(c.second);
    }
    for(std::size_t j = 0; j < r_.size(); ++j) {
      if(skip[j]) continue;
      while(!r_[j].empty()) {
        const std::uint32_t low = r_[j].back().first;
        const std::uint32_t j0 = pivot_[low];
        if(j0 == none) {
          pivot_[low] = std::uint32_t(j);
          break;
        }
        const Value f = Field::divide(r_[j].back().second, r_[j0].back().second);
        subtract_multiple<Field>(r_[j], r_[j0], f);
        if(track_v) subtract_multiple<Field>(v_[j], v_[j0], f);
      }
    }
  }

  std::size_t number_of_columns() const { return r_.size(); }
  const Column& reduced(std::size_t j) const { return r_[j]; }
  const Column& transformation(std::size_t j) const { return v_[j]; }
  // the column whose lowest row is `row`, or `none`
  std::uint32_t pivot(std::uint32_t row) const { return pivot_[row]; }

  // Algorithm 3: eliminates the dense vector `g` (over the rows) from its highest row down.
  // If `v_sum` is given, the multiples of V are accumulated in it (Algorithm 6).
  void totally_reduce(std::vector<Value>& g, std::vector<Value>* v_sum = nullptr) const
  {
    for(std::size_t r = g.size(); r-- > 0;) {
      if(Field::is_zero(g[r]) || pivot_[r] == none) continue;
      const Column& c = r_[pivot_[r]];
      const Value f = Field::divide(g[r], c.back().second);
      for(const auto& e : c) g[e.first] = Field::subtract(g[e.first], Field::multiply(f, e.second));
      if(v_sum != nullptr)
        for(const auto& e : v_[pivot_[r]]) (*v_sum)[e.first] = Field::add((*v_sum)[e.first], Field::multiply(f, e.second));
    }
  }

private:
  std::vector<Column> r_, v_;
  std::vector<std::uint32_t> pivot_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_COLUMN_REDUCTION_H
