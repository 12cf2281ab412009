// LOD2 building reconstruction against three methods of CGAL, fidelity against complexity as
// in Fig. 3.11 / Table 3.1 of the thesis: CGAL's points_3/building.ply (100,000 points with
// normals and the plane of each point, `segment_index`) and synthetic scenes with a known
// truth, in one run. Each method runs at several complexities:
//  - ours: CGAL::lod2_building_reconstruction at several concurrency weights (lambda1);
//  - PolyFit: CGAL::Polygonal_surface_reconstruction (GLPK) at several weights of fitting,
//    coverage and complexity, on the same planes as ours;
//  - QEM: Garland-Heckbert edge collapse of a dense mesh of the points (CGAL's advancing front
//    surface reconstruction, row "afsr") to several numbers of triangles;
//  - VSA: variational shape approximation of that dense mesh with several numbers of proxies.
// Per model: faces, triangles, RMS and largest (Hausdorff) distance of the input points to it
// (on a synthetic scene, of the points of the buildings: no method is asked to model the
// ground), for a synthetic scene the largest distance from the true roofs and walls to it and
// from it to the true scene (buildings and ground), the time from the points (the dense mesh
// included for QEM and VSA; PolyFit's candidate faces included), that time over the time of
// CGAL's Delaunay_triangulation_3 of the same points (the baseline), closed and valid.
// PolyFit's solver runs in a child process, stopped at a time limit. Output: a table on stdout,
// one JSON object per line with --json, one SVG plot per scene (RMS distance against faces, one
// polyline per method) and with --models every model as OFF in the output directory, peak memory.
//   benchmark_lod2 [building.ply] [--peers-only] [--json FILE] [--output DIR] [--models]
//                  [--scene NAME]... [--time-limit SECONDS] [--density D]
//                  [--wall-density-factor F] [--noise SIGMA] [--seed N]
// --peers-only skips ours; --scene (repeatable) runs only the named scenes ("building" is
// building.ply); --time-limit is that of each PolyFit model (default 300 s); the synthetic
// points are sampled at D points per square meter (default 10), walls at F times that (0.1).
#include <CGAL/lod2_building_reconstruction.h>

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/read_ply_points.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/helpers.h>
#ifdef CGAL_USE_GLPK
#include <CGAL/GLPK_mixed_integer_program_traits.h>
#include <CGAL/Polygonal_surface_reconstruction.h>
#endif

#include "benchmark_child_process.h"
#include "synthetic_buildings.h"

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace Test = CGAL::Polygon_partition_simplification::test;
namespace PMP = CGAL::Polygon_mesh_processing;
using Test::Kernel;
using Test::Mesh;
using Test::Point_3;
using Test::Sample;
using Clock = std::chrono::steady_clock;
using CGAL::Polygon_partition_simplification::benchmark::compute_in_child;
using CGAL::Polygon_partition_simplification::benchmark::Time_limit_reached;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string to_text(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

// One input point set, what its models are measured against, and the baseline time.
struct Input
{
  std::string name;
  std::vector<Sample> points;                    // given to every method
  std::vector<Point_3> measured;                 // whose distances to a model are reported
  std::vector<Point_3> truth_samples;            // synthetic: samples of the true roofs and walls
  std::unique_ptr<Test::Distance_to_mesh> truth; // synthetic: the true buildings and the ground
  double delaunay_seconds = 0;                   // Delaunay_triangulation_3 of the points
};

// One model of one method at one complexity.
struct Result
{
  std::string scene, method, setting, note;
  bool failed = false;
  std::size_t faces = 0, triangles = 0;
  Test::Distance_statistics to_model;             // of the measured input points
  double truth_to_model = -1, model_to_truth = -1; // synthetic scenes only (largest distances)
  double seconds = 0, delaunay_seconds = 0;
  bool closed = false, valid = false;
  bool closed_once_welded = false; // closed once its coincident vertices are merged
  Mesh model;                      // until the result is reported
};

Result make_result(const Input& input, const std::string& method, const std::string& setting)
{
  Result result;
  result.scene = input.name;
  result.method = method;
  result.setting = setting;
  result.delaunay_seconds = input.delaunay_seconds;
  return result;
}

Result failure(const Input& input, const std::string& method, const std::string& setting, const std::string& why)
{
  Result result = make_result(input, method, setting);
  result.failed = true;
  result.note = why;
  return result;
}

// A polygon mesh of a polygon soup that may have degenerate or badly oriented polygons.
template <class Polygon>
Mesh mesh_of_soup(std::vector<Point_3> points, std::vector<Polygon> polygons)
{
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons); // duplicates the points where it is not a manifold
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return mesh;
}

