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
// whole spanning tree (6,125,665 of its 6,126,529 edges for 1M points on a torus), and only
// the facets left between different components (18% of them) need to be sorted.
//
// The four facets of a cell are compared with certified double evaluations
// (internal/Triangle_order_3.h). Two certainly obtuse facets whose longest edge is the same
// edge of the cell have exactly the same R_B (the common case of a near tie: the two facets
// around the longest edge of a flat cell) and are compared by R_C. A comparison that the
// error bounds leave undecided is made exactly.

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Prefetch.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>

#include <algorithm>
#include <cstdint>
#include <limits>
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
    return compare_triangle_order(facet(a), facet(b)) == SMALLER ? -1 : 1;
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

// Calls `found(p, q)` for the cell at position `p` (in the numbering `cells` of the cell
// container), in increasing p, with the position q of the cell across its largest facet, or
// q = p for the cells with `terminal[p]` (they are not contracted) and the infinite cells.
// Returns the number of comparisons made exactly. `progress(fraction)` returns false to cancel.
template <class Triangulation, class Found, class Progress>
std::size_t for_each_cell_across_largest_facet(const Triangulation& dt,
                                               const Handle_index_map<typename Triangulation::Cell>& cells,
                                               const std::vector<bool>& terminal, const Found& found,
                                               const Progress& progress)
{
  const auto infinite = dt.infinite_vertex();
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
      throw Input_error(Input_error_code::CANCELLED, "cancelled by the callback");
    const auto& c = *it;
    if(terminal[pos] || c.has_vertex(infinite)) {
      found(pos, pos);
      continue;
    }
    Cell_facets_3 facets(c);
    found(pos, cells.index(&*c.neighbor(facets.largest(exact))));
  }
  return exact;
}

// Fills `across[p]` with the q of `for_each_cell_across_largest_facet()`.
template <class Triangulation, class Progress>
std::size_t cells_across_largest_facets(const Triangulation& dt,
                                        const Handle_index_map<typename Triangulation::Cell>& cells,
                                        const std::vector<bool>& terminal, std::vector<std::uint32_t>& across,
                                        const Progress& progress)
{
  across.resize(cells.size());
  return for_each_cell_across_largest_facet(
    dt, cells, terminal, [&across](std::uint32_t p, std::uint32_t q) { across[p] = q; }, progress);
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
