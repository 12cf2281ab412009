// The inputs, the measures and the output shared by the peer benchmarks of the LOD2 pipeline,
// each of which runs one method on the same inputs: benchmark_lod2_buildings (this package's
// lod2_building_reconstruction()), benchmark_polyfit (CGAL's Polygonal_surface_reconstruction)
// and ksr/benchmark_ksr (CGAL 6's Kinetic_surface_reconstruction_3). benchmark_ksr is built
// against CGAL 6.0.1, the others against CGAL 5.5.1: this header compiles against both.
//
// Inputs: a point file (building.ply: points with normals), or each building of a synthetic
// classified tile (synthetic_city.h, `City_options` but for the number of buildings and the
// seed): the points of one truth building and the ground points within 5 m of the bounding box
// of its footprint (no tree point, no other building), without normals, or with the true ones
// (--true-normals: the outward normal of the true face, up for the ground), without planes, or
// with the true ones (--true-planes: the ground and each true face of the building with points
// on it, numbered from 0; for the methods that take planes).
// Per model: faces (as the method outputs them), triangles, components, the RMS and the largest
// distance of the measured points to it (all the points of a file, the building's own points
// on a tile; an AABB tree on its triangles), closed and valid after the repairs that change no
// geometry (see measure_model()); the time from the points as given, the normal estimation of
// the peers included.
// Output: one JSON line per input on stdout; on a tile one per building, then the totals.
//   PROGRAM INPUT [options]
//   PROGRAM --synthetic-city N [--seed S] [--true-normals] [--true-planes] [options]
//   [--models PREFIX]: writes every model as PREFIX_METHOD[_BUILDING].off

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_BENCHMARK_LOD2_PEER_BENCHMARK_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_BENCHMARK_LOD2_PEER_BENCHMARK_H

#include "synthetic_city.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/version.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace benchmark {

using test::Mesh;
using test::Point_3;
using test::Sample;
using Polygon = std::vector<std::size_t>;
using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// One input of a method.
struct Peer_input
{
  std::string name;               // the file's name, or the tile's ("city30_seed1")
  int building = -1;              // index of the truth building on a tile, -1 for a file
  std::string kind;               // the kind of that building (synthetic_city.h)
  std::vector<Sample> points;     // given to the method
  bool has_normals = false;       // whether the points' normals are set
  bool has_planes = false;        // whether the points' plane indices are set (-1 otherwise)
  std::vector<Point_3> measured;  // whose distances to the model are reported
};

/// What a method did on one input and the measures of its model.
struct Peer_result
{
  std::size_t planes = 0;         // planes the method detected
  double seconds = 0;             // from the points as given to the model, normal estimation included
  double normals_seconds = 0;     // of which normal estimation, when the method needs normals the input lacks
  std::string failed;             // why there is no model; empty when there is one
  std::string note;
  std::size_t faces = 0, triangles = 0, components = 0;
  bool closed = false, valid = false;
  std::string repairs;                 // what measure_model() repaired before measuring
  test::Distance_statistics distances; // of the measured points to the model
  std::vector<Point_3> vertices;       // the model as the method output it
  std::vector<Polygon> polygons;
};

struct Peer_options
{
  std::string input;              // a point file, or
  std::size_t buildings = 0;      // the number of buildings of a synthetic tile
  unsigned seed = 1;              // of the tile
  bool true_normals = false;      // the tile's points get the normals of the true surfaces
  bool true_planes = false;       // and the planes of the true surfaces
  std::string models_prefix;      // where to write the models, if anywhere
};

