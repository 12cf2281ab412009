// lex_reconstruct open: an open surface bounded by closed polylines.
#ifndef URBAN_LEX_RECONSTRUCT_OPEN_COMMAND_H
#define URBAN_LEX_RECONSTRUCT_OPEN_COMMAND_H

#include "Memory_check.h"
#include "options_and_output.h"

#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>

namespace lex_reconstruct {

class Open_command
{
public:
  explicit Open_command(CLI::App& app)
  {
    command_ = app.add_subcommand("open", "open surface bounded by closed polylines");
    command_->add_option("INPUT", input_, "points: .xyz, .pwn, .ply, .off or .las")->required();
    command_->add_option("OUTPUT", output_, "mesh: .off, .ply or .obj")->required();
    add_memory_option(command_, max_memory_mb_);
    auto* b = command_->add_option("--boundary", boundary_file_, "closed polylines, CGAL's polylines text format");
    auto* a = command_->add_flag("--auto-boundary", auto_boundary_,
                                 "a polygon just outside the xy-footprint, draped at the height of the nearest points (terrain tiles); implies --drop-boundary-triangles");
    b->excludes(a);
    command_->add_option("--coefficients", coefficients_, "z2 (unoriented) or q (oriented, default)")
      ->check(CLI::IsMember({"z2", "q"}));
    command_->add_flag("--remove-blocking-points", remove_blocking_,
                       "remove the input points that keep a boundary edge out of the Delaunay triangulation");
    auto* d = command_->add_flag("--drop-boundary-triangles", drop_, "drop the triangles touching boundary vertices that are not input points");
    auto* k = command_->add_flag("--keep-boundary-triangles", keep_, "keep them with --auto-boundary");
    d->excludes(k);
    add_output_options(command_, options_);
  }
  Open_command(const Open_command&) = delete; // the options point into it
  Open_command& operator=(const Open_command&) = delete;

  bool parsed() const { return command_->parsed(); }

  // after the parse: one of --boundary and --auto-boundary is required
  void check() const
  {
    if(parsed() && boundary_file_.empty() && !auto_boundary_)
      throw CLI::RequiredError("--boundary or --auto-boundary");
  }

  int run() const
  {
    Output_file file(output_);
    const std::vector<Point> points = LOC::IO::read_point_file<Point>(input_);
    check_memory(points.size(), open_bytes_per_point, max_memory_mb_);
    std::vector<std::vector<Point>> boundary;
    if(auto_boundary_) boundary.push_back(LOC::footprint_boundary(points));
    else boundary = LOC::IO::read_polyline_file<Point>(boundary_file_);
    // the skirt of the automatic boundary is not part of the terrain
    const bool drop_skirt = drop_ || (auto_boundary_ && !keep_);
    Progress_bar bar;
    Mesh mesh;
    const LOC::Open_surface_report r = CGAL::lex_optimal_open_surface_reconstruction(
      points, boundary, mesh,
      LOC::parameters::coefficient_field(coefficients_ == "z2" ? LOC::Coefficient_field::Z2 : LOC::Coefficient_field::Q,
      LOC::parameters::remove_blocking_points(remove_blocking_,
      LOC::parameters::drop_boundary_triangles(drop_skirt,
      LOC::parameters::keep_non_manifold(options_.keep_non_manifold,
      LOC::parameters::number_of_threads(options_.threads,
      LOC::parameters::callback(bar.callback())))))));
    CGAL::Real_timer io;
    io.start();
    file.write(mesh, options_.ascii);
    io.stop();
    if(r.number_of_multiple_facets > 0)
      std::cerr << "\nwarning: " << r.number_of_multiple_facets
                << " triangles have a coefficient other than 1 or -1: over Q the boundary winds more than once "
                   "around them (loops bounding an annulus must turn in opposite directions); --coefficients z2 "
                   "ignores the orientations\n";
    report(r, io.time(), mesh);
    return 0;
  }

private:
  void report(const LOC::Open_surface_report& r, double io_seconds, const Mesh& mesh) const
  {
    if(!options_.json) {
      std::cerr << "\nwrote " << output_ << ": " << r.mesh_vertices << " vertices, " << r.mesh_faces << " faces ("
                << r.dropped_triangles << " boundary triangles dropped, " << r.trimmed_triangles
                << " pinched ones trimmed, " << r.number_of_removed_points << " points removed)\n";
      return;
    }
    nlohmann::json j;
    add_common_statistics(j, input_, output_, r, io_seconds, mesh);
    j["coefficients"] = coefficients_;
    j["representative_s"] = r.representative_seconds;
    j["optimal_chain_s"] = r.optimal_chain_seconds;
    j["orientation_cuts"] = r.orientation_cuts;
    j["boundary_vertices_added"] = r.number_of_boundary_vertices;
    j["removed_points"] = r.number_of_removed_points;
    j["dropped_triangles"] = r.dropped_triangles;
    j["trimmed_triangles"] = r.trimmed_triangles;
    j["chain_triangles"] = r.number_of_facets;
    j["multiple_triangles"] = r.number_of_multiple_facets;
    j["triangles"] = r.number_of_triangles;
    std::cout << j.dump() << std::endl;
  }

  CLI::App* command_ = nullptr;
  std::string input_, output_, boundary_file_, coefficients_ = "q";
  bool auto_boundary_ = false, remove_blocking_ = false, drop_ = false, keep_ = false;
  Output_options options_;
  double max_memory_mb_ = 0; // 0: the memory available
};

} // namespace lex_reconstruct

#endif // URBAN_LEX_RECONSTRUCT_OPEN_COMMAND_H
