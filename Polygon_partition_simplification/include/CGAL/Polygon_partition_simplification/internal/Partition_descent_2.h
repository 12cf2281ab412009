// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_DESCENT_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_DESCENT_2_H

// The continuous part of a round of the simplification (Algorithm 1): the terms of the energy
// of a working partition, the lines that move, and the descent with the step schedule
// alpha_k = alpha_0 r^k (Line_descent in Line_energy_2.h makes the steps). The combinatorial
// structure does not change during a descent; only the coefficients of the lines do.

#include <CGAL/Polygon_partition_simplification/internal/Line_energy_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Simplification_settings_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Working_partition_2.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// The concurrency triplets and orthogonality pairs of the current structure.
inline Energy_terms energy_terms(const Working_partition& w)
{
  Energy_terms terms;
  for(const auto& e : w.edges) {
    const Index i = e[0];
    for(Index j : w.vertex_lines[e[1]]) {
      if(j == i) continue;
      for(Index k : w.vertex_lines[e[2]])
        if(k != i && k != j) terms.triplets.push_back({i, j, k});
    }
  }
  for(const auto& l : w.vertex_lines) {
    for(std::size_t a = 0; a < l.size(); ++a)
      for(std::size_t b = a + 1; b < l.size(); ++b) {
        if(!w.lines[l[a]].is_fixed && !w.lines[l[b]].is_fixed) terms.pairs.push_back({l[a], l[b]});
        for(std::size_t c = b + 1; c < l.size(); ++c) terms.triplets.push_back({l[a], l[b], l[c]});
      }
  }
  return terms;
}

// The energy of `w` measured with the collapse distance as unit of length (the energy of the
// documentation of simplify_polygon_partition_2()).
inline double energy_in_collapse_units(const Working_partition& w, const Simplification_settings& s)
{
  const double epsilon = s.collapse_distance;
  return energy(w.lines, energy_terms(w), s.weights) / (epsilon * epsilon);
}

// The lines that rest (do not move) in a descent, given the lines that the reductions of the
// previous round changed (`changed`; empty before the first round, when every line moves).
// After the first round, the descent moves the changed lines and every line sharing a term of
// the energy with one of them; the others rest. A line put back (frozen) in the previous round
// is not woken for that reason alone: with the same neighbours its descent would lead to the
// same invalid reduction.
inline std::vector<bool> resting_lines(const Working_partition& w, const Energy_terms& terms,
                                       const std::vector<bool>& changed)
{
  std::vector<bool> resting;
  if(changed.empty()) return resting;
  resting.assign(w.lines.size(), true);
  auto wake = [&](const auto& term) {
    if(std::any_of(term.begin(), term.end(), [&](Index l) { return bool(changed[l]); }))
      for(Index l : term) resting[l] = false;
  };
  for(const auto& t : terms.triplets) wake(t);
  for(const auto& p : terms.pairs) wake(p);
  for(Index r = 0; r < w.lines.size(); ++r) if(changed[r]) resting[r] = false;
  return resting;
}

// A descent from the lines of `w` (which it does not modify): gradient steps alpha_0 r^k while
// the step is above alpha_min, some line moves, and the total number of steps `iterations`
// (incremented at each step) is below the maximum. Stops early at a step that would give a line
// non-finite coordinates. Returns the coefficients of all lines at the end.
inline std::vector<Vector_3d> descend(const Working_partition& w, const std::vector<bool>& changed,
                                      const Simplification_settings& s, std::size_t& iterations)
{
  const Energy_terms terms = energy_terms(w);
  Line_descent descent(w.lines, terms, s.weights, resting_lines(w, terms, changed));
  for(double alpha = s.initial_step; alpha > s.minimum_step && iterations < s.maximum_iterations &&
                                     descent.number_of_moving_lines() > 0; alpha *= s.step_ratio) {
    if(!descent.step(alpha)) break;
    ++iterations;
  }
  return descent.coefficients();
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_DESCENT_2_H
