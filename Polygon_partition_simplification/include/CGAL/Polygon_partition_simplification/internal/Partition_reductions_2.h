// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_REDUCTIONS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_REDUCTIONS_2_H

// The combinatorial reductions of section 3.3.5 on a partition in line representation.
//
// 0. An edge whose direction along its line reversed during the descent went through its
//    collapse: if it is shorter than epsilon its two points merge (b1); otherwise one of its
//    points went through infinity: see 2.
// 1. For every triplet (i, j, k) of the concurrency term, with points P_ij = u and P_ik = v
//    joined by an edge of line i, such that |det(L_i, L_j, L_k)| < eta, decide which exact
//    situation it approximates: (a) two of the lines are closer than d_L: merge them; (b1) u
//    and v are closer than d_P: merge the points (the edge collapses); (b2) neither: a point is
//    outside the disk of radius R (Eq. 3.15 guarantees one of the three when
//    eta = d_P d_L^2 / (5 (1 + R^2))), see 2.
// 2. A point sent to infinity: if its two most parallel lines are closer than epsilon
//    everywhere in the disk, the step between them is an edge shorter than epsilon that
//    collapsed, and they merge (a). Otherwise, with `remove_far_points`, the point is removed
//    with its edges (b2): the cells around it become one, the lines left without an edge at
//    the other end of each of its edges leave that point (which disappears if one line is
//    left). Without the option, and for a corner of only two edges or a point whose lines are
//    all kept back, the point stays (counted in far_points): the exact validity check of the
//    caller then decides whether the round is redone.
// 3. Restore the invariant (two lines share at most one point, two points at most one line)
//    with the thesis's faulty pairs: two points sharing two lines merge their lines if these
//    are closer than d_L, or merge if they are closer than epsilon or if all their lines pass
//    within d_P of one point; other pairs (two distant points on the same two lines) are a
//    conflict, reported to the caller (which redoes the round with their lines kept still).
// After merges the edges of every line are rebuilt from the union of the intervals they
// covered (merged lines overlap), points left on a single line disappear inside their chain,
// and dangling edges are removed. Merged lines get M_f = M_i + M_j and the line minimizing it.
// Every merge removes a line or a point, so the restoration ends.

#include <CGAL/Polygon_partition_simplification/internal/First_value_map.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_energy_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Union_find.h>
#include <CGAL/Polygon_partition_simplification/internal/Working_partition_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

struct Reduction_counts
{
  std::size_t line_merges = 0;
  std::size_t point_merges = 0;
  std::size_t removed_points = 0;  // points left on one line, or dangling
  std::size_t far_points = 0;      // case (b2) left as is (its lines kept back): left to the validity check
  std::size_t far_removals = 0;    // case (b2): points outside the disk removed with their edges
  std::size_t total() const { return line_merges + point_merges + removed_points; }
};

struct Reduction_thresholds
{
  double eta = 0;           // on |det|
  double point_distance = 0; // d_P
  double line_distance = 0;  // d_L
  double collapse_length = 0; // epsilon: a reversed edge shorter than this collapses
  bool remove_far_points = false; // (b2) as in the thesis: a point outside the disk is removed
};

class Partition_reducer
{
public:
  Partition_reducer(Working_partition& w, const Reduction_thresholds& t) : w_(w), t_(t) {}

  // +1 if q follows p along the direction (-b, a) of line L, -1 otherwise
  static signed char orientation_along(const Vector_3d& L, const std::array<double, 2>& p, const std::array<double, 2>& q)
  {
    return (-L[1] * (q[0] - p[0]) + L[0] * (q[1] - p[1])) >= 0 ? 1 : -1;
  }

