// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A synthetic classified aerial-LiDAR city tile whose truth is known, for the tests and the
// benchmark of a city-scale LOD2 pipeline. Buildings stand on a grid of square lots, one lot
// each (two for a pair of terraced houses), and cycle through eight kinds: a gable roof, a hip
// roof, an L-shaped flat roof, a flat box, a stepped building (a lower annex), a flat-roofed
// ring around a courtyard, two terraced houses sharing one wall (a gable roof and a lower flat
// roof), and a building scanned without any wall point. Sizes, heights and rotations are drawn
// from the seed (footprints 8 to 25 m, shrunk horizontally when they do not fit in their lot;
// heights 4 to 15 m; every fifth lot axis-aligned, the others rotated by any angle). Trees
// stand between the buildings, at least 1.5 m from every footprint: the upper half of a rough
// ellipsoidal crown, as an airborne scanner sees it, and a few trunk points.
// The points carry ASPRS classes (2 ground, 6 building, trees `tree_class`), the index of the
// truth building they sample and the face of it. The ground is sampled everywhere but under the
// buildings (courtyards included, under the crowns too), the roofs at the given density per
// square meter of roof, the walls more sparsely (none on a wall or the part of a wall that a
// neighbour's wall covers), all with Gaussian noise along the normal (sample_polygon() of
// synthetic_buildings.h). The layout (buildings and trees) depends only on the seed and the
// spacing, not on the density, the noise or whether the trees are sampled.
// Writers: PLY (binary, x y z classification), LAS 1.2 (point format 1), GeoJSON footprints.

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_TEST_SYNTHETIC_CITY_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_TEST_SYNTHETIC_CITY_H

#include "synthetic_buildings.h"

#include <CGAL/Iso_rectangle_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace test {

/// ASPRS classes of the points of a city (the trees get `City_options::tree_class`).
inline constexpr int las_ground_class = 2;
inline constexpr int las_building_class = 6;

struct City_options
{
  std::size_t buildings = 12;       // number of truth buildings (a pair of terraced houses counts two)
  double density = 10;              // points per square meter on the roofs and the ground
  double wall_density_factor = 0.1; // wall density relative to it
  double noise = 0.03;              // standard deviation of the displacement along the normal (m)
  bool trees = true;                // sample the trees (they are planted, and take room, either way)
  int tree_class = 5;               // LAS high vegetation; 1 = unclassified
  unsigned seed = 1;
  double spacing = 30;              // distance between building lots (m)
};

struct City_sample
{
  Point_3 point;
  int classification;
  int building = -1; // index of the true building, -1 for the ground and the trees
  int face = -1;     // index in that building's faces of the face the point samples, -1 without building
};

/// The truth buildings, the points, the ground rectangle (z = 0) and the footprints. The
/// `footprint` of a `Building` is its outer boundary; the courtyard of a ring is one of its
/// `footprint_holes` (clockwise), its floor and roof are four trapezoids each, as a face of a
/// polygon mesh has no hole.
struct City
{
  std::vector<Building> buildings;
  std::vector<City_sample> samples;
  Kernel::Iso_rectangle_2 extent;
  std::vector<std::vector<Point_2>> footprints;                   // counterclockwise, one per truth building
  std::vector<std::vector<std::vector<Point_2>>> footprint_holes; // clockwise, one list per truth building
  std::vector<std::string> kinds; // "gable", "hip", "l_shaped", "flat", "stepped", "courtyard",
                                  // "terraced_gable", "terraced_flat", "no_walls_" + one of the first four
};

namespace internal {

inline double uniform_in(std::mt19937& random, double low, double high) { return low + (high - low) * uniform(random); }

// A truth building in the frame of its lot and what of it the scanner sees.
struct City_part
{
  City_part(Building building, std::vector<std::vector<Point_2>> holes, std::string kind)
      : building(std::move(building)), holes(std::move(holes)), kind(std::move(kind))
  {}

