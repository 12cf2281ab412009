// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_METRIC_ALPHA_EXPANSION_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_METRIC_ALPHA_EXPANSION_H

// Alpha-expansion (Boykov, Veksler, Zabih 2001) for a labeling energy with a metric pairwise
// term:
//   E(f) = sum_v D(v, f_v) + sum_{edges e = (u, v)} V_e(f_u, f_v),
// D given as a dense matrix unary_costs[vertex][label], V_e by a callable
// pairwise(e, label of u, label of v) -> double that the caller guarantees to be, for each edge,
// a metric in the labels (zero on equal labels, symmetric, triangle inequality; two distinct
// labels may cost zero). CGAL::alpha_expansion_graphcut only takes the Potts model (a cost per
// edge when the labels differ); the lifted model of a partition needs a cost that depends on the
// two labels (the heights of two planes along the edge), hence this class.
//
// An expansion move for a label alpha lets every vertex keep its label or take alpha. Its energy
// is submodular because V_e is a metric, so the best move is a minimum s-t cut (Kolmogorov and
// Zabih 2004 construction), computed by Boost's boykov_kolmogorov_max_flow. The labels are tried
// in index order, and the minimization stops after a cycle over all labels in which no move
// lowered the energy by more than relative_tolerance * |E|. Every accepted move strictly lowers
// the energy, so no labeling comes back and the loop ends. The result is a local minimum for
// expansion moves; when every V_e is a multiple of one metric V, its energy is at most
// 2 max V / min_{a != b} V times the optimum (BVZ 2001, theorem 6.1). The result only depends
// on the input (no randomness, fixed order of the labels and of the graph's vertices and arcs).
//
// Forbidden labels: an infinite unary cost is replaced by a finite cost F (forbidden_cost()),
// larger than the energy of any labeling without forbidden labels plus the largest variation of
// the pairwise term at one vertex. A vertex on a forbidden label that has an allowed one is then
// never left by a local minimum, and F stays of the order of the energies, so that the cuts keep
// their precision (an F near the largest double would absorb every finite cost). Energies
// returned count F for each vertex on a forbidden label (only vertices with no allowed label end
// on one).

#include <CGAL/license/Polygon_partition_simplification.h>

// Boost's adjacency_list and boykov_kolmogorov_max_flow, with the false positives of g++ 12
// silenced in them
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

template <class PairwiseCost>
class Metric_alpha_expansion
{
public:
  using Edge = std::pair<std::size_t, std::size_t>;

  struct Result
  {
    double energy = 0;                 // energy of the final labeling
    std::size_t number_of_cycles = 0;  // cycles over all labels, the last one (no decrease) included
    std::size_t number_of_moves = 0;   // expansion moves that lowered the energy
  };

  // `unary_costs[v][l]`: cost of label l at vertex v (+infinity: forbidden); every row has the
  // same number of labels. `pairwise(e, a, b)`: cost of edge e when its first vertex has label a
  // and its second label b, a metric in (a, b) for each e.
  Metric_alpha_expansion(const std::vector<Edge>& edges,
                         const std::vector<std::vector<double>>& unary_costs,
                         const PairwiseCost& pairwise)
    : edges_(edges), unary_costs_(unary_costs), pairwise_(pairwise),
      number_of_labels_(unary_costs.empty() ? 0 : unary_costs.front().size())
  {
    CGAL_precondition(std::all_of(unary_costs_.begin(), unary_costs_.end(), [this](const std::vector<double>& row) {
      return row.size() == number_of_labels_;
    }));
    CGAL_precondition_msg(std::all_of(unary_costs_.begin(), unary_costs_.end(), [](const std::vector<double>& row) {
      return std::none_of(row.begin(), row.end(), [](double cost) {
        return std::isnan(cost) || cost == -std::numeric_limits<double>::infinity();
      });
    }), "unary costs are finite or +infinity");
    CGAL_precondition(std::all_of(edges_.begin(), edges_.end(), [this](const Edge& edge) {
      return edge.first < unary_costs_.size() && edge.second < unary_costs_.size() && edge.first != edge.second;
    }));
    replace_infinite_costs();
  }

  std::size_t number_of_labels() const { return number_of_labels_; }

