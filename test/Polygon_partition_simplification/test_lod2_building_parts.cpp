// Two parts of the LOD2 building reconstruction, each against oracles written elsewhere:
// - internal::Metric_alpha_expansion, on many small random graphs, against brute force over all
//   labelings and all expansion moves: the result is a local minimum for every expansion move
//   and within the bound of Boykov, Veksler and Zabih (2 max V / min V times the optimum), for
//   metrics |h_a - h_b|, truncated |h_a - h_b|, Potts and the lift's plane metric; zero pairwise
//   weights give the unary minimum; forbidden (infinite) labels are left wherever an allowed one
//   exists; the same input gives the same labels; on Potts instances CGAL's
//   alpha_expansion_graphcut is held to the same bound. A larger grid is checked against every
//   single-vertex change.
// - IO::write_CityJSON, on two hand-made buildings (a gable roof and a box that touches it),
//   read back with nlohmann::json: the CityJSON structure, semantics matching the faces, every
//   surface equal to a face of the mesh with the same orientation, vertices unique and within
//   half a unit of the scale of the originals, each shell closed and outward (rebuilt as a
//   Surface_mesh, CGAL's is_closed, is_outward_oriented and the volume of its triangulation);
//   missing property maps, bad precision and non-finite coordinates throw Input_error and write
//   nothing; the output does not depend on the locale.
// - internal::facade_evidence, on hand-made facades: the outside is the side without the roof
//   (with an overhanging eave on it, or a lower roof), whatever the sign of the plane's normal;
//   the samples lie on the horizontal through each point's projection on the plane, at
//   multiples of the step outwards and inwards, at the point's height; a wall that carries no
//   roof gives none; across a courtyard narrower than the walls are high, the outside of each
//   wing's facade is the courtyard although the other wing's roof is within reach.
// - internal::extend_ridges_to_footprint, on an L-shaped footprint (see
//   test_ridges_reach_the_footprint()).
// - internal::replace_outlines_by_footprint, on a square footprint and hand-made segments: the
//   outline pieces along its edges, the lines of a wall plane and a roof plane along them and
//   the outline pieces cutting its corners are replaced by its edges; a ridge, an outline piece
//   inside it, a short one far from its boundary, one from an edge to the opposite one and a
//   step wall inside stay. On a stepped
//   footprint, the step wall on the line of two footprint edges keeps the part between them,
//   the parts along the edges are removed.
// - internal::close_outline_corners, on a square outline with a corner cut off and on pieces
//   where it must add nothing (see test_outline_corners_are_closed()).
// the package's headers first: they read Boost's graph headers with g++'s false positives
// silenced (internal/CGAL_compatibility.h), before CGAL 6's triangulate_faces.h reads them
#include <CGAL/Polygon_partition_simplification/Building_surface_type.h>
#include <CGAL/Polygon_partition_simplification/IO/CityJSON.h>
#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/close_outline_corners_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/facade_evidence_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/footprint_segments_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Metric_alpha_expansion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/alpha_expansion_graphcut.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <locale>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>


namespace PPS = CGAL::Polygon_partition_simplification;

// ---------------------------------------------------------------------------------------------
// Alpha-expansion

using Edge = std::pair<std::size_t, std::size_t>;
using Pairwise = std::function<double(std::size_t, std::size_t, std::size_t)>;
using Labels = std::vector<std::size_t>;
const double infinity = std::numeric_limits<double>::infinity();

struct Instance
{
  std::size_t number_of_vertices = 0, number_of_labels = 0;
  std::vector<Edge> edges;
  std::vector<double> weights;
  std::vector<std::vector<double>> unary;  // [vertex][label], +infinity: forbidden
  Pairwise pairwise;                        // (edge, label of first vertex, label of second)
  double ratio = 0;                         // BVZ's max V / min nonzero V (0: no bound)
};

// the energy, computed here independently of the class under test
double energy(const Instance& instance, const Labels& labels)
{
  double result = 0;
  for(std::size_t v = 0; v < labels.size(); ++v)
    result += instance.unary[v][labels[v]];
  for(std::size_t e = 0; e < instance.edges.size(); ++e)
    result += instance.pairwise(e, labels[instance.edges[e].first], labels[instance.edges[e].second]);
  return result;
}

double optimum(const Instance& instance)
{
  Labels labels(instance.number_of_vertices, 0);
  double best = infinity;
  for(;;) {
    best = (std::min)(best, energy(instance, labels));
    std::size_t v = 0;
    while(v < labels.size() && ++labels[v] == instance.number_of_labels)
      labels[v++] = 0;
    if(v == labels.size())
      return best;
  }
}

// the lowest energy of all expansion moves of `alpha` from `labels` (every subset of vertices)
double best_expansion(const Instance& instance, const Labels& labels, std::size_t alpha)
{
  double best = infinity;
  const std::size_t n = labels.size();
  for(std::size_t subset = 0; subset < (std::size_t(1) << n); ++subset) {
    Labels moved = labels;
    for(std::size_t v = 0; v < n; ++v)
      if(subset & (std::size_t(1) << v))
        moved[v] = alpha;
    best = (std::min)(best, energy(instance, moved));
  }
  return best;
}

bool is_expansion_local_minimum(const Instance& instance, const Labels& labels)
{
  const double current = energy(instance, labels);
  for(std::size_t alpha = 0; alpha < instance.number_of_labels; ++alpha)
    if(best_expansion(instance, labels, alpha) < current - 1e-7 * (1 + std::abs(current)))
      return false;
  return true;
}

enum class Metric_kind { HEIGHT, TRUNCATED_HEIGHT, POTTS, PLANES };

