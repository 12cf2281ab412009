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
//
// A filter can restrict the records to some facets (for the closed surfaces, those between
// the components left by the contraction of internal/Largest_facets_3.h): the keys of the
// other facets are then not even computed.

#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Large_array_allocator.h>
#include <CGAL/Lex_optimal_chains/internal/Parallel_blocks.h>
#include <CGAL/Lex_optimal_chains/internal/Prefetch.h>
#include <CGAL/Lex_optimal_chains/internal/Radix_sort.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

struct Dual_edge_record
{
  // bits 63-20: the high bits of (a lower bound on) R_B^2 as a double;
  // bits 19-1: q = R_B^2 / R_C^2 in [0,1] as a fixed-point number (ascending q is
  //            descending R_C, the order among equal R_B);
  // bit 0: set if R_B^2 could not be bounded tightly (the key is then a lower bound)
  std::uint64_t key;
  std::uint32_t owner; // (position of the finite owner cell << 2) | facet index
  // (longest edge << 30) | position of the cell on the other side; longest edge is the index
  // (0-2, in the facet's vertex order) of the vertex opposite the longest edge of a certainly
  // obtuse triangle whose q is certified, 3 otherwise
  std::uint32_t other;
};

// The records of a graph, one per facet kept (tens of millions).
using Dual_edge_records = Large_vector<Dual_edge_record>;

