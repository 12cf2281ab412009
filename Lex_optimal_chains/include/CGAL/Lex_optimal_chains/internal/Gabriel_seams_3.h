// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_GABRIEL_SEAMS_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_GABRIEL_SEAMS_3_H

// The seams between tiles made of edges that every tile can impose. A tile imposes each edge
// of its cycle on the Delaunay triangulation of its points by removing the input points in
// the edge's closed diametral ball (remove_blocking_points): the edge is then a Gabriel edge,
// hence a Delaunay edge, unless another vertex of the cycle lies in that ball, which cannot be
// removed. In a dense scan two consecutive seam points can be a millimetre apart in xy and
// centimetres apart in z (on a wall, or in the noise): the ball of their edge then reaches the
// next seam points.
//
// Here every seam edge pq whose closed diametral ball holds another seam point t (of any seam:
// the seams of a tile's cycle are among them) is split at the orthogonal projection m of t on
// pq, in rounds, until no ball holds one. t in the ball means that the angle ptq is 90 degrees
// or more, so m lies strictly inside pq; the angles pmt and qmt are right, so t lies outside
// the balls of pm and mq. (A split at the midpoint would not do: where a seam climbs a wall
// and comes back down, the two edges at the top make a small angle, and their halves would
// take each other's points in turn forever; split at the projections, the points of both
// edges sit at matching distances from the top.) With several such points, the one whose
// projection is nearest to the middle of pq is taken. The added points lie on the edges: the
// seams keep their course in the plane, so the tiles keep their regions, and each added point
// is a seam point of the tiles on both sides. The edges to the frame are not split (the frame
// is a spacing away from the points, and its triangles are dropped). The test is exact
// (Side_of_bounded_sphere_3).

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// A seam, from the frame to the frame; `nodes[k]` is the index in `points` of its k-th node.
template <class Point>
struct Seam_polyline
{
  std::vector<Point> points;
  std::vector<std::size_t> nodes;
};

template <class Point>
class Gabriel_seams_3
{
  using Kernel = typename Kernel_traits<Point>::Kernel;

public:
  // `spacing`: the seam spacing, the cell size of the grid that finds the points near an edge
  Gabriel_seams_3(const std::vector<Seam_polyline<Point>*>& lines, double spacing) : lines_(lines), cell_(spacing) {}

  // Splits until no seam edge but those to the frame has a seam point in its closed
  // diametral ball; returns the number of points added.
  std::size_t split_until_gabriel()
  {
    std::size_t added = 0;
    for(int round = 0;; ++round) {
      build_grid();
      std::vector<std::vector<double>> split(lines_.size()); // per edge, where to split it (0: not)
      std::size_t count = 0;
      for(std::size_t l = 0; l < lines_.size(); ++l) {
        const std::vector<Point>& points = lines_[l]->points;
        split[l].assign(points.size(), 0.);
        for(std::size_t k = 1; k + 2 < points.size(); ++k) { // not the first and last edges: the frame
          split[l][k] = split_parameter(points[k], points[k + 1]);
          if(split[l][k] > 0) ++count;
        }
      }
      if(count == 0) return added;
      if(round == max_rounds)
        throw Input_error(Input_error_code::INVALID_PARAMETER,
                          "the seams between tiles could not be made of edges that the tiles can impose (" +
                            std::to_string(count) + " edges left after " + std::to_string(max_rounds) +
                            " rounds of splits): give a larger seam spacing");
      for(std::size_t l = 0; l < lines_.size(); ++l) added += split_marked(*lines_[l], split[l]);
    }
  }

private:
  static constexpr int max_rounds = 60;

  using Cell = std::pair<std::int64_t, std::int64_t>;

  Cell cell_of(double x, double y) const
  {
    return {std::int64_t(std::floor(x / cell_)), std::int64_t(std::floor(y / cell_))};
  }