// Whether a model is closed once its coincident vertices are merged: PolyFit's models are
// closed surfaces whose faces do not all share their corners.
bool is_closed_once_welded(const Mesh& model)
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  PMP::polygon_mesh_to_polygon_soup(model, points, polygons);
  return CGAL::is_closed(mesh_of_soup(points, polygons));
}

// Fills in the measures of a model computed in `seconds`; an empty model is a failure.
Result measure(Mesh model, const Input& input, Result result, double seconds)
{
  result.seconds = seconds;
  if(model.number_of_faces() == 0) {
    result.failed = true;
    result.note = "empty model (after " + to_text(seconds) + " s)";
    return result;
  }
  const Test::Distance_to_mesh to_model(model);
  result.faces = model.number_of_faces();
  result.triangles = to_model.triangles().size();
  result.to_model = Test::distances(input.measured, to_model);
  if(input.truth) {
    result.truth_to_model = Test::distances(input.truth_samples, to_model).max;
    result.model_to_truth = Test::distances(Test::sample_triangles(to_model.triangles(), 4), *input.truth).max;
  }
  result.closed = CGAL::is_closed(model);
  result.valid = CGAL::is_valid_polygon_mesh(model);
  result.closed_once_welded = result.closed || is_closed_once_welded(model);
  result.model = std::move(model);
  return result;
}

// Seeds the random generators that CGAL's algorithms use (VSA's seeding draws from std::rand),
// so that a method's draws do not depend on the methods run before it. The dense mesh still
// varies by a few faces from one process to another (ties inside the advancing front).
void reset_random_generators()
{
  std::srand(1);
  CGAL::get_default_random() = CGAL::Random(1);
}

// Runs the computation of one model; an exception gives a failed result that says why.
template <class Compute>
Result guarded(const Input& input, const std::string& method, const std::string& setting, Compute compute)
{
  reset_random_generators();
  try {
    return compute();
  } catch(const std::exception& error) {
    return failure(input, method, setting, error.what());
  }
}

// This package's reconstruction at the concurrency weight lambda1, on the planes of the input
// (segment_index of building.ply, the true planes of a synthetic scene) as PolyFit.
Result run_ours(const Input& input, double lambda1)
{
  namespace parameters = CGAL::Polygon_partition_simplification::parameters;
  Mesh model;
  const Clock::time_point start = Clock::now();
  const auto report = CGAL::lod2_building_reconstruction(
    input.points, model,
    parameters::concurrency_weight(lambda1, parameters::point_map(Test::Sample_point_map())
                                              .normal_map(Test::Sample_normal_map())
                                              .plane_index_map(Test::Sample_plane_index_map())));
  const double seconds = seconds_since(start);
  Result result = make_result(input, "ours", "lambda1=" + to_text(lambda1));
  result.note = "planes " + std::to_string(report.planes) + ", segments " + std::to_string(report.segments) + ", cells " +
                std::to_string(report.cells_before) + "->" + std::to_string(report.cells_after) + ", buildings " +
                std::to_string(report.buildings);
  return measure(model, input, result, seconds);
}

