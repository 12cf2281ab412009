// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SIMPLIFY_POLYGON_PARTITION_2_H
#define CGAL_SIMPLIFY_POLYGON_PARTITION_2_H

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_energy_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_reductions_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_validity_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
What `simplify_polygon_partition_2()` did.
*/
struct Simplification_statistics
{
  std::size_t lines_before = 0;   ///< lines of the input partition
  std::size_t points_before = 0;  ///< points of the input partition
  std::size_t cells_before = 0;   ///< cells of the input partition
  std::size_t orthogonal_pairs_before = 0; ///< pairs of lines meeting within 1e-4 degree of 90 degrees
  std::size_t lines_after = 0;    ///< lines of the result
  std::size_t points_after = 0;   ///< points of the result
  std::size_t cells_after = 0;    ///< cells of the result
  std::size_t orthogonal_pairs_after = 0; ///< pairs of lines meeting within 1e-4 degree of 90 degrees
  std::size_t iterations = 0;     ///< gradient steps
  std::size_t rounds = 0;         ///< descents followed by reductions (outer loop of Algorithm 1)
  std::size_t line_merges = 0;    ///< reductions (a): two lines merged
  std::size_t point_merges = 0;   ///< reductions (b1): two points merged (an edge collapsed)
  std::size_t removed_points = 0; ///< points left on a single line, or dangling, removed
  std::size_t far_points = 0;     ///< triplets below the threshold with a point outside the disk (b2)
  std::size_t rejected_rounds = 0; ///< reductions redone because they left the partition invalid (with some lines put back)
  double energy_before = 0;       ///< energy of the input partition (in units of the collapse distance)
  double energy_after = 0;        ///< energy of the result (in units of the collapse distance)
  double seconds = 0;             ///< running time
};

} // namespace Polygon_partition_simplification

