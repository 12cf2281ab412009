// CGAL 6's Kinetic_surface_reconstruction_3 (KSR) as a peer of the LOD2 pipeline, with the
// parameters of CGAL 6.0.1's example ksr_building.cpp, on a point file or building by building
// on the synthetic classified tile of benchmark_lod2_city (synthetic_city.h).
//   benchmark_ksr INPUT [--lambda V] [--models PREFIX]
//   benchmark_ksr --synthetic-city N [--seed S] [--true-normals] [--lambda V] [--models PREFIX]
// INPUT: points with normals (PLY, XYZ, OFF...); without normals they are estimated (jet fitting,
// 12 neighbors) and oriented (minimum spanning tree), as for the tile, whose points have none.
// Each building of the tile gets its own points and the ground points within 5 m of its
// footprint's bounding box; --true-normals gives them the outward normals of the true surfaces.
// KSR detects and regularizes planes, builds the kinetic partition, then labels it by min-cut
// (reconstruct_with_ground) for each lambda of the example (0.3 ... 0.99), or for V only. The
// model reported is the valid one closest to the points (smallest RMS), or the closest one when
// none is valid; time_s is detection + partition + that model's reconstruction (normal
// estimation apart: normals_s). Per model: faces (polygons of the output soup), triangles,
// soup_is_mesh, zero_boundary (each edge followed as often both ways), closed (CGAL::is_closed
// of the polygon mesh, when the soup is one), components, valid (the triangulated soup is a
// closed, valid polygon mesh without self-intersection bounding a positive volume),
// border_cycles, rms_m (RMS distance to the model of all input points of a file, of the
// building's own points on the tile). One JSON line per input (per building and a total for the
// tile), peak memory in it; the stages on stderr. --models writes every model as
// PREFIX[_BUILDING]_LAMBDA.ply.
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits_3.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Kinetic_surface_reconstruction_3.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/version.h>

#include "synthetic_city.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace City = CGAL::Polygon_partition_simplification::test;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Point_set = CGAL::Point_set_3<Point_3>;
using KSR = CGAL::Kinetic_surface_reconstruction_3<Kernel, Point_set, Point_set::Point_map, Point_set::Vector_map>;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Polygon = std::vector<std::size_t>;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double peak_rss_mb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;
}

// One model: KSR's labeling at one lambda and its measures.
struct Model
{
  double lambda = 0, seconds = 0;
  std::size_t faces = 0, triangles = 0, components = 0, border_cycles = 0;
  bool soup_is_mesh = false, zero_boundary = false, closed = false, valid = false;
  double sum_squared = 0; // of the distances of the measured points
  std::size_t measured = 0;
  double rms() const { return measured > 0 ? std::sqrt(sum_squared / double(measured)) : std::nan(""); }
};

// One run of KSR on one point set.
struct Run
{
  std::size_t points = 0, planes = 0;
  double normals_seconds = 0, partition_seconds = 0; // partition: detection, regularization, partition
  std::vector<Model> models;                         // the non-empty ones
  std::string error;                                 // empty when KSR ran
  const Model* best() const
  {
    auto rank = [](const Model& m) { return std::make_tuple(!m.valid, m.rms()); };
    const Model* best = nullptr;
    for(const Model& m : models)
      if(!best || rank(m) < rank(*best)) best = &m;
    return best;
  }
};

// Silences std::cout while it lives: KSR prints the size of its partition there.
struct Silent_cout
{
  std::ostringstream sink;
  std::streambuf* saved = std::cout.rdbuf(sink.rdbuf());
  ~Silent_cout() { std::cout.rdbuf(saved); }
};

// True if every edge of the soup is followed as often in one direction as in the other: the
// soup bounds a volume, edges visited twice by one polygon (KSR's bridges to holes) included.
bool has_zero_boundary(const std::vector<Polygon>& polygons)
{
  std::map<std::pair<std::size_t, std::size_t>, long> balance;
  for(const Polygon& polygon : polygons)
    for(std::size_t i = 0; i < polygon.size(); ++i) {
      const std::size_t a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      balance[std::minmax(a, b)] += a < b ? 1 : -1;
    }
  return std::all_of(balance.begin(), balance.end(), [](const auto& edge) { return edge.second == 0; });
}