#ifdef CGAL_USE_GLPK
// PolyFit on the planes of the input, at weights (fitting, coverage, complexity) from CGAL's
// examples and its default, from detailed to coarse, each solved in a child process within the
// time limit, each result given to `add` as soon as it is known. The coarser settings took
// longer on every input tried, so that they are not run after one has reached the limit. The
// time of a model includes the candidate faces, computed once.
void run_polyfit(const Input& input, double time_limit, const std::function<void(Result)>& add)
{
  reset_random_generators();
  const Clock::time_point start = Clock::now();
  CGAL::Polygonal_surface_reconstruction<Kernel> polyfit(input.points, Test::Sample_point_map(), Test::Sample_normal_map(),
                                                         Test::Sample_plane_index_map());
  const double candidates_seconds = seconds_since(start);
  if(!polyfit.error_message().empty()) {
    add(failure(input, "polyfit", "candidates", polyfit.error_message()));
    return;
  }
  bool limit_reached = false;
  for(const std::array<double, 3>& w : {std::array<double, 3>{0.8, 0.15, 0.05}, {0.43, 0.27, 0.3}, {0.3, 0.2, 0.5}, {0.2, 0.1, 0.7}}) {
    const std::string setting = "weights=" + to_text(w[0]) + "/" + to_text(w[1]) + "/" + to_text(w[2]);
    if(limit_reached) {
      add(failure(input, "polyfit", setting, "not run: a more detailed setting reached the time limit"));
      continue;
    }
    add(guarded(input, "polyfit", setting, [&] {
      const Clock::time_point solve = Clock::now();
      Mesh model;
      try {
        model = compute_in_child([&] {
          Mesh mesh;
          if(!polyfit.reconstruct<CGAL::GLPK_mixed_integer_program_traits<double>>(mesh, w[0], w[1], w[2]))
            throw std::runtime_error(polyfit.error_message());
          return mesh;
        }, time_limit);
      } catch(const Time_limit_reached&) {
        limit_reached = true;
        throw;
      }
      return measure(model, input, make_result(input, "polyfit", setting), candidates_seconds + seconds_since(solve));
    }));
  }
}
#else
void run_polyfit(const Input& input, double, const std::function<void(Result)>& add)
{
  add(failure(input, "polyfit", "-", "not built: GLPK was not found when configuring"));
}
#endif

// The dense triangle mesh that QEM and VSA simplify: CGAL's advancing front surface
// reconstruction. It leaves holes where the points are sparse and between its triangles; those
// of at most 100 edges are filled (CGAL's triangulate_hole), and the components of less than 1%
// of the triangles dropped, so that QEM and VSA can reach a few faces (a hole cannot close
// under edge collapses: each keeps some triangles around it).
Mesh dense_mesh(const Input& input)
{
  std::vector<Point_3> points;
  for(const Sample& sample : input.points) points.push_back(sample.point);
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(), std::back_inserter(triangles));
  Mesh mesh = mesh_of_soup(points, triangles);
  std::vector<Mesh::Halfedge_index> holes;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(holes));
  for(Mesh::Halfedge_index hole : holes)
    if(halfedges_around_face(hole, mesh).size() <= 100)
      PMP::triangulate_hole(mesh, hole, CGAL::Emptyset_iterator());
  PMP::keep_large_connected_components(mesh, mesh.number_of_faces() / 100);
  mesh.collect_garbage();
  return mesh;
}

// The genus, boundary cycles and components of a mesh (Euler's formula): edge collapses keep
// them, so that they bound how far QEM can simplify the dense mesh.
std::string topology_of(Mesh& mesh)
{
  std::vector<Mesh::Halfedge_index> boundaries;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(boundaries));
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
  const long components = long(PMP::connected_components(mesh, component));
  mesh.remove_property_map(component);
  const long euler = long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
  return "genus " + std::to_string((2 * components - long(boundaries.size()) - euler) / 2) + ", " +
         std::to_string(boundaries.size()) + " boundary cycles, " + std::to_string(components) + " components";
}

