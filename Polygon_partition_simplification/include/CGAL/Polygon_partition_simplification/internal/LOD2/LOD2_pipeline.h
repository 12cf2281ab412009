// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD2_PIPELINE_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD2_PIPELINE_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/LOD2_report.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/Building_extrusion_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/Cell_arrangement_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/Height_functions.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/building_meshes_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/building_segments_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/close_outline_corners_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/detect_building_planes_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/facade_evidence_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/footprint_segments_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/label_cells_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/triangulate_rings_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The settings of all the stages; lengths left at 0 are set from the average spacing.
struct LOD2_settings
{
  Plane_detection_settings planes;
  Lift_settings lift;
  double height_tolerance = 0;
  /// a footprint (outer ring counterclockwise, holes clockwise), empty for none: its edges are
  /// facade segments of the partition (they replace the roof outline pieces along them, see
  /// footprint_segments_2.h); the cells inside it are roofs, those outside it ground
  std::vector<std::vector<std::array<double, 2>>> footprint;

  Segment_extraction_settings segments_for(double spacing, double maximum_distance) const
  {
    Segment_extraction_settings s;
    s.maximum_distance = maximum_distance;
    s.minimum_length = 4 * spacing;
    s.outline_alpha = 2.5 * spacing;
    s.outline_tolerance = 2 * spacing;
    s.alignment_angle = planes.regularization_angle;
    s.alignment_distance = 2 * spacing;
    return s;
  }

  template <class Kernel>
  Segment_extraction_settings segments_for(const Building_planes_3<Kernel>& planes) const
  {
    return segments_for(planes.spacing, planes_distance(planes.spacing));
  }

  double planes_distance(double spacing) const { return planes.maximum_distance > 0 ? planes.maximum_distance : 3 * spacing; }
};

[[noreturn]] inline void throw_input_error(Input_error_code code, const std::string& message)
{
  throw Input_error(code, message);
}

/// the settings of the LOD2 pipeline read from the named parameters, checked
template <class NamedParameters>
LOD2_settings lod2_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace pps_np = Polygon_partition_simplification::internal_np;
  LOD2_settings settings;
  settings.planes.maximum_distance = choose_parameter(get_parameter(np, pps_np::maximum_distance), 0.);
  settings.planes.maximum_angle = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_normal_deviation), 20.);
  settings.planes.minimum_region_size = choose_parameter(get_parameter(np, pps_np::minimum_region_size), std::size_t(0));
  settings.lift.height_threshold = choose_parameter(get_parameter(np, pps_np::height_threshold), 0.);
  settings.lift.regularization_length = choose_parameter(get_parameter(np, pps_np::regularization_length), 0.);
  settings.lift.facade_weight = choose_parameter(get_parameter(np, pps_np::facade_weight), 0.25);
  settings.lift.minimum_building_height = choose_parameter(get_parameter(np, pps_np::minimum_building_height), 0.);
  settings.height_tolerance = choose_parameter(get_parameter(np, pps_np::height_tolerance), 0.);
  if(!choose_parameter(get_parameter(np, pps_np::walls_at_facades), true)) settings.lift.facade_samples = 0;
  const LOD2_settings& s = settings;
  auto check = [](bool ok, const char* message) {
    if(!ok) throw_input_error(Input_error_code::INVALID_PARAMETER, message);
  };
  check(s.planes.maximum_distance >= 0 && std::isfinite(s.planes.maximum_distance), "maximum_distance must be >= 0");
  check(s.planes.maximum_angle > 0 && s.planes.maximum_angle < 90, "maximum_normal_deviation must be in (0, 90) degrees");
  check(s.lift.height_threshold >= 0 && std::isfinite(s.lift.height_threshold), "height_threshold must be >= 0");
  check(s.lift.regularization_length >= 0 && std::isfinite(s.lift.regularization_length),
        "regularization_length must be >= 0");
  check(s.lift.facade_weight >= 0 && s.lift.facade_weight <= 1, "facade_weight must be in [0, 1]");
  check(s.lift.minimum_building_height >= 0 && std::isfinite(s.lift.minimum_building_height),
        "minimum_building_height must be >= 0");
  check(s.height_tolerance >= 0 && std::isfinite(s.height_tolerance), "height_tolerance must be >= 0");
  return settings;
}

