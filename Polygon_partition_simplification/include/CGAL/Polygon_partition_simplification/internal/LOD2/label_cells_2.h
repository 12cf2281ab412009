// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LABEL_CELLS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LABEL_CELLS_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/internal/LOD2/Cell_arrangement_2.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/Height_functions.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/facade_evidence_3.h>
#include <CGAL/Polygon_partition_simplification/internal/LOD2/runs_along_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Metric_alpha_expansion.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The settings of the lift, in input units.
struct Lift_settings
{
  double height_threshold = 1;        ///< epsilon of Eq. 3.1
  double regularization_length = 1;   ///< mu of the lift energy
  double facade_weight = 0.25;        ///< factor of the smoothness on edges along facade segments
  double minimum_building_height = 1; ///< a roof is at least this high above the ground at every corner
  /// an edge within this distance of a facade segment is along it; also the step of the facade samples
  double facade_distance = 0.5;
  std::size_t facade_samples = 2;     ///< samples in front of and behind every facade point (0: none)
  /// a roof label is refuted in a cell when more than this fraction of the cell's points lie
  /// more than `height_threshold` below its plane
  double refuting_fraction = 0.25;
  /// in a cell where a roof label is refuted, a point below its plane costs its depth up to this
  /// fraction of the plane's height above the ground (instead of `height_threshold`)
  double refuting_depth = 0.5;
  /// the points are those of one building (classified input): the ground label is refuted in a
  /// cell as a roof label is, by its points high above the ground (see lift_data_term())
  bool points_refute_ground = false;
};

/// An edge of the cell arrangement for the lift: its two cells, its ends, its weight.
struct Lift_edge
{
  std::size_t left = 0, right = 0; ///< the cells on both sides (`Cell_arrangement_2::no_cell` outside)
  std::array<double, 2> source{{0, 0}}, target{{0, 0}};
  double weight = 0; ///< mu * p_e * length
};

/// the edges of the arrangement for the lift, each once, in the arrangement's order
template <class Segment2Range>
std::vector<Lift_edge> lift_edges(const Cell_arrangement_2& cells, const Segment2Range& facades,
                                  const Lift_settings& settings)
{
  std::vector<Lift_edge> edges;
  for(auto e = cells.arrangement.edges_begin(); e != cells.arrangement.edges_end(); ++e) {
    Lift_edge edge;
    edge.left = e->face()->data();
    edge.right = e->twin()->face()->data();
    if(edge.left == edge.right) continue;
    edge.source = {e->source()->point().x(), e->source()->point().y()};
    edge.target = {e->target()->point().x(), e->target()->point().y()};
    const double length = std::hypot(edge.target[0] - edge.source[0], edge.target[1] - edge.source[1]);
    const double prior = runs_along(edge.source, edge.target, facades, settings.facade_distance)
                           ? settings.facade_weight : 1.0;
    edge.weight = settings.regularization_length * prior * length;
    edges.push_back(edge);
  }
  return edges;
}

/// V_e of Eq. 3.2 for labels a and b (without mu p_e length)
inline double mean_height_difference(const Height_functions& heights, const Lift_edge& edge, std::size_t a,
                                     std::size_t b)
{
  return 0.5 * (std::abs(heights.height(a, edge.source) - heights.height(b, edge.source)) +
                std::abs(heights.height(a, edge.target) - heights.height(b, edge.target)));
}

/// The evidence of the lift, each item with its cell: the points above the cells (roofs, ground,
/// clutter; not the facades) and the samples of `Facade_evidence_3`.
struct Lift_evidence
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::size_t> cell_of_point;
  std::vector<bool> open_above; // per point, if known: nothing was seen above it (open_above())
  Facade_evidence_3 facades;
  std::vector<std::size_t> cell_in_front, cell_behind;
};

