// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RUNS_ALONG_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RUNS_ALONG_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// a segment in double coordinates: its ends, its vector and the squared length of it
struct Double_segment_2
{
  std::array<double, 2> source, target;
  double ex, ey, squared;

  /// the squared distance from (px, py) to the segment
  double squared_distance(double px, double py) const
  {
    const double u = std::clamp(((px - source[0]) * ex + (py - source[1]) * ey) / squared, 0.0, 1.0);
    const double gx = source[0] + u * ex - px, gy = source[1] + u * ey - py;
    return gx * gx + gy * gy;
  }
};

/// `s` in double coordinates, if it has a length and is at less than 15 degrees from the
/// direction (dx, dy), of length `length`
template <class Segment2>
std::optional<Double_segment_2> nearly_parallel_segment(const Segment2& s, double dx, double dy, double length)
{
  Double_segment_2 d;
  d.source = {{CGAL::to_double(s.source().x()), CGAL::to_double(s.source().y())}};
  d.target = {{CGAL::to_double(s.target().x()), CGAL::to_double(s.target().y())}};
  d.ex = d.target[0] - d.source[0];
  d.ey = d.target[1] - d.source[1];
  d.squared = d.ex * d.ex + d.ey * d.ey;
  if(d.squared == 0 || std::abs(d.ex * dy - d.ey * dx) > std::sin(15 * CGAL_PI / 180) * std::sqrt(d.squared) * length)
    return std::nullopt;
  return d;
}

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
      const std::optional<Double_segment_2> d = nearly_parallel_segment(s, dx, dy, length);
      if(d && d->squared_distance(px, py) <= distance * distance) {
        ++near;
        break;
      }
    }
  }
  return near >= 2;
}

/// the parts of the segment (a, b), as parameter intervals [t0, t1] of a + t (b - a), that do
/// not run along `segments`: a segment at less than 15 degrees from it covers the part of (a,
/// b) over its own extent (widened by `distance` at both ends) if the middle of that part is
/// within `distance` of it; parts shorter than `minimum_length` are left out
template <class Segment2Range>
std::vector<std::array<double, 2>> parts_not_along(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                                   const Segment2Range& segments, double distance,
                                                   double minimum_length)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length = std::sqrt(dx * dx + dy * dy);
  std::vector<std::array<double, 2>> covered;
  if(length == 0) return covered;
  for(const auto& s : segments) {
    const std::optional<Double_segment_2> d = nearly_parallel_segment(s, dx, dy, length);
    if(!d) continue;
    auto along = [&](const std::array<double, 2>& r) { return ((r[0] - a[0]) * dx + (r[1] - a[1]) * dy) / (length * length); };
    const double from_source = along(d->source), from_target = along(d->target);
    const double widen = distance / length;
    const double t0 = std::max(0.0, std::min(from_source, from_target) - widen);
    const double t1 = std::min(1.0, std::max(from_source, from_target) + widen);
    if(!(t0 < t1)) continue;
    const double t = 0.5 * (t0 + t1);
    if(d->squared_distance(a[0] + t * dx, a[1] + t * dy) <= distance * distance) covered.push_back({{t0, t1}});
  }
  std::sort(covered.begin(), covered.end());
  std::vector<std::array<double, 2>> parts;
  double from = 0;
  auto keep = [&](double t0, double t1) {
    if((t1 - t0) * length >= minimum_length) parts.push_back({{t0, t1}});
  };
  for(const auto& interval : covered) {
    if(interval[0] > from) keep(from, interval[0]);
    from = std::max(from, interval[1]);
  }
  if(from < 1) keep(from, 1);
  return parts;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RUNS_ALONG_2_H
