// A curve through noisy 2D samples as a lexicographic optimal path (thesis Fig. 4.11): in the
// Delaunay triangulation of the samples, the minimal 1-chain bounded by two end samples, for
// the order of the edges by length (a user-given strict total order, ties broken by the
// vertices). Lexicographic minimality avoids long edges above all: the path follows the
// samples, without the shortcuts a shortest path would take.
//
//   lex_optimal_curve_2 [N]     N noisy samples of a spiral arc (default 400)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Random.h>
#include <CGAL/Lex_optimal_chains/minimal_chains.h>
#include <CGAL/Lex_optimal_chains/triangulation_complex.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
namespace LOC = CGAL::Lex_optimal_chains;
using Simplex = LOC::Simplicial_complex::Simplex;

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 400;
  if(n < 2) { std::cerr << "lex_optimal_curve_2: error: at least 2 samples\n"; return 1; }
  CGAL::Random rng(4);
  std::vector<Point> points;
  for(int i = 0; i < n; ++i) { // a spiral arc, noise of about a third of the sampling step
    const double t = 1 + 3 * CGAL_PI * i / (n - 1), r = 0.1 * t;
    points.emplace_back(r * std::cos(t) + rng.get_double(-0.004, 0.004), r * std::sin(t) + rng.get_double(-0.004, 0.004));
  }
  // the Delaunay 2-complex of the samples; its vertex i is the sample index_of[...]
  CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
  const auto tc = LOC::triangulation_complex_2(dt);
  const LOC::Simplicial_complex& complex = tc.complex;
  std::map<Point, std::uint32_t> sample_of;
  for(std::uint32_t i = 0; i < points.size(); ++i) sample_of[points[i]] = i;
  std::vector<std::uint32_t> sample(tc.vertices.size()), vertex(points.size());
  for(std::uint32_t v = 0; v < tc.vertices.size(); ++v) vertex[sample[v] = sample_of[tc.vertices[v]->point()]] = v;

  // edges by squared length, then by their vertices (a strict total order)
  auto less = [&](const Simplex& a, const Simplex& b) {
    const double la = CGAL::squared_distance(tc.vertices[a[0]]->point(), tc.vertices[a[1]]->point());
    const double lb = CGAL::squared_distance(tc.vertices[b[0]]->point(), tc.vertices[b[1]]->point());
    if(la != lb) return la < lb;
    // ties: by the sorted sample indices, which do not depend on the triangulation's numbering
    return std::minmax(sample[a[0]], sample[a[1]]) < std::minmax(sample[b[0]], sample[b[1]]);
  };
  const std::vector<std::uint32_t> order = LOC::sort_simplices(complex, 1, less);
  // the boundary: the two ends (vertices are 0-simplices; Z2)
  LOC::Chain<LOC::Z2_field> ends{{vertex[0], 1}, {vertex[n - 1], 1}}; // vertex i is the 0-simplex i
  std::sort(ends.begin(), ends.end());
  const auto path = LOC::minimal_chain_with_boundary<LOC::Z2_field>(complex, 1, order, ends);
  std::size_t along = 0;
  for(const auto& e : *path) {
    const Simplex& s = complex.simplex(1, e.first);
    const auto ab = std::minmax(sample[s[0]], sample[s[1]]);
    along += (ab.second == ab.first + 1); // an edge between consecutive samples of the curve
  }
  std::cout << "path of " << path->size() << " edges between the two ends, " << along
            << " of them between consecutive samples of the curve\n";
  for(const auto& e : *path)
    std::cout << sample[complex.simplex(1, e.first)[0]] << " " << sample[complex.simplex(1, e.first)[1]] << "\n";
  return 0;
}