  // `orientations`: those of the edges before the descent. An edge whose orientation
  // reversed went through a collapse during the descent: it is collapsed (b1). `moved`: the
  // lines that moved since their edges were last made by a reduction (see apply()), or empty
  // if that is unknown (then the edges of every line are made again).
  Reduction_counts run(const std::vector<signed char>& orientations, const std::vector<bool>& moved = {})
  {
    remake_all_ = moved.empty();
    moved_ = moved;
    reset();
    const std::size_t nv = w_.vertex_lines.size();
    degree_.assign(nv, 0);
    for(const auto& e : w_.edges) { ++degree_[e[1]]; ++degree_[e[2]]; }
    std::vector<std::array<double, 2>> points(nv);
    for(Index v = 0; v < nv; ++v) points[v] = w_.point(v);
    auto line = [&](Index l) -> const Vector_3d& { return w_.lines[l].coefficients; };
    auto try_line_merge = [&](Index x, Index y) {
      if(w_.lines[x].is_still() || w_.lines[y].is_still()) return false;
      return merge_close_classes(x, y, t_.line_distance);
    };
    {
      // A reversed edge shorter than the collapse distance went through its collapse; a longer
      // one has an end that went through infinity (its lines became parallel): that end is
      // removed, as in (b2).
      for(std::size_t e = 0; e < w_.edges.size(); ++e) {
        const Index u = w_.edges[e][1], v = w_.edges[e][2];
        if(orientation_along(line(w_.edges[e][0]), points[u], points[v]) == orientations[e]) continue;
        if(std::hypot(points[u][0] - points[v][0], points[u][1] - points[v][1]) < t_.collapse_length) {
          if(merge_close_points(u, v, points, t_.collapse_length)) ++counts_.point_merges;
          continue;
        }
        send_to_infinity(smallest_angle(u) < smallest_angle(v) ? u : v);
      }
    }
    // 1. triplets below eta
    for(const auto& e : w_.edges) {
      const Index i = e[0], u = e[1], v = e[2];
      for(Index j : w_.vertex_lines[u]) {
        if(j == i) continue;
        for(Index k : w_.vertex_lines[v]) {
          if(k == i || k == j) continue;
          if(!(std::abs(determinant(line(i), line(j), line(k))) < t_.eta)) continue;
          if(try_line_merge(j, k) || try_line_merge(i, j) || try_line_merge(i, k)) {
            ++counts_.line_merges; continue;
          }
          if(std::hypot(points[u][0] - points[v][0], points[u][1] - points[v][1]) < t_.point_distance) {
            if(merge_close_points(u, v, points, t_.point_distance)) ++counts_.point_merges;
            continue;
          }
          // (b2): a point outside the disk of radius R = 1 (the corners of the enclosing
          // rectangle are on its circle: rounding must not send them out)
          for(Index x : {u, v})
            if(points[x][0] * points[x][0] + points[x][1] * points[x][1] > 1. + 1e-9) send_to_infinity(x);
        }
      }
    }
    for(const auto& l : w_.vertex_lines) // lines through one point
      for(std::size_t a = 0; a < l.size(); ++a)
        for(std::size_t b = a + 1; b < l.size(); ++b)
          for(std::size_t c = b + 1; c < l.size(); ++c)
            if(std::abs(determinant(line(l[a]), line(l[b]), line(l[c]))) < t_.eta &&
               (try_line_merge(l[a], l[b]) || try_line_merge(l[a], l[c]) || try_line_merge(l[b], l[c])))
              ++counts_.line_merges;
    apply();
    // 2. invariant
    for(;;) {
      reset();
      bool changed = false;
      owner_.clear(w_.vertex_lines.size());
      for(Index v = 0; v < w_.vertex_lines.size(); ++v) {
        const auto& l = w_.vertex_lines[v];
        for(std::size_t a = 0; a < l.size(); ++a)
          for(std::size_t b = a + 1; b < l.size(); ++b) {
            const std::uint64_t key = (std::uint64_t(l[a]) << 32) | l[b]; // l[a] < l[b]: not no_key
            const Index first = owner_.insert(key, v); // the first point on these two lines
            if(first == v || vertex_sets_.same_set(first, v)) continue;
            if(!w_.lines[l[a]].is_still() && !w_.lines[l[b]].is_still() &&
               line_distance(line(l[a]), line(l[b])) < t_.line_distance && unite_lines(l[a], l[b])) {
              ++counts_.line_merges; changed = true; continue;
            }
            const auto p = w_.point(first), q = w_.point(v);
            if(std::hypot(p[0] - q[0], p[1] - q[1]) < t_.collapse_length) {
              if(unite_vertices(first, v)) ++counts_.point_merges;
              changed = true;
              continue;
            }
            // two distant points on the same two lines whose lines all pass within d_P of one
            // point: they are that point
            if(lines_meet_near_one_point(first, v)) {
              if(unite_vertices(first, v)) ++counts_.point_merges;
              changed = true;
              continue;
            }
            // otherwise no merge is faithful (merging them anyway, as the thesis does, can move a
            // wall by meters): the caller redoes the round with these lines kept still
            for(Index y : {first, v})
              for(Index x : w_.vertex_lines[y])
                conflicts_.insert(conflicts_.end(), w_.lines[x].members.begin(), w_.lines[x].members.end());
          }
      }
      if(!changed) break;
      apply();
    }
    return counts_;
  }

private:
  // A point sent to infinity: its two most parallel lines. When they are closer than the
  // collapse distance everywhere in the disk of radius R = 1, the step between them is an
  // edge shorter than epsilon that went through its collapse: they merge (a). Otherwise,
  // with `remove_far_points`, the point is removed with its edges (b2) by apply().
  void send_to_infinity(Index x)
  {
    const auto& l = w_.vertex_lines[x];
    double best = 2;
    Index p = 0, q = 0;
    for(std::size_t a = 0; a < l.size(); ++a)
      for(std::size_t b = a + 1; b < l.size(); ++b) {
        const Vector_3d& L = w_.lines[l[a]].coefficients;
        const Vector_3d& M = w_.lines[l[b]].coefficients;
        const double s = std::abs(L[0] * M[1] - L[1] * M[0]);
        if(s < best) { best = s; p = l[a]; q = l[b]; }
      }
    if(best < 1 && !w_.lines[p].is_still() && !w_.lines[q].is_still()) {
      const Vector_3d& L = w_.lines[p].coefficients;
      Vector_3d M = w_.lines[q].coefficients;
      if(L[0] * M[0] + L[1] * M[1] < 0) M = {-M[0], -M[1], -M[2]};
      const double spread = std::hypot(L[0] - M[0], L[1] - M[1]) + std::abs(L[2] - M[2]);
      if(spread < t_.collapse_length) {
        if(merge_close_classes(p, q, 2 * t_.collapse_length)) ++counts_.line_merges;
        return;
      }
    }
    if(std::all_of(l.begin(), l.end(), [&](Index m) { return w_.lines[m].is_still(); })) {
      ++counts_.far_points; // kept back: left as is, the validity check of the caller decides
      return;
    }
    // A point with two edges is a corner that only two cells share: without it their common
    // boundary would open, the cells would become one, and the dangling chains left would go
    // too (a polygon given alone would lose its cell). It stays, for the validity check.
    if(!t_.remove_far_points || degree_[x] < 3) { ++counts_.far_points; return; }
    if(!removed_[x]) { removed_[x] = true; ++counts_.far_removals; }
  }

