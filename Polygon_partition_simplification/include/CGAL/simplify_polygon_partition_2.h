// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SIMPLIFY_POLYGON_PARTITION_2_H
#define CGAL_SIMPLIFY_POLYGON_PARTITION_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_descent_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Simplification_round_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Simplification_settings_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Working_partition_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <chrono>
#include <functional>
#include <string>
#include <utility>
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
  std::size_t far_point_removals = 0; ///< reductions (b2) with `remove_far_points`: points outside the disk of the partition removed with their edges
  std::size_t far_points = 0;     ///< points outside the disk left in place (the validity check then decides whether the round is redone)
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

\tparam GeomTraits the geometric traits of the partition (see `Line_partition_2`): its exact
predicates decide the validity of every round
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
  \cgalParamNBegin{remove_far_points}
    \cgalParamDescription{case (b2) as in the thesis: a point that the descent sent outside the disk of
                          the partition is removed with its edges (the cells around it become one),
                          unless it is a corner of only two edges. Off, such a point stays and the
                          reductions of the round are redone with its lines kept back. Removal
                          simplifies more, with fewer redone rounds, but moves boundaries farther
                          from the input (see the manual)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
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
  using Geom_traits = typename Partition::Geom_traits;
  using Statistics = PPS::Simplification_statistics;
  const auto clock_start = std::chrono::steady_clock::now();

  // The parameters, checked, in the normalized frame of the partition (where the rounds work).
  const PPS::internal::Simplification_settings settings =
    PPS::internal::simplification_settings(np, partition.frame().scale);
  std::function<bool(const Partition&, const Statistics&)> callback;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::callback_t>::value)
    callback = parameters::get_parameter(np, internal_np::callback);
  // Each round turns a valid partition into a valid one: the input must be valid.
  {
    const std::string defect = partition.defect();
    if(!defect.empty())
      throw PPS::Input_error(PPS::Input_error_code::NO_CELL, "the partition is not valid: " + defect);
  }

  // The rounds work on a copy in working form; `partition` is replaced at the end only.
  PPS::internal::Working_partition w = PPS::internal::working_partition(partition);
  Statistics stats;
  stats.lines_before = partition.number_of_lines();
  stats.points_before = partition.number_of_vertices();
  stats.cells_before = PPS::internal::number_of_cells(w);
  stats.orthogonal_pairs_before = partition.number_of_orthogonal_pairs();
  stats.energy_before = PPS::internal::energy_in_collapse_units(w, settings);
  // the `_after` fields and the time, for the partition `x` made from `w`
  auto describe_result = [&](const Partition& x) {
    stats.energy_after = PPS::internal::energy_in_collapse_units(w, settings);
    stats.lines_after = x.number_of_lines();
    stats.points_after = x.number_of_vertices();
    stats.cells_after = PPS::internal::number_of_cells(w);
    stats.orthogonal_pairs_after = x.number_of_orthogonal_pairs();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  };

  // Algorithm 1: rounds (a descent, then the reductions, redone until the partition is valid)
  // until a round reduces nothing or is undone, the gradient steps run out, or the callback
  // stops the simplification.
  std::vector<bool> changed; // lines the previous round changed (none before the first: all move)
  for(;;) {
    PPS::internal::Round_reductions round =
      PPS::internal::simplification_round<Geom_traits>(w, changed, settings, stats.iterations);
    ++stats.rounds;
    stats.rejected_rounds += round.rejected_attempts;
    stats.line_merges += round.counts.line_merges;
    stats.point_merges += round.counts.point_merges;
    stats.removed_points += round.counts.removed_points;
    stats.far_points += round.counts.far_points;
    stats.far_point_removals += round.counts.far_removals;
    if(callback) { // the statistics so far, the `_after` fields describing the partition passed
      const Partition current = PPS::internal::line_partition<GeomTraits>(w, partition.frame(), partition.geom_traits());
      describe_result(current);
      if(!callback(current, stats)) break;
    }
    if(round.undone || round.counts.total() == 0 || stats.iterations >= settings.maximum_iterations) break;
    changed = std::move(round.changed_lines);
  }

  partition = PPS::internal::line_partition<GeomTraits>(w, partition.frame(), partition.geom_traits());
  describe_result(partition);
  return stats;
}

} // namespace CGAL

#endif // CGAL_SIMPLIFY_POLYGON_PARTITION_2_H
