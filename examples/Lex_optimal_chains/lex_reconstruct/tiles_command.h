// lex_reconstruct tiles: a terrain-like cloud in tiles whose meshes meet exactly at their seams,
// one mesh per tile in OUTPUT_DIR (created if missing), tile_C_R.ply for the tile of column C
// and row R, and with --merged their union, welded at the seams. Under MPI
// (lex_reconstruct_mpi) every rank reads the input and computes the seams; the tiles are dealt
// out to the ranks (balanced by their points), each rank writes its own; the first rank then
// makes the union from the tile files. The files are byte for byte those of one process.
// --out-of-core reads the input twice and buckets it into files, one per tile, so that the
// cloud is never in memory: the same tiles.
#ifndef URBAN_LEX_RECONSTRUCT_TILES_COMMAND_H
#define URBAN_LEX_RECONSTRUCT_TILES_COMMAND_H

#include "options_and_output.h"
#include "tiles_on_ranks.h"

#include <CGAL/lex_optimal_tiled_surface.h>

#include "Peak_memory.h"

#include <algorithm>
#include <exception>

namespace lex_reconstruct {

// What the tiles subcommand takes besides the output options.
struct Tiles_options
{
  double tile_size = 0, seam_spacing = 0;
  std::string merged, coefficients = "q";
  std::vector<int> classes; // of a LAS input (empty: all)
  bool out_of_core = false;
  std::string bucket_directory; // out of core: where the bucket files go (empty: next to the tiles)
};

// One run of the subcommand on the ranks of `group`: the checks, the tiles, their union, the
// report (each stage ends with settle_errors()).
class Tiles_run
{
public:
  Tiles_run(const std::string& input, const std::string& directory, const Tiles_options& t,
            const Output_options& options, const Process_group& group)
    : input_(input), directory_(directory), t_(t), options_(options), group_(group),
      measure_memory_(options.json && options.threads == 1), memory_(measure_memory_)
  {}

  int run()
  {
    check_outputs();
    reconstruct();
    merge();
    // the peak of the largest rank, union included (measuring the tiles resets getrusage's peak:
    // `memory_` has the peak before and during the tiles)
    const double peak_mb = group_.max(std::max(peak_rss_mb(), double(memory_.call_peak()) / (1024.0 * 1024.0)));
    if(!group_.is_root()) return 0;
    report(peak_mb);
    return 0;
  }

private:
  // the checks, on every rank; then the directory is created by the first tile written
  void check_outputs()
  {
    std::exception_ptr error;
    try {
      tile_directory_.reset(new Tile_directory(directory_, group_));
      if(!t_.merged.empty() && group_.is_root()) merged_file_.reset(new Output_file(t_.merged));
    } catch(...) {
      error = std::current_exception();
    }
    settle_errors(group_, error, [] {});
    field_ = t_.coefficients == "z2" ? LOC::Coefficient_field::Z2 : LOC::Coefficient_field::Q;
  }

  // on an error: the tiles written (and the directory, if created) are removed
  void undo()
  {
    tile_directory_->remove_written();
    group_.barrier();
    if(group_.is_root()) tile_directory_->remove_if_created();
  }

  // This rank's share of the tiles: every rank deals the tiles out alike, by their numbers of
  // points (Process_group::deal()), and keeps its own. Each tile is written as soon as it is
  // reconstructed, and freed: the memory is that of the tiles being reconstructed. With one
  // thread the peak memory of each tile is measured around it (Peak_memory.h).
  void reconstruct()
  {
    auto deal = [&](const std::vector<std::size_t>& points_per_tile) {
      rank_of_ = group_.deal(points_per_tile);
      std::vector<bool> mine(rank_of_.size());
      for(std::size_t k = 0; k < mine.size(); ++k) mine[k] = rank_of_[k] == group_.rank();
      memory_.start();
      return mine;
    };
    CGAL::Real_timer io;
    auto write_tile = [&](const LOC::Tile_report& tile, Mesh& mesh) {
      memory_.tile_done(tile.column, tile.row);
      io.start();
      tile_directory_->write(mesh, tile.column, tile.row, options_.ascii);
      mesh = Mesh();
      io.stop();
      memory_.visitor_done();
    };
    std::exception_ptr error;
    try {
      const auto np = LOC::parameters::seam_spacing(t_.seam_spacing,
                      LOC::parameters::coefficient_field(field_,
                      LOC::parameters::keep_non_manifold(options_.keep_non_manifold,
                      LOC::parameters::number_of_threads(options_.threads,
                      LOC::parameters::tile_filter(deal,
                      LOC::parameters::tile_visitor(write_tile))))));
      std::vector<Mesh> tiles;
      if(t_.out_of_core) { // the file read twice, the points bucketed into files
        const std::string buckets = t_.bucket_directory.empty() ? tile_directory_->parent() : t_.bucket_directory;
        auto each_point = [&](const auto& f) { LOC::IO::for_each_point_in_file<Point>(input_, t_.classes, f); };
        r_ = CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(each_point, t_.tile_size, buckets, tiles, np);
      } else {
        const std::vector<Point> points = LOC::IO::read_point_file<Point>(input_, t_.classes);
        r_ = CGAL::lex_optimal_tiled_surface_reconstruction(points, t_.tile_size, tiles, np);
      }
    } catch(...) {
      error = std::current_exception();
    }
    settle_errors(group_, error, [this] { undo(); });
    tile_peak_bytes_.resize(r_.tiles.size());
    for(std::size_t k = 0; k < r_.tiles.size(); ++k) tile_peak_bytes_[k] = memory_.tile_peak(r_.tiles[k].column, r_.tiles[k].row);
    gather_tile_reports(group_, r_, tile_peak_bytes_);
    write_s_ = group_.max(io.time());
  }

