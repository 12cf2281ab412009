// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Synthetic aerial-LiDAR-like scenes of buildings whose true LOD2 model is known, for the
// tests and the benchmark of the LOD2 reconstruction: a gable roof, a hip roof, an L-shaped
// flat roof, flat roofs at two heights (a building with a lower annex), and five such
// buildings on one ground. The truth of a building is a closed, outward-oriented polygon mesh
// (roofs, walls, floor on z = 0). Points are sampled uniformly on the roofs and on the ground
// around the buildings, at a lower density on the walls (an airborne scanner sees them
// poorly), and moved along the normal of the true surface by Gaussian noise. Flat roofs can
// overhang their walls (eaves, sampled as the roof but not part of the truth, whose walls
// stand on the footprints as LOD2 models' do); every flat roof gets them, so in the scene of two
// heights the main roof's eave would overhang the annex's roof: the tests give eaves to the
// L-shaped building only. The samples depend only on the seed, whatever the compiler: the
// uniform and normal variates are made here from std::mt19937, whose output the standard fixes,
// not by the library's distributions, which it does not, and one draw is one statement.
// Also: distances of points to a mesh and between two meshes both ways (sampled Hausdorff).

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_TEST_SYNTHETIC_BUILDINGS_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_TEST_SYNTHETIC_BUILDINGS_H

#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>

#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace test {

using Kernel = Exact_predicates_inexact_constructions_kernel;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Vector_3 = Kernel::Vector_3;
using Triangle_3 = Kernel::Triangle_3;
using Mesh = Surface_mesh<Point_3>;

/// What a face of a scene is; the values are bits, so that a set of roles is their sum.
enum Surface_role { ROOF = 1, WALL = 2, FLOOR = 4, GROUND = 8 };

/// A planar face of a true model, counterclockwise seen from outside (its normal points out),
/// and the index of the plane of its points (-1 for a floor, which is never sampled).
struct Planar_face
{
  std::vector<Point_3> vertices;
  Surface_role role;
  int plane_index = -1;
};

struct Building
{
  std::vector<Point_2> footprint; // counterclockwise
  std::vector<Planar_face> faces; // together a closed surface
};

enum class Scene_kind { GABLE_ROOF, HIP_ROOF, L_SHAPED_FLAT_ROOF, TWO_HEIGHT_FLAT_ROOFS, SEVERAL_BUILDINGS };

struct Scene
{
  std::string name;
  std::vector<Building> buildings;
  Kernel::Iso_rectangle_2 ground; // the ground is the plane z = 0 over this rectangle
  int number_of_planes = 1;       // plane indices: 0 for the ground, then one per roof or wall face
};

/// A sampled point, the unit outward normal of the true surface there and the index of its plane.
struct Sample
{
  Point_3 point;
  Vector_3 normal;
  int plane_index = -1;
};

/// Readable and writable property map of one member of `Sample` (for the algorithms and the PLY reader).
template <class T, T Sample::*member>
struct Sample_member_map
{
  using key_type = Sample;
  using value_type = T;
  using reference = const T&;
  using category = boost::read_write_property_map_tag;
  friend const T& get(Sample_member_map, const Sample& sample) { return sample.*member; }
  friend void put(Sample_member_map, Sample& sample, const T& value) { sample.*member = value; }
};
using Sample_point_map = Sample_member_map<Point_3, &Sample::point>;
using Sample_normal_map = Sample_member_map<Vector_3, &Sample::normal>;
using Sample_plane_index_map = Sample_member_map<int, &Sample::plane_index>;

struct Sampling_options
{
  double density = 20;              // points per square meter on the roofs and the ground
  double wall_density_factor = 0.1; // wall density relative to it: 1 (as the roofs), 0.1 (sparse), 0 (none)
  double noise = 0.05;              // standard deviation of the displacement along the normal (m)
  double eave_overhang = 0;         // width of the eaves of the flat roofs beyond the walls (sampled, not in the truth)
  unsigned seed = 1;
};

