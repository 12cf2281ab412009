// Tests of lex_optimal_feature_reconstruction() (thesis section 4.8.3): on a sampled cube whose
// 12 edges are the features (given, then estimated by the VCM), the subcomplex around the
// edges has beta = 12 - 8 + 1 = 5 independent cycles, and the critical basis is made of 5
// elements, each a face of the cube: one face is missing (the thesis's Fig. 4.30); dropping
// the largest element leaves 4 faces; on a synthetic street with the shadows of a scanner, the
// borders of the scan in the feature set make each shadow an element among the largest, and
// dropping them opens the shadows; bad input gives its reason and leaves the mesh as it is.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_feature_reconstruction.h>
#include <CGAL/lex_optimal_homologous_chain.h>
#include <CGAL/Lex_optimal_chains/triangulation_complex.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>

#include "test_support.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;

// The 6 faces of the unit cube sampled on jittered grids of n x n, and the points of its edges.
std::vector<Point> sampled_cube(CGAL::Random& rng, int n, std::vector<Point>& edge_points)
{
  std::vector<Point> points;
  const double h = 1.0 / n;
  for(int axis = 0; axis < 3; ++axis)
    for(double side : {0.0, 1.0})
      for(int i = 0; i <= n; ++i)
        for(int j = 0; j <= n; ++j) {
          double u = i * h, v = j * h;
          const bool on_edge = i == 0 || j == 0 || i == n || j == n;
          if(!on_edge) { u += rng.get_double(-0.2, 0.2) * h; v += rng.get_double(-0.2, 0.2) * h; }
          double c[3];
          c[axis] = side;
          c[(axis + 1) % 3] = u;
          c[(axis + 2) % 3] = v;
          const Point p(c[0], c[1], c[2]);
          points.push_back(p);
          if(on_edge) edge_points.push_back(p);
        }
  return points;
}

// the face of the cube (0 to 5) whose plane holds the triangle, or -1
int cube_face(const Mesh& mesh, Mesh::Face_index f)
{
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side) {
      bool all = true;
      for(auto v : mesh.vertices_around_face(mesh.halfedge(f))) {
        const Point& p = mesh.point(v);
        all = all && p[axis] == double(side);
      }
      if(all) return 2 * axis + side;
    }
  return -1;
}

// The elements of the mesh: which cube face holds most of each, and its share of it.
std::map<std::size_t, std::pair<int, double>> elements_by_face(const Mesh& mesh, const Mesh::Property_map<Mesh::Face_index, std::size_t>& element)
{
  std::map<std::size_t, std::map<int, std::size_t>> counts;
  for(auto f : mesh.faces()) ++counts[element[f]][cube_face(mesh, f)];
  std::map<std::size_t, std::pair<int, double>> result;
  for(const auto& [e, by_face] : counts) {
    std::size_t total = 0, best = 0;
    int face = -1;
    for(const auto& [cf, c] : by_face) {
      total += c;
      if(c > best) { best = c; face = cf; }
    }
    result[e] = {face, double(best) / double(total)};
  }
  return result;
}

// The mesh is a valid, vertex-manifold polygon mesh (CGAL's checks: no vertex of CGAL's
// PMP::duplicate_non_manifold_vertices() left to split), and the report counts the points that
// have several vertices (where elements meet in several umbrellas); an edge of three faces or
// more becomes at least two mesh edges (a mesh edge has at most two faces), so each of the
// report's non-manifold edges has a repeated point pair.
void check_manifold_report(const Mesh& mesh, const LOC::Feature_reconstruction_report& r)
{
  assert(CGAL::is_valid_polygon_mesh(mesh));
  Mesh copy = mesh;
  assert(CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(copy) == 0);
  std::map<Point, int> vertices_at;
  for(auto v : mesh.vertices()) ++vertices_at[mesh.point(v)];
  std::size_t split = 0;
  for(const auto& [p, n] : vertices_at) split += n > 1;
  std::map<std::pair<Point, Point>, int> edges_at;
  for(auto e : mesh.edges()) {
    Point a = mesh.point(mesh.source(mesh.halfedge(e))), b = mesh.point(mesh.target(mesh.halfedge(e)));
    if(b < a) std::swap(a, b);
    ++edges_at[{a, b}];
  }
  std::size_t repeated = 0;
  for(const auto& [ab, n] : edges_at) repeated += n > 1;
  std::cout << "  " << split << " split points, " << r.non_manifold_edges << " non-manifold edges (" << repeated
            << " repeated point pairs)" << std::endl;
  assert(r.non_manifold_vertices == split);
  assert(r.non_manifold_edges <= repeated); // an edge of three faces or more: at least two mesh edges
}

