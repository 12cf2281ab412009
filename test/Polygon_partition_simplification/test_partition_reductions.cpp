// The combinatorial reductions of section 3.3.5, one by one: on small partitions whose lines
// are set by hand where a descent could have left them, each of (a) line merge, (b1) point
// merge and (b2) removal of a point outside the disk must happen, alone, with the expected
// structure after it. Then the bound of Eq. 3.15 in exact arithmetic (below eta, one of the
// three situations holds), and properties of whole simplifications: every descent lowers the
// energy, every round leaves a valid partition where two lines share at most one point, and
// no point is left outside the disk.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/Polygon_partition_simplification/line_partition_from_geometry_2.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include "synthetic_footprints.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PPS = CGAL::Polygon_partition_simplification;
namespace I = PPS::internal;
using Partition = PPS::Line_partition_2<K>;
using GT = Partition::Geom_traits;
using Stats = PPS::Simplification_statistics;


// A partition made of axis-parallel rectangles (x0, y0, x1, y1), in working form, with the
// thresholds of the default parameters; lines are found by two of their input points.
struct Scene
{
  Partition partition;
  I::Working_partition start;
  I::Reduction_thresholds thresholds;

  // `remove_far_points`: (b2) as in the thesis (the named parameter of that name)
  explicit Scene(const std::vector<std::array<double, 4>>& rectangles, bool remove_far_points = false)
    : partition(make(rectangles)), start(I::working_partition(partition)),
      thresholds(I::simplification_settings(PPS::parameters::remove_far_points(remove_far_points),
                                            partition.frame().scale).thresholds)
  {}

  static Partition make(const std::vector<std::array<double, 4>>& rectangles)
  {
    std::vector<CGAL::Polygon_2<K>> polygons;
    for(const auto& [x0, y0, x1, y1] : rectangles) {
      CGAL::Polygon_2<K> p;
      for(const auto& [x, y] : {std::pair(x0, y0), std::pair(x1, y0), std::pair(x1, y1), std::pair(x0, y1)})
        p.push_back(K::Point_2(x, y));
      polygons.push_back(p);
    }
    return PPS::line_partition_from_polygons_2(polygons);
  }

  std::array<double, 2> normalized(double x, double y) const
  {
    const auto& f = partition.frame();
    return {(x - f.center_x) / f.scale, (y - f.center_y) / f.scale};
  }

  // the line through the input points (x0, y0) and (x1, y1), in the normalized frame
  I::Vector_3d line_through(double x0, double y0, double x1, double y1) const
  {
    const auto p = normalized(x0, y0), q = normalized(x1, y1);
    return I::line_through(p[0], p[1], q[0], q[1]);
  }

  // the index of the line of the partition through the input points (x0, y0) and (x1, y1)
  std::size_t line(double x0, double y0, double x1, double y1) const
  {
    const I::Vector_3d wanted = line_through(x0, y0, x1, y1);
    for(std::size_t l = 0; l < start.lines.size(); ++l)
      if(I::line_distance(start.lines[l].coefficients, wanted) < 1e-9) return l;
    assert(!"no such line");
    return 0;
  }