namespace internal {

inline Point_3 lift(const Point_2& p, double z) { return Point_3(p.x(), p.y(), z); }

// The wall on the footprint edge a -> b: that edge at z = 0, then its top from b back to a.
inline Planar_face wall(const Point_2& a, const Point_2& b, std::vector<Point_3> top_from_b_to_a)
{
  top_from_b_to_a.insert(top_from_b_to_a.begin(), {lift(a, 0), lift(b, 0)});
  return {top_from_b_to_a, WALL};
}

inline Planar_face wall_of_height(const Point_2& a, const Point_2& b, double height)
{
  return wall(a, b, {lift(b, height), lift(a, height)});
}

// A horizontal face over a counterclockwise polygon: a roof faces up, a floor down.
inline Planar_face horizontal_face(std::vector<Point_2> polygon, double z, Surface_role role)
{
  if(role == FLOOR) std::reverse(polygon.begin(), polygon.end());
  std::vector<Point_3> vertices;
  for(const Point_2& p : polygon) vertices.push_back(lift(p, z));
  return {vertices, role};
}

// The footprint and its floor; `walls_of_height` adds walls of that height on every edge.
inline Building building_on(const std::vector<Point_2>& footprint, double walls_of_height = 0)
{
  Building building{footprint, {horizontal_face(footprint, 0, FLOOR)}};
  for(std::size_t i = 0; walls_of_height > 0 && i < footprint.size(); ++i)
    building.faces.push_back(wall_of_height(footprint[i], footprint[(i + 1) % footprint.size()], walls_of_height));
  return building;
}

inline double rise(double run, double slope_degrees) { return run * std::tan(slope_degrees * CGAL_PI / 180); }

// Rectangle length x width, ridge along the length; the gable walls are pentagons.
inline Building gable_roof_building(double length, double width, double eave, double slope_degrees)
{
  const Point_2 a(0, 0), b(length, 0), c(length, width), d(0, width);
  const double top = eave + rise(width / 2, slope_degrees);
  const Point_3 ridge_a(0, width / 2, top), ridge_b(length, width / 2, top);
  Building building = building_on({a, b, c, d});
  building.faces.push_back(wall_of_height(a, b, eave));
  building.faces.push_back(wall(b, c, {lift(c, eave), ridge_b, lift(b, eave)}));
  building.faces.push_back(wall_of_height(c, d, eave));
  building.faces.push_back(wall(d, a, {lift(a, eave), ridge_a, lift(d, eave)}));
  building.faces.push_back({{lift(a, eave), lift(b, eave), ridge_b, ridge_a}, ROOF});
  building.faces.push_back({{lift(c, eave), lift(d, eave), ridge_a, ridge_b}, ROOF});
  return building;
}

// Rectangle length x width (length > width), four roof faces of the same slope.
inline Building hip_roof_building(double length, double width, double eave, double slope_degrees)
{
  const Point_2 a(0, 0), b(length, 0), c(length, width), d(0, width);
  const double top = eave + rise(width / 2, slope_degrees);
  const Point_3 ridge_a(width / 2, width / 2, top), ridge_b(length - width / 2, width / 2, top);
  Building building = building_on({a, b, c, d}, eave);
  building.faces.push_back({{lift(a, eave), lift(b, eave), ridge_b, ridge_a}, ROOF});
  building.faces.push_back({{lift(b, eave), lift(c, eave), ridge_b}, ROOF});
  building.faces.push_back({{lift(c, eave), lift(d, eave), ridge_a, ridge_b}, ROOF});
  building.faces.push_back({{lift(d, eave), lift(a, eave), ridge_a}, ROOF});
  return building;
}

// An L: the rectangle length x width without its corner beyond (notch_x, notch_y).
inline Building l_shaped_building(double length, double width, double notch_x, double notch_y, double height)
{
  const std::vector<Point_2> footprint{{0, 0}, {length, 0}, {length, notch_y}, {notch_x, notch_y}, {notch_x, width}, {0, width}};
  Building building = building_on(footprint, height);
  building.faces.push_back(horizontal_face(footprint, height, ROOF));
  return building;
}

// A main block length x width x height and a lower annex on the middle of its north side;
// the north wall of the main block goes around the annex (one non-convex face).
inline Building two_height_building(double length, double width, double height, double annex_width,
                                    double annex_depth, double annex_height)
{
  const double x0 = (length - annex_width) / 2, x1 = x0 + annex_width, y1 = width + annex_depth;
  const Point_2 a(0, 0), b(length, 0), c(length, width), d(0, width);
  const Point_2 p(x1, width), q(x1, y1), r(x0, y1), s(x0, width); // the annex
  Building building = building_on({a, b, c, p, q, r, s, d});
  building.faces.push_back(wall_of_height(a, b, height));
  building.faces.push_back(wall_of_height(b, c, height));
  building.faces.push_back({{lift(c, 0), lift(p, 0), lift(p, annex_height), lift(s, annex_height), lift(s, 0),
                             lift(d, 0), lift(d, height), lift(c, height)}, WALL});
  building.faces.push_back(wall_of_height(p, q, annex_height));
  building.faces.push_back(wall_of_height(q, r, annex_height));
  building.faces.push_back(wall_of_height(r, s, annex_height));
  building.faces.push_back(wall_of_height(d, a, height));
  building.faces.push_back(horizontal_face({a, b, c, d}, height, ROOF));
  building.faces.push_back(horizontal_face({s, p, q, r}, annex_height, ROOF));
  return building;
}

// Rotates a building by `angle` (radians) about the center of its footprint's bounding box and
// moves that center to (x, y).
inline Building place(Building building, double angle, double x, double y)
{
  const Bbox_2 box = bbox_2(building.footprint.begin(), building.footprint.end());
  const Vector_3 center((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, 0);
  const double cosine = std::cos(angle), sine = std::sin(angle);
  const Kernel::Aff_transformation_3 move(cosine, -sine, 0, x, sine, cosine, 0, y, 0, 0, 1, 0);
  for(Point_2& p : building.footprint) {
    const Point_3 moved = move(lift(p, 0) - center);
    p = Point_2(moved.x(), moved.y());
  }
  for(Planar_face& face : building.faces)
    for(Point_3& p : face.vertices) p = move(p - center);
  return building;
}

// 53 random bits of the generator as a double in [0, 1).
inline double uniform(std::mt19937& random)
{
  const std::uint32_t high = random() >> 5, low = random() >> 6;
  return (double(high) * 67108864. + double(low)) / 9007199254740992.;
}

// Box-Muller transform (one of the pair).
inline double standard_normal(std::mt19937& random)
{
  const double u = 1 - uniform(random); // in (0, 1]
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * CGAL_PI * uniform(random));
}

// An orthonormal frame of the plane of a polygon; the normal from Newell's formula, so
// outward for a polygon counterclockwise seen from outside.
struct Plane_frame
{
  Point_3 origin;
  Vector_3 u, v, normal;
};

inline Vector_3 unit(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

inline Plane_frame plane_frame(const std::vector<Point_3>& polygon)
{
  double nx = 0, ny = 0, nz = 0;
  for(std::size_t i = 0; i < polygon.size(); ++i) {
    const Point_3 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    nx += (p.y() - q.y()) * (p.z() + q.z());
    ny += (p.z() - q.z()) * (p.x() + q.x());
    nz += (p.x() - q.x()) * (p.y() + q.y());
  }
  const Vector_3 normal = unit(Vector_3(nx, ny, nz));
  const Vector_3 axis = std::abs(normal.z()) < 0.9 ? Vector_3(0, 0, 1) : Vector_3(1, 0, 0);
  const Vector_3 u = unit(cross_product(axis, normal));
  return {polygon.front(), u, cross_product(normal, u), normal};
}

// Appends round(density * area) points drawn uniformly in a planar polygon minus `holes`
// (polygons of the plane z = 0 that the vertical projection of a point must avoid), each
// moved along the normal by Gaussian noise.
inline void sample_polygon(const std::vector<Point_3>& polygon, const std::vector<std::vector<Point_2>>& holes,
                           double density, int plane_index, double noise, std::mt19937& random,
                           std::vector<Sample>& samples)
{
  const Plane_frame frame = plane_frame(polygon);
  std::vector<Point_2> flat;
  for(const Point_3& p : polygon) flat.emplace_back((p - frame.origin) * frame.u, (p - frame.origin) * frame.v);
  double area = std::abs(polygon_area_2(flat.begin(), flat.end(), Kernel()));
  for(const std::vector<Point_2>& hole : holes) area -= std::abs(polygon_area_2(hole.begin(), hole.end(), Kernel()));
  const Bbox_2 box = bbox_2(flat.begin(), flat.end());
  const long count = std::lround(density * std::max(area, 0.));
  for(long k = 0; k < count;) {
    // two draws in the arguments of one call would be unsequenced (g++ makes the second
    // first, Clang the first): the ordinate is drawn first, as g++ did when the scenes were
    // tuned
    const double v = uniform(random), u = uniform(random);
    const Point_2 q(box.xmin() + u * (box.xmax() - box.xmin()), box.ymin() + v * (box.ymax() - box.ymin()));
    if(bounded_side_2(flat.begin(), flat.end(), q, Kernel()) != ON_BOUNDED_SIDE) continue;
    const Point_3 p = frame.origin + q.x() * frame.u + q.y() * frame.v;
    const Point_2 below(p.x(), p.y());
    if(std::any_of(holes.begin(), holes.end(), [&](const std::vector<Point_2>& hole) {
         return bounded_side_2(hole.begin(), hole.end(), below, Kernel()) != ON_UNBOUNDED_SIDE;
       }))
      continue;
    samples.push_back({p + noise * standard_normal(random) * frame.normal, frame.normal, plane_index});
    ++k;
  }
}

// The counterclockwise polygon whose edges are those of `polygon` moved outwards by `width`.
inline std::vector<Point_2> offset_polygon(const std::vector<Point_2>& polygon, double width)
{
  const std::size_t n = polygon.size();
  auto outward = [&](std::size_t i) {
    const Point_2 &p = polygon[i % n], &q = polygon[(i + 1) % n];
    const double dx = q.x() - p.x(), dy = q.y() - p.y(), length = std::hypot(dx, dy);
    return std::array<double, 2>{{dy / length, -dx / length}};
  };
  std::vector<Point_2> result;
  for(std::size_t i = 0; i < n; ++i) {
    const auto a = outward(i + n - 1), b = outward(i);
    const double scale = width / (1 + a[0] * b[0] + a[1] * b[1]);
    result.emplace_back(polygon[i].x() + scale * (a[0] + b[0]), polygon[i].y() + scale * (a[1] + b[1]));
  }
  return result;
}

inline std::vector<Point_3> ground_polygon(const Scene& scene)
{
  std::vector<Point_3> polygon;
  for(int i = 0; i < 4; ++i) polygon.push_back(lift(scene.ground.vertex(i), 0)); // counterclockwise
  return polygon;
}

// The polygon mesh of polygons whose equal points are one vertex (the faces of a building
// share their corners exactly).
inline Mesh mesh_of(const std::vector<std::vector<Point_3>>& polygons)
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> faces;
  std::map<Point_3, std::size_t> index;
  for(const std::vector<Point_3>& polygon : polygons) {
    faces.emplace_back();
    for(const Point_3& p : polygon) {
      const auto inserted = index.emplace(p, points.size());
      if(inserted.second) points.push_back(p);
      faces.back().push_back(inserted.first->second);
    }
  }
  Mesh mesh;
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
  return mesh;
}

} // namespace internal