// True for a closed, valid triangle mesh without self-intersection bounding a positive volume.
bool is_solid(const Mesh& mesh)
{
  return CGAL::is_closed(mesh) && CGAL::is_valid_polygon_mesh(mesh) && !PMP::does_self_intersect(mesh) &&
         PMP::volume(mesh) > 0;
}

// The measures of a polygon soup: closed as it is (a polygon mesh without border), and once its
// polygons are triangulated (KSR joins the holes of a face to its outer border by bridges, which
// a polygon mesh cannot hold) as a triangle mesh (from the soup oriented when it is not one):
// components, the PMP checks, the distances (AABB tree) and its border cycles (KSR's model with
// ground is the ground, cut by the bounding box of the partition, with the buildings on it: one
// border cycle along that cut).
void measure(std::vector<Point_3> vertices, std::vector<Polygon> polygons, const std::vector<Point_3>& measured,
             Model& model)
{
  model.faces = polygons.size();
  model.soup_is_mesh = PMP::is_polygon_soup_a_polygon_mesh(polygons);
  model.zero_boundary = has_zero_boundary(polygons);
  if(model.soup_is_mesh) {
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(vertices, polygons, mesh);
    model.closed = CGAL::is_closed(mesh);
  }
  const bool triangulated = PMP::triangulate_polygons(vertices, polygons);
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::repair_polygon_soup(vertices, polygons);
    PMP::orient_polygon_soup(vertices, polygons);
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(vertices, polygons, mesh);
  model.triangles = num_faces(mesh);
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
  model.components = PMP::connected_components(mesh, component);
  model.valid = triangulated && is_solid(mesh);
  {
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
    CGAL::AABB_tree<CGAL::AABB_traits_3<Kernel, Primitive>> tree(faces(mesh).begin(), faces(mesh).end(), mesh);
    tree.accelerate_distance_queries();
    for(const Point_3& p : measured) model.sum_squared += CGAL::to_double(tree.squared_distance(p));
    model.measured = measured.size();
  }
  std::vector<Mesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(borders));
  model.border_cycles = borders.size();
}

// Normals for a point set without: jet fitting, oriented along a minimum spanning tree (points
// it cannot orient keep their normal).
void estimate_normals(Point_set& points)
{
  points.add_normal_map();
  CGAL::jet_estimate_normals<CGAL::Sequential_tag>(points, 12);
  CGAL::mst_orient_normals(points, 12);
}

// KSR with the parameters of CGAL 6.0.1's examples/Kinetic_surface_reconstruction/ksr_building.cpp
// (libcgal-demo 6.0.1, examples.tar.gz): region growing within 0.1 and 10 degrees, regions of
// 100 points or more, a bounding box oriented along the planes, parallelism and coplanarity
// regularized within 5 degrees and 0.02, a partition of k = 2, one model per lambda.
Run run_ksr(Point_set& points, const std::vector<Point_3>& measured, const std::vector<double>& lambdas,
            const std::string& models_prefix)
{
  Run run;
  run.points = points.size();
  Clock::time_point start = Clock::now();
  if(!points.has_normal_map()) estimate_normals(points);
  run.normals_seconds = seconds_since(start);
  const auto parameters = CGAL::parameters::maximum_distance(0.1)
                            .maximum_angle(10)
                            .minimum_region_size(100)
                            .reorient_bbox(true)
                            .regularize_parallelism(true)
                            .regularize_coplanarity(true)
                            .angle_tolerance(5)
                            .maximum_offset(0.02);
  try {
    Silent_cout silent;
    start = Clock::now();
    KSR ksr(points, parameters);
    ksr.detection_and_partition(2, parameters);
    run.partition_seconds = seconds_since(start);
    run.planes = ksr.detected_planar_shapes().size();
    std::cerr << run.planes << " planes, partition " << run.partition_seconds << " s" << std::endl;
    for(double lambda : lambdas) {
      std::vector<Point_3> vertices;
      std::vector<Polygon> polygons;
      start = Clock::now();
      ksr.reconstruct_with_ground(lambda, std::back_inserter(vertices), std::back_inserter(polygons));
      Model model;
      model.lambda = lambda;
      model.seconds = seconds_since(start);
      std::cerr << "lambda " << lambda << ": " << polygons.size() << " faces, " << model.seconds << " s" << std::endl;
      if(polygons.empty()) continue;
      if(!models_prefix.empty())
        CGAL::IO::write_polygon_soup(models_prefix + "_" + std::to_string(lambda) + ".ply", vertices, polygons);
      measure(std::move(vertices), std::move(polygons), measured, model);
      run.models.push_back(model);
    }
    if(run.models.empty()) run.error = "empty output for every lambda";
  } catch(const std::exception& e) {
    run.error = std::string("exception: ") + e.what();
  }
  return run;
}