  // The reductions after a descent that moved the lines `moved` (index, new coefficients) and
  // no other: the result in `w`, the counts returned. The start's edges are taken as made by
  // the reducer (those of a partition from rectangles are).
  I::Reduction_counts reduce(I::Working_partition& w, const std::vector<std::pair<std::size_t, I::Vector_3d>>& moved) const
  {
    std::vector<I::Vector_3d> coefficients;
    for(const auto& l : start.lines) coefficients.push_back(l.coefficients);
    for(const auto& [l, c] : moved) { // oriented like the line before, as after a descent
      const I::Vector_3d& before = start.lines[l].coefficients;
      coefficients[l] = before[0] * c[0] + before[1] * c[1] < 0 ? I::Vector_3d{-c[0], -c[1], -c[2]} : c;
    }
    I::moved_partition(w, start, coefficients, std::vector<bool>(start.lines.size(), false));
    I::Working_partition everywhere = w;
    const I::Round_start_edges start_edges(start);
    I::Partition_reducer reducer(w, thresholds);
    const I::Reduction_counts counts = reducer.run(start_edges.orientations, I::moved_lines(w, start));
    assert(reducer.conflicts().empty());
    // told which lines moved, the reducer makes the edges again only around them and the
    // merges: the same partition as when it makes them again everywhere
    I::Partition_reducer everywhere_reducer(everywhere, thresholds);
    everywhere_reducer.run(start_edges.orientations);
    assert(w.edges == everywhere.edges && w.vertex_lines == everywhere.vertex_lines);
    return counts;
  }
};

std::string defect(const I::Working_partition& w)
{
  return I::partition_defect<GT>(I::Working_partition_view{w}, nullptr, I::All_crossing_pairs<GT::Exact_predicates_kernel>());
}

// two points sharing two lines (the invariant of section 3.3.5 broken)
bool has_faulty_pair(const std::vector<std::vector<std::size_t>>& point_lines)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> seen;
  for(std::size_t v = 0; v < point_lines.size(); ++v) {
    const auto& l = point_lines[v];
    for(std::size_t a = 0; a < l.size(); ++a)
      for(std::size_t b = a + 1; b < l.size(); ++b)
        if(!seen.emplace(std::pair(std::min(l[a], l[b]), std::max(l[a], l[b])), v).second) return true;
  }
  return false;
}

bool has_faulty_pair(const I::Working_partition& w)
{
  std::vector<std::vector<std::size_t>> lines;
  for(const auto& v : w.vertex_lines) lines.emplace_back(v.begin(), v.end());
  return has_faulty_pair(lines);
}

double fidelity_of(const I::Vector_3d& L, const PPS::Line_metric& m)
{
  double e = 0;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) e += L[r] * m(r, c) * L[c];
  return e;
}

// (a): the wall x = 6 of three rectangles side by side moved onto the wall x = 5 (1e-9 away):
// the two lines merge into one, with the summed metric M_f = M_i + M_j and the line that
// minimizes it (x = 5.5, the best fit to the ends of both walls); the thin cell disappears.
void test_line_merge()
{
  const Scene s({{0, 0, 5, 10}, {5, 0, 6, 10}, {6, 0, 10, 10}});
  const std::size_t x5 = s.line(5, 0, 5, 10), x6 = s.line(6, 0, 6, 10);
  PPS::Line_metric summed = s.start.lines[x5].metric;
  summed += s.start.lines[x6].metric;
  I::Working_partition w;
  const I::Reduction_counts counts = s.reduce(w, {{x6, s.line_through(5 + 1e-9, 0, 5 + 1e-9, 10)}});
  std::cout << "line merge: lines " << s.start.lines.size() << " -> " << w.lines.size() << ", cells "
            << I::number_of_cells(s.start) << " -> " << I::number_of_cells(w) << std::endl;
  assert(counts.line_merges == 1 && counts.far_removals == 0);
  assert(w.lines.size() == s.start.lines.size() - 1);
  assert(I::number_of_cells(s.start) == 3 && I::number_of_cells(w) == 2);
  assert(defect(w).empty() && !has_faulty_pair(w));
  // the merged line: the one whose members are x5 and x6
  std::size_t merged = w.lines.size();
  for(std::size_t l = 0; l < w.lines.size(); ++l)
    if(w.lines[l].members.size() == 2) merged = l;
  assert(merged < w.lines.size());
  const auto& m = w.lines[merged].metric;
  for(int i = 0; i < 6; ++i) assert(m.entries[i] == summed.entries[i]);
  assert(I::line_distance(w.lines[merged].coefficients, s.line_through(5.5, 0, 5.5, 10)) < 1e-12);
  // no line of the cylinder fits M_f better (brute force over directions, c at its optimum)
  const double best = fidelity_of(w.lines[merged].coefficients, m);
  for(int k = 0; k < 3600; ++k) {
    const double t = 3.14159265358979323846 * k / 3600, a = std::cos(t), b = std::sin(t);
    const double c = -(m(0, 2) * a + m(1, 2) * b) / m(2, 2);
    assert(best <= fidelity_of({a, b, c}, m) + 1e-15);
  }
}