/*!
\ingroup PkgPolygonPartitionSimplificationRef

simplifies a polygonal partition in line representation (section 3.3 of the thesis,
Algorithm 1): gradient descents on the space of lines of the energy
\f[ E = \frac{1}{2\epsilon^2} \sum_i L_i^T M_i L_i
      + \lambda_1 \sum_{(i,j,k)} \min\left(1, \frac{|\det(L_i, L_j, L_k)|}{\epsilon}\right)
      + \lambda_2 \sum_{(i,j)} \min(\sin\alpha_{max}, |a_i a_j + b_i b_j|) \f]
(the energy of Eq. 3.3 measured with the collapse distance \f$\epsilon\f$ as unit of length)
interleaved with combinatorial reductions (line merges, point merges), until a descent
brings no reduction. The triplets \f$(i, j, k)\f$ are the lines \f$j\f$ and \f$k\f$ through the
two ends of an edge of line \f$i\f$ (and the triples of lines through a merged point); the
pairs \f$(i, j)\f$ are the lines meeting at a point.

Each descent makes steps \f$L_i \leftarrow \mathrm{normalize}(L_i - \alpha_k \nabla_i E)\f$ on the
cylinder \f$a^2 + b^2 = 1\f$ with the Riemannian gradient of Eq. 3.13 and steps
\f$\alpha_k = \alpha_0 r^k\f$ down to \f$\alpha_{min}\f$. The first descent moves all lines; each
later one moves the lines that the reductions of the previous round changed and the lines that
share a term of the energy with them. A reduction is decided when
\f$|\det(L_i, L_j, L_k)| < \eta = d_P d_L^2 / (5 (1 + R^2))\f$ (Eq. 3.15, \f$R = 1\f$ in the
normalized frame of the partition). After every round the partition is checked with exact
predicates (`Line_partition_2::defect()`); when it is not valid, the lines of the defective
edges (and the lines through their ends) get back the coordinates they had before the descent
and may not merge, and the reductions are redone, until the partition is valid. When these
lines are all kept back already (the defect comes from a change further away, such as a point
removed between the ends of an edge), the lines within one more point of them are kept back
too, ring after ring; at worst the result of the round is the partition before it. The result
is always a valid partition.

Lengths are in input units. The weights \f$\lambda_1\f$ and \f$\lambda_2\f$ have no unit: they
weigh the terms of the energy measured in units of \f$\epsilon\f$, so the result does not change
when the input is moved, rotated or scaled (with its lengths), and a building is simplified
the same way in a scene of any extent when \f$\epsilon\f$ is given in input units. In the
normalized frame of the partition (where the half-diagonal of its enclosing rectangle is 1,
and \f$\epsilon_n = \epsilon / \mathrm{half\ diagonal}\f$), this is the energy of the thesis,
\f$E_{thesis} = \frac12 \sum_i L_i^T M_i L_i + \lambda'_1 \sum \min(\epsilon_n, |\det|) + \lambda'_2 \sum
\min(\sin\alpha_{max}, |\cos|)\f$, times \f$1/\epsilon_n^2\f$, with \f$\lambda'_1 = \lambda_1 \epsilon_n\f$
and \f$\lambda'_2 = \lambda_2 \epsilon_n^2\f$: with the default \f$\epsilon_n = 0.01\f$, the defaults
\f$\lambda_1 = 0.5\f$ and \f$\lambda_2 = 5\f$ are \f$\lambda'_1 = 0.005\f$ and \f$\lambda'_2 = 0.0005\f$.

\tparam GeomTraits the kernel of the partition
\tparam NamedParameters a sequence of named parameters

\param partition the partition, replaced by its simplification
\param np optional named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{concurrency_weight}
    \cgalParamDescription{\f$\lambda_1\f$: larger values collapse more edges and merge more lines}
    \cgalParamType{`double`}
    \cgalParamDefault{0.5}
  \cgalParamNEnd
  \cgalParamNBegin{orthogonality_weight}
    \cgalParamDescription{\f$\lambda_2\f$: larger values make more pairs of lines orthogonal}
    \cgalParamType{`double`}
    \cgalParamDefault{5}
  \cgalParamNEnd
  \cgalParamNBegin{collapse_distance}
    \cgalParamDescription{\f$\epsilon\f$, positive: edges shorter than this (input units) are
                          pulled to a point; the concurrency term of a longer edge is constant.
                          It is also the unit of length of the energy: give it in input units
                          to simplify scenes of different extents (tiles of a city) alike}
    \cgalParamType{`double`}
    \cgalParamDefault{1% of the half-diagonal of the partition}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_angle}
    \cgalParamDescription{\f$\alpha_{max}\f$ in degrees: lines meeting at an angle within this of
                          90 degrees are pulled to orthogonality}
    \cgalParamType{`double`}
    \cgalParamDefault{5}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_length}
    \cgalParamDescription{\f$l_{min}\f$ of Eq. 3.5 (input units): segments shorter than this are
                          as hard to rotate as a segment of that length}
    \cgalParamType{`double`}
    \cgalParamDefault{the collapse distance}
  \cgalParamNEnd
  \cgalParamNBegin{point_merge_distance}
    \cgalParamDescription{\f$d_P\f$ (input units)}
    \cgalParamType{`double`}
    \cgalParamDefault{1% of the collapse distance}
  \cgalParamNEnd
  \cgalParamNBegin{line_merge_distance}
    \cgalParamDescription{\f$d_L\f$, between normalized line coordinates}
    \cgalParamType{`double`}
    \cgalParamDefault{1e-2}
  \cgalParamNEnd
  \cgalParamNBegin{initial_step}
    \cgalParamDescription{\f$\alpha_0\f$, in (0, 1] (1 is a full Newton step of the fidelity term)}
    \cgalParamType{`double`}
    \cgalParamDefault{\f$\min(0.02, 2.5\,10^{-3} / \max(\lambda_1, \lambda_2 / 10))\f$: the concurrency and
                      orthogonality terms then move lines by about the same amount whatever their weights}
  \cgalParamNEnd
  \cgalParamNBegin{step_ratio}
    \cgalParamDescription{\f$r\f$, in (0, 1)}
    \cgalParamType{`double`}
    \cgalParamDefault{0.97}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_step}
    \cgalParamDescription{\f$\alpha_{min}\f$}
    \cgalParamType{`double`}
    \cgalParamDefault{\f$\min(10^{-9}, \alpha_0 / 2)\f$ (\f$10^{-9}\f$ but for weights above about \f$10^6\f$)}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{largest total number of gradient steps}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{100000}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{called after every round with the current partition and the statistics
                          so far (the `_after` fields describe that partition); returning `false`
                          stops the simplification there (the partition is valid)}
    \cgalParamType{a callable `bool(const Line_partition_2<GeomTraits>&, const Simplification_statistics&)`}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return the statistics of the simplification

\throws Polygon_partition_simplification::Input_error with code `INVALID_PARAMETER` when a
parameter is out of range, or `NO_CELL` when the partition is not valid; `partition` is then
unchanged.
*/
template <class GeomTraits, class NamedParameters = parameters::Default_named_parameters>
Polygon_partition_simplification::Simplification_statistics
simplify_polygon_partition_2(Polygon_partition_simplification::Line_partition_2<GeomTraits>& partition,
                             const NamedParameters& np = parameters::default_values())
{
  namespace PPS = Polygon_partition_simplification;
  using Partition = PPS::Line_partition_2<GeomTraits>;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  using PPS::Input_error;
  using PPS::Input_error_code;
  const auto clock_start = std::chrono::steady_clock::now();

  const double scale = partition.frame().scale;
  const double lambda1 = choose_parameter(get_parameter(np, PPS::internal_np::concurrency_weight), 0.5);
  const double lambda2 = choose_parameter(get_parameter(np, PPS::internal_np::orthogonality_weight), 5.);
  const double epsilon = choose_parameter(get_parameter(np, PPS::internal_np::collapse_distance), 0.01 * scale) / scale;
  const double alpha_max = choose_parameter(get_parameter(np, internal_np::maximum_angle), 5.);
  const double l_min = choose_parameter(get_parameter(np, internal_np::minimum_length), epsilon * scale) / scale;
  const double d_p = choose_parameter(get_parameter(np, PPS::internal_np::point_merge_distance), 0.01 * epsilon * scale) / scale;
  const double d_l = choose_parameter(get_parameter(np, PPS::internal_np::line_merge_distance), 1e-2);
  // by default, the L1 terms move lines by about the same amount whatever their weights
  const double alpha0 = choose_parameter(get_parameter(np, PPS::internal_np::initial_step),
                                         std::min(0.02, 2.5e-3 / std::max({lambda1, 0.1 * lambda2, 1e-12})));
  const double ratio = choose_parameter(get_parameter(np, PPS::internal_np::step_ratio), 0.97);
  // (below the default initial step of weights above about 1e6 otherwise)
  const double alpha_min = choose_parameter(get_parameter(np, PPS::internal_np::minimum_step), std::min(1e-9, 0.5 * alpha0));
  const std::size_t max_iterations =
    choose_parameter(get_parameter(np, internal_np::number_of_iterations), std::size_t(100000));
  using Callback = std::function<bool(const Partition&, const PPS::Simplification_statistics&)>;
  Callback callback;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::callback_t>::value)
    callback = get_parameter(np, internal_np::callback);

  auto check = [](bool ok, const char* what) {
    if(!ok) throw Input_error(Input_error_code::INVALID_PARAMETER, what);
  };
  check(lambda1 >= 0 && std::isfinite(lambda1), "concurrency_weight must be >= 0");
  check(lambda2 >= 0 && std::isfinite(lambda2), "orthogonality_weight must be >= 0");
  check(epsilon > 0 && std::isfinite(epsilon) && std::isnormal(epsilon * epsilon),
        "collapse_distance must be > 0, with a square that is a normal double in the normalized frame "
        "(between about 1e-150 and 1e150 times the half-diagonal: it is the unit of the energy)");
  check(alpha_max >= 0 && alpha_max <= 90, "maximum_angle must be in [0, 90] degrees");
  check(l_min > 0 && std::isfinite(l_min), "minimum_length must be > 0");
  check(d_p > 0 && d_l > 0 && std::isfinite(d_p) && std::isfinite(d_l),
        "point_merge_distance and line_merge_distance must be > 0");
  check(alpha0 > 0 && alpha0 <= 1, "initial_step must be in (0, 1] (1 is a full Newton step of the fidelity term)");
  check(ratio > 0 && ratio < 1, "step_ratio must be in (0, 1)");
  check(alpha_min > 0 && alpha_min < alpha0, "minimum_step must be in (0, initial_step)");
  {
    const std::string defect = partition.defect();
    if(!defect.empty())
      throw Input_error(Input_error_code::NO_CELL, "the partition is not valid: " + defect);
  }

  PPS::internal::Energy_weights weights;
  // the energy measured with the collapse distance as unit of length, expressed in the normalized frame
  weights.concurrency_weight = lambda1 * epsilon;
  weights.orthogonality_weight = lambda2 * epsilon * epsilon;
  weights.collapse_distance = epsilon;
  weights.sin_maximum_angle = std::sin(alpha_max * 3.14159265358979323846 / 180.);
  weights.minimum_length = l_min;
  PPS::internal::Reduction_thresholds thresholds;
  thresholds.point_distance = d_p;
  thresholds.line_distance = d_l;
  thresholds.collapse_length = epsilon;
  thresholds.eta = d_p * d_l * d_l / (5. * (1. + 1.)); // Eq. 3.15 with R = 1

  // working copy
  PPS::internal::Working_partition w;
  for(const auto& l : partition.lines())
  {
    PPS::internal::Line_state state;
    state.coefficients = l.coefficients;
    state.metric = l.metric;
    state.number_of_segments = l.number_of_segments;
    state.is_fixed = l.is_fixed;
    w.lines.push_back(state);
  }
  for(const auto& v : partition.vertices())
    w.vertex_lines.emplace_back(v.lines.begin(), v.lines.end());
  for(const auto& e : partition.edges())
    w.edges.push_back({PPS::internal::Index(e.line), PPS::internal::Index(std::min(e.source, e.target)),
                       PPS::internal::Index(std::max(e.source, e.target))});

  auto to_partition = [&](const PPS::internal::Working_partition& x) {
    std::vector<typename Partition::Line> lines;
    for(const auto& l : x.lines) {
      typename Partition::Line line;
      line.coefficients = l.coefficients;
      line.metric = l.metric;
      line.number_of_segments = l.number_of_segments;
      line.is_fixed = l.is_fixed;
      lines.push_back(line);
    }
    std::vector<typename Partition::Vertex> vertices;
    for(const auto& v : x.vertex_lines) vertices.push_back({std::vector<std::size_t>(v.begin(), v.end())});
    std::vector<typename Partition::Edge> edges;
    for(const auto& e : x.edges) edges.push_back({e[0], e[1], e[2]});
    return Partition(partition.frame(), std::move(lines), std::move(vertices), std::move(edges));
  };

  PPS::Simplification_statistics stats;
  stats.lines_before = partition.number_of_lines();
  stats.points_before = partition.number_of_vertices();
  // a valid partition is a plane graph: its cells follow from Euler's formula
  auto number_of_cells = [](const PPS::internal::Working_partition& x) {
    std::vector<std::array<PPS::internal::Index, 2>> ends;
    ends.reserve(x.edges.size());
    for(const auto& e : x.edges) ends.push_back({{e[1], e[2]}});
    return PPS::internal::number_of_bounded_faces(x.vertex_lines.size(), ends);
  };
  stats.cells_before = number_of_cells(w);
  // the `_after` fields and the time, for the partition `x` made from `w`
  auto describe_result = [&](const Partition& x) {
    stats.energy_after = PPS::internal::energy(w.lines, PPS::internal::energy_terms(w), weights) / (epsilon * epsilon);
    stats.lines_after = x.number_of_lines();
    stats.points_after = x.number_of_vertices();
    stats.cells_after = number_of_cells(w);
    stats.orthogonal_pairs_after = x.number_of_orthogonal_pairs();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  };
  stats.orthogonal_pairs_before = partition.number_of_orthogonal_pairs();
  stats.energy_before = PPS::internal::energy(w.lines, PPS::internal::energy_terms(w), weights) / (epsilon * epsilon);

  // Algorithm 1. A round is a descent followed by reductions. When the reductions leave an
  // invalid partition, the lines of the defective edges (and of the points at their ends) get
  // back the coordinates they had before the descent, and the reductions are redone, until
  // the partition is valid (at worst, every line back where it was: the partition before the
  // round, which is valid).
  bool finished = false;
  std::vector<bool> changed; // lines the reductions of the previous round changed (none before the first)
  while(!finished) {
    const PPS::internal::Working_partition start = w;
    std::vector<PPS::internal::Vector_3d> moved;
    {
      // After the first round, the descent moves the lines the reductions changed and every
      // line sharing a term of the energy with one of them; the others rest. A line put back
      // (frozen) is not woken for that reason alone: with the same neighbours its descent would
      // lead to the same invalid reduction (waking them made 2.5 times more rounds and rejected
      // attempts on the benchmark).
      const PPS::internal::Energy_terms terms = PPS::internal::energy_terms(w);
      std::vector<bool> resting;
      if(!changed.empty()) {
        resting.assign(w.lines.size(), true);
        auto wake = [&](const auto& term) {
          if(std::any_of(term.begin(), term.end(), [&](PPS::internal::Index l) { return bool(changed[l]); }))
            for(PPS::internal::Index l : term) resting[l] = false;
        };
        for(const auto& t : terms.triplets) wake(t);
        for(const auto& p : terms.pairs) wake(p);
        for(PPS::internal::Index r = 0; r < w.lines.size(); ++r) if(changed[r]) resting[r] = false;
      }
      PPS::internal::Line_descent descent(w.lines, terms, weights, resting);
      for(double alpha = alpha0; alpha > alpha_min && stats.iterations < max_iterations &&
                                 descent.number_of_moving_lines() > 0; alpha *= ratio) {
        if(!descent.step(alpha)) break;
        ++stats.iterations;
      }
      moved = descent.coefficients();
    }
    std::vector<bool> frozen(start.lines.size(), false);
    PPS::internal::Reduction_counts counts;
    auto before_reductions = [&](PPS::internal::Working_partition& x) { // moved lines, frozen ones back
      x = start;
      for(PPS::internal::Index l = 0; l < x.lines.size(); ++l) {
        x.lines[l].members.assign(1, l);
        x.lines[l].is_frozen = frozen[l];
        if(!frozen[l]) x.lines[l].coefficients = moved[l];
      }
    };
    // The orientation of every edge along its line before the round (the reductions collapse
    // the edges that reversed), and the edges before the round, which is valid: an edge of the
    // reduced partition with the same ends (coordinates) crosses none of them.
    std::vector<signed char> orientations(start.edges.size());
    PPS::internal::Segment_coordinate_set start_edges(start.edges.size()); // their points are finite
    {
      std::vector<std::array<double, 2>> points(start.vertex_lines.size());
      for(PPS::internal::Index v = 0; v < points.size(); ++v) points[v] = start.point(v);
      for(std::size_t i = 0; i < start.edges.size(); ++i) {
        const auto& e = start.edges[i];
        const std::array<double, 2>& p = points[e[1]];
        const std::array<double, 2>& q = points[e[2]];
        orientations[i] = PPS::internal::Partition_reducer::orientation_along(start.lines[e[0]].coefficients, p, q);
        start_edges.insert(p, q);
      }
    }
    auto may_cross = [&](const std::array<double, 2>& p, const std::array<double, 2>& q) {
      return !start_edges.contains(p, q);
    };
    std::size_t ring = 0; // how far around a defect lines are frozen (grows when freezing stalls)
    std::vector<std::vector<PPS::internal::Index>> start_line_points; // built when a ring is needed
    for(;;) {
      before_reductions(w);
      PPS::internal::Partition_reducer reducer(w, thresholds);
      counts = reducer.run(orientations);
      std::vector<std::size_t> defective;
      const std::string defect =
        PPS::internal::partition_defect(PPS::internal::Working_partition_view{w}, &defective, may_cross);
      if(defect.empty() && reducer.conflicts().empty()) break;
      ++stats.rejected_rounds;
      bool progress = false;
      auto freeze = [&](PPS::internal::Index line) {
        for(PPS::internal::Index l : w.lines[line].members)
          if(!frozen[l] && !start.lines[l].is_fixed) { frozen[l] = true; progress = true; }
      };
      for(PPS::internal::Index l : reducer.conflicts())
        if(!frozen[l] && !start.lines[l].is_fixed) { frozen[l] = true; progress = true; }
      for(std::size_t e : defective) { // the edge's line and the lines through its ends
        freeze(w.edges[e][0]);
        for(int end = 1; end <= 2; ++end)
          for(PPS::internal::Index line : w.vertex_lines[w.edges[e][end]]) freeze(line);
      }
      // All these lines frozen already: the defect comes from a change further away (a point
      // between the ends of the edge removed because another line moved or merged). The lines
      // within `ring` points of them (before the round) are frozen too, one more ring each time.
      while(!progress && !defective.empty()) {
        ++ring;
        if(start_line_points.empty()) {
          start_line_points.resize(start.lines.size());
          for(PPS::internal::Index v = 0; v < start.vertex_lines.size(); ++v)
            for(PPS::internal::Index l : start.vertex_lines[v]) start_line_points[l].push_back(v);
        }
        std::vector<bool> reached(start.lines.size(), false);
        std::vector<PPS::internal::Index> layer;
        auto reach = [&](PPS::internal::Index line) {
          for(PPS::internal::Index l : w.lines[line].members)
            if(!reached[l]) { reached[l] = true; layer.push_back(l); }
        };
        for(std::size_t e : defective) {
          reach(w.edges[e][0]);
          for(int end = 1; end <= 2; ++end)
            for(PPS::internal::Index line : w.vertex_lines[w.edges[e][end]]) reach(line);
        }
        bool grew = true;
        for(std::size_t step = 0; step < ring && grew; ++step) {
          std::vector<PPS::internal::Index> next;
          for(PPS::internal::Index l : layer)
            for(PPS::internal::Index v : start_line_points[l])
              for(PPS::internal::Index m : start.vertex_lines[v])
                if(!reached[m]) { reached[m] = true; next.push_back(m); }
          grew = !next.empty();
          layer = std::move(next);
        }
        for(PPS::internal::Index l = 0; l < start.lines.size(); ++l)
          if(reached[l] && !frozen[l] && !start.lines[l].is_fixed) { frozen[l] = true; progress = true; }
        if(!grew) break; // the whole connected part is frozen
      }
      if(!progress) { w = start; finished = true; counts = {}; break; }
    }
    if(!finished) {
      PPS::internal::Working_partition before;
      before_reductions(before);
      changed = PPS::internal::changed_lines(before, w);
    }
    for(auto& l : w.lines) { l.is_frozen = false; l.members.clear(); }
    ++stats.rounds;
    stats.line_merges += counts.line_merges;
    stats.point_merges += counts.point_merges;
    stats.removed_points += counts.removed_points;
    stats.far_points += counts.far_points;
    if(callback) { // the statistics so far, the `_after` fields describing the partition passed
      const Partition current = to_partition(w);
      describe_result(current);
      if(!callback(current, stats)) break;
    }
    if(counts.total() == 0 || stats.iterations >= max_iterations) finished = true;
  }

  partition = to_partition(w);
  describe_result(partition);
  return stats;
}

} // namespace CGAL

#endif // CGAL_SIMPLIFY_POLYGON_PARTITION_2_H