/// The input points as the kernel's points, their normals and plane indices if given, and the
/// settings read from the named parameters.
template <class PointRange, class NamedParameters>
struct LOD2_input
{
  using Point_map = typename GetPointMap<PointRange, NamedParameters>::const_type;
  using Input_point = typename boost::property_traits<Point_map>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Input_point>::Kernel;
  using Point_3 = typename Kernel::Point_3;

  std::vector<Point_3> points;
  std::vector<typename Kernel::Vector_3> normals;
  std::vector<int> plane_index;
  LOD2_settings settings;

  /// the points of a part of a scene (a building and the ground around it), with the settings
  /// of the whole scene; `normals` is empty or has one normal per point
  LOD2_input(std::vector<Point_3> part, std::vector<typename Kernel::Vector_3> part_normals, const LOD2_settings& part_settings)
    : points(std::move(part)), normals(std::move(part_normals)), settings(part_settings)
  {
    if(points.size() < 3) throw_input_error(Input_error_code::EMPTY_INPUT, "fewer than 3 points");
    sort_points();
  }

  LOD2_input(const PointRange& range, const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const Point_map point_map = choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map));
    for(const auto& element : range) {
      const Input_point& p = get(point_map, element);
      if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
         !std::isfinite(CGAL::to_double(p.z())))
        throw_input_error(Input_error_code::NON_FINITE_COORDINATE,
                          "point " + std::to_string(points.size()) + " has a non-finite coordinate");
      points.push_back(p);
    }
    if(points.size() < 3) throw_input_error(Input_error_code::EMPTY_INPUT, "fewer than 3 points");
    read_optional_maps(range, np);
    sort_points();
    settings = lod2_settings(np);
  }

private:
  // the points in lexicographic order (with their normals and plane indices), so that the
  // result does not depend on the order of the input: the plane fits and the region growing
  // visit the points in this order
  void sort_points()
  {
    std::vector<std::size_t> order(points.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    auto key = [this](std::size_t i) {
      std::array<double, 7> k{{CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()),
                               CGAL::to_double(points[i].z()), 0, 0, 0, plane_index.empty() ? 0. : double(plane_index[i])}};
      if(!normals.empty())
        for(int c = 0; c < 3; ++c) k[3 + c] = CGAL::to_double(normals[i][c]);
      return k;
    };
    std::sort(order.begin(), order.end(), [&key](std::size_t a, std::size_t b) { return key(a) < key(b); });
    auto permute = [&order](auto& values) {
      if(values.empty()) return;
      auto copy = values;
      for(std::size_t i = 0; i < order.size(); ++i) values[i] = copy[order[i]];
    };
    permute(points);
    permute(normals);
    permute(plane_index);
  }

  template <class NP>
  void read_optional_maps(const PointRange& range, const NP& np)
  {
    using parameters::get_parameter;
    if constexpr(!parameters::is_default_parameter<NP, CGAL::internal_np::normal_t>::value) {
      const auto normal_map = get_parameter(np, CGAL::internal_np::normal_map);
      for(const auto& element : range) normals.push_back(get(normal_map, element));
    }
    if constexpr(!parameters::is_default_parameter<NP, CGAL::internal_np::plane_index_t>::value) {
      const auto index_map = get_parameter(np, CGAL::internal_np::plane_index_map);
      for(const auto& element : range) plane_index.push_back(int(get(index_map, element)));
    }
  }
};

/// the lengths left at 0 set from the average spacing of the points
inline void complete_settings(LOD2_settings& s, double spacing)
{
  if(s.lift.height_threshold == 0) s.lift.height_threshold = 5 * spacing;
  if(s.lift.regularization_length == 0) s.lift.regularization_length = 2 * spacing;
  if(s.lift.minimum_building_height == 0) s.lift.minimum_building_height = 10 * spacing;
  if(s.height_tolerance == 0) s.height_tolerance = std::min(spacing, 0.5 * s.lift.minimum_building_height);
  s.lift.facade_distance = s.planes_distance(spacing);
  if(s.height_tolerance > 0.5 * s.lift.minimum_building_height)
    throw_input_error(Input_error_code::INVALID_PARAMETER, "height_tolerance must be at most half of minimum_building_height");
}