// (b1): the wall x = 6 tilted so that it meets the floor 1e-9 away from the wall x = 5: the
// two points of the floor merge (the edge between them collapses) into one point on three
// lines; no line merges, the middle cell becomes a triangle.
void test_point_merge()
{
  const Scene s({{0, 0, 5, 10}, {5, 0, 6, 10}, {6, 0, 10, 10}});
  const std::size_t x6 = s.line(6, 0, 6, 10);
  I::Working_partition w;
  const I::Reduction_counts counts = s.reduce(w, {{x6, s.line_through(5 + 1e-9, 0, 7, 10)}});
  std::cout << "point merge: points " << s.start.vertex_lines.size() << " -> " << w.vertex_lines.size() << std::endl;
  assert(counts.point_merges == 1 && counts.line_merges == 0 && counts.far_removals == 0);
  assert(w.lines.size() == s.start.lines.size());
  assert(w.vertex_lines.size() == s.start.vertex_lines.size() - 1);
  assert(w.edges.size() == s.start.edges.size() - 1);
  assert(std::count_if(w.vertex_lines.begin(), w.vertex_lines.end(), [](const auto& l) { return l.size() == 3; }) == 1);
  assert(I::number_of_cells(w) == 3);
  assert(defect(w).empty() && !has_faulty_pair(w));
}

// (b2): a wall x = 5 standing on a floor y = 5 that crosses the box, turned about its foot
// until nearly parallel to the floor: their meeting point goes 5 km away, outside the disk of
// the partition. With `remove_far_points`, it is removed with its three edges; the floor and
// the wall, left without a point at which they bound two cells, go with it: one cell is left,
// the box. Without, it stays, and the partition is invalid (the caller redoes the round).
void test_far_point_removal()
{
  const std::vector<std::array<double, 4>> rectangles = {{0, 5, 10, 10}, {0, 0, 5, 5}, {5, 0, 10, 5}};
  {
    const Scene kept(rectangles);
    I::Working_partition w;
    const I::Reduction_counts counts =
      kept.reduce(w, {{kept.line(5, 0, 5, 5), kept.line_through(5, 0, 5 + 1000, 1)}});
    assert(counts.far_removals == 0 && counts.far_points >= 1);
    assert(w.lines.size() == 6 && I::number_of_cells(w) == 3 && !defect(w).empty());
  }
  const Scene s(rectangles, true);
  const std::size_t wall = s.line(5, 0, 5, 5);
  I::Working_partition w;
  const I::Reduction_counts counts = s.reduce(w, {{wall, s.line_through(5, 0, 5 + 1000, 1)}});
  std::cout << "far point removal: lines " << s.start.lines.size() << " -> " << w.lines.size() << ", cells "
            << I::number_of_cells(s.start) << " -> " << I::number_of_cells(w) << std::endl;
  assert(counts.far_removals == 1 && counts.far_points == 0 && counts.line_merges == 0);
  assert(I::number_of_cells(s.start) == 3 && I::number_of_cells(w) == 1);
  assert(w.lines.size() == 4 && w.vertex_lines.size() == 4);
  assert(defect(w).empty());
  for(I::Index v = 0; v < w.vertex_lines.size(); ++v) {
    const auto p = w.point(v);
    assert(p[0] * p[0] + p[1] * p[1] <= 1.);
  }
}

