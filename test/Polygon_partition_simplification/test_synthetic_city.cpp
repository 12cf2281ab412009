// Tests of the synthetic city tile (synthetic_city.h) used by the tests and the benchmark of the
// city-scale LOD2 pipeline: the truth meshes are closed, outward, bound a volume and do not
// intersect themselves (CGAL's PMP); the footprints are simple, oriented, match the floors and
// do not overlap (brute force with exact constructions), the terraced houses sharing an edge; the
// points are where their class says, at the expected densities, trees 1.5 m or more from every
// footprint; the same seed gives the same city; the LAS file reads back with the repository's
// reader (points within 1 mm, classes through its class filter), the PLY file with CGAL's reader,
// the GeoJSON with nlohmann-json (when found).
// With arguments, `test_synthetic_city BUILDINGS FILE [FOOTPRINTS]` writes the city of the
// default options with BUILDINGS buildings to FILE (.las or .ply) and, if given, its footprints
// to FOOTPRINTS (GeoJSON): the input of the tests of lod2_reconstruct and of measurements.

#include "synthetic_city.h"

#include <CGAL/Lex_optimal_chains/IO/read_las_points.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/IO/read_ply_points.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#ifdef SYNTHETIC_CITY_WITH_JSON
#include <nlohmann/json.hpp>
#endif

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace T = CGAL::Polygon_partition_simplification::test;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace PPS = CGAL::Polygon_partition_simplification;
using Point_2 = T::Point_2;
using Point_3 = T::Point_3;
using Ring = std::vector<Point_2>;

static double area(const Ring& ring) { return CGAL::polygon_area_2(ring.begin(), ring.end(), T::Kernel()); }

// the area of a footprint without its courtyards
static double net_area(const T::City& city, std::size_t b)
{
  double result = area(city.footprints[b]);
  for(const Ring& hole : city.footprint_holes[b]) result += area(hole); // clockwise: negative
  return result;
}

static double face_area(const std::vector<Point_3>& polygon)
{
  double x = 0, y = 0, z = 0; // Newell
  for(std::size_t i = 0; i < polygon.size(); ++i) {
    const Point_3 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    x += (p.y() - q.y()) * (p.z() + q.z()), y += (p.z() - q.z()) * (p.x() + q.x()), z += (p.x() - q.x()) * (p.y() + q.y());
  }
  return std::sqrt(x * x + y * y + z * z) / 2;
}

// Every truth mesh is a valid closed 2-manifold, outward, without self-intersection; its volume
// lies between 4 and 15 m times the net footprint area, its floors cover that area.
static void check_meshes(const T::City& city)
{
  for(std::size_t b = 0; b < city.buildings.size(); ++b) {
    const std::string name = "building " + std::to_string(b) + " (" + city.kinds[b] + ")";
    T::Mesh mesh = T::truth_mesh(city.buildings[b]);
    assert(CGAL::is_valid_polygon_mesh(mesh));
    assert(CGAL::is_closed(mesh));
    assert(mesh.number_of_faces() == city.buildings[b].faces.size());
    PMP::triangulate_faces(mesh);
    assert(CGAL::is_closed(mesh) && PMP::is_outward_oriented(mesh));
    assert(!PMP::does_self_intersect(mesh));
    const double volume = PMP::volume(mesh), footprint = net_area(city, b);
    assert(volume > 0);
    assert(volume >= 4 * footprint * 0.999 && volume <= 15 * footprint * 1.001);
    double floors = 0;
    for(const T::Planar_face& face : city.buildings[b].faces)
      if(face.role == T::FLOOR) floors += face_area(face.vertices);
    assert(std::abs(floors - footprint) < 1e-6 * footprint);
  }
}

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

static CGAL::Polygon_2<EK> exact_polygon(const Ring& ring)
{
  CGAL::Polygon_2<EK> polygon;
  for(const Point_2& p : ring) polygon.push_back(EK::Point_2(p.x(), p.y()));
  return polygon;
}

