// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Random scenes that stress the kinetic partition, and an oracle that no one here wrote for
// its result. Used by test_kinetic_partition_stress and by benchmark_kinetic_partition_stress.
//
// Scenes (each deterministic for a generator and a seed; read_segments() reads others):
//   grid        3 to 40 segments with endpoints on small integer grids (2 to 10 wide)
//   collinear   families of segments on nearly one line (ends moved off it by 1e-15 to 1e-6
//               of the scene), across grid segments
//   concurrent  rays from points within 1e-12 to 1e-7 of each other, 5 to 20 degrees apart
//   star        3 to 80 segments from radius 0.1 to 1 around a point
//   duplicates  grid scenes with segments given again (either way round) and collinear
//               segments that overlap them, contain them or extend them
//   tiny        grid scenes with segments a few units in the last place long
//   offset      grid scenes scaled down to millimetres at offsets of 1e7, and segments that
//               start within 2e-9 of each other there
//   large       100 to 10,000 short random segments, some of them on a lattice
//
// Oracle: the output edges, with the coordinates the user gets (`point()`), are inserted in
// CGAL's Arrangement_2 with exact constructions (Epeck); the partition is valid when the
// arrangement has exactly its points and edges (no crossing, overlap, point inside an edge or
// points that coincide), every edge has two different faces on its sides, and no boundary of
// a bounded face passes twice through a vertex. Coverage: every input segment is covered by
// edges, up to a tolerance (the segments collinear up to rounding are moved onto one line).

