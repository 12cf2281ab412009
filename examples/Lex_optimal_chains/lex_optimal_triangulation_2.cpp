// The Delaunay (or regular) triangulation of 2D points found as a lexicographic optimal
// chain (Proposition 3 and Theorem 4.19 of the thesis): the minimal 2-chain of the full
// 2-complex over the points (all triangles) bounded by the boundary of their convex hull,
// computed with the general matrix algorithm.
//
//   lex_optimal_triangulation_2 [POINTS]
//
// POINTS: a text file, one point per line, "x y" or, weighted, "x y w" (all lines alike).
// Without a file, 30 random points. Prints one triangle per line: three 0-based indices of
// input points, increasing. The full complex has n(n-1)(n-2)/6 triangles: at most 200 points.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/Random.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/property_map.h>
#include <CGAL/Lex_optimal_chains/minimal_chains.h>
#include <CGAL/Lex_optimal_chains/Simplex_orders.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
namespace LOC = CGAL::Lex_optimal_chains;
using Field = LOC::Z2_field;

static void read(const std::string& path, std::vector<Point>& points, std::vector<double>& weights)
{
  std::ifstream in(path);
  if(!in) throw std::invalid_argument("cannot open '" + path + "'");
  std::string line;
  int columns = 0;
  for(int number = 1; std::getline(in, line); ++number) {
    std::istringstream ls(line);
    std::vector<double> v;
    double x;
    while(ls >> x) v.push_back(x);
    std::string rest;
    ls.clear();
    if((ls >> rest) || (v.size() != 2 && v.size() != 3 && !v.empty()))
      throw std::invalid_argument("line " + std::to_string(number) + " is not 'x y' or 'x y w'");
    if(v.empty()) continue;
    if(columns != 0 && int(v.size()) != columns)
      throw std::invalid_argument("line " + std::to_string(number) + ": all lines must have the same number of values");
    columns = int(v.size());
    for(double c : v)
      if(!std::isfinite(c)) throw std::invalid_argument("line " + std::to_string(number) + " has a NaN or infinite value");
    points.emplace_back(v[0], v[1]);
    weights.push_back(columns == 3 ? v[2] : 0.0);
  }
}

int main(int argc, char** argv)
{
  try {
    std::vector<Point> points;
    std::vector<double> weights;
    if(argc > 1) {
      read(argv[1], points, weights);
    } else {
      CGAL::Random rng(1);
      for(int i = 0; i < 30; ++i) points.emplace_back(rng.get_double(), rng.get_double()), weights.push_back(0);
    }
    const bool weighted = std::any_of(weights.begin(), weights.end(), [](double w) { return w != 0; });
    std::vector<Point> sorted = points;
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw std::invalid_argument("two points are equal");
    if(points.size() < 3) throw std::invalid_argument("fewer than 3 points");
    if(points.size() > 200) throw std::invalid_argument("more than 200 points: the full complex would be too large");

    // the convex hull boundary, a 1-cycle (Z2)
    std::vector<std::size_t> ids(points.size()), hull;
    for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
    CGAL::convex_hull_2(ids.begin(), ids.end(), std::back_inserter(hull),
                        CGAL::Convex_hull_traits_adapter_2<K, CGAL::Pointer_property_map<Point>::const_type>(
                          CGAL::make_property_map(static_cast<const std::vector<Point>&>(points))));
    if(hull.size() < 3) throw std::invalid_argument("all points are collinear");
    const LOC::Simplicial_complex complex = LOC::Simplicial_complex::full(std::uint32_t(points.size()), 2);
    LOC::Chain<Field> boundary;
    for(std::size_t i = 0; i < hull.size(); ++i) {
      const std::uint32_t a = std::uint32_t(hull[i]), b = std::uint32_t(hull[(i + 1) % hull.size()]);
      boundary.emplace_back(std::uint32_t(complex.index({(std::min)(a, b), (std::max)(a, b)})), 1);
    }
    std::sort(boundary.begin(), boundary.end());

    // the order of Lemma 4.14, or the generalized order of weighted points
    const std::vector<std::uint32_t> order =
      weighted ? LOC::sort_simplices(complex, 2, LOC::Weighted_simplex_order<Point>(points, weights))
               : LOC::sort_simplices(complex, 2, LOC::Triangle_order<Point>(points));
    const auto chain = LOC::minimal_chain_with_boundary<Field>(complex, 2, order, boundary);
    if(!chain) throw std::logic_error("the hull boundary bounds no chain"); // cannot happen
    std::vector<LOC::Simplicial_complex::Simplex> triangles;
    for(const auto& e : *chain) triangles.push_back(complex.simplex(2, e.first));
    std::sort(triangles.begin(), triangles.end());
    for(const auto& t : triangles) std::cout << t[0] << " " << t[1] << " " << t[2] << "\n";
  } catch(const std::exception& e) {
    std::cerr << "lex_optimal_triangulation_2: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
