// lex_reconstruct features: a surface decomposed into the elements of the critical basis of the
// relative 2-cycles around sharp features (thesis section 4.8.3); a binary PLY output has the
// element of each face as the int face property `element`.
#ifndef URBAN_LEX_RECONSTRUCT_FEATURES_COMMAND_H
#define URBAN_LEX_RECONSTRUCT_FEATURES_COMMAND_H

#include "Memory_check.h"
#include "options_and_output.h"

#include <CGAL/lex_optimal_feature_reconstruction.h>

namespace lex_reconstruct {

// What the features subcommand takes besides the output options.
struct Features_options
{
  double threshold = 0.16, offset = 0;
  std::size_t drop_largest = 0;
  bool relative = false, borders = false;
};

class Features_command
{
public:
  explicit Features_command(CLI::App& app)
  {
    command_ = app.add_subcommand("features", "a surface decomposed into the elements of the critical basis around sharp features");
    command_->add_option("INPUT", input_, "points: .xyz, .pwn, .ply, .off or .las")->required();
    command_->add_option("OUTPUT", output_, "mesh: .off, .ply (with the element of each face) or .obj")->required();
    add_memory_option(command_, max_memory_mb_);
    command_->add_option("--threshold", features_.threshold, "threshold of the VCM feature estimate (default 0.16)")
      ->check(positive_number());
    command_->add_option("--offset", features_.offset,
                         "offset of the feature points that bounds the subcomplex (default: 1.5 times the average spacing)")
      ->check(positive_number());
    command_->add_option("--drop-largest", features_.drop_largest, "leave the K largest elements out (opens occlusion holes)");
    command_->add_flag("--relative", features_.relative, "optimal chains relative to the subcomplex around the features");
    command_->add_flag("--borders", features_.borders, "add the rims of the scan and of its holes to the features");
    command_->add_flag("--ascii", options_.ascii, "write a .ply mesh as text, without the elements (binary by default)");
    command_->add_flag("--json", options_.json, "print one JSON line of statistics on stdout");
  }
  Features_command(const Features_command&) = delete; // the options point into it
  Features_command& operator=(const Features_command&) = delete;

  bool parsed() const { return command_->parsed(); }

  int run() const
  {
    Output_file file(output_);
    const std::vector<Point> points = LOC::IO::read_point_file<Point>(input_);
    check_memory(points.size(), features_bytes_per_point, max_memory_mb_);
    Mesh mesh;
    auto element = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(0)).first;
    const auto np = LOC::parameters::feature_threshold(features_.threshold,
                    LOC::parameters::border_features(features_.borders,
                    LOC::parameters::relative_to_features(features_.relative,
                    LOC::parameters::drop_largest_elements(features_.drop_largest,
                    LOC::parameters::face_element_map(element)))));
    const LOC::Feature_reconstruction_report r =
      features_.offset > 0 ? CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_offset(features_.offset, np))
                           : CGAL::lex_optimal_feature_reconstruction(points, mesh, np);
    std::vector<std::int32_t> face_element(mesh.num_faces(), -1);
    for(Mesh::Face_index f : mesh.faces()) face_element[f] = std::int32_t(element[f]);
    CGAL::Real_timer io;
    io.start();
    file.write(mesh, options_.ascii, &face_element);
    io.stop();
    if(options_.json) {
      std::cout << statistics(r, io.time(), mesh).dump() << std::endl;
    } else {
      std::cerr << "wrote " << output_ << ": " << r.mesh_faces << " faces in " << r.element_sizes.size() - r.number_of_dropped_elements
                << " elements of the critical basis (" << r.number_of_cycles << " cycles around " << r.number_of_feature_points
                << " feature points)\n";
    }
    // the mesh is a 2-manifold with several vertices at some points: say where and why
    if(r.non_manifold_vertices + r.non_manifold_edges > 0)
      std::cerr << "note: " << r.non_manifold_vertices << " points and " << r.non_manifold_edges
                << " edges where elements of the basis meet are not manifold; the mesh has a vertex per umbrella "
                   "and an edge per face there\n";
    return 0;
  }

private:
  nlohmann::json statistics(const LOC::Feature_reconstruction_report& r, double io_seconds, const Mesh& mesh) const
  {
    nlohmann::json j;
    j["input"] = input_;
    j["output"] = output_;
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
    j["non_manifold_vertices"] = r.non_manifold_vertices;
    j["non_manifold_edges"] = r.non_manifold_edges;
    j["average_spacing"] = r.average_spacing;
    j["offset"] = r.offset;
    j["relative"] = features_.relative;
    j["delaunay_s"] = r.delaunay_seconds;
    j["feature_s"] = r.feature_seconds;
    j["subcomplex_s"] = r.subcomplex_seconds;
    j["chains_s"] = r.chain_seconds;
    j["basis_s"] = r.basis_seconds;
    j["mesh_s"] = r.mesh_seconds;
    j["write_s"] = io_seconds;
    j["total_s"] = r.total_seconds + io_seconds;
    j["peak_rss_mb"] = peak_rss_mb();
    nlohmann::json mj;
    add_mesh_statistics(mj, mesh);
    j["mesh"] = mj;
    return j;
  }

  CLI::App* command_ = nullptr;
  std::string input_, output_;
  Features_options features_;
  Output_options options_;
  double max_memory_mb_ = 0; // 0: the memory available
};

} // namespace lex_reconstruct

#endif // URBAN_LEX_RECONSTRUCT_FEATURES_COMMAND_H