// Garland-Heckbert edge collapse (quadric error metrics) of a copy of the dense mesh down to
// about `faces` triangles (3/2 as many edges), with the placements that flip a face refused.
// Collapses keep the topology, so that a dense mesh with many handles (noise makes them) stops
// above the target; its row says so.
// g++ 12 sees, inlined here, CGAL 5.5's quadric storage give an uninitialized Eigen matrix as the
// default value of a property map (the values are all set before they are read): a false
// -Wmaybe-uninitialized, silenced for this function only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
Result run_qem(const Input& input, const Mesh& dense, double dense_seconds, std::size_t faces)
{
  namespace SMS = CGAL::Surface_mesh_simplification;
  using Policies = SMS::GarlandHeckbert_plane_policies<Mesh, Kernel>;
  Mesh model = dense;
  const Clock::time_point start = Clock::now();
  Policies policies(model);
  const SMS::Bounded_normal_change_placement<Policies::Get_placement> placement(policies.get_placement());
  SMS::edge_collapse(model, SMS::Count_stop_predicate<Mesh>(3 * faces / 2),
                     CGAL::parameters::get_cost(policies.get_cost()).get_placement(placement));
  model.collect_garbage();
  Result result = make_result(input, "qem", "faces=" + std::to_string(faces));
  if(model.number_of_faces() > 2 * faces) result.note = "stopped above the target: collapses would change the topology";
  return measure(model, input, result, dense_seconds + seconds_since(start));
}
#pragma GCC diagnostic pop

// Variational shape approximation of the dense mesh with `proxies` proxies (hierarchical
// seeding, 30 iterations); the model is its triangulated approximation (anchors, triangles).
Result run_vsa(const Input& input, const Mesh& dense, double dense_seconds, std::size_t proxies)
{
  std::vector<Point_3> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  const Clock::time_point start = Clock::now();
  const bool manifold = CGAL::Surface_mesh_approximation::approximate_triangle_mesh(
    dense, CGAL::parameters::max_number_of_proxies(proxies)
             .number_of_iterations(30)
             .anchors(std::back_inserter(anchors))
             .triangles(std::back_inserter(triangles)));
  Mesh model = mesh_of_soup(anchors, triangles);
  Result result = make_result(input, "vsa", "proxies=" + std::to_string(proxies));
  if(!manifold) result.note = "the approximation is not a 2-manifold";
  return measure(model, input, result, dense_seconds + seconds_since(start));
}

struct Options
{
  std::string building_ply = CGAL::data_file_path("points_3/building.ply");
  std::string json_path, output_directory = ".";
  bool peers_only = false, write_models = false;
  double time_limit = 300; // seconds, of each PolyFit model
  std::vector<std::string> scenes; // only these; all if empty
  Test::Sampling_options sampling;
};

// All the methods on one input; `report` is called on each result as soon as it is known, then
// its model is dropped.
std::vector<Result> run_methods(const Input& input, const Options& options, const std::function<void(const Result&)>& report)
{
  std::vector<Result> results;
  const std::function<void(Result)> add = [&](Result result) {
    report(result);
    result.model = Mesh();
    results.push_back(std::move(result));
  };
  if(!options.peers_only)
    for(double lambda1 : {0.0005, 0.002, 0.01, 0.05})
      add(guarded(input, "ours", "lambda1=" + to_text(lambda1), [&] { return run_ours(input, lambda1); }));
  try {
    run_polyfit(input, options.time_limit, add);
  } catch(const std::exception& error) {
    add(failure(input, "polyfit", "candidates", error.what()));
  }
  Mesh dense;
  reset_random_generators();
  const Clock::time_point start = Clock::now();
  try {
    dense = dense_mesh(input);
  } catch(const std::exception& error) {
    add(failure(input, "afsr", "-", error.what()));
    return results;
  }
  const double dense_seconds = seconds_since(start);
  Result dense_result = make_result(input, "afsr", "dense");
  dense_result.note = topology_of(dense);
  add(measure(dense, input, dense_result, dense_seconds));
  for(std::size_t faces : {50, 100, 200, 500, 1000, 2000})
    add(guarded(input, "qem", "faces=" + std::to_string(faces), [&] { return run_qem(input, dense, dense_seconds, faces); }));
  for(std::size_t proxies : {10, 20, 50, 100, 200})
    add(guarded(input, "vsa", "proxies=" + std::to_string(proxies),
                [&] { return run_vsa(input, dense, dense_seconds, proxies); }));
  return results;
}

