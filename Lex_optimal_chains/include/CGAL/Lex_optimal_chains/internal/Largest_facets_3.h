// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LARGEST_FACETS_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LARGEST_FACETS_3_H

// The largest facet of every finite cell of a 3D Delaunay triangulation in the triangle order
// of Lemma 4.14 (R_B, then R_C reversed, then the sorted vertex coordinates), found cell by
// cell without sorting anything.
//
// Why: when the facets are processed in decreasing order with disjoint sets (Kruskal, and
// Algorithm 8, which is Kruskal with the sources kept apart from the sinks), the largest
// facet of a cell that is neither a source nor a sink is the first facet of that cell to be
// processed, so it always unites the cell with its neighbor; and uniting them in advance
// changes no later decision (the cell is connected to nothing else before). These unions are
// the first step of Boruvka's algorithm: on points sampled from a surface they are nearly the
// whole spanning tree, and only the facets left between different components need to be
// sorted (the manual, section "Complexity and Performance", gives the proportions).
//
// The four facets of a cell are first compared from the six squared edge lengths alone, in
// double with certified error bounds (`certified_largest_facet()`); on the rare cells where a
// bound leaves a comparison undecided, facet by facet with the evaluations of
// internal/Triangle_order_3.h (`Cell_facets_3`), and exactly when those cannot decide. Two
// certainly obtuse facets whose longest edge is the same edge of the cell have exactly the
// same R_B (the common case of a near tie: the two facets around the longest edge of a flat
// cell) and are compared by R_C.

#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Parallel_blocks.h>
#include <CGAL/Lex_optimal_chains/internal/Prefetch.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>


#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The facets of one cell, with their certified double radii computed as they are needed:
// the six edges of the cell are computed once for its four facets, with the same roundings as
// `approximate_radii()` on each facet (same results, bit for bit).
struct Cell_facets_3
{
  Coordinates_3 point[4];
  double edge[4][4][3]; // edge[i][k], i < k: point[k] - point[i] (edge(k, i) = -edge(i, k) exactly)
  double length[4][4];  // squared lengths, symmetric
  Approximate_radii_3 radii[4]; // facet j: the vertices (j+1)&3, (j+2)&3, (j+3)&3
  // 0: nothing known, 1: the facet is certainly obtuse and R_B is known (`radii[j].rb2`,
  // `rb_error`, `longest`), 2: all of `radii[j]`
  int known[4] = {0, 0, 0, 0};
  // after `classify(j)`: the facet is certainly acute (its radii may not be computed yet)
  bool acute[4] = {false, false, false, false};
  double longest_length[4] = {0, 0, 0, 0}; // after `classify(j)`: the largest squared edge length of facet j
  std::optional<Triangle_order_key_3> keys[4]; // made by `key(j)`

  template <class Cell>
  explicit Cell_facets_3(const Cell& c)
  {
    for(int k = 0; k < 4; ++k) {
      const auto& q = c.vertex(k)->point();
      point[k] = Coordinates_3{{q.x(), q.y(), q.z()}};
    }
    for(int i = 0; i < 4; ++i)
      for(int k = i + 1; k < 4; ++k) {
        for(int x = 0; x < 3; ++x) edge[i][k][x] = point[k][x] - point[i][x];
        length[i][k] = length[k][i] =
          edge[i][k][0] * edge[i][k][0] + edge[i][k][1] * edge[i][k][1] + edge[i][k][2] * edge[i][k][2];
      }
  }

  Triangle_coordinates_3 facet(int j) const
  {
    return Triangle_coordinates_3{{point[(j + 1) & 3], point[(j + 2) & 3], point[(j + 3) & 3]}};
  }

