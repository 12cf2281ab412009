// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD2_CITY_PIPELINE_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD2_CITY_PIPELINE_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/City_building.h>
#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/LOD2_pipeline.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/lod12_block_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/solid_defect_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/split_into_buildings_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/triangulate_non_planar_faces_3.h>

#include <CGAL/Real_timer.h>
#include <CGAL/exceptions.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <new>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// Building points and ground points of a tile, as the kernel's points (with their normals when given).
template <class Kernel>
struct Classified_points
{
  using Point_3 = typename Kernel::Point_3;
  using Vector_3 = typename Kernel::Vector_3;
  std::vector<Point_3> building, ground;
  std::vector<Vector_3> building_normals, ground_normals; // empty, or one per point
  std::vector<std::array<double, 2>> building_xy, ground_xy;
};

/// the heights at the fractions `q` (in [0, 1]) of the sorted heights of `points`
template <class PointRange>
std::vector<double> height_quantiles(const PointRange& points, std::vector<double> q)
{
  std::vector<double> z;
  for(const auto& p : points) z.push_back(CGAL::to_double(p.z()));
  if(z.empty()) return std::vector<double>(q.size(), 0);
  std::sort(z.begin(), z.end());
  for(double& f : q) f = z[std::min(z.size() - 1, std::size_t(f * double(z.size() - 1) + 0.5))];
  return q;
}

/// The part of a tile given to the LOD2 pipeline for one building: its building points and the
/// ground points in its box widened by `margin`, found through a grid of the ground points.
template <class Kernel>
class Building_parts
{
public:
  Building_parts(const Classified_points<Kernel>& tile, double margin)
    : tile_(tile), grid_{0, 0, std::max(margin, 1e-9)}, margin_(margin)
  {
    keyed_ = sorted_by_cell(tile.ground_xy, grid_);
  }

  /// indices of the ground points within `margin` of the box of the building points `members`
  std::vector<std::size_t> ground_around(const std::vector<std::size_t>& members) const
  {
    double box[4] = {1e300, 1e300, -1e300, -1e300};
    for(std::size_t i : members) {
      box[0] = std::min(box[0], tile_.building_xy[i][0]);
      box[1] = std::min(box[1], tile_.building_xy[i][1]);
      box[2] = std::max(box[2], tile_.building_xy[i][0]);
      box[3] = std::max(box[3], tile_.building_xy[i][1]);
    }
    std::vector<std::size_t> result;
    const auto low = grid_.cell(box[0] - margin_, box[1] - margin_), high = grid_.cell(box[2] + margin_, box[3] + margin_);
    for(std::int64_t x = low[0]; x <= high[0]; ++x) {
      auto it = std::lower_bound(keyed_.begin(), keyed_.end(), std::make_pair(std::array<std::int64_t, 2>{{x, low[1]}}, std::size_t(0)));
      for(; it != keyed_.end() && it->first[0] == x && it->first[1] <= high[1]; ++it) {
        const auto& p = tile_.ground_xy[it->second];
        if(p[0] >= box[0] - margin_ && p[0] <= box[2] + margin_ && p[1] >= box[1] - margin_ && p[1] <= box[3] + margin_)
          result.push_back(it->second);
      }
    }
    return result;
  }

private:
  const Classified_points<Kernel>& tile_;
  Plane_grid grid_;
  double margin_;
  std::vector<std::pair<std::array<std::int64_t, 2>, std::size_t>> keyed_;
};

/// The work of one building: its points, its footprint if given, and what the pipeline needs.
template <class Kernel>
struct Building_job
{
  std::size_t id;
  std::vector<std::size_t> members; // indices in Classified_points::building
  const Footprint_rings* footprint = nullptr;
};

/// the LOD2 pipeline on one building, its model checked (`solid_defect()`); the LoD 1.2 block of
/// its footprint (given, the LOD2 floor, or the convex hull of its points) in every case. No
/// error of the pipeline on this building leaves this function, but a lack of memory.
template <class Kernel, class Point, class NamedParameters>
City_building<Point> model_building(const Classified_points<Kernel>& tile, const Building_parts<Kernel>& parts,
                                    const Building_job<Kernel>& job, const LOD2_settings& settings,
                                    const NamedParameters& np)
{
  using Input = LOD2_input<std::vector<typename Kernel::Point_3>, CGAL::parameters::Default_named_parameters>;
  City_building<Point> result;
  result.id = job.id;
  result.points = job.members.size();
  std::vector<typename Kernel::Point_3> points, own;
  std::vector<typename Kernel::Vector_3> normals;
  for(std::size_t i : job.members) own.push_back(tile.building[i]);
  points = own;
  for(std::size_t i : job.members)
    if(!tile.building_normals.empty()) normals.push_back(tile.building_normals[i]);
  const std::vector<std::size_t> ground = parts.ground_around(job.members);
  std::vector<typename Kernel::Point_3> ground_points;
  for(std::size_t i : ground) {
    ground_points.push_back(tile.ground[i]);
    points.push_back(tile.ground[i]);
    if(!tile.ground_normals.empty()) normals.push_back(tile.ground_normals[i]);
  }
  result.ground_points = ground.size();
  const std::vector<double> heights = height_quantiles(own, {0.5, 0.7, 1.0});
  result.roof_height_50p = heights[0];
  result.roof_height_70p = heights[1];
  result.roof_height_max = heights[2];
  result.ground_height = ground.empty() ? height_quantiles(own, {0.0})[0] : height_quantiles(ground_points, {0.5})[0];
  try {
    CGAL::Real_timer total;
    total.start();
    LOD2_settings own_settings = settings;
    if(job.footprint != nullptr) own_settings.footprint = *job.footprint;
    own_settings.lift.points_refute_ground = true; // the building's own points and its ground
    Input input(std::move(points), std::move(normals), own_settings);
    Surface_mesh<Point> model;
    result.report = reconstruct_lod2_from_input(input, model, np, total);
    // faces bent by the heights merged at their corners become triangles, as val3dity wants
    // planar faces; vertices closer than the snapping tolerance are merged, as the CityJSON
    // writers merge them
    const Solid_tolerances tolerances;
    if(result.report.buildings != 1)
      result.reason = "the LOD2 pipeline made " + std::to_string(result.report.buildings) + " solids, not one";
    else if(!triangulate_non_planar_faces(model, 0.5 * tolerances.planarity))
      result.reason = "a bent face cannot be triangulated";
    else {
      snap_solid(model, tolerances.snap); // the vertices as written, slivers gone
      result.reason = solid_defect(model, tolerances);
    }
    if(result.reason.empty()) {
      result.lod22 = std::move(model);
      result.status = Building_model_status::LOD22;
      result.rms_distance = result.report.rms_distance;
    } else if(result.report.buildings == 1) {
      result.reason = "the LoD 2.2 solid is not valid: " + result.reason;
    }
  } catch(const std::bad_alloc&) {
    throw;
  } catch(const std::exception& e) {
    result.reason = e.what();
  }
  return result;
}