Instance random_instance(std::mt19937& random, Metric_kind kind, double forbidden_probability = 0)
{
  std::uniform_real_distribution<double> unit(0, 1);
  Instance instance;
  instance.number_of_vertices = 4 + random() % 4;
  instance.number_of_labels = 2 + random() % 3;
  const std::size_t n = instance.number_of_vertices, labels = instance.number_of_labels;
  instance.unary.assign(n, std::vector<double>(labels));
  for(std::size_t v = 0; v < n; ++v) {
    for(double& cost : instance.unary[v])
      cost = unit(random) < forbidden_probability ? infinity : 10 * unit(random);
    if(std::all_of(instance.unary[v].begin(), instance.unary[v].end(), [](double c) { return c == infinity; }))
      instance.unary[v][random() % labels] = 10 * unit(random);
  }
  for(std::size_t u = 0; u < n; ++u)
    for(std::size_t v = u + 1; v < n; ++v)
      if(unit(random) < 0.5) {
        instance.edges.emplace_back(u, v);
        instance.weights.push_back(3 * unit(random));
      }
  if(instance.edges.empty()) {
    instance.edges.emplace_back(0, 1);
    instance.weights.push_back(1);
  }
  const std::vector<double> w = instance.weights;
  if(kind == Metric_kind::POTTS) {
    instance.pairwise = [w](std::size_t e, std::size_t a, std::size_t b) { return a == b ? 0. : w[e]; };
    instance.ratio = 1;
    return instance;
  }
  if(kind == Metric_kind::PLANES) {
    // label l: the plane z = p0 + p1 x + p2 y; edge e: two endpoints; the lift's cost
    // w_e * 1/2 * sum over the endpoints of the difference of the heights of the two planes
    std::vector<std::array<double, 3>> planes(labels);
    for(auto& p : planes)
      p = {{10 * unit(random), unit(random) - 0.5, unit(random) - 0.5}};
    std::vector<std::array<double, 4>> ends(instance.edges.size());
    for(auto& x : ends)
      x = {{10 * unit(random), 10 * unit(random), 10 * unit(random), 10 * unit(random)}};
    instance.pairwise = [w, planes, ends](std::size_t e, std::size_t a, std::size_t b) {
      double sum = 0;
      for(int i = 0; i < 2; ++i) {
        const double x = ends[e][2 * i], y = ends[e][2 * i + 1];
        sum += std::abs((planes[a][0] + planes[a][1] * x + planes[a][2] * y) -
                        (planes[b][0] + planes[b][1] * x + planes[b][2] * y));
      }
      return w[e] * sum / 2;
    };
    // per-edge metrics: the bound takes the largest ratio over the edges
    double ratio = 1;
    for(std::size_t e = 0; e < instance.edges.size(); ++e) {
      double smallest = infinity, largest = 0;
      for(std::size_t a = 0; a < labels; ++a)
        for(std::size_t b = a + 1; b < labels; ++b) {
          const double cost = instance.pairwise(e, a, b);
          smallest = (std::min)(smallest, cost);
          largest = (std::max)(largest, cost);
        }
      ratio = (smallest > 1e-9 * largest) ? (std::max)(ratio, largest / smallest) : 0;
      if(ratio == 0)
        break;
    }
    instance.ratio = ratio;
    return instance;
  }
  // distinct heights, at least 0.1 apart
  std::vector<double> heights;
  while(heights.size() < labels) {
    const double h = 10 * unit(random);
    if(std::all_of(heights.begin(), heights.end(), [h](double g) { return std::abs(g - h) >= 0.1; }))
      heights.push_back(h);
  }
  const double truncation = kind == Metric_kind::TRUNCATED_HEIGHT ? 1 + 4 * unit(random) : infinity;
  auto metric = [heights, truncation](std::size_t a, std::size_t b) {
    return (std::min)(truncation, std::abs(heights[a] - heights[b]));
  };
  instance.pairwise = [w, metric](std::size_t e, std::size_t a, std::size_t b) { return w[e] * metric(a, b); };
  double smallest = infinity, largest = 0;
  for(std::size_t a = 0; a < labels; ++a)
    for(std::size_t b = a + 1; b < labels; ++b) {
      smallest = (std::min)(smallest, metric(a, b));
      largest = (std::max)(largest, metric(a, b));
    }
  instance.ratio = largest / smallest;
  return instance;
}

Labels random_labels(std::mt19937& random, const Instance& instance)
{
  Labels labels(instance.number_of_vertices);
  for(std::size_t& l : labels)
    l = random() % instance.number_of_labels;
  return labels;
}

using Expansion = PPS::internal::Metric_alpha_expansion<Pairwise>;

// runs the class under test from `start` and checks what holds on every instance; returns the
// labels
Labels run_and_check(const Instance& instance, const Labels& start)
{
  const Expansion expansion(instance.edges, instance.unary, instance.pairwise);
  Labels labels = start;
  const Expansion::Result result = expansion.minimize(labels);
  assert(labels.size() == instance.number_of_vertices);
  for(std::size_t l : labels)
    assert(l < instance.number_of_labels);
  assert(result.number_of_cycles >= 1);
  assert(std::abs(result.energy - expansion.energy(labels)) <= 1e-12 * (1 + std::abs(result.energy)));
  assert(result.energy <= expansion.energy(start));
  // deterministic
  Labels again = start;
  const Expansion::Result second = expansion.minimize(again);
  assert(again == labels && second.energy == result.energy && second.number_of_cycles == result.number_of_cycles);
  return labels;
}

void test_alpha_expansion_against_brute_force()
{
  std::mt19937 random(20260612);
  const Metric_kind kinds[] = {Metric_kind::HEIGHT, Metric_kind::TRUNCATED_HEIGHT, Metric_kind::POTTS, Metric_kind::PLANES};
  const char* names[] = {"height", "truncated height", "Potts", "planes"};
  for(int k = 0; k < 4; ++k) {
    std::size_t optimal = 0, instances = 0, bounded = 0;
    double worst_ratio = 1;
    for(int trial = 0; trial < 150; ++trial) {
      const Instance instance = random_instance(random, kinds[k]);
      const Labels start = (trial % 2) ? random_labels(random, instance)
                                       : Expansion(instance.edges, instance.unary, instance.pairwise).unary_minimum_labels();
      const Labels labels = run_and_check(instance, start);
      const double ours = energy(instance, labels), best = optimum(instance);
      assert(is_expansion_local_minimum(instance, labels));
      assert(ours >= best - 1e-9 * (1 + best));
      if(instance.ratio > 0) {
        assert(ours <= 2 * instance.ratio * best + 1e-9 * (1 + best));
        ++bounded;
      }
      ++instances;
      if(ours <= best + 1e-9 * (1 + best))
        ++optimal;
      else
        worst_ratio = (std::max)(worst_ratio, ours / best);
    }
    std::cout << "alpha-expansion, " << names[k] << ": " << optimal << " optimal of " << instances
              << " (" << bounded << " with the BVZ bound), worst energy / optimum " << worst_ratio << std::endl;
  }
}

