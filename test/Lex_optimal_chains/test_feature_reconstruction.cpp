// Tests of lex_optimal_feature_reconstruction() (thesis section 4.8.3): on a sampled cube whose
// 12 edges are the features (given, then estimated by the VCM), the subcomplex around the
// edges has beta = 12 - 8 + 1 = 5 independent cycles, and the critical basis is made of 5
// elements, each a face of the cube: one face is missing (the thesis's Fig. 4.30); dropping
// the largest element leaves 4 faces; bad input gives its reason and leaves the mesh as it is.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_feature_reconstruction.h>
#include <CGAL/Lex_optimal_chains/triangulation_complex.h>
#include <CGAL/boost/graph/generators.h>

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
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_offset(-1.));
  });
  expect_error(Code::INVALID_PARAMETER, [&] {
    CGAL::lex_optimal_feature_reconstruction(points, mesh, LOC::parameters::feature_threshold(std::numeric_limits<double>::quiet_NaN()));
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

int main()
{
  test_bad_input();
  test_dense_agreement();
  test_cube();
  std::cout << "done" << std::endl;
  return 0;
}