#ifndef POLYGON_PARTITION_SIMPLIFICATION_KINETIC_STRESS_SCENES_H
#define POLYGON_PARTITION_SIMPLIFICATION_KINETIC_STRESS_SCENES_H

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/kinetic_partition_2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace kinetic_stress {

using Segment = std::array<double, 4>;

enum class Generator { grid, collinear, concurrent, star, duplicates, tiny, offset, large };
constexpr Generator all_generators[] = {Generator::grid,       Generator::collinear, Generator::concurrent,
                                        Generator::star,       Generator::duplicates, Generator::tiny,
                                        Generator::offset,     Generator::large};

inline const char* name(Generator g)
{
  switch(g) {
  case Generator::grid: return "grid";
  case Generator::collinear: return "collinear";
  case Generator::concurrent: return "concurrent";
  case Generator::star: return "star";
  case Generator::duplicates: return "duplicates";
  case Generator::tiny: return "tiny";
  case Generator::offset: return "offset";
  default: return "large";
  }
}

// n segments with integer endpoints in [0, g]^2, no zero-length one, no two equal
inline std::vector<Segment> grid_segments(std::mt19937_64& rng, std::size_t n, int g)
{
  std::uniform_int_distribution<int> c(0, g);
  std::set<Segment> seen;
  std::vector<Segment> s;
  for(int attempts = 0; s.size() < n && attempts < 1000; ++attempts) {
    Segment x{double(c(rng)), double(c(rng)), double(c(rng)), double(c(rng))};
    if(x[0] == x[2] && x[1] == x[3]) continue;
    const Segment key = std::make_pair(x[0], x[1]) < std::make_pair(x[2], x[3]) ? x : Segment{x[2], x[3], x[0], x[1]};
    if(!seen.insert(key).second) continue;
    s.push_back(x);
  }
  return s;
}

inline std::vector<Segment> collinear_scene(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(0, 1), angle(0, 3.14159265358979323846);
  std::vector<Segment> s = grid_segments(rng, 2 + rng() % 6, 4);
  for(auto& x : s)
    for(double& c : x) c /= 4;
  const int families = 1 + int(rng() % 3);
  for(int f = 0; f < families; ++f) {
    const double a = angle(rng), ox = u(rng), oy = u(rng), dx = std::cos(a), dy = std::sin(a);
    const double off = std::pow(10., -15 + 9 * u(rng)); // 1e-15 to 1e-6
    const int pieces = 2 + int(rng() % 5);
    for(int k = 0; k < pieces; ++k) {
      const double t0 = -0.7 + 1.4 * u(rng), t1 = t0 + 0.05 + 0.6 * u(rng);
      auto jitter = [&] { return off * (2 * u(rng) - 1); };
      s.push_back({ox + t0 * dx + jitter(), oy + t0 * dy + jitter(), ox + t1 * dx + jitter(), oy + t1 * dy + jitter()});
    }
  }
  return s;
}

inline std::vector<Segment> concurrent_scene(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Segment> s = grid_segments(rng, 1 + rng() % 4, 3);
  for(auto& x : s)
    for(double& c : x) c = c / 3 - 0.5;
  const double cx = u(rng) - 0.5, cy = u(rng) - 0.5, spread = std::pow(10., -12 + 5 * u(rng));
  const int rays = 2 + int(rng() % 6);
  double a = 6.283185307179586 * u(rng);
  for(int k = 0; k < rays; ++k) {
    a += (5 + 15 * u(rng)) * 3.14159265358979323846 / 180;
    const double x = cx + spread * (2 * u(rng) - 1), y = cy + spread * (2 * u(rng) - 1), l = 0.2 + 0.8 * u(rng);
    s.push_back({x, y, x + l * std::cos(a), y + l * std::sin(a)});
  }
  return s;
}

inline std::vector<Segment> star_scene(std::mt19937_64& rng, std::size_t n)
{
  std::uniform_real_distribution<double> u(0, 1);
  const double cx = (rng() % 2) ? 0 : 100 * u(rng), cy = (rng() % 2) ? 0 : 100 * u(rng);
  const bool regular = rng() % 2;
  std::vector<Segment> s;
  for(std::size_t k = 0; k < n; ++k) {
    const double a = regular ? 6.283185307179586 * double(k) / double(n) : 6.283185307179586 * u(rng);
    s.push_back({cx + 0.1 * std::cos(a), cy + 0.1 * std::sin(a), cx + std::cos(a), cy + std::sin(a)});
  }
  return s;
}

inline std::vector<Segment> duplicates_scene(std::mt19937_64& rng)
{
  std::vector<Segment> s = grid_segments(rng, 3 + rng() % 10, 2 + int(rng() % 5));
  const std::size_t n = s.size();
  const int extra = 1 + int(rng() % 4);
  for(int k = 0; k < extra; ++k) {
    const Segment x = s[rng() % n];
    switch(rng() % 4) {
    case 0: s.push_back(x); break;                                                   // the same
    case 1: s.push_back({x[2], x[3], x[0], x[1]}); break;                            // reversed
    case 2: s.push_back({x[0], x[1], 2 * x[2] - x[0], 2 * x[3] - x[1]}); break;      // extends it
    default: s.push_back({(x[0] + x[2]) / 2, (x[1] + x[3]) / 2, x[2], x[3]}); break; // inside it
    }
  }
  std::shuffle(s.begin(), s.end(), rng);
  return s;
}

inline std::vector<Segment> tiny_scene(std::mt19937_64& rng)
{
  std::vector<Segment> s = grid_segments(rng, 3 + rng() % 8, 3);
  const int tiny = 1 + int(rng() % 3);
  for(int k = 0; k < tiny; ++k) {
    const double x = double(1 + rng() % 3) + (rng() % 2 ? 0.5 : 0), y = double(1 + rng() % 3) + (rng() % 2 ? 0.25 : 0);
    double ex = x, ey = y;
    for(int u = 1 + int(rng() % 4); u > 0; --u) ex = std::nextafter(ex, 1e9);
    if(rng() % 2)
      for(int u = int(rng() % 4); u > 0; --u) ey = std::nextafter(ey, 1e9);
    s.push_back({x, y, ex, ey});
  }
  return s;
}

inline std::vector<Segment> offset_scene(std::mt19937_64& rng)
{
  std::vector<Segment> s = grid_segments(rng, 3 + rng() % 8, 4);
  const double scale = std::pow(10., -3 + 3 * std::uniform_real_distribution<double>(0, 1)(rng));
  const double ox = 1e7 + double(rng() % 1000), oy = 1e7 - double(rng() % 1000);
  for(auto& x : s) x = {ox + scale * x[0], oy + scale * x[1], ox + scale * x[2], oy + scale * x[3]};
  if(rng() % 2) { // segments starting within 2e-9 of each other
    const double x = ox + scale, y = oy + scale;
    s.push_back({x, y, x + scale, y + 0.3 * scale});
    s.push_back({std::nextafter(x, 1e9), y, x + 0.2 * scale, y + scale});
  }
  return s;
}

inline std::vector<Segment> large_scene(std::mt19937_64& rng, std::size_t n)
{
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Segment> s;
  const double length = 3 / std::sqrt(double(n));
  while(s.size() < n) {
    if(rng() % 4 == 0) { // on a lattice: collinear pieces, equal arrival times
      const int m = int(std::sqrt(double(n))) + 1;
      const double x = double(rng() % m) / m, y = double(rng() % m) / m;
      s.push_back(rng() % 2 ? Segment{x, y, x + 1. / m, y} : Segment{x, y, x, y + 1. / m});
    } else {
      const double x = u(rng), y = u(rng), a = 6.283185307179586 * u(rng), l = length * (0.2 + u(rng));
      s.push_back({x, y, x + l * std::cos(a), y + l * std::sin(a)});
    }
  }
  std::set<Segment> seen;
  s.erase(std::remove_if(s.begin(), s.end(), [&](const Segment& x) { return !seen.insert(x).second; }), s.end());
  return s;
}

// The scene of generator g for a seed; `maximum_size` bounds the size of large scenes.
inline std::vector<Segment> scene(Generator g, unsigned long long seed, std::size_t maximum_size = 10000)
{
  std::mt19937_64 rng(seed * 8 + static_cast<unsigned long long>(g) + 1);
  switch(g) {
  case Generator::grid: {
    const std::size_t n = 3 + rng() % (rng() % 4 == 0 ? 38 : 14);
    const int sizes[] = {2, 3, 4, 6, 10};
    return grid_segments(rng, n, sizes[rng() % 5]);
  }
  case Generator::collinear: return collinear_scene(rng);
  case Generator::concurrent: return concurrent_scene(rng);
  case Generator::star: return star_scene(rng, 3 + rng() % 78);
  case Generator::duplicates: return duplicates_scene(rng);
  case Generator::tiny: return tiny_scene(rng);
  case Generator::offset: return offset_scene(rng);
  default: {
    // sizes 100 to maximum_size, log-uniform
    const double e = std::uniform_real_distribution<double>(2, std::log10(double(std::max<std::size_t>(maximum_size, 100))))(rng);
    return large_scene(rng, std::size_t(std::pow(10., e)));
  }
  }
}

// What the oracle says of the points (x, y) and edges (pairs of point indices) of a partition:
// an empty string when they form a valid partition, otherwise what is wrong.
inline std::string oracle_defect(const std::vector<std::array<double, 2>>& points,
                                 const std::vector<std::array<std::size_t, 2>>& edges)
{
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  using Arrangement = CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>>;
  for(const auto& p : points)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1])) return "a point is not finite";
  {
    std::vector<std::array<double, 2>> sorted = points;
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return "two points coincide";
  }
  std::vector<EK::Segment_2> segments;
  for(const auto& e : edges) {
    const auto& a = points[e[0]];
    const auto& b = points[e[1]];
    segments.emplace_back(EK::Point_2(a[0], a[1]), EK::Point_2(b[0], b[1]));
  }
  Arrangement arrangement;
  CGAL::insert(arrangement, segments.begin(), segments.end());
  if(arrangement.number_of_edges() != edges.size() || arrangement.number_of_vertices() != points.size())
    return "edges cross, overlap or pass through a point (" + std::to_string(arrangement.number_of_edges()) +
           " arrangement edges for " + std::to_string(edges.size()) + ", " +
           std::to_string(arrangement.number_of_vertices()) + " vertices for " + std::to_string(points.size()) + ")";
  for(auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e)
    if(e->face() == e->twin()->face()) return "an edge has the same face on both sides";
  auto simple = [](auto ccb) {
    std::set<Arrangement::Vertex_const_handle> seen;
    auto h = ccb;
    do
      if(!seen.insert(h->target()).second) return false;
    while(++h != ccb);
    return true;
  };
  for(auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    if(f->is_unbounded()) continue;
    if(!simple(f->outer_ccb())) return "the boundary of a cell passes twice through a point";
    for(auto h = f->holes_begin(); h != f->holes_end(); ++h)
      if(!simple(*h)) return "the boundary of a hole of a cell passes twice through a point";
  }
  return {};
}