inline std::uint64_t double_bits(double d)
{
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

// In-place MSD radix sort (American flag sort) on the bits [lowest_shift, shift + width) of
// the keys, then insertion sort on the full key in small buckets. With `parallel`, the
// buckets of the first digit are sorted on its threads (they are independent: the result is
// the same).
inline void radix_sort_records(Dual_edge_record* begin, Dual_edge_record* end, int shift, int lowest_shift,
                               int width = 8, Parallel_blocks* parallel = nullptr)
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
  if(shift < lowest_shift) shift = lowest_shift;
  const std::size_t buckets = std::size_t(1) << width;
  const std::uint64_t mask = buckets - 1;
  std::size_t small[3][256];
  std::vector<std::size_t> large;
  std::size_t *count = small[0], *head = small[1], *tail = small[2];
  if(buckets > 256) {
    large.resize(3 * buckets);
    count = large.data(); head = count + buckets; tail = head + buckets;
  }
  std::fill(count, count + buckets, std::size_t(0));
  for(Dual_edge_record* p = begin; p < end; ++p) ++count[(p->key >> shift) & mask];
  if(std::find(count, count + buckets, n) != count + buckets) {
    radix_sort_records(begin, end, shift - 8, lowest_shift, 8, parallel); // one bucket: next digit
    return;
  }
  std::size_t sum = 0;
  for(std::size_t d = 0; d < buckets; ++d) { head[d] = sum; sum += count[d]; tail[d] = sum; }
  for(std::size_t d = 0; d < buckets; ++d) { // in-place cycle permutation
    while(head[d] < tail[d]) {
      Dual_edge_record x = begin[head[d]];
      std::size_t dx = (x.key >> shift) & mask;
      while(dx != d) {
        std::swap(x, begin[head[dx]++]);
        dx = (x.key >> shift) & mask;
      }
      begin[head[d]++] = x;
    }
  }
  if(shift == lowest_shift) return;
  if(parallel != nullptr && parallel->is_parallel(n)) {
    // head[d] is now the end of bucket d
    parallel->run(0, buckets, 1, n, [&](std::size_t d, std::size_t, std::size_t) {
      if(count[d] > 1) radix_sort_records(begin + (head[d] - count[d]), begin + head[d], shift - 8, lowest_shift);
    });
    return;
  }
  std::size_t start = 0;
  for(std::size_t d = 0; d < buckets; ++d) {
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
  // bits of the fixed-point q in the key, and the error bound on R_C^2 for q to be used:
  // q then has an absolute error below 2^-28, far below the step 2^-19 of its code
  static constexpr int q_bits = 19;
  static constexpr double max_q_error = 1.0 / (1ull << 30);

  // All the finite facets. `progress(fraction)` returns false to cancel.
  template <class Progress>
  Sorted_dual_graph_3(const Triangulation& dt, const Progress& progress)
    : Sorted_dual_graph_3(dt, Handle_index_map<Cell>(dt.tds().cells().begin(), dt.tds().cells().end()), progress,
                          [](std::uint32_t, int, std::uint32_t) { return true; })
  {}

  // The finite facets for which `keep(owner, j, other)` is true: the facet j of the cell at
  // position `owner` (in the numbering `cells` of the cell container, in iteration order),
  // whose record it is, shared with the cell at position `other`.
  // With `threads` > 1 (and TBB), the keys are computed and the records sorted on that many
  // threads; `keep` must then be safe to call concurrently. The records are the same, in the
  // same order, for any number of threads.
  template <class Progress, class Keep>
  Sorted_dual_graph_3(const Triangulation& dt, const Handle_index_map<Cell>& cells, const Progress& progress,
                      Keep&& keep, unsigned threads = 1)
    : dt_(dt), cells_(cells)
  {
    check_number_of_cells(cells_.size());
    auto t0 = std::chrono::steady_clock::now();
    build_records(progress, keep, threads);
    auto t1 = std::chrono::steady_clock::now();
    sort_records(progress, threads);
    auto t2 = std::chrono::steady_clock::now();
    key_seconds_ = std::chrono::duration<double>(t1 - t0).count();
    sort_seconds_ = std::chrono::duration<double>(t2 - t1).count() - repair_seconds_;
  }

  // Throws TOO_LARGE if the record codes (position << 2 | index) cannot number `n` cells.
  static void check_number_of_cells(std::size_t n)
  {
    if(n >= (std::size_t(1) << 30))
      throw Input_error(Input_error_code::TOO_LARGE,
                        "the triangulation has 2^30 cells or more: split the points into tiles");
  }

  // timings of the stages (statistics)
  double key_seconds() const { return key_seconds_; }
  double sort_seconds() const { return sort_seconds_; }
  double repair_seconds() const { return repair_seconds_; }

  std::size_t number_of_cells() const { return cells_.size(); }
  // the numbering of the cells (positions) used by the records
  const Handle_index_map<Cell>& cell_positions() const { return cells_; }
  // records sorted increasingly along the triangle order
  const Dual_edge_records& records() const { return records_; }
  // gives the records away (the graph has none afterwards), for a caller that filters them
  // in place rather than into fresh memory
  Dual_edge_records release_records() { return std::move(records_); }

  std::uint32_t position(Cell_handle c) const { return cells_.index(&*c); }
  Cell_handle cell(std::uint32_t position) const
  {
    auto& tds = const_cast<typename Triangulation::Triangulation_data_structure&>(dt_.tds());
    return tds.cells().iterator_to(*const_cast<Cell*>(cells_.element(position)));
  }

  static std::uint32_t owner_position(const Record& r) { return r.owner >> 2; }
  // Hints that the owner cell of `r` will be read soon (a performance hint only).
  void prefetch_owner(const Record& r) const { prefetch_object(cells_.element(owner_position(r))); }
  static std::uint32_t other_position(const Record& r) { return r.other & 0x3fffffffu; }
  static int longest_edge(const Record& r) { return int(r.other >> 30); }
  static int facet_index(const Record& r) { return int(r.owner & 3); }

  // The code (owner position << 2 | facet index) of the record of the finite facet (c, i),
  // and whether the record's orientation (outward of its owner) is opposite to the facet's
  // (outward of c). The owner is the finite cell of the facet, or the one of lower address
  // if both are finite (as in build_records()).
  std::pair<std::uint32_t, bool> record_code(Cell_handle c, int i) const { return record_code(dt_, cells_, c, i); }

  static std::pair<std::uint32_t, bool> record_code(const Triangulation& dt, const Handle_index_map<Cell>& cells,
                                                    Cell_handle c, int i)
  {
    const Cell_handle n = c->neighbor(i);
    bool c_owns;
    if(dt.is_infinite(c)) c_owns = false;
    else if(dt.is_infinite(n)) c_owns = true;
    else c_owns = !std::less<const Cell*>()(&*n, &*c);
    if(c_owns) return {(cells.index(&*c) << 2) | std::uint32_t(i), false};
    return {(cells.index(&*n) << 2) | std::uint32_t(n->index(c)), true};
  }

  // The facet between the adjacent cells at positions `a` (finite) and `b`, as the position
  // of the owner of its record and its index there (the owner is chosen as in the records).
  static std::pair<std::uint32_t, int> facet_between(const Triangulation& dt, const Handle_index_map<Cell>& cells,
                                                     std::uint32_t a, std::uint32_t b)
  {
    const Cell* x = cells.element(a);
    const Cell* y = cells.element(b);
    if(!y->has_vertex(dt.infinite_vertex()) && std::less<const Cell*>()(y, x)) std::swap(x, y), a = b;
    for(int j = 0; j < 4; ++j)
      if(&*x->neighbor(j) == y) return std::make_pair(a, j);
    CGAL_error_msg("the cells are not adjacent");
    return std::make_pair(a, 0);
  }

  Triangle_coordinates_3 coordinates(const Record& r) const
  {
    return facet_coordinates(cell(owner_position(r)), facet_index(r));
  }

  static Triangle_coordinates_3 facet_coordinates(Cell_handle c, int j) { return facet_coordinates(*c, j); }

  // number of records that the fast keys did not order, and of those that the exact
  // comparator had to order (statistics)
  std::size_t number_of_records_in_runs() const { return in_runs_; }
  std::size_t number_of_exactly_sorted_records() const { return exactly_sorted_; }

private:
  // From this many cells, the key pass runs on several threads when it is given more than one.
  static constexpr std::size_t minimum_cells_for_parallel_keys = 200000;

  template <class Progress, class Keep>
  void build_records(const Progress& progress, Keep& keep, unsigned threads)
  {
    // reserved for all the facets: the pages that a filter leaves unused are never touched
    records_.reserve(number_of_finite_facets(dt_));
    Parallel_blocks parallel(threads, minimum_cells_for_parallel_keys);
    if(parallel.is_parallel(cells_.size())) {
      build_records_in_blocks(parallel, progress, keep);
      return;
    }
    std::uint32_t pos = 0;
    const auto& container = dt_.tds().cells();
    // the vertices of the cells a few steps ahead are fetched early
    auto ahead = container.begin();
    for(int i = 0; i < 8 && ahead != container.end(); ++i) ++ahead;
    for(auto it = container.begin(); it != container.end(); ++it, ++pos) {
      if(ahead != container.end()) {
        for(int i = 0; i < 4; ++i) prefetch_object(&*ahead->vertex(i));
        ++ahead;
      }
      if((pos & 0xfffff) == 0 && !progress(0.5 * double(pos) / double(cells_.size())))
        throw Cancelled();
      add_records_of_cell(*it, pos, keep, records_, [this](std::uint32_t owner, std::uint64_t upper) {
        uncertain_upper_.emplace(owner, upper);
      });
    }
  }

  // The key pass on several threads: the records of each block of cells are made into the
  // block's own buffer, and the buffers are appended in the order of the blocks, so that the
  // records are in the same order as with one thread.
  template <class Progress, class Keep>
  void build_records_in_blocks(Parallel_blocks& parallel, const Progress& progress, Keep& keep)
  {
    constexpr std::size_t block = std::size_t(1) << 14, wave = std::size_t(1) << 20;
    struct Block_output
    {
      Dual_edge_records records;
      std::vector<std::pair<std::uint32_t, std::uint64_t>> uncertain;
    };
    std::vector<Block_output> outputs(wave / block);
    parallel.run_in_waves(
      cells_.size(), block, wave, [&](double x) { return progress(0.5 * x); },
      [&](std::size_t b, std::size_t first, std::size_t last) {
        Block_output& out = outputs[b % outputs.size()];
        for(std::uint32_t pos = std::uint32_t(first); pos != last; ++pos)
          add_records_of_cell(*cells_.element(pos), pos, keep, out.records,
                              [&out](std::uint32_t owner, std::uint64_t upper) { out.uncertain.emplace_back(owner, upper); });
      },
      [&](std::size_t first_block, std::size_t blocks) {
        for(std::size_t b = first_block; b < first_block + blocks; ++b) {
          Block_output& out = outputs[b % outputs.size()];
          records_.insert(records_.end(), out.records.begin(), out.records.end());
          uncertain_upper_.insert(out.uncertain.begin(), out.uncertain.end());
          out.records.clear();
          out.uncertain.clear();
        }
      });
  }

  // Adds to `records` the records of the facets that the cell `c` at position `pos` writes:
  // each finite facet is written once, by the cell of lower address among its two cells; an
  // infinite cell writes its finite facet from the side of its finite neighbor. No neighbor
  // cell is read in the common case. `uncertain(owner, upper)` receives the upper bounds of
  // the keys that are only lower bounds.
  template <class Keep, class Uncertain>
  void add_records_of_cell(const Cell& c, std::uint32_t pos, Keep& keep, Dual_edge_records& records,
                           const Uncertain& uncertain) const
  {
    const Vertex_handle infinite = dt_.infinite_vertex();
    int infinite_index = -1;
    for(int i = 0; i < 4; ++i)
      if(c.vertex(i) == infinite) infinite_index = i;
    if(infinite_index >= 0) {
      const Cell_handle n = c.neighbor(infinite_index);
      if(std::less<const Cell*>()(&*n, &c)) return;
      const std::uint32_t n_pos = cells_.index(&*n);
      int j = 0; // the index of c in n
      while(&*n->neighbor(j) != &c) ++j;
      if(keep(n_pos, j, pos)) add_record(*n, n_pos, j, pos, records, uncertain);
      return;
    }
    for(int j = 0; j < 4; ++j) {
      const Cell* n = &*c.neighbor(j);
      if(std::less<const Cell*>()(n, &c)) continue;
      const std::uint32_t n_pos = cells_.index(n);
      if(keep(pos, j, n_pos)) add_record(c, pos, j, n_pos, records, uncertain);
    }
  }

  template <class Uncertain>
  static void add_record(const Cell& c, std::uint32_t pos, int j, std::uint32_t other, Dual_edge_records& records,
                         const Uncertain& uncertain)
  {
    std::uint64_t upper;
    Record r = make_record(facet_coordinates(c, j), pos, j, other, upper);
    if(r.key & 1) uncertain(r.owner, upper);
    records.push_back(r);
  }

public:
  // The number of finite facets of `dt` (of dimension 3).
  static std::size_t number_of_finite_facets(const Triangulation& dt)
  {
    std::vector<Cell_handle> hull;
    dt.incident_cells(dt.infinite_vertex(), std::back_inserter(hull));
    return 2 * dt.tds().number_of_cells() - (3 * hull.size()) / 2;
  }

  static Triangle_coordinates_3 facet_coordinates(const Cell& c, int j)
  {
    Triangle_coordinates_3 t;
    for(int k = 0; k < 3; ++k) {
      const auto& p = c.vertex((j + 1 + k) & 3)->point();
      t[k] = Coordinates_3{{p.x(), p.y(), p.z()}};
    }
    return t;
  }

  // The record of the facet `j` of the cell at position `pos` whose vertices, in the order
  // of the facet, are `t`; `upper` receives the upper bound of the code of R_B^2 when the
  // key is only a lower bound (bit 0 set).
  static Record make_record(const Triangle_coordinates_3& t, std::uint32_t pos, int j, std::uint32_t other,
                            std::uint64_t& upper)
  {
    const Approximate_radii_3 a = approximate_radii(t);
    Record r;
    r.owner = (pos << 2) | std::uint32_t(j);
    int longest = 3;
    if(a.rb_error < max_relative_error) {
      std::uint64_t q = (std::uint64_t(1) << q_bits) - 1; // acute or right: q = 1
      if(a.longest >= 0 && a.rc_error < max_q_error) {
        longest = a.longest;
        q = std::uint64_t((std::min)(1.0, a.rb2 / a.rc2) * double((std::uint64_t(1) << q_bits) - 1));
      }
      r.key = (double_bits(a.rb2) & ~((std::uint64_t(1) << dropped_bits) - 1)) | (q << 1);
      upper = r.key >> dropped_bits;
    } else {
      const std::pair<double, double> range = enclosure_of_squared_rb(t);
      r.key = double_bits(range.first) | 1;
      upper = double_bits(range.second) >> dropped_bits;
    }
    r.other = other | (std::uint32_t(longest) << 30);
    return r;
  }

private:

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

  // A triangle of a run with its radii in double and certified error bounds, and its longest
  // edge as a pair of vertices when it is certainly obtuse.
  struct Run_member
  {
    Record record;
    Approximate_radii_3 radii;
    const void* edge[2];
  };


  // The longest edge of a record as a pair of vertices, or (null, null) if it is not known
  // from the key pass. Reads the owner cell.
  std::pair<const void*, const void*> longest_edge_vertices(const Record& r) const
  {
    const int l = longest_edge(r);
    if(l == 3) return std::make_pair(nullptr, nullptr);
    const Cell* c = cells_.element(owner_position(r));
    const int f = facet_index(r);
    const void* a = &*c->vertex((f + 1 + (l + 1) % 3) & 3);
    const void* b = &*c->vertex((f + 1 + (l + 2) % 3) & 3);
    if(std::less<const void*>()(b, a)) std::swap(a, b);
    return std::make_pair(a, b);
  }

  // Orders the run [i, j) from the keys alone when it is the common case: certainly obtuse
  // triangles with the same longest edge (so exactly the same R_B), whose codes of q differ
  // by 2 or more; `edges` are their longest edges. Returns false otherwise.
  bool sort_run_by_keys(std::size_t i, std::size_t j, const std::pair<const void*, const void*>* edges)
  {
    const std::uint64_t code = records_[i].key >> dropped_bits;
    for(std::size_t k = i; k < j; ++k) {
      const Record& r = records_[k];
      if(edges[k - i].first == nullptr || edges[k - i] != edges[0] || (r.key >> dropped_bits) != code || (r.key & 1))
        return false;
    }
    std::sort(records_.begin() + i, records_.begin() + j,
              [](const Record& x, const Record& y) { return x.key < y.key; });
    for(std::size_t k = i + 1; k < j; ++k)
      if((records_[k].key >> 1) - (records_[k - 1].key >> 1) < 2) return false;
    return true;
  }

  Run_member make_member(const Record& r) const
  {
    const Cell* c = cells_.element(owner_position(r));
    const int f = facet_index(r);
    Run_member m;
    m.record = r;
    Triangle_coordinates_3 t;
    for(int k = 0; k < 3; ++k) {
      const auto& p = c->vertex((f + 1 + k) & 3)->point();
      t[k] = Coordinates_3{{p.x(), p.y(), p.z()}};
    }
    m.radii = approximate_radii(t);
    m.edge[0] = m.edge[1] = nullptr;
    if(m.radii.longest >= 0) {
      const void* a = &*c->vertex((f + 1 + (m.radii.longest + 1) % 3) & 3);
      const void* b = &*c->vertex((f + 1 + (m.radii.longest + 2) % 3) & 3);
      m.edge[0] = (std::min)(a, b, std::less<const void*>());
      m.edge[1] = (std::max)(a, b, std::less<const void*>());
    }
    return m;
  }

  // Sorts the records of a run, whose members are [first, last), with their double
  // evaluations when the error bounds decide every comparison (insertion sort: runs are
  // short); returns false, leaving the members in some order, when one is undecided.
  static bool sort_members_in_double(Run_member* first, Run_member* last)
  {
    for(Run_member* a = first + 1; a < last; ++a) {
      const Run_member x = *a;
      Run_member* b = a;
      for(; b > first; --b) {
        const int c = compare_in_double(*(b - 1), x);
        if(c == 0) return false;
        if(c < 0) break;
        *b = *(b - 1);
      }
      *b = x;
    }
    return true;
  }

  // -1, +1: the first comes before, after the second; 0: undecided
  static int compare_in_double(const Run_member& a, const Run_member& b)
  {
    auto separated = [](double x, double ex, double y, double ey) -> int {
      if(x * (1 + ex) < y * (1 - ey)) return -1;
      if(y * (1 + ey) < x * (1 - ex)) return 1;
      return 0;
    };
    if(a.edge[0] != nullptr && a.edge[0] == b.edge[0] && a.edge[1] == b.edge[1])
      return -separated(a.radii.rc2, a.radii.rc_error, b.radii.rc2, b.radii.rc_error); // equal R_B: larger R_C first
    return separated(a.radii.rb2, a.radii.rb_error, b.radii.rb2, b.radii.rb_error);
  }

  std::uint64_t upper_code(const Record& r) const
  {
    if((r.key & 1) == 0) return r.key >> dropped_bits;
    return uncertain_upper_.at(r.owner);
  }

  template <class Progress>
  void sort_records(const Progress& progress, unsigned threads)
  {
    if(!progress(0.5))
      throw Cancelled();
    if(records_.empty()) return;
    std::uint64_t lo = records_.front().key, hi = lo;
    for(const Record& r : records_) { lo = (std::min)(lo, r.key); hi = (std::max)(hi, r.key); }
    int top = 63;
    while(top > 0 && ((lo ^ hi) >> top) == 0) --top; // highest differing bit
    // first digit: 16 bits below the highest differing bit, then 8 bits at a time
    const int width = 12; // 4096 counters for the first digit: they stay in the L1 cache
    Parallel_blocks parallel(threads, minimum_cells_for_parallel_keys);
    radix_sort_records(records_.data(), records_.data() + records_.size(), (std::max)(top - width + 1, 0),
                       dropped_bits, width, &parallel);
    if(!progress(0.8))
      throw Cancelled();

    // runs that the keys cannot order: first found in one sequential sweep...
    const auto repair_start = std::chrono::steady_clock::now();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;
    const std::size_t n = records_.size();
    for(std::size_t i = 0; i < n;) {
      std::uint64_t reach = upper_code(records_[i]);
      std::size_t j = i + 1;
      while(j < n && (records_[j].key >> dropped_bits) <= reach + 1) {
        reach = (std::max)(reach, upper_code(records_[j]));
        ++j;
      }
      if(j - i > 1) runs.emplace_back(std::uint32_t(i), std::uint32_t(j));
      i = j;
    }
    // ... then ordered from their keys when possible (the common case), else sorted in
    // double when the bounds decide, exactly otherwise. The records of a run are scattered in
    // memory: their cells are read in chunks, in memory order (a radix sort of the positions),
    // which turns random reads into nearly sequential ones.
    std::vector<std::pair<Triangle_order_key_3, Record>> run;
    std::vector<std::uint64_t> order, buffer;
    std::vector<std::uint32_t> record_of_slot;
    std::vector<std::pair<const void*, const void*>> edges; // a chunk's longest edges, run after run
    std::vector<Run_member> members;                        // a chunk's members, run after run
    std::vector<std::size_t> undecided;                     // runs of the chunk not ordered by keys
    constexpr std::size_t chunk = std::size_t(1) << 16;
    // reads `read(slot, record)` for the slots of the runs `which` of a chunk, in memory order
    auto gather = [&](const std::vector<std::size_t>& which, auto&& read) {
      order.clear();
      record_of_slot.clear();
      for(std::size_t g : which)
        for(std::uint32_t k = runs[g].first; k < runs[g].second; ++k) {
          order.push_back((std::uint64_t(owner_position(records_[k])) << 32) | record_of_slot.size());
          record_of_slot.push_back(k);
        }
      radix_sort_high_words(order, buffer);
      constexpr std::size_t ahead = 12; // cells fetched early: their reads then overlap
      for(std::size_t i = 0; i < order.size(); ++i) {
        if(i + ahead < order.size()) prefetch_object(cells_.element(std::uint32_t(order[i + ahead] >> 32)));
        read(std::uint32_t(order[i]), records_[record_of_slot[std::uint32_t(order[i])]]);
      }
    };
    std::vector<std::size_t> all;
    for(std::size_t g0 = 0; g0 < runs.size();) {
      std::size_t g1 = g0, count = 0;
      while(g1 < runs.size() && (count == 0 || count + (runs[g1].second - runs[g1].first) <= chunk))
        count += runs[g1].second - runs[g1].first, ++g1;
      all.clear();
      for(std::size_t g = g0; g < g1; ++g) all.push_back(g);
      edges.resize(count);
      gather(all, [&](std::uint32_t slot, const Record& r) { edges[slot] = longest_edge_vertices(r); });
      undecided.clear();
      std::size_t slot = 0;
      for(std::size_t g = g0; g < g1; ++g) {
        in_runs_ += runs[g].second - runs[g].first;
        if(!sort_run_by_keys(runs[g].first, runs[g].second, edges.data() + slot)) undecided.push_back(g);
        slot += runs[g].second - runs[g].first;
      }
      std::size_t needed = 0;
      for(std::size_t g : undecided) needed += runs[g].second - runs[g].first;
      members.resize(needed);
      gather(undecided, [&](std::uint32_t s, const Record& r) { members[s] = make_member(r); });
      std::size_t first_slot = 0;
      for(std::size_t g : undecided) {
        const std::size_t i = runs[g].first, j = runs[g].second;
        Run_member* m = members.data() + first_slot;
        first_slot += j - i;
        if(sort_members_in_double(m, m + (j - i))) {
          for(std::size_t k = i; k < j; ++k) records_[k] = m[k - i].record;
        } else {
          run.clear();
          for(std::size_t k = i; k < j; ++k)
            run.emplace_back(Triangle_order_key_3(coordinates(records_[k])), records_[k]);
          std::sort(run.begin(), run.end(),
                    [](const auto& x, const auto& y) { return compare(x.first, y.first) == SMALLER; });
          for(std::size_t k = i; k < j; ++k) records_[k] = run[k - i].second;
          exactly_sorted_ += j - i;
        }
      }
      g0 = g1;
    }
    repair_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - repair_start).count();
  }

  const Triangulation& dt_;
  Handle_index_map<Cell> cells_;
  Dual_edge_records records_;
  std::unordered_map<std::uint32_t, std::uint64_t> uncertain_upper_;
  std::size_t in_runs_ = 0, exactly_sorted_ = 0;
  double key_seconds_ = 0, sort_seconds_ = 0, repair_seconds_ = 0;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_SORTED_DUAL_GRAPH_3_H