  // the finite cost that stands for +infinity (0 when no cost is infinite)
  double forbidden_cost() const { return forbidden_cost_; }

  double energy(const std::vector<std::size_t>& labels) const
  {
    CGAL_precondition(labels.size() == unary_costs_.size());
    double result = 0;
    for(std::size_t v = 0; v < labels.size(); ++v)
      result += unary_costs_[v][labels[v]];
    for(std::size_t e = 0; e < edges_.size(); ++e)
      result += pairwise_(e, labels[edges_[e].first], labels[edges_[e].second]);
    return result;
  }

  // the label of smallest unary cost at each vertex (the smallest such label on ties): a
  // starting labeling
  std::vector<std::size_t> unary_minimum_labels() const
  {
    std::vector<std::size_t> labels(unary_costs_.size(), 0);
    for(std::size_t v = 0; v < labels.size(); ++v)
      labels[v] = std::size_t(std::min_element(unary_costs_[v].begin(), unary_costs_[v].end()) -
                              unary_costs_[v].begin());
    return labels;
  }

  // improves `labels` (one label per vertex, the starting labeling) by expansion moves until a
  // cycle over all labels lowers the energy by no more than relative_tolerance * |E|
  Result minimize(std::vector<std::size_t>& labels, double relative_tolerance = 1e-9) const
  {
    CGAL_precondition(labels.size() == unary_costs_.size() && relative_tolerance >= 0);
    CGAL_precondition(std::all_of(labels.begin(), labels.end(),
                                  [this](std::size_t label) { return label < number_of_labels_; }));
    Result result;
    result.energy = energy(labels);
    std::vector<std::size_t> candidate;
    for(bool lowered = true; lowered;) {
      lowered = false;
      ++result.number_of_cycles;
      for(std::size_t alpha = 0; alpha < number_of_labels_; ++alpha) {
        candidate = labels;
        if(!expand(alpha, candidate))
          continue;
        // the energy of the move is recomputed from the labels, not taken from the flow, so
        // that the acceptance does not depend on the rounding of the cut
        const double candidate_energy = energy(candidate);
        if(candidate_energy < result.energy - relative_tolerance * std::abs(result.energy)) {
          labels.swap(candidate);
          result.energy = candidate_energy;
          ++result.number_of_moves;
          lowered = true;
        }
      }
    }
    return result;
  }

private:
  using Graph_traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
  using Graph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS,
    boost::property<boost::vertex_color_t, boost::default_color_type,
      boost::property<boost::vertex_distance_t, long,
        boost::property<boost::vertex_predecessor_t, Graph_traits::edge_descriptor>>>,
    boost::property<boost::edge_capacity_t, double,
      boost::property<boost::edge_residual_capacity_t, double,
        boost::property<boost::edge_reverse_t, Graph_traits::edge_descriptor>>>>;

  // an arc of capacity `capacity` and its reverse arc of capacity 0, as the max flow needs
  static void add_arc(Graph& graph, std::size_t from, std::size_t to, double capacity)
  {
    const auto forward = boost::add_edge(from, to, graph).first;
    const auto backward = boost::add_edge(to, from, graph).first;
    boost::put(boost::edge_capacity, graph, forward, capacity);
    boost::put(boost::edge_capacity, graph, backward, 0.);
    boost::put(boost::edge_reverse, graph, forward, backward);
    boost::put(boost::edge_reverse, graph, backward, forward);
  }

