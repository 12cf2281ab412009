// lod2_reconstruct: LOD2 building models from a point cloud of buildings and the ground
// around them (planes, 3D segments, kinetic partition, simplification, lift, extrusion).
//
//   lod2_reconstruct INPUT OUTPUT [--planes detect|PROPERTY] [--classes G:B] [--footprints FILE]
//                    [--threads N] [--lambda1 V] [--lambda2 V] [--epsilon V] [--json]
//   mpirun -np K lod2_reconstruct_mpi INPUT OUTPUT ...   (a city tile, its buildings dealt out to K ranks)
//
// INPUT: points as .ply, .xyz, .pwn, .off or uncompressed .las (normals used when present; z is
// vertical). A classified input (a LAS file, or a PLY file with an int or uchar `classification`
// or `label` property) or one given --footprints (GeoJSON polygons) is a city tile: its buildings
// are modelled one at a time, in parallel (lod2_city_reconstruction()), each as an LoD 2.2 solid
// or, where that fails, an LoD 1.2 block. Otherwise the points are one scene
// (lod2_building_reconstruction()); with --planes PROPERTY, the plane of every point is read
// from that integer property of a .ply (-1: no plane), as `segment_index` in CGAL's
// points_3/building.ply. OUTPUT: the model as .off, .ply, .obj, CityJSON 1.1 (.city.json) or,
// for a tile, CityJSON Text Sequences (.city.jsonl). On bad input: a one-line reason, exit code
// 1, no output file.
// Under MPI (lod2_reconstruct_mpi, built when CMake finds MPI) every rank reads the tile and
// splits it into buildings; the buildings are dealt out to the ranks by their numbers of points
// (the building_filter of lod2_city_reconstruction()), each rank models its own, and the first
// rank gathers them, writes the output (byte for byte that of one process) and prints the JSON
// and the errors. A scene runs on one rank only.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Lex_optimal_chains/IO/read_las_points.h>
#include <CGAL/Lex_optimal_chains/internal/PLY_structure_check.h>
#include <CGAL/Polygon_partition_simplification/IO/CityJSON.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/lod2_building_reconstruction.h>
#include <CGAL/lod2_city_reconstruction.h>

#include "City_building_bytes.h"
#include "GeoJSON_footprints.h"
#include "Process_group.h"
#include "Temporary_output_files.h"
#include "lod2_reconstruct_command_line.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_set = CGAL::Point_set_3<K::Point_3, K::Vector_3>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using lod2_reconstruct::ends_with;
using lod2_reconstruct::Options;
namespace PPS = CGAL::Polygon_partition_simplification;