// (b2) does not apply to a corner of only two edges: the right side of a lone square turned
// past parallel to its top sends their corner 10 km away; removing it would open the
// square and lose its cell. It stays (counted in far_points), and the exact validity check,
// which sees the edges leave the disk, makes the caller redo the round.
void test_far_corner_stays()
{
  const Scene s({{0, 0, 10, 10}}, true);
  const std::size_t right = s.line(10, 0, 10, 10);
  I::Working_partition w;
  const I::Reduction_counts counts = s.reduce(w, {{right, s.line_through(10, 0, 10 + 1000, -1)}});
  assert(counts.far_removals == 0 && counts.far_points >= 1);
  assert(w.lines.size() == 4 && w.vertex_lines.size() == 4 && I::number_of_cells(w) == 1);
  assert(!defect(w).empty());
}

// An edge that the descent reversed and that no reduction removes: the wall between two squares
// tilted so that it meets their top past the top right corner. The point it sent there stays
// (no removal, and it is not far enough to be a collapse); along the top line the points now
// come in another order, so the reducer makes the top line's edges again although the top line
// did not move (Scene::reduce compares with the edges made again everywhere).
void test_reversed_edge_kept()
{
  const Scene s({{0, 0, 10, 10}, {10, 0, 20, 10}});
  I::Working_partition w;
  const I::Reduction_counts counts = s.reduce(w, {{s.line(10, 0, 10, 10), s.line_through(10, 0, 25, 10)}});
  assert(counts.far_points >= 1 && counts.total() == 0);
  const std::size_t top = s.line(0, 10, 20, 10);
  std::size_t top_edges = 0;
  for(const auto& e : w.edges) top_edges += e[0] == top;
  assert(top_edges == 2);
  assert(!defect(w).empty());
}

