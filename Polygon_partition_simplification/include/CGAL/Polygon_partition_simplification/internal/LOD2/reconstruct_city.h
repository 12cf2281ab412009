// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RECONSTRUCT_CITY_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RECONSTRUCT_CITY_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/City_building.h>
#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/LOD2_city_pipeline.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// Building points closer than this many spacings are one building (without footprints).
constexpr double city_cluster_spacings = 3;
/// The ground points within this many spacings of a building's box are given with it.
constexpr double city_ground_margin_spacings = 10;
/// A cluster of fewer building points is no building.
constexpr std::size_t city_minimum_building_points = 50;

/// the points of `range` split by their class: building, ground, or neither (left out); without
/// a classification map, every point is a building point when footprints are given (the points
/// outside them serve as ground)
template <class Kernel, class PointRange, class NamedParameters>
Classified_points<Kernel> read_classified_points(const PointRange& range, const NamedParameters& np, LOD2_city_report& report)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace pps_np = Polygon_partition_simplification::internal_np;
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  const Point_map point_map = choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map));
  const std::vector<int> ground_classes = choose_parameter(get_parameter(np, pps_np::ground_classes), std::vector<int>{2});
  const std::vector<int> building_classes = choose_parameter(get_parameter(np, pps_np::building_classes), std::vector<int>{6});
  constexpr bool has_classes = !parameters::is_default_parameter<NamedParameters, pps_np::classification_map_t>::value;
  constexpr bool has_normals = !parameters::is_default_parameter<NamedParameters, CGAL::internal_np::normal_t>::value;
  Classified_points<Kernel> tile;
  std::size_t index = 0;
  for(const auto& element : range) {
    const auto& p = get(point_map, element);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw_input_error(Input_error_code::NON_FINITE_COORDINATE, "point " + std::to_string(index) + " has a non-finite coordinate");
    ++index;
    bool building = true, ground = false;
    if constexpr(has_classes) {
      const int c = int(get(get_parameter(np, pps_np::classification_map), element));
      building = std::find(building_classes.begin(), building_classes.end(), c) != building_classes.end();
      ground = !building && std::find(ground_classes.begin(), ground_classes.end(), c) != ground_classes.end();
    }
    if(!building && !ground) continue;
    (building ? tile.building : tile.ground).push_back(typename Kernel::Point_3(x, y, z));
    (building ? tile.building_xy : tile.ground_xy).push_back({{x, y}});
    if constexpr(has_normals)
      (building ? tile.building_normals : tile.ground_normals).push_back(get(get_parameter(np, CGAL::internal_np::normal_map), element));
  }
  report.points = index;
  report.building_points = tile.building.size();
  report.ground_points = tile.ground.size();
  return tile;
}

/// the footprints as rings (outer counterclockwise, holes clockwise), checked: simple polygons
/// with an area; each with its building points (which are then removed from the others)
template <class Kernel, class FootprintRange>
std::vector<Footprint_rings> footprint_rings(const FootprintRange& footprints)
{
  std::vector<Footprint_rings> result;
  std::size_t index = 0;
  for(const auto& polygon : footprints) {
    const std::string name = "footprint " + std::to_string(index++);
    Footprint_rings rings;
    auto add = [&](const auto& ring, bool outer) {
      if(ring.size() < 3 || !ring.is_simple() || ring.orientation() == COLLINEAR)
        throw_input_error(Input_error_code::INVALID_PARAMETER, name + " has a ring that is not a simple polygon with an area");
      rings.emplace_back();
      for(auto v = ring.vertices_begin(); v != ring.vertices_end(); ++v)
        rings.back().push_back({{CGAL::to_double(v->x()), CGAL::to_double(v->y())}});
      if((ring.orientation() == COUNTERCLOCKWISE) != outer) std::reverse(rings.back().begin(), rings.back().end());
    };
    add(polygon.outer_boundary(), true);
    for(auto hole = polygon.holes_begin(); hole != polygon.holes_end(); ++hole) add(*hole, false);
    result.push_back(std::move(rings));
  }
  return result;
}

/// one job per footprint holding building points; with footprints and no classes, the points
/// outside every footprint become the ground
template <class Kernel, class FootprintRange>
std::vector<Building_job<Kernel>> footprint_jobs(Classified_points<Kernel>& tile, const FootprintRange& footprints,
                                                 const std::vector<Footprint_rings>& rings, bool classified,
                                                 LOD2_city_report& report)
{
  std::vector<std::vector<std::size_t>> inside = points_in_polygons_2(tile.building_xy, footprints);
  if(!classified) { // the building points outside the footprints are the ground
    std::vector<bool> in(tile.building.size(), false);
    for(const auto& members : inside)
      for(std::size_t i : members) in[i] = true;
    Classified_points<Kernel> split;
    std::vector<std::size_t> new_index(tile.building.size());
    for(std::size_t i = 0; i < tile.building.size(); ++i) {
      const bool b = in[i];
      new_index[i] = (b ? split.building : split.ground).size();
      (b ? split.building : split.ground).push_back(tile.building[i]);
      (b ? split.building_xy : split.ground_xy).push_back(tile.building_xy[i]);
      if(!tile.building_normals.empty()) (b ? split.building_normals : split.ground_normals).push_back(tile.building_normals[i]);
    }
    for(auto& members : inside)
      for(std::size_t& i : members) i = new_index[i];
    tile = std::move(split);
    report.building_points = tile.building.size();
    report.ground_points = tile.ground.size();
  }
  std::vector<Building_job<Kernel>> jobs;
  for(std::size_t f = 0; f < inside.size(); ++f) {
    if(inside[f].size() < city_minimum_building_points) {
      ++report.footprints_without_points;
      continue;
    }
    jobs.push_back({f, std::move(inside[f]), &rings[f]});
  }
  return jobs;
}