  // From the squared edge lengths alone, as `approximate_radii()` decides it: whether the
  // facet is certainly obtuse (then R_B is known) or certainly acute (R_B = R_C is computed
  // later, if it is needed); the full radii otherwise.
  void classify(int j)
  {
    if(known[j] > 0 || acute[j]) return;
    const int p = (j + 1) & 3, q = (j + 2) & 3, r = (j + 3) & 3;
    const double l0 = length[q][r], l1 = length[p][r], l2 = length[p][q];
    int index = 0;
    double m = l0;
    if(l1 > m) { m = l1; index = 1; }
    if(l2 > m) { m = l2; index = 2; }
    longest_length[j] = m;
    const double s = l0 + l1 + l2 - m;
    constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
    const bool in_range = m > 1e-250 && m < 1e250;
    if(m > s * (1 + 64 * u)) {
      radii[j].longest = index;
      radii[j].rb2 = m * 0.25;
      radii[j].rb_error = in_range ? 16 * u : std::numeric_limits<double>::infinity();
      known[j] = 1;
    } else if(in_range && m < s * (1 - 64 * u)) {
      acute[j] = true;
    } else {
      compute(j);
    }
  }

  bool certainly_obtuse(int j) const { return known[j] > 0 && radii[j].longest >= 0; }

  // For two certainly obtuse facets `a` and `b` whose longest edge is the same edge XY of the
  // cell (so that their R_B are equal): -1, +1 if R_C(a) is certainly smaller, larger than
  // R_C(b); 0 if undecided. Facet a is the triangle b X Y, obtuse at b, and
  //   R_C(a)^2 = |XY|^2 |bX|^2 |bY|^2 / (4 |bX x bY|^2),
  // so the comparison is that of |bX|^2 |bY|^2 |aX x aY|^2 and |aX|^2 |aY|^2 |bX x bY|^2: no
  // division, and the error bound needs no per-component terms. Error analysis (u = 2^-53,
  // l the squared lengths, each within 6u of its value): each component of the cross product
  // of the rounded edges e, f is within 4.01u |e| |f| of its value, so |e x f|^2 is within
  // 17u l_e l_f; each product below is then within 15u of itself plus 17u P, with P the
  // product of the four squared lengths, and their difference within 15u (va + vb) + 34u P.
  // The bound used is more than twice that.
  int compare_circumradii_of_pair(int a, int b) const
  {
    constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
    int x = -1, y = -1; // the vertices of the common edge
    for(int k = 0; k < 4; ++k)
      if(k != a && k != b) (x < 0 ? x : y) = k;
    const double lbx = length[b][x], lby = length[b][y], lax = length[a][x], lay = length[a][y];
    for(const double l : {lbx, lby, lax, lay})
      if(!(l > 1e-60 && l < 1e60)) return 0; // the products would leave the normal range
    auto squared_cross = [this](int o, int x, int y) {
      const double* e = edge[(std::min)(o, x)][(std::max)(o, x)]; // +-(x - o)
      const double* f = edge[(std::min)(o, y)][(std::max)(o, y)]; // +-(y - o)
      const double nx = e[1] * f[2] - e[2] * f[1], ny = e[2] * f[0] - e[0] * f[2], nz = e[0] * f[1] - e[1] * f[0];
      return nx * nx + ny * ny + nz * nz;
    };
    const double va = (lbx * lby) * squared_cross(a, x, y); // 4 R_C(a)^2 d_a d_b / |XY|^2
    const double vb = (lax * lay) * squared_cross(b, x, y); // 4 R_C(b)^2 d_a d_b / |XY|^2
    const double bound = 40 * u * (va + vb) + 80 * u * ((lbx * lby) * (lax * lay));
    if(va - vb > bound) return 1;
    if(vb - va > bound) return -1;
    return 0;
  }

  void compute(int j)
  {
    if(known[j] == 2) return;
    const int p = (j + 1) & 3, q = (j + 2) & 3, r = (j + 3) & 3;
    const double* a = edge[(std::min)(p, q)][(std::max)(p, q)]; // +-(q - p)
    const double* b = edge[(std::min)(p, r)][(std::max)(p, r)]; // +-(r - p)
    radii[j] = approximate_radii_from_edges(a[0], a[1], a[2], b[0], b[1], b[2], length[q][r], length[p][r],
                                            length[p][q]);
    known[j] = 2;
  }

  // cell index of the vertex opposite the longest edge of a certainly obtuse facet, -1 otherwise
  int opposite_longest(int j) const { return radii[j].longest >= 0 ? (j + 1 + radii[j].longest) & 3 : -1; }

