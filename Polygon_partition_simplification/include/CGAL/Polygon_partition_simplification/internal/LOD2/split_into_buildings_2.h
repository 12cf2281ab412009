// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_SPLIT_INTO_BUILDINGS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_SPLIT_INTO_BUILDINGS_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/internal/Union_find.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// A square grid over the plane: the cell of a point is (floor((x - x0) / size), floor((y - y0) / size)).
struct Plane_grid
{
  double x0 = 0, y0 = 0, size = 1;

  std::array<std::int64_t, 2> cell(double x, double y) const
  {
    return {{std::int64_t(std::floor((x - x0) / size)), std::int64_t(std::floor((y - y0) / size))}};
  }
};

/// the indices 0..n-1 sorted by the grid cell of their point (then by index), and the cell of each
template <class PointRange>
std::vector<std::pair<std::array<std::int64_t, 2>, std::size_t>> sorted_by_cell(const PointRange& points,
                                                                                const Plane_grid& grid)
{
  std::vector<std::pair<std::array<std::int64_t, 2>, std::size_t>> keyed(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) keyed[i] = {grid.cell(points[i][0], points[i][1]), i};
  std::sort(keyed.begin(), keyed.end());
  return keyed;
}

/// The average spacing of points of an aerial scan from their density, in linear time: with cells
/// of side c holding m points at the median over the occupied cells, the spacing is c / sqrt(m).
/// Cells of 4 times sqrt(area / n) over the bounding box (about 16 points each if the points
/// filled it) hold enough points for the median to be stable, and the occupied cells only count,
/// so the empty space between buildings does not thin the estimate.
template <class PointRange>
double spacing_from_density(const PointRange& points, const Bbox_2& box)
{
  const double n = double(points.size());
  const double extent = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  double area = (box.xmax() - box.xmin()) * (box.ymax() - box.ymin());
  if(!(area > 0)) area = extent * extent / n; // the points on a line
  if(!(area > 0) || points.size() < 2) return 0;
  const Plane_grid grid{box.xmin(), box.ymin(), 4 * std::sqrt(area / n)};
  const auto keyed = sorted_by_cell(points, grid);
  std::vector<std::size_t> counts;
  for(std::size_t i = 0, j = 0; i < keyed.size(); i = j) {
    for(j = i; j < keyed.size() && keyed[j].first == keyed[i].first; ++j) {}
    counts.push_back(j - i);
  }
  std::nth_element(counts.begin(), counts.begin() + counts.size() / 2, counts.end());
  return grid.size / std::sqrt(double(counts[counts.size() / 2]));
}

/// The points split into clusters by 2D connectivity: two points are in one cluster when a chain
/// of grid cells of side `distance`, each holding a point and touching the next by a side or a
/// corner, joins their cells (so points closer than `distance` are always joined, and points
/// farther than 2 sqrt(2) `distance` never directly). The clusters come in the order of their
/// lowest cell, each with its point indices increasing: the result depends on the coordinates
/// only (the grid starts at the corner of the bounding box), not on the order of the points.
template <class PointRange>
std::vector<std::vector<std::size_t>> clusters_by_distance_2(const PointRange& points, const Bbox_2& box,
                                                             double distance)
{
  const Plane_grid grid{box.xmin(), box.ymin(), distance};
  const auto keyed = sorted_by_cell(points, grid);
  std::vector<std::array<std::int64_t, 2>> cells;   // occupied cells, increasing
  std::vector<std::size_t> cell_of_point(points.size());
  for(const auto& [cell, i] : keyed) {
    if(cells.empty() || cells.back() != cell) cells.push_back(cell);
    cell_of_point[i] = cells.size() - 1;
  }
  Union_find sets(cells.size());
  for(std::size_t c = 0; c < cells.size(); ++c)
    for(std::int64_t dx = 0; dx <= 1; ++dx)
      for(std::int64_t dy = -1; dy <= 1; ++dy) {
        if(dx == 0 && dy <= 0) continue; // each pair of neighbours once
        const std::array<std::int64_t, 2> neighbour{{cells[c][0] + dx, cells[c][1] + dy}};
        const auto found = std::lower_bound(cells.begin(), cells.end(), neighbour);
        if(found != cells.end() && *found == neighbour) sets.unite(c, std::size_t(found - cells.begin()));
      }
  // clusters numbered by their lowest cell: the cells are visited in increasing order
  std::vector<std::size_t> cluster_of_root(cells.size(), std::size_t(-1));
  std::vector<std::vector<std::size_t>> clusters;
  for(std::size_t c = 0; c < cells.size(); ++c) {
    std::size_t& cluster = cluster_of_root[sets.find(c)];
    if(cluster == std::size_t(-1)) {
      cluster = clusters.size();
      clusters.emplace_back();
    }
  }
  for(std::size_t i = 0; i < points.size(); ++i) clusters[cluster_of_root[sets.find(cell_of_point[i])]].push_back(i);
  return clusters;
}

/// The indices of the points in each polygon with holes (a point on a boundary is inside; a
/// point in several polygons goes to the first), found through a grid over the polygons' boxes.
template <class PointRange, class PolygonWithHolesRange>
std::vector<std::vector<std::size_t>> points_in_polygons_2(const PointRange& points, const PolygonWithHolesRange& polygons)
{
  std::vector<std::vector<std::size_t>> inside(polygons.size());
  std::vector<std::pair<Bbox_2, std::size_t>> boxes;
  for(std::size_t f = 0; f < polygons.size(); ++f) boxes.push_back({polygons[f].outer_boundary().bbox(), f});
  // the boxes sorted by xmin; a point is tested against those with xmin <= x, from the first
  std::sort(boxes.begin(), boxes.end(), [](const auto& a, const auto& b) {
    return a.first.xmin() < b.first.xmin() || (a.first.xmin() == b.first.xmin() && a.second < b.second);
  });
  auto contains = [](const auto& polygon, const auto& p) {
    const auto& outer = polygon.outer_boundary();
    if(CGAL::bounded_side_2(outer.vertices_begin(), outer.vertices_end(), p) == ON_UNBOUNDED_SIDE) return false;
    for(auto hole = polygon.holes_begin(); hole != polygon.holes_end(); ++hole)
      if(CGAL::bounded_side_2(hole->vertices_begin(), hole->vertices_end(), p) == ON_BOUNDED_SIDE) return false;
    return true;
  };
  using Point_2 = typename std::decay_t<decltype(polygons[0].outer_boundary())>::Point_2;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i][0], y = points[i][1];
    const Point_2 p(x, y);
    std::size_t owner = polygons.size();
    for(const auto& [box, f] : boxes) {
      if(box.xmin() > x) break;
      if(f < owner && x <= box.xmax() && y >= box.ymin() && y <= box.ymax() && contains(polygons[f], p)) owner = f;
    }
    if(owner < polygons.size()) inside[owner].push_back(i);
  }
  return inside;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_SPLIT_INTO_BUILDINGS_2_H