/// A scene of the given kind, its plane indices assigned and its ground 8 m wider than the
/// buildings on every side. Footprints 8 x 10 to 24 x 20 m, buildings 8 to 12 m tall (eaves 4 to
/// 7 m, an annex 5 m), roof slopes 30 to 45 degrees, rotated 0.1 to 1.2 radians.
inline Scene make_scene(Scene_kind kind)
{
  using namespace internal;
  const Building gable = gable_roof_building(16, 10, 6, 35), hip = hip_roof_building(20, 12, 7, 30),
                 l_shaped = l_shaped_building(24, 18, 10, 8, 9), two_height = two_height_building(22, 12, 12, 10, 8, 5);
  Scene scene;
  switch(kind) {
  case Scene_kind::GABLE_ROOF: scene.name = "gable_roof", scene.buildings = {place(gable, 0.35, 0, 0)}; break;
  case Scene_kind::HIP_ROOF: scene.name = "hip_roof", scene.buildings = {place(hip, 0.35, 0, 0)}; break;
  case Scene_kind::L_SHAPED_FLAT_ROOF:
    scene.name = "l_shaped_flat_roof", scene.buildings = {place(l_shaped, 0.35, 0, 0)};
    break;
  case Scene_kind::TWO_HEIGHT_FLAT_ROOFS:
    scene.name = "two_height_flat_roofs", scene.buildings = {place(two_height, 0.35, 0, 0)};
    break;
  case Scene_kind::SEVERAL_BUILDINGS:
    scene.name = "several_buildings";
    scene.buildings = {place(gable, 0.35, 0, 0), place(hip, -0.2, 35, 0), place(l_shaped, 0.1, 72, 0),
                       place(two_height, 0.5, 16, 36), place(gable_roof_building(10, 8, 4, 45), 1.2, 52, 34)};
    break;
  }
  std::vector<Point_2> corners;
  for(Building& building : scene.buildings) {
    corners.insert(corners.end(), building.footprint.begin(), building.footprint.end());
    for(Planar_face& face : building.faces)
      face.plane_index = face.role == FLOOR ? -1 : scene.number_of_planes++;
  }
  const Bbox_2 box = bbox_2(corners.begin(), corners.end());
  const double margin = 8;
  scene.ground = Kernel::Iso_rectangle_2(Point_2(box.xmin() - margin, box.ymin() - margin),
                                         Point_2(box.xmax() + margin, box.ymax() + margin));
  return scene;
}

