// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SIMPLIFICATION_SETTINGS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SIMPLIFICATION_SETTINGS_2_H

// The named parameters of simplify_polygon_partition_2(), with their defaults, checked and
// expressed in the normalized frame of the partition (lengths divided by its scale), where the
// descent and the reductions work.

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_energy_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_reductions_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

struct Simplification_settings
{
  double collapse_distance = 0;    // epsilon, normalized frame: the unit of length of the energy
  Energy_weights weights;          // of the energy measured in units of epsilon
  Reduction_thresholds thresholds; // of the reductions
  double initial_step = 0;         // alpha_0
  double step_ratio = 0;           // r
  double minimum_step = 0;         // alpha_min
  std::size_t maximum_iterations = 0; // gradient steps of the whole simplification
};

// The settings of the named parameters `np` for a partition of scale `scale` (input length of a
// unit of the normalized frame). Throws Input_error (INVALID_PARAMETER) when one is out of range.
template <class NamedParameters>
Simplification_settings simplification_settings(const NamedParameters& np, double scale)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace np_ = Polygon_partition_simplification::internal_np;
  namespace cgal_np = CGAL::internal_np;

  const double lambda1 = choose_parameter(get_parameter(np, np_::concurrency_weight), 0.5);
  const double lambda2 = choose_parameter(get_parameter(np, np_::orthogonality_weight), 5.);
  const double epsilon = choose_parameter(get_parameter(np, np_::collapse_distance), 0.01 * scale) / scale;
  const double alpha_max = choose_parameter(get_parameter(np, cgal_np::maximum_angle), 5.);
  const double l_min = choose_parameter(get_parameter(np, cgal_np::minimum_length), epsilon * scale) / scale;
  const double d_p = choose_parameter(get_parameter(np, np_::point_merge_distance), 0.01 * epsilon * scale) / scale;
  const double d_l = choose_parameter(get_parameter(np, np_::line_merge_distance), 1e-2);
  // by default, the L1 terms move lines by about the same amount whatever their weights
  const double alpha0 = choose_parameter(get_parameter(np, np_::initial_step),
                                         std::min(0.02, 2.5e-3 / std::max({lambda1, 0.1 * lambda2, 1e-12})));
  const double ratio = choose_parameter(get_parameter(np, np_::step_ratio), 0.97);
  // (below the default initial step of weights above about 1e6 otherwise)
  const double alpha_min = choose_parameter(get_parameter(np, np_::minimum_step), std::min(1e-9, 0.5 * alpha0));
  const bool remove_far = choose_parameter(get_parameter(np, np_::remove_far_points), false);
  const std::size_t max_iterations =
    choose_parameter(get_parameter(np, cgal_np::number_of_iterations), std::size_t(100000));

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

  Simplification_settings s;
  s.collapse_distance = epsilon;
  // the energy measured with the collapse distance as unit of length, expressed in the normalized frame
  s.weights.concurrency_weight = lambda1 * epsilon;
  s.weights.orthogonality_weight = lambda2 * epsilon * epsilon;
  s.weights.collapse_distance = epsilon;
  s.weights.sin_maximum_angle = std::sin(alpha_max * 3.14159265358979323846 / 180.);
  s.weights.minimum_length = l_min;
  s.thresholds.point_distance = d_p;
  s.thresholds.line_distance = d_l;
  s.thresholds.collapse_length = epsilon;
  s.thresholds.remove_far_points = remove_far;
  s.thresholds.eta = d_p * d_l * d_l / (5. * (1. + 1.)); // Eq. 3.15 with R = 1
  s.initial_step = alpha0;
  s.step_ratio = ratio;
  s.minimum_step = alpha_min;
  s.maximum_iterations = max_iterations;
  return s;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SIMPLIFICATION_SETTINGS_2_H
