// lex_reconstruct: surface reconstruction from a point cloud as a lexicographic optimal chain.
//
//   lex_reconstruct closed INPUT OUTPUT [--interior X,Y,Z]... [--exterior X,Y,Z]...
//                   [--min-persistence V] [--robust [--smoothing-neighbors K]]
//                   [--keep-non-manifold] [--threads N] [--ascii] [--json]
//   lex_reconstruct open INPUT OUTPUT (--boundary FILE | --auto-boundary)
//                   [--coefficients z2|q] [--remove-blocking-points]
//                   [--drop-boundary-triangles | --keep-boundary-triangles] [--keep-non-manifold]
//                   [--threads N] [--ascii] [--json]
//   lex_reconstruct tiles INPUT OUTPUT_DIR --tile-size S [--seam-spacing V] [--merged FILE]
//                   [--classes C,...] [--out-of-core [--bucket-dir DIR]] [--coefficients z2|q]
//                   [--keep-non-manifold] [--threads N] [--ascii] [--json]
//   mpirun -np K lex_reconstruct_mpi tiles ...   (the same, the tiles dealt out to K ranks)
//   lex_reconstruct features INPUT OUTPUT [--threshold V] [--offset E] [--drop-largest K]
//                   [--borders] [--relative] [--ascii] [--json]
//
// INPUT: points as XYZ, PLY, OFF or uncompressed LAS (1.0 to 1.4; --classes keeps the points of
// these classifications). OUTPUT: a mesh as OFF, PLY (binary unless --ascii) or
// OBJ, by extension.
// Boundary FILE: CGAL's polylines text format, one closed polyline per line:
// "n x1 y1 z1 ... xn yn zn" with the last point equal to the first.
// tiles: one mesh per tile in OUTPUT_DIR (created if missing), tile_C_R.ply for the tile of
// column C and row R, and with --merged their union, welded at the seams. Under MPI
// (lex_reconstruct_mpi, built when CMake finds MPI) every rank reads the input and computes
// the seams; the tiles are dealt out to the ranks (balanced by their points), each rank
// writes its own; the first rank then makes the union from the tile files. The files are
// byte for byte those of one process. --out-of-core reads the input twice and buckets it
// into files, one per tile, so that the cloud is never in memory: the same tiles.
// features: the critical basis of the relative 2-cycles around sharp features (thesis section
// 4.8.3); a binary PLY output has the element of each face as the int face property `element`.
// On error: a one-line reason on stderr, exit code 1, and no output file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/lex_optimal_closed_surface.h>
#include <CGAL/lex_optimal_feature_reconstruction.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/lex_optimal_tiled_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>
#include <CGAL/Lex_optimal_chains/IO/input_files.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include "Peak_memory.h"
#include "Process_group.h"

#include <CLI/CLI.hpp>
#include <boost/timer/progress_display.hpp>
#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;

static double peak_rss_mb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0; // kilobytes on Linux
}

static Point parse_point(const std::string& text)
{
  std::istringstream in(text);
  double c[3];
  char sep1 = 0, sep2 = 0;
  if(!(in >> c[0] >> sep1 >> c[1] >> sep2 >> c[2]) || sep1 != ',' || sep2 != ',' || !in.eof())
    throw std::invalid_argument("'" + text + "' is not a point X,Y,Z");
  return Point(c[0], c[1], c[2]);
}

static std::string lower_extension(const std::string& path)
{
  std::string e = std::filesystem::path(path).extension().string();
  for(char& ch : e) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return e;
}

// components, border loops and genus of the written mesh (sum over the components of
// (2 - chi - border loops) / 2)
struct Mesh_topology
{
  std::size_t components = 0, border_edges = 0, border_loops = 0;
  long genus = 0;
};

static Mesh_topology topology(const Mesh& mesh)
{
  Mesh_topology t;
  {
    Mesh copy = mesh; // the component map is a property of the mesh
    auto fcc = copy.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
    t.components = CGAL::Polygon_mesh_processing::connected_components(copy, fcc);
  }
  std::vector<char> seen(mesh.number_of_halfedges(), 0);
  for(Mesh::Halfedge_index h : mesh.halfedges()) {
    if(!mesh.is_border(h)) continue;
    ++t.border_edges;
    if(seen[h]) continue;
    ++t.border_loops;
    for(Mesh::Halfedge_index g = h; !seen[g]; g = mesh.next(g)) seen[g] = 1;
  }
  const long chi = long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
  t.genus = (2 * long(t.components) - chi - long(t.border_loops)) / 2;
  return t;
}

struct Progress_bar
{
  std::unique_ptr<boost::timer::progress_display> bar;
  Progress_bar() { if(isatty(STDERR_FILENO)) bar.reset(new boost::timer::progress_display(100, std::cerr)); }
  std::function<bool(double)> callback()
  {
    return [this](double x) {
      if(bar) {
        const unsigned long target = (unsigned long)(x * 100);
        while(bar->count() < target) ++(*bar);
      }
      return true;
    };
  }
};