  Building building;
  std::vector<std::vector<Point_2>> holes; // clockwise
  std::string kind;
  bool has_wall_points = true;
  std::map<std::size_t, double> hidden_below; // faces covered by a neighbour's wall up to that height
};

inline Building flat_box_building(double length, double width, double height)
{
  const std::vector<Point_2> footprint{{0, 0}, {length, 0}, {length, width}, {0, width}};
  Building building = building_on(footprint, height);
  building.faces.push_back(horizontal_face(footprint, height, ROOF));
  return building;
}

// A flat-roofed ring: the rectangle length x width around a courtyard, its wings `wing` wide.
// Floor and roof are four trapezoids each; the walls of the courtyard face into it (they stand
// on its boundary followed clockwise).
inline City_part courtyard_building(double length, double width, double wing, double height)
{
  const std::vector<Point_2> outer{{0, 0}, {length, 0}, {length, width}, {0, width}};
  const std::vector<Point_2> inner{{wing, wing}, {length - wing, wing}, {length - wing, width - wing}, {wing, width - wing}};
  City_part part{{outer, {}}, {std::vector<Point_2>(inner.rbegin(), inner.rend())}, "courtyard"};
  for(std::size_t i = 0; i < 4; ++i) {
    const std::size_t j = (i + 1) % 4;
    const std::vector<Point_2> trapezoid{outer[i], outer[j], inner[j], inner[i]};
    part.building.faces.push_back(horizontal_face(trapezoid, 0, FLOOR));
    part.building.faces.push_back(horizontal_face(trapezoid, height, ROOF));
    part.building.faces.push_back(wall_of_height(outer[i], outer[j], height));
    part.building.faces.push_back(wall_of_height(inner[j], inner[i], height));
  }
  return part;
}

inline Building translated(Building building, double dx)
{
  for(Point_2& p : building.footprint) p = Point_2(p.x() + dx, p.y());
  for(Planar_face& face : building.faces)
    for(Point_3& p : face.vertices) p = Point_3(p.x() + dx, p.y(), p.z());
  return building;
}

// The index of the wall of a building standing on the line x = `x` (its vertices are exact).
inline std::size_t wall_on_line(const Building& building, double x)
{
  for(std::size_t f = 0; f < building.faces.size(); ++f)
    if(building.faces[f].role == WALL &&
       std::all_of(building.faces[f].vertices.begin(), building.faces[f].vertices.end(),
                   [x](const Point_3& p) { return p.x() == x; }))
      return f;
  CGAL_error_msg("no wall on that line");
  return 0;
}

// Two terraced houses in a row along x, of the same depth: a gable roof (ridge along the row)
// and, east of it, a lower flat roof. They share the wall x = length_a: the flat house's side of
// it is hidden, the gable end is seen above the flat roof only.
inline std::vector<City_part> terraced_houses(double length_a, double length_b, double width, double eave_a,
                                              double slope_a, double height_b)
{
  City_part a{gable_roof_building(length_a, width, eave_a, slope_a), {}, "terraced_gable"};
  City_part b{translated(flat_box_building(length_b, width, height_b), length_a), {}, "terraced_flat"};
  a.hidden_below[wall_on_line(a.building, length_a)] = height_b;
  b.hidden_below[wall_on_line(b.building, length_a)] = std::numeric_limits<double>::infinity();
  return {a, b};
}

// The part of a planar polygon at or above the height z (Sutherland-Hodgman); empty when nothing
// of it is strictly above.
inline std::vector<Point_3> clip_above(const std::vector<Point_3>& polygon, double z)
{
  double top = -std::numeric_limits<double>::infinity();
  for(const Point_3& p : polygon) top = (std::max)(top, p.z());
  if(!(top > z)) return {};
  std::vector<Point_3> result;
  for(std::size_t i = 0; i < polygon.size(); ++i) {
    const Point_3 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    if(p.z() >= z) result.push_back(p);
    if((p.z() < z) != (q.z() < z)) result.push_back(p + (z - p.z()) / (q.z() - p.z()) * (q - p));
  }
  result.erase(std::unique(result.begin(), result.end()), result.end()); // a vertex at z is met twice
  if(result.size() > 1 && result.front() == result.back()) result.pop_back();
  return result;
}

// The steepest slope (at most `slope`, degrees) that keeps a ridge half_width from the eave at
// most 15 m high.
inline double capped_slope(double slope, double eave, double half_width)
{
  return (std::min)(slope, std::atan((15 - eave) / half_width) * 180 / CGAL_PI);
}

enum class Lot_kind { GABLE, HIP, L_SHAPED, FLAT, STEPPED, COURTYARD, TERRACED, NO_WALLS };

// The buildings of a lot of that kind in the lot's frame, their sizes drawn from `random`;
// `cycle` (the number of earlier lots of that kind) chooses the roof of the building without walls.
inline std::vector<City_part> lot_parts(Lot_kind kind, std::size_t cycle, std::mt19937& random)
{
  // one draw a statement, in the order g++ made them when the city was tuned (the draws in the
  // arguments of one call are unsequenced: g++ makes the last one first, Clang the first)
  auto u = [&](double low, double high) { return uniform_in(random, low, high); };
  switch(kind) {
  case Lot_kind::GABLE: {
    const double length = u(10, 25), width = u(8, (std::min)(length, 16.)), eave = u(4, 8);
    return {{gable_roof_building(length, width, eave, capped_slope(u(25, 45), eave, width / 2)), {}, "gable"}};
  }
  case Lot_kind::HIP: {
    const double length = u(12, 25), width = u(8, (std::min)(length - 2, 16.)), eave = u(4, 9);
    return {{hip_roof_building(length, width, eave, capped_slope(u(20, 40), eave, width / 2)), {}, "hip"}};
  }
  case Lot_kind::L_SHAPED: {
    const double length = u(14, 25), width = u(12, 22);
    const double height = u(4, 15), notch_y = width * u(0.35, 0.6), notch_x = length * u(0.4, 0.65);
    return {{l_shaped_building(length, width, notch_x, notch_y, height), {}, "l_shaped"}};
  }
  case Lot_kind::FLAT: {
    const double length = u(8, 25);
    const double height = u(4, 15), width = u(8, (std::min)(length, 20.));
    return {{flat_box_building(length, width, height), {}, "flat"}};
  }
  case Lot_kind::STEPPED: {
    const double length = u(14, 25), width = u(9, 16), height = u(8, 15);
    const double annex_height = u(4, height - 3), annex_depth = u(4, 8), annex_width = length * u(0.3, 0.6);
    return {{two_height_building(length, width, height, annex_width, annex_depth, annex_height), {}, "stepped"}};
  }
  case Lot_kind::COURTYARD: {
    const double length = u(16, 22), width = u(16, 22);
    const double height = u(6, 15), wing = u(5, 6.5);
    return {courtyard_building(length, width, wing, height)};
  }
  case Lot_kind::TERRACED: {
    const double length_a = u(8, 12), length_b = u(8, 12), width = u(8, 12), eave = u(6, 9);
    const double height_b = u(4, eave - 1.5), slope = capped_slope(u(30, 45), eave, width / 2);
    return terraced_houses(length_a, length_b, width, eave, slope, height_b);
  }
  case Lot_kind::NO_WALLS: {
    std::vector<City_part> parts = lot_parts(Lot_kind(cycle % 4), cycle, random);
    parts.front().kind = "no_walls_" + parts.front().kind;
    parts.front().has_wall_points = false;
    return parts;
  }
  }
  return {};
}

// Shrinks the parts horizontally (when a footprint corner is farther than `radius` from the
// center of the bounding box of the footprints), rotates them by `angle` about that center and
// moves it to `target`. The same map for all parts keeps their common corners equal.
inline void place_parts(std::vector<City_part>& parts, double angle, double radius, const Point_2& target)
{
  std::vector<Point_2> corners;
  for(const City_part& part : parts) corners.insert(corners.end(), part.building.footprint.begin(), part.building.footprint.end());
  const Bbox_2 box = bbox_2(corners.begin(), corners.end());
  const Vector_3 center((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, 0);
  double farthest = 0;
  for(const Point_2& p : corners) farthest = (std::max)(farthest, std::hypot(p.x() - center.x(), p.y() - center.y()));
  const double scale = farthest > radius ? radius / farthest : 1;
  const double cosine = scale * std::cos(angle), sine = scale * std::sin(angle);
  const Kernel::Aff_transformation_3 move(cosine, -sine, 0, target.x(), sine, cosine, 0, target.y(), 0, 0, 1, 0);
  auto move_2 = [&](Point_2& p) {
    const Point_3 moved = move(lift(p, 0) - center);
    p = Point_2(moved.x(), moved.y());
  };
  for(City_part& part : parts) {
    std::for_each(part.building.footprint.begin(), part.building.footprint.end(), move_2);
    for(std::vector<Point_2>& hole : part.holes) std::for_each(hole.begin(), hole.end(), move_2);
    for(Planar_face& face : part.building.faces)
      for(Point_3& p : face.vertices) p = move(p - center);
  }
}

// The horizontal distance of a point to a polygon, 0 inside it.
inline double distance_to_polygon(const Point_2& p, const std::vector<Point_2>& polygon)
{
  if(bounded_side_2(polygon.begin(), polygon.end(), p, Kernel()) != ON_UNBOUNDED_SIDE) return 0;
  double squared = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < polygon.size(); ++i)
    squared = (std::min)(squared, CGAL::squared_distance(p, Kernel::Segment_2(polygon[i], polygon[(i + 1) % polygon.size()])));
  return std::sqrt(squared);
}

inline double distance_to_footprints(const Point_2& p, const std::vector<City_part>& parts)
{
  double distance = std::numeric_limits<double>::infinity();
  for(const City_part& part : parts) distance = (std::min)(distance, distance_to_polygon(p, part.building.footprint));
  return distance;
}

// A crown: an ellipsoid of horizontal radius `radius` and vertical radius `height_radius` about
// (center, center_z).
struct Tree
{
  Point_2 center;
  double radius, height_radius, center_z;
};

// One to three trees in the lot, their crowns inside it, 2 m or more from the footprints and
// apart from each other (fewer when no room is found in 40 draws).
inline std::vector<Tree> plant_trees(const Kernel::Iso_rectangle_2& lot, const std::vector<City_part>& parts,
                                     std::mt19937& random)
{
  std::vector<Tree> trees;
  const std::size_t wanted = 1 + std::size_t(uniform(random) * 3);
  for(int draw = 0; draw < 40 && trees.size() < wanted; ++draw) {
    const double radius = uniform_in(random, 2, 4), height_radius = radius * uniform_in(random, 0.7, 1.2);
    const double center_z = (std::max)(uniform_in(random, 4, 10), height_radius + 2);
    const double y = uniform_in(random, lot.ymin() + radius + 0.5, lot.ymax() - radius - 0.5); // (g++'s order)
    const Point_2 center(uniform_in(random, lot.xmin() + radius + 0.5, lot.xmax() - radius - 0.5), y);
    if(distance_to_footprints(center, parts) < radius + 2) continue;
    if(std::any_of(trees.begin(), trees.end(), [&](const Tree& tree) {
         return std::sqrt(squared_distance(center, tree.center)) < radius + tree.radius;
       }))
      continue;
    trees.push_back({center, radius, height_radius, center_z});
  }
  return trees;
}

// The upper half of the crown seen from above (`density` points per square meter of its
// horizontal disk), rough (Gaussian displacement along the normal of 5% of the radius plus
// `noise`), and three to six trunk points under it.
inline std::vector<Point_3> sample_tree(const Tree& tree, double density, double noise, std::mt19937& random)
{
  std::vector<Point_3> points;
  const double r = tree.radius, rz = tree.height_radius, roughness = noise + 0.05 * r;
  const long count = std::lround(density * CGAL_PI * r * r);
  for(long k = 0; k < count;) {
    const double dx = uniform_in(random, -r, r), dy = uniform_in(random, -r, r), d2 = (dx * dx + dy * dy) / (r * r);
    if(d2 >= 1) continue;
    const double dz = rz * std::sqrt(1 - d2);
    const Vector_3 normal = unit(Vector_3(dx / (r * r), dy / (r * r), dz / (rz * rz)));
    const Point_3 p(tree.center.x() + dx, tree.center.y() + dy, tree.center_z + dz);
    points.push_back(p + roughness * standard_normal(random) * normal);
    ++k;
  }
  const int trunk = 3 + int(uniform(random) * 4);
  for(int k = 0; k < trunk; ++k) {
    const double x = tree.center.x() + 0.1 * standard_normal(random), y = tree.center.y() + 0.1 * standard_normal(random);
    points.emplace_back(x, y, uniform_in(random, 0.5, tree.center_z - rz));
  }
  return points;
}

// The roofs and walls of a building: no wall point for a building without, none on the hidden
// part of a wall.
inline void sample_part(const City_part& part, int index, const City_options& options, std::mt19937& random,
                        std::vector<City_sample>& out)
{
  std::vector<Sample> samples;
  const std::vector<Planar_face>& faces = part.building.faces;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    if(faces[f].role == FLOOR) continue;
    double density = options.density;
    std::vector<Point_3> polygon = faces[f].vertices;
    if(faces[f].role == WALL) {
      density *= part.has_wall_points ? options.wall_density_factor : 0;
      const auto hidden = part.hidden_below.find(f);
      if(hidden != part.hidden_below.end()) polygon = clip_above(polygon, hidden->second);
    }
    if(polygon.size() >= 3 && density > 0)
      sample_polygon(polygon, {}, density, int(f), options.noise, random, samples);
  }
  for(const Sample& s : samples) out.push_back({s.point, las_building_class, index, s.plane_index});
}