/// the RMS and largest distances to the model of the points on the planes other than the
/// ground (the points of no plane are clutter: vegetation, cars, noise)
template <class Kernel, class Point>
void measure_distances(const std::vector<typename Kernel::Point_3>& points, const Building_planes_3<Kernel>& planes,
                       const CGAL::Surface_mesh<Point>& model, LOD2_report& report)
{
  using Mesh = CGAL::Surface_mesh<Point>;
  if(model.is_empty()) return;
  Mesh triangles = model;
  CGAL::Polygon_mesh_processing::triangulate_faces(triangles);
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<AABB_traits_3<typename CGAL::Kernel_traits<Point>::Kernel, Primitive>>;
  Tree tree(faces(triangles).first, faces(triangles).second, triangles);
  tree.accelerate_distance_queries();
  std::vector<bool> measured(points.size(), false);
  for(std::size_t p = 0; p < planes.planes.size(); ++p)
    if(p != planes.ground)
      for(std::size_t i : planes.planes[p].inliers) measured[i] = true;
  double sum = 0;
  for(std::size_t i = 0; i < points.size(); ++i) {
    if(!measured[i]) continue;
    const Point p(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z()));
    const double squared = CGAL::to_double(tree.squared_distance(p));
    sum += squared;
    report.maximum_distance = std::max(report.maximum_distance, std::sqrt(squared));
    ++report.measured_points;
  }
  if(report.measured_points > 0) report.rms_distance = std::sqrt(sum / double(report.measured_points));
}

/// true when (x, y) is inside the footprint (inside its outer ring and outside its holes)
inline bool is_inside_footprint(const std::vector<std::vector<std::array<double, 2>>>& footprint, double x, double y)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  for(std::size_t r = 0; r < footprint.size(); ++r) {
    std::vector<K::Point_2> ring;
    for(const auto& p : footprint[r]) ring.emplace_back(p[0], p[1]);
    const bool in = CGAL::bounded_side_2(ring.begin(), ring.end(), K::Point_2(x, y)) != CGAL::ON_UNBOUNDED_SIDE;
    if(in != (r == 0)) return false;
  }
  return true;
}

