// lex_reconstruct: surface reconstruction from a point cloud as a lexicographic optimal chain.
//
//   lex_reconstruct closed INPUT OUTPUT [--interior X,Y,Z]... [--exterior X,Y,Z]...
//                   [--threads N] [--json]
//
// INPUT: points as XYZ, PLY or OFF. OUTPUT: a mesh as OFF, PLY or OBJ, by extension.
// On error: a one-line reason on stderr, exit code 1, and no output file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/lex_optimal_closed_surface.h>

#include <CLI/CLI.hpp>
#include <boost/timer/progress_display.hpp>
#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
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

int main(int argc, char** argv)
{
  CLI::App app{"Surface reconstruction as a lexicographic optimal chain (Lex_optimal_chains)"};
  app.require_subcommand(1);
  CLI::App* closed = app.add_subcommand("closed", "closed surface through a lexicographic min-cut");
  std::string input, output;
  std::vector<std::string> interior_text, exterior_text;
  unsigned threads = 1;
  bool json = false;
  closed->add_option("INPUT", input, "points: .xyz, .ply or .off")->required();
  closed->add_option("OUTPUT", output, "mesh: .off, .ply or .obj")->required();
  closed->add_option("--interior", interior_text, "a point inside the surface, X,Y,Z (repeatable)");
  closed->add_option("--exterior", exterior_text, "a point outside the surface, X,Y,Z (repeatable)");
  closed->add_option("--threads", threads, "threads for the Delaunay triangulation")->check(CLI::Range(1u, 1024u));
  closed->add_flag("--json", json, "print one JSON line of statistics on stdout");
  try {
    app.parse(argc, argv);
  } catch(const CLI::ParseError& e) {
    return app.exit(e);
  }

  // written under a temporary name with the same extension, renamed on success
  const std::filesystem::path out_path(output);
  const std::string tmp =
    (out_path.parent_path() / ("." + out_path.stem().string() + ".partial" + out_path.extension().string())).string();
  try {
    const std::string out_ext = lower_extension(output);
    if(out_ext != ".off" && out_ext != ".ply" && out_ext != ".obj")
      throw std::invalid_argument("output '" + output + "' must end in .off, .ply or .obj");
    const std::string in_ext = lower_extension(input);
    if(in_ext != ".xyz" && in_ext != ".ply" && in_ext != ".off")
      throw std::invalid_argument("input '" + input + "' must end in .xyz, .ply or .off");
    if(!std::filesystem::is_regular_file(input))
      throw std::invalid_argument("cannot open input '" + input + "'");
    std::vector<Point> interior, exterior;
    for(const std::string& t : interior_text) interior.push_back(parse_point(t));
    for(const std::string& t : exterior_text) exterior.push_back(parse_point(t));

    std::vector<Point> points;
    {
      // CGAL's readers print their own diagnostics: keep the one-line reason of this program
      std::ostringstream reader_messages;
      std::streambuf* saved = std::cerr.rdbuf(reader_messages.rdbuf());
      const bool read = CGAL::IO::read_points(input, std::back_inserter(points));
      std::cerr.rdbuf(saved);
      if(!read) throw std::invalid_argument("cannot read points from '" + input + "'");
    }

    std::unique_ptr<boost::timer::progress_display> bar;
    if(isatty(STDERR_FILENO)) bar.reset(new boost::timer::progress_display(100, std::cerr));
    const std::function<bool(double)> progress = [&bar](double x) {
      if(bar) {
        const unsigned long target = (unsigned long)(x * 100);
        while(bar->count() < target) ++(*bar);
      }
      return true;
    };

    Mesh mesh;
    const LOC::Closed_surface_report r = CGAL::lex_optimal_closed_surface_reconstruction(
      points, mesh,
      LOC::parameters::interior_points(interior,
      LOC::parameters::exterior_points(exterior,
      LOC::parameters::number_of_threads(threads,
      LOC::parameters::callback(progress)))));

    CGAL::Real_timer io;
    io.start();
    if(!CGAL::IO::write_polygon_mesh(tmp, mesh, CGAL::parameters::stream_precision(17)))
      throw std::runtime_error("cannot write '" + output + "'");
    std::filesystem::rename(tmp, output);
    io.stop();

    if(json) {
      nlohmann::json j;
      j["input"] = input;
      j["output"] = output;
      j["points"] = r.number_of_input_points;
      j["delaunay_s"] = r.delaunay_seconds;
      j["order_s"] = r.order_seconds;
      j["cut_s"] = r.cut_seconds;
      j["output_s"] = r.output_seconds + io.time();
      j["total_s"] = r.total_seconds + io.time();
      j["peak_rss_mb"] = peak_rss_mb();
      j["vertices"] = r.mesh_vertices;
      j["faces"] = r.mesh_faces;
      j["components"] = r.components;
      j["boundary_edges"] = std::count_if(halfedges(mesh).begin(), halfedges(mesh).end(),
                                          [&mesh](Mesh::Halfedge_index h) { return is_border(h, mesh); });
      j["non_manifold_vertices"] = r.non_manifold_vertices;
      j["non_manifold_edges"] = r.non_manifold_edges;
      j["closed"] = CGAL::is_closed(mesh);
      j["genus"] = r.genus;
      j["automatic_interior"] = r.automatic_interior;
      j["interior_persistence"] = r.interior_persistence;
      j["triangles"] = r.number_of_triangles;
      j["exactly_ordered_triangles"] = r.number_of_exactly_ordered_triangles;
      std::cout << j.dump() << std::endl;
    } else {
      std::cerr << "\nwrote " << output << ": " << r.mesh_vertices << " vertices, " << r.mesh_faces
                << " faces, " << r.components << " component(s), genus " << r.genus << "\n";
    }
  } catch(const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    std::cerr << "lex_reconstruct: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