void check_cube(const char* what, const Mesh& mesh, const Mesh::Property_map<Mesh::Face_index, std::size_t>& element,
                const LOC::Feature_reconstruction_report& r, std::size_t expected_elements)
{
  const auto by_face = elements_by_face(mesh, element);
  std::set<int> faces;
  std::cout << "  " << what << ": " << r.number_of_feature_points << " feature points, B of " << r.subcomplex_vertices
            << " vertices, " << r.subcomplex_edges << " edges, " << r.subcomplex_triangles << " triangles, beta "
            << r.number_of_cycles << ", " << r.mesh_faces << " faces; elements:";
  for(const auto& [e, fs] : by_face) {
    std::cout << " " << e << " (face " << fs.first << ", " << r.element_sizes[e] << " triangles, " << fs.second << " on it)";
    assert(fs.first >= 0 && fs.second > 0.9);
    faces.insert(fs.first);
  }
  std::cout << std::endl;
  assert(r.number_of_cycles == 5);
  assert(by_face.size() == expected_elements && faces.size() == expected_elements);
  assert(mesh.is_valid());
  check_manifold_report(mesh, r);
}

void test_cube()
{
  std::cout << "sampled cube, its edges as features" << std::endl;
  CGAL::Random rng(4);
  std::vector<Point> edges;
  const std::vector<Point> points = sampled_cube(rng, 24, edges);
  Mesh mesh;
  auto element = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(-1)).first;
  LOC::Feature_reconstruction_report r = CGAL::lex_optimal_feature_reconstruction(
    points, mesh, LOC::parameters::feature_points(edges, LOC::parameters::face_element_map(element)));
  check_cube("given edges", mesh, element, r, 5);
  { // the feature points moved off the vertices by far less than the spacing: the same vertices
    // (the nearest ones), the same elements
    std::vector<Point> moved;
    for(const Point& p : edges) moved.emplace_back(p.x() + rng.get_double(-1e-4, 1e-4), p.y() + rng.get_double(-1e-4, 1e-4), p.z());
    Mesh moved_mesh;
    const auto moved_r = CGAL::lex_optimal_feature_reconstruction(points, moved_mesh, LOC::parameters::feature_points(moved));
    assert(moved_r.number_of_feature_points == r.number_of_feature_points && moved_r.element_sizes == r.element_sizes);
  }
  // the largest element dropped: 4 faces
  r = CGAL::lex_optimal_feature_reconstruction(
    points, mesh, LOC::parameters::feature_points(edges, LOC::parameters::face_element_map(element, LOC::parameters::drop_largest_elements(1))));
  check_cube("largest dropped", mesh, element, r, 4);
  // relative to B: the same 5 faces, without the triangles of B
  Mesh relative_mesh;
  auto relative_element = relative_mesh.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(-1)).first;
  r = CGAL::lex_optimal_feature_reconstruction(
    points, relative_mesh, LOC::parameters::feature_points(edges, LOC::parameters::face_element_map(relative_element, LOC::parameters::relative_to_features(true))));
  check_cube("relative", relative_mesh, relative_element, r, 5);
  // the features estimated by the VCM
  Mesh vcm_mesh;
  auto vcm_element = vcm_mesh.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(-1)).first;
  r = CGAL::lex_optimal_feature_reconstruction(points, vcm_mesh, LOC::parameters::face_element_map(vcm_element));
  check_cube("VCM", vcm_mesh, vcm_element, r, 5);
}

