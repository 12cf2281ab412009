// Benchmark of the tiled reconstruction of a city-like terrain (section 4.8, Fig. 4.27 and
// Table 4.2 of the thesis): a cloud of 1 km x 1 km (hills, a grid of blocks 12 m high, noise
// 5 cm) meshed untiled (lex_optimal_open_surface_reconstruction() with the automatic footprint
// boundary) and in tiles of about 250,000 points (lex_optimal_tiled_surface_reconstruction(),
// then merge_tile_meshes()) on 1 and 2 threads, and streamed on 2 threads (each tile freed
// as soon as it is made, as `lex_reconstruct tiles` does after writing it; no union), against
// the Delaunay triangulation of the same points (the baseline). Each measurement runs in a
// fresh process (peak memory is per process); the one-thread runs on one CPU. Above 5M points
// only the Delaunay triangulation and the streamed tiles run.
//
// With --ranks (when lex_reconstruct_mpi was built): the same terrains written to binary PLY
// and tiled by `mpirun -np K lex_reconstruct_mpi tiles` on 1 and 2 ranks, one thread each: the
// tile phase (the slowest rank's), the whole command, the peak memory of a rank and of a tile.
//
//   benchmark_tiled_surface [N ...] [--repeat R]     (default: 1,000,000 and 5,000,000)
//   benchmark_tiled_surface --ranks [N ...]          the MPI table
//   benchmark_tiled_surface --one MODE N [THREADS]   one measurement (delaunay | untiled | tiled | streamed), JSON
//   benchmark_tiled_surface --one write N FILE       writes the terrain of N points to FILE (.ply)
//   benchmark_tiled_surface --one write_dense N NOISE FILE
//                                                    writes the dense block with walls of the tests
//                                                    (500 points per square metre, N from above,
//                                                    heights with noise NOISE) to FILE (.ply), for
//                                                    lex_reconstruct tiles and check_output_mesh
//   benchmark_tiled_surface --one out_of_core N THREADS FILE   the tiles out of core from FILE, JSON
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/lex_optimal_tiled_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>
#include <CGAL/Lex_optimal_chains/IO/input_files.h>
#include <CGAL/IO/write_points.h>

#include "benchmark_support.h"
#include "dense_block_with_walls.h"

#if defined(LEX_RECONSTRUCT_MPI) && defined(MPIEXEC)
#include <nlohmann/json.hpp>
#endif
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;

// the side of tiles of about 250,000 points of the 1 km x 1 km terrain of n points (at least
// 2 x 2 tiles)
static double tile_size(std::size_t n) { return std::min(500., 1000 * std::sqrt(250000. / double(n))); }

// The tiles out of core: the points streamed twice from `file` (binary PLY, written by
// `--one write`) into bucket files next to it, each tile freed as soon as it is made.
static int out_of_core(std::size_t n, unsigned threads, const std::string& file)
{
  if(threads > 1) allow_all_cpus();
  const double base_mb = peak_rss_mb();
  std::size_t faces = 0;
  auto free_tile = [&](const LOC::Tile_report& tile, Mesh& mesh) {
    faces += tile.mesh_faces;
    mesh = Mesh();
  };
  auto each_point = [&](const auto& f) { LOC::IO::for_each_point_in_file<Point>(file, {}, f); };
  std::vector<Mesh> tiles;
  CGAL::Real_timer t;
  t.start();
  const auto r = CGAL::lex_optimal_tiled_surface_reconstruction_out_of_core(
    each_point, tile_size(n), std::filesystem::path(file).parent_path().string(), tiles,
    LOC::parameters::number_of_threads(threads, LOC::parameters::tile_visitor(free_tile)));
  t.stop();
  double largest_tile = 0;
  for(const auto& tile : r.tiles) largest_tile = std::max(largest_tile, double(tile.number_of_points));
  std::ostringstream json;
  json << std::setprecision(6) << "{\"mode\":\"out_of_core\",\"n\":" << n << ",\"threads\":" << threads
       << ",\"total_s\":" << t.time() << ",\"seam_s\":" << r.seam_seconds << ",\"tiles_s\":" << r.tiles_seconds
       << ",\"tiles\":" << r.tiles.size() << ",\"largest_tile\":" << largest_tile << ",\"faces\":" << faces;
  return print_measurement(json.str(), base_mb);
}