// Eq. 3.15: with eta = d_P d_L^2 / (5 (1 + R^2)), R = 1, every triplet of lines (i, j, k) with
// |det(L_i, L_j, L_k)| < eta is in one of the situations (a) two of its lines closer than d_L,
// (b1) P_ij and P_ik closer than d_P, (b2) P_ij or P_ik outside the disk of radius R. Decided
// in exact rational arithmetic on the double coefficients, on random triplets built near each
// situation and near none (two lines through nearby points of a third one, at small angles).
void test_eta_bound()
{
  using ET = CGAL::Exact_rational;
  const I::Reduction_thresholds t =
    I::simplification_settings(PPS::parameters::default_values(), 1.).thresholds;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1), uniform(0, 1);
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform(rng)); };
  const ET eta(t.eta), dp2 = ET(t.point_distance) * ET(t.point_distance), dl2 = ET(t.line_distance) * ET(t.line_distance);
  auto line_distance2 = [](const I::Vector_3d& u, const I::Vector_3d& v) {
    ET plus = 0, minus = 0;
    for(int c = 0; c < 3; ++c) {
      plus += (ET(u[c]) - ET(v[c])) * (ET(u[c]) - ET(v[c]));
      minus += (ET(u[c]) + ET(v[c])) * (ET(u[c]) + ET(v[c]));
    }
    return (std::min)(plus, minus);
  };
  // the point of two lines, exactly, or false if they are parallel
  auto meet = [](const I::Vector_3d& u, const I::Vector_3d& v, ET& x, ET& y) {
    const ET w = ET(u[0]) * ET(v[1]) - ET(u[1]) * ET(v[0]);
    if(w == 0) return false;
    x = (ET(u[1]) * ET(v[2]) - ET(u[2]) * ET(v[1])) / w;
    y = (ET(u[2]) * ET(v[0]) - ET(u[0]) * ET(v[2])) / w;
    return true;
  };
  std::size_t below = 0, cases[3] = {0, 0, 0};
  for(int trial = 0; trial < 200000; ++trial) {
    // line i through the disk; half of the trials: two points on it at a distance from 1e-14
    // to 3, lines j and k through them at angles from 1e-8 to pi/2 with line i (near (a) and
    // (b1)); the other half: lines j and k at angles from 1e-9 to 1e-3 with line i, anywhere
    // in the disk (three nearly parallel lines, near (b2))
    const double theta = 3.14159265358979323846 * uniform(rng), ci = 0.9 * unit(rng);
    const double a = std::cos(theta), b = std::sin(theta);
    const I::Vector_3d Li = {a, b, ci};
    auto at_angle = [&](double x, double y, double lo, double hi) {
      const double angle = theta + 1.5707963267948966 + (rng() % 2 ? 1 : -1) * log_uniform(lo, hi);
      return I::line_through(x, y, x + std::cos(angle), y + std::sin(angle));
    };
    I::Vector_3d Lj, Lk;
    if(trial % 2 == 0) {
      const double s0 = unit(rng), gap = log_uniform(1e-14, 3.);
      const double px = -a * ci - b * s0, py = -b * ci + a * s0;
      Lj = at_angle(px, py, 1e-8, 1.5707963);
      Lk = at_angle(px - b * gap, py + a * gap, 1e-8, 1.5707963);
    } else {
      Lj = at_angle(0.7 * unit(rng), 0.7 * unit(rng), 1e-9, 1e-3);
      Lk = at_angle(0.7 * unit(rng), 0.7 * unit(rng), 1e-9, 1e-3);
    }
    ET det = 0;
    {
      const ET x0 = ET(Li[1]) * ET(Lj[2]) - ET(Li[2]) * ET(Lj[1]), x1 = ET(Li[2]) * ET(Lj[0]) - ET(Li[0]) * ET(Lj[2]),
               x2 = ET(Li[0]) * ET(Lj[1]) - ET(Li[1]) * ET(Lj[0]);
      det = x0 * ET(Lk[0]) + x1 * ET(Lk[1]) + x2 * ET(Lk[2]);
    }
    if(CGAL::abs(det) >= eta) continue;
    ++below;
    if(line_distance2(Li, Lj) < dl2 || line_distance2(Li, Lk) < dl2 || line_distance2(Lj, Lk) < dl2) { ++cases[0]; continue; }
    ET x1, y1, x2, y2;
    const bool finite = meet(Li, Lj, x1, y1) && meet(Li, Lk, x2, y2);
    if(!finite || x1 * x1 + y1 * y1 > 1 || x2 * x2 + y2 * y2 > 1) { ++cases[2]; continue; }
    const ET d2 = (x1 - x2) * (x1 - x2) + (y1 - y2) * (y1 - y2);
    if(d2 < dp2) { ++cases[1]; continue; }
    std::cerr << "triplet below eta in none of the three situations: |P_ij - P_ik| = " << std::sqrt(CGAL::to_double(d2))
              << std::endl;
    assert(false);
  }
  std::cout << "eta bound: " << below << " triplets below eta: " << cases[0] << " (a), " << cases[1] << " (b1), "
            << cases[2] << " (b2)" << std::endl;
  assert(cases[0] > 100 && cases[1] > 100 && cases[2] > 100);
}

