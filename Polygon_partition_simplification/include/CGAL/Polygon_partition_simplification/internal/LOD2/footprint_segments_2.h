// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FOOTPRINT_SEGMENTS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FOOTPRINT_SEGMENTS_2_H

// A given footprint in the segments of a building: its edges are facade segments, and they
// replace the roof outline pieces that stand for the same walls. An outline piece is drawn
// where the points of a roof plane end; along a footprint edge it is the same wall seen with
// the point spacing's error, and near a footprint corner a short piece cuts the corner off.
// Kept, such a piece makes thin cells between itself and the footprint edge, and a wedge cell
// that the lift can give to the wrong roof plane or to the ground.

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_segment_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/runs_along_2.h>

#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

using Footprint_rings = std::vector<std::vector<std::array<double, 2>>>;

/// Adds the edges of `footprint` to `segments` as facades, after removing the roof outline pieces
/// (facade segments of a single roof plane) that run along a footprint edge within `distance`,
/// or that are shorter than 2 `distance` with an end within `distance` of the footprint's
/// boundary. The segments between planes (ridges, eaves on wall planes) stay.
template <class Kernel>
void replace_outlines_by_footprint(const Footprint_rings& footprint, double distance,
                                   std::vector<Building_segment_2<Kernel>>& segments)
{
  if(footprint.empty()) return;
  std::vector<typename Kernel::Segment_2> edges;
  for(const auto& ring : footprint)
    for(std::size_t i = 0; i < ring.size(); ++i) {
      const auto& p = ring[i];
      const auto& q = ring[(i + 1) % ring.size()];
      edges.emplace_back(typename Kernel::Point_2(p[0], p[1]), typename Kernel::Point_2(q[0], q[1]));
    }
  auto near_boundary = [&](const typename Kernel::Point_2& p) {
    return std::any_of(edges.begin(), edges.end(), [&](const typename Kernel::Segment_2& e) {
      return CGAL::to_double(CGAL::squared_distance(p, e)) <= distance * distance;
    });
  };
  auto replaced = [&](const Building_segment_2<Kernel>& s) {
    if(!s.is_facade || s.first_plane != s.second_plane) return false;
    const std::array<double, 2> a{{CGAL::to_double(s.segment.source().x()), CGAL::to_double(s.segment.source().y())}};
    const std::array<double, 2> b{{CGAL::to_double(s.segment.target().x()), CGAL::to_double(s.segment.target().y())}};
    if(runs_along(a, b, edges, distance)) return true;
    return CGAL::to_double(s.segment.squared_length()) < 4 * distance * distance &&
           (near_boundary(s.segment.source()) || near_boundary(s.segment.target()));
  };
  segments.erase(std::remove_if(segments.begin(), segments.end(), replaced), segments.end());
  for(const auto& e : edges) {
    Building_segment_2<Kernel> s;
    s.segment = e;
    s.is_facade = true;
    segments.push_back(s);
  }
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_FOOTPRINT_SEGMENTS_2_H