// The parts of the input segments not covered by the edges (each from points[e[0]] to
// points[e[1]]): the parts of edges beside a segment that are within `tolerance` of its line,
// projected on it, cover it up to gaps of at most `tolerance`; the larger gaps are returned
// (input index, piece).
inline std::vector<std::pair<std::size_t, Segment>>
uncovered_parts(const std::vector<Segment>& input, const std::vector<std::array<double, 2>>& points,
                const std::vector<std::array<std::size_t, 2>>& edges, double tolerance)
{
  // the edges in a grid of cells, by their bounding boxes
  double low[2] = {HUGE_VAL, HUGE_VAL}, high[2] = {-HUGE_VAL, -HUGE_VAL};
  for(const auto& p : points)
    for(int c = 0; c < 2; ++c) { low[c] = std::min(low[c], p[c]); high[c] = std::max(high[c], p[c]); }
  const int cells = std::max(1, int(std::sqrt(double(edges.size()))));
  const double size = std::max(high[0] - low[0], high[1] - low[1]) / cells * (1 + 1e-12) + 1e-300;
  auto cell = [&](double v, int c) { return std::clamp(int((v - low[c]) / size), 0, cells - 1); };
  std::vector<std::vector<std::size_t>> grid(std::size_t(cells) * cells);
  for(std::size_t e = 0; e < edges.size(); ++e) {
    const auto& a = points[edges[e][0]];
    const auto& b = points[edges[e][1]];
    for(int i = cell(std::min(a[0], b[0]) - tolerance, 0); i <= cell(std::max(a[0], b[0]) + tolerance, 0); ++i)
      for(int j = cell(std::min(a[1], b[1]) - tolerance, 1); j <= cell(std::max(a[1], b[1]) + tolerance, 1); ++j)
        grid[std::size_t(i) * cells + j].push_back(e);
  }
  std::vector<std::pair<std::size_t, Segment>> result;
  std::vector<std::size_t> candidates;
  for(std::size_t s = 0; s < input.size(); ++s) {
    const Segment& x = input[s];
    const double dx = x[2] - x[0], dy = x[3] - x[1], length = std::hypot(dx, dy);
    if(!(length > tolerance)) continue;
    candidates.clear();
    for(int i = cell(std::min(x[0], x[2]), 0); i <= cell(std::max(x[0], x[2]), 0); ++i)
      for(int j = cell(std::min(x[1], x[3]), 1); j <= cell(std::max(x[1], x[3]), 1); ++j)
        candidates.insert(candidates.end(), grid[std::size_t(i) * cells + j].begin(), grid[std::size_t(i) * cells + j].end());
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::vector<std::pair<double, double>> intervals; // along the segment, in input units
    for(std::size_t e : candidates) {
      const auto& a = points[edges[e][0]];
      const auto& b = points[edges[e][1]];
      auto off = [&](const std::array<double, 2>& p) { return std::abs(dx * (p[1] - x[1]) - dy * (p[0] - x[0])) / length; };
      auto along = [&](const std::array<double, 2>& p) { return (dx * (p[0] - x[0]) + dy * (p[1] - x[1])) / length; };
      // the part of the edge beside the segment (an edge can go on far beyond the end of a
      // segment moved onto its line, where the lines part by more than the tolerance)
      const double ta = along(a), tb = along(b);
      if(!(ta != tb)) continue;
      const double from = std::max(std::min(ta, tb), -tolerance), to = std::min(std::max(ta, tb), length + tolerance);
      if(!(from < to)) continue;
      auto at = [&](double t) { // the point of the edge at parameter t along the segment
        const double u = (t - ta) / (tb - ta);
        return std::array<double, 2>{a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])};
      };
      if(off(at(from)) > tolerance || off(at(to)) > tolerance) continue;
      intervals.push_back({from, to});
    }
    intervals.push_back({length, HUGE_VAL}); // the end of the segment closes the last gap
    std::sort(intervals.begin(), intervals.end());
    double reached = 0;
    for(const auto& [t0, t1] : intervals) {
      if(t0 > reached + tolerance && reached < length - tolerance) {
        const double u0 = reached / length, u1 = std::min(t0, length) / length;
        result.push_back({s, {x[0] + u0 * dx, x[1] + u0 * dy, x[0] + u1 * dx, x[1] + u1 * dy}});
      }
      reached = std::max(reached, t1);
    }
  }
  return result;
}

