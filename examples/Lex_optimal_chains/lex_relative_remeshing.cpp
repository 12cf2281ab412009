// Relative remeshing (thesis Fig. 4.28): a patch of terrain is remeshed inside a junction
// cycle that is badly placed (here it runs 1.5 m above the ground, as the border of an old
// mesh would after a change of the terrain). With absolute chains the new patch must end
// exactly on that cycle; with chains relative to a band B of triangles around it, the patch
// may end anywhere in B, and the result is lexicographically smaller.
//
//   lex_relative_remeshing [NUMBER_OF_POINTS]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Lex_optimal_chains_traits_3.h>
#include <CGAL/lex_optimal_homologous_chain.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <set>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using DT = CGAL::Delaunay_triangulation_3<K>;
using Facet = DT::Facet;
using Vertex_handle = DT::Vertex_handle;
namespace LOC = CGAL::Lex_optimal_chains;
using Triangle = std::array<Vertex_handle, 3>; // vertices sorted by address

double ground(double x, double y) { return 2 * std::sin(x / 15) * std::cos(y / 20); }

Triangle triangle(const Facet& f)
{
  Triangle t{{f.first->vertex((f.second + 1) & 3), f.first->vertex((f.second + 2) & 3), f.first->vertex((f.second + 3) & 3)}};
  std::sort(t.begin(), t.end());
  return t;
}

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 20000;
  CGAL::Random rng(3);
  DT dt;
  // the new acquisition: a noisy terrain on [0, 100]^2
  std::vector<Point> points;
  for(int i = 0; i < n; ++i) {
    const double x = rng.get_double(0, 100), y = rng.get_double(0, 100);
    points.emplace_back(x, y, ground(x, y) + rng.get_double(-0.05, 0.05));
  }
  dt.insert(points.begin(), points.end());
  // the junction with the old mesh: a circle of radius 30, 1.5 m above the ground; its edges
  // (1 m long) are Delaunay edges since their diametral balls stay above the terrain
  const double elevation = 1.5;
  const int k = 190;
  std::vector<Vertex_handle> ring;
  for(int i = 0; i < k; ++i) {
    const double a = 2 * CGAL_PI * i / k, x = 50 + 30 * std::cos(a), y = 50 + 30 * std::sin(a);
    ring.push_back(dt.insert(Point(x, y, ground(x, y) + elevation)));
  }
  std::vector<std::pair<Vertex_handle, Vertex_handle>> cycle;
  for(int i = 0; i < k; ++i) cycle.emplace_back(ring[i], ring[(i + 1) % k]);
  for(const auto& e : cycle) {
    DT::Cell_handle c;
    int i, j;
    if(!dt.is_edge(e.first, e.second, c, i, j)) {
      std::cerr << "a junction edge is not a Delaunay edge\n";
      return 1;
    }
  }

  // B: the triangles inside the 2.5 m offset of the junction (tested at their vertices, edge
  // midpoints and centroid). A coarser rule, such as "all three vertices near the junction",
  // would take long triangles across the circle, which together span it: the relative class
  // would then be zero, and so would the relative optimum.
  auto near_junction = [&](const Point& p) {
    for(const Vertex_handle& r : ring)
      if(CGAL::squared_distance(p, r->point()) < 2.5 * 2.5) return true;
    return false;
  };
  std::vector<Facet> band;
  for(auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
    const Triangle t = triangle(*f);
    const Point& p = t[0]->point();
    const Point& q = t[1]->point();
    const Point& r = t[2]->point();
    if(near_junction(p) && near_junction(q) && near_junction(r) && near_junction(CGAL::midpoint(p, q)) &&
       near_junction(CGAL::midpoint(q, r)) && near_junction(CGAL::midpoint(r, p)) && near_junction(CGAL::centroid(p, q, r)))
      band.push_back(*f);
  }

  std::vector<std::pair<Facet, std::int64_t>> absolute, relative;
  CGAL::lex_optimal_chain_with_boundary(dt, cycle, std::back_inserter(absolute));
  CGAL::lex_optimal_chain_with_boundary(dt, cycle, std::back_inserter(relative), LOC::parameters::relative_facets(band));

  // compare them as relative chains: the triangles of B do not count
  std::set<Triangle> in_band;
  for(const Facet& f : band) in_band.insert(triangle(f));
  std::set<Triangle> a, r;
  for(const auto& fk : absolute) if(!in_band.count(triangle(fk.first))) a.insert(triangle(fk.first));
  for(const auto& fk : relative) r.insert(triangle(fk.first));
  std::vector<Triangle> difference;
  std::set_symmetric_difference(a.begin(), a.end(), r.begin(), r.end(), std::back_inserter(difference));
  CGAL::Lex_optimal_chains_traits_3<K>::Compare_triangle_order_3 compare;
  auto less = [&](const Triangle& s, const Triangle& t) {
    return compare(s[0]->point(), s[1]->point(), s[2]->point(), t[0]->point(), t[1]->point(), t[2]->point()) == CGAL::SMALLER;
  };
  std::cout << "junction of " << k << " edges, band B of " << band.size() << " triangles\n"
            << "absolute optimum: " << absolute.size() << " triangles (" << a.size() << " outside B)\n"
            << "relative optimum: " << relative.size() << " triangles\n";
  if(difference.empty()) {
    std::cout << "the two optima coincide outside B\n";
    return 0;
  }
  const Triangle largest = *std::max_element(difference.begin(), difference.end(), less);
  const bool relative_is_smaller = a.count(largest) != 0;
  std::cout << "the largest triangle where they differ belongs to the "
            << (relative_is_smaller ? "absolute" : "relative") << " optimum: the relative optimum is lexicographically "
            << (relative_is_smaller ? "smaller" : "LARGER (this would be a bug)") << "\n";
  // the absolute optimum, cut to K \ B, is one of the chains the relative problem minimizes over
  return relative_is_smaller ? 0 : 1;
}