// A triangle mesh as binary little-endian PLY, byte for byte what CGAL's writer gives but for
// the comment line (double x y z per vertex, a uchar-counted int list per face, the corners
// from the target of the face's half-edge), written through a buffer. CGAL's writer makes one
// stream write per value, which is slow on millions of triangles (the manual, section
// "Usage", gives the times).
static bool write_binary_ply(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* face_element = nullptr)
{
  const std::uint16_t probe = 1;
  char first_byte;
  std::memcpy(&first_byte, &probe, 1);
  if(first_byte != 1) return CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::use_binary_mode(true)); // big-endian
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment Generated by lex_reconstruct\nelement vertex "
      << mesh.number_of_vertices() << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
      << mesh.number_of_faces() << "\nproperty list uchar int vertex_indices\n"
      << (face_element ? "property int element\n" : "") << "end_header\n";
  // the records go through a buffer of 1 MiB, written when full (a buffer of the whole file
  // would be fresh memory: a page fault every 4 KiB)
  std::vector<char> buffer(1 << 20);
  std::size_t used = 0;
  auto append = [&](const void* bytes, std::size_t size) {
    if(used + size > buffer.size()) {
      out.write(buffer.data(), std::streamsize(used));
      used = 0;
    }
    std::memcpy(buffer.data() + used, bytes, size);
    used += size;
  };
  std::vector<std::int32_t> index(mesh.num_vertices(), -1); // over the vertex range, removed ones included
  std::int32_t next = 0;
  for(const Mesh::Vertex_index v : mesh.vertices()) {
    index[v] = next++;
    const Point& p = mesh.point(v);
    const double xyz[3] = {p.x(), p.y(), p.z()};
    append(xyz, sizeof(xyz));
  }
  for(const Mesh::Face_index f : mesh.faces()) {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    if(mesh.next(mesh.next(mesh.next(h))) != h) return false; // not a triangle
    char record[17];
    record[0] = 3;
    const std::int32_t corners[3] = {index[mesh.target(h)], index[mesh.target(mesh.next(h))], index[mesh.source(h)]};
    std::memcpy(record + 1, corners, sizeof(corners));
    if(face_element) std::memcpy(record + 13, &(*face_element)[f], sizeof(std::int32_t));
    append(record, face_element ? 17 : 13);
  }
  out.write(buffer.data(), std::streamsize(used));
  return bool(out.flush());
}

// The mesh is written under a temporary name with the same extension, renamed on success.
class Output_file
{
public:
  explicit Output_file(const std::string& output) : output_(output)
  {
    const std::filesystem::path out_path(output);
    tmp_ = (out_path.parent_path() / ("." + out_path.stem().string() + ".partial" + out_path.extension().string())).string();
    const std::string out_ext = lower_extension(output);
    if(out_ext != ".off" && out_ext != ".ply" && out_ext != ".obj")
      throw std::invalid_argument("output '" + output + "' must end in .off, .ply or .obj");
    // checked before the reconstruction: the file is created (empty) and removed at the end
    // unless it is written
    if(!std::ofstream(tmp_))
      throw std::runtime_error("cannot write '" + output + "' (no such directory, or no permission)");
  }
  ~Output_file() { std::error_code ignored; std::filesystem::remove(tmp_, ignored); }
  // `face_element` (indexed by face): an int property `element` of the faces of a binary PLY file
  void write(const Mesh& mesh, bool ascii, const std::vector<std::int32_t>* face_element = nullptr)
  {
    const bool written = !ascii && lower_extension(output_) == ".ply"
                           ? write_binary_ply(tmp_, mesh, face_element)
                           : CGAL::IO::write_polygon_mesh(tmp_, mesh, CGAL::parameters::stream_precision(17).use_binary_mode(!ascii));
    if(!written)
      throw std::runtime_error("cannot write '" + output_ + "'");
    std::filesystem::rename(tmp_, output_);
  }
private:
  std::string output_, tmp_;
};

// the options common to both subcommands
struct Output_options
{
  unsigned threads = 1;
  bool keep_non_manifold = false, ascii = false, json = false;
};

static void add_output_options(CLI::App* command, Output_options& options)
{
  command->add_flag("--keep-non-manifold", options.keep_non_manifold,
                    "keep the optimal chain as it is: its non-manifold vertices and edges are split in the mesh "
                    "instead of resolved by local changes of the chain");
  command->add_option("--threads", options.threads, "threads for the Delaunay triangulation (tiles: tiles reconstructed at once)")->check(CLI::Range(1u, 1024u));
  command->add_flag("--ascii", options.ascii, "write a .ply mesh as text (binary by default)");
  command->add_flag("--json", options.json, "print one JSON line of statistics on stdout");
}

static void add_mesh_statistics(nlohmann::json& j, const Mesh& mesh)
{
  const Mesh_topology t = topology(mesh);
  j["vertices"] = mesh.number_of_vertices();
  j["faces"] = mesh.number_of_faces();
  j["components"] = t.components;
  j["boundary_edges"] = t.border_edges;
  j["boundary_loops"] = t.border_loops;
  j["closed"] = t.border_edges == 0 && mesh.number_of_faces() > 0;
  j["genus"] = t.genus;
}