// Whether the uncovered parts `gaps` (from uncovered_parts()) split a cell of the partition
// made by `points` and `edges`: a part of an input segment that bounds no cell (a bridge
// between two parts of the partition, or a dangling end) cannot be an edge of a valid
// partition, the others must be edges. The gaps, lengthened by `tolerance` at both ends to
// reach the edges they end at, are added to the exact arrangement of the edges, and its faces
// larger than `minimum_area` (thinner faces come from the rounding of the points) are
// counted before and after.
inline bool gaps_split_cells(const std::vector<std::array<double, 2>>& points,
                             const std::vector<std::array<std::size_t, 2>>& edges,
                             const std::vector<std::pair<std::size_t, Segment>>& gaps, double tolerance,
                             double minimum_area)
{
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  using Arrangement = CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>>;
  if(gaps.empty()) return false;
  std::vector<EK::Segment_2> segments;
  for(const auto& e : edges)
    segments.emplace_back(EK::Point_2(points[e[0]][0], points[e[0]][1]), EK::Point_2(points[e[1]][0], points[e[1]][1]));
  auto large_faces = [&](const Arrangement& a) {
    std::size_t n = 0;
    for(auto f = a.faces_begin(); f != a.faces_end(); ++f) {
      if(f->is_unbounded()) continue;
      double area = 0;
      auto h = f->outer_ccb();
      do {
        const auto& p = h->source()->point();
        const auto& q = h->target()->point();
        area += CGAL::to_double(p.x()) * CGAL::to_double(q.y()) - CGAL::to_double(q.x()) * CGAL::to_double(p.y());
      } while(++h != f->outer_ccb());
      if(std::abs(area) / 2 > minimum_area) ++n;
    }
    return n;
  };
  Arrangement before;
  CGAL::insert(before, segments.begin(), segments.end());
  for(const auto& [s, g] : gaps) {
    const double dx = g[2] - g[0], dy = g[3] - g[1], l = std::hypot(dx, dy), u = tolerance / l;
    segments.emplace_back(EK::Point_2(g[0] - u * dx, g[1] - u * dy), EK::Point_2(g[2] + u * dx, g[3] + u * dy));
  }
  Arrangement after;
  CGAL::insert(after, segments.begin(), segments.end());
  return large_faces(after) > large_faces(before);
}

