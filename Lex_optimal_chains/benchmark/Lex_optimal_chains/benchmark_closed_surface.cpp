// Benchmark of closed surface reconstruction against CGAL's Delaunay triangulation and
// advancing front reconstruction, on points sampled from a noisy torus. "resolution" is the
// resolution of the non-manifold vertices, "mesh" the rest of the making of the mesh;
// "split" counts the non-manifold vertices left (split in the mesh).
//
//   benchmark_closed_surface [N ...] [--repeat R]
//                                              runs every measurement for each N, each in a
//                                              fresh process (peak memory is per process),
//                                              R times (default 1), and prints a table with
//                                              the medians (ratios taken within a repetition);
//                                              all on the lowest-numbered CPU allowed
//   benchmark_closed_surface --one MODE N [T]  one measurement (delaunay | lex | afsr), JSON;
//                                              lex with T threads (default 1), on every CPU
//
// The table has the whole reconstruction on 2 threads (with TBB) against the Delaunay
// triangulation on one thread ("total2/DT").
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_closed_surface.h>

#include "benchmark_support.h"

#include <array>
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

// n points on a torus (R = 1, r = 0.4), uniform by area, with noise of 0.2% of r
static std::vector<Point> noisy_torus(std::size_t n)
{
  CGAL::Random rng(42);
  const double R = 1.0, r = 0.4, eps = 0.0008, pi = 3.14159265358979323846;
  std::vector<Point> pts;
  pts.reserve(n);
  while(pts.size() < n) {
    const double u = rng.get_double(0, 2 * pi), v = rng.get_double(0, 2 * pi);
    if(rng.get_double(0, R + r) > R + r * std::cos(v)) continue;
    pts.emplace_back((R + r * std::cos(v)) * std::cos(u) + rng.get_double(-eps, eps),
                     (R + r * std::cos(v)) * std::sin(u) + rng.get_double(-eps, eps),
                     r * std::sin(v) + rng.get_double(-eps, eps));
  }
  return pts;
}

static int one(const std::string& mode, std::size_t n, unsigned threads)
{
  const std::vector<Point> pts = noisy_torus(n);
  const double base_mb = peak_rss_mb();
  CGAL::Real_timer t;
  std::ostringstream json;
  json << std::setprecision(6) << "{\"mode\":\"" << mode << "\",\"n\":" << n;
  if(mode == "delaunay") {
    t.start();
    CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
    t.stop();
    json << ",\"delaunay_s\":" << t.time() << ",\"cells\":" << dt.number_of_cells();
  } else if(mode == "lex") {
    Mesh mesh;
    if(threads > 1) allow_all_cpus();
    t.start();
    const auto r = CGAL::lex_optimal_closed_surface_reconstruction(
      pts, mesh, CGAL::Lex_optimal_chains::parameters::number_of_threads(threads));
    t.stop();
    json << ",\"delaunay_s\":" << r.delaunay_seconds << ",\"order_s\":" << r.order_seconds
         << ",\"cut_s\":" << r.cut_seconds << ",\"resolution_s\":" << r.resolution_seconds
         << ",\"mesh_s\":" << r.output_seconds << ",\"total_s\":" << t.time()
         << ",\"resolved\":" << r.resolved_non_manifold_vertices << ",\"split_vertices\":" << r.non_manifold_vertices
         << ",\"faces\":" << r.mesh_faces << ",\"genus\":" << r.genus << ",\"components\":" << r.components
         << ",\"exactly_ordered\":" << r.number_of_exactly_ordered_triangles << ",\"triangles\":" << r.number_of_triangles;
  } else if(mode == "afsr") {
    std::vector<std::array<std::size_t, 3>> facets;
    t.start();
    CGAL::advancing_front_surface_reconstruction(pts.begin(), pts.end(), std::back_inserter(facets));
    t.stop();
    json << ",\"total_s\":" << t.time() << ",\"faces\":" << facets.size();
  } else {
    std::cerr << "unknown mode " << mode << "\n";
    return 2;
  }
  return print_measurement(json.str(), base_mb);
}