// The points of a lot: its ground but under the buildings (the courtyards are ground), the
// buildings (numbered from `first_index`), the trees when asked, each tree point inside the lot
// and 1.5 m or more from its footprints (the buildings of the other lots are farther).
inline void sample_lot(const Kernel::Iso_rectangle_2& lot, const std::vector<City_part>& parts, const std::vector<Tree>& trees,
                       int first_index, const City_options& options, std::mt19937& random, std::vector<City_sample>& out)
{
  std::vector<Sample> ground;
  std::vector<Point_3> square;
  for(int i = 0; i < 4; ++i) square.push_back(lift(lot.vertex(i), 0));
  std::vector<std::vector<Point_2>> footprints;
  for(const City_part& part : parts) footprints.push_back(part.building.footprint);
  sample_polygon(square, footprints, options.density, -1, options.noise, random, ground);
  for(const City_part& part : parts)
    for(const std::vector<Point_2>& hole : part.holes) {
      std::vector<Point_3> courtyard;
      for(auto p = hole.rbegin(); p != hole.rend(); ++p) courtyard.push_back(lift(*p, 0));
      sample_polygon(courtyard, {}, options.density, -1, options.noise, random, ground);
    }
  for(const Sample& s : ground) out.push_back({s.point, las_ground_class});
  for(std::size_t i = 0; i < parts.size(); ++i) sample_part(parts[i], first_index + int(i), options, random, out);
  for(const Tree& tree : trees) {
    if(!options.trees) break;
    for(const Point_3& p : sample_tree(tree, options.density, options.noise, random)) {
      const Point_2 below(p.x(), p.y());
      if(lot.has_on_bounded_side(below) && distance_to_footprints(below, parts) >= 1.5)
        out.push_back({p, options.tree_class});
    }
  }
}