// Whether the interiors of two simple counterclockwise polygons meet (brute force, exact): a
// piece of an edge of one (split where it meets the other's boundary) inside the other, or two
// edges overlapping in the same direction (both interiors on their left). An overlap region is
// bounded by such pieces, or by shared stretches of boundary, which the interiors of both are
// then on the same side of.
static bool interiors_meet(const CGAL::Polygon_2<EK>& p, const CGAL::Polygon_2<EK>& q)
{
  for(auto e = p.edges_begin(); e != p.edges_end(); ++e) {
    std::vector<EK::Point_2> cuts{e->source(), e->target()};
    for(auto f = q.edges_begin(); f != q.edges_end(); ++f) {
      const auto meet = CGAL::intersection(*e, *f);
      if(!meet) continue;
      if(const EK::Point_2* point = PPS::internal::get_if<EK::Point_2>(meet)) cuts.push_back(*point);
      if(const EK::Segment_2* common = PPS::internal::get_if<EK::Segment_2>(meet)) {
        if(e->to_vector() * f->to_vector() > 0) return true;
        cuts.push_back(common->source()), cuts.push_back(common->target());
      }
    }
    std::sort(cuts.begin(), cuts.end(), [&](const EK::Point_2& a, const EK::Point_2& b) {
      return (a - e->source()) * e->to_vector() < (b - e->source()) * e->to_vector();
    });
    for(std::size_t i = 0; i + 1 < cuts.size(); ++i)
      if(cuts[i] != cuts[i + 1] && q.bounded_side(CGAL::midpoint(cuts[i], cuts[i + 1])) == CGAL::ON_BOUNDED_SIDE) return true;
  }
  return false;
}

// two consecutive corners of one ring are two consecutive corners of the other (either way)
static bool share_an_edge(const Ring& a, const Ring& b)
{
  for(std::size_t i = 0; i < a.size(); ++i)
    for(std::size_t j = 0; j < b.size(); ++j)
      if(a[i] == b[j] && (a[(i + 1) % a.size()] == b[(j + b.size() - 1) % b.size()] || a[(i + 1) % a.size()] == b[(j + 1) % b.size()]))
        return true;
  return false;
}

// Footprints simple, counterclockwise, holes clockwise inside them; no two overlap, the
// terraced houses share an edge.
static void check_footprints(const T::City& city)
{
  assert(city.footprints.size() == city.buildings.size() && city.footprint_holes.size() == city.buildings.size() &&
          city.kinds.size() == city.buildings.size());
  std::vector<CGAL::Polygon_2<EK>> exact;
  for(std::size_t b = 0; b < city.footprints.size(); ++b) {
    const Ring& outer = city.footprints[b];
    assert(outer == city.buildings[b].footprint);
    assert(CGAL::is_simple_2(outer.begin(), outer.end(), T::Kernel()) && area(outer) > 0);
    for(const Ring& hole : city.footprint_holes[b]) {
      assert(CGAL::is_simple_2(hole.begin(), hole.end(), T::Kernel()) && area(hole) < 0);
      for(const Point_2& p : hole)
        assert(CGAL::bounded_side_2(outer.begin(), outer.end(), p, T::Kernel()) == CGAL::ON_BOUNDED_SIDE);
    }
    exact.push_back(exact_polygon(outer));
  }
  for(std::size_t a = 0; a < exact.size(); ++a)
    for(std::size_t b = a + 1; b < exact.size(); ++b)
      if(CGAL::do_overlap(exact[a].bbox(), exact[b].bbox()))
        assert(!interiors_meet(exact[a], exact[b]) && !interiors_meet(exact[b], exact[a]));
  std::size_t pairs = 0;
  for(std::size_t b = 0; b + 1 < city.kinds.size(); ++b)
    if(city.kinds[b] == "terraced_gable") {
      ++pairs;
      assert(city.kinds[b + 1] == "terraced_flat");
      assert(share_an_edge(city.footprints[b], city.footprints[b + 1]));
    }
  assert(pairs == city.buildings.size() / 9 + (city.buildings.size() % 9 >= 8 ? 1 : 0));
}

