// lex_reconstruct: surface reconstruction from a point cloud as a lexicographic optimal chain.
//
//   lex_reconstruct closed INPUT OUTPUT [--interior X,Y,Z]... [--exterior X,Y,Z]...
//                   [--min-persistence V] [--keep-non-manifold] [--threads N] [--ascii] [--json]
//   lex_reconstruct open INPUT OUTPUT (--boundary FILE | --auto-boundary)
//                   [--coefficients z2|q] [--remove-blocking-points]
//                   [--drop-boundary-triangles | --keep-boundary-triangles] [--keep-non-manifold]
//                   [--threads N] [--ascii] [--json]
//
// INPUT: points as XYZ, PLY or OFF. OUTPUT: a mesh as OFF, PLY (binary unless --ascii) or
// OBJ, by extension.
// Boundary FILE: CGAL's polylines text format, one closed polyline per line:
// "n x1 y1 z1 ... xn yn zn" with the last point equal to the first.
// On error: a one-line reason on stderr, exit code 1, and no output file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/lex_optimal_closed_surface.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

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

static std::vector<std::vector<Point>> read_polylines(const std::string& path)
{
  std::ifstream in(path);
  if(!in) throw std::invalid_argument("cannot open boundary file '" + path + "'");
  std::vector<std::vector<Point>> polylines;
  std::string line;
  for(int number = 1; std::getline(in, line); ++number) {
    const std::string where = "line " + std::to_string(number) + " of '" + path + "'";
    std::istringstream ls(line);
    std::vector<std::string> tokens;
    for(std::string t; ls >> t;) tokens.push_back(t);
    if(tokens.empty()) continue; // blank line
    char* end = nullptr;
    const long n = std::strtol(tokens[0].c_str(), &end, 10);
    if(*end != '\0' || end == tokens[0].c_str())
      throw std::invalid_argument(where + " does not start with a whole number of points, but '" + tokens[0] + "'");
    if(n < 0 || n > 100000000) throw std::invalid_argument(where + ": bad number of points " + tokens[0]);
    if(tokens.size() != std::size_t(1 + 3 * n))
      throw std::invalid_argument(where + " announces " + tokens[0] + " points (" + std::to_string(3 * n) +
                                  " coordinates) but has " + std::to_string(tokens.size() - 1) + " coordinates");
    std::vector<Point> polyline;
    double c[3];
    for(long i = 0; i < n; ++i) {
      for(int k = 0; k < 3; ++k) {
        const std::string& t = tokens[std::size_t(1 + 3 * i + k)];
        c[k] = std::strtod(t.c_str(), &end);
        if(*end != '\0' || end == t.c_str() || !std::isfinite(c[k]))
          throw std::invalid_argument(where + ": coordinate '" + t + "' of point " + std::to_string(i + 1) +
                                      " is not a finite number");
      }
      polyline.emplace_back(c[0], c[1], c[2]);
    }
    polylines.push_back(std::move(polyline));
  }
  return polylines;
}