// the keys common to both subcommands: the run, its shared timings, and the written mesh
template <class Report>
static void add_common_statistics(nlohmann::json& j, const std::string& input, const std::string& output,
                                  const Report& r, double io_seconds, const Mesh& mesh)
{
  j["input"] = input;
  j["output"] = output;
  j["points"] = r.number_of_input_points;
  j["delaunay_s"] = r.delaunay_seconds;
  j["order_s"] = r.order_seconds;
  j["resolution_s"] = r.resolution_seconds;
  j["mesh_s"] = r.output_seconds;
  j["write_s"] = io_seconds;
  j["output_s"] = r.output_seconds + io_seconds;
  j["total_s"] = r.total_seconds + io_seconds;
  j["peak_rss_mb"] = peak_rss_mb();
  add_mesh_statistics(j, mesh);
  j["non_manifold_vertices"] = r.non_manifold_vertices;
  j["non_manifold_edges"] = r.non_manifold_edges;
  j["resolved_non_manifold_vertices"] = r.resolved_non_manifold_vertices;
  j["resolution_changed_triangles"] = r.resolution_changed_facets;
}

// What the closed subcommand takes besides the output options.
struct Closed_options
{
  std::vector<std::string> interior_text, exterior_text;
  double min_persistence = 0; // 0: not given, the adaptive acceptance of the automatic interior
  bool robust = false;
  std::size_t smoothing_neighbors = 0;
};

static int run_closed(const std::string& input, const std::string& output, const Closed_options& c,
                      const Output_options& options)
{
  Output_file file(output);
  std::vector<Point> interior, exterior;
  for(const std::string& t : c.interior_text) interior.push_back(parse_point(t));
  for(const std::string& t : c.exterior_text) exterior.push_back(parse_point(t));
  const std::vector<Point> points = LOC::IO::read_point_file<Point>(input);
  Progress_bar bar;
  Mesh mesh;
  const auto np = LOC::parameters::interior_points(interior,
                  LOC::parameters::exterior_points(exterior,
                  LOC::parameters::robust(c.robust,
                  LOC::parameters::smoothing_neighbors(c.smoothing_neighbors,
                  LOC::parameters::keep_non_manifold(options.keep_non_manifold,
                  LOC::parameters::number_of_threads(options.threads,
                  LOC::parameters::callback(bar.callback())))))));
  // the adaptive acceptance applies only when no fixed threshold is given
  const LOC::Closed_surface_report r =
    c.min_persistence > 0
      ? CGAL::lex_optimal_closed_surface_reconstruction(points, mesh, LOC::parameters::minimum_interior_persistence(c.min_persistence, np))
      : CGAL::lex_optimal_closed_surface_reconstruction(points, mesh, np);
  CGAL::Real_timer io;
  io.start();
  file.write(mesh, options.ascii);
  io.stop();
  if(options.json) {
    nlohmann::json j;
    add_common_statistics(j, input, output, r, io.time(), mesh);
    j["cut_s"] = r.cut_seconds;
    j["genus"] = r.genus; // of the closed components, as split by the documented rule
    j["automatic_interior"] = r.automatic_interior;
    j["interior_persistence"] = r.interior_persistence;
    j["runner_up_persistence"] = r.runner_up_persistence;
    j["robust"] = r.robust;
    j["scale"] = r.smoothing_neighbors; // k of the jet fits (robust)
    j["smoothing_passes"] = r.smoothing_passes;
    j["noise_estimate"] = r.noise_estimate;
    j["average_spacing"] = r.average_spacing;
    j["smoothing_s"] = r.smoothing_seconds;
    j["points_on_surface"] = r.mesh_vertices; // input points (smoothed, if robust) that the surface goes through
    j["triangles"] = r.number_of_triangles;
    j["exactly_ordered_triangles"] = r.number_of_exactly_ordered_triangles;
    std::cout << j.dump() << std::endl;
  } else {
    std::cerr << "\nwrote " << output << ": " << r.mesh_vertices << " vertices, " << r.mesh_faces << " faces, "
              << r.components << " component(s), genus " << r.genus << "\n";
  }
  return 0;
}

static int run_open(const std::string& input, const std::string& output, const std::string& boundary_file,
                    bool auto_boundary, const std::string& coefficients, bool remove_blocking, bool drop, bool keep,
                    const Output_options& options)
{
  Output_file file(output);
  if(coefficients != "z2" && coefficients != "q")
    throw std::invalid_argument("--coefficients must be z2 or q, not '" + coefficients + "'");
  const std::vector<Point> points = LOC::IO::read_point_file<Point>(input);
  std::vector<std::vector<Point>> boundary;
  if(auto_boundary) boundary.push_back(LOC::footprint_boundary(points));
  else boundary = LOC::IO::read_polyline_file<Point>(boundary_file);
  // the skirt of the automatic boundary is not part of the terrain
  const bool drop_skirt = drop || (auto_boundary && !keep);
  Progress_bar bar;
  Mesh mesh;
  const LOC::Open_surface_report r = CGAL::lex_optimal_open_surface_reconstruction(
    points, boundary, mesh,
    LOC::parameters::coefficient_field(coefficients == "z2" ? LOC::Coefficient_field::Z2 : LOC::Coefficient_field::Q,
    LOC::parameters::remove_blocking_points(remove_blocking,
    LOC::parameters::drop_boundary_triangles(drop_skirt,
    LOC::parameters::keep_non_manifold(options.keep_non_manifold,
    LOC::parameters::number_of_threads(options.threads,
    LOC::parameters::callback(bar.callback())))))));
  CGAL::Real_timer io;
  io.start();
  file.write(mesh, options.ascii);
  io.stop();
  if(r.number_of_multiple_facets > 0)
    std::cerr << "\nwarning: " << r.number_of_multiple_facets
              << " triangles have a coefficient other than 1 or -1: over Q the boundary winds more than once "
                 "around them (loops bounding an annulus must turn in opposite directions); --coefficients z2 "
                 "ignores the orientations\n";
  if(options.json) {
    nlohmann::json j;
    add_common_statistics(j, input, output, r, io.time(), mesh);
    j["coefficients"] = coefficients;
    j["representative_s"] = r.representative_seconds;
    j["optimal_chain_s"] = r.optimal_chain_seconds;
    j["orientation_cuts"] = r.orientation_cuts;
    j["boundary_vertices_added"] = r.number_of_boundary_vertices;
    j["removed_points"] = r.number_of_removed_points;
    j["dropped_triangles"] = r.dropped_triangles;
    j["chain_triangles"] = r.number_of_facets;
    j["multiple_triangles"] = r.number_of_multiple_facets;
    j["triangles"] = r.number_of_triangles;
    std::cout << j.dump() << std::endl;
  } else {
    std::cerr << "\nwrote " << output << ": " << r.mesh_vertices << " vertices, " << r.mesh_faces << " faces ("
              << r.dropped_triangles << " boundary triangles dropped, " << r.number_of_removed_points << " points removed)\n";
  }
  return 0;
}