// Potts instances: CGAL's alpha_expansion_graphcut from the same start, held to the same bound
void test_alpha_expansion_against_CGAL()
{
  std::mt19937 random(7);
  std::size_t theirs_local_minima = 0, ours_lower = 0, theirs_lower = 0, instances = 200;
  for(std::size_t trial = 0; trial < instances; ++trial) {
    const Instance instance = random_instance(random, Metric_kind::POTTS);
    const Labels start = random_labels(random, instance);
    const Labels ours = run_and_check(instance, start);
    std::vector<std::vector<double>> cost_matrix(instance.number_of_labels,
                                                 std::vector<double>(instance.number_of_vertices));
    for(std::size_t v = 0; v < instance.number_of_vertices; ++v)
      for(std::size_t l = 0; l < instance.number_of_labels; ++l)
        cost_matrix[l][v] = instance.unary[v][l];
    Labels theirs = start;
    CGAL::alpha_expansion_graphcut(instance.edges, instance.weights, cost_matrix, theirs);
    const double best = optimum(instance), ours_energy = energy(instance, ours), theirs_energy = energy(instance, theirs);
    assert(is_expansion_local_minimum(instance, ours));
    assert(ours_energy <= 2 * best + 1e-9 * (1 + best));
    assert(theirs_energy <= 2 * best + 1e-9 * (1 + best));
    if(is_expansion_local_minimum(instance, theirs))
      ++theirs_local_minima;
    if(ours_energy < theirs_energy - 1e-9 * (1 + best))
      ++ours_lower;
    if(theirs_energy < ours_energy - 1e-9 * (1 + best))
      ++theirs_lower;
  }
  std::cout << "Potts against CGAL::alpha_expansion_graphcut on " << instances << " instances: ours lower "
            << ours_lower << ", CGAL's lower " << theirs_lower << ", CGAL's a local minimum "
            << theirs_local_minima << std::endl;
}

void test_alpha_expansion_special_cases()
{
  std::mt19937 random(11);
  // zero pairwise weights: the unary minimum, from any start
  for(int trial = 0; trial < 100; ++trial) {
    Instance instance = random_instance(random, Metric_kind(trial % 4));
    instance.pairwise = [](std::size_t, std::size_t, std::size_t) { return 0.; };
    const Labels labels = run_and_check(instance, random_labels(random, instance));
    for(std::size_t v = 0; v < instance.number_of_vertices; ++v)
      assert(labels[v] == std::size_t(std::min_element(instance.unary[v].begin(), instance.unary[v].end()) -
                                     instance.unary[v].begin()));
  }
  // forbidden labels: never kept where an allowed one exists, even from a start on forbidden
  // labels; the result is a local minimum of the true energy, within the bound
  for(int trial = 0; trial < 150; ++trial) {
    const Instance instance = random_instance(random, Metric_kind(trial % 4), 0.4);
    const Labels labels = run_and_check(instance, random_labels(random, instance));
    for(std::size_t v = 0; v < instance.number_of_vertices; ++v)
      assert(instance.unary[v][labels[v]] != infinity);
    const double ours = energy(instance, labels), best = optimum(instance);
    const Expansion expansion(instance.edges, instance.unary, instance.pairwise);
    assert(expansion.forbidden_cost() > 0 || std::none_of(instance.unary.begin(), instance.unary.end(),
          [](const std::vector<double>& row) { return std::count(row.begin(), row.end(), infinity) > 0; }));
    assert(std::abs(ours - expansion.energy(labels)) <= 1e-9 * (1 + ours));
    assert(is_expansion_local_minimum(instance, labels));
    if(instance.ratio > 0)
      assert(ours <= 2 * instance.ratio * best + 1e-9 * (1 + best));
  }
  // a vertex with no allowed label: the others still get allowed ones
  {
    Instance instance = random_instance(random, Metric_kind::HEIGHT, 0.3);
    std::fill(instance.unary[0].begin(), instance.unary[0].end(), infinity);
    const Labels labels = run_and_check(instance, random_labels(random, instance));
    for(std::size_t v = 1; v < instance.number_of_vertices; ++v)
      assert(instance.unary[v][labels[v]] != infinity);
  }
}

// a 30 x 30 grid with 8 labels: no single-vertex change lowers the energy (each is an
// expansion move)
void test_alpha_expansion_on_a_grid()
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  const std::size_t side = 30, labels = 8, n = side * side;
  Instance instance;
  instance.number_of_vertices = n;
  instance.number_of_labels = labels;
  instance.unary.assign(n, std::vector<double>(labels));
  std::vector<double> heights(labels);
  for(std::size_t l = 0; l < labels; ++l)
    heights[l] = double(l) + 0.3 * unit(random);
  for(std::size_t v = 0; v < n; ++v) {
    const double truth = (v % side < side / 2 ? 2. : 5.) + (v / side < side / 3 ? 1. : 0.);
    for(std::size_t l = 0; l < labels; ++l)
      instance.unary[v][l] = (std::min)(2., std::abs(heights[l] - truth + 2 * (unit(random) - 0.5)));
  }
  for(std::size_t v = 0; v < n; ++v) {
    if(v % side + 1 < side) instance.edges.emplace_back(v, v + 1);
    if(v + side < n) instance.edges.emplace_back(v, v + side);
  }
  std::vector<double> w(instance.edges.size());
  for(double& x : w)
    x = 0.2 + 0.5 * unit(random);
  instance.pairwise = [w, heights](std::size_t e, std::size_t a, std::size_t b) { return w[e] * std::abs(heights[a] - heights[b]); };
  const Expansion expansion(instance.edges, instance.unary, instance.pairwise);
  const Labels start = expansion.unary_minimum_labels();
  const Labels result = run_and_check(instance, start);
  const double e = energy(instance, result);
  for(std::size_t v = 0; v < n; ++v)
    for(std::size_t l = 0; l < labels; ++l) {
      Labels changed = result;
      changed[v] = l;
      assert(energy(instance, changed) >= e - 1e-9 * e);
    }
  std::cout << "grid 30 x 30, 8 labels: energy " << energy(instance, start) << " -> " << e << std::endl;
}

// ---------------------------------------------------------------------------------------------
// CityJSON

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Face = Mesh::Face_index;
using Type = PPS::Building_surface_type;
using json = nlohmann::json;

// far from the origin and with more decimals than written, as georeferenced data
const Kernel::Vector_3 offset(651234.5678901, 6861234.1234567, 35.4321);

struct Building_faces
{
  std::size_t index;
  std::vector<std::vector<Point>> faces;  // outward
  std::vector<Type> types;
  double volume;
};

// a gable roof on a 10 x 6 footprint (eaves at 4, ridge at 7 along x): 1 ground, 4 walls
// (two of them pentagons), 2 roof faces
Building_faces gable_building(std::size_t index)
{
  auto p = [](double x, double y, double z) { return Point(x, y, z) + offset; };
  const Point g0 = p(0, 0, 0), g1 = p(10, 0, 0), g2 = p(10, 6, 0), g3 = p(0, 6, 0);
  const Point e0 = p(0, 0, 4), e1 = p(10, 0, 4), e2 = p(10, 6, 4), e3 = p(0, 6, 4);
  const Point r0 = p(0, 3, 7), r1 = p(10, 3, 7);
  return {index,
          {{g0, g3, g2, g1}, {g0, g1, e1, e0}, {g1, g2, e2, r1, e1}, {g2, g3, e3, e2}, {g3, g0, e0, r0, e3},
           {e0, e1, r1, r0}, {e2, e3, r0, r1}},
          {Type::GROUND, Type::WALL, Type::WALL, Type::WALL, Type::WALL, Type::ROOF, Type::ROOF},
          10 * 6 * 4 + 10 * 6 * 3 / 2.};
}

