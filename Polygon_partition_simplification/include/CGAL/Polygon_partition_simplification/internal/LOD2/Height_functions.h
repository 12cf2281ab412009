// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_HEIGHT_FUNCTIONS_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_HEIGHT_FUNCTIONS_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_planes_3.h>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The labels of the lift as height functions z = a x + b y + c: label 0 is the ground, the
/// others are the non-vertical planes other than the ground, in the order of the planes.
struct Height_functions
{
  static constexpr std::size_t ground_label = 0;
  static constexpr std::size_t no_plane = std::numeric_limits<std::size_t>::max();

  std::vector<std::array<double, 3>> coefficients; ///< (a, b, c) per label
  std::vector<std::size_t> plane_of_label;         ///< index in the planes; `no_plane` for a flat ground

  template <class Kernel>
  explicit Height_functions(const Building_planes_3<Kernel>& planes)
  {
    if(planes.ground < planes.planes.size()) {
      coefficients.push_back(of_plane(planes.planes[planes.ground].plane));
      plane_of_label.push_back(planes.ground);
    } else {
      coefficients.push_back({{0, 0, planes.ground_level}});
      plane_of_label.push_back(no_plane);
    }
    for(std::size_t p = 0; p < planes.planes.size(); ++p) {
      if(p == planes.ground || planes.planes[p].is_vertical) continue;
      coefficients.push_back(of_plane(planes.planes[p].plane));
      plane_of_label.push_back(p);
    }
  }

  std::size_t number_of_labels() const { return coefficients.size(); }

  double height(std::size_t label, const std::array<double, 2>& xy) const
  {
    const auto& k = coefficients[label];
    return k[0] * xy[0] + k[1] * xy[1] + k[2];
  }

private:
  template <class Plane_3>
  static std::array<double, 3> of_plane(const Plane_3& plane)
  {
    const double a = CGAL::to_double(plane.a()), b = CGAL::to_double(plane.b());
    const double c = CGAL::to_double(plane.c()), d = CGAL::to_double(plane.d());
    return {{-a / c, -b / c, -d / c}};
  }
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_HEIGHT_FUNCTIONS_H
