// lod2_reconstruct: LOD2 building models from a point cloud of buildings and the ground
// around them (planes, 3D segments, kinetic partition, simplification, lift, extrusion).
//
//   lod2_reconstruct INPUT OUTPUT [--planes detect|PROPERTY] [--lambda1 V] [--lambda2 V]
//                    [--epsilon V] [--json]
//
// INPUT: points as .ply, .xyz or .off (normals used when present; z is vertical). With
// --planes PROPERTY, the plane of every point is read from that integer property of a .ply
// (-1: no plane), as `segment_index` in CGAL's points_3/building.ply. OUTPUT: the model as .off,
// .ply, .obj, or CityJSON 1.1 when the name ends in .city.json. On bad input: a one-line reason,
// exit code 1, no output file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Polygon_partition_simplification/IO/CityJSON.h>
#include <CGAL/lod2_building_reconstruction.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_set = CGAL::Point_set_3<K::Point_3, K::Vector_3>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PPS = CGAL::Polygon_partition_simplification;

static bool ends_with(const std::string& s, const std::string& end)
{
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

static Point_set read_points(const std::string& input)
{
  if(!(ends_with(input, ".ply") || ends_with(input, ".xyz") || ends_with(input, ".off")))
    throw std::runtime_error("INPUT must be a .ply, .xyz or .off point cloud: " + input);
  std::ifstream probe(input);
  if(!probe) throw std::runtime_error("cannot read " + input);
  Point_set points;
  // CGAL's readers report a bad line on std::cerr: it is kept out of the one-line reason
  std::ostringstream reader_messages;
  std::streambuf* cerr_buffer = std::cerr.rdbuf(reader_messages.rdbuf());
  const bool read = CGAL::IO::read_point_set(input, points);
  std::cerr.rdbuf(cerr_buffer);
  if(!read) throw std::runtime_error("cannot read the points of " + input);
  if(points.empty()) throw std::runtime_error("no point in " + input);
  return points;
}

// the model written to a temporary file, renamed to `output` once complete
static void write_model(const Mesh& model, const std::string& output)
{
  const std::string temporary = output + ".partial" + output.substr(output.rfind('.'));
  bool written = false;
  if(ends_with(output, ".city.json")) {
    std::ofstream out(temporary);
    written = PPS::IO::write_CityJSON(out, model) && out.good();
  } else {
    written = CGAL::IO::write_polygon_mesh(temporary, model, CGAL::parameters::stream_precision(17));
  }
  if(!written || std::rename(temporary.c_str(), output.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + output);
  }
}

template <class NamedParameters>
static PPS::LOD2_report reconstruct(const Point_set& points, const std::string& planes, Mesh& model,
                                    const NamedParameters& np)
{
  auto with_normals = [&](const auto& parameters) {
    if(points.has_normal_map()) return CGAL::lod2_building_reconstruction(points, model, parameters.normal_map(points.normal_map()));
    return CGAL::lod2_building_reconstruction(points, model, parameters);
  };
  const auto base = np.point_map(points.point_map());
  if(planes == "detect") return with_normals(base);
  auto property = points.property_map<int>(planes);
  if(!property.second) throw std::runtime_error("the points have no int property '" + planes + "'");
  return with_normals(base.plane_index_map(property.first));
}

int main(int argc, char** argv)
{
  CLI::App app{"LOD2 building models from a point cloud (planes, segments, kinetic partition, simplification, lift)"};
  std::string input, output, planes = "detect";
  double lambda1 = 0.5, lambda2 = 5, epsilon = 0;
  bool json = false, walls_at_eaves = false;
  app.add_option("INPUT", input, "points: .ply, .xyz or .off")->required();
  app.add_option("OUTPUT", output, "model: .off, .ply, .obj, or .city.json (CityJSON 1.1)")->required();
  app.add_option("--planes", planes, "detect (region growing, default) or the name of an int point property giving the plane of each point");
  app.add_option("--lambda1", lambda1, "weight of the concurrency term of the simplification, default 0.5");
  app.add_option("--lambda2", lambda2, "weight of the orthogonality term, default 5");
  app.add_option("--epsilon", epsilon, "longest edge to collapse in the simplification, input units (default: 1% of the half-diagonal)");
  app.add_flag("--walls-at-eaves", walls_at_eaves,
               "put the walls at the edges of the roofs, as seen from above (default: on the facades, where facade points show them)");
  app.add_flag("--json", json, "print one line of JSON statistics");
  CLI11_PARSE(app, argc, argv);
  try {
    if(!(ends_with(output, ".off") || ends_with(output, ".ply") || ends_with(output, ".obj") || ends_with(output, ".city.json")))
      throw std::runtime_error("OUTPUT must end in .off, .ply, .obj or .city.json: " + output);
    const Point_set points = read_points(input);
    Mesh model;
    const auto np = PPS::parameters::concurrency_weight(
      lambda1, PPS::parameters::orthogonality_weight(lambda2, PPS::parameters::walls_at_facades(!walls_at_eaves)));
    const PPS::LOD2_report report = epsilon > 0 ? reconstruct(points, planes, model, PPS::parameters::collapse_distance(epsilon, np))
                                                : reconstruct(points, planes, model, np);
    write_model(model, output);
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    if(json) {
      nlohmann::json j;
      j["points"] = report.points;
      j["planes"] = report.planes;
      j["roof_planes"] = report.roof_planes;
      j["segments"] = report.segments;
      j["facade_segments"] = report.facade_segments;
      j["cells_before"] = report.cells_before;
      j["cells_after"] = report.cells_after;
      j["buildings"] = report.buildings;
      j["faces"] = report.faces;
      j["roof_faces"] = report.roof_faces;
      j["wall_faces"] = report.wall_faces;
      j["closed"] = report.closed;
      j["bounds_volume"] = report.bounds_volume;
      j["repaired_buildings"] = report.repaired_buildings;
      j["rms_m"] = report.rms_distance;
      j["max_m"] = report.maximum_distance;
      j["measured_points"] = report.measured_points;
      j["planes_s"] = report.planes_seconds;
      j["segments_s"] = report.segments_seconds;
      j["partition_s"] = report.partition_seconds;
      j["simplification_s"] = report.simplification_seconds;
      j["lift_s"] = report.lift_seconds;
      j["extrusion_s"] = report.extrusion_seconds;
      j["total_s"] = report.seconds;
      j["peak_rss_mb"] = double(usage.ru_maxrss) / 1024.0;
      std::cout << j.dump() << std::endl;
    } else {
      std::cout << report.buildings << " buildings, " << report.faces << " faces ("
                << (report.closed ? "closed" : "NOT closed") << "), RMS distance " << report.rms_distance
                << "; model written to " << output << std::endl;
    }
  } catch(const std::exception& e) {
    std::cerr << "lod2_reconstruct: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