// On a small cube, relative to B: the elements are those of the dense critical basis of
// Z^min_2(K, B) (critical_basis() on the complex of the triangulation, the same order), each
// with the same triangles.
void test_dense_agreement()
{
  std::cout << "small cube: the dense critical basis of (K, B)" << std::endl;
  using DT = CGAL::Delaunay_triangulation_3<Kernel>;
  CGAL::Random rng(11);
  std::vector<Point> edges;
  std::vector<Point> points = sampled_cube(rng, 5, edges);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  Mesh mesh;
  auto element = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(-1)).first;
  const LOC::Feature_reconstruction_report r = CGAL::lex_optimal_feature_reconstruction(
    points, mesh, LOC::parameters::feature_points(edges, LOC::parameters::face_element_map(element, LOC::parameters::relative_to_features(true))));
  // the dense side: the complex of the triangulation, B on its vertices, the same subcomplex
  const DT dt(points.begin(), points.end());
  std::vector<DT::Vertex_handle> features;
  for(const Point& p : edges) features.push_back(dt.nearest_vertex(p));
  std::sort(features.begin(), features.end());
  features.erase(std::unique(features.begin(), features.end()), features.end());
  const LOC::internal::Feature_subcomplex_3<DT> b(dt, features, r.offset);
  { // B's edges in the package's order on edges: that of the exact order with zero weights
    const std::vector<double> zero(b.points.size(), 0.);
    const auto expected = LOC::sort_simplices(b.complex, 1, LOC::Weighted_simplex_order<Point>(b.points, zero));
    std::size_t ties = 0; // edges of the same length, ordered by their points
    for(std::size_t i = 1; i < expected.size(); ++i) {
      const auto& x = b.complex.simplex(1, expected[i - 1]);
      const auto& y = b.complex.simplex(1, expected[i]);
      ties += CGAL::squared_distance(b.points[x[0]], b.points[x[1]]) == CGAL::squared_distance(b.points[y[0]], b.points[y[1]]);
    }
    std::cout << "  " << expected.size() << " edges of B (" << ties << " ties) in the package's order" << std::endl;
    assert(b.sorted_edges() == expected && ties > 0);
  }
  const auto k = LOC::triangulation_complex_3(dt);
  std::map<DT::Vertex_handle, std::uint32_t> index;
  std::vector<Point> k_points;
  for(std::uint32_t i = 0; i < k.vertices.size(); ++i) { index[k.vertices[i]] = i; k_points.push_back(k.vertices[i]->point()); }
  LOC::Simplicial_complex b_complex(std::uint32_t(k.vertices.size()));
  for(std::uint32_t e = 0; e < b.complex.number_of_simplices(1); ++e) {
    const auto& s = b.complex.simplex(1, e);
    b_complex.add_simplex({std::min(index[b.vertices[s[0]]], index[b.vertices[s[1]]]), std::max(index[b.vertices[s[0]]], index[b.vertices[s[1]]])});
  }
  for(std::uint32_t t = 0; t < b.complex.number_of_simplices(2); ++t) {
    const auto& s = b.complex.simplex(2, t);
    std::array<std::uint32_t, 3> v{index[b.vertices[s[0]]], index[b.vertices[s[1]]], index[b.vertices[s[2]]]};
    std::sort(v.begin(), v.end());
    b_complex.add_simplex({v[0], v[1], v[2]});
  }
  const LOC::Triangle_order<Point> order(k_points);
  const std::vector<std::uint32_t> sorted = LOC::sort_simplices(k.complex, 2, order);
  const auto dense = LOC::critical_basis<LOC::Z2_field>(k.complex, 2, sorted, &b_complex);
  assert(dense.size() == r.number_of_cycles);
  // the triangles of each element, as points
  using Triangle = std::array<Point, 3>;
  std::vector<std::set<Triangle>> dense_elements;
  for(const auto& c : dense) {
    std::set<Triangle> triangles;
    for(const auto& e : c) {
      const auto& s = k.complex.simplex(2, e.first);
      Triangle t{k_points[s[0]], k_points[s[1]], k_points[s[2]]};
      std::sort(t.begin(), t.end());
      triangles.insert(t);
    }
    dense_elements.push_back(triangles);
  }
  for(std::size_t e = 0; e < dense.size(); ++e) assert(r.element_sizes[e] == dense_elements[e].size());
  // every face of the mesh is in its element, and in no element before it
  for(auto f : mesh.faces()) {
    Triangle t;
    int j = 0;
    for(auto v : mesh.vertices_around_face(mesh.halfedge(f))) t[std::size_t(j++)] = mesh.point(v);
    std::sort(t.begin(), t.end());
    const std::size_t e = element[f];
    assert(dense_elements[e].count(t) == 1);
    for(std::size_t before = 0; before < e; ++before) assert(dense_elements[before].count(t) == 0);
  }
  { // the function on the user's triangulation, made from the points in another order, gives
    // the same elements and mesh
    std::vector<Point> shuffled = points;
    CGAL::cpp98::random_shuffle(shuffled.begin(), shuffled.end(), rng);
    const DT user_dt(shuffled.begin(), shuffled.end());
    Mesh from_dt;
    auto from_dt_element = from_dt.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(-1)).first;
    const LOC::Feature_reconstruction_report r_dt = CGAL::lex_optimal_feature_reconstruction(
      user_dt, from_dt, LOC::parameters::feature_points(edges, LOC::parameters::face_element_map(from_dt_element, LOC::parameters::relative_to_features(true))));
    assert(r_dt.element_sizes == r.element_sizes && r_dt.number_of_input_points == r.number_of_input_points);
    std::multiset<std::pair<std::array<Point, 3>, std::size_t>> a, b_faces;
    for(auto f : mesh.faces()) {
      std::array<Point, 3> t; int j = 0;
      for(auto v : mesh.vertices_around_face(mesh.halfedge(f))) t[std::size_t(j++)] = mesh.point(v);
      std::sort(t.begin(), t.end());
      a.emplace(t, element[f]);
    }
    for(auto f : from_dt.faces()) {
      std::array<Point, 3> t; int j = 0;
      for(auto v : from_dt.vertices_around_face(from_dt.halfedge(f))) t[std::size_t(j++)] = from_dt.point(v);
      std::sort(t.begin(), t.end());
      b_faces.emplace(t, from_dt_element[f]);
    }
    assert(a == b_faces);
  }
  std::cout << "  " << dense.size() << " elements of " << r.element_sizes[0] << ", ... triangles: the same as the dense ones ("
            << mesh.number_of_faces() << " faces)" << std::endl;
}

