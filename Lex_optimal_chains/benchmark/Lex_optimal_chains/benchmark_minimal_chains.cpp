// Benchmark of the matrix algorithms on 3D Delaunay complexes (points uniform in a cube):
// the reduction of the boundary matrix of the tetrahedra (rows: triangles in the order of
// Lemma 4.14; Lex-OHCP of a triangle, Algorithms 2+3) and of the triangles (columns in that
// order, with V; minimal 2-chain bounded by the boundary of a triangle, Algorithms 4+6+5),
// time and peak memory, each size in its own process, and the growth exponents.
//
//   benchmark_minimal_chains [N ...]        (default 1000 2000 4000 8000)
//   benchmark_minimal_chains --one N
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Lex_optimal_chains/minimal_chains.h>
#include <CGAL/Lex_optimal_chains/Simplex_orders.h>

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
namespace LOC = CGAL::Lex_optimal_chains;

static int one(std::size_t n)
{
  CGAL::Random rng(8);
  std::vector<Point> points;
  for(std::size_t i = 0; i < n; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  CGAL::Real_timer t;
  t.start();
  CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end());
  std::map<Point, std::uint32_t> index_of;
  for(std::uint32_t i = 0; i < points.size(); ++i) index_of[points[i]] = i;
  LOC::Simplicial_complex complex{std::uint32_t(n)};
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    complex.add_simplex({index_of[c->vertex(0)->point()], index_of[c->vertex(1)->point()],
                         index_of[c->vertex(2)->point()], index_of[c->vertex(3)->point()]});
  const std::vector<std::uint32_t> order = LOC::sort_simplices(complex, 2, LOC::Triangle_order<Point>(points));
  t.stop();
  const double build = t.time();
  // a chain: one triangle (the largest)
  const LOC::Chain<LOC::Z2_field> gamma0{{order.back(), 1}};
  t.reset(); t.start();
  const auto homologous = LOC::minimal_homologous_chain<LOC::Z2_field>(complex, 2, order, gamma0);
  t.stop();
  const double ohcp = t.time();
  LOC::Chain<LOC::Z2_field> boundary;
  for(const auto& fs : complex.boundary(2, order.back())) boundary.emplace_back(fs.first, 1);
  std::sort(boundary.begin(), boundary.end());
  t.reset(); t.start();
  const auto bounded = LOC::minimal_chain_with_boundary<LOC::Z2_field>(complex, 2, order, boundary);
  t.stop();
  std::cout << std::setprecision(6) << "{\"n\":" << n << ",\"triangles\":" << complex.number_of_simplices(2)
            << ",\"tetrahedra\":" << complex.number_of_simplices(3) << ",\"build_s\":" << build
            << ",\"homologous_s\":" << ohcp << ",\"with_boundary_s\":" << t.time()
            << ",\"homologous_size\":" << homologous.size() << ",\"bounded_size\":" << (bounded ? bounded->size() : 0)
            << ",\"peak_rss_mb\":" << peak_rss_mb() << "}" << std::endl;
  return 0;
}

int main(int argc, char** argv)
{
  if(argc == 3 && std::string(argv[1]) == "--one") return one(std::stoul(argv[2]));
  std::vector<std::size_t> sizes;
  for(int i = 1; i < argc; ++i) sizes.push_back(std::stoul(argv[i]));
  if(sizes.empty()) sizes = {1000, 2000, 4000, 8000};
  std::cout << "points  triangles  homologous_s (d3)  exponent  with_boundary_s (d2)  exponent  peak_MB\n";
  std::map<std::string, double> previous;
  for(std::size_t n : sizes) {
    auto v = run_child(std::string(argv[0]) + " --one " + std::to_string(n));
    auto exponent = [&](const char* key) {
      if(previous.empty() || previous[key] <= 0) return std::string("   -");
      std::ostringstream s;
      s << std::fixed << std::setprecision(2) << std::log(v[key] / previous[key]) / std::log(v["triangles"] / previous["triangles"]);
      return s.str();
    };
    std::cout << std::fixed << std::setprecision(3) << std::setw(6) << n << "  " << std::setw(9) << v["triangles"] << "  "
              << std::setw(17) << v["homologous_s"] << "  " << std::setw(8) << exponent("homologous_s") << "  "
              << std::setw(20) << v["with_boundary_s"] << "  " << std::setw(8) << exponent("with_boundary_s") << "  "
              << std::setw(7) << v["peak_rss_mb"] << std::endl;
    previous = v;
  }
  return 0;
}