  // -1, +1: facet `a` comes before, after facet `b` in the order; `exact` counts the
  // comparisons that the double evaluations could not decide.
  int compare(int a, int b, std::size_t& exact)
  {
    auto separated = [](double x, double ex, double y, double ey) -> int {
      if(x * (1 + ex) < y * (1 - ey)) return -1;
      if(y * (1 + ey) < x * (1 - ex)) return 1;
      return 0;
    };
    classify(a);
    classify(b);
    // An acute facet that contains the longest edge of an obtuse one, or a longer edge, is
    // larger: its R_B is its circumradius, above half of each of its edges.
    auto acute_wins = [this](int c, int o) {
      return acute[c] && certainly_obtuse(o) &&
             (opposite_longest(o) == c || longest_length[c] > longest_length[o] * (1 + 1e-12));
    };
    if(acute_wins(a, b)) return 1;
    if(acute_wins(b, a)) return -1;
    int c;
    // facet a's longest edge is the cell edge without the vertices a and opposite_longest(a)
    if(opposite_longest(a) == b && opposite_longest(b) == a) {
      c = -compare_circumradii_of_pair(a, b); // same R_B: larger R_C first
      if(c == 0) {
        compute(a);
        compute(b);
        c = -separated(radii[a].rc2, radii[a].rc_error, radii[b].rc2, radii[b].rc_error);
      }
    } else {
      if(acute[a]) compute(a);
      if(acute[b]) compute(b);
      c = separated(radii[a].rb2, radii[a].rb_error, radii[b].rb2, radii[b].rb_error);
    }
    if(c != 0) return c;
    ++exact;
    return key(a) < key(b) ? -1 : 1;
  }

  // the facet as a key of the exact order, made once (a facet can be compared with several)
  const Triangle_order_key_3& key(int j)
  {
    if(!keys[j]) keys[j].emplace(facet(j));
    return *keys[j];
  }

  // The largest facet. R_B^2 of a triangle lies between (longest edge)^2 / 4 and
  // (longest edge)^2 / 3 (the circumradius of an acute triangle is at most its longest edge
  // over sqrt(3)), so a facet whose longest edge is below sqrt(3/4) times the longest edge of
  // the cell (with a margin for the roundings) cannot be the largest.
  int largest(std::size_t& exact)
  {
    double cell_longest = 0;
    for(int i = 0; i < 4; ++i)
      for(int k = i + 1; k < 4; ++k) cell_longest = (std::max)(cell_longest, length[i][k]);
    int best = -1;
    for(int j = 0; j < 4; ++j) {
      const int p = (j + 1) & 3, q = (j + 2) & 3, r = (j + 3) & 3;
      const double m = (std::max)(length[q][r], (std::max)(length[p][r], length[p][q]));
      if(m * (4 * (1 + 1e-12)) < cell_longest * (3 * (1 - 1e-12))) continue;
      if(best < 0 || compare(j, best, exact) > 0) best = j;
    }
    return best;
  }
};