std::string json_number(double value)
{
  if(!std::isfinite(value)) return "null";
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

std::string json_model(const Model& m)
{
  std::ostringstream out;
  out << std::boolalpha << "\"faces\":" << m.faces << ",\"triangles\":" << m.triangles << ",\"soup_is_mesh\":" << m.soup_is_mesh
      << ",\"zero_boundary\":" << m.zero_boundary << ",\"closed\":" << m.closed << ",\"components\":" << m.components
      << ",\"valid\":" << m.valid << ",\"border_cycles\":" << m.border_cycles << ",\"rms_m\":" << json_number(m.rms());
  return out.str();
}

// The members of a run's JSON line after its name: the best model, then every model.
std::string json_run(const Run& run)
{
  std::ostringstream out;
  out << "\"points\":" << run.points << ",\"planes\":" << run.planes << ",\"normals_s\":" << json_number(run.normals_seconds);
  const Model* best = run.best();
  if(!best) return out.str() + ",\"failed\":\"" + run.error + "\"";
  out << ",\"lambda\":" << best->lambda << ",\"time_s\":" << json_number(run.partition_seconds + best->seconds) << ","
      << json_model(*best) << ",\"partition_s\":" << json_number(run.partition_seconds) << ",\"lambdas\":[";
  for(std::size_t i = 0; i < run.models.size(); ++i)
    out << (i ? "," : "") << "{\"lambda\":" << run.models[i].lambda << ",\"time_s\":" << json_number(run.models[i].seconds)
        << "," << json_model(run.models[i]) << "}";
  return out.str() + "]";
}

int run_file(const std::string& path, const std::vector<double>& lambdas, const std::string& models_prefix)
{
  Point_set points;
  if(!CGAL::IO::read_point_set(path, points) || points.empty()) {
    std::cout << "{\"input\":\"" << path << "\",\"failed\":\"cannot read the points\"}" << std::endl;
    return 1;
  }
  const std::vector<Point_3> measured(points.points().begin(), points.points().end());
  const Run run = run_ksr(points, measured, lambdas, models_prefix);
  std::cout << "{\"input\":\"" << path << "\",\"cgal\":\"" << CGAL_VERSION_STR << "\"," << json_run(run)
            << ",\"peak_rss_mb\":" << json_number(peak_rss_mb()) << "}" << std::endl;
  return run.models.empty() ? 1 : 0;
}

// The points KSR gets for building `b` of the tile: its own and the ground within 5 m of the
// bounding box of its footprint, with the true outward normals when asked (else none).
Point_set building_points(const City::City& city, int b, bool true_normals, std::vector<Point_3>& measured)
{
  const CGAL::Bbox_2 box = CGAL::bbox_2(city.footprints[std::size_t(b)].begin(), city.footprints[std::size_t(b)].end());
  const std::vector<City::Planar_face>& faces = city.buildings[std::size_t(b)].faces;
  Point_set points;
  if(true_normals) points.add_normal_map();
  for(const City::City_sample& s : city.samples) {
    const bool own = s.classification == City::las_building_class && s.building == b;
    const bool ground = s.classification == City::las_ground_class && s.point.x() >= box.xmin() - 5 &&
                        s.point.x() <= box.xmax() + 5 && s.point.y() >= box.ymin() - 5 && s.point.y() <= box.ymax() + 5;
    if(own) measured.push_back(s.point);
    if(!own && !ground) continue;
    const auto index = points.insert(s.point);
    if(true_normals && own)
      points.normal(*index) = City::internal::plane_frame(faces[std::size_t(s.face)].vertices).normal;
    else if(true_normals)
      points.normal(*index) = City::Vector_3(0, 0, 1);
  }
  return points;
}

// KSR building by building on the tile of N buildings: one line per building, then the totals
// (times and faces summed, closed and valid counted, the RMS over the points of every building
// with a model).
int run_city(std::size_t buildings, unsigned seed, bool true_normals, const std::vector<double>& lambdas,
             const std::string& models_prefix)
{
  City::City_options options;
  options.buildings = buildings;
  options.seed = seed;
  const City::City city = City::make_city(options);
  const std::string tile = "\"tile\":\"city" + std::to_string(buildings) + "_seed" + std::to_string(seed) +
                           (true_normals ? "_true_normals" : "") + "\"";
  double seconds = 0, normals_seconds = 0, sum_squared = 0;
  std::size_t faces = 0, closed = 0, valid = 0, failed = 0, measured_points = 0;
  for(int b = 0; b < int(city.buildings.size()); ++b) {
    std::vector<Point_3> measured;
    Point_set points = building_points(city, b, true_normals, measured);
    std::cerr << "building " << b << ": " << points.size() << " points" << std::endl;
    const std::string prefix = models_prefix.empty() ? "" : models_prefix + "_" + std::to_string(b);
    const Run run = run_ksr(points, measured, lambdas, prefix);
    std::cout << "{" << tile << ",\"building\":" << b << ",\"kind\":\"" << city.kinds[std::size_t(b)] << "\"," << json_run(run)
              << "}" << std::endl;
    normals_seconds += run.normals_seconds;
    const Model* best = run.best();
    if(!best) {
      ++failed;
      continue;
    }
    seconds += run.partition_seconds + best->seconds;
    faces += best->faces;
    closed += best->closed;
    valid += best->valid;
    sum_squared += best->sum_squared;
    measured_points += best->measured;
  }
  std::cout << "{" << tile << ",\"total\":true,\"buildings\":" << city.buildings.size() << ",\"points\":" << city.samples.size()
            << ",\"time_s\":" << json_number(seconds) << ",\"normals_s\":" << json_number(normals_seconds)
            << ",\"faces\":" << faces << ",\"closed\":" << closed << ",\"valid\":" << valid << ",\"failed\":" << failed
            << ",\"rms_m\":" << json_number(measured_points ? std::sqrt(sum_squared / double(measured_points)) : std::nan(""))
            << ",\"peak_rss_mb\":" << json_number(peak_rss_mb()) << "}" << std::endl;
  return failed == city.buildings.size() ? 1 : 0;
}

int main(int argc, char** argv)
{
  std::vector<double> lambdas{0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 0.99}; // those of ksr_building.cpp
  std::string input, models_prefix;
  long buildings = 0;
  unsigned seed = 1;
  bool true_normals = false;
  for(int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if(argument == "--lambda" && i + 1 < argc) lambdas = {std::atof(argv[++i])};
    else if(argument == "--synthetic-city" && i + 1 < argc) buildings = std::atol(argv[++i]);
    else if(argument == "--true-normals") true_normals = true;
    else if(argument == "--models" && i + 1 < argc) models_prefix = argv[++i];
    else if(argument == "--seed" && i + 1 < argc) seed = unsigned(std::atol(argv[++i]));
    else if(input.empty() && argument.rfind("--", 0) != 0) input = argument;
    else input.clear(), buildings = -1, i = argc;
  }
  if(buildings < 0 || (buildings == 0) == input.empty()) {
    std::cerr << "usage: " << argv[0] << " INPUT [--lambda V] [--models PREFIX]\n       " << argv[0]
              << " --synthetic-city N [--seed S] [--true-normals] [--lambda V] [--models PREFIX]\n";
    return 2;
  }
  if(buildings > 0) return run_city(std::size_t(buildings), seed, true_normals, lambdas, models_prefix);
  return run_file(input, lambdas, models_prefix);
}