  // Do the lines of points u and v all pass within d_P of one point (their least-squares
  // point)? Then u and v are one point up to d_P, as the merge of lines made them.
  bool lines_meet_near_one_point(Index u, Index v) const
  {
    Point_lines all(w_.vertex_lines[u].begin(), w_.vertex_lines[u].end());
    all.insert(all.end(), w_.vertex_lines[v].begin(), w_.vertex_lines[v].end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    const auto p = point_of_lines(
      all, [this](std::size_t l) -> const Vector_3d& { return w_.lines[l].coefficients; },
      [this](std::size_t l) { return w_.lines[l].is_fixed; });
    if(!std::isfinite(p[0]) || !std::isfinite(p[1])) return false;
    for(Index l : all) {
      const Vector_3d& L = w_.lines[l].coefficients;
      if(!(std::abs(L[0] * p[0] + L[1] * p[1] + L[2]) < t_.point_distance)) return false;
    }
    return true;
  }

  // |sin| of the smallest angle between two lines of point v
  double smallest_angle(Index v) const
  {
    double result = 1;
    const auto& l = w_.vertex_lines[v];
    for(std::size_t a = 0; a < l.size(); ++a)
      for(std::size_t b = a + 1; b < l.size(); ++b) {
        const Vector_3d& p = w_.lines[l[a]].coefficients;
        const Vector_3d& q = w_.lines[l[b]].coefficients;
        result = std::min(result, std::abs(p[0] * q[1] - p[1] * q[0]));
      }
    return result;
  }

  Index find_line(Index x) { return line_sets_.find(x); }
  Index find_vertex(Index x) { return vertex_sets_.find(x); }

  // Merges the classes of x and y if every line of one is within `bound` of every line of the
  // other (complete linkage): chains of pairwise close lines, such as the sides of the
  // 360-gon, do not merge all at once before the merged lines get their new coordinates.
  bool merge_close_classes(Index x, Index y, double bound)
  {
    const Index rx = find_line(x), ry = find_line(y);
    if(rx == ry) return false;
    auto& cx = class_members_[rx];
    auto& cy = class_members_[ry];
    if(cx.empty()) cx.push_back(rx);
    if(cy.empty()) cy.push_back(ry);
    for(Index a : cx)
      for(Index b : cy)
        if(line_distance(w_.lines[a].coefficients, w_.lines[b].coefficients) >= bound) return false;
    unite_lines(rx, ry);
    const Index r = find_line(rx);
    auto& target = class_members_[r];
    auto& source = class_members_[r == rx ? ry : rx];
    target.insert(target.end(), source.begin(), source.end());
    source.clear();
    return true;
  }

  // Merges the classes of points u and v if all their points are within `bound` of each other
  // (complete linkage: a ring of short edges does not collapse into one point at once), unless
  // every line through u and v is kept still: around a defect of a previous attempt, the
  // partition must stay that of the start of the round, since a merge of the ends of a short
  // edge there can leave a defect that no freezing removes.
  bool merge_close_points(Index u, Index v, const std::vector<std::array<double, 2>>& points, double bound)
  {
    auto still = [&](Index x) {
      return std::all_of(w_.vertex_lines[x].begin(), w_.vertex_lines[x].end(),
                         [&](Index l) { return w_.lines[l].is_still(); });
    };
    if(still(u) && still(v)) return false;
    const Index ru = find_vertex(u), rv = find_vertex(v);
    if(ru == rv) return false;
    auto& cu = vertex_members_[ru];
    auto& cv = vertex_members_[rv];
    if(cu.empty()) cu.push_back(ru);
    if(cv.empty()) cv.push_back(rv);
    for(Index a : cu)
      for(Index b : cv)
        if(!(std::hypot(points[a][0] - points[b][0], points[a][1] - points[b][1]) < bound)) return false;
    unite_vertices(ru, rv);
    const Index r = find_vertex(ru);
    auto& target = vertex_members_[r];
    auto& source = vertex_members_[r == ru ? rv : ru];
    target.insert(target.end(), source.begin(), source.end());
    source.clear();
    return true;
  }

  // The classes of lines and of points to merge keep their smallest member as representative:
  // apply() numbers the merged lines and points in the order of their representatives and
  // starts a merged line from the state of its representative.
  bool unite_lines(Index x, Index y) { return line_sets_.unite_at_smallest(x, y); }
  bool unite_vertices(Index x, Index y) { return vertex_sets_.unite_at_smallest(x, y); }

  void reset()
  {
    line_sets_.reset(w_.lines.size());
    class_members_.assign(w_.lines.size(), {});
    vertex_members_.assign(w_.vertex_lines.size(), {});
    vertex_sets_.reset(w_.vertex_lines.size());
    removed_.assign(w_.vertex_lines.size(), false);
  }

  // argmin of L^T M L over a^2 + b^2 = 1: with c = -(M_ac a + M_bc b) / M_cc, the smallest
  // eigenvector of the Schur complement of M_cc in M
  static Vector_3d best_line(const Line_metric& m)
  {
    const double mcc = m(2, 2);
    const double s00 = m(0, 0) - m(0, 2) * m(0, 2) / mcc, s01 = m(0, 1) - m(0, 2) * m(1, 2) / mcc,
                 s11 = m(1, 1) - m(1, 2) * m(1, 2) / mcc;
    const double half_trace = 0.5 * (s00 + s11), det = s00 * s11 - s01 * s01;
    const double smallest = half_trace - std::sqrt(std::max(0., half_trace * half_trace - det));
    // (S - smallest I) (a, b) = 0: (a, b) is orthogonal to either row of S - smallest I; the
    // larger row decides (with S diagonal, the lines of a merge all axis-parallel, the first
    // row can be zero up to rounding, and its orthogonal direction would be noise)
    double a = s01, b = smallest - s00;
    if(std::hypot(s00 - smallest, s01) < std::hypot(s01, s11 - smallest)) { a = smallest - s11; b = s01; }
    const double n = std::hypot(a, b);
    if(!(n > 0)) return {std::nan(""), 0, 0};
    a /= n; b /= n;
    return {a, b, -(m(0, 2) * a + m(1, 2) * b) / mcc};
  }

  // Rebuilds the partition after merges: merged lines get the sum of their metrics and the
  // line that minimizes it (the best fit to the endpoints of all their segments, as in QEM);
  // a fixed line keeps its coefficients.
  void apply()
  {
    const std::size_t nl = w_.lines.size(), nv = w_.vertex_lines.size();
    std::vector<Index> new_line(nl, Index(-1));
    std::vector<Line_state> lines;
    std::vector<Vector_3d> sum;
    for(Index l = 0; l < nl; ++l) {
      const Index r = find_line(l);
      if(new_line[r] == Index(-1)) {
        new_line[r] = Index(lines.size());
        lines.push_back(w_.lines[r]);
        lines.back().metric = Line_metric();
        lines.back().number_of_segments = 0;
        lines.back().members.clear();
        sum.push_back({0, 0, 0});
      }
      new_line[l] = new_line[r];
      Line_state& target = lines[new_line[l]];
      const Line_state& source = w_.lines[l];
      target.metric += source.metric;
      target.number_of_segments += source.number_of_segments;
      target.is_fixed = target.is_fixed || source.is_fixed;
      target.is_frozen = target.is_frozen || source.is_frozen;
      target.members.insert(target.members.end(), source.members.begin(), source.members.end());
      const Vector_3d& reference = w_.lines[r].coefficients;
      const double orientation =
        reference[0] * source.coefficients[0] + reference[1] * source.coefficients[1] < 0 ? -1. : 1.;
      const double weight = double(std::max<std::size_t>(source.number_of_segments, 1));
      for(int c = 0; c < 3; ++c) sum[new_line[l]][c] += weight * orientation * source.coefficients[c];
    }
    for(Index l = 0; l < nl; ++l) {
      Line_state& target = lines[new_line[l]];
      if(w_.lines[l].is_fixed) target.coefficients = w_.lines[l].coefficients;
    }
    for(std::size_t l = 0; l < lines.size(); ++l) {
      if(lines[l].is_fixed || lines[l].members.size() < 2) continue;
      // the line minimizing L^T M_f L on the cylinder, oriented like the mean of the merged lines
      Vector_3d best = best_line(lines[l].metric);
      if(best[0] * sum[l][0] + best[1] * sum[l][1] < 0) best = {-best[0], -best[1], -best[2]};
      lines[l].coefficients = std::isfinite(best[0]) ? best : normalized_line(sum[l]);
    }

    std::vector<Index> new_vertex(nv, Index(-1));
    std::vector<Point_lines> vertex_lines;
    for(Index v = 0; v < nv; ++v) {
      const Index r = find_vertex(v);
      if(new_vertex[r] == Index(-1)) { new_vertex[r] = Index(vertex_lines.size()); vertex_lines.emplace_back(); }
      new_vertex[v] = new_vertex[r];
      for(Index l : w_.vertex_lines[v]) vertex_lines[new_vertex[v]].push_back(new_line[l]);
    }
    for(auto& l : vertex_lines) {
      std::sort(l.begin(), l.end());
      l.erase(std::unique(l.begin(), l.end()), l.end());
    }
    // (b2): a point outside the disk goes with its edges; at the other end of each, the lines
    // left without an edge there are no longer lines of that point (a point left on one line
    // then disappears inside its chain)
    std::vector<bool> removed(vertex_lines.size(), false);
    for(Index v = 0; v < nv; ++v) if(removed_[v]) removed[new_vertex[v]] = true;
    std::vector<std::array<Index, 3>> old_edges;
    std::vector<Index> touched;
    for(const auto& e : w_.edges) {
      Index u = new_vertex[e[1]], v = new_vertex[e[2]];
      if(u == v) continue;
      if(removed[u] || removed[v]) {
        if(!removed[u]) touched.push_back(u);
        if(!removed[v]) touched.push_back(v);
        continue;
      }
      old_edges.push_back({new_line[e[0]], u, v});
    }
    if(!touched.empty()) {
      std::sort(touched.begin(), touched.end());
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
      std::vector<Point_lines> kept(touched.size());
      for(const auto& e : old_edges)
        for(int end = 1; end <= 2; ++end) {
          const auto it = std::lower_bound(touched.begin(), touched.end(), e[end]);
          if(it != touched.end() && *it == e[end]) kept[it - touched.begin()].push_back(e[0]);
        }
      for(std::size_t t = 0; t < touched.size(); ++t) {
        auto& k = kept[t];
        std::sort(k.begin(), k.end());
        k.erase(std::unique(k.begin(), k.end()), k.end());
        vertex_lines[touched[t]] = std::move(k);
      }
      for(Index v = 0; v < vertex_lines.size(); ++v) if(removed[v]) vertex_lines[v].clear();
    }
    const std::vector<bool> affected = affected_lines(new_line, new_vertex, removed, lines.size());
    w_.lines = std::move(lines);
    w_.vertex_lines = std::move(vertex_lines);
    w_.edges = rechain(old_edges, affected);
    remove_dangling_edges();
    remake_all_ = false; // the edges of every line are made: none moved since
    moved_.assign(w_.lines.size(), false);
  }

  // The lines of the partition that apply() makes (numbered by `new_line`, `number_of_lines`
  // of them; its points numbered by `new_vertex`, `removed` those removed in case (b2)) whose
  // edges it must make again: the merged lines, the lines through a point that merged, was
  // removed or lost an edge to a removed point, or has a line that merged or moved (its
  // coordinates changed). The edges of the other lines are those rechain() would make: it made
  // them for the same points at the same coordinates (when the reducer's first apply() follows
  // a descent, the lines that did not move in it).
  std::vector<bool> affected_lines(const std::vector<Index>& new_line, const std::vector<Index>& new_vertex,
                                   const std::vector<bool>& removed, std::size_t number_of_lines)
  {
    const std::size_t nl = w_.lines.size(), nv = w_.vertex_lines.size();
    std::vector<bool> affected(number_of_lines, remake_all_);
    if(remake_all_) return affected;
    std::vector<bool> merged_line(nl, false); // lines of a class of two or more (old numbering)
    for(Index l = 0; l < nl; ++l) {
      const Index r = find_line(l);
      if(r != l) merged_line[l] = merged_line[r] = true;
    }
    std::vector<bool> merged_vertex(nv, false);
    for(Index v = 0; v < nv; ++v) {
      const Index r = find_vertex(v);
      if(r != v) merged_vertex[v] = merged_vertex[r] = true;
    }
    for(Index l = 0; l < nl; ++l) if(merged_line[l]) affected[new_line[l]] = true;
    for(Index v = 0; v < nv; ++v) {
      const auto& lines = w_.vertex_lines[v];
      const bool changed = merged_vertex[v] || removed[new_vertex[v]] ||
                           std::any_of(lines.begin(), lines.end(), [&](Index l) { return merged_line[l] || moved_[l]; });
      if(changed) for(Index l : lines) affected[new_line[l]] = true;
    }
    // the lines at the other end of an edge to a removed point (or to a point merged with one):
    // the point may lose them
    for(const auto& e : w_.edges)
      if(removed[new_vertex[e[1]]] || removed[new_vertex[e[2]]])
        for(Index v : {e[1], e[2]})
          for(Index l : w_.vertex_lines[v]) affected[new_line[l]] = true;
    return affected;
  }

  // The edges of every `affected` line, rebuilt from the union of the intervals its old edges
  // cover: inside each union, consecutive points of the line (points on at least two lines, in
  // the order along the line) are joined. Overlapping edges of merged lines become one chain and
  // a point left on a single line disappears inside its chain. The other lines keep their old
  // edges.
  std::vector<std::array<Index, 3>> rechain(const std::vector<std::array<Index, 3>>& old_edges,
                                            const std::vector<bool>& affected) const
  {
    const std::size_t nl = w_.lines.size(), nv = w_.vertex_lines.size();
    std::vector<std::array<double, 2>> points(nv);
    for(Index v = 0; v < nv; ++v)
      points[v] = w_.vertex_lines[v].size() >= 2 ? w_.point(v) : std::array<double, 2>{0, 0};
    auto parameter = [&](Index l, Index v) {
      const Vector_3d& L = w_.lines[l].coefficients;
      return -L[1] * points[v][0] + L[0] * points[v][1];
    };
    // per line (compressed rows): its old edges (u, v), and its points on at least two lines
    std::vector<Index> first_edge(nl + 1, 0), first_point(nl + 1, 0);
    for(const auto& e : old_edges) ++first_edge[e[0] + 1];
    for(Index v = 0; v < nv; ++v)
      if(w_.vertex_lines[v].size() >= 2)
        for(Index l : w_.vertex_lines[v]) ++first_point[l + 1];
    for(std::size_t l = 0; l < nl; ++l) {
      first_edge[l + 1] += first_edge[l];
      first_point[l + 1] += first_point[l];
    }
    std::vector<std::pair<Index, Index>> line_edges(old_edges.size());
    std::vector<Index> line_points(first_point[nl]);
    {
      std::vector<Index> next(first_edge.begin(), first_edge.end() - 1);
      for(const auto& e : old_edges) line_edges[next[e[0]]++] = {e[1], e[2]};
      next.assign(first_point.begin(), first_point.end() - 1);
      for(Index v = 0; v < nv; ++v)
        if(w_.vertex_lines[v].size() >= 2)
          for(Index l : w_.vertex_lines[v]) line_points[next[l]++] = v;
    }
    std::vector<std::array<Index, 3>> edges;
    std::vector<std::pair<double, double>> intervals, unions; // buffers reused from line to line
    std::vector<std::pair<Index, Index>> through;
    std::vector<std::pair<double, Index>> sorted;
    // A point left on a single line lies on that line only, so the groups of such points
    // joined by edges are found with one union-find over all points, line after line. A group
    // is named by its representative, which orders the groups of a line: the representative is
    // that of the second point of the edge that joined two groups (unite_into()).
    Union_find<Index> groups(nv);
    for(Index l = 0; l < nl; ++l) {
      const std::size_t first_of_line = edges.size();
      if(!affected[l]) {
        for(Index k = first_edge[l]; k < first_edge[l + 1]; ++k) {
          const auto [u, v] = line_edges[k];
          edges.push_back({l, std::min(u, v), std::max(u, v)});
        }
        std::sort(edges.begin() + first_of_line, edges.end());
        continue;
      }
      // Intervals with real points at both ends. A single-line point has no coordinates of its
      // own: it lies where the chain through it goes. Single-line points joined by edges form a
      // group (three or more lines merged in a row leave several in a row), and the real points
      // at the ends of the group's edges bound one interval.
      intervals.clear();
      through.clear(); // (group of single-line points, real point)
      for(Index k = first_edge[l]; k < first_edge[l + 1]; ++k) {
        const auto [u, v] = line_edges[k];
        const bool ru = w_.vertex_lines[u].size() >= 2, rv = w_.vertex_lines[v].size() >= 2;
        if(ru && rv) {
          const double a = parameter(l, u), b = parameter(l, v);
          intervals.push_back({std::min(a, b), std::max(a, b)});
        } else if(ru) through.push_back({v, u});
        else if(rv) through.push_back({u, v});
        else groups.unite_into(u, v);
      }
      for(auto& t : through) t.first = groups.find(t.first);
      std::sort(through.begin(), through.end());
      for(std::size_t i = 0, j; i < through.size(); i = j) {
        double lo = parameter(l, through[i].second), hi = lo;
        for(j = i + 1; j < through.size() && through[j].first == through[i].first; ++j) {
          const double t = parameter(l, through[j].second);
          lo = std::min(lo, t);
          hi = std::max(hi, t);
        }
        if(hi > lo) intervals.push_back({lo, hi}); // a group reached from one real point only dangles
      }
      if(intervals.empty()) continue;
      std::sort(intervals.begin(), intervals.end());
      unions.assign(1, intervals[0]);
      for(const auto& i : intervals) {
        if(i.first <= unions.back().second) unions.back().second = std::max(unions.back().second, i.second);
        else unions.push_back(i);
      }
      sorted.clear();
      for(Index k = first_point[l]; k < first_point[l + 1]; ++k)
        sorted.push_back({parameter(l, line_points[k]), line_points[k]});
      std::sort(sorted.begin(), sorted.end());
      std::size_t k = 0;
      for(const auto& [lo, hi] : unions) {
        while(k < sorted.size() && sorted[k].first < lo) ++k;
        for(; k + 1 < sorted.size() && sorted[k + 1].first <= hi; ++k) {
          Index u = sorted[k].second, v = sorted[k + 1].second;
          if(v < u) std::swap(u, v);
          edges.push_back({l, u, v});
        }
        ++k;
      }
      // sorted line by line: the lines come in order, so the whole array ends up sorted
      std::sort(edges.begin() + first_of_line, edges.end());
    }
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
  }

  // removes edges with an end of degree 1, repeatedly, then the points without edges
  void remove_dangling_edges()
  {
    for(;;) {
      std::vector<Index> degree(w_.vertex_lines.size(), 0);
      for(const auto& e : w_.edges) { ++degree[e[1]]; ++degree[e[2]]; }
      const std::size_t before = w_.edges.size();
      w_.edges.erase(std::remove_if(w_.edges.begin(), w_.edges.end(),
                                    [&](const auto& e) { return degree[e[1]] == 1 || degree[e[2]] == 1; }),
                     w_.edges.end());
      if(w_.edges.size() == before) break;
    }
    const std::size_t before = w_.vertex_lines.size();
    compact_vertices();
    counts_.removed_points += before - w_.vertex_lines.size();
  }

  // drops points without edges and renumbers
  void compact_vertices()
  {
    std::vector<Index> degree(w_.vertex_lines.size(), 0);
    for(const auto& e : w_.edges) { ++degree[e[1]]; ++degree[e[2]]; }
    std::vector<Index> renumber(w_.vertex_lines.size(), Index(-1));
    std::vector<Point_lines> kept;
    for(Index v = 0; v < w_.vertex_lines.size(); ++v)
      if(degree[v] > 0) { renumber[v] = Index(kept.size()); kept.push_back(std::move(w_.vertex_lines[v])); }
    w_.vertex_lines = std::move(kept);
    for(auto& e : w_.edges) { e[1] = renumber[e[1]]; e[2] = renumber[e[2]]; }
    // lines without edges disappear too
    std::vector<Index> used(w_.lines.size(), Index(-1));
    for(const auto& e : w_.edges) used[e[0]] = 0;
    for(const auto& l : w_.vertex_lines) for(Index x : l) used[x] = 0;
    std::vector<Line_state> lines;
    for(Index l = 0; l < w_.lines.size(); ++l)
      if(used[l] == 0) { used[l] = Index(lines.size()); lines.push_back(w_.lines[l]); }
    w_.lines = std::move(lines);
    for(auto& e : w_.edges) e[0] = used[e[0]];
    for(auto& l : w_.vertex_lines) for(Index& x : l) x = used[x];
  }

  Working_partition& w_;
  Reduction_thresholds t_;
  First_value_map owner_; // the first point met on each pair of lines (key: the two lines)
  Reduction_counts counts_;
  Union_find<Index> line_sets_, vertex_sets_; // the classes of lines and of points merged in a pass
  std::vector<Index> conflicts_;
  std::vector<bool> removed_; // points outside the disk (b2) that apply() removes with their edges
  std::vector<Index> degree_; // edges at each point before the first apply()
  std::vector<bool> moved_;   // lines whose coordinates changed since their edges were made
  bool remake_all_ = true;    // make the edges of every line again (which moved is not known)
  std::vector<std::vector<Index>> class_members_;  // lines of each class (at its root) in a pass
  std::vector<std::vector<Index>> vertex_members_; // points of each class (at its root) in a pass

public:
  // lines (indices at the start of the round) of pairs of distant points sharing two lines
  const std::vector<Index>& conflicts() const { return conflicts_; }
};

// The lines of `after` (the result of `Partition_reducer::run()` on `before`, whose lines
// carry their `members` in `before`) that the reductions changed: merged lines, lines whose
// coefficients changed, and lines whose points or edges changed (points named by their lines,
// and lines by their smallest member, in both partitions).
inline std::vector<bool> changed_lines(const Working_partition& before, const Working_partition& after)
{
  const Index removed = Index(-1), unnamed = Index(-2), long_name = Index(-3);
  std::vector<Index> name(before.lines.size(), removed); // line of `before` -> name
  std::vector<bool> changed(after.lines.size(), false);
  for(Index r = 0; r < after.lines.size(); ++r) {
    const auto& members = after.lines[r].members;
    if(members.empty()) { changed[r] = true; continue; }
    const Index key = *std::min_element(members.begin(), members.end());
    for(Index l : members) name[l] = key;
    changed[r] = members.size() > 1 || after.lines[r].coefficients != before.lines[members[0]].coefficients;
  }
  // A point's name, the sorted distinct names of its lines, as two numbers: {a, b} for two
  // names a < b, {a, a} for one, {long_name, k} for the k-th other one (no line is numbered
  // long_name). The same numbering serves both partitions.
  using Point_name = std::array<Index, 2>;
  std::map<std::vector<Index>, Index> long_names;
  std::vector<Index> buffer;
  auto point_name = [&](const Working_partition& x, Index v, const auto& line_name) -> Point_name {
    buffer.clear();
    for(Index l : x.vertex_lines[v]) buffer.push_back(line_name(l));
    std::sort(buffer.begin(), buffer.end());
    buffer.erase(std::unique(buffer.begin(), buffer.end()), buffer.end());
    if(buffer.size() == 2) return {{buffer[0], buffer[1]}};
    if(buffer.size() == 1) return {{buffer[0], buffer[0]}};
    return {{long_name, long_names.emplace(buffer, Index(long_names.size())).first->second}};
  };
  // Around each line (compressed rows): {0, point name, 0, 0} for each of its points and
  // {1, first point name, second point name} for each of its edges, sorted.
  using Entry = std::array<Index, 5>;
  struct Around { std::vector<Index> first; std::vector<Entry> entries; };
  auto neighbourhoods = [&](const Working_partition& x, const auto& line_name) {
    Around result;
    const std::size_t n = x.lines.size();
    result.first.assign(n + 1, 0);
    for(const auto& l : x.vertex_lines) for(Index line : l) ++result.first[line + 1];
    for(const auto& e : x.edges) ++result.first[e[0] + 1];
    for(std::size_t l = 0; l < n; ++l) result.first[l + 1] += result.first[l];
    result.entries.resize(result.first[n]);
    std::vector<Index> next(result.first.begin(), result.first.end() - 1);
    std::vector<Point_name> names(x.vertex_lines.size());
    for(Index v = 0; v < x.vertex_lines.size(); ++v) {
      names[v] = point_name(x, v, line_name);
      for(Index l : x.vertex_lines[v]) result.entries[next[l]++] = {{0, names[v][0], names[v][1], 0, 0}};
    }
    for(const auto& e : x.edges) {
      const auto& [p, q] = std::minmax(names[e[1]], names[e[2]]);
      result.entries[next[e[0]]++] = {{1, p[0], p[1], q[0], q[1]}};
    }
    for(std::size_t l = 0; l < n; ++l)
      std::sort(result.entries.begin() + result.first[l], result.entries.begin() + result.first[l + 1]);
    return result;
  };
  const Around old_around = neighbourhoods(before, [&](Index l) { return name[l]; });
  const Around new_around = neighbourhoods(after, [&](Index r) {
    return after.lines[r].members.empty() ? unnamed : name[after.lines[r].members[0]];
  });
  for(Index r = 0; r < after.lines.size(); ++r) {
    if(changed[r]) continue;
    const Index l = after.lines[r].members[0];
    changed[r] = !std::equal(old_around.entries.begin() + old_around.first[l],
                             old_around.entries.begin() + old_around.first[l + 1],
                             new_around.entries.begin() + new_around.first[r],
                             new_around.entries.begin() + new_around.first[r + 1]);
  }
  return changed;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_PARTITION_REDUCTIONS_2_H