/// Normals by jet fitting on 12 neighbours, oriented along a minimum spanning tree (a point it
/// cannot orient keeps its normal); returns the seconds it took.
inline double estimate_normals(Peer_input& input)
{
  using Point_with_normal = std::tuple<Point_3, test::Vector_3, int>; // the algorithms reorder the points
  const Clock::time_point start = Clock::now();
  std::vector<Point_with_normal> points;
  for(const Sample& sample : input.points) points.emplace_back(sample.point, sample.normal, sample.plane_index);
  const auto maps = parameters::point_map(Nth_of_tuple_property_map<0, Point_with_normal>())
                      .normal_map(Nth_of_tuple_property_map<1, Point_with_normal>());
  jet_estimate_normals<Sequential_tag>(points, 12, maps);
  mst_orient_normals(points, 12, maps);
  input.points.clear();
  for(const Point_with_normal& p : points) input.points.push_back({std::get<0>(p), std::get<1>(p), std::get<2>(p)});
  input.has_normals = true;
  return seconds_since(start);
}

/// A point file; false when it cannot be read or holds no point.
inline bool read_point_file(const std::string& path, Peer_input& input)
{
  input.name = std::filesystem::path(path).filename().string();
  if(!IO::read_points(path, std::back_inserter(input.points),
                      parameters::point_map(test::Sample_point_map()).normal_map(test::Sample_normal_map())) ||
     input.points.empty())
    return false;
  for(Sample& sample : input.points) {
    sample.plane_index = -1;
    input.has_normals = input.has_normals || sample.normal != test::Vector_3(0, 0, 0);
    input.measured.push_back(sample.point);
  }
  return true;
}

/// The inputs of the buildings of the tile: each building's points, the ground points within
/// `margin` of the bounding box of its footprint (found through the lots of the tile, each box
/// registered in the lots it overlaps).
inline std::vector<Peer_input> city_inputs(const Peer_options& options, double margin = 5)
{
  test::City_options city_options;
  city_options.buildings = options.buildings;
  city_options.seed = options.seed;
  const test::City city = test::make_city(city_options);
  const double lot = city_options.spacing;
  std::vector<Peer_input> inputs(city.buildings.size());
  std::vector<Bbox_2> boxes;
  std::map<std::pair<long, long>, std::vector<std::size_t>> boxes_in_lot;
  for(std::size_t b = 0; b < inputs.size(); ++b) {
    inputs[b].name = "city" + std::to_string(options.buildings) + "_seed" + std::to_string(options.seed);
    inputs[b].building = int(b);
    inputs[b].kind = city.kinds[b];
    inputs[b].has_normals = options.true_normals;
    inputs[b].has_planes = options.true_planes;
    const Bbox_2 box = bbox_2(city.footprints[b].begin(), city.footprints[b].end());
    boxes.emplace_back(box.xmin() - margin, box.ymin() - margin, box.xmax() + margin, box.ymax() + margin);
    for(long i = long(std::floor(boxes[b].xmin() / lot)); i <= long(std::floor(boxes[b].xmax() / lot)); ++i)
      for(long j = long(std::floor(boxes[b].ymin() / lot)); j <= long(std::floor(boxes[b].ymax() / lot)); ++j)
        boxes_in_lot[{i, j}].push_back(b);
  }
  for(const test::City_sample& s : city.samples) {
    if(s.classification == test::las_building_class && s.building >= 0) {
      const test::Vector_3 normal =
        options.true_normals ? test::internal::plane_frame(city.buildings[std::size_t(s.building)].faces[std::size_t(s.face)].vertices).normal
                             : test::Vector_3(0, 0, 0);
      inputs[std::size_t(s.building)].points.push_back({s.point, normal, options.true_planes ? 1 + s.face : -1});
      inputs[std::size_t(s.building)].measured.push_back(s.point);
      continue;
    }
    if(s.classification != test::las_ground_class) continue;
    const auto found = boxes_in_lot.find({long(std::floor(s.point.x() / lot)), long(std::floor(s.point.y() / lot))});
    if(found == boxes_in_lot.end()) continue;
    for(std::size_t b : found->second)
      if(boxes[b].xmin() <= s.point.x() && s.point.x() <= boxes[b].xmax() && boxes[b].ymin() <= s.point.y() &&
         s.point.y() <= boxes[b].ymax())
        inputs[b].points.push_back({s.point, test::Vector_3(0, 0, options.true_normals ? 1 : 0), options.true_planes ? 0 : -1});
  }
  for(Peer_input& input : inputs) { // the planes numbered 0 to n - 1 (PolyFit divides by zero on a plane without points)
    std::map<int, int> number;
    for(const Sample& sample : input.points) number.emplace(sample.plane_index, 0);
    int next = 0;
    for(auto& entry : number) entry.second = entry.first < 0 ? -1 : next++;
    for(Sample& sample : input.points) sample.plane_index = number[sample.plane_index];
  }
  return inputs;
}