// The table on stdout: one line per model.
void print_header()
{
  std::printf("%-22s %-8s %-22s %7s %9s %8s %8s %8s %8s %9s %9s %6s %5s  %s\n", "scene", "method", "setting", "faces",
              "triangles", "rms_m", "max_m", "truth>m", "m>truth", "seconds", "x_delaun", "closed", "valid", "note");
}

void print_result(const Result& r)
{
  if(r.failed) {
    std::printf("%-22s %-8s %-22s FAILED: %s\n", r.scene.c_str(), r.method.c_str(), r.setting.c_str(), r.note.c_str());
  } else {
    char truth[2][16] = {"-", "-"};
    if(r.truth_to_model >= 0) std::snprintf(truth[0], sizeof truth[0], "%.3f", r.truth_to_model);
    if(r.model_to_truth >= 0) std::snprintf(truth[1], sizeof truth[1], "%.3f", r.model_to_truth);
    std::printf("%-22s %-8s %-22s %7zu %9zu %8.4f %8.3f %8s %8s %9.3f %9.2f %6s %5s  %s\n", r.scene.c_str(), r.method.c_str(),
                r.setting.c_str(), r.faces, r.triangles, r.to_model.rms, r.to_model.max, truth[0], truth[1], r.seconds,
                r.seconds / r.delaunay_seconds, r.closed ? "yes" : r.closed_once_welded ? "welded" : "no",
                r.valid ? "yes" : "no", r.note.c_str());
  }
  std::fflush(stdout);
}

std::string json_string(const std::string& text)
{
  std::string quoted = "\"";
  for(char c : text) {
    if(c == '"' || c == '\\') quoted += '\\';
    quoted += (c == '\n' || c == '\t') ? ' ' : c;
  }
  return quoted + "\"";
}

// A number, or null where it is not one (the distance to an empty model is infinite).
std::string json_number(double value) { return std::isfinite(value) ? to_text(value) : "null"; }

void write_json_line(std::ostream& out, const Result& r)
{
  out << "{\"scene\":" << json_string(r.scene) << ",\"method\":" << json_string(r.method)
      << ",\"setting\":" << json_string(r.setting) << ",\"failed\":" << (r.failed ? "true" : "false")
      << ",\"faces\":" << r.faces << ",\"triangles\":" << r.triangles << ",\"rms\":" << json_number(r.to_model.rms)
      << ",\"max\":" << json_number(r.to_model.max) << ",\"measured_points\":" << r.to_model.count;
  if(r.truth_to_model >= 0)
    out << ",\"truth_to_model_max\":" << json_number(r.truth_to_model)
        << ",\"model_to_truth_max\":" << json_number(r.model_to_truth);
  out << ",\"seconds\":" << r.seconds << ",\"delaunay_seconds\":" << r.delaunay_seconds
      << ",\"closed\":" << (r.closed ? "true" : "false")
      << ",\"closed_once_welded\":" << (r.closed_once_welded ? "true" : "false") << ",\"valid\":" << (r.valid ? "true" : "false")
      << ",\"note\":" << json_string(r.note) << "}" << std::endl;
}

// 1, 2 or 5 times a power of ten, at least `value`.
double round_step(double value)
{
  const double power = std::pow(10., std::floor(std::log10(value)));
  for(double m : {1., 2., 5.})
    if(m * power >= value) return m * power;
  return 10 * power;
}