// The largest facet of the cell with vertices `point` (facet j is opposite point j), or -1
// when a comparison is too close for the error bounds (then `Cell_facets_3::largest()`
// decides). Everything comes from the six squared edge lengths l, computed as in
// `Cell_facets_3` (each within 6u of its value, u = 2^-53): for the facet with vertices p, q,
// r and l0 = |qr|^2, l1 = |pr|^2, l2 = |pq|^2,
//   d = |pq x pr|^2 = l1 l2 - t^2 / 4, with t = 2 pq.pr = l1 + l2 - l0   (Lagrange's identity),
//   R_C^2 = l0 l1 l2 / (4 d),   R_B^2 = max(l) / 4 if obtuse, R_C^2 otherwise.
// Error analysis, with S = l0 + l1 + l2 (exact values D, S; computed d, s): t is within
// 8.01u S of its value, so t^2 / 4 is within 4.26u S^2; l1 l2 is within 13.01u l1 l2 <= 3.26u S^2;
// so |d - D| <= 7.52u S^2 + u|d| <= 7.8u S^2, below e d for the computed e = 16u s^2 / d (the
// roundings of s, s^2 and the quotient are far inside the factor 2). When e < 1/4,
// R_C^2 / c - 1 is within e / (1 - e) + 21u <= (4/3) e + 21u (the products and the quotient
// add 21u), below 2 (e + 32u), the bound of `approximate_radii_from_edges()`; R_B^2 of a
// certainly obtuse facet is within 16u. The
// lengths are kept within [1e-120, 1e120], so that no product leaves the normal range. A
// facet that could be the largest and whose R_B has no such bound (nearly right, or flat
// enough for d to lose its sign) leaves the cell undecided. This uses no cross product and
// few branches, and leaves undecided only cells with a nearly right or nearly flat facet.
inline int certified_largest_facet(const Coordinates_3 (&point)[4])
{
  constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
  // edge e joins the vertices first[e] < second[e]
  static constexpr int first[6] = {0, 0, 0, 1, 1, 2}, second[6] = {1, 2, 3, 2, 3, 3};
  double l[6];
  for(int e = 0; e < 6; ++e) {
    const Coordinates_3 &a = point[first[e]], &b = point[second[e]];
    const double x = b[0] - a[0], y = b[1] - a[1], z = b[2] - a[2];
    l[e] = x * x + y * y + z * z;
    if(!(l[e] > 1e-120 && l[e] < 1e120)) return -1; // each one tested: also NaN
  }
  double highest = l[0];
  for(int e = 1; e < 6; ++e) highest = (std::max)(highest, l[e]);
  // facet j, with p = (j+1)&3, q = (j+2)&3, r = (j+3)&3: the edges pq, pr and qr
  static constexpr int edge_pq[4] = {3, 5, 2, 0}, edge_pr[4] = {4, 1, 4, 1}, edge_qr[4] = {5, 2, 0, 3};
  // A facet whose longest edge is below sqrt(3/4) times the longest edge of the cell cannot be
  // the largest (see `Cell_facets_3::largest()`): it is smaller than the facets on that edge,
  // which are candidates.
  const double too_short = highest * (3 * (1 - 1e-12)) / (4 * (1 + 1e-12));
  bool candidate[4];
  double rb2[4], rb_error[4], rc2[4], rc_error[4];
  bool rc_known[4];
  int longest_edge[4]; // the cell edge that is the longest edge of a certainly obtuse facet, else 6 + j
  for(int j = 0; j < 4; ++j) {
    const double l0 = l[edge_qr[j]], l1 = l[edge_pr[j]], l2 = l[edge_pq[j]];
    double m = l0;
    int e = edge_qr[j];
    if(l1 > m) { m = l1; e = edge_pr[j]; }
    if(l2 > m) { m = l2; e = edge_pq[j]; }
    candidate[j] = m >= too_short;
    const double sum = l0 + l1 + l2, others = sum - m;
    const double t = l1 + l2 - l0;
    const double d = l1 * l2 - 0.25 * (t * t);
    const double c = l0 * (l1 * (l2 / (4 * d)));
    const double e_d = 16 * u * (sum * sum) / d;
    // known: positive, in range, with a bound (d may even come out negative on a flat facet)
    rc_known[j] = d > 0 && e_d < 0.25; // then c stays within [1e-121, 1e133]
    rc2[j] = c;
    rc_error[j] = 2 * (e_d + 32 * u);
    const bool obtuse = m > others * (1 + 64 * u), acute = m < others * (1 - 64 * u);
    if(candidate[j] && !obtuse && !(acute && rc_known[j])) return -1; // R_B not known closely enough
    rb2[j] = obtuse ? m * 0.25 : c;
    rb_error[j] = obtuse ? 16 * u : rc_error[j];
    longest_edge[j] = obtuse ? e : 6 + j;
  }
  int best = -1;
  for(int j = 0; j < 4; ++j)
    if(candidate[j] && (best < 0 || rb2[j] > rb2[best] || (rb2[j] == rb2[best] && rc2[j] < rc2[best]))) best = j;
  for(int j = 0; j < 4; ++j) {
    if(j == best || !candidate[j]) continue;
    if(longest_edge[j] == longest_edge[best]) { // the same R_B exactly: the smaller R_C is larger
      if(!(rc_known[best] && rc_known[j] && rc2[best] * (1 + rc_error[best]) < rc2[j] * (1 - rc_error[j])))
        return -1;
    } else if(!(rb2[best] * (1 - rb_error[best]) > rb2[j] * (1 + rb_error[j]))) {
      return -1;
    }
  }
  return best;
}