  // replaces `labels` by the best expansion move of `alpha`; returns whether a label changed.
  // Binary variable x_v = 1 when v takes alpha, i.e. v is on the sink side of the cut; an arc
  // from a to b is paid when a is on the source side and b on the sink side.
  bool expand(std::size_t alpha, std::vector<std::size_t>& labels) const
  {
    const std::size_t n = labels.size(), source = n, sink = n + 1;
    Graph graph(n + 2);
    // E_v(1) - E_v(0) of each vertex, unary terms plus the parts of the pairwise terms that
    // depend on one variable only
    std::vector<double> difference(n, 0.);
    for(std::size_t v = 0; v < n; ++v)
      if(labels[v] != alpha)
        difference[v] = unary_costs_[v][alpha] - unary_costs_[v][labels[v]];
    for(std::size_t e = 0; e < edges_.size(); ++e) {
      const std::size_t u = edges_[e].first, v = edges_[e].second;
      const std::size_t label_u = labels[u], label_v = labels[v];
      if(label_u == alpha && label_v == alpha)
        continue;
      if(label_u == alpha) { // only x_v varies: E(0) = V(alpha, f_v), E(1) = V(alpha, alpha) = 0
        difference[v] -= pairwise_(e, alpha, label_v);
        continue;
      }
      if(label_v == alpha) {
        difference[u] -= pairwise_(e, label_u, alpha);
        continue;
      }
      // E(x_u, x_v) with A = E(0,0), B = E(0,1), C = E(1,0), E(1,1) = 0:
      // A + (C - A) x_u - C x_v + (B + C - A) (1 - x_u) x_v, the last coefficient being >= 0
      // by the triangle inequality (submodularity); rounding may leave it slightly negative.
      const double a = pairwise_(e, label_u, label_v);
      const double b = pairwise_(e, label_u, alpha);
      const double c = pairwise_(e, alpha, label_v);
      const double coupling = b + c - a;
      CGAL_precondition_msg(coupling >= -1e-9 * (std::abs(a) + std::abs(b) + std::abs(c)),
                            "the pairwise cost must satisfy the triangle inequality");
      difference[u] += c - a;
      difference[v] -= c;
      if(coupling > 0)
        add_arc(graph, u, v, coupling);
    }
    for(std::size_t v = 0; v < n; ++v) {
      if(labels[v] == alpha)
        continue;
      if(difference[v] > 0)
        add_arc(graph, source, v, difference[v]);  // paid when v takes alpha
      else if(difference[v] < 0)
        add_arc(graph, v, sink, -difference[v]);   // paid when v keeps its label
    }
    boost::boykov_kolmogorov_max_flow(graph, source, sink);
    // white: the vertices that reach the sink in the residual graph, the smallest sink side of
    // a minimum cut (a vertex free of both trees keeps its label)
    bool changed = false;
    for(std::size_t v = 0; v < n; ++v)
      if(labels[v] != alpha &&
         boost::get(boost::vertex_color, graph, v) == boost::color_traits<boost::default_color_type>::white()) {
        labels[v] = alpha;
        changed = true;
      }
    return changed;
  }

  // F > max_v hi(v) + sum_v (hi(v) - lo(v)) + P, hi and lo the largest and smallest allowed
  // costs of v and P a bound on the pairwise term, so that a labeling with a forbidden label
  // costs more than one without where a vertex has an allowed label. P uses the triangle
  // inequality through label 0: V_e(a, b) <= V_e(a, 0) + V_e(0, b) <= 2 max_c V_e(0, c).
  void replace_infinite_costs()
  {
    const double infinity = std::numeric_limits<double>::infinity();
    bool has_forbidden = false;
    double largest = 0, spans = 0, pairwise_bound = 0;
    for(const std::vector<double>& row : unary_costs_) {
      double lo = infinity, hi = -infinity;
      for(double cost : row) {
        if(cost == infinity) {
          has_forbidden = true;
        } else {
          lo = (std::min)(lo, cost);
          hi = (std::max)(hi, cost);
        }
      }
      if(lo <= hi) {
        largest = (std::max)(largest, std::abs(hi));
        spans += hi - lo;
      }
    }
    if(!has_forbidden)
      return;
    for(std::size_t e = 0; e < edges_.size(); ++e) {
      double edge_bound = 0;
      for(std::size_t c = 1; c < number_of_labels_; ++c)
        edge_bound = (std::max)(edge_bound, pairwise_(e, 0, c));
      pairwise_bound += 2 * edge_bound;
    }
    forbidden_cost_ = 2 * (largest + spans + pairwise_bound) + 1;
    for(std::vector<double>& row : unary_costs_)
      for(double& cost : row)
        if(cost == infinity)
          cost = forbidden_cost_;
  }

  std::vector<Edge> edges_;
  std::vector<std::vector<double>> unary_costs_;
  PairwiseCost pairwise_;
  std::size_t number_of_labels_;
  double forbidden_cost_ = 0;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_METRIC_ALPHA_EXPANSION_H
