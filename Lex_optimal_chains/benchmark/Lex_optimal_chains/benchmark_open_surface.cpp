// Benchmark of open surface reconstruction in the shape of Table 4.2 of the thesis, on a
// noisy terrain (a smooth height field with steps like buildings, noise of 5 cm) meshed
// with the automatic footprint boundary.
//
//   benchmark_open_surface [N ...] [--repeat R]
//                                            each measurement in a fresh process (peak
//                                            memory is per process), R times (default 1),
//                                            then a table of medians (ratios taken within a
//                                            repetition); all on the lowest-numbered CPU
//                                            allowed
//   benchmark_open_surface --one MODE N      one measurement (delaunay | lex), JSON
//   benchmark_open_surface --profile N       one verbose reconstruction
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>

#include "benchmark_support.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;

static int one(const std::string& mode, std::size_t n, bool verbose)
{
  const std::vector<Point> pts = noisy_terrain<Point>(n);
  const std::vector<std::vector<Point>> boundary{LOC::footprint_boundary(pts)};
  const double base_mb = peak_rss_mb();
  CGAL::Real_timer t;
  std::ostringstream json;
  json << std::setprecision(6) << "{\"mode\":\"" << mode << "\",\"n\":" << n;
  if(mode == "delaunay") {
    std::vector<Point> all = pts;
    all.insert(all.end(), boundary[0].begin(), boundary[0].end() - 1);
    t.start();
    CGAL::Delaunay_triangulation_3<K> dt(all.begin(), all.end());
    t.stop();
    json << ",\"delaunay_s\":" << t.time() << ",\"cells\":" << dt.number_of_cells();
  } else if(mode == "lex") {
    Mesh mesh;
    t.start();
    const auto r = CGAL::lex_optimal_open_surface_reconstruction(
      pts, boundary, mesh, LOC::parameters::drop_boundary_triangles(true, CGAL::parameters::verbose(verbose)));
    t.stop();
    json << ",\"delaunay_s\":" << r.delaunay_seconds << ",\"representative_s\":" << r.representative_seconds
         << ",\"order_s\":" << r.order_seconds << ",\"algorithm10_s\":" << r.optimal_chain_seconds
         << ",\"resolution_s\":" << r.resolution_seconds << ",\"output_s\":" << r.output_seconds
         << ",\"total_s\":" << t.time() << ",\"vertices\":" << r.mesh_vertices
         << ",\"resolved\":" << r.resolved_non_manifold_vertices
         << ",\"faces\":" << r.mesh_faces << ",\"representative_triangles\":" << r.number_of_representative_triangles
         << ",\"non_manifold_vertices\":" << r.non_manifold_vertices;
  } else {
    std::cerr << "unknown mode " << mode << "\n";
    return 2;
  }
  return print_measurement(json.str(), base_mb);
}

int main(int argc, char** argv)
{
  if(argc == 4 && std::string(argv[1]) == "--one") return one(argv[2], std::stoul(argv[3]), false);
  if(argc == 3 && std::string(argv[1]) == "--profile") return one("lex", std::stoul(argv[2]), true);
  std::vector<std::size_t> sizes;
  std::size_t repeat = 1;
  if(!parse_sizes(argc, argv, sizes, repeat)) {
    std::cerr << "usage: " << argv[0] << " [N ...] [--repeat R]   (medians of R runs of each measurement)\n"
              << "       " << argv[0] << " --one MODE N | --profile N\n";
    return 2;
  }
  if(sizes.empty()) sizes = {1000000, 5000000};
  pin_measurements_to_one_cpu(); // the processes of the ratios on the same CPU
  std::cout << std::fixed << std::setprecision(3)
            << "points     delaunay_s  representative_s  order_s  alg10_s  optimal_chain_s  resolution_s  output_s  total_s"
               "  repr/DT  chain/DT  total/DT  peak_GB  peak/DT\n";
  for(std::size_t n : sizes) {
    // the runs of one repetition follow each other: their ratios are taken before the medians
    std::vector<std::map<std::string, double>> ds, ls, rs;
    for(std::size_t k = 0; k < repeat; ++k) {
      auto d = run_child(std::string(argv[0]) + " --one delaunay " + std::to_string(n));
      auto l = run_child(std::string(argv[0]) + " --one lex " + std::to_string(n));
      const double dt = d["delaunay_s"], chain = l["order_s"] + l["algorithm10_s"];
      rs.push_back({{"chain_s", chain}, {"repr_dt", l["representative_s"] / dt}, {"chain_dt", chain / dt},
                    {"total_dt", l["total_s"] / dt}, {"peak_dt", l["peak_rss_mb"] / d["peak_rss_mb"]}});
      ds.push_back(d); ls.push_back(l);
    }
    auto d = median(ds), l = median(ls), r = median(rs);
    std::cout << std::setw(9) << n << "  " << std::setw(10) << d["delaunay_s"] << "  " << std::setw(16) << l["representative_s"]
              << "  " << std::setw(7) << l["order_s"] << "  " << std::setw(7) << l["algorithm10_s"] << "  "
              << std::setw(15) << r["chain_s"] << "  " << std::setw(12) << l["resolution_s"] << "  " << std::setw(8)
              << l["output_s"] << "  " << std::setw(7) << l["total_s"]
              << "  " << std::setw(7) << r["repr_dt"] << "  " << std::setw(8) << r["chain_dt"] << "  "
              << std::setw(8) << r["total_dt"] << "  " << std::setw(7) << l["peak_rss_mb"] / 1024 << "  "
              << std::setw(7) << r["peak_dt"];
    std::cout << "  (" << l["resolved"] << " non-manifold vertices resolved, " << l["non_manifold_vertices"] << " split)";
    if(repeat > 1) std::cout << "  medians of " << repeat << " runs";
    std::cout << std::endl;
  }
  return 0;
}