// The kinds of the lots: the cycle of eight, a pair of terraced houses replaced by a building
// without walls when a single building is left to make.
inline std::vector<Lot_kind> lot_kinds(std::size_t buildings)
{
  std::vector<Lot_kind> kinds;
  for(std::size_t lot = 0, count = 0; count < buildings; ++lot) {
    Lot_kind kind = Lot_kind(lot % 8);
    if(kind == Lot_kind::TERRACED && count + 2 > buildings) kind = Lot_kind::NO_WALLS;
    kinds.push_back(kind);
    count += kind == Lot_kind::TERRACED ? 2 : 1;
  }
  return kinds;
}

} // namespace internal

/// Readable property maps of the position and the class of a `City_sample`.
struct City_point_map
{
  using key_type = City_sample; using value_type = Point_3; using reference = const Point_3&;
  using category = boost::readable_property_map_tag;
  friend reference get(City_point_map, const City_sample& s) { return s.point; }
};
struct City_class_map
{
  using key_type = City_sample; using value_type = int; using reference = int;
  using category = boost::readable_property_map_tag;
  friend int get(City_class_map, const City_sample& s) { return s.classification; }
};

/// A city of `options.buildings` truth buildings on a grid of square lots `options.spacing` wide
/// (as many columns as rows, or one fewer row; the last lots of the last row hold ground and
/// trees only), the first lot at the origin; each building (or pair) within spacing / 2 - 2.2 m
/// of the center of its lot. Deterministic: the same options
/// give the same city (the variates come from std::mt19937, whose output the standard fixes,
/// not from the library's distributions). \pre `options.spacing >= 12`
inline City make_city(const City_options& options = {})
{
  using namespace internal;
  CGAL_precondition(options.spacing >= 12);
  const std::vector<Lot_kind> kinds = lot_kinds(options.buildings);
  const std::size_t columns = std::size_t(std::ceil(std::sqrt(double(kinds.size()))));
  const std::size_t rows = columns == 0 ? 0 : (kinds.size() + columns - 1) / columns;
  const double s = options.spacing;
  std::mt19937 layout(options.seed), sampling(options.seed ^ 0x5bd1e995u);
  City city;
  city.extent = Kernel::Iso_rectangle_2(Point_2(0, 0), Point_2(double(columns) * s, double(rows) * s));
  for(std::size_t lot = 0; lot < columns * rows; ++lot) { // the last lots of the last row may stay empty
    const double x0 = double(lot % columns) * s, y0 = double(lot / columns) * s;
    const Kernel::Iso_rectangle_2 square(Point_2(x0, y0), Point_2(x0 + s, y0 + s));
    if(lot >= kinds.size()) {
      const std::vector<Tree> trees = plant_trees(square, {}, layout);
      sample_lot(square, {}, trees, 0, options, sampling, city.samples);
      continue;
    }
    std::vector<City_part> parts = lot_parts(kinds[lot], lot / 8, layout);
    const double angle = lot % 5 == 3 ? 0 : uniform_in(layout, 0, CGAL_PI);
    const double dy = uniform_in(layout, -0.5, 0.5), dx = uniform_in(layout, -0.5, 0.5); // (g++'s order)
    const Point_2 target(x0 + s / 2 + dx, y0 + s / 2 + dy);
    place_parts(parts, angle, s / 2 - 3, target);
    const std::vector<Tree> trees = plant_trees(square, parts, layout);
    sample_lot(square, parts, trees, int(city.buildings.size()), options, sampling, city.samples);
    for(City_part& part : parts) {
      city.footprints.push_back(part.building.footprint);
      city.footprint_holes.push_back(part.holes);
      city.kinds.push_back(part.kind);
      city.buildings.push_back(std::move(part.building));
    }
  }
  return city;
}