struct Class_counts
{
  std::size_t ground = 0, building = 0, tree = 0, other = 0;
};

static Class_counts count_classes(const T::City& city, int tree_class)
{
  Class_counts counts;
  for(const T::City_sample& s : city.samples)
    (s.classification == T::las_ground_class ? counts.ground
     : s.classification == T::las_building_class ? counts.building
     : s.classification == tree_class ? counts.tree : counts.other)++;
  return counts;
}

// Ground points on z = 0 outside the buildings (in the courtyards allowed), at the expected
// number; building points near their face, roofs at the expected number, walls on every
// building but the one without; tree points 1.5 m or more from every footprint.
static void check_samples(const T::City& city, const T::City_options& options)
{
  const Class_counts counts = count_classes(city, options.tree_class);
  assert(counts.other == 0 && counts.ground > 0 && counts.building > 0);
  assert(options.trees == (counts.tree > 0));
  double ground_area = city.extent.area();
  for(std::size_t b = 0; b < city.buildings.size(); ++b) ground_area -= net_area(city, b);
  assert(std::abs(double(counts.ground) - options.density * ground_area) < 0.001 * options.density * ground_area + 10);
  std::vector<std::size_t> wall_points(city.buildings.size(), 0), roof_points(city.buildings.size(), 0);
  const double tolerance = 6 * options.noise + 1e-9;
  for(const T::City_sample& s : city.samples) {
    const Point_2 below(s.point.x(), s.point.y());
    if(s.classification == T::las_ground_class) {
      assert(s.building == -1 && std::abs(s.point.z()) <= tolerance);
      for(std::size_t b = 0; b < city.buildings.size(); ++b) {
        bool inside = CGAL::bounded_side_2(city.footprints[b].begin(), city.footprints[b].end(), below, T::Kernel()) == CGAL::ON_BOUNDED_SIDE;
        for(const Ring& hole : city.footprint_holes[b])
          inside = inside && CGAL::bounded_side_2(hole.begin(), hole.end(), below, T::Kernel()) == CGAL::ON_UNBOUNDED_SIDE;
        assert(!inside);
      }
    } else if(s.classification == T::las_building_class) {
      assert(s.building >= 0 && std::size_t(s.building) < city.buildings.size());
      if(s.building < 0 || std::size_t(s.building) >= city.buildings.size()) continue;
      const std::vector<T::Planar_face>& faces = city.buildings[std::size_t(s.building)].faces;
      assert(s.face >= 0 && std::size_t(s.face) < faces.size() && faces[std::size_t(s.face)].role != T::FLOOR);
      if(s.face < 0 || std::size_t(s.face) >= faces.size()) continue;
      const T::internal::Plane_frame plane = T::internal::plane_frame(faces[std::size_t(s.face)].vertices);
      assert(std::abs((s.point - plane.origin) * plane.normal) <= tolerance);
      ++(faces[std::size_t(s.face)].role == T::WALL ? wall_points : roof_points)[std::size_t(s.building)];
    } else {
      assert(s.building == -1 && s.point.z() > 0 && s.point.z() < 16);
      for(std::size_t b = 0; b < city.buildings.size(); ++b)
        assert(T::internal::distance_to_polygon(below, city.footprints[b]) >= 1.5);
    }
  }
  for(std::size_t b = 0; b < city.buildings.size(); ++b) {
    double roof_area = 0;
    std::size_t roofs = 0;
    for(const T::Planar_face& face : city.buildings[b].faces)
      if(face.role == T::ROOF) roof_area += face_area(face.vertices), ++roofs;
    assert(std::abs(double(roof_points[b]) - options.density * roof_area) <= 0.5 * double(roofs) + 1e-9);
    const bool without_walls = city.kinds[b].compare(0, 9, "no_walls_") == 0;
    assert(without_walls == (wall_points[b] == 0));
  }
}