// The plot of one scene: RMS distance of the input points against the number of faces (log
// scale), one polyline per method in the order of the results.
void write_plot(const std::string& path, const std::string& scene, const std::vector<Result>& results)
{
  std::map<std::string, std::vector<std::pair<double, double>>> curves;
  std::vector<std::string> methods;
  double low = 1e300, high = 1, top = 0;
  for(const Result& r : results) {
    if(r.failed || r.faces == 0 || !std::isfinite(r.to_model.rms)) continue;
    if(curves.find(r.method) == curves.end()) methods.push_back(r.method);
    curves[r.method].emplace_back(double(r.faces), r.to_model.rms);
    low = std::min(low, double(r.faces)), high = std::max(high, double(r.faces)), top = std::max(top, r.to_model.rms);
  }
  if(methods.empty()) return;
  const double x0 = std::floor(std::log10(low)), x1 = std::max(x0 + 1, std::ceil(std::log10(high)));
  const double y_step = round_step(std::max(top, 1e-6) / 5), y1 = y_step * std::ceil(std::max(top, 1e-6) / y_step);
  const double left = 70, right = 520, bottom = 360, up = 40; // the frame of the plot, in pixels
  auto x = [&](double faces) { return left + (std::log10(faces) - x0) / (x1 - x0) * (right - left); };
  auto y = [&](double rms) { return bottom - rms / y1 * (bottom - up); };
  std::ofstream svg(path);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"680\" height=\"410\" font-family=\"sans-serif\" "
         "font-size=\"12\">\n<rect width=\"680\" height=\"410\" fill=\"white\"/>\n"
      << "<text x=\"" << left << "\" y=\"24\" font-size=\"14\">" << scene << ": RMS distance of the points to the model</text>\n";
  for(double decade = x0; decade <= x1; ++decade)
    for(double m = 1; m < 10 && decade + std::log10(m) <= x1; ++m) {
      const double px = x(m * std::pow(10., decade));
      svg << "<line x1=\"" << px << "\" y1=\"" << up << "\" x2=\"" << px << "\" y2=\"" << bottom << "\" stroke=\""
          << (m == 1 ? "#bbb" : "#eee") << "\"/>\n";
      if(m == 1)
        svg << "<text x=\"" << px << "\" y=\"" << bottom + 16 << "\" text-anchor=\"middle\">" << std::fixed
            << std::setprecision(0) << std::pow(10., decade) << std::defaultfloat << std::setprecision(6) << "</text>\n";
    }
  for(double v = 0; v <= y1 * (1 + 1e-9); v += y_step)
    svg << "<line x1=\"" << left << "\" y1=\"" << y(v) << "\" x2=\"" << right << "\" y2=\"" << y(v) << "\" stroke=\"#ddd\"/>\n"
        << "<text x=\"" << left - 6 << "\" y=\"" << y(v) + 4 << "\" text-anchor=\"end\">" << v << "</text>\n";
  svg << "<rect x=\"" << left << "\" y=\"" << up << "\" width=\"" << right - left << "\" height=\"" << bottom - up
      << "\" fill=\"none\" stroke=\"black\"/>\n<text x=\"" << (left + right) / 2 << "\" y=\"" << bottom + 36
      << "\" text-anchor=\"middle\">number of faces</text>\n<text x=\"16\" y=\"" << (up + bottom) / 2
      << "\" transform=\"rotate(-90 16 " << (up + bottom) / 2 << ")\" text-anchor=\"middle\">RMS distance (m)</text>\n";
  const std::map<std::string, std::string> colors{
    {"ours", "#d62728"}, {"polyfit", "#1f77b4"}, {"afsr", "#7f7f7f"}, {"qem", "#2ca02c"}, {"vsa", "#9467bd"}};
  for(std::size_t i = 0; i < methods.size(); ++i) {
    std::vector<std::pair<double, double>>& curve = curves[methods[i]];
    std::sort(curve.begin(), curve.end());
    const std::string color = colors.count(methods[i]) ? colors.at(methods[i]) : "#ff7f0e";
    svg << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"2\" points=\"";
    for(const auto& point : curve) svg << x(point.first) << "," << y(point.second) << " ";
    svg << "\"/>\n";
    for(const auto& point : curve)
      svg << "<circle cx=\"" << x(point.first) << "\" cy=\"" << y(point.second) << "\" r=\"3\" fill=\"" << color << "\"/>\n";
    svg << "<line x1=\"540\" y1=\"" << up + 10 + 20 * i << "\" x2=\"565\" y2=\"" << up + 10 + 20 * i << "\" stroke=\""
        << color << "\" stroke-width=\"2\"/><text x=\"572\" y=\"" << up + 14 + 20 * i << "\">" << methods[i] << "</text>\n";
  }
  svg << "</svg>\n";
}