  // the union, by the first rank, from the files of all (written once every rank is here)
  void merge()
  {
    std::exception_ptr error;
    if(!t_.merged.empty() && group_.is_root()) {
      try {
        merge_watch_.start();
        m_ = merge_tile_files(*tile_directory_, r_, field_, merged_);
        merge_watch_.stop();
        merged_io_.start();
        merged_file_->write(merged_, options_.ascii);
        merged_io_.stop();
      } catch(...) {
        error = std::current_exception();
      }
    }
    settle_errors(group_, error, [this] { undo(); });
  }

  void report(double peak_mb) const
  {
    if(!options_.json) {
      std::cerr << "wrote " << r_.tiles.size() << " tiles (" << r_.columns << " x " << r_.rows << ") in " << directory_;
      if(!t_.merged.empty())
        std::cerr << " and " << t_.merged << ": " << m_.mesh_vertices << " vertices, " << m_.mesh_faces << " faces";
      std::cerr << "\n";
      return;
    }
    nlohmann::json j = tiles_json(input_, directory_, group_, r_, rank_of_, tile_peak_bytes_, measure_memory_, t_.out_of_core);
    j["merge_s"] = merge_watch_.time();
    j["write_s"] = write_s_ + merged_io_.time(); // the tiles' within tiles_s
    j["total_s"] = r_.total_seconds + merge_watch_.time() + merged_io_.time();
    j["peak_rss_mb"] = peak_mb;
    if(!t_.merged.empty()) {
      j["merged"] = t_.merged;
      nlohmann::json mj;
      add_mesh_statistics(mj, merged_);
      mj["cancelled_faces"] = m_.cancelled_faces;
      mj["removed_closed_components"] = m_.removed_closed_components;
      mj["non_manifold_vertices"] = m_.non_manifold_vertices;
      mj["non_manifold_edges"] = m_.non_manifold_edges;
      j["merged_mesh"] = mj;
    }
    std::cout << j.dump() << std::endl;
  }

  const std::string& input_;
  const std::string& directory_;
  const Tiles_options& t_;
  const Output_options& options_;
  const Process_group& group_;
  std::unique_ptr<Tile_directory> tile_directory_;
  std::unique_ptr<Output_file> merged_file_;
  LOC::Coefficient_field field_ = LOC::Coefficient_field::Q;
  const bool measure_memory_;
  Tile_peak_memory memory_;
  std::vector<std::size_t> rank_of_;         // the rank of each tile
  std::vector<std::size_t> tile_peak_bytes_; // the peak memory of each tile
  LOC::Tiled_surface_report r_;
  double write_s_ = 0;
  Mesh merged_;
  LOC::Tile_merge_report m_;
  CGAL::Real_timer merge_watch_, merged_io_;
};

class Tiles_command
{
public:
  explicit Tiles_command(CLI::App& app)
  {
    command_ = app.add_subcommand("tiles", "a terrain-like cloud in tiles whose meshes meet exactly at their seams");
    command_->add_option("INPUT", input_, "points: .xyz, .pwn, .ply, .off or .las")->required();
    command_->add_option("OUTPUT_DIR", directory_, "directory of the tile meshes tile_C_R.ply (created if missing)")->required();
    command_->add_option("--tile-size", tiles_.tile_size, "largest side of a tile, in the units of the points")
      ->required()
      ->check(positive_number());
    command_->add_option("--seam-spacing", tiles_.seam_spacing,
                         "distance between seam points (default: 3 times the mean spacing of the points)")
      ->check(positive_number());
    command_->add_option("--merged", tiles_.merged, "also write the union of the tiles, welded at the seams (.off, .ply or .obj)");
    command_->add_option("--coefficients", tiles_.coefficients, "z2 (unoriented) or q (oriented upwards, default)")
      ->check(CLI::IsMember({"z2", "q"}));
    command_->add_option("--classes", tiles_.classes, "with a LAS input: the classifications kept, e.g. 2,6 (ground, building)")
      ->delimiter(',')
      ->check(CLI::Range(0, 255));
    auto* out_of_core = command_->add_flag("--out-of-core", tiles_.out_of_core,
                                           "stream the input twice and bucket it into files per tile, so that the memory holds "
                                           "the tiles being made and not the cloud (same tiles)");
    command_->add_option("--bucket-dir", tiles_.bucket_directory,
                         "with --out-of-core: an existing directory for the bucket files (24 bytes a point; "
                         "default: OUTPUT_DIR if it exists, else its parent)")
      ->needs(out_of_core);
    add_output_options(command_, options_);
  }
  Tiles_command(const Tiles_command&) = delete; // the options point into it
  Tiles_command& operator=(const Tiles_command&) = delete;

  bool parsed() const { return command_->parsed(); }

  int run(const Process_group& group) const
  {
    return Tiles_run(input_, directory_, tiles_, options_, group).run();
  }

private:
  CLI::App* command_ = nullptr;
  std::string input_, directory_;
  Tiles_options tiles_;
  Output_options options_;
};

} // namespace lex_reconstruct

#endif // URBAN_LEX_RECONSTRUCT_TILES_COMMAND_H