// Whole simplifications of synthetic footprints: every descent (from the partition after each
// round, all lines free) does not raise the energy; after every round the partition is valid,
// two lines share at most one point, and no point lies outside the disk of the partition; the
// reducer that makes the edges again only around what moved gives the partition it gives when
// it makes them again everywhere.
void test_rounds()
{
  for(unsigned seed : {1u, 2u, 3u})
    for(bool remove_far_points : {false, true}) {
      const auto f = synthetic::make_footprints(6, 0.05, seed);
      std::vector<K::Segment_2> segments;
      for(const auto& x : f.segments) segments.emplace_back(K::Point_2(x[0], x[1]), K::Point_2(x[2], x[3]));
      Partition p = CGAL::kinetic_partition_2(segments);
      const I::Simplification_settings settings =
        I::simplification_settings(PPS::parameters::remove_far_points(remove_far_points), p.frame().scale);
      std::size_t rounds = 0, descents_lowering = 0, partial_reductions = 0;
      auto check_round = [&](const Partition& q, const Stats&) {
        assert(q.is_valid());
        std::vector<std::vector<std::size_t>> lines;
        for(const auto& v : q.vertices()) lines.push_back(v.lines);
        assert(!has_faulty_pair(lines));
        I::Working_partition w = I::working_partition(q);
        for(I::Index v = 0; v < w.vertex_lines.size(); ++v) {
          const auto x = w.point(v);
          assert(x[0] * x[0] + x[1] * x[1] <= 1. + 1e-12);
        }
        // The reductions after a descent that moves some lines only: the edges made again around
        // what moved and merged (the reducer told which lines moved) are those made again
        // everywhere (the reducer told nothing).
        {
          std::vector<bool> changed(w.lines.size(), false);
          for(std::size_t l = 0; l < w.lines.size(); l += 5) changed[l] = true;
          std::size_t steps = 0;
          const std::vector<I::Vector_3d> moved = I::descend(w, changed, settings, steps);
          const I::Round_start_edges start_edges(w);
          const std::vector<bool> none_frozen(w.lines.size(), false);
          I::Working_partition local, everywhere;
          I::moved_partition(local, w, moved, none_frozen);
          I::moved_partition(everywhere, w, moved, none_frozen);
          const std::vector<bool> moved_lines = I::moved_lines(local, w);
          I::Partition_reducer local_reducer(local, settings.thresholds), everywhere_reducer(everywhere, settings.thresholds);
          const std::size_t reductions = local_reducer.run(start_edges.orientations, moved_lines).total();
          everywhere_reducer.run(start_edges.orientations);
          assert(local.edges == everywhere.edges);
          assert(local.vertex_lines == everywhere.vertex_lines);
          assert(local.lines.size() == everywhere.lines.size());
          for(std::size_t l = 0; l < std::min(local.lines.size(), everywhere.lines.size()); ++l)
            assert(local.lines[l].coefficients == everywhere.lines[l].coefficients);
          if(reductions > 0 && std::count(moved_lines.begin(), moved_lines.end(), false) > 0) ++partial_reductions;
        }
        const double before = I::energy_in_collapse_units(w, settings);
        std::size_t steps = 0;
        const std::vector<I::Vector_3d> moved = I::descend(w, {}, settings, steps);
        for(std::size_t l = 0; l < w.lines.size(); ++l) w.lines[l].coefficients = moved[l];
        const double after = I::energy_in_collapse_units(w, settings);
        assert(after <= before * (1 + 1e-12));
        descents_lowering += after < before;
        ++rounds;
        return true;
      };
      const Stats s = CGAL::simplify_polygon_partition_2(
        p, PPS::parameters::remove_far_points(remove_far_points).callback(
             std::function<bool(const Partition&, const Stats&)>(check_round)));
      assert(remove_far_points || s.far_point_removals == 0);
      std::cout << "footprints (seed " << seed << (remove_far_points ? ", far points removed" : "") << "): "
                << s.rounds << " rounds, " << s.line_merges << " line merges, " << s.point_merges << " point merges, "
                << s.far_point_removals << " far points removed, " << s.rejected_rounds << " redone; cells " << s.cells_before << " -> " << s.cells_after << std::endl;
      assert(rounds == s.rounds && descents_lowering > 0);
      std::cout << "  reductions after a partial descent, edges made again locally: " << partial_reductions << " rounds" << std::endl;
      assert(partial_reductions > 0);
    }
}

int main()
{
  test_line_merge();
  test_point_merge();
  test_far_point_removal();
  test_far_corner_stays();
  test_reversed_edge_kept();
  test_eta_bound();
  test_rounds();
  std::cout << "ok" << std::endl;
  return 0;
}