// The size in bytes of a binary PLY file's data, from the element counts and property types
// of its header, when every property is a scalar (with a list property the size depends on
// the data) and the counts are below 2^48 bytes' worth: 0 otherwise.
static unsigned long long binary_ply_data_size(const std::vector<std::pair<unsigned long long, std::vector<std::string>>>& elements)
{
  unsigned long long total = 0;
  for(const auto& [count, properties] : elements) {
    unsigned long long record = 0;
    for(const std::string& type : properties) {
      unsigned long long size = 0;
      if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") size = 1;
      else if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") size = 2;
      else if(type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") size = 4;
      else if(type == "double" || type == "float64") size = 8;
      else return 0; // a list, or a type this check does not know
      record += size;
    }
    // a count too large for the file is left to CGAL's reader (which then fails), not wrapped around
    if(record != 0 && count > (1ull << 48) / record) return 0;
    total += count * record;
  }
  return total;
}

// CGAL's readers stop after the number of points that an OFF or PLY header declares: a header
// that declares fewer than the file holds would drop points silently. For ASCII files (one
// record per line) whose points come last (an OFF file without faces, a PLY file whose last
// element is the vertices) the data lines are counted against the header; for binary PLY
// files whose properties are all scalars, the size of the data is compared with the size the
// header gives. Binary PLY files with list properties (faces), binary OFF files, and ASCII files
// with faces after the points (where an extra line may be an extra face) are not checked.
static void check_declared_counts(const std::string& input, const std::string& ext)
{
  std::ifstream in(input, std::ios::binary);
  std::string line;
  auto next_line = [&](bool skip_comments) {
    while(std::getline(in, line)) {
      const auto first = line.find_first_not_of(" \t\r");
      if(first == std::string::npos) continue;
      if(skip_comments && line[first] == '#') continue;
      return true;
    }
    return false;
  };
  unsigned long long declared = 0; // records: points (OFF), elements (PLY)
  std::string what, last_element;
  if(ext == ".off") {
    if(!next_line(true)) return;
    std::istringstream header(line);
    std::string keyword;
    header >> keyword;
    if(keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) return; // CGAL decides
    std::string rest;
    std::getline(header, rest);
    if(rest.find("BINARY") != std::string::npos) return;
    if(rest.find_first_not_of(" \t\r") == std::string::npos) { if(!next_line(true)) return; rest = line; }
    if(keyword.find("ST") != std::string::npos || keyword.find("4") != std::string::npos || keyword.find("n") != std::string::npos)
      return; // dimension or texture variants: left to CGAL
    std::istringstream counts(rest);
    unsigned long long v = 0, f = 0;
    if(!(counts >> v >> f)) return;
    if(f != 0) return;
    declared = v;
    what = std::to_string(v) + " points";
  } else if(ext == ".ply") {
    if(!next_line(false) || line.rfind("ply", 0) != 0) return;
    bool binary = false, ended = false;
    std::vector<std::pair<unsigned long long, std::vector<std::string>>> elements; // count, property types
    while(next_line(false)) {
      if(line.rfind("end_header", 0) == 0) { ended = true; break; }
      std::istringstream words(line);
      std::string keyword, name;
      words >> keyword;
      if(keyword == "format") {
        std::string format;
        words >> format;
        if(format == "binary_little_endian" || format == "binary_big_endian") binary = true;
        else if(format != "ascii") return;
      } else if(keyword == "element") {
        unsigned long long count = 0;
        if(!(words >> name >> count)) return;
        declared += count;
        what += (what.empty() ? "" : ", ") + std::to_string(count) + " " + name;
        last_element = name;
        elements.push_back({count, {}});
      } else if(keyword == "property") {
        std::string type;
        if(!(words >> type) || elements.empty()) return;
        elements.back().second.push_back(type);
      }
    }
    if(binary) {
      if(!ended) return;
      const auto data_start = in.tellg(); // after the line "end_header" and its end of line
      const unsigned long long expected = binary_ply_data_size(elements);
      if(data_start < 0 || expected == 0) return;
      const unsigned long long size = std::filesystem::file_size(input);
      if(size > (unsigned long long)(data_start) + expected)
        throw std::invalid_argument("input '" + input + "' holds more data than its header declares (" + what + ", " +
                                    std::to_string(expected) + " bytes, against " +
                                    std::to_string(size - (unsigned long long)(data_start)) +
                                    "): the points beyond would be ignored; fix the header");
      return;
    }
    if(last_element != "vertex") return;
  } else
    return;
  unsigned long long records = 0;
  while(next_line(ext == ".off")) {
    if(++records > declared)
      throw std::invalid_argument("input '" + input + "' holds more records than its header declares (" + what +
                                  "): the points beyond would be ignored; fix the header");
  }
}

static std::vector<Point> read_input_points(const std::string& input)
{
  const std::string in_ext = lower_extension(input);
  if(in_ext != ".xyz" && in_ext != ".ply" && in_ext != ".off")
    throw std::invalid_argument("input '" + input + "' must end in .xyz, .ply or .off");
  if(!std::filesystem::is_regular_file(input)) throw std::invalid_argument("cannot open input '" + input + "'");
  std::vector<Point> points;
  // CGAL's readers print their own diagnostics: keep the one-line reason of this program
  std::ostringstream reader_messages;
  std::streambuf* saved = std::cerr.rdbuf(reader_messages.rdbuf());
  const bool read = CGAL::IO::read_points(input, std::back_inserter(points));
  std::cerr.rdbuf(saved);
  if(!read) throw std::invalid_argument("cannot read points from '" + input + "'");
  check_declared_counts(input, in_ext);
  return points;
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
static bool write_binary_ply(const std::string& path, const Mesh& mesh)
{
  const std::uint16_t probe = 1;
  char first_byte;
  std::memcpy(&first_byte, &probe, 1);
  if(first_byte != 1) return CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::use_binary_mode(true)); // big-endian
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment Generated by lex_reconstruct\nelement vertex "
      << mesh.number_of_vertices() << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
      << mesh.number_of_faces() << "\nproperty list uchar int vertex_indices\nend_header\n";
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
    char record[13];
    record[0] = 3;
    const std::int32_t corners[3] = {index[mesh.target(h)], index[mesh.target(mesh.next(h))], index[mesh.source(h)]};
    std::memcpy(record + 1, corners, sizeof(corners));
    append(record, sizeof(record));
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
  void write(const Mesh& mesh, bool ascii)
  {
    const bool written = !ascii && lower_extension(output_) == ".ply"
                           ? write_binary_ply(tmp_, mesh)
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
  command->add_option("--threads", options.threads, "threads for the Delaunay triangulation")->check(CLI::Range(1u, 1024u));
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

static int run_closed(const std::string& input, const std::string& output, const std::vector<std::string>& interior_text,
                      const std::vector<std::string>& exterior_text, double min_persistence,
                      const Output_options& options)
{
  Output_file file(output);
  std::vector<Point> interior, exterior;
  for(const std::string& t : interior_text) interior.push_back(parse_point(t));
  for(const std::string& t : exterior_text) exterior.push_back(parse_point(t));
  const std::vector<Point> points = read_input_points(input);
  Progress_bar bar;
  Mesh mesh;
  const LOC::Closed_surface_report r = CGAL::lex_optimal_closed_surface_reconstruction(
    points, mesh,
    LOC::parameters::interior_points(interior,
    LOC::parameters::exterior_points(exterior,
    LOC::parameters::minimum_interior_persistence(min_persistence,
    LOC::parameters::keep_non_manifold(options.keep_non_manifold,
    LOC::parameters::number_of_threads(options.threads,
    LOC::parameters::callback(bar.callback())))))));
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
  const std::vector<Point> points = read_input_points(input);
  std::vector<std::vector<Point>> boundary;
  if(auto_boundary) boundary.push_back(LOC::footprint_boundary(points));
  else boundary = read_polylines(boundary_file);
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

int main(int argc, char** argv)
{
  CLI::App app{"Surface reconstruction as a lexicographic optimal chain (Lex_optimal_chains)"};
  app.require_subcommand(1);
  std::string input, output, boundary_file, coefficients = "q";
  std::vector<std::string> interior_text, exterior_text;
  Output_options options;
  double min_persistence = 4;
  bool auto_boundary = false, remove_blocking = false, drop = false, keep = false;

  CLI::App* closed = app.add_subcommand("closed", "closed surface through a lexicographic min-cut");
  closed->add_option("INPUT", input, "points: .xyz, .ply or .off")->required();
  closed->add_option("OUTPUT", output, "mesh: .off, .ply or .obj")->required();
  closed->add_option("--interior", interior_text, "a point inside the surface, X,Y,Z (repeatable)");
  closed->add_option("--exterior", exterior_text, "a point outside the surface, X,Y,Z (repeatable)");
  closed->add_option("--min-persistence", min_persistence,
                     "without --interior: how clearly the automatic interior must stand out (default 4; "
                     "lower it when the error says the most persistent void is below it)")
    ->check(CLI::Validator(
      [](std::string& text) {
        const double v = std::strtod(text.c_str(), nullptr);
        return std::isfinite(v) && v > 0 ? std::string() : "must be a positive finite number, not " + text;
      },
      "POSITIVE"));
  add_output_options(closed, options);

  CLI::App* open = app.add_subcommand("open", "open surface bounded by closed polylines");
  open->add_option("INPUT", input, "points: .xyz, .ply or .off")->required();
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
  try {
    app.parse(argc, argv);
    if(open->parsed() && boundary_file.empty() && !auto_boundary)
      throw CLI::RequiredError("--boundary or --auto-boundary");
  } catch(const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch(const CLI::ParseError& e) { // one line and exit code 1, as for bad input
    std::cerr << "lex_reconstruct: error: " << e.what() << " (see --help)" << std::endl;
    return 1;
  }
  try {
    if(closed->parsed()) return run_closed(input, output, interior_text, exterior_text, min_persistence, options);
    return run_open(input, output, boundary_file, auto_boundary, coefficients, remove_blocking, drop, keep, options);
  } catch(const std::exception& e) {
    std::cerr << "lex_reconstruct: error: " << e.what() << std::endl;
    return 1;
  }
}