/// The true footprints of a city as polygons with holes, in the order of its buildings.
inline std::vector<Polygon_with_holes_2<Kernel>> footprint_polygons(const City& city)
{
  std::vector<Polygon_with_holes_2<Kernel>> footprints;
  for(std::size_t b = 0; b < city.footprints.size(); ++b) {
    footprints.emplace_back(Polygon_2<Kernel>(city.footprints[b].begin(), city.footprints[b].end()));
    for(const auto& hole : city.footprint_holes[b]) footprints.back().add_hole(Polygon_2<Kernel>(hole.begin(), hole.end()));
  }
  return footprints;
}


namespace internal {

template <class T>
void write_little_endian(std::ostream& out, T value)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  std::reverse(bytes, bytes + sizeof(T));
#endif
  out.write(reinterpret_cast<const char*>(bytes), sizeof(T));
}

inline std::ofstream open_for_writing(const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  if(!out) throw std::runtime_error("cannot open '" + path + "' for writing");
  return out;
}

inline void close_written(std::ofstream& out, const std::string& path)
{
  out.close();
  if(!out) throw std::runtime_error("cannot write '" + path + "'");
}

} // namespace internal

/// The points as a binary little-endian PLY file: `double` (float64) x y z and `uchar classification`.
inline void write_city_ply(const City& city, const std::string& path)
{
  std::ofstream out = internal::open_for_writing(path);
  out << "ply\nformat binary_little_endian 1.0\ncomment synthetic classified aerial LiDAR city\n"
      << "element vertex " << city.samples.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "property uchar classification\nend_header\n";
  for(const City_sample& s : city.samples) {
    internal::write_little_endian(out, s.point.x());
    internal::write_little_endian(out, s.point.y());
    internal::write_little_endian(out, s.point.z());
    internal::write_little_endian(out, std::uint8_t(s.classification));
  }
  internal::close_written(out, path);
}