// The wall the terraced houses share is seen above the lower (flat) roof only: no point of the
// flat house on it, the points of the gable house on it above that roof.
static void check_shared_walls(const T::City& city, double noise)
{
  for(std::size_t b = 0; b + 1 < city.kinds.size(); ++b) {
    if(city.kinds[b] != "terraced_gable") continue;
    double roof = 0;
    for(const T::Planar_face& face : city.buildings[b + 1].faces)
      for(const Point_3& p : face.vertices) roof = (std::max)(roof, p.z());
    // a wall of one house whose corners are all on the other's footprint
    auto on_shared_wall = [&](std::size_t building, int face) {
      const Ring& other = city.footprints[building == b ? b + 1 : b];
      const T::Planar_face& f = city.buildings[building].faces[std::size_t(face)];
      return f.role == T::WALL && std::all_of(f.vertices.begin(), f.vertices.end(), [&](const Point_3& p) {
               return T::internal::distance_to_polygon(Point_2(p.x(), p.y()), other) < 1e-6;
             });
    };
    for(std::size_t house : {b, b + 1}) {
      std::size_t shared = 0;
      for(std::size_t f = 0; f < city.buildings[house].faces.size(); ++f) shared += on_shared_wall(house, int(f)) ? 1 : 0;
      assert(shared == 1);
    }
    std::size_t seen = 0;
    for(const T::City_sample& s : city.samples) {
      if(s.building == int(b + 1)) assert(!on_shared_wall(b + 1, s.face));
      if(s.building == int(b) && on_shared_wall(b, s.face)) {
        ++seen;
        assert(s.point.z() >= roof - 6 * noise);
      }
    }
    assert(seen > 0);
  }
}

static bool same_samples(const T::City& a, const T::City& b)
{
  if(a.samples.size() != b.samples.size()) return false;
  for(std::size_t i = 0; i < a.samples.size(); ++i)
    if(a.samples[i].point != b.samples[i].point || a.samples[i].classification != b.samples[i].classification ||
       a.samples[i].building != b.samples[i].building || a.samples[i].face != b.samples[i].face)
      return false;
  return true;
}

// The same options give the same city; another seed another one; the layout does not depend on
// the density or the trees.
static void check_determinism(const T::City& city, const T::City_options& options)
{
  assert(same_samples(city, T::make_city(options)));
  T::City_options other = options;
  other.seed = options.seed + 1;
  const T::City reseeded = T::make_city(other);
  assert(!same_samples(city, reseeded) && reseeded.footprints != city.footprints);
  other = options;
  other.density = options.density / 2, other.trees = !options.trees;
  const T::City sparser = T::make_city(other);
  assert(sparser.footprints == city.footprints && sparser.footprint_holes == city.footprint_holes);
  assert((count_classes(sparser, options.tree_class).tree > 0) == other.trees);
}

template <class T_>
static T_ field(const std::vector<unsigned char>& bytes, std::size_t offset)
{
  T_ value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T_)); // the test machine is little-endian, as LAS
  return value;
}

static bool near(const Point_3& p, const Point_3& q, double d)
{
  return std::abs(p.x() - q.x()) <= d && std::abs(p.y() - q.y()) <= d && std::abs(p.z() - q.z()) <= d;
}