  // every seam point, by the cell of the grid that holds it in the xy-plane
  void build_grid()
  {
    grid_.clear();
    for(const Seam_polyline<Point>* line : lines_)
      for(const Point& p : line->points) grid_.emplace_back(cell_of(p.x(), p.y()), &p);
    std::sort(grid_.begin(), grid_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  }

  // Where to split pq, as a parameter in (0, 1) along it: the projection of the seam point in
  // the closed ball of diameter pq whose projection is nearest to the middle (ties: the
  // smaller point); 0 when no seam point other than p and q lies in that ball.
  double split_parameter(const Point& p, const Point& q) const
  {
    const double r = 0.5 * std::sqrt(CGAL::squared_distance(p, q));
    const double cx = 0.5 * (p.x() + q.x()), cy = 0.5 * (p.y() + q.y());
    const Cell low = cell_of(cx - r, cy - r), high = cell_of(cx + r, cy + r);
    const auto side = typename Kernel::Side_of_bounded_sphere_3();
    const double dx = q.x() - p.x(), dy = q.y() - p.y(), dz = q.z() - p.z();
    const double length2 = dx * dx + dy * dy + dz * dz;
    double best = 0;
    const Point* best_point = nullptr;
    for(std::int64_t i = low.first; i <= high.first; ++i) {
      auto it = std::lower_bound(grid_.begin(), grid_.end(), Cell(i, low.second),
                                 [](const auto& entry, const Cell& c) { return entry.first < c; });
      for(; it != grid_.end() && it->first <= Cell(i, high.second); ++it) {
        const Point& t = *it->second;
        if(t == p || t == q || side(p, q, t) == ON_UNBOUNDED_SIDE) continue;
        // strictly inside (0, 1) in exact terms; kept off the ends in floating point, by as
        // little as keeps the split point apart from them: a split kept 1% away from an end,
        // where the projection is nearer to it, leaves t in the ball of the longer part
        const double u = std::clamp(((t.x() - p.x()) * dx + (t.y() - p.y()) * dy + (t.z() - p.z()) * dz) / length2, 1e-6, 1 - 1e-6);
        if(best_point == nullptr || std::abs(u - 0.5) < std::abs(best - 0.5) ||
           (std::abs(u - 0.5) == std::abs(best - 0.5) && t < *best_point)) {
          best = u;
          best_point = &t;
        }
      }
    }
    return best;
  }

  // splits each edge (k, k + 1) with a parameter `at[k]` > 0 there; keeps the nodes at their points
  static std::size_t split_marked(Seam_polyline<Point>& line, const std::vector<double>& at)
  {
    std::vector<Point> points;
    std::vector<std::size_t> new_index(line.points.size());
    for(std::size_t k = 0; k < line.points.size(); ++k) {
      new_index[k] = points.size();
      points.push_back(line.points[k]);
      if(!(at[k] > 0)) continue;
      const Point& p = line.points[k];
      const Point& q = line.points[k + 1];
      const double u = at[k];
      const Point m(p.x() + u * (q.x() - p.x()), p.y() + u * (q.y() - p.y()), p.z() + u * (q.z() - p.z()));
      // strictly between p and q in x and in y, unless they share it: the seam stays monotone
      auto between = [](double a, double b, double c) { return a == b || (c > (std::min)(a, b) && c < (std::max)(a, b)); };
      if(!between(p.x(), q.x(), m.x()) || !between(p.y(), q.y(), m.y()))
        throw Input_error(Input_error_code::INVALID_PARAMETER,
                          "two seam points are too close to be split further: give a larger seam spacing");
      points.push_back(m);
    }
    for(std::size_t& n : line.nodes) n = new_index[n];
    const std::size_t added = points.size() - line.points.size();
    line.points = std::move(points);
    return added;
  }

  std::vector<Seam_polyline<Point>*> lines_;
  double cell_;
  std::vector<std::pair<Cell, const Point*>> grid_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_GABRIEL_SEAMS_3_H