namespace internal {

// True for a closed, valid triangle mesh without self-intersection, outward oriented, bounding
// a positive volume.
inline bool is_solid(const Mesh& mesh)
{
  namespace PMP = Polygon_mesh_processing;
  return is_closed(mesh) && is_valid_polygon_mesh(mesh) && !PMP::does_self_intersect(mesh) && PMP::is_outward_oriented(mesh) &&
         PMP::volume(mesh) > 0;
}

// True if a polygon of the soup passes through one of its vertices twice (KSR joins the holes
// of a face to its outer border by bridges; orient_polygon_soup() does not end on such polygons).
inline bool has_repeated_vertex(const std::vector<Polygon>& polygons)
{
  return std::any_of(polygons.begin(), polygons.end(), [](Polygon polygon) {
    std::sort(polygon.begin(), polygon.end());
    return std::adjacent_find(polygon.begin(), polygon.end()) != polygon.end();
  });
}

// The triangle mesh of a polygon soup whose coincident points are merged; `mesh` is its polygon
// mesh, or empty when the soup is none (KSR joins the holes of a face to its outer border by
// bridges: such polygons are triangulated in the soup from CGAL 5.6 on, then the soup is
// oriented, which duplicates the points where it is not a 2-manifold). False in `triangulated`
// when a polygon could not be triangulated.
inline Mesh triangle_mesh(std::vector<Point_3> vertices, std::vector<Polygon> polygons, Mesh mesh, bool& triangulated)
{
  namespace PMP = Polygon_mesh_processing;
  triangulated = true;
  if(mesh.is_empty()) {
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(5, 6, 0)
    triangulated = PMP::triangulate_polygons(vertices, polygons);
#endif
    if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
      PMP::repair_polygon_soup(vertices, polygons);
      PMP::orient_polygon_soup(vertices, polygons);
    }
    PMP::polygon_soup_to_polygon_mesh(vertices, polygons, mesh);
  }
  triangulated = PMP::triangulate_faces(mesh) && triangulated;
  return mesh;
}

inline std::string json_string(const std::string& text)
{
  std::string quoted = "\"";
  for(char c : text) {
    if(c == '"' || c == '\\') quoted += '\\';
    quoted += (c == '\n' || c == '\t') ? ' ' : c;
  }
  return quoted + "\"";
}

inline std::string json_number(double value)
{
  if(!std::isfinite(value)) return "null";
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

inline double peak_rss_mb()
{
  rusage self, children; // PolyFit's solver runs in child processes
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &children);
  return double(std::max(self.ru_maxrss, children.ru_maxrss)) / 1024.;
}

} // namespace internal