namespace internal {

// The eaves of the flat roofs of a building: each flat roof's outline and that outline moved
// outwards by `overhang`, at the roof's height.
struct Eave
{
  std::vector<Point_2> outline;
  std::vector<Point_3> outer;
  int plane_index;
};

inline std::vector<Eave> eaves(const Scene& scene, double overhang)
{
  std::vector<Eave> result;
  for(const Building& building : scene.buildings)
    for(const Planar_face& face : building.faces) {
      const double z = face.vertices.front().z();
      const bool flat = std::all_of(face.vertices.begin(), face.vertices.end(), [z](const Point_3& p) { return p.z() == z; });
      if(face.role != ROOF || !flat || !(overhang > 0)) continue;
      Eave eave{{}, {}, face.plane_index};
      for(const Point_3& p : face.vertices) eave.outline.emplace_back(p.x(), p.y());
      for(const Point_2& p : offset_polygon(eave.outline, overhang)) eave.outer.push_back(lift(p, z));
      result.push_back(eave);
    }
  return result;
}

} // namespace internal

/// Points of the ground (plane index 0, not under the buildings or their eaves), the roofs, the
/// eaves and the walls.
inline std::vector<Sample> sample_scene(const Scene& scene, const Sampling_options& options = {})
{
  std::mt19937 random(options.seed);
  std::vector<Sample> samples;
  const std::vector<internal::Eave> eaves = internal::eaves(scene, options.eave_overhang);
  // the ground is hidden by the footprints and the eaves (a footprint inside an eave that
  // hides it is left out, so that the area of the holes counts it once)
  std::vector<std::vector<Point_2>> hidden;
  for(const internal::Eave& eave : eaves) {
    hidden.emplace_back();
    for(const Point_3& p : eave.outer) hidden.back().emplace_back(p.x(), p.y());
  }
  for(const Building& building : scene.buildings)
    if(std::none_of(eaves.begin(), eaves.end(), [&](const internal::Eave& e) { return e.outline == building.footprint; }))
      hidden.push_back(building.footprint);
  internal::sample_polygon(internal::ground_polygon(scene), hidden, options.density, 0, options.noise, random, samples);
  for(const Building& building : scene.buildings)
    for(const Planar_face& face : building.faces)
      if(face.role != FLOOR)
        internal::sample_polygon(face.vertices, {}, options.density * (face.role == WALL ? options.wall_density_factor : 1),
                                 face.plane_index, options.noise, random, samples);
  for(const internal::Eave& eave : eaves)
    internal::sample_polygon(eave.outer, {eave.outline}, options.density, eave.plane_index, options.noise, random, samples);
  return samples;
}