// a box [10, 16.0007] x [0, 6] x [0, 4], touching the gable building along x = 10 (16.0007:
// not a whole number of millimetres from the lowest corner, so that the rounding is checked)
Building_faces box_building(std::size_t index)
{
  auto p = [](double x, double y, double z) { return Point(x, y, z) + offset; };
  const double x1 = 16.0007;
  const Point g0 = p(10, 0, 0), g1 = p(x1, 0, 0), g2 = p(x1, 6, 0), g3 = p(10, 6, 0);
  const Point e0 = p(10, 0, 4), e1 = p(x1, 0, 4), e2 = p(x1, 6, 4), e3 = p(10, 6, 4);
  return {index,
          {{e0, e1, e2, e3}, {g0, g1, e1, e0}, {g1, g2, e2, e1}, {g2, g3, e3, e2}, {g3, g0, e0, e3}, {g0, g3, g2, g1}},
          {Type::ROOF, Type::WALL, Type::WALL, Type::WALL, Type::WALL, Type::GROUND},
          (x1 - 10) * 6 * 4};
}

// one mesh with both buildings, vertices shared within a building only
Mesh make_mesh(const std::vector<Building_faces>& buildings, bool with_building, bool with_type)
{
  Mesh mesh;
  Mesh::Property_map<Face, std::size_t> building_map;
  Mesh::Property_map<Face, Type> type_map;
  if(with_building) building_map = mesh.add_property_map<Face, std::size_t>("f:building", 0).first;
  if(with_type) type_map = mesh.add_property_map<Face, Type>("f:surface_type", Type::ROOF).first;
  for(const Building_faces& building : buildings) {
    std::map<Point, Mesh::Vertex_index> vertex;
    for(std::size_t i = 0; i < building.faces.size(); ++i) {
      std::vector<Mesh::Vertex_index> face;
      for(const Point& q : building.faces[i]) {
        auto found = vertex.find(q);
        if(found == vertex.end())
          found = vertex.emplace(q, mesh.add_vertex(q)).first;
        face.push_back(found->second);
      }
      const Face f = mesh.add_face(face);
      assert(f != Mesh::null_face());
      if(with_building) building_map[f] = building.index;
      if(with_type) type_map[f] = building.types[i];
    }
  }
  return mesh;
}

// checks the file against the buildings it was written from (`scale`: the expected scale)
void check_CityJSON(const std::string& text, const std::vector<Building_faces>& buildings, double scale)
{
  const json j = json::parse(text);
  assert(j.at("type") == "CityJSON" && j.at("version") == "1.1");
  const json& transform = j.at("transform");
  assert(transform.at("scale").size() == 3 && transform.at("translate").size() == 3);
  std::array<double, 3> translate;
  for(int i = 0; i < 3; ++i) {
    assert(transform["scale"][i].get<double>() == scale);
    translate[i] = transform["translate"][i].get<double>();
  }
  // vertices: integers, no two equal, all used, each within half a unit of an original point
  const json& vertices = j.at("vertices");
  std::set<std::array<long long, 3>> distinct;
  std::vector<Point> decoded;
  std::set<Point> originals;
  for(const Building_faces& building : buildings)
    for(const auto& face : building.faces)
      originals.insert(face.begin(), face.end());
  for(const json& v : vertices) {
    assert(v.size() == 3 && v[0].is_number_integer() && v[1].is_number_integer() && v[2].is_number_integer());
    distinct.insert({{v[0].get<long long>(), v[1].get<long long>(), v[2].get<long long>()}});
    decoded.emplace_back(v[0].get<long long>() * scale + translate[0], v[1].get<long long>() * scale + translate[1],
                         v[2].get<long long>() * scale + translate[2]);
    // each coordinate within half a unit (rounding to the nearest integer)
    double nearest = infinity;
    for(const Point& q : originals)
      nearest = (std::min)(nearest, (std::max)({std::abs(q.x() - decoded.back().x()), std::abs(q.y() - decoded.back().y()),
                                                std::abs(q.z() - decoded.back().z())}));
    assert(nearest <= scale / 2 + 1e-7);
  }
  assert(distinct.size() == vertices.size());
  std::vector<bool> used(vertices.size(), false);

  const json& objects = j.at("CityObjects");
  assert(objects.size() == buildings.size());
  for(const Building_faces& building : buildings) {
    const std::string id = "building_" + std::to_string(building.index);
    assert(objects.contains(id));
    const json& object = objects[id];
    assert(object.at("type") == "Building" && object.at("geometry").size() == 1);
    const json& geometry = object["geometry"][0];
    assert(geometry.at("type") == "Solid" && geometry.at("lod").is_string() && geometry["lod"] == "2.2");
    const json& boundaries = geometry.at("boundaries");
    assert(boundaries.size() == 1);  // one shell
    const json& shell = boundaries[0];
    assert(shell.size() == building.faces.size());
    const json& semantics = geometry.at("semantics");
    const char* type_names[] = {"RoofSurface", "WallSurface", "GroundSurface"};
    assert(semantics.at("surfaces").size() == 3);
    for(int t = 0; t < 3; ++t)
      assert(semantics["surfaces"][t].at("type") == type_names[t]);
    assert(semantics.at("values").size() == 1 && semantics["values"][0].size() == shell.size());

    // each surface is one face of the building, with its orientation and its type
    std::vector<std::size_t> points_of_shell;
    std::vector<std::vector<std::size_t>> polygons;
    std::vector<bool> matched(building.faces.size(), false);
    for(std::size_t s = 0; s < shell.size(); ++s) {
      assert(shell[s].size() == 1);  // an outer ring, no hole
      const json& ring = shell[s][0];
      assert(ring.size() >= 3);
      std::vector<std::size_t> polygon;
      for(const json& index : ring) {
        assert(index.is_number_unsigned() && index.get<std::size_t>() < vertices.size());
        const std::size_t i = index.get<std::size_t>();
        assert(std::find(polygon.begin(), polygon.end(), i) == polygon.end());
        polygon.push_back(i);
        used[i] = true;
      }
      std::size_t matches = 0;
      for(std::size_t f = 0; f < building.faces.size(); ++f) {
        const auto& face = building.faces[f];
        if(face.size() != polygon.size())
          continue;
        for(std::size_t shift = 0; shift < face.size(); ++shift) {
          bool same = true;
          for(std::size_t i = 0; i < face.size() && same; ++i)
            same = CGAL::squared_distance(face[(i + shift) % face.size()], decoded[polygon[i]]) <= 3 * scale * scale;
          if(same) {
            ++matches;
            assert(!matched[f]);
            matched[f] = true;
            assert(semantics["values"][0][s] == static_cast<unsigned int>(building.types[f]));
          }
        }
      }
      assert(matches == 1);
      polygons.push_back(polygon);
    }

    // the shell bounds the volume of the building with outward surfaces
    std::vector<Point> points;
    std::map<std::size_t, std::size_t> local;
    for(auto& polygon : polygons)
      for(std::size_t& i : polygon) {
        const auto inserted = local.emplace(i, points.size());
        if(inserted.second)
          points.push_back(decoded[i]);
        i = inserted.first->second;
      }
    assert(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons));
    Mesh solid;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, solid);
    assert(CGAL::is_closed(solid));
    assert(CGAL::Polygon_mesh_processing::triangulate_faces(solid));
    assert(CGAL::Polygon_mesh_processing::is_outward_oriented(solid));
    const double volume = CGAL::Polygon_mesh_processing::volume(solid);
    assert(std::abs(volume - building.volume) <= 300 * scale);  // area 300 at most, moved by the rounding
  }
  assert(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
}