/// Measures a model given as a polygon soup (as KSR outputs it; the faces of a polygon mesh
/// otherwise), after the repairs that change no geometry, each noted in `repairs`: coincident
/// vertices merged (PolyFit's faces do not share their corners), and the orientation of the
/// faces made consistent when it is not (CGAL's orient_polygon_soup(); PolyFit orients each face
/// by its plane), then, when that closes the surface, outward (orient_to_bound_a_volume()).
/// `closed`: the soup is then a polygon mesh without border (`CGAL::is_closed()`). `valid`:
/// closed and, triangulated, a valid polygon mesh without self-intersection
/// (`does_self_intersect()`), outward oriented (`is_outward_oriented()`), of positive volume.
inline void measure_model(std::vector<Point_3> vertices, std::vector<Polygon> polygons, const std::vector<Point_3>& measured,
                          Peer_result& result)
{
  namespace PMP = Polygon_mesh_processing;
  result.faces = polygons.size();
  result.vertices = vertices;
  result.polygons = polygons;
  std::vector<std::string> repairs;
  if(PMP::merge_duplicate_points_in_polygon_soup(vertices, polygons) > 0) repairs.push_back("vertices merged");
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons) && !internal::has_repeated_vertex(polygons)) {
    std::vector<Point_3> oriented_vertices = vertices;
    std::vector<Polygon> oriented_polygons = polygons;
    PMP::orient_polygon_soup(oriented_vertices, oriented_polygons);
    if(PMP::is_polygon_soup_a_polygon_mesh(oriented_polygons)) {
      vertices = std::move(oriented_vertices), polygons = std::move(oriented_polygons);
      repairs.push_back("faces oriented");
    }
  }
  Mesh mesh;
  if(PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::polygon_soup_to_polygon_mesh(vertices, polygons, mesh);
    result.closed = is_closed(mesh);
  }
  bool triangulated = false;
  Mesh triangles = internal::triangle_mesh(std::move(vertices), std::move(polygons), std::move(mesh), triangulated);
  if(result.closed && !repairs.empty() && repairs.back() == "faces oriented" && is_closed(triangles) &&
     !PMP::is_outward_oriented(triangles)) {
    PMP::orient_to_bound_a_volume(triangles);
    repairs.back() = "faces oriented outward";
  }
  result.triangles = triangles.number_of_faces();
  auto component = triangles.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
  result.components = PMP::connected_components(triangles, component);
  triangles.remove_property_map(component);
  result.valid = result.closed && triangulated && internal::is_solid(triangles);
  for(const std::string& repair : repairs) result.repairs += (result.repairs.empty() ? "" : ", ") + repair;
  const test::Distance_to_mesh to_model(triangles);
  result.distances = test::distances(measured, to_model);
}

/// The same for a polygon mesh.
inline void measure_model(const Mesh& model, const std::vector<Point_3>& measured, Peer_result& result)
{
  std::vector<Point_3> vertices;
  std::vector<Polygon> polygons;
  Polygon_mesh_processing::polygon_mesh_to_polygon_soup(model, vertices, polygons);
  measure_model(std::move(vertices), std::move(polygons), measured, result);
}

/// The JSON line of a result.
inline std::string json_line(const std::string& method, const Peer_input& input, const Peer_result& r)
{
  using internal::json_number;
  std::ostringstream out;
  out << std::boolalpha << "{\"method\":" << internal::json_string(method) << ",\"input\":" << internal::json_string(input.name);
  if(input.building >= 0) out << ",\"building\":" << input.building << ",\"kind\":" << internal::json_string(input.kind);
  out << ",\"points\":" << input.points.size() << ",\"measured\":" << input.measured.size() << ",\"planes\":" << r.planes
      << ",\"time_s\":" << json_number(r.seconds) << ",\"normals_s\":" << json_number(r.normals_seconds);
  if(r.failed.empty())
    out << ",\"faces\":" << r.faces << ",\"triangles\":" << r.triangles << ",\"components\":" << r.components
        << ",\"closed\":" << r.closed << ",\"valid\":" << r.valid << ",\"repairs\":" << internal::json_string(r.repairs)
        << ",\"rms_m\":" << json_number(r.distances.rms)
        << ",\"max_m\":" << json_number(r.distances.max);
  else
    out << ",\"failed\":" << internal::json_string(r.failed);
  if(!r.note.empty()) out << ",\"note\":" << internal::json_string(r.note);
  if(input.building < 0) out << ",\"peak_rss_mb\":" << json_number(internal::peak_rss_mb());
  out << "}";
  return out.str();
}

/// The totals of a method over the buildings of a tile.
struct Tile_totals
{
  std::size_t buildings = 0, points = 0, modelled = 0, closed = 0, valid = 0, repaired = 0, faces = 0;
  double seconds = 0, normals_seconds = 0, rms_sum = 0;

  void add(const Peer_input& input, const Peer_result& r)
  {
    ++buildings;
    points += input.points.size();
    seconds += r.seconds;
    normals_seconds += r.normals_seconds;
    if(!r.failed.empty()) return;
    ++modelled;
    closed += r.closed;
    valid += r.valid;
    repaired += !r.repairs.empty();
    faces += r.faces;
    rms_sum += r.distances.rms;
  }