void test_bad_input()
{
  std::cout << "bad input" << std::endl;
  CGAL::Random rng(2);
  std::vector<Point> edges;
  const std::vector<Point> points = sampled_cube(rng, 8, edges);
  Mesh mesh;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), mesh);
  using Code = LOC::Input_error_code;
  expect_error(Code::EMPTY_INPUT, [&] { CGAL::lex_optimal_feature_reconstruction(std::vector<Point>(), mesh); });
  std::vector<Point> nan = points;
  nan[3] = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  expect_error(Code::NON_FINITE_COORDINATE, [&] { CGAL::lex_optimal_feature_reconstruction(nan, mesh); });
  expect_error(Code::TOO_FEW_POINTS, [&] {
    CGAL::lex_optimal_feature_reconstruction(std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 0, 0)}, mesh);
  });
  std::vector<Point> flat;
  for(int i = 0; i < 50; ++i) flat.emplace_back(rng.get_double(), rng.get_double(), 0.);
  expect_error(Code::DEGENERATE_POINT_SET, [&] { CGAL::lex_optimal_feature_reconstruction(flat, mesh); });
  const CGAL::Delaunay_triangulation_3<Kernel> flat_dt(flat.begin(), flat.end());
  expect_error(Code::DEGENERATE_POINT_SET, [&] { CGAL::lex_optimal_feature_reconstruction(flat_dt, mesh); });
  const CGAL::Delaunay_triangulation_3<Kernel> cube_dt(points.begin(), points.end());
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_feature_reconstruction(cube_dt, mesh, LOC::parameters::feature_threshold(0.));
  });
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_offset(-1.));
  });
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_threshold(std::numeric_limits<double>::quiet_NaN()));
  });
  std::vector<Point> nan_features = edges;
  nan_features[5] = Point(0, std::numeric_limits<double>::infinity(), 0);
  expect_error(Code::NON_FINITE_COORDINATE, [&] {
    CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_points(nan_features));
  });
  // one feature point: B has no cycle
  expect_error(Code::EMPTY_RESULT, [&] {
    CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_points(std::vector<Point>{points[0]}));
  });
  expect_error(Code::EMPTY_RESULT, [&] {
    CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_points(edges, LOC::parameters::drop_largest_elements(5)));
  });
  assert(mesh.number_of_faces() == 4); // unchanged
}