/// The points as LAS 1.2, point data record format 1 (28 bytes: GPS time 0, intensity 0, each
/// point the single return of its pulse), scale 0.001 m, offsets at the minimum corner of the
/// points; the bounds of the header are those of the stored (rounded) coordinates.
inline void write_city_las(const City& city, const std::string& path)
{
  const double scale = 0.001;
  std::array<double, 3> offset{{0, 0, 0}};
  if(!city.samples.empty())
    for(int c = 0; c < 3; ++c)
      offset[c] = std::min_element(city.samples.begin(), city.samples.end(), [c](const City_sample& a, const City_sample& b) {
                    return a.point[c] < b.point[c];
                  })->point[c];
  std::vector<std::array<std::int32_t, 3>> records;
  std::array<double, 3> low{{0, 0, 0}}, high{{0, 0, 0}};
  for(const City_sample& s : city.samples) {
    std::array<std::int32_t, 3> record;
    for(int c = 0; c < 3; ++c) {
      const double steps = std::round((s.point[c] - offset[c]) / scale);
      if(!(steps >= 0 && steps <= 2147483647.)) throw std::runtime_error("'" + path + "': the city is too large for LAS at 1 mm");
      record[c] = std::int32_t(steps);
      const double stored = record[c] * scale + offset[c]; // as a LAS reader computes it
      low[c] = records.empty() ? stored : (std::min)(low[c], stored);
      high[c] = records.empty() ? stored : (std::max)(high[c], stored);
    }
    records.push_back(record);
  }
  std::ofstream out = internal::open_for_writing(path);
  using internal::write_little_endian;
  char text[64] = "LASF";
  out.write(text, 4);
  for(int i = 0; i < 10; ++i) write_little_endian(out, std::uint16_t(0)); // source id, encoding, GUID
  write_little_endian(out, std::uint8_t(1));                                 // version 1.2
  write_little_endian(out, std::uint8_t(2));
  std::memset(text, 0, sizeof(text));
  std::strcpy(text, "synthetic city");
  std::strcpy(text + 32, "synthetic_city.h");
  out.write(text, 64);                          // system identifier, generating software
  write_little_endian(out, std::uint16_t(0));   // creation day (unknown: the file depends on the city only)
  write_little_endian(out, std::uint16_t(0));   // creation year
  write_little_endian(out, std::uint16_t(227)); // header size
  write_little_endian(out, std::uint32_t(227)); // offset to the points
  write_little_endian(out, std::uint32_t(0));   // no variable length record
  write_little_endian(out, std::uint8_t(1));    // point data record format 1
  write_little_endian(out, std::uint16_t(28));
  write_little_endian(out, std::uint32_t(records.size()));
  for(int r = 0; r < 5; ++r) write_little_endian(out, std::uint32_t(r == 0 ? records.size() : 0)); // by return
  for(int c = 0; c < 3; ++c) write_little_endian(out, scale);
  for(int c = 0; c < 3; ++c) write_little_endian(out, offset[c]);
  for(int c = 0; c < 3; ++c) {
    write_little_endian(out, high[c]);
    write_little_endian(out, low[c]);
  }
  for(std::size_t i = 0; i < records.size(); ++i) {
    for(int c = 0; c < 3; ++c) write_little_endian(out, records[i][c]);
    write_little_endian(out, std::uint16_t(0));                                 // intensity
    write_little_endian(out, std::uint8_t(1 | 1 << 3));                         // return 1 of 1
    write_little_endian(out, std::uint8_t(city.samples[i].classification & 0x1F));
    write_little_endian(out, std::int8_t(0));                                   // scan angle rank
    write_little_endian(out, std::uint8_t(0));                                  // user data
    write_little_endian(out, std::uint16_t(0));                                 // point source id
    write_little_endian(out, 0.0);                                              // GPS time
  }
  internal::close_written(out, path);
}

