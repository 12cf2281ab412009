// lex_reconstruct closed: a closed surface through a lexicographic min-cut.
#ifndef URBAN_LEX_RECONSTRUCT_CLOSED_COMMAND_H
#define URBAN_LEX_RECONSTRUCT_CLOSED_COMMAND_H

#include "Memory_check.h"
#include "options_and_output.h"

#include <CGAL/lex_optimal_closed_surface.h>

namespace lex_reconstruct {

// What the closed subcommand takes besides the output options.
struct Closed_options
{
  std::vector<std::string> interior_text, exterior_text;
  double min_persistence = 0; // 0: not given, the adaptive acceptance of the automatic interior
  bool robust = false;
  std::size_t smoothing_neighbors = 0;
};

class Closed_command
{
public:
  explicit Closed_command(CLI::App& app)
  {
    command_ = app.add_subcommand("closed", "closed surface through a lexicographic min-cut");
    command_->add_option("INPUT", input_, "points: .xyz, .pwn, .ply, .off or .las")->required();
    command_->add_option("OUTPUT", output_, "mesh: .off, .ply or .obj")->required();
    add_memory_option(command_, max_memory_mb_);
    command_->add_option("--interior", closed_.interior_text, "a point inside the surface, X,Y,Z (repeatable)");
    command_->add_option("--exterior", closed_.exterior_text, "a point outside the surface, X,Y,Z (repeatable)");
    command_->add_option("--min-persistence", closed_.min_persistence,
                         "without --interior: how clearly the automatic interior must stand out (default: from 4, or "
                         "from 2 when it stands out from the other voids; lower it when the error says the most "
                         "persistent void is below it)")
      ->check(positive_number());
    auto* robust = command_->add_flag("--robust", closed_.robust,
                                      "smooth noisy points (jet fitting) before the reconstruction");
    command_->add_option("--smoothing-neighbors", closed_.smoothing_neighbors,
                         "with --robust: neighbours of the jet fits (default: estimated from the points, at least 24)")
      ->needs(robust)
      ->check(CLI::Range(std::size_t(8), std::size_t(100000)));
    add_output_options(command_, options_);
  }
  Closed_command(const Closed_command&) = delete; // the options point into it
  Closed_command& operator=(const Closed_command&) = delete;

  bool parsed() const { return command_->parsed(); }

  int run() const
  {
    Output_file file(output_);
    std::vector<Point> interior, exterior;
    for(const std::string& t : closed_.interior_text) interior.push_back(parse_point(t));
    for(const std::string& t : closed_.exterior_text) exterior.push_back(parse_point(t));
    const std::vector<Point> points = LOC::IO::read_point_file<Point>(input_);
    check_memory(points.size(), closed_bytes_per_point, max_memory_mb_);
    Progress_bar bar;
    Mesh mesh;
    const auto np = LOC::parameters::interior_points(interior,
                    LOC::parameters::exterior_points(exterior,
                    LOC::parameters::robust(closed_.robust,
                    LOC::parameters::smoothing_neighbors(closed_.smoothing_neighbors,
                    LOC::parameters::keep_non_manifold(options_.keep_non_manifold,
                    LOC::parameters::number_of_threads(options_.threads,
                    LOC::parameters::callback(bar.callback())))))));
    // the adaptive acceptance applies only when no fixed threshold is given
    const LOC::Closed_surface_report r =
      closed_.min_persistence > 0
        ? CGAL::lex_optimal_closed_surface_reconstruction(points, mesh, LOC::parameters::minimum_interior_persistence(closed_.min_persistence, np))
        : CGAL::lex_optimal_closed_surface_reconstruction(points, mesh, np);
    CGAL::Real_timer io;
    io.start();
    file.write(mesh, options_.ascii);
    io.stop();
    report(r, io.time(), mesh);
    return 0;
  }

private:
  void report(const LOC::Closed_surface_report& r, double io_seconds, const Mesh& mesh) const
  {
    if(!options_.json) {
      std::cerr << "\nwrote " << output_ << ": " << r.mesh_vertices << " vertices, " << r.mesh_faces << " faces, "
                << r.components << " component(s), genus " << r.genus << "\n";
      return;
    }
    nlohmann::json j;
    add_common_statistics(j, input_, output_, r, io_seconds, mesh);
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
  }

  CLI::App* command_ = nullptr;
  std::string input_, output_;
  Closed_options closed_;
  Output_options options_;
  double max_memory_mb_ = 0; // 0: the memory available
};

} // namespace lex_reconstruct

#endif // URBAN_LEX_RECONSTRUCT_CLOSED_COMMAND_H