int main(int argc, char** argv)
{
  if((argc == 4 || argc == 5) && std::string(argv[1]) == "--one")
    return one(argv[2], std::stoul(argv[3]), argc == 5 ? unsigned(std::stoul(argv[4])) : 1u);
  if(argc == 3 && std::string(argv[1]) == "--profile") { // one verbose reconstruction
    const std::vector<Point> pts = noisy_torus(std::stoul(argv[2]));
    Mesh mesh;
    CGAL::lex_optimal_closed_surface_reconstruction(pts, mesh, CGAL::parameters::verbose(true));
    return 0;
  }
  std::vector<std::size_t> sizes;
  std::size_t repeat = 1;
  if(!parse_sizes(argc, argv, sizes, repeat)) {
    std::cerr << "usage: " << argv[0] << " [N ...] [--repeat R]   (medians of R runs of each measurement)\n"
              << "       " << argv[0] << " --one MODE N [THREADS] | --profile N\n";
    return 2;
  }
  if(sizes.empty()) sizes = {100000, 1000000};
  pin_measurements_to_one_cpu(); // the processes of the ratios on the same CPU
  std::cout << std::fixed << std::setprecision(3)
            << "points     delaunay_s  lex_total_s  order+cut_s  resolution_s  mesh_s  (order+cut)/DT  (order+cut+res+mesh)/DT"
               "  mesh_us/point  total/DT  total2/DT  peakRSS_lex/DT  afsr_s  afsr/lex  resolved  split\n";
  for(std::size_t n : sizes) {
    // the runs of one repetition follow each other: their ratios are taken before the medians
    std::vector<std::map<std::string, double>> ds, ls, as, rs;
    for(std::size_t k = 0; k < repeat; ++k) {
      auto d = run_child(std::string(argv[0]) + " --one delaunay " + std::to_string(n));
      auto l = run_child(std::string(argv[0]) + " --one lex " + std::to_string(n));
      auto l2 = run_child(std::string(argv[0]) + " --one lex " + std::to_string(n) + " 2");
      std::map<std::string, double> a;
      if(n <= 1000000) a = run_child(std::string(argv[0]) + " --one afsr " + std::to_string(n));
      const double dt = d["delaunay_s"], oc = l["order_s"] + l["cut_s"];
      const double after = oc + l["resolution_s"] + l["mesh_s"];
      std::map<std::string, double> r{{"order_cut_s", oc}, {"order_cut_dt", oc / dt}, {"after_dt", after / dt},
                                      {"mesh_us", 1e6 * (l["resolution_s"] + l["mesh_s"]) / double(n)},
                                      {"total_dt", l["total_s"] / dt}, {"total2_dt", l2["total_s"] / dt}, {"peak_dt", l["peak_rss_mb"] / d["peak_rss_mb"]}};
      if(a.count("total_s")) r["afsr_lex"] = a["total_s"] / l["total_s"];
      ds.push_back(d); ls.push_back(l); as.push_back(a); rs.push_back(r);
    }
    auto d = median(ds), l = median(ls), a = median(as), r = median(rs);
    std::cout << std::setw(9) << n << "  " << std::setw(10) << d["delaunay_s"] << "  " << std::setw(11) << l["total_s"] << "  "
              << std::setw(11) << r["order_cut_s"] << "  " << std::setw(12) << l["resolution_s"] << "  " << std::setw(6)
              << l["mesh_s"] << "  " << std::setw(14) << r["order_cut_dt"] << "  " << std::setw(23) << r["after_dt"] << "  "
              << std::setw(13) << r["mesh_us"] << "  " << std::setw(8) << r["total_dt"] << "  " << std::setw(9) << r["total2_dt"] << "  " << std::setw(14) << r["peak_dt"] << "  ";
    if(a.count("total_s")) std::cout << std::setw(6) << a["total_s"] << "  " << std::setw(8) << r["afsr_lex"];
    else std::cout << "     -         -";
    std::cout << "  " << std::setw(8) << l["resolved"] << "  " << std::setw(5) << l["split_vertices"];
    std::cout << "   (peak MB: DT " << d["peak_rss_mb"] << ", lex " << l["peak_rss_mb"] << ")";
    if(repeat > 1) std::cout << "  medians of " << repeat << " runs";
    std::cout << std::endl;
  }
  return 0;
}