static int one(const std::string& mode, std::size_t n, unsigned threads)
{
  if(threads > 1) allow_all_cpus();
  const std::vector<Point> pts = noisy_terrain<Point>(n);
  const double base_mb = peak_rss_mb();
  CGAL::Real_timer t;
  std::ostringstream json;
  json << std::setprecision(6) << "{\"mode\":\"" << mode << "\",\"n\":" << n << ",\"threads\":" << threads;
  if(mode == "delaunay") {
    t.start();
    CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
    t.stop();
    json << ",\"total_s\":" << t.time() << ",\"cells\":" << dt.number_of_cells();
  } else if(mode == "untiled") {
    Mesh mesh;
    t.start();
    const std::vector<std::vector<Point>> boundary{LOC::footprint_boundary(pts)};
    const auto r = CGAL::lex_optimal_open_surface_reconstruction(
      pts, boundary, mesh, LOC::parameters::drop_boundary_triangles(true, LOC::parameters::number_of_threads(threads)));
    t.stop();
    json << ",\"total_s\":" << t.time() << ",\"faces\":" << r.mesh_faces;
  } else if(mode == "tiled" || mode == "streamed") {
    std::vector<Mesh> tiles;
    Mesh merged;
    std::size_t faces = 0;
    auto free_tile = [&](const LOC::Tile_report& tile, Mesh& mesh) {
      faces += tile.mesh_faces;
      if(mode == "streamed") mesh = Mesh();
    };
    t.start();
    const auto r = CGAL::lex_optimal_tiled_surface_reconstruction(
      pts, tile_size(n), tiles, LOC::parameters::number_of_threads(threads, LOC::parameters::tile_visitor(free_tile)));
    LOC::Tile_merge_report m;
    if(mode == "tiled") m = LOC::merge_tile_meshes(tiles, merged);
    else m.mesh_faces = faces;
    t.stop();
    double largest_tile = 0;
    for(const auto& tile : r.tiles) largest_tile = std::max(largest_tile, double(tile.number_of_points));
    json << ",\"total_s\":" << t.time() << ",\"seam_s\":" << r.seam_seconds << ",\"tiles_s\":" << r.tiles_seconds
         << ",\"merge_s\":" << m.seconds << ",\"tiles\":" << r.tiles.size() << ",\"largest_tile\":" << largest_tile
         << ",\"faces\":" << m.mesh_faces << ",\"non_manifold_vertices\":" << m.non_manifold_vertices
         << ",\"removed_pockets\":" << m.removed_closed_components;
  } else {
    std::cerr << "unknown mode " << mode << "\n";
    return 2;
  }
  return print_measurement(json.str(), base_mb);
}

