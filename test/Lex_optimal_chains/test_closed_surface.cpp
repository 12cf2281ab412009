// Closed surface reconstruction: samples of surfaces of known topology (sphere, torus, a
// genus-2 mesh from CGAL's data sampled by PMP) give closed, valid, outward oriented meshes of
// the right genus near the samples; identical output for shuffled input and 1 or 2 threads;
// kitten.xyz gives one closed component; constraints; bad input gives the documented error.
//   test_closed_surface [CGAL data directory]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/lex_optimal_closed_surface.h>
#include <CGAL/Lex_optimal_chains/Lexicographic_min_cut.h>

#include "test_support.h"

#include <boost/iterator/indirect_iterator.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using DT = CGAL::Delaunay_triangulation_3<K>;
namespace LOC = CGAL::Lex_optimal_chains;
namespace PMP = CGAL::Polygon_mesh_processing;

CGAL::Random rng(2026);
const double pi = 3.14159265358979323846;

Vector noise(double s) { return Vector(rng.get_double(-s, s), rng.get_double(-s, s), rng.get_double(-s, s)); }

std::vector<Point> sample_sphere(std::size_t n, const Point& c, double r, double eps)
{
  std::vector<Point> pts;
  while(pts.size() < n) {
    const Vector v(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
    const double l = std::sqrt(v.squared_length());
    if(l < 1e-3 || l > 1) continue;
    pts.push_back(c + v * (r / l) + noise(eps));
  }
  return pts;
}

// uniform on the torus by rejection on the area element (R + r cos v)
std::vector<Point> sample_torus(std::size_t n, double R, double r, double eps)
{
  std::vector<Point> pts;
  while(pts.size() < n) {
    const double u = rng.get_double(0, 2 * pi), v = rng.get_double(0, 2 * pi);
    if(rng.get_double(0, R + r) > R + r * std::cos(v)) continue;
    pts.push_back(Point((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)) + noise(eps));
  }
  return pts;
}

long euler_genus(const Mesh& m)
{
  const long chi = long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
  return (2 - chi) / 2;
}

std::string as_off(const Mesh& m)
{
  std::ostringstream out;
  out.precision(17);
  CGAL::IO::write_OFF(out, m);
  return out.str();
}

// checks shared by all closed reconstructions
void check_mesh(const Mesh& m, const LOC::Closed_surface_report& r, const std::vector<Point>& input)
{
  assert(CGAL::is_valid_polygon_mesh(m));
  assert(CGAL::is_closed(m));
  assert(CGAL::is_triangle_mesh(m));
  assert(r.mesh_faces == num_faces(m) && r.mesh_vertices == num_vertices(m));
  assert(PMP::is_outward_oriented(m));
  // interpolating: every vertex is an input point
  std::set<Point> in(input.begin(), input.end());
  for(auto v : vertices(m)) assert(in.count(m.point(v)) == 1);
}

template <class Points, class NP = CGAL::parameters::Default_named_parameters>
LOC::Closed_surface_report reconstruct(const Points& pts, Mesh& m, const NP& np = CGAL::parameters::default_values())
{
  m.clear();
  return CGAL::lex_optimal_closed_surface_reconstruction(pts, m, np);
}

// ---- the oracle of the contracted cut: the straightforward algorithms on all the facets ----
// All the finite facets sorted (Sorted_dual_graph_3 without filter), the persistence by a
// plain Kruskal pass over all of them, and Algorithm 8 by the public Lexicographic_min_cut
// over all of them; the contracted pipeline of lex_optimal_closed_surface() must give the
// same interior cell, the same inside cells and the same cut in the same order.
namespace LI = LOC::internal;
using Full_graph = LI::Sorted_dual_graph_3<DT>;

LI::Automatic_interior full_most_persistent_void(const Full_graph& graph, const std::vector<std::uint32_t>& sinks)
{
  const auto& records = graph.records();
  const std::size_t n = graph.number_of_cells(), m = records.size();
  constexpr std::uint32_t unborn = std::numeric_limits<std::uint32_t>::max();
  LI::Union_find sets(n);
  std::vector<std::uint32_t> birth(n, unborn);
  std::uint32_t sink_root = sinks.front();
  for(std::uint32_t c : sinks) sink_root = sets.unite(sink_root, c);
  birth[sink_root] = 0;
  LI::Automatic_interior best;
  bool found = false;
  for(std::size_t t = 0; t < m; ++t) {
    const auto& r = records[m - 1 - t];
    const std::uint32_t scan = std::uint32_t(t + 1);
    const std::uint32_t a = sets.find(Full_graph::owner_position(r)), b = sets.find(Full_graph::other_position(r));
    if(birth[a] == unborn) birth[a] = scan;
    if(birth[b] == unborn) birth[b] = scan;
    if(a == b) continue;
    const bool a_younger = birth[a] > birth[b] || (birth[a] == birth[b] && a > b);
    const std::uint32_t young = a_younger ? a : b, old = a_younger ? b : a;
    const auto& born_with = records[m - birth[young]];
    const double born = LI::key_value(born_with.key), dies = LI::key_value(r.key);
    const double persistence = dies > 0 ? born / dies : std::numeric_limits<double>::infinity();
    if(!found || persistence > best.persistence) {
      best.cell = sets.find(Full_graph::owner_position(born_with)) == young ? Full_graph::owner_position(born_with)
                                                                           : Full_graph::other_position(born_with);
      best.persistence = persistence;
      found = true;
    }
    const std::uint32_t old_birth = birth[old];
    birth[sets.link_roots(a, b)] = old_birth;
  }
  assert(found);
  return best;
}

// The cells of `dt` holding `points`, by position (the cells of a point on a facet, edge or vertex: all of them)
std::vector<std::uint32_t> cells_of(const DT& dt, const Full_graph& graph, const std::vector<Point>& points)
{
  std::vector<std::uint32_t> cells;
  for(const Point& p : points) cells.push_back(graph.position(dt.locate(p)));
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

// Compares the facets and the inside of the contracted pipeline (the optimal cycle kept as it
// is: keep_non_manifold) with the oracle, for the automatic interior when `interior` is empty
// and otherwise for the cells holding `interior` (whose points must lie inside cells), plus,
// for the automatic case, Algorithm 8 from
// `extra_sources` other single cells through the spanning tree.
void check_against_full_algorithm_8(const std::vector<Point>& pts, const std::vector<Point>& interior,
                                    const std::vector<Point>& exterior, const char* what, int extra_sources = 0)
{
  const DT dt(pts.begin(), pts.end());
  const Full_graph graph(dt, [](double) { return true; });
  std::vector<std::uint32_t> sinks = cells_of(dt, graph, exterior);
  {
    std::vector<DT::Cell_handle> hull;
    dt.incident_cells(dt.infinite_vertex(), std::back_inserter(hull));
    for(const auto& c : hull) sinks.push_back(graph.position(c));
    std::sort(sinks.begin(), sinks.end());
    sinks.erase(std::unique(sinks.begin(), sinks.end()), sinks.end());
  }
  auto always = [](double) { return true; };
  // the oracle's cut from the given sources, as (inside cell, facet) in decreasing order
  auto full_cut = [&](const std::vector<std::uint32_t>& sources) {
    LOC::Lexicographic_min_cut cut(graph.number_of_cells(), sources, sinks);
    std::vector<DT::Facet> facets;
    const auto& records = graph.records();
    for(std::size_t t = records.size(); t-- > 0;) {
      const auto& r = records[t];
      if(!cut.process(Full_graph::owner_position(r), Full_graph::other_position(r))) continue;
      const auto owner = graph.cell(Full_graph::owner_position(r));
      const int j = Full_graph::facet_index(r);
      if(cut.is_on_source_side(Full_graph::owner_position(r))) facets.emplace_back(owner, j);
      else facets.emplace_back(owner->neighbor(j), owner->neighbor(j)->index(owner));
    }
    return facets;
  };
  std::vector<DT::Facet> got;
  LOC::Closed_surface_report report;
  if(interior.empty()) {
    const LI::Automatic_interior expected = full_most_persistent_void(graph, sinks);
    report = CGAL::lex_optimal_closed_surface(dt, std::back_inserter(got),
                                              LOC::parameters::minimum_interior_persistence(0.0, LOC::parameters::exterior_points(exterior,
                                              LOC::parameters::keep_non_manifold(true))));
    assert(report.interior_persistence == expected.persistence);
    assert(got == full_cut(std::vector<std::uint32_t>{expected.cell}));
    // other single sources, through the spanning tree of the contracted pass
    LI::Contracted_dual_graph_3<DT> contracted(dt, graph.cell_positions(), std::vector<std::uint32_t>(), sinks, always);
    LI::Dense_numbers components;
    std::vector<std::uint32_t> tree;
    const LI::Automatic_interior a = LI::most_persistent_void(contracted, components, tree);
    assert(a.cell == expected.cell);
    std::size_t contractions = 0;
    for(std::uint32_t c = 0; c < graph.number_of_cells(); ++c)
      contractions += contracted.across(c) != c && !(contracted.across(contracted.across(c)) == c && contracted.across(c) < c);
    assert(tree.size() + contractions == graph.number_of_cells() - sinks.size()); // a spanning tree, sinks contracted
    const std::vector<std::uint32_t> tree_copy = tree;
    CGAL::Random pick(7);
    for(int k = 0; k < extra_sources; ++k) {
      std::uint32_t s;
      do s = std::uint32_t(pick.get_int(0, int(graph.number_of_cells())));
      while(std::binary_search(sinks.begin(), sinks.end(), s));
      LI::Contracted_dual_graph_3<DT> again(dt, graph.cell_positions(), std::vector<std::uint32_t>(), sinks, always);
      LI::Dense_numbers again_components;
      std::vector<std::uint32_t> again_tree;
      LI::most_persistent_void(again, again_components, again_tree);
      assert(again_tree == tree_copy);
      std::vector<bool> inside;
      const auto cut = LI::lexicographic_closed_cut_from_tree(again, again_components, again_tree, s, sinks, inside, always);
      std::vector<DT::Facet> facets;
      for(const auto& r : cut) {
        const auto owner = graph.cell(Full_graph::owner_position(r));
        const int j = Full_graph::facet_index(r);
        if(inside[Full_graph::owner_position(r)]) facets.emplace_back(owner, j);
        else facets.emplace_back(owner->neighbor(j), owner->neighbor(j)->index(owner));
      }
      assert(facets == full_cut(std::vector<std::uint32_t>{s}));
    }
  } else {
    report = CGAL::lex_optimal_closed_surface(dt, std::back_inserter(got),
                                              LOC::parameters::exterior_points(exterior, LOC::parameters::interior_points(interior,
                                              LOC::parameters::keep_non_manifold(true))));
    assert(got == full_cut(cells_of(dt, graph, interior)));
  }
  std::cout << what << ": the contracted cut equals Algorithm 8 over all " << graph.records().size()
            << " facets (" << got.size() << " facets cut";
  if(extra_sources > 0) std::cout << ", and from " << extra_sources << " other sources";
  std::cout << ")\n";
}

// Dense indices over elements in blocks far apart in memory (a static array and a large heap
// block, terabytes apart on Linux): the page table must not span the address range (it once
// took 11 GB when the allocator placed the cells of a triangulation in two regions).
static int static_block[3000];

// peak resident memory of the process in MB (Linux), 0 elsewhere
double peak_rss_mb()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024;
  return 0;
}

void test_handle_index_map()
{
  std::vector<int> heap_block(std::size_t(1) << 22); // mmapped by glibc: far from the static array
  std::vector<const int*> order; // runs: a piece of each block, twice
  for(int i = 0; i < 1000; ++i) order.push_back(static_block + i);
  for(int i = 0; i < 5000; ++i) order.push_back(heap_block.data() + 100000 + i);
  for(int i = 2000; i < 3000; ++i) order.push_back(static_block + i);
  for(int i = 0; i < 5000; ++i) order.push_back(heap_block.data() + 3000000 + i);
  for(int& x : heap_block) x = 1; // resident before the peak is read
  const double before = peak_rss_mb();
  const LOC::internal::Handle_index_map<int> map(boost::make_indirect_iterator(order.begin()),
                                                 boost::make_indirect_iterator(order.end()), 7);
  assert(peak_rss_mb() - before < 64); // not gigabytes of page table
  assert(map.size() == order.size());
  for(std::uint32_t i = 0; i < order.size(); ++i) {
    assert(map.index(order[i]) == i + 7);
    assert(map.element(i + 7) == order[i]);
  }
  std::cout << "dense indices over blocks " << std::abs(reinterpret_cast<const char*>(heap_block.data()) -
                                                         reinterpret_cast<const char*>(static_block)) / (1 << 20)
            << " MB apart: OK\n";
}

int main(int argc, char** argv)
{
  std::cout << std::unitbuf;
  const std::string data = argc > 1 ? argv[1] : "";
  Mesh m;
  test_handle_index_map();

  // --- sphere, noisy, automatic interior -------------------------------------------------------
  {
    const std::vector<Point> pts = sample_sphere(20000, Point(0.3, -0.2, 0.1), 1.0, 0.002);
    const LOC::Closed_surface_report r = reconstruct(pts, m);
    check_mesh(m, r, pts);
    assert(r.automatic_interior && r.components == 1 && r.genus == 0 && euler_genus(m) == 0);
    for(auto f : faces(m)) { // the faces lie on the sphere, up to the noise and the chord
      Point c = CGAL::centroid(m.point(target(halfedge(f, m), m)), m.point(target(next(halfedge(f, m), m), m)),
                               m.point(source(halfedge(f, m), m)));
      assert(std::abs(std::sqrt(CGAL::squared_distance(c, Point(0.3, -0.2, 0.1))) - 1.0) < 0.02);
    }
    std::cout << "sphere: " << r.mesh_faces << " faces, persistence " << r.interior_persistence
              << ", non-manifold vertices/edges " << r.non_manifold_vertices << "/" << r.non_manifold_edges << "\n";

    // shuffled input and a different number of threads give the same mesh
    std::vector<Point> shuffled = pts;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(3));
    Mesh m2, m3;
    reconstruct(shuffled, m2);
    assert(as_off(m) == as_off(m2));
    reconstruct(shuffled, m3, LOC::parameters::number_of_threads(2u));
    assert(as_off(m) == as_off(m3));

    // scaled by powers of two (exactly): the same mesh and the same persistence, far beyond the
    // range where the product of three squared lengths overflows or underflows a double
    for(const int k : {180, -200}) {
      std::vector<Point> scaled;
      for(const Point& p : pts) scaled.emplace_back(std::ldexp(p.x(), k), std::ldexp(p.y(), k), std::ldexp(p.z(), k));
      Mesh ms;
      const LOC::Closed_surface_report rs = reconstruct(scaled, ms);
      for(auto v : vertices(ms)) {
        const Point& q = ms.point(v);
        ms.point(v) = Point(std::ldexp(q.x(), -k), std::ldexp(q.y(), -k), std::ldexp(q.z(), -k));
      }
      std::cout << "sphere scaled by 2^" << k << ": persistence " << rs.interior_persistence << "\n";
      assert(as_off(ms) == as_off(m));
      assert(std::abs(rs.interior_persistence / r.interior_persistence - 1) < 1e-12);
    }

    // the facet function on a user's triangulation, with an explicit interior point
    DT dt(pts.begin(), pts.end());
    std::vector<DT::Facet> facets;
    const LOC::Closed_surface_report rf = CGAL::lex_optimal_closed_surface(
      dt, std::back_inserter(facets), LOC::parameters::interior_points(std::vector<Point>{Point(0.3, -0.2, 0.1)}));
    assert(!rf.automatic_interior && facets.size() == r.mesh_faces);
    for(const DT::Facet& f : facets) {
      const int i = f.second;
      const auto ov = LOC::internal::outward_facet_vertices(i);
      assert(!dt.is_infinite(f.first));
      assert(CGAL::orientation(f.first->vertex(ov[0])->point(), f.first->vertex(ov[1])->point(),
                               f.first->vertex(ov[2])->point(), f.first->vertex(i)->point()) == CGAL::NEGATIVE);
    }
  }

  // --- half-edges grouped by edge, against a map, on random soups (small and large buckets) --------
  for(int seed = 0; seed < 4; ++seed) {
    std::mt19937 gen(seed);
    const std::uint32_t nv = seed < 2 ? 6 : 300; // few vertices: large buckets and groups
    std::vector<std::uint32_t> corners(3 * (seed % 2 ? 2000 : 300));
    for(std::size_t t = 0; 3 * t < corners.size(); ++t) { // triangles of distinct vertices
      do {
        for(int k = 0; k < 3; ++k) corners[3 * t + k] = std::uint32_t(gen() % nv);
      } while(corners[3 * t] == corners[3 * t + 1] || corners[3 * t] == corners[3 * t + 2] ||
              corners[3 * t + 1] == corners[3 * t + 2]);
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> expected;
    for(std::uint32_t h = 0; h < corners.size(); ++h) {
      const std::uint32_t a = corners[h], b = corners[3 * (h / 3) + (h % 3 + 1) % 3];
      expected[std::make_pair((std::min)(a, b), (std::max)(a, b))].push_back(h);
    }
    std::vector<std::vector<std::uint32_t>> got;
    std::uint32_t previous = 0; // groups come in increasing order of their smaller vertex
    LOC::internal::for_each_edge_group(nv, std::uint32_t(corners.size()), [&](std::uint32_t c) { return corners[c]; },
                                       [&](const std::uint32_t* first, const std::uint32_t* last) {
                                         const std::uint32_t a = corners[*first], b = corners[3 * (*first / 3) + (*first % 3 + 1) % 3];
                                         assert((std::min)(a, b) >= previous);
                                         previous = (std::min)(a, b);
                                         got.emplace_back(first, last);
                                       });
    std::vector<std::vector<std::uint32_t>> want;
    for(const auto& e : expected) want.push_back(e.second);
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    assert(got == want); // the same groups, each in increasing order
  }

  // --- the surface of any union of cells: random unions around a hub vertex ----------------------
  // Random sets of cells around one vertex, the first of the triangulation: its edges form
  // one large bucket of the twin search, and the unions have many non-manifold edges and
  // vertices. Oracles: CGAL's validity of the halfedge structure (one cycle of halfedges around
  // every vertex), the facets as triples of points, and the split edges counted by brute force.
  for(int seed = 0; seed < 3; ++seed) {
    CGAL::Random rng(seed);
    DT dt;
    dt.insert(Point(0, 0, 0)); // inserted one by one: the hub is the first finite vertex
    for(int i = 0; i < 400; ++i) { // around it, nearly on a sphere: the hub sees most points
      const double x = rng.get_double(-1, 1), y = rng.get_double(-1, 1), z = rng.get_double(-1, 1);
      const double r = std::sqrt(x * x + y * y + z * z) / rng.get_double(0.9, 1.0);
      if(r > 0.1) dt.insert(Point(x / r, y / r, z / r));
    }
    const LOC::internal::Handle_index_map<DT::Cell> cells(dt.tds().cells().begin(), dt.tds().cells().end());
    const LOC::internal::Handle_index_map<DT::Vertex> vertex_positions(dt.tds().vertices().begin(), dt.tds().vertices().end());
    const DT::Vertex_handle hub = dt.nearest_vertex(Point(0, 0, 0));
    std::vector<bool> inside(cells.size(), false);
    for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      inside[cells.index(&*c)] = (c->has_vertex(hub) ? rng.get_double() < 0.5 : rng.get_double() < 0.05);
    std::vector<std::uint32_t> facets; // keys: 4 * cell position + index
    std::map<std::pair<Point, Point>, int> edge_facets;
    std::multiset<std::array<Point, 3>> expected;
    std::size_t at_hub = 0;
    for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      for(int i = 0; i < 4; ++i)
        if(inside[cells.index(&*c)] && !inside[cells.index(&*c->neighbor(i))]) {
          facets.push_back(LOC::internal::Closed_surface_mesh_3<DT>::facet_key(cells.index(&*c), i));
          std::array<Point, 3> t;
          for(int k = 0; k < 3; ++k) t[k] = c->vertex((i + 1 + k) & 3)->point();
          std::sort(t.begin(), t.end());
          expected.insert(t);
          for(int a = 0; a < 3; ++a)
            for(int b = a + 1; b < 3; ++b) ++edge_facets[std::make_pair(t[a], t[b])];
          at_hub += c->vertex((i + 1) & 3) == hub || c->vertex((i + 2) & 3) == hub || c->vertex((i + 3) & 3) == hub;
        }
    std::size_t split_edges = 0;
    for(const auto& e : edge_facets) split_edges += e.second > 2;
    const std::size_t number_of_facets = facets.size();
    // the same facets, about half of them named from their outside cell (as the cut names a
    // facet by the cell that owns its record): the same mesh, index for index
    std::vector<std::uint32_t> mixed = facets;
    std::size_t named_from_outside = 0;
    for(std::uint32_t& key : mixed)
      if(rng.get_double() < 0.5) {
        const DT::Cell_handle c = dt.tds().cells().iterator_to(*const_cast<DT::Cell*>(cells.element(key >> 2)));
        const DT::Cell_handle n = c->neighbor(int(key & 3));
        key = LOC::internal::Closed_surface_mesh_3<DT>::facet_key(cells.index(&*n), n->index(c));
        ++named_from_outside;
      }
    LOC::internal::Closed_surface_mesh_3<DT> surface(std::move(facets), cells, vertex_positions, inside);
    surface.complete();
    Mesh union_mesh;
    surface.build(union_mesh, union_mesh.points());
    {
      LOC::internal::Closed_surface_mesh_3<DT> again(std::move(mixed), cells, vertex_positions, inside);
      again.complete();
      Mesh mixed_mesh;
      again.build(mixed_mesh, mixed_mesh.points());
      assert(named_from_outside > 0 && num_vertices(mixed_mesh) == num_vertices(union_mesh) &&
             num_faces(mixed_mesh) == num_faces(union_mesh));
      for(auto v : vertices(union_mesh)) assert(mixed_mesh.point(v) == union_mesh.point(v));
      for(auto f : faces(union_mesh)) {
        auto h = halfedge(f, union_mesh), g = halfedge(f, mixed_mesh);
        for(int k = 0; k < 3; ++k, h = next(h, union_mesh), g = next(g, mixed_mesh))
          assert(target(h, union_mesh) == target(g, mixed_mesh));
      }
      assert(again.statistics().non_manifold_edges == surface.statistics().non_manifold_edges &&
             again.statistics().non_manifold_vertices == surface.statistics().non_manifold_vertices);
    }
    assert(CGAL::is_valid_polygon_mesh(union_mesh) && CGAL::is_closed(union_mesh) && CGAL::is_triangle_mesh(union_mesh));
    std::multiset<std::array<Point, 3>> got;
    for(auto f : faces(union_mesh)) {
      std::array<Point, 3> t;
      int k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, union_mesh), union_mesh)) t[k++] = union_mesh.point(target(h, union_mesh));
      std::sort(t.begin(), t.end());
      got.insert(t);
    }
    std::cout << "union of cells (seed " << seed << "): " << number_of_facets << " facets, " << at_hub << " at the hub, "
              << surface.statistics().non_manifold_edges << " split edges (brute force " << split_edges << "), "
              << surface.statistics().non_manifold_vertices << " split vertices\n";
    assert(got == expected);
    assert(surface.statistics().non_manifold_edges == split_edges && split_edges > 0);
    assert(surface.statistics().non_manifold_vertices > 0 && at_hub > 64);
    assert(surface.statistics().vertices == num_vertices(union_mesh));
    std::map<Point, int> copies; // mesh vertices per point: split vertices have several
    for(auto v : vertices(union_mesh)) ++copies[union_mesh.point(v)];
    std::size_t split_vertices = 0;
    for(const auto& c : copies) split_vertices += c.second > 1;
    assert(surface.statistics().non_manifold_vertices == split_vertices);
  }

  // --- torus: genus 1 ----------------------------------------------------------------------------
  {
    const std::vector<Point> pts = sample_torus(30000, 1.0, 0.35, 0.001);
    check_against_full_algorithm_8(pts, {}, {}, "torus", 12);
    {
      // two nested spheres, exterior points, a uniform cloud (no surface: the persistence is
      // small and the sources are anywhere), full grids (exact ties everywhere)
      std::vector<Point> nested = sample_sphere(6000, Point(0, 0, 0), 1.0, 0.002);
      const std::vector<Point> inner = sample_sphere(3000, Point(0.1, 0, 0), 0.5, 0.002);
      nested.insert(nested.end(), inner.begin(), inner.end());
      check_against_full_algorithm_8(nested, {}, {}, "nested spheres", 8);
      check_against_full_algorithm_8(nested, {Point(0.1, 0.01, 0.02)}, {Point(0.8, 0.01, 0.02), Point(5, 5, 5)},
                                     "nested spheres with constraints");
      std::vector<Point> cloud;
      for(int i = 0; i < 4000; ++i) cloud.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
      check_against_full_algorithm_8(cloud, {}, {}, "uniform cloud", 8);
      for(int g : {2, 3, 6}) {
        std::vector<Point> grid;
        for(int i = 0; i <= g; ++i)
          for(int j = 0; j <= g; ++j)
            for(int k = 0; k <= g; ++k) grid.emplace_back(i, j, k);
        check_against_full_algorithm_8(grid, {}, {}, "full grid", 6);
        check_against_full_algorithm_8(grid, {Point(0.5 + 0.01, 0.5 + 0.02, 0.5 + 0.03)}, {}, "full grid with interior");
      }
    }
    const LOC::Closed_surface_report r = reconstruct(pts, m);
    check_mesh(m, r, pts);
    std::cout << "torus: " << r.mesh_faces << " faces, " << r.components << " component(s), genus " << r.genus << "\n";
    assert(r.components == 1 && r.genus == 1 && euler_genus(m) == 1);
  }

  // --- the surface of a cube sampled on an integer grid: massive exact ties of the order and
  //     co-spherical Delaunay configurations; the output must still be closed, valid and
  //     independent of the input order
  {
    std::vector<Point> pts;
    const int g = 24;
    for(int i = 0; i <= g; ++i)
      for(int j = 0; j <= g; ++j)
        for(int k = 0; k <= g; ++k)
          if(i == 0 || j == 0 || k == 0 || i == g || j == g || k == g) pts.emplace_back(i, j, k);
    const LOC::Closed_surface_report r = reconstruct(pts, m, LOC::parameters::interior_points(std::vector<Point>{Point(g / 2.0 + 0.1, g / 2.0 + 0.2, g / 2.0 + 0.3)}));
    check_mesh(m, r, pts);
    std::cout << "grid cube: " << r.mesh_faces << " faces, genus " << r.genus << ", " << r.components << " component(s), "
              << r.number_of_exactly_ordered_triangles << " triangles ordered exactly\n";
    assert(r.components == 1 && r.genus == 0 && r.number_of_exactly_ordered_triangles > 0);
    std::vector<Point> shuffled = pts;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(11));
    Mesh m2;
    reconstruct(shuffled, m2, LOC::parameters::interior_points(std::vector<Point>{Point(g / 2.0 + 0.1, g / 2.0 + 0.2, g / 2.0 + 0.3)}));
    assert(as_off(m) == as_off(m2));
  }

  // --- two spheres: one interior point per sphere gives two components; one gives one ------------
  {
    std::vector<Point> pts = sample_sphere(6000, Point(0, 0, 0), 1.0, 0.001);
    const std::vector<Point> b = sample_sphere(6000, Point(3, 0, 0), 1.0, 0.001);
    pts.insert(pts.end(), b.begin(), b.end());
    LOC::Closed_surface_report r = reconstruct(pts, m, LOC::parameters::interior_points(std::vector<Point>{Point(0, 0, 0), Point(3, 0, 0)}));
    check_mesh(m, r, pts);
    assert(r.components == 2 && r.genus == 0);
    r = reconstruct(pts, m, LOC::parameters::interior_points(std::vector<Point>{Point(3, 0, 0)}));
    check_mesh(m, r, pts);
    assert(r.components == 1);
    for(auto v : vertices(m)) assert(m.point(v).x() > 1.5);
    // an exterior point inside the first sphere, interior in the second: the same
    Mesh m2;
    reconstruct(pts, m2, LOC::parameters::interior_points(std::vector<Point>{Point(3, 0, 0)},
                         LOC::parameters::exterior_points(std::vector<Point>{Point(0, 0, 0)})));
    assert(as_off(m) == as_off(m2));
  }

  // --- a genus-2 mesh from CGAL's data, sampled by PMP ----------------------------------------------
  if(!data.empty()) {
    Mesh source;
    const bool ok = CGAL::IO::read_polygon_mesh(data + "/meshes/double-torus-example.off", source);
    assert(ok && CGAL::is_closed(source));
    PMP::triangulate_faces(source); // the file has quadrangles
    std::vector<Point> pts;
    PMP::sample_triangle_mesh(source, std::back_inserter(pts),
                              CGAL::parameters::number_of_points_on_faces(40000).do_sample_vertices(false).do_sample_edges(false).random_seed(1));
    const LOC::Closed_surface_report r = reconstruct(pts, m);
    check_mesh(m, r, pts);
    const double d = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(m, source, CGAL::parameters::number_of_points_per_area_unit(200));
    CGAL::Bbox_3 box = PMP::bbox(source);
    const double diag = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) + CGAL::square(box.zmax() - box.zmin()));
    std::cout << "double torus: genus " << r.genus << " (source " << euler_genus(source) << "), "
              << r.components << " component(s), Hausdorff " << d / diag << " x diagonal\n";
    assert(r.components == 1 && r.genus == euler_genus(source) && r.genus == 2);
    assert(d < 0.01 * diag);

    // kitten.xyz, a real scan: one closed component
    std::vector<Point> kitten;
    const bool read = CGAL::IO::read_points(data + "/points_3/kitten.xyz", std::back_inserter(kitten));
    assert(read && kitten.size() > 1000);
    const LOC::Closed_surface_report rk = reconstruct(kitten, m);
    check_mesh(m, rk, kitten);
    std::cout << "kitten: " << rk.mesh_faces << " faces, " << rk.components << " component(s), genus " << rk.genus << "\n";
    assert(rk.components == 1);

    // sphere_20k.xyz has non-manifold places: kept as they are, the number of split edges
    // equals the number of Delaunay edges in more than two facets of the optimal cycle,
    // counted by brute force (their resolution: test_manifold_resolution.cpp)
    std::vector<Point> sphere;
    const bool read_sphere = CGAL::IO::read_points(data + "/points_3/sphere_20k.xyz", std::back_inserter(sphere));
    assert(read_sphere);
    const LOC::Closed_surface_report rs = reconstruct(sphere, m, LOC::parameters::keep_non_manifold(true));
    check_mesh(m, rs, sphere);
    DT dt(sphere.begin(), sphere.end());
    std::vector<DT::Facet> facets;
    CGAL::lex_optimal_closed_surface(dt, std::back_inserter(facets), LOC::parameters::keep_non_manifold(true));
    std::map<std::pair<Point, Point>, int> edge_facets;
    for(const DT::Facet& f : facets)
      for(int a = 1; a < 4; ++a)
        for(int b = a + 1; b < 4; ++b) {
          Point p = f.first->vertex((f.second + a) & 3)->point(), q = f.first->vertex((f.second + b) & 3)->point();
          if(q < p) std::swap(p, q);
          ++edge_facets[std::make_pair(p, q)];
        }
    std::size_t split_edges = 0;
    for(const auto& e : edge_facets) split_edges += e.second > 2;
    std::cout << "sphere_20k: " << rs.non_manifold_edges << " split edges (brute force " << split_edges << "), "
              << rs.non_manifold_vertices << " split vertices\n";
    assert(rs.non_manifold_edges == split_edges && split_edges > 0);
    assert(facets.size() == rs.mesh_faces);
  } else {
    std::cout << "no data directory given: the genus-2 and kitten checks are skipped\n";
  }

  // --- bad input: typed errors, the mesh is left as it was --------------------------------------------
  {
    Mesh kept;
    const std::vector<Point> tet{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
    auto run = [&](const std::vector<Point>& pts, auto np) {
      const std::size_t before = num_faces(kept);
      try { CGAL::lex_optimal_closed_surface_reconstruction(pts, kept, np); }
      catch(...) { assert(num_faces(kept) == before); throw; }
    };
    const auto none = CGAL::parameters::default_values();
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    expect_error(LOC::Input_error_code::EMPTY_INPUT, [&] { run({}, none); });
    expect_error(LOC::Input_error_code::TOO_FEW_POINTS, [&] { run({tet[0], tet[1], tet[2]}, none); });
    expect_error(LOC::Input_error_code::TOO_FEW_POINTS, [&] { run(std::vector<Point>(50, Point(1, 2, 3)), none); });
    std::vector<Point> plane;
    for(int i = 0; i < 100; ++i) plane.emplace_back(rng.get_double(), rng.get_double(), 0);
    expect_error(LOC::Input_error_code::DEGENERATE_POINT_SET, [&] { run(plane, none); });
    expect_error(LOC::Input_error_code::NON_FINITE_COORDINATE, [&] { run({tet[0], tet[1], Point(nan, 0, 0), tet[3]}, none); });
    expect_error(LOC::Input_error_code::NON_FINITE_COORDINATE, [&] { run({tet[0], tet[1], Point(0, inf, 0), tet[3]}, none); });
    const std::vector<Point> sphere = sample_sphere(3000, Point(0, 0, 0), 1, 0.001);
    expect_error(LOC::Input_error_code::CONSTRAINT_OUTSIDE_HULL,
                 [&] { run(sphere, LOC::parameters::interior_points(std::vector<Point>{Point(5, 0, 0)})); });
    expect_error(LOC::Input_error_code::NON_FINITE_COORDINATE,
                 [&] { run(sphere, LOC::parameters::interior_points(std::vector<Point>{Point(0, 0, nan)})); });
    expect_error(LOC::Input_error_code::CONFLICTING_CONSTRAINTS,
                 [&] { run(sphere, LOC::parameters::interior_points(std::vector<Point>{Point(0, 0, 0)},
                                   LOC::parameters::exterior_points(std::vector<Point>{Point(0, 0, 0)}))); });
    expect_cancelled(
      [&] { run(sphere, LOC::parameters::callback(std::function<bool(double)>([](double x) { return x < 0.5; }))); });
    // at the very end (progress 1) too, before the mesh is touched
    expect_cancelled(
      [&] { run(sphere, LOC::parameters::callback(std::function<bool(double)>([](double x) { return x < 1; }))); });
    {
      const DT dt(sphere.begin(), sphere.end());
      std::vector<DT::Facet> written;
      expect_cancelled([&] {
        CGAL::lex_optimal_closed_surface(dt, std::back_inserter(written),
          LOC::parameters::callback(std::function<bool(double)>([](double x) { return x < 1; })));
      });
      assert(written.empty()); // cancelled before anything was written
    }
    // an open surface (a spherical cap) has no persistent interior
    std::vector<Point> cap;
    for(const Point& p : sample_sphere(8000, Point(0, 0, 0), 1, 0.0005)) if(p.z() > 0.3) cap.push_back(p);
    expect_error(LOC::Input_error_code::NO_INTERIOR_FOUND, [&] { run(cap, none); });
    assert(num_faces(kept) == 0);
  }
  std::cout << "all closed surface checks passed\n";
  return 0;
}