template <class Function>
void check_throws(Function f, PPS::Input_error_code code)
{
  try {
    f();
  } catch(const PPS::Input_error& error) {
    assert(error.code() == code);
    std::cout << "  refused: " << error.what() << std::endl;
    return;
  }
  assert(!"an Input_error was expected");
}

// a decimal comma and digit grouping, as some locales have
struct Comma_numbers : std::numpunct<char>
{
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

void test_CityJSON()
{
  const std::vector<Building_faces> buildings = {box_building(7), gable_building(3)};
  const Mesh mesh = make_mesh(buildings, true, true);

  std::ostringstream os;
  assert(PPS::IO::write_CityJSON(os, mesh));
  const std::string text = os.str();
  check_CityJSON(text, buildings, 0.001);
  {
    const json j = json::parse(text);
    // the touching buildings share four points: written once
    assert(j["vertices"].size() == 10 + 8 - 4);
    // buildings by increasing index
    assert(j["CityObjects"].begin().key() == "building_3");
  }
  std::cout << "CityJSON: " << text.size() << " bytes" << std::endl;

  // another precision
  std::ostringstream centimetres;
  assert(PPS::IO::write_CityJSON(centimetres, mesh, CGAL::parameters::stream_precision(2)));
  check_CityJSON(centimetres.str(), buildings, 0.01);

  // the output does not depend on the locale, of the stream or the global one
  {
    const std::locale comma(std::locale::classic(), new Comma_numbers);
    const std::locale previous = std::locale::global(comma);
    std::ostringstream localized;
    localized.imbue(comma);
    localized << 1234.5 << ' ';
    const std::string check_locale = localized.str();
    assert(check_locale == "1.234,5 ");
    assert(PPS::IO::write_CityJSON(localized, mesh));
    std::locale::global(previous);
    assert(localized.str() == check_locale + text);
  }

  // the file overload writes the same text
  const std::string file = "test_lod2_building_parts.city.json";
  std::filesystem::remove(file);
  assert(PPS::IO::write_CityJSON(file, mesh));
  {
    std::ifstream in(file, std::ios::binary);
    std::stringstream content;
    content << in.rdbuf();
    assert(content.str() == text);
  }
  std::filesystem::remove(file);

  // refused input: a typed error and nothing written, no file made
  const Mesh without_type = make_mesh(buildings, true, false);
  const Mesh without_building = make_mesh(buildings, false, true);
  Mesh wrong_type = make_mesh(buildings, false, true);
  wrong_type.add_property_map<Face, int>("f:building", 0);
  for(const Mesh* bad : std::vector<const Mesh*>{&without_type, &without_building, &wrong_type}) {
    std::ostringstream nothing;
    check_throws([&] { PPS::IO::write_CityJSON(nothing, *bad); }, PPS::Input_error_code::MISSING_PROPERTY);
    assert(nothing.str().empty());
    check_throws([&] { PPS::IO::write_CityJSON(file, *bad); }, PPS::Input_error_code::MISSING_PROPERTY);
    assert(!std::filesystem::exists(file));
  }
  {
    std::ostringstream nothing;
    check_throws([&] { PPS::IO::write_CityJSON(nothing, mesh, CGAL::parameters::stream_precision(0.001)); },
                 PPS::Input_error_code::INVALID_PARAMETER);
    check_throws([&] { PPS::IO::write_CityJSON(nothing, mesh, CGAL::parameters::stream_precision(16)); },
                 PPS::Input_error_code::INVALID_PARAMETER);
    Mesh not_finite = mesh;
    not_finite.point(*not_finite.vertices().begin()) = Point(std::nan(""), 0, 0);
    check_throws([&] { PPS::IO::write_CityJSON(nothing, not_finite); }, PPS::Input_error_code::NON_FINITE_COORDINATE);
    assert(nothing.str().empty());
  }

  // a mesh without faces: a valid file without city objects
  {
    Mesh empty;
    empty.add_property_map<Face, std::size_t>("f:building", 0);
    empty.add_property_map<Face, Type>("f:surface_type", Type::ROOF);
    std::ostringstream out;
    assert(PPS::IO::write_CityJSON(out, empty));
    const json j = json::parse(out.str());
    assert(j["CityObjects"].empty() && j["vertices"].empty());
  }

  // JSON strings are escaped
  {
    const std::string tricky = "a\"b\\c\nd\te\x01 \xc3\xa9/";
    std::string out;
    PPS::internal::append_JSON_string(out, tricky);
    assert(json::parse(out).get<std::string>() == tricky);
  }
}

// ---------------------------------------------------------------------------------------------
// Facade evidence: samples in front of and behind the facades

namespace facade_evidence {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Planes = PPS::Building_planes_3<K>;

struct Scene
{
  std::vector<K::Point_3> points;
  Planes planes;