/// one job per cluster of building points (see `clusters_by_distance_2()`) of at least
/// `city_minimum_building_points` points
template <class Kernel>
std::vector<Building_job<Kernel>> cluster_jobs(const Classified_points<Kernel>& tile, const Bbox_2& box, LOD2_city_report& report)
{
  std::vector<Building_job<Kernel>> jobs;
  for(auto& members : clusters_by_distance_2(tile.building_xy, box, report.cluster_distance)) {
    if(members.size() < city_minimum_building_points) {
      ++report.clusters_too_small;
      continue;
    }
    jobs.push_back({jobs.size(), std::move(members), nullptr});
  }
  return jobs;
}

/// the jobs kept by the named parameter `building_filter` (every job without it), which is
/// called once with the ids and the numbers of building points of all the jobs, by increasing id
template <class Kernel, class NamedParameters>
void filter_jobs(std::vector<Building_job<Kernel>>& jobs, const NamedParameters& np)
{
  namespace pps_np = Polygon_partition_simplification::internal_np;
  if constexpr(!parameters::is_default_parameter<NamedParameters, pps_np::building_filter_t>::value) {
    std::vector<std::size_t> ids, points;
    for(const Building_job<Kernel>& job : jobs) {
      ids.push_back(job.id);
      points.push_back(job.members.size());
    }
    const std::vector<bool> keep = parameters::get_parameter(np, pps_np::building_filter)(ids, points);
    if(keep.size() != jobs.size())
      throw_input_error(Input_error_code::INVALID_PARAMETER,
                        "building_filter returned " + std::to_string(keep.size()) + " values for " +
                          std::to_string(jobs.size()) + " buildings: it must return one per building");
    std::vector<Building_job<Kernel>> kept;
    for(std::size_t j = 0; j < jobs.size(); ++j)
      if(keep[j]) kept.push_back(std::move(jobs[j]));
    jobs = std::move(kept);
  } else {
    CGAL_USE(jobs);
    CGAL_USE(np);
  }
}

template <class PointRange, class Point, class NamedParameters>
LOD2_city_report reconstruct_city(const PointRange& range, std::vector<City_building<Point>>& buildings,
                                  const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace pps_np = Polygon_partition_simplification::internal_np;
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Kernel = typename CGAL::Kernel_traits<typename boost::property_traits<Point_map>::value_type>::Kernel;
  constexpr bool has_classes = !parameters::is_default_parameter<NamedParameters, pps_np::classification_map_t>::value;
  constexpr bool has_footprints = !parameters::is_default_parameter<NamedParameters, pps_np::footprints_t>::value;
  static_assert(has_classes || has_footprints,
                "lod2_city_reconstruction() needs a classification_map, footprints, or both");
  CGAL::Real_timer total;
  total.start();
  const LOD2_settings settings = lod2_settings(np);
  const int threads = choose_parameter(get_parameter(np, pps_np::number_of_threads), 0);
  if(threads < 0) throw_input_error(Input_error_code::INVALID_PARAMETER, "number_of_threads must be >= 0 (0: all cores)");
  LOD2_city_report report;
  Classified_points<Kernel> tile = read_classified_points<Kernel>(range, np, report);
  if(tile.building.empty())
    throw_input_error(Input_error_code::NO_BUILDING, has_classes ? "no point of a building class" : "no point");
  Bbox_2 box;
  for(const auto& p : tile.building_xy) box += Bbox_2(p[0], p[1], p[0], p[1]);
  report.spacing = spacing_from_density(tile.building_xy, box);
  if(!(report.spacing > 0))
    throw_input_error(Input_error_code::NO_HORIZONTAL_EXTENT, "the building points have no extent in x or in y");
  report.cluster_distance = city_cluster_spacings * report.spacing;
  std::vector<Footprint_rings> rings;
  std::vector<Building_job<Kernel>> jobs;
  if constexpr(has_footprints) {
    const auto& footprints = get_parameter(np, pps_np::footprints);
    rings = footprint_rings<Kernel>(footprints);
    jobs = footprint_jobs(tile, footprints, rings, has_classes, report);
  } else {
    jobs = cluster_jobs(tile, box, report);
  }
  if(jobs.empty())
    throw_input_error(Input_error_code::NO_BUILDING, "no building: no cluster of building points" +
                                                    std::string(has_footprints ? " in a footprint" : "") + " has " +
                                                    std::to_string(city_minimum_building_points) + " points");
  filter_jobs(jobs, np);
  report.split_seconds = total.time();
  buildings = model_buildings<Kernel, Point>(tile, jobs, settings, city_ground_margin_spacings * report.spacing,
                                             threads, np, report);
  report.seconds = total.time();
  return report;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_RECONSTRUCT_CITY_H