/// The truth of one building: a closed, outward-oriented polygon mesh.
inline Mesh truth_mesh(const Building& building)
{
  std::vector<std::vector<Point_3>> polygons;
  for(const Planar_face& face : building.faces) polygons.push_back(face.vertices);
  return internal::mesh_of(polygons);
}

/// The faces of the given roles (a sum of `Surface_role`) of all the buildings, and the ground
/// rectangle if `GROUND` is one of them (it overlaps the floors); the default is the truth of
/// the scene, one closed surface per building.
inline Mesh scene_mesh(const Scene& scene, int roles = ROOF + WALL + FLOOR)
{
  std::vector<std::vector<Point_3>> polygons;
  for(const Building& building : scene.buildings)
    for(const Planar_face& face : building.faces)
      if(roles & face.role) polygons.push_back(face.vertices);
  if(roles & GROUND) polygons.push_back(internal::ground_polygon(scene));
  return internal::mesh_of(polygons);
}

/// The non-degenerate triangles of the faces of a polygon mesh (CGAL's triangulation of each
/// face on a copy; a fan for a face it could not triangulate).
inline std::vector<Triangle_3> triangles_of(Mesh mesh)
{
  Polygon_mesh_processing::triangulate_faces(mesh);
  std::vector<Triangle_3> triangles;
  for(Mesh::Face_index f : mesh.faces()) {
    std::vector<Point_3> corners;
    for(Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh)) corners.push_back(mesh.point(v));
    for(std::size_t i = 1; i + 1 < corners.size(); ++i) {
      const Triangle_3 triangle(corners[0], corners[i], corners[i + 1]);
      if(!triangle.is_degenerate()) triangles.push_back(triangle);
    }
  }
  return triangles;
}