/// The footprints as a GeoJSON FeatureCollection (RFC 7946) of Polygons, one feature per truth
/// building with the properties "id" (its index) and "kind"; the outer ring counterclockwise,
/// the holes (courtyards) clockwise, each ring closed, coordinates with full double precision.
inline void write_footprints_geojson(const City& city, const std::string& path)
{
  std::ofstream out = internal::open_for_writing(path);
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  auto ring = [&](const std::vector<Point_2>& polygon) {
    out << '[';
    for(std::size_t i = 0; i <= polygon.size(); ++i) {
      const Point_2& p = polygon[i % polygon.size()];
      out << (i == 0 ? "" : ", ") << '[' << p.x() << ", " << p.y() << ']';
    }
    out << ']';
  };
  out << "{\"type\": \"FeatureCollection\", \"features\": [";
  for(std::size_t b = 0; b < city.footprints.size(); ++b) {
    out << (b == 0 ? "\n" : ",\n") << "{\"type\": \"Feature\", \"properties\": {\"id\": " << b << ", \"kind\": \""
        << city.kinds[b] << "\"}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [";
    ring(city.footprints[b]);
    for(const std::vector<Point_2>& hole : city.footprint_holes[b]) out << ", ", ring(hole);
    out << "]}}";
  }
  out << "\n]}\n";
  internal::close_written(out, path);
}

} // namespace test
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_TEST_SYNTHETIC_CITY_H