// What the features subcommand takes besides the output options.
struct Features_options
{
  double threshold = 0.16, offset = 0;
  std::size_t drop_largest = 0;
  bool relative = false, borders = false;
};

static int run_features(const std::string& input, const std::string& output, const Features_options& o,
                        const Output_options& options)
{
  Output_file file(output);
  const std::vector<Point> points = LOC::IO::read_point_file<Point>(input);
  Mesh mesh;
  auto element = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(0)).first;
  const auto np = LOC::parameters::feature_threshold(o.threshold,
                  LOC::parameters::border_features(o.borders,
                  LOC::parameters::relative_to_features(o.relative,
                  LOC::parameters::drop_largest_elements(o.drop_largest,
                  LOC::parameters::face_element_map(element)))));
  const LOC::Feature_reconstruction_report r =
    o.offset > 0 ? CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_offset(o.offset, np))
                 : CGAL::lex_optimal_feature_reconstruction(points, mesh, np);
  std::vector<std::int32_t> face_element(mesh.num_faces(), -1);
  for(Mesh::Face_index f : mesh.faces()) face_element[f] = std::int32_t(element[f]);
  CGAL::Real_timer io;
  io.start();
  file.write(mesh, options.ascii, &face_element);
  io.stop();
  if(options.json) {
    nlohmann::json j;
    j["input"] = input;
    j["output"] = output;
    j["points"] = r.number_of_input_points;
    j["feature_points"] = r.number_of_feature_points;
    j["border_points"] = r.number_of_border_points;
    j["subcomplex_simplices"] = r.subcomplex_vertices + r.subcomplex_edges + r.subcomplex_triangles;
    j["subcomplex_vertices"] = r.subcomplex_vertices;
    j["subcomplex_edges"] = r.subcomplex_edges;
    j["subcomplex_triangles"] = r.subcomplex_triangles;
    j["cycles"] = r.number_of_cycles;
    j["elements"] = r.element_sizes.size();
    j["element_sizes"] = r.element_sizes;
    j["dropped_elements"] = r.number_of_dropped_elements;
    j["faces"] = r.mesh_faces;
    j["average_spacing"] = r.average_spacing;
    j["offset"] = r.offset;
    j["relative"] = o.relative;
    j["delaunay_s"] = r.delaunay_seconds;
    j["feature_s"] = r.feature_seconds;
    j["subcomplex_s"] = r.subcomplex_seconds;
    j["chains_s"] = r.chain_seconds;
    j["basis_s"] = r.basis_seconds;
    j["mesh_s"] = r.mesh_seconds;
    j["write_s"] = io.time();
    j["total_s"] = r.total_seconds + io.time();
    j["peak_rss_mb"] = peak_rss_mb();
    nlohmann::json mj;
    add_mesh_statistics(mj, mesh);
    j["mesh"] = mj;
    std::cout << j.dump() << std::endl;
  } else {
    std::cerr << "wrote " << output << ": " << r.mesh_faces << " faces in " << r.element_sizes.size() - r.number_of_dropped_elements
              << " elements of the critical basis (" << r.number_of_cycles << " cycles around " << r.number_of_feature_points
              << " feature points)\n";
  }
  return 0;
}

// What the tiles subcommand takes besides the output options.
struct Tiles_options
{
  double tile_size = 0, seam_spacing = 0;
  std::string merged, coefficients = "q";
  std::vector<int> classes; // of a LAS input (empty: all)
  bool out_of_core = false;
  std::string bucket_directory; // out of core: where the bucket files go (empty: next to the tiles)
};

// An error already reported by another rank: this rank exits with code 1 and says nothing.
struct Reported_by_another_rank : std::runtime_error
{
  Reported_by_another_rank() : std::runtime_error("reported by another rank") {}
};

// Where an error comes in the order of the work: -1 before the tiles, the tile's row and column
// for the error of a tile (the library names it: "tile (C, R): ..."), none for no error.
constexpr long long no_error = std::numeric_limits<long long>::max();