/// Per point of `points`: whether it is open to the sky as an aerial scan sees it, that is,
/// within `tolerance` of the highest point of its square of side `step` (a grid in xy). The
/// ground of a courtyard is; the lower points of a wall, or points under an eave, are not.
inline std::vector<bool> open_above(const std::vector<std::array<double, 3>>& points, double step, double tolerance)
{
  std::vector<bool> result(points.size(), true);
  if(points.empty() || !(step > 0)) return result;
  double x0 = points[0][0], y0 = points[0][1];
  for(const auto& p : points) x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]);
  auto key = [&](const std::array<double, 3>& p) {
    return std::make_pair(std::int64_t(std::floor((p[0] - x0) / step)), std::int64_t(std::floor((p[1] - y0) / step)));
  };
  std::map<std::pair<std::int64_t, std::int64_t>, double> highest;
  for(const auto& p : points) {
    auto [it, inserted] = highest.emplace(key(p), p[2]);
    if(!inserted) it->second = std::max(it->second, p[2]);
  }
  for(std::size_t i = 0; i < points.size(); ++i) result[i] = points[i][2] >= highest.at(key(points[i])) - tolerance;
  return result;
}

/// the data term of Eq. 3.1 for every cell and label: the area of the cell times the mean
/// residual of its evidence, where a point costs its vertical distance to the label's plane, a
/// sample in front of a facade the height of the plane above it and a sample behind a facade
/// the height of the plane below it, each at most `height_threshold`. A cell without evidence
/// costs nothing on the ground and `height_threshold * area` on a roof (no evidence of a
/// building); a roof label whose plane is less than `minimum_building_height` above the ground
/// at a corner of the cell is forbidden (+infinity).
///
/// An aerial scan sees nothing below a roof: when more than `refuting_fraction` of the points of
/// a cell are open above (`Lift_evidence::open_above`) and lie more than `height_threshold`
/// below a roof label's plane (a courtyard under the roof of its wings), each of them costs its
/// depth up to `refuting_depth` times the height of the plane above the ground. The evidence of an open yard then grows with the height of its
/// walls, as the cost of the walls does (V_e of Eq. 3.2), instead of staying at
/// `height_threshold` per point, which roofs over every square yard narrower than
/// 4 `mu` / `height_threshold` times the height of its walls (1.6 times with the default
/// settings) unless its walls are seen as facades.
///
/// With `points_refute_ground` (the points of one classified building, no clutter among them),
/// the ground label is refuted the same way by the points open above that lie more than
/// `height_threshold` above the ground: each costs `refuting_depth` times its height. A small
/// cell of roof points at a corner of a building, whose two outer edges are longer than the
/// edge it shares with the roof, otherwise costs less as ground (its area times
/// `height_threshold`, and the wall along the shorter edge) and the model loses the corner.
/// Without classes, points high above the ground may be trees, which this would make roofs.
inline std::vector<std::vector<double>> lift_data_term(const Cell_arrangement_2& cells, const Lift_evidence& evidence,
                                                       const Height_functions& heights, const Lift_settings& settings)
{
  const std::size_t labels = heights.number_of_labels();
  std::vector<std::vector<double>> cost(cells.number_of_cells(), std::vector<double>(labels, 0));
  std::vector<std::size_t> count(cells.number_of_cells(), 0);
  // per cell and label: the cost with the points below a roof plane at their depth, and the
  // number of these points
  std::vector<std::vector<double>> refuted_cost(cells.number_of_cells(), std::vector<double>(labels, 0));
  std::vector<std::vector<std::size_t>> refuting(cells.number_of_cells(), std::vector<std::size_t>(labels, 0));
  // `below` and `above` weigh the plane's height below and above the sample; `points`: the
  // samples are points seen from above
  auto add = [&](const std::vector<std::array<double, 3>>& samples, const std::vector<std::size_t>& cell_of_sample,
                 double below, double above, bool points) {
    for(std::size_t i = 0; i < samples.size(); ++i) {
      const std::size_t c = cell_of_sample[i];
      if(c == Cell_arrangement_2::no_cell) continue;
      ++count[c];
      const std::array<double, 2> xy{{samples[i][0], samples[i][1]}};
      const double ground = heights.height(Height_functions::ground_label, xy);
      for(std::size_t l = 0; l < labels; ++l) {
        const double plane = heights.height(l, xy), difference = plane - samples[i][2];
        const double residual = difference > 0 ? above * difference : -below * difference;
        cost[c][l] += std::min(settings.height_threshold, residual);
        double cap = settings.height_threshold;
        if(points && !evidence.open_above.empty() && evidence.open_above[i] && l != Height_functions::ground_label &&
           difference > settings.height_threshold) {
          cap = std::max(cap, settings.refuting_depth * (plane - ground));
          ++refuting[c][l];
        }
        if(settings.points_refute_ground && points && !evidence.open_above.empty() && evidence.open_above[i] &&
           l == Height_functions::ground_label && -difference > settings.height_threshold) {
          cap = std::max(cap, settings.refuting_depth * (-difference));
          ++refuting[c][l];
        }
        refuted_cost[c][l] += std::min(cap, residual);
      }
    }
  };
  add(evidence.points, evidence.cell_of_point, 1, 1, true);
  add(evidence.facades.in_front, evidence.cell_in_front, 0, 1, false);
  add(evidence.facades.behind, evidence.cell_behind, 1, 0, false);
  for(std::size_t c = 0; c < cells.number_of_cells(); ++c) {
    double area = 0;
    for(const auto& ring : cells.rings[c]) {
      for(std::size_t i = 0; i < ring.size(); ++i) {
        const auto& p = ring[i];
        const auto& q = ring[(i + 1) % ring.size()];
        area += 0.5 * (p.x() * q.y() - q.x() * p.y());
      }
    }
    for(std::size_t l = 0; l < labels; ++l) {
      if(double(refuting[c][l]) > settings.refuting_fraction * double(count[c])) cost[c][l] = refuted_cost[c][l];
      cost[c][l] = count[c] > 0 ? area * cost[c][l] / double(count[c])
                                : (l == Height_functions::ground_label ? 0 : area * settings.height_threshold);
      for(const auto& ring : cells.rings[c])
        for(const auto& p : ring) {
          const std::array<double, 2> xy{{p.x(), p.y()}};
          if(l != Height_functions::ground_label &&
             heights.height(l, xy) < heights.height(Height_functions::ground_label, xy) + settings.minimum_building_height)
            cost[c][l] = std::numeric_limits<double>::infinity();
        }
    }
  }
  return cost;
}