#if defined(LEX_RECONSTRUCT_MPI) && defined(MPIEXEC)
// The tile phase of lex_reconstruct_mpi on 1 and 2 ranks (one thread each), on the terrains
// written to files; the tile phase is the slowest rank's.
static int rank_table(const std::string& self, const std::vector<std::size_t>& sizes)
{
  namespace fs = std::filesystem;
  const fs::path work = fs::temp_directory_path() / ("benchmark_tiled_surface_" + std::to_string(::getpid()));
  fs::create_directories(work);
  std::cout << std::fixed << std::setprecision(3)
            << "   points  tiles  ranks  tiles_s  seam_s  total_s  tiles_s/1rank  peak_GB/rank  largest_tile_peak_GB\n";
  for(std::size_t n : sizes) {
    const std::string file = (work / ("terrain_" + std::to_string(n) + ".ply")).string();
    if(std::system((self + " --one write " + std::to_string(n) + " " + file).c_str()) != 0) {
      fs::remove_all(work);
      return 1;
    }
    double one_rank = 0;
    for(int ranks : {1, 2}) {
      const std::string out = (work / ("tiles_" + std::to_string(ranks))).string();
      const std::string command = std::string(MPIEXEC) + " --allow-run-as-root --oversubscribe -np " + std::to_string(ranks) +
                                  " " + LEX_RECONSTRUCT_MPI + " tiles " + file + " " + out + " --tile-size " +
                                  std::to_string(tile_size(n)) + " --json";
      std::string output;
      {
        FILE* p = popen(command.c_str(), "r");
        char buffer[4096];
        while(p && fgets(buffer, sizeof buffer, p)) output += buffer;
        if(!p || pclose(p) != 0) {
          std::cerr << "failed: " << command << "\n" << output;
          fs::remove_all(work);
          return 1;
        }
      }
      const nlohmann::json j = nlohmann::json::parse(output);
      double largest_tile_peak = 0;
      for(const auto& tile : j["per_tile"]) largest_tile_peak = std::max(largest_tile_peak, tile["peak_rss_mb"].get<double>());
      std::map<std::string, double> r{{"tiles", j["tiles"].get<double>()}, {"tiles_s", j["tiles_s"].get<double>()},
                                      {"seam_s", j["seam_s"].get<double>()}, {"total_s", j["total_s"].get<double>()},
                                      {"rank_peak_rss_mb", j["peak_rss_mb"].get<double>()},
                                      {"largest_tile_peak_rss_mb", largest_tile_peak}};
      fs::remove_all(out);
      if(ranks == 1) one_rank = r["tiles_s"];
      std::cout << std::setw(9) << n << "  " << std::setw(5) << int(r["tiles"]) << "  " << std::setw(5) << ranks << "  "
                << std::setw(7) << r["tiles_s"] << "  " << std::setw(6) << r["seam_s"] << "  " << std::setw(7)
                << r["total_s"] << "  " << std::setw(13) << r["tiles_s"] / one_rank << "  " << std::setw(12)
                << r["rank_peak_rss_mb"] / 1024 << "  " << std::setw(20) << r["largest_tile_peak_rss_mb"] / 1024
                << std::endl;
    }
    fs::remove(file);
  }
  fs::remove_all(work);
  return 0;
}
#endif