// The largest facet of the finite cell `c`; `exact` counts the comparisons made exactly.
template <class Cell>
int largest_facet(const Cell& c, std::size_t& exact)
{
  Coordinates_3 point[4];
  for(int k = 0; k < 4; ++k) {
    const auto& q = c.vertex(k)->point();
    point[k] = Coordinates_3{{q.x(), q.y(), q.z()}};
  }
  const int fast = certified_largest_facet(point);
  if(fast >= 0) return fast;
  return Cell_facets_3(c).largest(exact);
}

// From this many cells, `for_each_cell_across_largest_facet()` runs on several threads when
// it is given more than one: below, starting the threads costs more than it saves.
constexpr std::size_t minimum_cells_for_parallel_contraction = 200000;

// Calls `found(p, q)` for the cell at position `p` (in the numbering `cells` of the cell
// container) with the position q of the cell across its largest facet, or q = p for the cells
// with `terminal[p]` (they are not contracted) and the infinite cells. Returns the number of
// comparisons made exactly. `progress(fraction)` returns false to cancel; it is called from
// the calling thread only. With `threads` > 1 (and TBB), the cells are handled by that many
// threads, each p once, in no particular order: `found` must then be safe to call
// concurrently for different p (the contractions write the parent of p only). The result is
// the same for any number of threads: the largest facet of a cell depends on the cell alone.
template <class Triangulation, class Found, class Progress>
std::size_t for_each_cell_across_largest_facet(const Triangulation& dt,
                                               const Handle_index_map<typename Triangulation::Cell>& cells,
                                               const std::vector<bool>& terminal, const Found& found,
                                               const Progress& progress, unsigned threads = 1)
{
  const auto infinite = dt.infinite_vertex();
  Parallel_blocks parallel(threads, minimum_cells_for_parallel_contraction);
  if(parallel.is_parallel(cells.size())) {
    std::atomic<std::size_t> exact{0};
    parallel.run_in_waves(
      cells.size(), std::size_t(1) << 13, std::size_t(1) << 20, progress,
      [&](std::size_t, std::size_t first, std::size_t last) {
        std::size_t local_exact = 0;
        for(std::uint32_t pos = std::uint32_t(first); pos != last; ++pos) {
          const auto& c = *cells.element(pos);
          if(terminal[pos] || c.has_vertex(infinite)) found(pos, pos);
          else found(pos, cells.index(&*c.neighbor(largest_facet(c, local_exact))));
        }
        exact += local_exact;
      },
      [](std::size_t, std::size_t) {});
    return exact;
  }
  const auto& container = dt.tds().cells();
  std::size_t exact = 0;
  std::uint32_t pos = 0;
  auto ahead = container.begin(); // the vertices of the cells a few steps ahead are fetched early
  for(int i = 0; i < 8 && ahead != container.end(); ++i) ++ahead;
  for(auto it = container.begin(); it != container.end(); ++it, ++pos) {
    if(ahead != container.end()) {
      for(int i = 0; i < 4; ++i) prefetch_object(&*ahead->vertex(i));
      ++ahead;
    }
    if((pos & 0xfffff) == 0 && !progress(double(pos) / double(cells.size())))
      throw Cancelled();
    const auto& c = *it;
    if(terminal[pos] || c.has_vertex(infinite)) {
      found(pos, pos);
      continue;
    }
    found(pos, cells.index(&*c.neighbor(largest_facet(c, exact))));
  }
  return exact;
}

// Fills the order fields of a report (closed or open surfaces) from a contracted dual graph
// (`Contracted_dual_graph_3` or `Contracted_homologous_graph_3`).
template <class Contracted, class Report>
void report_order_statistics(const Contracted& contracted, double seconds, Report& report)
{
  report.number_of_exactly_ordered_triangles =
    contracted.number_of_exact_comparisons() + contracted.graph().number_of_exactly_sorted_records();
  report.number_of_triangles_in_close_runs = contracted.graph().number_of_records_in_runs();
  report.order_seconds = seconds;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LARGEST_FACETS_3_H