static long long error_order(const std::exception_ptr& error)
{
  try {
    std::rethrow_exception(error);
  } catch(const std::exception& e) {
    unsigned long column = 0, row = 0;
    if(std::sscanf(e.what(), "tile (%lu, %lu):", &column, &row) == 2) return (static_cast<long long>(row) << 32) + column;
  } catch(...) {
  }
  return -1;
}

// Every rank calls this after a stage, with the error it met (or none). If some rank met one,
// `undo` is called on every rank (each removes what it wrote), then the first error in the
// order of the work (of the lowest rank among equals) is thrown by its rank, and the others
// throw Reported_by_another_rank: one line on stderr, whatever the number of ranks.
static void settle_errors(const Process_group& group, const std::exception_ptr& error, const std::function<void()>& undo)
{
  const long long order = error ? error_order(error) : no_error;
  const long long first = group.min(order);
  if(first == no_error) return;
  undo();
  group.barrier();
  const long long reporter = group.min(order == first ? static_cast<long long>(group.rank()) : no_error);
  if(static_cast<long long>(group.rank()) == reporter) std::rethrow_exception(error);
  throw Reported_by_another_rank();
}

// The output directory of the tiles: an existing one, or one created (by the first rank to
// write a tile) in an existing directory, and removed again if the command fails.
class Tile_directory
{
public:
  Tile_directory(const std::string& directory, const Process_group& group) : directory_(directory)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    existed_ = fs::exists(directory, error);
    if(existed_ && !fs::is_directory(directory, error)) throw std::runtime_error("'" + directory + "' is not a directory");
    const fs::path parent = existed_ ? fs::path(directory) : fs::absolute(fs::path(directory), error).parent_path();
    if(!fs::is_directory(parent, error))
      throw std::runtime_error("cannot create the tile directory '" + directory + "': no directory " + parent.string());
    // writable? (Output_file throws if not; one probe per rank)
    Output_file probe((parent / (".lex_reconstruct_probe_" + std::to_string(group.rank()) + ".ply")).string());
    parent_ = parent.string();
  }
  // the directory that holds the tile directory (or the tile directory itself, if it exists)
  const std::string& parent() const { return parent_; }
  std::string tile_path(std::size_t column, std::size_t row) const
  {
    return (std::filesystem::path(directory_) / ("tile_" + std::to_string(column) + "_" + std::to_string(row) + ".ply")).string();
  }
  void write(const Mesh& mesh, std::size_t column, std::size_t row, bool ascii)
  {
    std::error_code error;
    std::filesystem::create_directory(directory_, error); // false, without error, if another rank made it
    if(error) throw std::runtime_error("cannot create the tile directory '" + directory_ + "' (" + error.message() + ")");
    const std::string path = tile_path(column, row);
    Output_file(path).write(mesh, ascii);
    written_.push_back(path);
  }
  // the tiles this rank wrote
  void remove_written()
  {
    std::error_code error;
    for(const std::string& path : written_) std::filesystem::remove(path, error);
    written_.clear();
  }
  // the directory, if this command created it (once every rank has removed its tiles)
  void remove_if_created()
  {
    std::error_code error;
    if(!existed_) std::filesystem::remove(directory_, error); // only if empty
  }
private:
  std::string directory_, parent_;
  bool existed_ = false;
  std::vector<std::string> written_;
};

// The union of the tiles, from the tile files: so that one process and several ranks, which
// write the same files, make the same union byte for byte.
static LOC::Tile_merge_report merge_tile_files(const Tile_directory& directory, const LOC::Tiled_surface_report& r,
                                               LOC::Coefficient_field field, Mesh& merged)
{
  std::vector<Mesh> tiles(r.tiles.size());
  for(std::size_t t = 0; t < tiles.size(); ++t) {
    const std::string path = directory.tile_path(r.tiles[t].column, r.tiles[t].row);
    if(!CGAL::IO::read_polygon_mesh(path, tiles[t]))
      throw std::runtime_error("cannot read back the tile '" + path + "' for the union");
  }
  LOC::Tile_merge_report m = LOC::merge_tile_meshes(tiles, merged, field);
  merged.collect_garbage(); // the closed pockets removed: the writer numbers the vertices left
  return m;
}

// The report of every rank's tiles and the peak memory of each tile (`tile_peak_bytes`, by
// tile), on every rank: a tile's numbers come from the rank that made it (the others have
// zeros), the times are the largest over the ranks.
static void gather_tile_reports(const Process_group& group, LOC::Tiled_surface_report& r,
                                std::vector<std::size_t>& tile_peak_bytes)
{
  constexpr std::size_t fields = 7;
  std::vector<double> values(fields * r.tiles.size(), 0);
  for(std::size_t t = 0; t < r.tiles.size(); ++t) {
    const LOC::Tile_report& tile = r.tiles[t];
    if(!tile.reconstructed) continue;
    const double v[fields] = {1, double(tile.number_of_points), double(tile.number_of_removed_points),
                              double(tile.mesh_vertices), double(tile.mesh_faces), tile.seconds,
                              double(tile_peak_bytes[t])};
    std::copy(v, v + fields, values.begin() + std::ptrdiff_t(fields * t));
  }
  values = group.sum(values);
  for(std::size_t t = 0; t < r.tiles.size(); ++t) {
    LOC::Tile_report& tile = r.tiles[t];
    const double* v = values.data() + fields * t;
    tile.reconstructed = v[0] > 0;
    tile.number_of_points = std::size_t(v[1]);
    tile.number_of_removed_points = std::size_t(v[2]);
    tile.mesh_vertices = std::size_t(v[3]);
    tile.mesh_faces = std::size_t(v[4]);
    tile.seconds = v[5];
    tile_peak_bytes[t] = std::size_t(v[6]);
  }
  r.seam_seconds = group.max(r.seam_seconds);
  r.tiles_seconds = group.max(r.tiles_seconds);
  r.total_seconds = group.max(r.total_seconds);
}