/// Distances to the surface of a polygon mesh (an AABB tree on its triangles).
class Distance_to_mesh
{
public:
  explicit Distance_to_mesh(const Mesh& mesh) : triangles_(triangles_of(mesh)), tree_(triangles_.begin(), triangles_.end())
  {
    tree_.accelerate_distance_queries();
  }
  Distance_to_mesh(const Distance_to_mesh&) = delete; // the tree refers to the triangles
  Distance_to_mesh& operator=(const Distance_to_mesh&) = delete;

  /// infinity for a mesh without a non-degenerate face
  double operator()(const Point_3& p) const
  {
    return triangles_.empty() ? std::numeric_limits<double>::infinity() : std::sqrt(tree_.squared_distance(p));
  }
  const std::vector<Triangle_3>& triangles() const { return triangles_; }

private:
  using Primitive =
    Polygon_partition_simplification::internal::AABB_triangle_primitive_3<Kernel, std::vector<Triangle_3>::const_iterator>;
  std::vector<Triangle_3> triangles_;
  AABB_tree<Polygon_partition_simplification::internal::AABB_traits_3<Kernel, Primitive>> tree_;
};

struct Distance_statistics
{
  double rms = 0;
  double max = 0;
  std::size_t count = 0;
};

/// RMS and largest distance of points (read with `point_map`) to a surface.
template <class PointRange, class PointMap = Identity_property_map<Point_3>>
Distance_statistics distances(const PointRange& points, const Distance_to_mesh& surface, PointMap point_map = PointMap())
{
  Distance_statistics statistics;
  double sum_of_squares = 0;
  for(const auto& item : points) {
    const double d = surface(get(point_map, item));
    sum_of_squares += d * d;
    statistics.max = std::max(statistics.max, d);
    ++statistics.count;
  }
  if(statistics.count > 0) statistics.rms = std::sqrt(sum_of_squares / double(statistics.count));
  return statistics;
}

/// The corners of the triangles and, in expectation, `density` points per unit area drawn
/// uniformly on them.
inline std::vector<Point_3> sample_triangles(const std::vector<Triangle_3>& triangles, double density, unsigned seed = 1)
{
  std::mt19937 random(seed);
  std::vector<Point_3> samples;
  for(const Triangle_3& t : triangles) {
    samples.insert(samples.end(), {t[0], t[1], t[2]});
    const double expected = density * std::sqrt(t.squared_area());
    const long count = long(expected) + (internal::uniform(random) < expected - std::floor(expected) ? 1 : 0);
    for(long k = 0; k < count; ++k) {
      const double r = std::sqrt(internal::uniform(random)), s = internal::uniform(random);
      samples.push_back(t[0] + r * (1 - s) * (t[1] - t[0]) + r * s * (t[2] - t[0]));
    }
  }
  return samples;
}

struct Two_way_distances
{
  Distance_statistics truth_to_model; // samples of the truth to the model: is everything modeled?
  Distance_statistics model_to_truth; // samples of the model to the truth: is the model nothing more?
};

/// A model is within d of the truth both ways when both maxima are at most d (a sampled
/// Hausdorff distance; `density` samples per unit area on each surface, plus the corners).
inline Two_way_distances two_way_distances(const Mesh& model, const Mesh& truth, double density = 10, unsigned seed = 1)
{
  const Distance_to_mesh to_model(model), to_truth(truth);
  return {distances(sample_triangles(to_truth.triangles(), density, seed), to_model),
          distances(sample_triangles(to_model.triangles(), density, seed), to_truth)};
}

} // namespace test
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_TEST_SYNTHETIC_BUILDINGS_H