int main(int argc, char** argv)
{
  if(argc == 5 && std::string(argv[1]) == "--one" && std::string(argv[2]) == "write") {
    const std::vector<Point> pts = noisy_terrain<Point>(std::stoul(argv[3]));
    return CGAL::IO::write_points(argv[4], pts, CGAL::parameters::use_binary_mode(true)) ? 0 : 1;
  }
  if(argc == 6 && std::string(argv[1]) == "--one" && std::string(argv[2]) == "write_dense") {
    const double density = 500, side = std::sqrt(double(std::stoul(argv[3])) / density);
    const std::vector<Point> pts = dense_block_with_walls<Point>(side, density, std::stod(argv[4]), 1);
    return CGAL::IO::write_points(argv[5], pts, CGAL::parameters::use_binary_mode(true)) ? 0 : 1;
  }
  if(argc == 6 && std::string(argv[1]) == "--one" && std::string(argv[2]) == "out_of_core")
    return out_of_core(std::stoul(argv[3]), unsigned(std::stoul(argv[4])), argv[5]);
  if((argc == 4 || argc == 5) && std::string(argv[1]) == "--one")
    return one(argv[2], std::stoul(argv[3]), argc == 5 ? unsigned(std::stoul(argv[4])) : 1u);
  if(argc >= 2 && std::string(argv[1]) == "--ranks") {
#if defined(LEX_RECONSTRUCT_MPI) && defined(MPIEXEC)
    std::vector<std::size_t> sizes;
    for(int i = 2; i < argc; ++i) sizes.push_back(std::stoul(argv[i]));
    if(sizes.empty()) sizes = {1000000, 5000000};
    return rank_table(argv[0], sizes);
#else
    std::cerr << "lex_reconstruct_mpi was not built (MPI not found)\n";
    return 2;
#endif
  }
  std::vector<std::size_t> sizes;
  std::size_t repeat = 1;
  if(!parse_sizes(argc, argv, sizes, repeat)) {
    std::cerr << "usage: " << argv[0] << " [N ...] [--repeat R]   (medians of R runs of each measurement)\n"
              << "       " << argv[0] << " --one MODE N [THREADS]\n";
    return 2;
  }
  if(sizes.empty()) sizes = {1000000, 5000000};
  pin_measurements_to_one_cpu();
  std::cout << std::fixed << std::setprecision(3)
            << "   points  tiles  delaunay_s  untiled_s  tiled_1t_s  tiled_2t_s  streamed_2t_s  untiled/DT  tiled_1t/DT"
               "  tiled_2t/DT  streamed/DT  2t/1t  out_of_core_2t_s  ooc/DT  peak_GB: DT  untiled  tiled_1t  tiled_2t"
               "  streamed  out_of_core\n";
  const std::string self = argv[0];
  namespace fs = std::filesystem;
  const fs::path work = fs::temp_directory_path() / ("benchmark_tiled_surface_" + std::to_string(::getpid()));
  fs::create_directories(work);
  const std::string terrain_file = (work / "terrain.ply").string();
  for(std::size_t n : sizes) {
    std::vector<std::map<std::string, double>> ds, us, t1s, t2s, sts, os, rs;
    if(std::system((self + " --one write " + std::to_string(n) + " " + terrain_file).c_str()) != 0) {
      fs::remove_all(work);
      return 1;
    }
    for(std::size_t k = 0; k < repeat; ++k) {
      const bool all = n <= 5000000;
      std::map<std::string, double> none;
      auto d = run_child(self + " --one delaunay " + std::to_string(n));
      auto u = all ? run_child(self + " --one untiled " + std::to_string(n)) : none;
      auto t1 = all ? run_child(self + " --one tiled " + std::to_string(n) + " 1") : none;
      auto t2 = all ? run_child(self + " --one tiled " + std::to_string(n) + " 2") : none;
      auto st = run_child(self + " --one streamed " + std::to_string(n) + " 2");
      auto o = run_child(self + " --one out_of_core " + std::to_string(n) + " 2 " + terrain_file);
      const double dt = d["total_s"];
      rs.push_back({{"untiled_dt", u["total_s"] / dt}, {"t1_dt", t1["total_s"] / dt}, {"t2_dt", t2["total_s"] / dt},
                    {"st_dt", st["total_s"] / dt}, {"t2_t1", t1["total_s"] > 0 ? t2["total_s"] / t1["total_s"] : 0},
                    {"o_dt", o["total_s"] / dt}});
      ds.push_back(d); us.push_back(u); t1s.push_back(t1); t2s.push_back(t2); sts.push_back(st); os.push_back(o);
    }
    fs::remove(terrain_file);
    auto d = median(ds), u = median(us), t1 = median(t1s), t2 = median(t2s), st = median(sts), o = median(os), r = median(rs);
    std::cout << std::setw(9) << n << "  " << std::setw(5) << int(st["tiles"]) << "  " << std::setw(10) << d["total_s"]
              << "  " << std::setw(9) << u["total_s"] << "  " << std::setw(10) << t1["total_s"] << "  " << std::setw(10)
              << t2["total_s"] << "  " << std::setw(13) << st["total_s"] << "  " << std::setw(10) << r["untiled_dt"]
              << "  " << std::setw(11) << r["t1_dt"] << "  " << std::setw(11) << r["t2_dt"] << "  " << std::setw(11)
              << r["st_dt"] << "  " << std::setw(5) << r["t2_t1"] << "  " << std::setw(16) << o["total_s"] << "  "
              << std::setw(6) << r["o_dt"] << "  " << std::setw(11) << d["peak_rss_mb"] / 1024
              << "  " << std::setw(7) << u["peak_rss_mb"] / 1024 << "  " << std::setw(8) << t1["peak_rss_mb"] / 1024
              << "  " << std::setw(8) << t2["peak_rss_mb"] / 1024 << "  " << std::setw(8) << st["peak_rss_mb"] / 1024
              << "  " << std::setw(11) << o["peak_rss_mb"] / 1024;
    if(repeat > 1) std::cout << "  medians of " << repeat << " runs";
    std::cout << std::endl;
  }
  std::cout << "thesis, Table 4.2 (Dublin, untiled, one tile each): 1,056,038 points: Delaunay 2.633 s, total 4.208 s, "
               "1.4 GB; 5,225,819 points: 14.416 s, 22.461 s, 5.5 GB\n";
  fs::remove_all(work);
  return 0;
}