// The baseline of the times: CGAL's Delaunay_triangulation_3 of the points.
double delaunay_seconds(const std::vector<Sample>& samples)
{
  std::vector<Point_3> points;
  for(const Sample& sample : samples) points.push_back(sample.point);
  const Clock::time_point start = Clock::now();
  const CGAL::Delaunay_triangulation_3<Kernel> triangulation(points.begin(), points.end());
  return triangulation.number_of_vertices() > 0 ? seconds_since(start) : 0;
}

// building.ply with its normals and planes (segment_index, -1 for a point on none); null if unreadable.
std::unique_ptr<Input> read_building(const std::string& path)
{
  auto input = std::make_unique<Input>();
  input->name = "building";
  std::ifstream stream(path);
  if(!stream ||
     !CGAL::IO::read_PLY_with_properties(stream, std::back_inserter(input->points),
                                         CGAL::make_ply_point_reader(Test::Sample_point_map()),
                                         CGAL::make_ply_normal_reader(Test::Sample_normal_map()),
                                         std::make_pair(Test::Sample_plane_index_map(), CGAL::PLY_property<int>("segment_index"))) ||
     input->points.empty())
    return nullptr;
  for(const Sample& sample : input->points) input->measured.push_back(sample.point);
  input->delaunay_seconds = delaunay_seconds(input->points);
  return input;
}

// A synthetic scene: its points, the points of its buildings (plane index not 0, the ground)
// as the measured ones, and its truth.
std::unique_ptr<Input> synthetic_input(const Test::Scene& scene, const Test::Sampling_options& sampling)
{
  auto input = std::make_unique<Input>();
  input->name = scene.name;
  input->points = Test::sample_scene(scene, sampling);
  for(const Sample& sample : input->points)
    if(sample.plane_index != 0) input->measured.push_back(sample.point);
  input->truth_samples = Test::sample_triangles(Test::triangles_of(Test::scene_mesh(scene, Test::ROOF + Test::WALL)), 4);
  input->truth = std::make_unique<Test::Distance_to_mesh>(
    Test::scene_mesh(scene, Test::ROOF + Test::WALL + Test::FLOOR + Test::GROUND));
  input->delaunay_seconds = delaunay_seconds(input->points);
  return input;
}

// False for a command line it does not understand.
bool parse_options(int argc, char** argv, Options& options)
{
  options.sampling.density = 10;
  for(int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    const bool has_value = i + 1 < argc;
    if(argument == "--peers-only") options.peers_only = true;
    else if(argument == "--json" && has_value) options.json_path = argv[++i];
    else if(argument == "--output" && has_value) options.output_directory = argv[++i];
    else if(argument == "--models") options.write_models = true;
    else if(argument == "--time-limit" && has_value) options.time_limit = std::atof(argv[++i]);
    else if(argument == "--scene" && has_value) options.scenes.push_back(argv[++i]);
    else if(argument == "--density" && has_value) options.sampling.density = std::atof(argv[++i]);
    else if(argument == "--wall-density-factor" && has_value) options.sampling.wall_density_factor = std::atof(argv[++i]);
    else if(argument == "--noise" && has_value) options.sampling.noise = std::atof(argv[++i]);
    else if(argument == "--seed" && has_value) options.sampling.seed = unsigned(std::atol(argv[++i]));
    else if(i == 1 && argument.rfind("--", 0) != 0) options.building_ply = argument;
    else return false;
  }
  return options.sampling.density > 0;
}