  // a plane whose inliers are the points (x, y, z) of a grid of step 0.25 on the given ranges
  void add(const K::Plane_3& plane, bool vertical, std::array<double, 2> xs, std::array<double, 2> ys,
           std::array<double, 2> zs, double jitter = 0)
  {
    PPS::Building_plane_3<K> p;
    p.plane = plane;
    p.is_vertical = vertical;
    std::mt19937 random(unsigned(points.size()));
    std::uniform_real_distribution<double> noise(-jitter, jitter);
    for(double x = xs[0]; x <= xs[1] + 1e-9; x += 0.25)
      for(double y = ys[0]; y <= ys[1] + 1e-9; y += 0.25)
        for(double z = zs[0]; z <= zs[1] + 1e-9; z += 0.25) {
          p.inliers.push_back(points.size());
          points.emplace_back(x + (vertical ? noise(random) : 0), y, z);
        }
    planes.planes.push_back(p);
  }
};

// a flat roof at 10 over [0, 10] x [0, 10], with an eave of 1 m beyond x = 10, and the facade
// x = 10 (its plane given with either normal) carrying it; with `lower_roof`, a roof at 4 over
// [10, 20] x [0, 10] in front of the facade, which then goes from 4 to 10
Scene box(bool normal_outwards, bool lower_roof, bool roof = true)
{
  Scene scene;
  scene.add(K::Plane_3(0, 0, 1, 0), false, {-5, 25}, {-5, 15}, {0, 0}); // the ground
  scene.planes.ground = 0;
  if(roof) scene.add(K::Plane_3(0, 0, 1, -10), false, {0, 11}, {0, 10}, {10, 10});
  if(lower_roof) scene.add(K::Plane_3(0, 0, 1, -4), false, {11.25, 20}, {0, 10}, {4, 4});
  const K::Plane_3 facade = normal_outwards ? K::Plane_3(1, 0, 0, -10) : K::Plane_3(-1, 0, 0, 10);
  scene.add(facade, true, {10, 10}, {0, 10}, {lower_roof ? 4. : 0., 10}, 0.05);
  return scene;
}

void test_facade_evidence()
{
  const double step = 0.3;
  for(bool normal_outwards : {true, false})
    for(bool lower_roof : {false, true}) {
      const Scene scene = box(normal_outwards, lower_roof);
      const auto samples = PPS::internal::facade_evidence<K>(scene.points, scene.planes, step, 2);
      const auto& facade = scene.planes.planes.back().inliers;
      assert(samples.in_front.size() == 2 * facade.size() && samples.behind.size() == 2 * facade.size());
      for(std::size_t i = 0; i < facade.size(); ++i)
        for(std::size_t k = 0; k < 2; ++k) {
          const auto& p = scene.points[facade[i]];
          const auto& front = samples.in_front[2 * i + k];
          const auto& back = samples.behind[2 * i + k];
          assert(std::abs(front[0] - (10 + double(k + 1) * step)) < 1e-9); // outwards, from the plane
          assert(std::abs(back[0] - (10 - double(k + 1) * step)) < 1e-9);
          assert(front[1] == p.y() && front[2] == p.z() && back[1] == p.y() && back[2] == p.z());
        }
    }
  // a wall with a roof only far from it (beyond its height): neither side is the inside
  Scene lone_wall = box(true, false, false);
  lone_wall.add(K::Plane_3(0, 0, 1, -10), false, {-20, -15}, {0, 10}, {10, 10});
  const auto none = PPS::internal::facade_evidence<K>(lone_wall.points, lone_wall.planes, step, 2);
  assert(none.in_front.empty() && none.behind.empty());
}

// A courtyard 6 m wide between a wing 6 m deep and a wider one, both 15 m high: the facade of
// the narrow wing has more roof within its height on the courtyard side (the other wing) than on
// its own, but the roof on its own side starts at the wall.
void test_facade_evidence_across_a_courtyard()
{
  Scene scene;
  scene.add(K::Plane_3(0, 0, 1, 0), false, {-5, 45}, {-5, 15}, {0, 0});
  scene.planes.ground = 0;
  scene.add(K::Plane_3(0, 0, 1, -15), false, {4, 10}, {0, 10}, {15, 15});  // the narrow wing
  scene.add(K::Plane_3(0, 0, 1, -15), false, {16, 40}, {0, 10}, {15, 15}); // the other one
  scene.add(K::Plane_3(-1, 0, 0, 10), true, {10, 10}, {0, 10}, {0, 15});   // its normal into the narrow wing
  scene.add(K::Plane_3(1, 0, 0, -16), true, {16, 16}, {0, 10}, {0, 15});   // its normal into the other wing
  const double step = 0.3;
  const auto samples = PPS::internal::facade_evidence<K>(scene.points, scene.planes, step, 1);
  const std::size_t n = scene.planes.planes[3].inliers.size();
  assert(samples.in_front.size() == 2 * n && samples.behind.size() == 2 * n);
  for(std::size_t i = 0; i < n; ++i) {
    assert(std::abs(samples.in_front[i][0] - (10 + step)) < 1e-9 && std::abs(samples.behind[i][0] - (10 - step)) < 1e-9);
    assert(std::abs(samples.in_front[n + i][0] - (16 - step)) < 1e-9 && std::abs(samples.behind[n + i][0] - (16 + step)) < 1e-9);
  }
}

} // namespace facade_evidence

// ---------------------------------------------------------------------------------------------
// A square footprint of 20 m, a facade distance of 1 m: which segments it replaces.
// the segment from (x0, y0) to (x1, y1) of the planes `first` and `second`
PPS::Building_segment_2<CGAL::Exact_predicates_inexact_constructions_kernel>
piece(double x0, double y0, double x1, double y1, bool facade, std::size_t first, std::size_t second)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  PPS::Building_segment_2<K> s;
  s.segment = K::Segment_2(K::Point_2(x0, y0), K::Point_2(x1, y1));
  s.is_facade = facade;
  s.first_plane = first;
  s.second_plane = second;
  return s;
}