/// The labels a footprint allows: the cells outside it are ground, the cells inside it are roofs
/// (as 3DBAG's models fill their footprints: a thin cell between an outline that cuts a corner
/// and the footprint's corner is not left out). A cell is inside when the centroid of its largest
/// triangle is: the simplification may move the footprint's lines a little, so a cell is judged
/// by its bulk.
inline void confine_to_footprint(const Cell_arrangement_2& cells,
                                 const std::vector<std::vector<std::array<double, 2>>>& footprint,
                                 std::vector<std::vector<double>>& cost)
{
  for(std::size_t c = 0; c < cells.number_of_cells(); ++c) {
    std::vector<std::vector<Ring_corner>> rings;
    std::vector<std::array<double, 2>> corners;
    for(const auto& ring : cells.rings[c]) {
      rings.emplace_back();
      for(const auto& p : ring) {
        rings.back().push_back({corners.size(), p.x(), p.y()});
        corners.push_back({{p.x(), p.y()}});
      }
    }
    double largest = -1, x = 0, y = 0;
    for(const auto& t : triangulate_rings(rings)) {
      const auto &a = corners[t[0]], &b = corners[t[1]], &d = corners[t[2]];
      const double area = std::abs((b[0] - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (b[1] - a[1]));
      if(area > largest) {
        largest = area;
        x = (a[0] + b[0] + d[0]) / 3;
        y = (a[1] + b[1] + d[1]) / 3;
      }
    }
    if(largest < 0) continue;
    const bool inside = is_inside_footprint(footprint, x, y);
    for(std::size_t l = 0; l < cost[c].size(); ++l)
      if((l == Height_functions::ground_label) == inside) cost[c][l] = std::numeric_limits<double>::infinity();
  }
}

/// the labeled cells extruded into `mesh`
template <class Kernel, class PolygonWithHolesRange, class Point>
void lift_and_extrude(const std::vector<typename Kernel::Point_3>& points, const Building_planes_3<Kernel>& planes,
                      const std::vector<Building_segment_2<Kernel>>& segments, const PolygonWithHolesRange& cells,
                      const LOD2_settings& settings, CGAL::Surface_mesh<Point>& mesh, LOD2_report& report)
{
  CGAL::Real_timer timer;
  timer.start();
  const Cell_arrangement_2 arrangement(cells);
  std::vector<bool> on_facade(points.size(), false);
  for(const auto& plane : planes.planes)
    if(plane.is_vertical)
      for(std::size_t i : plane.inliers) on_facade[i] = true;
  Lift_evidence evidence;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!on_facade[i])
      evidence.points.push_back(
        {{CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z())}});
  evidence.cell_of_point = arrangement.locate(evidence.points);
  // squares of half the planes' distance: the ground of a yard a few metres wide is open above
  evidence.open_above = open_above(evidence.points, 0.5 * settings.lift.facade_distance, settings.lift.height_threshold);
  if(settings.lift.facade_samples > 0) {
    evidence.facades = facade_evidence<Kernel>(points, planes, settings.lift.facade_distance, settings.lift.facade_samples);
    evidence.cell_in_front = arrangement.locate(evidence.facades.in_front);
    evidence.cell_behind = arrangement.locate(evidence.facades.behind);
  }
  std::vector<typename Kernel::Segment_2> facades;
  for(const auto& s : segments)
    if(s.is_facade) facades.push_back(s.segment);
  const Height_functions heights(planes);
  const std::vector<Lift_edge> edges = lift_edges(arrangement, facades, settings.lift);
  std::vector<std::vector<double>> cost = lift_data_term(arrangement, evidence, heights, settings.lift);
  if(!settings.footprint.empty()) confine_to_footprint(arrangement, settings.footprint, cost);
  const std::vector<std::size_t> labels = label_cells(arrangement, edges, std::move(cost), heights);
  report.lift_seconds = timer.time();
  timer.reset();
  Building_extrusion_3 extrusion(arrangement, labels, heights, settings.height_tolerance);
  std::vector<Building_soup> soups = extrusion.take_buildings();
  CGAL::Surface_mesh<Point> model;
  add_buildings_to_mesh(soups, heights, model, report);
  measure_distances(points, planes, model, report);
  mesh = std::move(model);
  report.extrusion_seconds = timer.time();
}

/// the segments without repetition (in either orientation) and without zero-length ones, in
/// the order of their first occurrence
template <class Kernel>
std::vector<typename Kernel::Segment_2> distinct_segments(const std::vector<Building_segment_2<Kernel>>& segments)
{
  std::set<std::pair<typename Kernel::Point_2, typename Kernel::Point_2>> seen;
  std::vector<typename Kernel::Segment_2> result;
  for(const auto& s : segments) {
    const auto& p = s.segment.source();
    const auto& q = s.segment.target();
    if(p == q || !seen.insert({std::min(p, q), std::max(p, q)}).second) continue;
    result.push_back(s.segment);
  }
  return result;
}

/// the kinetic partition of the segments, computed once; unless the user sets
/// `collinearity_distance`, the segments within twice the spacing of the line of a longer one
/// are moved onto it, so that the outlines of two roofs that meet at a step (without an
/// intersection line between them) share their edge instead of leaving a strip of ground between
/// them. A partition that `defect()` refuses (none over the stress scenes of the manual) is a
/// defect of the package: it throws `std::logic_error` rather than model on it.
template <class Segment_2, class NamedParameters>
auto kinetic_partition_of_segments(const std::vector<Segment_2>& segments, double spacing, const NamedParameters& np)
{
  auto partition = [&] {
    if constexpr(parameters::is_default_parameter<NamedParameters, internal_np::collinearity_distance_t>::value)
      return CGAL::kinetic_partition_2(segments, parameters::collinearity_distance(2 * spacing, np));
    else
      return CGAL::kinetic_partition_2(segments, np);
  }();
  const std::string defect = partition.defect();
  if(!defect.empty())
    throw std::logic_error("the kinetic partition of the " + std::to_string(segments.size()) +
                           " segments is not valid (" + defect + "): please report it with the input");
  return partition;
}