// The LAS file read back by the repository's reader: the same points within 1 mm in the same
// order, each class alone through its class filter; the header's counts, scale, offsets, bounds.
static void check_las(const T::City& city, int tree_class, const std::string& path)
{
  T::write_city_las(city, path);
  namespace IO = CGAL::Lex_optimal_chains::IO;
  const std::vector<Point_3> all = IO::read_las_points<Point_3>(path);
  assert(all.size() == city.samples.size());
  for(std::size_t i = 0; i < all.size() && i < city.samples.size(); ++i)
    assert(near(all[i], city.samples[i].point, 0.0005 + 1e-9));
  for(int c : {T::las_ground_class, T::las_building_class, tree_class}) {
    const std::vector<Point_3> read = IO::read_las_points<Point_3>(path, {c});
    std::vector<Point_3> expected;
    for(const T::City_sample& s : city.samples)
      if(s.classification == c) expected.push_back(s.point);
    bool same = read.size() == expected.size();
    for(std::size_t i = 0; same && i < read.size(); ++i) same = near(read[i], expected[i], 0.0005 + 1e-9);
    assert(same);
  }
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> header(227);
  in.read(reinterpret_cast<char*>(header.data()), 227);
  assert(std::memcmp(header.data(), "LASF", 4) == 0 && header[24] == 1 && header[25] == 2 && header[104] == 1 &&
          field<std::uint16_t>(header, 94) == 227 && field<std::uint32_t>(header, 96) == 227 && field<std::uint16_t>(header, 105) == 28);
  assert(field<std::uint32_t>(header, 107) == city.samples.size() && field<std::uint32_t>(header, 111) == city.samples.size() &&
          field<std::uint32_t>(header, 115) == 0);
  for(int c = 0; c < 3; ++c) {
    double low = std::numeric_limits<double>::infinity(), high = -low, written_low = low;
    for(const Point_3& p : all) low = (std::min)(low, p[c]), high = (std::max)(high, p[c]);
    for(const T::City_sample& s : city.samples) written_low = (std::min)(written_low, s.point[c]);
    assert(field<double>(header, 131 + 8 * c) == 0.001 && field<double>(header, 155 + 8 * c) == written_low);
    assert(field<double>(header, 179 + 16 * c) == high && field<double>(header, 187 + 16 * c) == low);
  }
}

// The PLY file read back by CGAL's reader: the same doubles, the same classes.
static void check_ply(const T::City& city, const std::string& path)
{
  T::write_city_ply(city, path);
  std::vector<std::pair<Point_3, unsigned char>> read;
  std::ifstream in(path, std::ios::binary);
  const bool ok = CGAL::IO::read_PLY_with_properties(
      in, std::back_inserter(read), CGAL::IO::make_ply_point_reader(CGAL::First_of_pair_property_map<std::pair<Point_3, unsigned char>>()),
      std::make_pair(CGAL::Second_of_pair_property_map<std::pair<Point_3, unsigned char>>(),
                     CGAL::IO::PLY_property<unsigned char>("classification")));
  assert(ok && read.size() == city.samples.size());
  bool same = read.size() == city.samples.size();
  for(std::size_t i = 0; same && i < read.size(); ++i)
    same = read[i].first == city.samples[i].point && int(read[i].second) == city.samples[i].classification;
  assert(same);
}

// The GeoJSON read back: one feature per building, its id, its rings closed and equal to the
// footprint and the holes.
static void check_geojson(const T::City& city, const std::string& path)
{
  T::write_footprints_geojson(city, path);
#ifdef SYNTHETIC_CITY_WITH_JSON
  std::ifstream in(path);
  const nlohmann::json json = nlohmann::json::parse(in);
  assert(json["type"] == "FeatureCollection" && json["features"].size() == city.buildings.size());
  for(std::size_t b = 0; b < json["features"].size() && b < city.buildings.size(); ++b) {
    const nlohmann::json& feature = json["features"][b];
    assert(feature["properties"]["id"] == b && feature["geometry"]["type"] == "Polygon");
    const nlohmann::json& rings = feature["geometry"]["coordinates"];
    assert(rings.size() == 1 + city.footprint_holes[b].size());
    for(std::size_t r = 0; r < rings.size() && r <= city.footprint_holes[b].size(); ++r) {
      const Ring& ring = r == 0 ? city.footprints[b] : city.footprint_holes[b][r - 1];
      bool same = rings[r].size() == ring.size() + 1;
      for(std::size_t i = 0; same && i <= ring.size(); ++i)
        same = rings[r][i][0].get<double>() == ring[i % ring.size()].x() && rings[r][i][1].get<double>() == ring[i % ring.size()].y();
      assert(same);
    }
  }
#else
  std::cout << "NOTICE: nlohmann-json not found, " << path << " is written, not read back" << std::endl;
#endif
}

