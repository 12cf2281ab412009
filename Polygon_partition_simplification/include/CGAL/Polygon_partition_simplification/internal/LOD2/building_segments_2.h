// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_SEGMENTS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_SEGMENTS_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_planes_3.h>
#include <CGAL/Polygon_partition_simplification/Building_segment_2.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/align_outlines_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/roof_outlines_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/runs_along_2.h>

#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The settings of the extraction of segments, in input units.
struct Segment_extraction_settings
{
  double maximum_distance = 0;     ///< points within this distance of an intersection line bound its segment
  double minimum_length = 0;       ///< shorter segments are dropped
  double outline_alpha = 0;        ///< radius of the alpha shapes of the roofs' points
  double outline_tolerance = 0;    ///< Douglas-Peucker tolerance of the roofs' outlines
  std::size_t minimum_contacts = 5; ///< adjacent planes share at least this many nearest-neighbour pairs
  std::size_t neighbors = 12;      ///< k of the k-nearest-neighbour graph
  double alignment_angle = 5;      ///< outlines this close to a facade's direction take it (degrees)
  double alignment_distance = 0;   ///< outlines and facades this close to one line are put on it
};

/// the points of two planes that are nearest neighbours of a point of the other, for every
/// pair of planes (a < b) with such points
template <class Kernel>
std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>>
plane_contacts(const std::vector<typename Kernel::Point_3>& points, const std::vector<int>& plane_of_point,
               std::size_t neighbors)
{
  const Point_neighbors_3<Kernel> query(points, neighbors);
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> contacts;
  std::vector<std::size_t> neighborhood;
  for(std::size_t i = 0; i < points.size(); ++i) {
    if(plane_of_point[i] < 0) continue;
    neighborhood.clear();
    query(i, neighborhood);
    for(std::size_t j : neighborhood) {
      if(plane_of_point[j] < 0 || plane_of_point[j] == plane_of_point[i]) continue;
      const std::size_t a = std::size_t(plane_of_point[i]), b = std::size_t(plane_of_point[j]);
      contacts[{std::min(a, b), std::max(a, b)}].push_back(i);
    }
  }
  for(auto& entry : contacts) {
    std::sort(entry.second.begin(), entry.second.end());
    entry.second.erase(std::unique(entry.second.begin(), entry.second.end()), entry.second.end());
  }
  return contacts;
}

/// the parameters, along `line` (of point `origin` and unit vector `direction`), of the part
/// where the points of plane `a` and those of plane `b` within `distance` of it both extend;
/// empty (first > last) when they do not overlap
template <class Kernel>
std::array<double, 2> span_of_both_planes(const std::vector<typename Kernel::Point_3>& points,
                                          const Building_planes_3<Kernel>& planes, std::size_t a, std::size_t b,
                                          const typename Kernel::Line_3& line, const typename Kernel::Point_3& origin,
                                          const typename Kernel::Vector_3& direction, double distance)
{
  std::array<double, 2> both{{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}};
  for(std::size_t plane : {a, b}) {
    double first = std::numeric_limits<double>::infinity(), last = -first;
    for(std::size_t i : planes.planes[plane].inliers) {
      if(CGAL::to_double(CGAL::squared_distance(line, points[i])) > distance * distance) continue;
      const double t = CGAL::to_double((points[i] - origin) * direction);
      first = std::min(first, t);
      last = std::max(last, t);
    }
    both[0] = std::max(both[0], first);
    both[1] = std::min(both[1], last);
  }
  return both;
}

/// the segment of the intersection line of planes `a` and `b` spanned by their contact points
/// near it, projected to the horizontal plane; false when the planes are nearly parallel or the
/// segment is too short (two facades meet on a vertical line). The intersection of two roofs
/// (a ridge, a valley) also spans the part where the points of both roofs within
/// `maximum_distance` of it extend: near a gable wall, the points of the two slopes have few
/// nearest-neighbour pairs across the ridge, and a ridge that ends short of the wall stops at
/// the corner of a roof outline, so that one slope covers the strip beyond it (up to 16 m high
/// on a gable of the 1,000-building tile).
template <class Kernel>
bool intersection_segment(const std::vector<typename Kernel::Point_3>& points, const Building_planes_3<Kernel>& planes,
                          std::size_t a, std::size_t b, const std::vector<std::size_t>& contacts,
                          const Segment_extraction_settings& settings, Building_segment_2<Kernel>& out)
{
  const auto& pa = planes.planes[a].plane;
  const auto& pb = planes.planes[b].plane;
  const auto na = pa.orthogonal_vector(), nb = pb.orthogonal_vector();
  const double sine = std::sqrt(CGAL::to_double(CGAL::cross_product(na, nb).squared_length()) /
                                (CGAL::to_double(na.squared_length()) * CGAL::to_double(nb.squared_length())));
  if(sine < std::sin(10.0 * CGAL_PI / 180.0)) return false;
  const auto result = CGAL::intersection(pa, pb);
  const auto* line = get_if<typename Kernel::Line_3>(result);
  if(line == nullptr) return false;
  const auto origin = line->point(0);
  auto direction = line->to_vector();
  direction = direction / std::sqrt(CGAL::to_double(direction.squared_length()));
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for(std::size_t i : contacts) {
    if(CGAL::to_double(CGAL::squared_distance(*line, points[i])) > 4 * settings.maximum_distance * settings.maximum_distance)
      continue;
    const double t = CGAL::to_double((points[i] - origin) * direction);
    low = std::min(low, t);
    high = std::max(high, t);
  }
  const auto is_roof = [&planes](std::size_t plane) { return plane != planes.ground && !planes.planes[plane].is_vertical; };
  if(is_roof(a) && is_roof(b)) {
    const std::array<double, 2> both = span_of_both_planes<Kernel>(points, planes, a, b, *line, origin, direction,
                                                                           settings.maximum_distance);
    low = std::min(low, both[0]);
    high = std::max(high, both[1]);
  }
  if(!(low < high)) return false;
  const auto p = origin + low * direction, q = origin + high * direction;
  out.segment = typename Kernel::Segment_2(typename Kernel::Point_2(p.x(), p.y()), typename Kernel::Point_2(q.x(), q.y()));
  if(CGAL::to_double(out.segment.squared_length()) < settings.minimum_length * settings.minimum_length) return false;
  out.is_facade = planes.planes[a].is_vertical != planes.planes[b].is_vertical;
  out.first_plane = a;
  out.second_plane = b;
  return true;
}

