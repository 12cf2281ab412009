// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_SORTED_DUAL_GRAPH_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_SORTED_DUAL_GRAPH_3_H

// The dual graph of a 3D Delaunay triangulation completed to S^3 (its infinite cells all
// stand for the infinite vertex), with its edges (the finite facets) sorted along the
// triangle order of Lemma 4.14.
//
// Vertices of the dual graph: every cell of the triangulation data structure, numbered by
// its position in the cell container; infinite cells are merged by the users of this
// graph. Edges: one record per finite facet, owned by a finite cell.
//
// Sorting: a key pass computes R_B^2 in double with a certified relative error bound
// (internal/Triangle_order_3.h) and stores its bit pattern (monotone for positive doubles).
// An in-place MSD radix sort orders the records by the key with its 20 lowest bits dropped.
// A sweep then finds the runs of records whose keys are too close for the bound to order
// them (and all exact ties: obtuse triangles sharing their longest edge) and sorts each
// such run with the exact comparator. Records whose key could not be certified are
// placed at a lower bound of their R_B^2 and widen the run up to their upper bound.

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

struct Dual_edge_record
{
  std::uint64_t key;   // bit pattern of (a bound on) R_B^2; bit 0 set: uncertain
  std::uint32_t owner; // (position of the finite owner cell << 2) | facet index
  std::uint32_t other; // position of the cell on the other side
};