// `rank_of` and `tile_peak_bytes`: the rank and the peak memory of each tile
static nlohmann::json tiles_json(const std::string& input, const std::string& directory, const Process_group& group,
                                 const LOC::Tiled_surface_report& r, const std::vector<std::size_t>& rank_of,
                                 const std::vector<std::size_t>& tile_peak_bytes, bool memory_measured, bool out_of_core)
{
  nlohmann::json j;
  j["input"] = input;
  j["output"] = directory;
  j["points"] = r.number_of_input_points;
  j["tiles"] = r.tiles.size();
  j["columns"] = r.columns;
  j["rows"] = r.rows;
  j["tile_width"] = r.tile_width;
  j["tile_height"] = r.tile_height;
  j["seam_spacing"] = r.seam_spacing;
  j["seam_points"] = r.number_of_seam_points;
  j["ranks"] = group.size();
  j["threads"] = r.number_of_threads;
  j["seam_s"] = r.seam_seconds;
  j["tiles_s"] = r.tiles_seconds;
  j["tile_memory_measured"] = memory_measured;
  j["out_of_core"] = out_of_core;
  nlohmann::json per_tile = nlohmann::json::array();
  for(std::size_t t = 0; t < r.tiles.size(); ++t) {
    const LOC::Tile_report& tile = r.tiles[t];
    per_tile.push_back({{"column", tile.column}, {"row", tile.row}, {"rank", rank_of[t]}, {"points", tile.number_of_points},
                        {"cycle_vertices", tile.number_of_cycle_vertices}, {"removed_points", tile.number_of_removed_points},
                        {"vertices", tile.mesh_vertices}, {"faces", tile.mesh_faces}, {"seconds", tile.seconds},
                        {"peak_rss_mb", double(tile_peak_bytes[t]) / (1024.0 * 1024.0)}});
  }
  j["per_tile"] = per_tile;
  return j;
}