static void report(const std::string& name, const T::City& city, const T::City_options& options)
{
  const Class_counts counts = count_classes(city, options.tree_class);
  std::cout << "{\"city\": \"" << name << "\", \"buildings\": " << city.buildings.size() << ", \"points\": " << city.samples.size()
            << ", \"ground\": " << counts.ground << ", \"building\": " << counts.building << ", \"trees\": " << counts.tree
            << ", \"extent_m\": [" << city.extent.xmax() - city.extent.xmin() << ", " << city.extent.ymax() - city.extent.ymin()
            << "]}" << std::endl;
}

// the city of the default options with `argv[1]` buildings, written to `argv[2]` (.las or .ply)
// and its footprints to `argv[3]` (GeoJSON), if given
static int write_city(int argc, char** argv)
{
  T::City_options options;
  options.buildings = std::size_t(std::strtoul(argv[1], nullptr, 10));
  const std::string path = argc > 2 ? argv[2] : "";
  auto ends_with = [&path](const std::string& end) {
    return path.size() >= end.size() && path.compare(path.size() - end.size(), end.size(), end) == 0;
  };
  if(options.buildings == 0 || !(ends_with(".las") || ends_with(".ply"))) {
    std::cerr << "usage: test_synthetic_city BUILDINGS FILE.las|FILE.ply [FOOTPRINTS.geojson]" << std::endl;
    return 1;
  }
  const T::City city = T::make_city(options);
  try {
    if(ends_with(".las")) T::write_city_las(city, path);
    else T::write_city_ply(city, path);
    if(argc > 3) T::write_footprints_geojson(city, argv[3]);
  } catch(const std::exception& e) {
    std::cerr << "test_synthetic_city: " << e.what() << std::endl;
    return 1;
  }
  report(path, city, options);
  return 0;
}

int main(int argc, char** argv)
{
  if(argc > 1) return write_city(argc, argv);
  const T::City_options options;
  const T::City city = T::make_city(options);
  report("default", city, options);
  assert(city.buildings.size() == 12);
  check_meshes(city);
  check_footprints(city);
  check_samples(city, options);
  check_shared_walls(city, options.noise);
  check_determinism(city, options);
  check_las(city, options.tree_class, "test_synthetic_city.las");
  check_ply(city, "test_synthetic_city.ply");
  check_geojson(city, "test_synthetic_city.geojson");

  // unclassified trees, a sparser wall sampling, another seed, an odd count (the last pair of
  // terraced houses replaced by one building)
  T::City_options small;
  small.buildings = 16, small.tree_class = 1, small.wall_density_factor = 0.3, small.seed = 7, small.spacing = 26;
  const T::City small_city = T::make_city(small);
  assert(small_city.buildings.size() == 16);
  check_meshes(small_city);
  check_footprints(small_city);
  check_samples(small_city, small);
  check_shared_walls(small_city, small.noise);
  check_las(small_city, small.tree_class, "test_synthetic_city_unclassified_trees.las");

  T::City_options large;
  large.buildings = 120;
  const T::City large_city = T::make_city(large);
  report("120 buildings", large_city, large);
  assert(large_city.buildings.size() == 120);
  check_meshes(large_city);
  check_footprints(large_city);

  std::cout << "test_synthetic_city: all checks passed" << std::endl;
  return 0;
}