inline std::uint64_t double_bits(double d)
{
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

inline void radix_sort_records(Dual_edge_record* begin, Dual_edge_record* end, int shift, int lowest_shift)
{
  const std::size_t n = std::size_t(end - begin);
  if(n < 48 || shift < lowest_shift) {
    // insertion sort on the full key
    for(Dual_edge_record* i = begin + (n ? 1 : 0); i < end; ++i) {
      Dual_edge_record x = *i;
      Dual_edge_record* j = i;
      for(; j > begin && (j - 1)->key > x.key; --j) *j = *(j - 1);
      *j = x;
    }
    return;
  }
  std::size_t count[256] = {0};
  for(Dual_edge_record* p = begin; p < end; ++p) ++count[(p->key >> shift) & 0xff];
  if(std::find(std::begin(count), std::end(count), n) != std::end(count)) {
    radix_sort_records(begin, end, shift - 8, lowest_shift); // one bucket: next digit
    return;
  }
  std::size_t head[256], tail[256];
  std::size_t sum = 0;
  for(int d = 0; d < 256; ++d) { head[d] = sum; sum += count[d]; tail[d] = sum; }
  // American flag sort: in-place cycle permutation
  for(int d = 0; d < 256; ++d) {
    while(head[d] < tail[d]) {
      Dual_edge_record x = begin[head[d]];
      int dx = int((x.key >> shift) & 0xff);
      while(dx != d) {
        std::swap(x, begin[head[dx]++]);
        dx = int((x.key >> shift) & 0xff);
      }
      begin[head[d]++] = x;
    }
  }
  std::size_t start = 0;
  for(int d = 0; d < 256; ++d) {
    if(count[d] > 1) radix_sort_records(begin + start, begin + start + count[d], shift - 8, lowest_shift);
    start += count[d];
  }
}

template <class Triangulation>
class Sorted_dual_graph_3
{
public:
  using Cell = typename Triangulation::Cell;
  using Cell_handle = typename Triangulation::Cell_handle;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Record = Dual_edge_record;

  // bits of the key below the resolution at which the fast bound orders two keys
  static constexpr int dropped_bits = 20;
  // relative error bound that the fast key must meet (2^-36, well below 2^-33)
  static constexpr double max_relative_error = 1.0 / (1ull << 36);

  // `progress(fraction)` returns false to cancel.
  template <class Progress>
  Sorted_dual_graph_3(const Triangulation& dt, const Progress& progress)
    : dt_(dt), cells_(dt.tds().cells().begin(), dt.tds().cells().end())
  {
    if(cells_.size() >= (std::size_t(1) << 30))
      throw Input_error(Input_error_code::TOO_FEW_POINTS, "triangulation too large (2^30 cells or more)");
    build_records(progress);
    sort_records(progress);
  }

  const Triangulation& triangulation() const { return dt_; }
  std::size_t number_of_cells() const { return cells_.size(); }
  // records sorted increasingly along the triangle order
  const std::vector<Record>& records() const { return records_; }

  std::uint32_t position(Cell_handle c) const { return cells_.index(&*c); }
  Cell_handle cell(std::uint32_t position) const
  {
    auto& tds = const_cast<typename Triangulation::Triangulation_data_structure&>(dt_.tds());
    return tds.cells().iterator_to(*const_cast<Cell*>(cells_.element(position)));
  }

  static std::uint32_t owner_position(const Record& r) { return r.owner >> 2; }
  static int facet_index(const Record& r) { return int(r.owner & 3); }

  Triangle_coordinates_3 coordinates(const Record& r) const
  {
    return facet_coordinates(cell(owner_position(r)), facet_index(r));
  }

  static Triangle_coordinates_3 facet_coordinates(Cell_handle c, int j)
  {
    Triangle_coordinates_3 t;
    for(int k = 0; k < 3; ++k) {
      const auto& p = c->vertex((j + 1 + k) & 3)->point();
      t[k] = Coordinates_3{{p.x(), p.y(), p.z()}};
    }
    return t;
  }

  // number of records sorted with the exact comparator (statistics)
  std::size_t number_of_repaired_records() const { return repaired_; }

private:
  template <class Progress>
  void build_records(const Progress& progress)
  {
    std::vector<Cell_handle> hull;
    dt_.incident_cells(dt_.infinite_vertex(), std::back_inserter(hull));
    const std::size_t facets = 2 * cells_.size() - (3 * hull.size()) / 2;
    records_.reserve(facets);

    const Vertex_handle infinite = dt_.infinite_vertex();
    std::uint32_t pos = 0;
    const auto& container = dt_.tds().cells();
    for(auto it = container.begin(); it != container.end(); ++it, ++pos) {
      if((pos & 0xfffff) == 0 && !progress(0.5 * double(pos) / double(cells_.size())))
        throw Input_error(Input_error_code::CANCELLED, "cancelled by the callback");
      const Cell& c = *it;
      if(c.vertex(0) == infinite || c.vertex(1) == infinite || c.vertex(2) == infinite ||
         c.vertex(3) == infinite)
        continue;
      for(int j = 0; j < 4; ++j) {
        const Cell_handle n = c.neighbor(j);
        const bool n_infinite = n->has_vertex(infinite);
        if(!n_infinite && !(std::less<const Cell*>()(&c, &*n))) continue;
        const std::uint32_t other = cells_.index(&*n);
        Triangle_coordinates_3 t;
        for(int k = 0; k < 3; ++k) {
          const auto& p = c.vertex((j + 1 + k) & 3)->point();
          t[k] = Coordinates_3{{p.x(), p.y(), p.z()}};
        }
        double rb2, err;
        Record r;
        r.owner = (pos << 2) | std::uint32_t(j);
        r.other = other;
        if(approximate_squared_rb(t, max_relative_error, rb2, err)) {
          r.key = double_bits(rb2) & ~std::uint64_t(1);
        } else {
          const std::pair<double, double> range = enclosure_of_squared_rb(t);
          r.key = double_bits(range.first) | 1;
          uncertain_upper_.emplace(r.owner, double_bits(range.second) >> dropped_bits);
        }
        records_.push_back(r);
      }
    }
    CGAL_assertion(records_.size() == facets);
  }

  // An interval that certainly contains R_B^2, for triangles the fast path could not bound.
  static std::pair<double, double> enclosure_of_squared_rb(const Triangle_coordinates_3& t)
  {
    using I = Interval_nt<false>;
    Protect_FPU_rounding<true> protection;
    I l[3];
    I n[3];
    I e[3][3];
    for(int i = 0; i < 3; ++i)
      for(int k = 0; k < 3; ++k)
        e[i][k] = I(t[(i + 2) % 3][k]) - I(t[(i + 1) % 3][k]);
    for(int i = 0; i < 3; ++i) l[i] = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
    n[0] = e[2][1] * e[1][2] - e[2][2] * e[1][1];
    n[1] = e[2][2] * e[1][0] - e[2][0] * e[1][2];
    n[2] = e[2][0] * e[1][1] - e[2][1] * e[1][0];
    const I d = I(4) * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const I num = l[0] * l[1] * l[2];
    const double lmax_inf = (std::max)(l[0].inf(), (std::max)(l[1].inf(), l[2].inf()));
    const double lmax_sup = (std::max)(l[0].sup(), (std::max)(l[1].sup(), l[2].sup()));
    double rc_sup = std::numeric_limits<double>::infinity();
    if(d.inf() > 0) rc_sup = (num / d).sup();
    // R_B^2 is (longest edge)^2 / 4 for an obtuse triangle and R_C^2 otherwise; it is
    // never below (longest edge)^2 / 4.
    double hi = (std::max)(lmax_sup * 0.25, rc_sup);
    if(!(hi <= std::numeric_limits<double>::max())) hi = std::numeric_limits<double>::max();
    return std::make_pair(lmax_inf * 0.25, hi);
  }

  std::uint64_t upper_code(const Record& r) const
  {
    if((r.key & 1) == 0) return r.key >> dropped_bits;
    return uncertain_upper_.at(r.owner);
  }

  template <class Progress>
  void sort_records(const Progress& progress)
  {
    if(!progress(0.5))
      throw Input_error(Input_error_code::CANCELLED, "cancelled by the callback");
    if(records_.empty()) return;
    std::uint64_t lo = records_.front().key, hi = lo;
    for(const Record& r : records_) { lo = (std::min)(lo, r.key); hi = (std::max)(hi, r.key); }
    int top = 63;
    while(top > 0 && ((lo ^ hi) >> top) == 0) --top; // highest differing bit
    int shift = (std::max)(top - 7, 0);
    radix_sort_records(records_.data(), records_.data() + records_.size(), shift, dropped_bits);
    if(!progress(0.8))
      throw Input_error(Input_error_code::CANCELLED, "cancelled by the callback");

    // runs that the keys cannot order: sort them exactly
    std::vector<std::pair<Triangle_order_key_3, Record>> run;
    const std::size_t n = records_.size();
    std::size_t i = 0;
    while(i < n) {
      std::uint64_t reach = upper_code(records_[i]);
      std::size_t j = i + 1;
      while(j < n && (records_[j].key >> dropped_bits) <= reach + 1) {
        reach = (std::max)(reach, upper_code(records_[j]));
        ++j;
      }
      if(j - i > 1) {
        run.clear();
        for(std::size_t k = i; k < j; ++k)
          run.emplace_back(Triangle_order_key_3(coordinates(records_[k])), records_[k]);
        std::sort(run.begin(), run.end(),
                  [](const auto& a, const auto& b) { return compare(a.first, b.first) == SMALLER; });
        for(std::size_t k = i; k < j; ++k) records_[k] = run[k - i].second;
        repaired_ += j - i;
      }
      i = j;
    }
  }

  const Triangulation& dt_;
  Handle_index_map<Cell> cells_;
  std::vector<Record> records_;
  std::unordered_map<std::uint32_t, std::uint64_t> uncertain_upper_;
  std::size_t repaired_ = 0;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_SORTED_DUAL_GRAPH_3_H