// Runs the methods on one input and writes its results: table, JSON lines, models, plot.
void benchmark(const Input& input, const Options& options, std::ofstream& json)
{
  std::printf("# %s: %zu points (%zu measured), Delaunay_triangulation_3 %.3f s\n", input.name.c_str(), input.points.size(),
              input.measured.size(), input.delaunay_seconds);
  const std::filesystem::path directory(options.output_directory);
  const std::vector<Result> results = run_methods(input, options, [&](const Result& result) {
    print_result(result);
    if(json.is_open()) write_json_line(json, result);
    if(options.write_models && !result.failed) {
      std::string name = "lod2_" + result.scene + "_" + result.method + "_" + result.setting + ".off";
      std::replace_if(name.begin(), name.end(), [](char c) { return c == '=' || c == '/'; }, '_');
      CGAL::IO::write_OFF((directory / name).string(), result.model, CGAL::parameters::stream_precision(17));
    }
  });
  write_plot((directory / ("lod2_" + input.name + ".svg")).string(), input.name, results);
}

int main(int argc, char** argv)
{
  Options options;
  if(!parse_options(argc, argv, options)) {
    std::cerr << "usage: " << argv[0] << " [building.ply] [--peers-only] [--json FILE] [--output DIR] [--models]\n"
              << "       [--scene NAME]... [--time-limit SECONDS] [--density POINTS_PER_M2] [--wall-density-factor F]\n"
              << "       [--noise SIGMA_M] [--seed N]\n";
    return 1;
  }
  std::ofstream json;
  if(!options.json_path.empty()) json.open(options.json_path);
  std::error_code ignored;
  std::filesystem::create_directories(options.output_directory, ignored);
  if(!options.json_path.empty() && !json) {
    std::cerr << "cannot write " << options.json_path << "\n";
    return 1;
  }
  auto wanted = [&](const std::string& name) {
    return options.scenes.empty() || std::find(options.scenes.begin(), options.scenes.end(), name) != options.scenes.end();
  };
#ifndef CGAL_USE_GLPK
  std::printf("# built without GLPK: no PolyFit\n");
#endif
  std::printf("# synthetic scenes: %g points/m2, walls x%g, noise %g m, seed %u; times include the dense mesh (QEM, VSA) "
              "and the candidate faces (PolyFit)\n",
              options.sampling.density, options.sampling.wall_density_factor, options.sampling.noise, options.sampling.seed);
  print_header();
  bool unreadable = false;
  if(wanted("building")) {
    const std::unique_ptr<Input> input = read_building(options.building_ply);
    if(input) benchmark(*input, options, json);
    else std::printf("# cannot read %s (points, normals, segment_index)\n", options.building_ply.c_str());
    unreadable = !input;
  }
  using Kind = Test::Scene_kind;
  for(Kind kind : {Kind::GABLE_ROOF, Kind::HIP_ROOF, Kind::L_SHAPED_FLAT_ROOF, Kind::TWO_HEIGHT_FLAT_ROOFS, Kind::SEVERAL_BUILDINGS}) {
    const Test::Scene scene = Test::make_scene(kind);
    if(wanted(scene.name)) benchmark(*synthetic_input(scene, options.sampling), options, json);
  }
  rusage self, children;
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &children);
  std::printf("peak memory: %.1f MB\n", double(std::max(self.ru_maxrss, children.ru_maxrss)) / 1024.);
  return unreadable ? 1 : 0;
}