/// the label of every cell (section 3.2.3): the ground or a roof plane, minimizing
/// sum_C E_C + mu sum_e V_e by alpha-expansion; the outside of the partition is ground
inline std::vector<std::size_t> label_cells(const Cell_arrangement_2& cells, const std::vector<Lift_edge>& edges,
                                            std::vector<std::vector<double>> cost, const Height_functions& heights)
{
  const std::size_t none = Cell_arrangement_2::no_cell;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> edges_of_pair;
  for(std::size_t e = 0; e < edges.size(); ++e) {
    const Lift_edge& edge = edges[e];
    if(edge.left == none || edge.right == none) { // against the outside, which is ground
      const std::size_t c = edge.left == none ? edge.right : edge.left;
      for(std::size_t l = 0; l < heights.number_of_labels(); ++l)
        cost[c][l] += edge.weight * mean_height_difference(heights, edge, l, Height_functions::ground_label);
      continue;
    }
    edges_of_pair[{std::min(edge.left, edge.right), std::max(edge.left, edge.right)}].push_back(e);
  }
  std::vector<std::pair<std::size_t, std::size_t>> graph_edges;
  std::vector<std::vector<std::size_t>> arrangement_edges;
  for(auto& entry : edges_of_pair) {
    graph_edges.push_back(entry.first);
    arrangement_edges.push_back(std::move(entry.second));
  }
  auto pairwise = [&](std::size_t g, std::size_t a, std::size_t b) {
    double sum = 0;
    if(a != b)
      for(std::size_t e : arrangement_edges[g]) sum += edges[e].weight * mean_height_difference(heights, edges[e], a, b);
    return sum;
  };
  std::vector<std::size_t> labels(cells.number_of_cells(), Height_functions::ground_label);
  for(std::size_t c = 0; c < labels.size(); ++c)
    labels[c] = std::size_t(std::min_element(cost[c].begin(), cost[c].end()) - cost[c].begin());
  Metric_alpha_expansion<decltype(pairwise)> expansion(graph_edges, cost, pairwise);
  expansion.minimize(labels);
  return labels;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LOD2_LABEL_CELLS_2_H