/// the LOD2 model of the points of `input` (sorted, settings read), whose time starts at `total`;
/// `np` gives the parameters of the kinetic partition and of the simplification
template <class Input, class Point, class NamedParameters>
LOD2_report reconstruct_lod2_from_input(Input& input, CGAL::Surface_mesh<Point>& mesh, const NamedParameters& np,
                                        const CGAL::Real_timer& total)
{
  using Kernel = typename Input::Kernel;
  CGAL::Real_timer timer;
  timer.start();
  LOD2_report report;
  report.points = input.points.size();
  const Bbox_3 box = CGAL::bbox_3(input.points.begin(), input.points.end());
  if(!(box.xmax() > box.xmin()) || !(box.ymax() > box.ymin()))
    throw_input_error(Input_error_code::NO_HORIZONTAL_EXTENT, "the points have no extent in x or in y");
  const Building_planes_3<Kernel> planes =
    detect_building_planes<Kernel>(input.points, input.normals, input.plane_index, input.settings.planes);
  report.planes = planes.planes.size();
  for(std::size_t p = 0; p < planes.planes.size(); ++p)
    if(p != planes.ground && !planes.planes[p].is_vertical) ++report.roof_planes;
  if(report.roof_planes == 0)
    throw_input_error(Input_error_code::NO_PLANE, "no roof plane found among " + std::to_string(report.planes) +
                                                    " planes: too few points, or maximum_distance too small for the noise");
  complete_settings(input.settings, planes.spacing);
  report.planes_seconds = timer.time();
  timer.reset();
  auto segments = building_segments<Kernel>(input.points, planes, input.settings.segments_for(planes));
  replace_outlines_by_footprint(input.settings.footprint, input.settings.lift.facade_distance, segments);
  extend_ridges_to_footprint(input.settings.footprint, segments);
  if(input.settings.footprint.empty()) {
    std::vector<bool> is_vertical;
    for(const auto& plane : planes.planes) is_vertical.push_back(plane.is_vertical);
    remove_corner_chords(segments, is_vertical, 2 * planes.spacing, 10 * planes.spacing);
    close_outline_corners(segments, 2 * planes.spacing, 10 * planes.spacing);
  }
  const std::vector<typename Kernel::Segment_2> segments_2 = distinct_segments(segments);
  for(const auto& s : segments) report.facade_segments += s.is_facade ? 1 : 0;
  report.segments = segments_2.size();
  if(segments_2.empty()) throw_input_error(Input_error_code::NO_PLANE, "no segment found between or around the planes");
  report.segments_seconds = timer.time();
  timer.reset();
  auto partition = kinetic_partition_of_segments(segments_2, planes.spacing, np);
  report.cells_before = partition.number_of_cells();
  report.partition_seconds = timer.time();
  timer.reset();
  CGAL::simplify_polygon_partition_2(partition, np);
  std::vector<typename decltype(partition)::Polygon_with_holes_2> cells;
  partition.cells(std::back_inserter(cells));
  report.cells_after = cells.size();
  report.simplification_seconds = timer.time();
  lift_and_extrude<Kernel>(input.points, planes, segments, cells, input.settings, mesh, report);
  report.seconds = total.time();
  return report;
}

template <class PointRange, class Point, class NamedParameters>
LOD2_report reconstruct_lod2(const PointRange& range, CGAL::Surface_mesh<Point>& mesh, const NamedParameters& np)
{
  if(!mesh.is_empty())
    throw_input_error(Input_error_code::INVALID_PARAMETER, "the output mesh must be empty");
  CGAL::Real_timer total;
  total.start();
  LOD2_input<PointRange, NamedParameters> input(range, np);
  return reconstruct_lod2_from_input(input, mesh, np, total);
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LOD2_PIPELINE_H