// The segments of a file, one "x0 y0 x1 y1" per line ('#' starts a comment line).
inline std::vector<Segment> read_segments(const std::string& path)
{
  std::ifstream in(path);
  std::vector<Segment> result;
  std::string line;
  while(std::getline(in, line)) {
    if(line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Segment s;
    if(fields >> s[0] >> s[1] >> s[2] >> s[3]) result.push_back(s);
  }
  return result;
}

// What happened to one scene.
struct Scene_result
{
  bool refused = false;       // kinetic_partition_2() threw an Input_error
  std::string error;          // its message
  std::string defect;         // the oracle's, on the coordinates the user gets (empty: valid)
  std::string normalized_defect; // the oracle's, on the coordinates of the normalized frame
  bool package_says_valid = false; // Line_partition_2::is_valid()
  std::size_t uncovered = 0;  // input segments with parts that split a cell but are not covered by edges
  std::size_t segments = 0, edges = 0;
  std::size_t extended_corner_ends = 0; // ends stopped at a corner that went on to split a pinched cell
  std::size_t removed_edges = 0; // edges the rounding removed to keep the partition valid
  double seconds = 0;         // of kinetic_partition_2()
};

// The kinetic partition of `scene` with the named parameters `np` (`report` excepted), checked.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
Scene_result run_scene(const std::vector<Segment>& scene, const NamedParameters& np = CGAL::parameters::default_values())
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  namespace PPS = CGAL::Polygon_partition_simplification;
  Scene_result r;
  r.segments = scene.size();
  std::vector<K::Segment_2> segments;
  for(const auto& x : scene) segments.emplace_back(K::Point_2(x[0], x[1]), K::Point_2(x[2], x[3]));
  PPS::Line_partition_2<K> p;
  const auto t0 = std::chrono::steady_clock::now();
  PPS::Kinetic_partition_report report;
  try {
    p = CGAL::kinetic_partition_2(segments, PPS::parameters::report(&report, np));
  } catch(const PPS::Input_error& e) {
    r.refused = true;
    r.error = e.what();
    return r;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.extended_corner_ends = report.extended_corner_ends;
  r.removed_edges = report.removed_edges;
  std::vector<std::array<double, 2>> points, normalized;
  for(std::size_t v = 0; v < p.number_of_vertices(); ++v) {
    const K::Point_2 q = p.point(v);
    points.push_back({q.x(), q.y()});
    normalized.push_back(p.normalized_point(v));
  }
  std::vector<std::array<std::size_t, 2>> edges;
  for(const auto& e : p.edges()) edges.push_back({e.source, e.target});
  r.edges = edges.size();
  r.defect = oracle_defect(points, edges);
  r.normalized_defect = oracle_defect(normalized, edges);
  r.package_says_valid = p.is_valid();
  double largest = 0;
  for(const auto& x : scene)
    for(double c : x) largest = std::max(largest, std::abs(c));
  // segments are moved onto the line of a longer one by up to the collinearity distance
  const double moved = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, PPS::internal_np::collinearity_distance), 0.);
  // (by default 1e-7 half-diagonals or 16 units in the last place), then the points by the
  // rounding of the partition
  const double tolerance = std::max(2e-7 * p.frame().scale + 40 * (std::nextafter(largest, HUGE_VAL) - largest), 2 * moved);
  const auto gaps = uncovered_parts(scene, points, edges, tolerance);
  if(gaps_split_cells(points, edges, gaps, 2 * tolerance, 100 * tolerance * p.frame().scale)) {
    std::set<std::size_t> segments_with_gaps;
    for(const auto& g : gaps) segments_with_gaps.insert(g.first);
    r.uncovered = segments_with_gaps.size();
  }
  return r;
}

} // namespace kinetic_stress

#endif // POLYGON_PARTITION_SIMPLIFICATION_KINETIC_STRESS_SCENES_H