void test_footprint_replaces_outlines()
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Segment = PPS::Building_segment_2<K>;
  const std::vector<Segment> kept{
    piece(2, 10, 18, 10, false, 1, 2),   // a ridge between two roof planes
    piece(5, 4, 15, 4, true, 1, 1),      // an outline piece inside (a step of the roof)
    piece(9, 9, 10, 10.2, true, 2, 2),   // short, far from the boundary
    piece(3, 19.2, 3.9, 19.6, false, 1, 2), // short near the boundary, but a ridge
    piece(2, 15, 17, 15, true, 3, 1),     // a wall plane meeting a roof plane inside (a step)
    piece(0.5, 8, 19.5, 12, true, 2, 2)}; // from an edge to the opposite one (a step)
  const std::vector<Segment> replaced{
    piece(19.6, 2, 19.4, 18, true, 1, 1), // along the edge x = 20, 0.5 m inside
    piece(0.5, 3, 0.5, 17, true, 3, 1),   // along the edge x = 0: a wall plane meeting a roof plane
    piece(18.9, 0.3, 19.7, 1.2, true, 2, 2),  // cuts the corner (20, 0)
    piece(0.4, 17.5, 2.5, 19.6, true, 2, 2)}; // from an edge to the next, 2 m from their corner (0, 20)
  std::vector<Segment> segments = kept;
  segments.insert(segments.end(), replaced.begin(), replaced.end());
  const std::vector<std::vector<std::array<double, 2>>> square{{{{0, 0}}, {{20, 0}}, {{20, 20}}, {{0, 20}}}};
  PPS::internal::replace_outlines_by_footprint(square, 1., segments);
  assert(segments.size() == kept.size() + 4);
  for(std::size_t i = 0; i < kept.size(); ++i) assert(segments[i].segment == kept[i].segment);
  for(std::size_t k = 0; k < 4; ++k) {
    const Segment& edge = segments[kept.size() + k];
    assert(edge.is_facade);
    assert(edge.segment.source() == K::Point_2(square[0][k][0], square[0][k][1]));
    assert(edge.segment.target() == K::Point_2(square[0][(k + 1) % 4][0], square[0][(k + 1) % 4][1]));
  }
  // no footprint: nothing changes
  std::vector<Segment> unchanged = kept;
  PPS::internal::replace_outlines_by_footprint({}, 1., unchanged);
  assert(unchanged.size() == kept.size());
  // a stepped footprint: the high wall at y = 10 stands between x = 6 and 14, above the lower
  // part; its line with the high roof runs across the whole building, 0.2 m off and 2 degrees
  // from the footprint's edges (0, 10)-(6, 10) and (14, 10)-(20, 10)
  const std::vector<std::vector<std::array<double, 2>>> stepped{
    {{{0, 0}}, {{20, 0}}, {{20, 10}}, {{14, 10}}, {{14, 16}}, {{6, 16}}, {{6, 10}}, {{0, 10}}}};
  std::vector<Segment> step{piece(-0.5, 9.8, 20.5, 9.8 + 21 * std::tan(2 * CGAL_PI / 180), true, 4, 1)};
  PPS::internal::replace_outlines_by_footprint(stepped, 1., step);
  assert(step.size() == 1 + 8);
  const Segment& middle = step.front();
  assert(middle.first_plane == 4 && middle.second_plane == 1 && middle.is_facade);
  // the middle keeps its line and ends where the edges end, at x = 6 and 14
  const K::Line_2 line(K::Point_2(-0.5, 9.8), K::Point_2(20.5, 9.8 + 21 * std::tan(2 * CGAL_PI / 180)));
  for(const K::Point_2& p : {middle.segment.source(), middle.segment.target()})
    assert(CGAL::squared_distance(p, line) < 1e-20);
  const double x0 = std::min(middle.segment.source().x(), middle.segment.target().x());
  const double x1 = std::max(middle.segment.source().x(), middle.segment.target().x());
  assert(std::abs(x0 - 6) < 1e-9 && std::abs(x1 - 14) < 1e-9);
}

// Ridges reach the footprint's boundary: on an L-shaped footprint, the ridge of either wing is
// extended to its end walls, an oblique one to where its line leaves the L, one on a diagonal
// through two corners to these corners, one sticking out of the footprint is cut where it leaves
// it; one whose middle is outside, facade segments and roof outline pieces stay as they are.
void test_ridges_reach_the_footprint()
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Segment = PPS::Building_segment_2<K>;
  // the L: (0, 0) to (30, 0) to (30, 10) to (10, 10) to (10, 30) to (0, 30)
  const std::vector<std::vector<std::array<double, 2>>> footprint{
    {{{0, 0}}, {{30, 0}}, {{30, 10}}, {{10, 10}}, {{10, 30}}, {{0, 30}}}};
  std::vector<Segment> segments{
    piece(12, 5, 26, 5, false, 1, 2),    // the ridge of the long wing: from x = 0 to 30
    piece(5, 12, 5, 25, false, 3, 4),    // the other wing's: from y = 0 to 30
    piece(14, 6, 18, 8, false, 1, 3),    // on y = x / 2 - 1: from (2, 0) to (22, 10)
    piece(20, 20, 25, 25, false, 3, 1),  // its middle is outside: unchanged
    piece(-2, 2, 3, 2, false, 2, 3),     // sticks out through x = 0: cut there, extended to x = 30
    piece(12, 5, 26, 5, true, 1, 5),     // a facade segment: unchanged
    piece(12, 4, 26, 4, true, 1, 1)};    // a roof outline piece: unchanged
  const std::vector<Segment> given = segments;
  PPS::internal::extend_ridges_to_footprint(footprint, segments);
  auto is = [](const Segment& s, double x0, double y0, double x1, double y1) {
    return CGAL::squared_distance(s.segment.source(), K::Point_2(x0, y0)) < 1e-18 &&
           CGAL::squared_distance(s.segment.target(), K::Point_2(x1, y1)) < 1e-18;
  };
  assert(is(segments[0], 0, 5, 30, 5));
  assert(is(segments[1], 5, 0, 5, 30));
  assert(is(segments[2], 2, 0, 22, 10));
  assert(is(segments[4], 0, 2, 30, 2));
  for(std::size_t i : {3, 5, 6}) assert(segments[i].segment == given[i].segment);
  // on the diagonal, through the corners (0, 0) and (10, 10): inside the L between them
  std::vector<Segment> diagonal{piece(2, 2, 6, 6, false, 1, 2)};
  PPS::internal::extend_ridges_to_footprint(footprint, diagonal);
  assert(is(diagonal[0], 0, 0, 10, 10));
}