// A synthetic street: a ground 30 x 12 between two facades 8 high, three boxes (cars) standing
// on it, and behind each box a shadow of the scanner with no ground point; every surface
// sampled at about 0.25, the features estimated by the VCM (threshold 0.2, offset 0.2). The
// ground is one element, the largest; each facade is one element; each box has elements of
// its own. (The shadows are filled by the ground's element: dropping the largest element
// removes the ground, not only the shadows; the thesis's Fig. 4.31 opens them.)
void test_street()
{
  std::cout << "synthetic street, features by the VCM" << std::endl;
  struct Box { double x0, y0, x1, y1, h; };
  const std::vector<Box> boxes{{4, 3, 8, 4.8, 1.5}, {13, 6.5, 17, 8.3, 1.6}, {22, 3.5, 26, 5.3, 1.4}};
  auto in_box = [&](double x, double y) {
    for(const Box& b : boxes) if(x > b.x0 - 0.01 && x < b.x1 + 0.01 && y > b.y0 - 0.01 && y < b.y1 + 0.01) return true;
    return false;
  };
  auto in_shadow = [&](double x, double y) { // behind a box, seen from the middle of the street
    for(const Box& b : boxes)
      if(x > b.x0 && x < b.x1 && ((b.y0 < 6 && y > b.y1 && y < b.y1 + 2.5) || (b.y0 > 6 && y < b.y0 && y > b.y0 - 2.5))) return true;
    return false;
  };
  CGAL::Random rng(3);
  const double step = 0.25;
  auto jitter = [&] { return rng.get_double(-0.2, 0.2) * step; };
  std::vector<Point> points;
  for(double x = 0; x <= 30; x += step)
    for(double y = 0; y <= 12; y += step) {
      const double px = x + jitter(), py = std::min(12., std::max(0., y + jitter()));
      if(!in_box(px, py) && !in_shadow(px, py)) points.emplace_back(px, py, 0.);
    }
  for(double side : {0., 12.})
    for(double x = 0; x <= 30; x += step)
      for(double z = step; z <= 8; z += step) points.emplace_back(x + jitter(), side, z + (z > step ? jitter() : 0.));
  for(const Box& b : boxes) {
    for(double x = b.x0; x <= b.x1 + 1e-9; x += step)
      for(double y = b.y0; y <= b.y1 + 1e-9; y += step) points.emplace_back(x, y, b.h);
    for(double x = b.x0; x <= b.x1 + 1e-9; x += step)
      for(double z = 0; z < b.h - 1e-9; z += step) { points.emplace_back(x, b.y0, z); points.emplace_back(x, b.y1, z); }
    for(double y = b.y0 + step; y < b.y1 - 1e-9; y += step)
      for(double z = 0; z < b.h - 1e-9; z += step) { points.emplace_back(b.x0, y, z); points.emplace_back(b.x1, y, z); }
  }
  Mesh mesh;
  auto element = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(-1)).first;
  const LOC::Feature_reconstruction_report r = CGAL::lex_optimal_feature_reconstruction(
    points, mesh, LOC::parameters::face_element_map(element, LOC::parameters::feature_threshold(0.2, LOC::parameters::feature_offset(0.2))));
  // the class of each face: ground, facade 0 or 1, box i, or other
  std::map<std::size_t, std::map<std::string, std::size_t>> by_element;
  std::map<std::string, std::map<std::size_t, std::size_t>> by_class;
  for(auto f : mesh.faces()) {
    std::vector<Point> c;
    for(auto v : mesh.vertices_around_face(mesh.halfedge(f))) c.push_back(mesh.point(v));
    std::string cls = "other";
    const double cx = (c[0].x() + c[1].x() + c[2].x()) / 3, cy = (c[0].y() + c[1].y() + c[2].y()) / 3;
    if(c[0].z() == 0 && c[1].z() == 0 && c[2].z() == 0) cls = in_shadow(cx, cy) ? "shadow" : in_box(cx, cy) ? "other" : "ground";
    else if(c[0].y() == c[1].y() && c[1].y() == c[2].y() && (c[0].y() == 0 || c[0].y() == 12))
      cls = c[0].y() == 0 ? "facade 0" : "facade 1";
    else
      for(std::size_t i = 0; i < boxes.size(); ++i) {
        const Box& b = boxes[i];
        bool on = true;
        for(const Point& p : c)
          on = on && p.x() >= b.x0 - 1e-9 && p.x() <= b.x1 + 1e-9 && p.y() >= b.y0 - 1e-9 && p.y() <= b.y1 + 1e-9 && p.z() <= b.h + 1e-9;
        if(on) cls = "box " + std::to_string(i);
      }
    ++by_element[element[f]][cls];
    ++by_class[cls][element[f]];
  }
  auto main_element = [&](const std::string& cls) {
    std::size_t best = 0, total = 0, e = 0;
    for(const auto& [el, n] : by_class[cls]) { total += n; if(n > best) { best = n; e = el; } }
    std::cout << "  " << cls << ": " << total << " faces, " << best << " in element " << e << " of " << r.element_sizes.size() << std::endl;
    assert(double(best) >= 0.95 * double(total));
    return e;
  };
  std::cout << "  " << points.size() << " points, " << r.number_of_feature_points << " feature points, beta " << r.number_of_cycles
            << ", " << r.mesh_faces << " faces" << std::endl;
  check_manifold_report(mesh, r);
  const std::size_t ground = main_element("ground");
  assert(ground + 1 == r.element_sizes.size()); // the largest element
  assert(main_element("facade 0") != main_element("facade 1"));
  for(std::size_t i = 0; i < boxes.size(); ++i) {
    std::size_t own = 0; // elements whose faces are all on box i
    for(const auto& [e, classes] : by_element) own += classes.size() == 1 && classes.begin()->first == "box " + std::to_string(i);
    std::cout << "  box " << i << ": " << own << " elements of its own" << std::endl;
    assert(own > 0);
  }
  // With the borders of the scan in the feature set, each shadow's rim is a cycle of B and the
  // shadow's filling an element: the three largest, so that dropping them opens the shadows
  // (thesis Fig. 4.31) and leaves the ground.
  std::cout << "synthetic street, features by the VCM and the borders" << std::endl;
  auto shadow_faces = [&](const Mesh& m, const Mesh::Property_map<Mesh::Face_index, std::size_t>* el, std::map<std::size_t, std::size_t>* by) {
    std::size_t shadow = 0, ground = 0;
    for(auto f : m.faces()) {
      std::vector<Point> c;
      for(auto v : m.vertices_around_face(m.halfedge(f))) c.push_back(m.point(v));
      if(c[0].z() != 0 || c[1].z() != 0 || c[2].z() != 0) continue;
      const double cx = (c[0].x() + c[1].x() + c[2].x()) / 3, cy = (c[0].y() + c[1].y() + c[2].y()) / 3;
      if(in_shadow(cx, cy)) { ++shadow; if(by) ++(*by)[(*el)[f]]; }
      else if(!in_box(cx, cy)) ++ground;
    }
    return std::make_pair(shadow, ground);
  };
  Mesh with_borders;
  auto border_element = with_borders.add_property_map<Mesh::Face_index, std::size_t>("f:element", std::size_t(-1)).first;
  const auto borders_np = LOC::parameters::border_features(true, LOC::parameters::feature_threshold(0.2, LOC::parameters::feature_offset(0.2)));
  const LOC::Feature_reconstruction_report rb =
    CGAL::lex_optimal_feature_reconstruction(points, with_borders, LOC::parameters::face_element_map(border_element, borders_np));
  check_manifold_report(with_borders, rb);
  std::map<std::size_t, std::size_t> shadow_elements;
  const auto [shadows, ground_faces] = shadow_faces(with_borders, &border_element, &shadow_elements);
  std::cout << "  " << rb.number_of_border_points << " border points, beta " << rb.number_of_cycles << "; shadow faces by element:";
  for(const auto& [e, n] : shadow_elements) std::cout << " " << e << " (" << n << ")";
  std::cout << std::endl;
  const std::size_t m = rb.element_sizes.size();
  for(std::size_t e = m - 3; e < m; ++e) assert(shadow_elements[e] >= 30); // each shadow, in the three largest
  assert(shadows <= shadow_elements[m - 1] + shadow_elements[m - 2] + shadow_elements[m - 3] + 2);
  Mesh opened;
  CGAL::lex_optimal_feature_reconstruction(points, opened, LOC::parameters::drop_largest_elements(3, borders_np));
  const auto [open_shadows, open_ground] = shadow_faces(opened, nullptr, nullptr);
  std::cout << "  the 3 largest dropped: " << open_shadows << " of " << shadows << " shadow faces left, " << open_ground << " of "
            << ground_faces << " ground faces" << std::endl;
  assert(open_shadows <= 2 && double(open_ground) >= 0.98 * double(ground_faces)); // the rims go with the shadows
}

