// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RUNS_ALONG_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RUNS_ALONG_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// true when the segment (a, b) runs along `segments`: two of its points at 1/4, 1/2 and 3/4
/// are within `distance` of a segment at less than 15 degrees from it
template <class Segment2Range>
bool runs_along(const std::array<double, 2>& a, const std::array<double, 2>& b,
                     const Segment2Range& segments, double distance)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length = std::sqrt(dx * dx + dy * dy);
  if(length == 0) return false;
  int near = 0;
  for(double t : {0.25, 0.5, 0.75}) {
    const double px = a[0] + t * dx, py = a[1] + t * dy;
    for(const auto& s : segments) {
      const double sx = CGAL::to_double(s.source().x()), sy = CGAL::to_double(s.source().y());
      const double ex = CGAL::to_double(s.target().x()) - sx, ey = CGAL::to_double(s.target().y()) - sy;
      const double squared = ex * ex + ey * ey;
      if(squared == 0 || std::abs(ex * dy - ey * dx) > std::sin(15 * CGAL_PI / 180) * std::sqrt(squared) * length)
        continue;
      const double u = std::clamp(((px - sx) * ex + (py - sy) * ey) / squared, 0.0, 1.0);
      const double qx = sx + u * ex - px, qy = sy + u * ey - py;
      if(qx * qx + qy * qy <= distance * distance) {
        ++near;
        break;
      }
    }
  }
  return near >= 2;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RUNS_ALONG_2_H