// Corners cut off by a roof outline are closed: on a 20 m square outline whose corner (20, 0) a
// 2.6 m piece cuts off, with ends a few decimetres apart as outlines come, the sides' lines
// are extended to the corner, as facade segments of the sides' planes; the other corners, a
// piece longer than the longest, a short piece between two nearly parallel pieces (a jog), a
// short ridge and a piece whose neighbours run away from their meeting point add nothing.
void test_outline_corners_are_closed()
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Segment = PPS::Building_segment_2<K>;
  std::vector<Segment> square{
    piece(0, 0, 18.2, 0.02, true, 1, 1),   // bottom side, plane 1
    piece(18.5, 0.1, 19.9, 2.3, true, 1, 1), // cuts the corner (20, 0) off
    piece(20, 2.1, 20, 20, true, 2, 2),    // right side, plane 2 (its end 0.2 m from the piece's)
    piece(20, 20, 0, 20, true, 1, 1),
    piece(0, 20, 0, 0, true, 3, 5)};       // a wall plane 3 meeting roof plane 5
  const std::vector<Segment> given = square;
  PPS::internal::close_outline_corners(square, 0.6, 3.);
  assert(square.size() == given.size() + 2);
  for(std::size_t i = 0; i < given.size(); ++i) assert(square[i].segment == given[i].segment);
  // the two added segments run from the sides' ends to where their lines meet
  const K::Line_2 bottom = given[0].segment.supporting_line(), right = given[2].segment.supporting_line();
  const Segment& from_bottom = square[given.size()].first_plane == 1 ? square[given.size()] : square[given.size() + 1];
  const Segment& from_right = square[given.size()].first_plane == 1 ? square[given.size() + 1] : square[given.size()];
  assert(from_bottom.is_facade && from_bottom.first_plane == 1 && from_bottom.second_plane == 1);
  assert(from_right.is_facade && from_right.first_plane == 2 && from_right.second_plane == 2);
  assert(from_bottom.segment.source() == given[0].segment.target());
  assert(from_right.segment.source() == given[2].segment.source());
  const K::Point_2 x = from_bottom.segment.target(); // on both lines, near the true corner
  assert(from_right.segment.target() == x);
  assert(CGAL::squared_distance(x, bottom) < 1e-18 && CGAL::squared_distance(x, right) < 1e-18);
  assert(CGAL::squared_distance(x, K::Point_2(20, 0)) < 0.1);
  // nothing is added for:
  const std::vector<std::vector<Segment>> unchanged{
    {piece(0, 0, 16, 0, true, 1, 1), piece(16.3, 0.1, 19.9, 4.3, true, 1, 1), piece(20, 4.2, 20, 20, true, 1, 1)}, // 5.5 m piece
    {piece(0, 0, 10, 0, true, 1, 1), piece(10.1, 0, 10.6, 0.5, true, 1, 1), piece(10.7, 0.5, 20, 0.6, true, 1, 1)}, // a jog
    {piece(0, 0, 18.2, 0, true, 1, 1), piece(18.5, 0.1, 19.9, 2.3, false, 1, 2), piece(20, 2.1, 20, 20, true, 2, 2)}, // a ridge
    {piece(0, 0, 17.5, 0, true, 1, 1), piece(18.5, 0.1, 19.9, 2.3, true, 1, 1), piece(20, 2.1, 20, 20, true, 2, 2)}}; // 1 m gap
  for(std::vector<Segment> segments : unchanged) {
    const std::size_t n = segments.size();
    PPS::internal::close_outline_corners(segments, 0.6, 3.);
    assert(segments.size() == n);
  }
  // a neighbour that runs away from where its line meets the other's: that point is behind the
  // end of the other
  std::vector<Segment> away{piece(0, 0, 10, 0, true, 1, 1), piece(10, 0.2, 10, 2, true, 1, 1), piece(10.1, 2.2, 12, 4, true, 1, 1)};
  PPS::internal::close_outline_corners(away, 0.6, 3.);
  assert(away.size() == 3);
}

// Pieces of roof outlines that cut across a corner of two detected walls are removed: on a
// building whose walls 1 and 2 meet at the convex corner (20, 0), and walls 4 and 5 at the
// concave corner (10, 8) (planes 0 ground, 3 roof), a 1.6 m piece with an end on each wall's
// line near the corner (the outline of the roof's points cuts the convex corner and bridges
// the concave one) goes, and the other segments stay in their order. A piece along one wall,
// a piece longer than the longest, a piece with an end away from every wall line, a piece
// between two parallel walls and the corner of outlines without walls (nothing is vertical)
// stay.
void test_corner_chords_are_removed()
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Segment = PPS::Building_segment_2<K>;
  const std::vector<bool> is_vertical{false, true, true, false, true, true};
  const std::vector<Segment> walls{
    piece(0, 0, 19.3, 0.02, true, 1, 3),  // wall 1 under the roof, 0.7 m short of the corner
    piece(0, 0, 19.1, 0, true, 0, 1),     // wall 1 on the ground
    piece(20, 0.8, 20, 20, true, 2, 3),   // wall 2 under the roof
    piece(10, 8.6, 10, 18, true, 4, 3),   // wall 4, north of the concave corner
    piece(10.7, 8, 24, 8.01, true, 5, 3)}; // wall 5, east of it
  const Segment convex = piece(19.0, 0.05, 20.02, 1.2, true, 3, 3), concave = piece(10.6, 7.98, 10.01, 8.9, true, 3, 3);
  const std::vector<Segment> kept{
    piece(2, 0.1, 8, 0.1, true, 3, 3),      // along wall 1: both ends near one wall
    piece(15, 0.05, 20, 4.5, true, 3, 3),   // 6.7 m, longer than the longest (3 m)
    piece(19.0, 0.05, 21.5, 1.2, true, 3, 3), // its target is 1.5 m from wall 2's line
    piece(2, 20.2, 3, 19.9, false, 3, 6)};  // a ridge
  std::vector<Segment> segments = walls;
  segments.insert(segments.begin() + 2, convex);
  segments.push_back(concave);
  segments.insert(segments.end(), kept.begin(), kept.end());
  PPS::internal::remove_corner_chords(segments, is_vertical, 0.6, 3.);
  std::vector<Segment> expected = walls;
  expected.insert(expected.end(), kept.begin(), kept.end());
  assert(segments.size() == expected.size());
  for(std::size_t i = 0; i < expected.size() && i < segments.size(); ++i)
    assert(segments[i].segment == expected[i].segment && segments[i].first_plane == expected[i].first_plane);
  // between two parallel walls (a 1.2 m gap closed by the outline): kept
  std::vector<Segment> parallel{piece(0, 0, 10, 0, true, 1, 3), piece(10.5, 1.2, 20, 1.2, true, 2, 3),
                                piece(9.9, 0.05, 10.6, 1.15, true, 3, 3)};
  PPS::internal::remove_corner_chords(parallel, is_vertical, 0.6, 3.);
  assert(parallel.size() == 3);
  // the same corner with outlines on both sides and no wall plane: kept (close_outline_corners()
  // adds the corner and the graph cut chooses)
  std::vector<Segment> outlines{piece(0, 0, 19.3, 0.02, true, 3, 3), piece(20, 0.8, 20, 20, true, 3, 3), convex};
  PPS::internal::remove_corner_chords(outlines, std::vector<bool>(6, false), 0.6, 3.);
  assert(outlines.size() == 3);
}

int main()
{
  test_alpha_expansion_against_brute_force();
  test_alpha_expansion_against_CGAL();
  test_alpha_expansion_special_cases();
  test_alpha_expansion_on_a_grid();
  test_CityJSON();
  facade_evidence::test_facade_evidence();
  facade_evidence::test_facade_evidence_across_a_courtyard();
  test_footprint_replaces_outlines();
  test_ridges_reach_the_footprint();
  test_outline_corners_are_closed();
  test_corner_chords_are_removed();
  std::cout << "done" << std::endl;
  return EXIT_SUCCESS;
}