static int run_tiles(const std::string& input, const std::string& directory, const Tiles_options& t,
                     const Output_options& options, const Process_group& group)
{
  // the checks, on every rank; then the directory is created by the first tile written
  std::unique_ptr<Tile_directory> tile_directory;
  std::unique_ptr<Output_file> merged_file;
  std::exception_ptr error;
  try {
    if(t.coefficients != "z2" && t.coefficients != "q")
      throw std::invalid_argument("--coefficients must be z2 or q, not '" + t.coefficients + "'");
    tile_directory.reset(new Tile_directory(directory, group));
    if(!t.merged.empty() && group.is_root()) merged_file.reset(new Output_file(t.merged));
  } catch(...) {
    error = std::current_exception();
  }
  settle_errors(group, error, [] {});
  const LOC::Coefficient_field field = t.coefficients == "z2" ? LOC::Coefficient_field::Z2 : LOC::Coefficient_field::Q;

  // This rank's share of the tiles: every rank deals the tiles out alike, by their numbers of
  // points (Process_group::deal()), and keeps its own. Each tile is written as soon as it is
  // reconstructed, and freed: the memory is that of the tiles being reconstructed. On an
  // error, the tiles written (and the directory, if created) are removed. With one thread the
  // peak memory of each tile is measured around it (Peak_memory.h).
  const bool measure_memory = options.json && options.threads == 1;
  Tile_peak_memory memory(measure_memory);
  std::vector<std::size_t> rank_of; // the rank of each tile
  auto deal = [&](const std::vector<std::size_t>& points_per_tile) {
    rank_of = group.deal(points_per_tile);
    std::vector<bool> mine(rank_of.size());
    for(std::size_t k = 0; k < mine.size(); ++k) mine[k] = rank_of[k] == group.rank();
    memory.start();
    return mine;
  };
  CGAL::Real_timer io;
  auto write_tile = [&](const LOC::Tile_report& tile, Mesh& mesh) {
    memory.tile_done(tile.column, tile.row);
    io.start();
    tile_directory->write(mesh, tile.column, tile.row, options.ascii);
    mesh = Mesh();
    io.stop();
    memory.visitor_done();
  };
  LOC::Tiled_surface_report r;
  try {
    const auto np = LOC::parameters::seam_spacing(t.seam_spacing,
                    LOC::parameters::coefficient_field(field,
                    LOC::parameters::keep_non_manifold(options.keep_non_manifold,
                    LOC::parameters::number_of_threads(options.threads,
                    LOC::parameters::tile_filter(deal,
                    LOC::parameters::tile_visitor(write_tile))))));
    std::vector<Mesh> tiles;
    if(t.out_of_core) { // the file read twice, the points bucketed into files
      const std::string buckets = t.bucket_directory.empty() ? tile_directory->parent() : t.bucket_directory;
      auto each_point = [&](const auto& f) { LOC::IO::for_each_point_in_file<Point>(input, t.classes, f); };
      r = CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(each_point, t.tile_size, buckets, tiles, np);
    } else {
      const std::vector<Point> points = LOC::IO::read_point_file<Point>(input, t.classes);
      r = CGAL::lex_optimal_tiled_surface_reconstruction(points, t.tile_size, tiles, np);
    }
  } catch(...) {
    error = std::current_exception();
  }
  auto undo = [&] {
    tile_directory->remove_written();
    group.barrier();
    if(group.is_root()) tile_directory->remove_if_created();
  };
  settle_errors(group, error, undo);
  std::vector<std::size_t> tile_peak_bytes(r.tiles.size());
  for(std::size_t k = 0; k < r.tiles.size(); ++k) tile_peak_bytes[k] = memory.tile_peak(r.tiles[k].column, r.tiles[k].row);
  gather_tile_reports(group, r, tile_peak_bytes);
  const double write_s = group.max(io.time());

  // the union, by the first rank, from the files of all (written once every rank is here)
  Mesh merged;
  LOC::Tile_merge_report m;
  CGAL::Real_timer merge_watch, merged_io;
  if(!t.merged.empty() && group.is_root()) {
    try {
      merge_watch.start();
      m = merge_tile_files(*tile_directory, r, field, merged);
      merge_watch.stop();
      merged_io.start();
      merged_file->write(merged, options.ascii);
      merged_io.stop();
    } catch(...) {
      error = std::current_exception();
    }
  }
  settle_errors(group, error, undo);
  // the peak of the largest rank, union included (measuring the tiles resets getrusage's peak:
  // `memory` has the peak before and during the tiles)
  const double peak_mb = group.max(std::max(peak_rss_mb(), double(memory.call_peak()) / (1024.0 * 1024.0)));
  if(!group.is_root()) return 0;
  if(options.json) {
    nlohmann::json j = tiles_json(input, directory, group, r, rank_of, tile_peak_bytes, measure_memory, t.out_of_core);
    j["merge_s"] = merge_watch.time();
    j["write_s"] = write_s + merged_io.time(); // the tiles' within tiles_s
    j["total_s"] = r.total_seconds + merge_watch.time() + merged_io.time();
    j["peak_rss_mb"] = peak_mb;
    if(!t.merged.empty()) {
      j["merged"] = t.merged;
      nlohmann::json mj;
      add_mesh_statistics(mj, merged);
      mj["cancelled_faces"] = m.cancelled_faces;
      mj["removed_closed_components"] = m.removed_closed_components;
      mj["non_manifold_vertices"] = m.non_manifold_vertices;
      mj["non_manifold_edges"] = m.non_manifold_edges;
      j["merged_mesh"] = mj;
    }
    std::cout << j.dump() << std::endl;
  } else {
    std::cerr << "wrote " << r.tiles.size() << " tiles (" << r.columns << " x " << r.rows << ") in " << directory;
    if(!t.merged.empty())
      std::cerr << " and " << t.merged << ": " << m.mesh_vertices << " vertices, " << m.mesh_faces << " faces";
    std::cerr << "\n";
  }
  return 0;
}