/// the 2D segments of a building scene (section 3.2.1): the intersections of adjacent planes
/// (a facade with a roof or the ground, two roofs), and the outlines of the roofs' points,
/// which give the walls that aerial scans hardly see; intersections of the ground with a
/// non-vertical plane are left out (their contacts are noise), and so are the parts of an
/// outline along an intersection of its plane (the intersection is where the two planes meet;
/// the outlines of both stop short of it, and would leave a strip between them). Of an outline
/// piece that runs along intersections (`runs_along()`), the parts beyond their ends stay
/// (`parts_not_along()`) when they are at least twice the shortest segment long: where a wall
/// continues past a lower roof beside it, its intersection with the higher roof ends at the
/// lower roof, and these parts carry its line to the roof's end (shorter parts, near the gable
/// walls where an intersection has few contacts, would stop a ridge short of the wall). The
/// outlines then follow the facades (`align_outlines_with_facades()`)
template <class Kernel>
std::vector<Building_segment_2<Kernel>> building_segments(const std::vector<typename Kernel::Point_3>& points,
                                                          const Building_planes_3<Kernel>& planes,
                                                          const Segment_extraction_settings& settings)
{
  std::vector<int> plane_of_point(points.size(), -1);
  for(std::size_t p = 0; p < planes.planes.size(); ++p)
    for(std::size_t i : planes.planes[p].inliers) plane_of_point[i] = int(p);
  std::vector<Building_segment_2<Kernel>> segments;
  for(const auto& entry : plane_contacts<Kernel>(points, plane_of_point, settings.neighbors)) {
    const std::size_t a = entry.first.first, b = entry.first.second;
    if(entry.second.size() < settings.minimum_contacts) continue;
    const bool with_ground = a == planes.ground || b == planes.ground;
    if(with_ground && !planes.planes[a].is_vertical && !planes.planes[b].is_vertical) continue;
    Building_segment_2<Kernel> segment;
    if(intersection_segment<Kernel>(points, planes, a, b, entry.second, settings, segment))
      segments.push_back(segment);
  }
  const std::size_t intersections = segments.size();
  for(std::size_t p = 0; p < planes.planes.size(); ++p) {
    if(p == planes.ground || planes.planes[p].is_vertical) continue;
    std::vector<typename Kernel::Segment_2> meetings; // the intersections of plane p
    for(std::size_t s = 0; s < intersections; ++s)
      if(segments[s].first_plane == p || segments[s].second_plane == p) meetings.push_back(segments[s].segment);
    for(const auto& piece : roof_outline_segments<Kernel>(points, planes.planes[p].inliers, settings.outline_alpha,
                                                          settings.outline_tolerance, settings.minimum_length)) {
      const std::array<double, 2> a{{CGAL::to_double(piece.source().x()), CGAL::to_double(piece.source().y())}};
      const std::array<double, 2> b{{CGAL::to_double(piece.target().x()), CGAL::to_double(piece.target().y())}};
      const std::vector<std::array<double, 2>> parts =
        runs_along(a, b, meetings, settings.maximum_distance)
          ? parts_not_along(a, b, meetings, settings.maximum_distance, 2 * settings.minimum_length)
          : std::vector<std::array<double, 2>>{{{0., 1.}}};
      for(const auto& part : parts) {
        Building_segment_2<Kernel> segment;
        auto at = [&](double t) {
          return typename Kernel::Point_2(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
        };
        segment.segment = part[0] == 0 && part[1] == 1 ? piece : typename Kernel::Segment_2(at(part[0]), at(part[1]));
        segment.is_facade = true;
        segment.first_plane = segment.second_plane = p;
        segments.push_back(segment);
      }
    }
  }
  align_outlines_with_facades<Kernel>(points, planes, segments, settings.alignment_angle, settings.alignment_distance);
  return segments;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_BUILDING_SEGMENTS_2_H
