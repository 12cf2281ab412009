// lex_reconstruct tiles: the work shared by the ranks of a process group (one process, or the
// MPI ranks of lex_reconstruct_mpi). Errors are settled across the ranks (one line on stderr,
// the first in the order of the work), the tile directory is written by every rank and undone
// on error, the union is made from the tile files, and the tile reports are gathered.
#ifndef URBAN_LEX_RECONSTRUCT_TILES_ON_RANKS_H
#define URBAN_LEX_RECONSTRUCT_TILES_ON_RANKS_H

#include "options_and_output.h"

#include <CGAL/lex_optimal_tiled_surface.h>

#include "../Process_group.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <limits>

namespace lex_reconstruct {

// An error already reported by another rank: this rank exits with code 1 and says nothing.
struct Reported_by_another_rank : std::runtime_error
{
  Reported_by_another_rank() : std::runtime_error("reported by another rank") {}
};

// Where an error comes in the order of the work: -1 before the tiles, the tile's row and column
// for the error of a tile (the library names it: "tile (C, R): ..."), none for no error.
constexpr long long no_error = std::numeric_limits<long long>::max();

inline long long error_order(const std::exception_ptr& error)
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
inline void settle_errors(const Process_group& group, const std::exception_ptr& error, const std::function<void()>& undo)
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
inline LOC::Tile_merge_report merge_tile_files(const Tile_directory& directory, const LOC::Tiled_surface_report& r,
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
inline void gather_tile_reports(const Process_group& group, LOC::Tiled_surface_report& r,
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
inline nlohmann::json tiles_json(const std::string& input, const std::string& directory, const Process_group& group,
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

} // namespace lex_reconstruct

#endif // URBAN_LEX_RECONSTRUCT_TILES_ON_RANKS_H
