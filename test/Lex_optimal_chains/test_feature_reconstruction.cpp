// Tests of lex_optimal_feature_reconstruction() (thesis section 4.8.3): on a sampled cube whose
// 12 edges are the features (given, then estimated by the VCM), the subcomplex around the
// edges has beta = 12 - 8 + 1 = 5 independent cycles, and the critical basis is made of 5
// elements, each a face of the cube: one face is missing (the thesis's Fig. 4.30); dropping
// the largest element leaves 4 faces; bad input gives its reason and leaves the mesh as it is.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_feature_reconstruction.h>

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

int main()
{
  test_cube();
  std::cout << "done" << std::endl;
  return 0;
}
