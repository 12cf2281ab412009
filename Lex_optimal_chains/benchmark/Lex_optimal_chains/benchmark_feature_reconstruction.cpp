// Benchmark of lex_optimal_feature_reconstruction() (thesis section 4.8.3): a ground 100 x 100
// with a grid of 6 x 6 boxes (blocks of 8 to 14 on a side, 3 to 12 high), every surface
// sampled on a grid of step s (about N points) jittered by 0.2 s along it and by 0.01 s across
// it (a scan's noise; without it, the coplanar and cospherical points make most comparisons
// exact); the features by the VCM. The time
// of each stage and its ratio to the Delaunay triangulation of the same call, the numbers of
// feature points, of simplices of B, of cycles and of elements, and the peak memory. Each size
// runs in its own process, on one CPU.
//
//   benchmark_feature_reconstruction [N ...]      (default: 100,000 and 1,000,000)
//   benchmark_feature_reconstruction --one N      one measurement, JSON
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_feature_reconstruction.h>

#include "benchmark_support.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;

struct Block { double x0, y0, x1, y1, h; };

static std::vector<Point> blocks_scene(std::size_t n)
{
  CGAL::Random rng(17);
  std::vector<Block> blocks;
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 6; ++j) {
      const double x = 3 + 16 * i, y = 3 + 16 * j;
      blocks.push_back({x, y, x + rng.get_double(8, 14), y + rng.get_double(8, 14), rng.get_double(3, 12)});
    }
  double area = 100 * 100;
  for(const Block& b : blocks) area += 2 * (b.x1 - b.x0 + b.y1 - b.y0) * b.h;
  const double step = std::sqrt(area / double(n));
  auto jitter = [&] { return rng.get_double(-0.2, 0.2) * step; };
  auto noise = [&] { return rng.get_double(-0.01, 0.01) * step; };
  auto inside = [&](double x, double y) {
    for(const Block& b : blocks) if(x > b.x0 && x < b.x1 && y > b.y0 && y < b.y1) return &b;
    return static_cast<const Block*>(nullptr);
  };
  std::vector<Point> points;
  for(double x = 0; x <= 100; x += step)
    for(double y = 0; y <= 100; y += step) {
      const double px = x + jitter(), py = y + jitter();
      const Block* b = inside(px, py);
      points.emplace_back(px, py, (b ? b->h : 0.) + noise());
    }
  for(const Block& b : blocks) {
    for(double t = 0; t < b.h; t += step) {
      for(double x = b.x0; x <= b.x1; x += step) {
        points.emplace_back(x + jitter(), b.y0 + noise(), t + jitter());
        points.emplace_back(x + jitter(), b.y1 + noise(), t + jitter());
      }
      for(double y = b.y0 + step; y < b.y1; y += step) {
        points.emplace_back(b.x0 + noise(), y + jitter(), t + jitter());
        points.emplace_back(b.x1 + noise(), y + jitter(), t + jitter());
      }
    }
  }
  return points;
}

static int one(std::size_t n)
{
  const std::vector<Point> points = blocks_scene(n);
  const double base_mb = peak_rss_mb();
  Mesh mesh;
  const LOC::Feature_reconstruction_report r = CGAL::lex_optimal_feature_reconstruction(points, mesh);
  std::ostringstream json;
  json << std::setprecision(6) << "{\"n\":" << r.number_of_input_points << ",\"delaunay_s\":" << r.delaunay_seconds
       << ",\"feature_s\":" << r.feature_seconds << ",\"subcomplex_s\":" << r.subcomplex_seconds
       << ",\"chains_s\":" << r.chain_seconds << ",\"basis_s\":" << r.basis_seconds << ",\"mesh_s\":" << r.mesh_seconds
       << ",\"total_s\":" << r.total_seconds << ",\"feature_points\":" << r.number_of_feature_points
       << ",\"subcomplex_simplices\":" << r.subcomplex_vertices + r.subcomplex_edges + r.subcomplex_triangles
       << ",\"cycles\":" << r.number_of_cycles << ",\"faces\":" << r.mesh_faces;
  return print_measurement(json.str(), base_mb);
}

int main(int argc, char** argv)
{
  if(argc == 3 && std::string(argv[1]) == "--one") return one(std::stoul(argv[2]));
  std::vector<std::size_t> sizes;
  std::size_t repeat = 1;
  if(!parse_sizes(argc, argv, sizes, repeat)) {
    std::cerr << "usage: " << argv[0] << " [N ...]\n";
    return 2;
  }
  if(sizes.empty()) sizes = {100000, 1000000};
  pin_measurements_to_one_cpu();
  std::cout << std::fixed << std::setprecision(3)
            << "   points  features  B_simplices  cycles    faces  delaunay_s  feature_s  subcomplex_s  chains_s  basis_s"
               "  total_s  total/DT  peak_GB\n";
  for(std::size_t n : sizes) {
    auto r = run_child(std::string(argv[0]) + " --one " + std::to_string(n));
    std::cout << std::setw(9) << std::size_t(r["n"]) << "  " << std::setw(8) << std::size_t(r["feature_points"]) << "  "
              << std::setw(11) << std::size_t(r["subcomplex_simplices"]) << "  " << std::setw(6) << std::size_t(r["cycles"])
              << "  " << std::setw(7) << std::size_t(r["faces"]) << "  " << std::setw(10) << r["delaunay_s"] << "  "
              << std::setw(9) << r["feature_s"] << "  " << std::setw(12) << r["subcomplex_s"] << "  " << std::setw(8)
              << r["chains_s"] << "  " << std::setw(7) << r["basis_s"] << "  " << std::setw(7) << r["total_s"] << "  "
              << std::setw(8) << r["total_s"] / r["delaunay_s"] << "  " << std::setw(7) << r["peak_rss_mb"] / 1024 << std::endl;
  }
  return 0;
}