// The chains of many cycles made 64 at a time (bit i of each value for cycle i) are those that
// lex_optimal_chain_with_boundary() makes for each cycle alone, absolute and relative to a set
// of triangles; more than 64 cycles, so that there are two groups. Each cycle is the boundary of a
// few random triangles, over Z2, or the sum of two of them.
void test_batched_chains()
{
  std::cout << "chains of up to 75 cycles (70 random ones, 5 sums of two) in groups of 64 against one run per cycle" << std::endl;
  using DT = CGAL::Delaunay_triangulation_3<Kernel>;
  using Vertex_handle = DT::Vertex_handle;
  using Cycle = std::vector<std::pair<Vertex_handle, Vertex_handle>>;
  CGAL::Random rng(5);
  std::vector<Point> points;
  for(int i = 0; i < 1500; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  const DT dt(points.begin(), points.end());
  std::vector<DT::Facet> facets(dt.finite_facets_begin(), dt.finite_facets_end());
  using Key = std::array<Vertex_handle, 3>;
  auto key = [](const DT::Facet& f) {
    Key k{f.first->vertex((f.second + 1) & 3), f.first->vertex((f.second + 2) & 3), f.first->vertex((f.second + 3) & 3)};
    std::sort(k.begin(), k.end());
    return k;
  };
  std::vector<Cycle> cycles;
  for(int c = 0; c < 70; ++c) {
    std::map<std::pair<Vertex_handle, Vertex_handle>, int> edges; // the Z2 boundary
    for(int t = rng.get_int(1, 6); t > 0; --t) {
      const Key k = key(facets[std::size_t(rng.get_int(0, int(facets.size())))]);
      for(int j = 0; j < 3; ++j) edges[std::minmax(k[j], k[(j + 1) % 3])] ^= 1;
    }
    Cycle cycle;
    for(const auto& [e, odd] : edges) if(odd) cycle.push_back(e);
    if(!cycle.empty()) cycles.push_back(cycle);
  }
  // and sums of two of them in the same group: cycles that share edges, linearly dependent
  for(std::size_t c = 0; c + 1 < 10; c += 2) {
    std::map<std::pair<Vertex_handle, Vertex_handle>, int> edges;
    for(const auto* cycle : {&cycles[c], &cycles[c + 1]})
      for(const auto& e : *cycle) edges[std::minmax(e.first, e.second)] ^= 1;
    Cycle sum;
    for(const auto& [e, odd] : edges) if(odd) sum.push_back(e);
    cycles.insert(cycles.begin() + 20, sum);
  }
  assert(cycles.size() > 64);
  std::vector<DT::Facet> b;
  for(int i = 0; i < 200; ++i) b.push_back(facets[std::size_t(rng.get_int(0, int(facets.size())))]);
  for(bool relative : {false, true}) {
    const auto batched = relative ? LOC::internal::optimal_chains_with_boundaries(dt, cycles, LOC::parameters::relative_facets(b))
                                  : LOC::internal::optimal_chains_with_boundaries(dt, cycles, CGAL::parameters::default_values());
    assert(batched.size() == cycles.size());
    std::size_t triangles = 0;
    for(std::size_t c = 0; c < cycles.size(); ++c) {
      std::vector<std::pair<DT::Facet, std::int64_t>> alone;
      const auto z2 = LOC::Coefficient_field::Z2;
      if(relative)
        CGAL::lex_optimal_chain_with_boundary(dt, cycles[c], std::back_inserter(alone),
                                              LOC::parameters::coefficient_field(z2, LOC::parameters::relative_facets(b)));
      else CGAL::lex_optimal_chain_with_boundary(dt, cycles[c], std::back_inserter(alone), LOC::parameters::coefficient_field(z2));
      std::set<Key> expected, got;
      for(const auto& fk : alone) expected.insert(key(fk.first));
      for(const auto& f : batched[c]) assert(got.insert(key(f)).second); // each triangle once
      assert(!expected.empty() && got == expected);
      triangles += got.size();
    }
    std::cout << "  " << (relative ? "relative: " : "absolute: ") << triangles << " triangles, the same" << std::endl;
  }
}

// The border points of a sampled square are its outer ring, and an evenly sampled sphere has
// none.
void test_border_points()
{
  std::cout << "border points of a square and of a sphere" << std::endl;
  CGAL::Random rng(7);
  std::vector<Point> square, sphere;
  const double step = 0.25;
  for(int i = 0; i <= 40; ++i)
    for(int j = 0; j <= 40; ++j)
      square.emplace_back(i * step + rng.get_double(-0.05, 0.05), j * step + rng.get_double(-0.05, 0.05), rng.get_double(-0.01, 0.01));
  std::sort(square.begin(), square.end());
  const auto borders = LOC::internal::border_points(square, LOC::internal::border_neighbours, LOC::internal::border_gap);
  std::size_t ring = 0;
  for(const Point& p : square) {
    const double d = std::min({p.x(), p.y(), 10 - p.x(), 10 - p.y()}); // to the square's border
    const bool border = std::binary_search(borders.begin(), borders.end(), p);
    if(d < 0.1) { ++ring; assert(border); }  // the outer ring: all of it
    if(d > 2.5 * step) assert(!border);     // three rows in: none
  }
  std::cout << "  " << borders.size() << " border points, the " << ring << " of the outer ring among them" << std::endl;
  assert(ring == 160);
  for(int i = 0; i < 3000; ++i) { // a Fibonacci sphere: even sampling, no hole
    const double z = 1 - (2 * i + 1) / 3000., t = i * CGAL_PI * (3 - std::sqrt(5.)), r = std::sqrt(1 - z * z);
    sphere.emplace_back(r * std::cos(t), r * std::sin(t), z);
  }
  assert(LOC::internal::border_points(sphere, LOC::internal::border_neighbours, LOC::internal::border_gap).empty());
}

int main()
{
  test_border_points();
  test_batched_chains();
  test_bad_input();
  test_dense_agreement();
  test_cube();
  test_street();
  std::cout << "done" << std::endl;
  return 0;
}