/// the LoD 1.2 block of a building: its footprint extruded from the ground to the 70th
/// percentile of its heights; the convex hull of its points when that block is not valid
template <class Kernel, class Point>
void add_lod12_block(const Classified_points<Kernel>& tile, const Building_job<Kernel>& job, City_building<Point>& building)
{
  const double bottom = building.ground_height;
  const double top = std::max(building.roof_height_70p, bottom + 1.0);
  std::optional<Footprint_rings> rings;
  if(job.footprint != nullptr) rings = *job.footprint;
  else if(building.status == Building_model_status::LOD22) rings = floor_rings(building.lod22);
  if(rings) {
    building.lod12 = extruded_block<Point>(*rings, bottom, top, building.id);
    if(solid_defect(building.lod12).empty()) return;
  }
  std::vector<std::array<double, 2>> own;
  for(std::size_t i : job.members) own.push_back(tile.building_xy[i]);
  building.lod12 = extruded_block<Point>(convex_hull_ring(own), bottom, top, building.id);
}

/// the id of every face of the model set to that of the building
template <class Point>
void set_building_id(Surface_mesh<Point>& mesh, std::size_t id)
{
  auto owner = optional_property_map(mesh.template property_map<typename Surface_mesh<Point>::Face_index, std::size_t>("f:building"));
  if(!owner) return;
  for(auto f : mesh.faces()) (*owner)[f] = id;
}

/// runs `f(j)` for every job, largest first, on `threads` threads (TBB) or serially
template <class Function>
void for_each_job(const std::vector<std::size_t>& order, int threads, const Function& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(threads != 1) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, order.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t k = r.begin(); k != r.end(); ++k) f(order[k]);
      });
    });
    return;
  }
#else
  CGAL_USE(threads);
#endif
  for(std::size_t j : order) f(j);
}

/// every building modelled (in parallel), its LoD 1.2 block made, the times summed in `report`
template <class Kernel, class Point, class NamedParameters>
std::vector<City_building<Point>> model_buildings(const Classified_points<Kernel>& tile,
                                                  const std::vector<Building_job<Kernel>>& jobs,
                                                  const LOD2_settings& settings, double margin, int threads,
                                                  const NamedParameters& np, LOD2_city_report& report)
{
  const Building_parts<Kernel> parts(tile, margin);
  std::vector<City_building<Point>> buildings(jobs.size());
  std::vector<double> validation(jobs.size(), 0);
  std::vector<std::size_t> order(jobs.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return jobs[a].members.size() > jobs[b].members.size(); });
  CGAL::Real_timer timer;
  timer.start();
  for_each_job(order, threads, [&](std::size_t j) {
    buildings[j] = model_building<Kernel, Point>(tile, parts, jobs[j], settings, np);
    CGAL::Real_timer checks;
    checks.start();
    add_lod12_block(tile, jobs[j], buildings[j]);
    set_building_id(buildings[j].lod22, jobs[j].id);
    validation[j] = checks.time();
  });
  report.buildings_seconds = timer.time();
  for(std::size_t j = 0; j < jobs.size(); ++j) {
    const LOD2_report& r = buildings[j].report;
    report.planes_seconds += r.planes_seconds;
    report.segments_seconds += r.segments_seconds;
    report.partition_seconds += r.partition_seconds;
    report.simplification_seconds += r.simplification_seconds;
    report.lift_seconds += r.lift_seconds;
    report.extrusion_seconds += r.extrusion_seconds;
    report.validation_seconds += validation[j];
    if(buildings[j].status == Building_model_status::LOD22) ++report.buildings_valid;
    else ++report.buildings_lod12_fallback;
  }
  report.buildings = jobs.size();
  return buildings;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD2_CITY_PIPELINE_H