int main(int argc, char** argv)
{
  Process_group group(argc, argv); // MPI_Init under lex_reconstruct_mpi
  CLI::App app{"Surface reconstruction as a lexicographic optimal chain (Lex_optimal_chains)"};
  app.require_subcommand(1);
  std::string input, output, boundary_file, coefficients = "q";
  Closed_options closed_options;
  Output_options options;
  bool auto_boundary = false, remove_blocking = false, drop = false, keep = false;

  CLI::App* closed = app.add_subcommand("closed", "closed surface through a lexicographic min-cut");
  closed->add_option("INPUT", input, "points: .xyz, .ply, .off or .las")->required();
  closed->add_option("OUTPUT", output, "mesh: .off, .ply or .obj")->required();
  closed->add_option("--interior", closed_options.interior_text, "a point inside the surface, X,Y,Z (repeatable)");
  closed->add_option("--exterior", closed_options.exterior_text, "a point outside the surface, X,Y,Z (repeatable)");
  closed->add_option("--min-persistence", closed_options.min_persistence,
                     "without --interior: how clearly the automatic interior must stand out (default: from 4, or "
                     "from 2 when it stands out from the other voids; lower it when the error says the most "
                     "persistent void is below it)")
    ->check(CLI::Validator(
      [](std::string& text) {
        const double v = std::strtod(text.c_str(), nullptr);
        return std::isfinite(v) && v > 0 ? std::string() : "must be a positive finite number, not " + text;
      },
      "POSITIVE"));
  auto* robust = closed->add_flag("--robust", closed_options.robust,
                                  "smooth noisy points (jet fitting) before the reconstruction");
  closed->add_option("--smoothing-neighbors", closed_options.smoothing_neighbors,
                     "with --robust: neighbours of the jet fits (default: estimated from the points, at least 24)")
    ->needs(robust)
    ->check(CLI::Range(std::size_t(8), std::size_t(100000)));
  add_output_options(closed, options);

  CLI::App* open = app.add_subcommand("open", "open surface bounded by closed polylines");
  open->add_option("INPUT", input, "points: .xyz, .ply, .off or .las")->required();
  open->add_option("OUTPUT", output, "mesh: .off, .ply or .obj")->required();
  auto* b = open->add_option("--boundary", boundary_file, "closed polylines, CGAL's polylines text format");
  auto* a = open->add_flag("--auto-boundary", auto_boundary,
                           "a polygon just outside the xy-footprint, draped at the height of the nearest points (terrain tiles); implies --drop-boundary-triangles");
  b->excludes(a);
  open->add_option("--coefficients", coefficients, "z2 (unoriented) or q (oriented, default)");
  open->add_flag("--remove-blocking-points", remove_blocking,
                 "remove the input points that keep a boundary edge out of the Delaunay triangulation");
  auto* d = open->add_flag("--drop-boundary-triangles", drop, "drop the triangles touching boundary vertices that are not input points");
  auto* k = open->add_flag("--keep-boundary-triangles", keep, "keep them with --auto-boundary");
  d->excludes(k);
  add_output_options(open, options);

  Features_options features_options;
  CLI::App* features = app.add_subcommand("features", "a surface decomposed into the elements of the critical basis around sharp features");
  features->add_option("INPUT", input, "points: .xyz, .ply, .off or .las")->required();
  features->add_option("OUTPUT", output, "mesh: .off, .ply (with the element of each face) or .obj")->required();
  const CLI::Validator positive_number(
    [](std::string& text) {
      const double v = std::strtod(text.c_str(), nullptr);
      return std::isfinite(v) && v > 0 ? std::string() : "must be a positive finite number, not " + text;
    },
    "POSITIVE");
  features->add_option("--threshold", features_options.threshold, "threshold of the VCM feature estimate (default 0.16)")
    ->check(positive_number);
  features->add_option("--offset", features_options.offset,
                       "offset of the feature points that bounds the subcomplex (default: 1.5 times the average spacing)")
    ->check(positive_number);
  features->add_option("--drop-largest", features_options.drop_largest, "leave the K largest elements out (opens occlusion holes)");
  features->add_flag("--relative", features_options.relative, "optimal chains relative to the subcomplex around the features");
  features->add_flag("--borders", features_options.borders, "add the rims of the scan and of its holes to the features");
  features->add_flag("--ascii", options.ascii, "write a .ply mesh as text, without the elements (binary by default)");
  features->add_flag("--json", options.json, "print one JSON line of statistics on stdout");

  Tiles_options tiles_options;
  CLI::App* tiles = app.add_subcommand("tiles", "a terrain-like cloud in tiles whose meshes meet exactly at their seams");
  tiles->add_option("INPUT", input, "points: .xyz, .ply, .off or .las")->required();
  tiles->add_option("OUTPUT_DIR", output, "directory of the tile meshes tile_C_R.ply (created if missing)")->required();
  tiles->add_option("--tile-size", tiles_options.tile_size, "largest side of a tile, in the units of the points")->required();
  tiles->add_option("--seam-spacing", tiles_options.seam_spacing,
                    "distance between seam points (default: 3 times the mean spacing of the points)");
  tiles->add_option("--merged", tiles_options.merged, "also write the union of the tiles, welded at the seams (.off, .ply or .obj)");
  tiles->add_option("--coefficients", tiles_options.coefficients, "z2 (unoriented) or q (oriented upwards, default)");
  tiles->add_option("--classes", tiles_options.classes, "with a LAS input: the classifications kept, e.g. 2,6 (ground, building)")
    ->delimiter(',')
    ->check(CLI::Range(0, 255));
  auto* out_of_core = tiles->add_flag("--out-of-core", tiles_options.out_of_core,
                                      "stream the input twice and bucket it into files per tile, so that the memory holds "
                                      "the tiles being made and not the cloud (same tiles)");
  tiles->add_option("--bucket-dir", tiles_options.bucket_directory,
                    "with --out-of-core: an existing directory for the bucket files (24 bytes a point; "
                    "default: OUTPUT_DIR if it exists, else its parent)")
    ->needs(out_of_core);
  add_output_options(tiles, options);
  try {
    app.parse(argc, argv);
    if(open->parsed() && boundary_file.empty() && !auto_boundary)
      throw CLI::RequiredError("--boundary or --auto-boundary");
    if(group.size() > 1 && !tiles->parsed())
      throw CLI::ValidationError("only the tiles subcommand runs on several MPI ranks (" +
                                 std::to_string(group.size()) + " here): run the others with one");
  } catch(const CLI::CallForHelp& e) {
    return group.is_root() ? app.exit(e) : 0;
  } catch(const CLI::CallForAllHelp& e) {
    return group.is_root() ? app.exit(e) : 0;
  } catch(const CLI::ParseError& e) { // one line and exit code 1, as for bad input
    if(group.is_root()) std::cerr << "lex_reconstruct: error: " << e.what() << " (see --help)" << std::endl;
    return 1;
  }
  try {
    if(closed->parsed()) return run_closed(input, output, closed_options, options);
    if(tiles->parsed()) return run_tiles(input, output, tiles_options, options, group);
    if(features->parsed()) return run_features(input, output, features_options, options);
    return run_open(input, output, boundary_file, auto_boundary, coefficients, remove_blocking, drop, keep, options);
  } catch(const Reported_by_another_rank&) {
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "lex_reconstruct: error: " << e.what() << std::endl;
    return 1;
  }
}