  // the mean RMS is over the buildings with a model
  std::string json_line(const std::string& method, const std::string& tile) const
  {
    using internal::json_number;
    std::ostringstream out;
    out << "{\"method\":" << internal::json_string(method) << ",\"input\":" << internal::json_string(tile)
        << ",\"total\":true,\"buildings\":" << buildings << ",\"points\":" << points << ",\"modelled\":" << modelled
        << ",\"closed\":" << closed << ",\"valid\":" << valid << ",\"repaired\":" << repaired << ",\"faces\":" << faces
        << ",\"time_s\":" << json_number(seconds)
        << ",\"normals_s\":" << json_number(normals_seconds)
        << ",\"rms_mean_m\":" << json_number(modelled ? rms_sum / double(modelled) : std::nan(""))
        << ",\"peak_rss_mb\":" << json_number(internal::peak_rss_mb()) << "}";
    return out.str();
  }
};

/// Parses the options common to the peer benchmarks; `extra(argument, i)` takes the others
/// (and may read `argv[++i]`), false for one it does not know. False for a bad command line.
inline bool parse_peer_options(int argc, char** argv, Peer_options& options,
                               const std::function<bool(const std::string&, int&)>& extra)
{
  long buildings = 0;
  for(int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    const bool has_value = i + 1 < argc;
    if(argument == "--synthetic-city" && has_value) buildings = std::atol(argv[++i]);
    else if(argument == "--seed" && has_value) options.seed = unsigned(std::atol(argv[++i]));
    else if(argument == "--true-normals") options.true_normals = true;
    else if(argument == "--true-planes") options.true_planes = true;
    else if(argument == "--models" && has_value) options.models_prefix = argv[++i];
    else if(options.input.empty() && argument.rfind("--", 0) != 0) options.input = argument;
    else if(!extra(argument, i)) return false;
  }
  options.buildings = std::size_t(std::max(0L, buildings));
  return buildings >= 0 && (buildings > 0) != !options.input.empty();
}

/// Runs `method` (a Peer_result from a Peer_input, or an exception) on the inputs of the
/// options and prints a JSON line per input, and for a tile the totals; the name of the method
/// in them says "_true_planes" and "_true_normals" when the tile's points have those. Returns
/// the exit code: 1 when no input gave a model.
inline int run_peer_benchmark(const Peer_options& options, std::string method,
                              const std::function<Peer_result(Peer_input&)>& run)
{
  if(options.buildings > 0 && options.true_planes) method += "_true_planes";
  if(options.buildings > 0 && options.true_normals) method += "_true_normals";
  std::vector<Peer_input> inputs;
  if(options.buildings > 0) {
    inputs = city_inputs(options);
  } else {
    inputs.emplace_back();
    if(!read_point_file(options.input, inputs.back())) {
      std::cout << "{\"method\":\"" << method << "\",\"input\":" << internal::json_string(options.input)
                << ",\"failed\":\"cannot read the points\"}" << std::endl;
      return 1;
    }
  }
  Tile_totals totals;
  for(Peer_input& input : inputs) {
    Peer_result result;
    try {
      result = run(input);
    } catch(const std::exception& error) {
      result.failed = error.what();
    }
    std::cout << json_line(method, input, result) << std::endl;
    totals.add(input, result);
    if(!options.models_prefix.empty() && result.failed.empty())
      IO::write_polygon_soup(options.models_prefix + "_" + method + (input.building >= 0 ? "_" + std::to_string(input.building) : "") +
                               ".off",
                             result.vertices, result.polygons, parameters::stream_precision(17));
  }
  if(options.buildings > 0) std::cout << totals.json_line(method, inputs.empty() ? "" : inputs.front().name) << std::endl;
  return totals.modelled > 0 ? 0 : 1;
}

} // namespace benchmark
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_BENCHMARK_LOD2_PEER_BENCHMARK_H