static Point_set read_points(const std::string& input)
{
  if(!(ends_with(input, ".ply") || ends_with(input, ".xyz") || ends_with(input, ".pwn") || ends_with(input, ".off")))
    throw std::runtime_error("INPUT must be a .ply, .xyz, .pwn, .off or .las point cloud: " + input);
  std::ifstream probe(input);
  if(!probe) throw std::runtime_error("cannot read " + input);
  // a PLY file that CGAL's reader cannot read safely (a property before any element, counts
  // the data cannot hold, coordinates and normals not all float or all double) is refused first
  if(ends_with(input, ".ply"))
    CGAL::Lex_optimal_chains::internal::check_PLY_structure(input, {"x", "y", "z", "nx", "ny", "nz"}, true);
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
  const urban_programs::Temporary_output_file interrupted(temporary);
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

// ---- city tiles: classified points, footprints, one model per building ----

// A point of a city tile: its position, its normal (zero when the input has none) and its class.
struct Tile_point
{
  K::Point_3 point;
  K::Vector_3 normal = CGAL::NULL_VECTOR;
  int classification = 0;
};
struct Tile_position_map
{
  using key_type = Tile_point; using value_type = K::Point_3; using reference = const K::Point_3&;
  using category = boost::readable_property_map_tag;
  friend reference get(Tile_position_map, const Tile_point& p) { return p.point; }
};
struct Tile_normal_map
{
  using key_type = Tile_point; using value_type = K::Vector_3; using reference = const K::Vector_3&;
  using category = boost::readable_property_map_tag;
  friend reference get(Tile_normal_map, const Tile_point& p) { return p.normal; }
};
struct Tile_class_map
{
  using key_type = Tile_point; using value_type = int; using reference = int;
  using category = boost::readable_property_map_tag;
  friend int get(Tile_class_map, const Tile_point& p) { return p.classification; }
};

struct Tile
{
  std::vector<Tile_point> points;
  bool has_classes = false, has_normals = false;
};

// the class of each point of a PLY point set: its int or uchar property `classification` or `label`
static bool read_classes(const Point_set& points, std::vector<int>& classes)
{
  for(const char* name : {"classification", "label"}) {
    if(auto map = PPS::internal::optional_property_map(points.property_map<int>(name))) {
      for(auto i : points) classes.push_back((*map)[i]);
      return true;
    }
    if(auto map = PPS::internal::optional_property_map(points.property_map<unsigned char>(name))) {
      for(auto i : points) classes.push_back(int((*map)[i]));
      return true;
    }
  }
  return false;
}

static Tile read_tile(const std::string& input)
{
  Tile tile;
  if(ends_with(input, ".laz"))
    throw std::runtime_error("compressed LAS (LAZ) is not supported: decompress it first (laszip, or pdal translate in.laz out.las): " + input);
  if(ends_with(input, ".las")) {
    try {
      CGAL::Lex_optimal_chains::IO::for_each_las_record<K::Point_3>(input, [&](const K::Point_3& p, int c) {
        tile.points.push_back({p, CGAL::NULL_VECTOR, c});
      });
    } catch(const std::exception& e) {
      throw std::runtime_error(e.what());
    }
    if(tile.points.empty()) throw std::runtime_error("no point in " + input);
    tile.has_classes = true;
    return tile;
  }
  const Point_set points = read_points(input);
  std::vector<int> classes;
  tile.has_classes = read_classes(points, classes);
  tile.has_normals = points.has_normal_map();
  std::size_t k = 0;
  for(auto i : points) {
    tile.points.push_back({points.point(i), tile.has_normals ? points.normal(i) : CGAL::NULL_VECTOR,
                           tile.has_classes ? classes[k] : 0});
    ++k;
  }
  return tile;
}

using Polygon_with_holes = CGAL::Polygon_with_holes_2<K>;

// the polygons of a GeoJSON FeatureCollection (Polygon and MultiPolygon features), in file order
static std::vector<Polygon_with_holes> read_footprints(const std::string& path)
{
  std::ifstream in(path);
  if(!in) throw std::runtime_error("cannot read the footprints " + path);
  return lod2_reconstruct::read_GeoJSON_footprints<K>(in, path);
}

using City_building = PPS::City_building<K::Point_3>;

// one mesh of the best model of every building, with the face property f:building
static Mesh best_models(const std::vector<City_building>& buildings)
{
  Mesh all;
  auto owner = all.add_property_map<Mesh::Face_index, int>("f:building", 0).first;
  for(const auto& b : buildings) {
    const Mesh& model = b.status == PPS::Building_model_status::LOD22 ? b.lod22 : b.lod12;
    const std::size_t first = all.number_of_vertices();
    for(auto v : model.vertices()) all.add_vertex(model.point(v));
    for(auto f : model.faces()) {
      std::vector<Mesh::Vertex_index> corners;
      for(auto v : CGAL::vertices_around_face(model.halfedge(f), model))
        corners.push_back(Mesh::Vertex_index(Mesh::size_type(first + std::size_t(v))));
      owner[all.add_face(corners)] = int(b.id);
    }
  }
  return all;
}

// the city model written to a temporary file, renamed to `output` once complete
static void write_city(const std::vector<City_building>& buildings, const std::string& output)
{
  const std::string temporary = output + ".partial";
  const urban_programs::Temporary_output_file interrupted(temporary);
  bool written = false;
  if(ends_with(output, ".city.json") || ends_with(output, ".city.jsonl")) {
    std::ofstream out(temporary, std::ios::binary);
    written = (ends_with(output, ".city.json") ? PPS::IO::write_CityJSON(out, buildings)
                                                : PPS::IO::write_CityJSON_sequence(out, buildings)) && out.good();
  } else if(ends_with(output, ".ply")) { // CGAL's PLY writer of a Surface_mesh keeps the int property f:building
    std::ofstream out(temporary, std::ios::binary);
    CGAL::IO::set_binary_mode(out);
    written = CGAL::IO::write_PLY(out, best_models(buildings)) && out.good();
  } else {
    const std::string named = temporary + output.substr(output.rfind('.'));
    const urban_programs::Temporary_output_file interrupted_named(named);
    Mesh all = best_models(buildings);
    written = CGAL::IO::write_polygon_mesh(named, all, CGAL::parameters::stream_precision(17)) &&
              std::rename(named.c_str(), temporary.c_str()) == 0;
  }
  if(!written || std::rename(temporary.c_str(), output.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + output);
  }
}

static nlohmann::json city_statistics(const PPS::LOD2_city_report& r)
{
  nlohmann::json j;
  j["points"] = r.points;
  j["building_points"] = r.building_points;
  j["ground_points"] = r.ground_points;
  j["spacing"] = r.spacing;
  j["buildings"] = r.buildings;
  j["buildings_valid"] = r.buildings_valid;
  j["buildings_lod12_fallback"] = r.buildings_lod12_fallback;
  j["clusters_too_small"] = r.clusters_too_small;
  j["footprints_without_points"] = r.footprints_without_points;
  j["buildings_per_s"] = r.seconds > 0 ? double(r.buildings) / r.seconds : 0.;
  j["split_s"] = r.split_seconds;
  j["planes_s"] = r.planes_seconds;
  j["segments_s"] = r.segments_seconds;
  j["partition_s"] = r.partition_seconds;
  j["simplification_s"] = r.simplification_seconds;
  j["lift_s"] = r.lift_seconds;
  j["extrusion_s"] = r.extrusion_seconds;
  j["validation_s"] = r.validation_seconds;
  j["buildings_s"] = r.buildings_seconds;
  j["total_s"] = r.seconds;
  return j;
}

static double peak_rss_mb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

// ---- the buildings of a tile over the processes of one command (MPI ranks, or one process) ----

// An error already reported by another rank: this rank exits with code 1 and says nothing.
struct Reported_by_another_rank : std::runtime_error
{
  Reported_by_another_rank() : std::runtime_error("reported by another rank") {}
};

// Every rank calls this with the error it met, if any. If some rank met one, the lowest such
// rank throws it and the others throw Reported_by_another_rank: one line on stderr.
static void settle_errors(const Process_group& group, const std::exception_ptr& error)
{
  const long long none = static_cast<long long>(group.size());
  const long long reporter = group.min(error ? static_cast<long long>(group.rank()) : none);
  if(reporter == none) return;
  if(reporter == static_cast<long long>(group.rank())) std::rethrow_exception(error);
  throw Reported_by_another_rank();
}


// What one rank makes of a tile: the deal of all its buildings, and the buildings of this rank
struct City_share
{
  std::vector<std::size_t> ids, ranks; // every building of the tile, by increasing id, and its rank
  std::vector<City_building> buildings;
  PPS::LOD2_city_report report;
};

// every rank splits the tile; the building filter keeps the buildings dealt to this rank
template <class NamedParameters>
static City_share model_share(const Tile& tile, const std::vector<Polygon_with_holes>& footprints,
                              const Process_group& group, const NamedParameters& np)
{
  City_share share;
  auto mine = [&share, &group](const std::vector<std::size_t>& ids, const std::vector<std::size_t>& points) {
    share.ids = ids;
    share.ranks = group.deal(points); // the same deal on every rank: by points, largest first
    std::vector<bool> keep(ids.size());
    for(std::size_t b = 0; b < ids.size(); ++b) keep[b] = share.ranks[b] == group.rank();
    return keep;
  };
  const auto filtered = PPS::parameters::building_filter(mine, np);
  auto run = [&](const auto& parameters) {
    if(tile.has_normals)
      return CGAL::lod2_city_reconstruction(tile.points, share.buildings, parameters.normal_map(Tile_normal_map()));
    return CGAL::lod2_city_reconstruction(tile.points, share.buildings, parameters);
  };
  if(!tile.has_classes) share.report = run(PPS::parameters::footprints(footprints, filtered));
  else if(footprints.empty()) share.report = run(PPS::parameters::classification_map(Tile_class_map(), filtered));
  else share.report = run(PPS::parameters::footprints(footprints, PPS::parameters::classification_map(Tile_class_map(), filtered)));
  return share;
}

// The report of the tile on every rank: the counts and times of the buildings summed over the
// ranks, the wall-clock times of the slowest rank (the counts of the tile are those of every rank).
static void gather_city_reports(const Process_group& group, PPS::LOD2_city_report& r)
{
  std::vector<double> v = group.sum({double(r.buildings), double(r.buildings_valid), double(r.buildings_lod12_fallback),
                                     r.planes_seconds, r.segments_seconds, r.partition_seconds, r.simplification_seconds,
                                     r.lift_seconds, r.extrusion_seconds, r.validation_seconds});
  r.buildings = std::size_t(v[0]);
  r.buildings_valid = std::size_t(v[1]);
  r.buildings_lod12_fallback = std::size_t(v[2]);
  r.planes_seconds = v[3];
  r.segments_seconds = v[4];
  r.partition_seconds = v[5];
  r.simplification_seconds = v[6];
  r.lift_seconds = v[7];
  r.extrusion_seconds = v[8];
  r.validation_seconds = v[9];
  r.split_seconds = group.max(r.split_seconds);
  r.buildings_seconds = group.max(r.buildings_seconds);
  r.seconds = group.max(r.seconds);
}

// On the first rank, the buildings of the other ranks (`parts`) added to its own, by increasing
// id; each building of the deal must come once.
static void add_gathered_buildings(const std::vector<std::string>& parts, City_share& share)
{
  for(std::size_t r = 1; r < parts.size(); ++r) city_buildings_from_bytes(parts[r], share.buildings);
  std::sort(share.buildings.begin(), share.buildings.end(),
            [](const City_building& a, const City_building& b) { return a.id < b.id; });
  bool each_once = share.buildings.size() == share.ids.size();
  for(std::size_t b = 0; each_once && b < share.ids.size(); ++b) each_once = share.buildings[b].id == share.ids[b];
  if(!each_once) throw std::runtime_error("the ranks did not model each building of the tile once: do they all read the same input?");
}

// The buildings of every rank gathered on the first, which lists the fallbacks and their reasons
// on std::cerr, writes the output and returns the statistics (the other ranks return nothing).
static nlohmann::json write_gathered_city(const Process_group& group, City_share& share, const std::string& output)
{
  gather_city_reports(group, share.report);
  std::vector<std::string> parts;
  if(group.size() > 1) parts = group.gather(group.is_root() ? std::string() : city_buildings_to_bytes(share.buildings));
  const double peak_mb = group.max(peak_rss_mb());
  if(!group.is_root()) return nlohmann::json();
  add_gathered_buildings(parts, share);
  for(const auto& b : share.buildings)
    if(!b.reason.empty()) std::cerr << "lod2_reconstruct: building " << b.id << ": LoD 1.2 only: " << b.reason << std::endl;
  write_city(share.buildings, output);
  nlohmann::json j = city_statistics(share.report);
  std::vector<std::size_t> per_rank(group.size(), 0);
  for(std::size_t r : share.ranks) ++per_rank[r];
  j["ranks"] = group.size();
  j["buildings_per_rank"] = per_rank;
  j["peak_rss_mb"] = std::max(peak_mb, peak_rss_mb());
  return j;
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
  const auto property = PPS::internal::optional_property_map(points.property_map<int>(planes));
  if(!property) throw std::runtime_error("the points have no int property '" + planes + "'");
  return with_normals(base.plane_index_map(*property));
}

static nlohmann::json scene_statistics(const PPS::LOD2_report& report)
{
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
  return j;
}

// the whole point cloud as one scene (lod2_building_reconstruction())
template <class NamedParameters>
static nlohmann::json reconstruct_scene(const std::string& input, const std::string& planes, const std::string& output,
                                        const NamedParameters& np)
{
  if(ends_with(output, ".city.jsonl")) throw std::runtime_error("OUTPUT .city.jsonl is for city tiles (classified points or --footprints)");
  const Point_set points = read_points(input);
  Mesh model;
  const PPS::LOD2_report report = reconstruct(points, planes, model, np);
  if(report.buildings == 0) throw std::runtime_error("no building found in " + input + ": no roof stands above the ground");
  write_model(model, output);
  return scene_statistics(report);
}

// The command on every rank: the checks, the input, and the model of a scene (on one rank) or
// this rank's buildings of a tile, which the first rank then gathers and writes. Returns the
// statistics on the first rank.
static nlohmann::json run(const Options& o, const Process_group& group)
{
  std::exception_ptr error;
  nlohmann::json j;
  City_share share;
  bool city = false;
  try {
    const std::vector<Polygon_with_holes> footprints = o.footprints_file.empty() ? std::vector<Polygon_with_holes>()
                                                                                 : read_footprints(o.footprints_file);
    const auto base = PPS::parameters::concurrency_weight(
      o.lambda1, PPS::parameters::orthogonality_weight(o.lambda2, PPS::parameters::walls_at_facades(!o.walls_at_eaves)));
    const bool tile_input = ends_with(o.input, ".las") || ends_with(o.input, ".laz") || !footprints.empty();
    Tile tile;
    if(tile_input || ends_with(o.input, ".ply")) tile = read_tile(o.input);
    city = tile.has_classes || !footprints.empty();
    if(!city && group.size() > 1)
      throw std::runtime_error("only city tiles (classified points or --footprints) run on several MPI ranks (" +
                               std::to_string(group.size()) + " here): run a scene on one");
    auto model = [&](const auto& np) {
      const auto city_np = PPS::parameters::ground_classes(
        o.ground_classes, PPS::parameters::building_classes(o.building_classes, PPS::parameters::number_of_threads(o.threads, np)));
      if(city) share = model_share(tile, footprints, group, city_np.point_map(Tile_position_map()));
      else j = reconstruct_scene(o.input, o.planes, o.output, np);
    };
    if(o.epsilon > 0) model(PPS::parameters::collapse_distance(o.epsilon, base));
    else model(base);
  } catch(...) {
    error = std::current_exception();
  }
  settle_errors(group, error);
  if(city) return write_gathered_city(group, share, o.output);
  j["peak_rss_mb"] = peak_rss_mb();
  return j;
}

int main(int argc, char** argv)
{
  Process_group group(argc, argv); // MPI_Init under lod2_reconstruct_mpi
  lod2_reconstruct::Command_line command_line;
  try {
    command_line.parse(argc, argv);
  } catch(const CLI::CallForHelp& e) { // printed once
    return group.is_root() ? command_line.app.exit(e) : 0;
  } catch(const CLI::ParseError& e) { // one line and exit code 1, as for bad input
    if(group.is_root()) std::cerr << "lod2_reconstruct: error: " << e.what() << " (see --help)" << std::endl;
    return 1;
  }
  const lod2_reconstruct::Options& o = command_line.options;
  try {
    const nlohmann::json j = run(o, group);
    if(!group.is_root()) return 0;
    if(o.json) std::cout << j.dump() << std::endl;
    else std::cout << j["buildings"] << " buildings; model written to " << o.output << std::endl;
  } catch(const Reported_by_another_rank&) {
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "lod2_reconstruct: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
