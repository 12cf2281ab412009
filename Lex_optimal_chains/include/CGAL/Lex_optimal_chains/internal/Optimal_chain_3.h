// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPTIMAL_CHAIN_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPTIMAL_CHAIN_3_H

#include <CGAL/Lex_optimal_chains/Open_surface_report.h>
#include <CGAL/Lex_optimal_chains/Coefficient_field.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Geom_traits_check.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_arithmetic.h>
#include <CGAL/Lex_optimal_chains/internal/Homologous_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Representative_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <algorithm>
#include <cstdint>
#include <functional>
#include <iostream>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The finite facet of `dt` with vertices (a, b, c), as (cell, index), and true if (a, b, c)
// is oriented outward of that cell; throws INVALID_CHAIN if it is not a finite facet.
template <class Triangulation>
std::pair<typename Triangulation::Facet, bool>
oriented_facet(const Triangulation& dt, typename Triangulation::Vertex_handle a,
               typename Triangulation::Vertex_handle b, typename Triangulation::Vertex_handle c)
{
  typename Triangulation::Cell_handle cell;
  int i, j, k;
  if(dt.is_infinite(a) || dt.is_infinite(b) || dt.is_infinite(c) || !dt.is_facet(a, b, c, cell, i, j, k))
    throw Input_error(Input_error_code::INVALID_CHAIN, "a triangle of the chain is not a finite facet of the triangulation");
  const int f = 6 - i - j - k;
  // outward of `cell`: ((f+1)&3, (f+2)&3, (f+3)&3), the last two swapped when f is odd
  int o[3] = {(f + 1) & 3, (f + 2) & 3, (f + 3) & 3};
  if(f & 1) std::swap(o[1], o[2]);
  // (i, j, k) is outward iff it is a rotation of o
  const bool outward = (i == o[0] && j == o[1]) || (i == o[1] && j == o[2]) || (i == o[2] && j == o[0]);
  return {typename Triangulation::Facet(cell, f), outward};
}

// Writes the chain of `lexicographic_homologous_chain()` (record codes and coefficients) to
// `out` as (facet, coefficient) with a positive coefficient: the facet is oriented outward of
// the owner for a positive coefficient, of the other cell for a negative one (without signs:
// outward of the owner, with the coefficient as it is).
template <class Arithmetic, class Triangulation, class OutputIterator>
void write_chain(const Triangulation& dt, const Handle_index_map<typename Triangulation::Cell>& cells,
                 const Dual_edge_records& chain, OutputIterator out, Open_surface_report& report)
{
  using Facet = typename Triangulation::Facet;
  auto& container = const_cast<typename Triangulation::Triangulation_data_structure&>(dt.tds()).cells();
  report.number_of_facets = chain.size();
  for(std::size_t i = 0; i < chain.size(); ++i) {
    if(i + 8 < chain.size()) prefetch_object(cells.element(chain[i + 8].owner >> 2));
    const Dual_edge_record& entry = chain[i];
    const auto owner =
      container.iterator_to(*const_cast<typename Triangulation::Cell*>(cells.element(entry.owner >> 2)));
    const int j = int(entry.owner & 3);
    const std::int64_t k = Arithmetic::to_integer(chain_coefficient<Arithmetic>(entry));
    if(Arithmetic::has_signs && k != 1 && k != -1) ++report.number_of_multiple_facets;
    if(!Arithmetic::has_signs || k > 0) *out++ = std::make_pair(Facet(owner, j), k);
    else *out++ = std::make_pair(Facet(owner->neighbor(j), owner->neighbor(j)->index(owner)), -k);
  }
}

template <class Triangulation>
void check_dimension(const Triangulation& dt)
{
  if(dt.dimension() < 3)
    throw Input_error(dt.number_of_vertices() < 4 ? Input_error_code::TOO_FEW_POINTS : Input_error_code::DEGENERATE_POINT_SET,
                      dt.number_of_vertices() < 4 ? "fewer than 4 distinct points: the triangulation has no tetrahedron"
                                                  : "all points are coplanar: the triangulation has no tetrahedron");
}

// The part common to both public functions once Gamma0 is known as oriented triangles or
// facets: map Gamma0 and B to records, contract and sort (internal/Homologous_chain_3.h), run
// Algorithm 10.
template <class Arithmetic, class Triangulation, class NamedParameters, class AddGamma0, class OutputIterator>
void optimal_chain(const Triangulation& dt, const NamedParameters& np, const AddGamma0& add_gamma0,
                   const std::function<bool(double)>& callback, double progress_from, OutputIterator out,
                   Open_surface_report& report)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Graph = Sorted_dual_graph_3<Triangulation>;
  using Facet = typename Triangulation::Facet;
  using Value = typename Arithmetic::Value;
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const double span = 1.0 - progress_from;
  Stopwatch watch;
  const Handle_index_map<typename Triangulation::Cell> cells(dt.tds().cells().begin(), dt.tds().cells().end());
  Graph::check_number_of_cells(cells.size()); // before any record code is made
  report.number_of_vertices = dt.number_of_vertices();
  report.number_of_triangles = Graph::number_of_finite_facets(dt);
  Record_values<Value> gamma0(cells.size());
  add_gamma0([&](const Facet& f, std::int64_t k) {
    if(dt.is_infinite(f))
      throw Input_error(Input_error_code::INVALID_CHAIN, "a facet of the chain has the infinite vertex");
    const auto code = Graph::record_code(dt, cells, f.first, f.second);
    const Value v = Arithmetic::from_integer(k);
    gamma0.template add<Arithmetic>(code.first, code.second ? Arithmetic::negate(v) : v);
  });
  Record_values<std::uint8_t> relative(cells.size());
  const std::vector<Facet> no_facets;
  // a copy: CGAL 5.5 returns the parameter by value, a reference to it would dangle
  const auto relative_range = choose_parameter(get_parameter(np, Lex_optimal_chains::internal_np::relative_facets), no_facets);
  for(const Facet& f : relative_range) {
    if(dt.is_infinite(f))
      throw Input_error(Input_error_code::INVALID_CHAIN, "a facet of the subcomplex B has the infinite vertex");
    relative.template add<Z2_arithmetic>(Graph::record_code(dt, cells, f.first, f.second).first, 1);
  }
  report.number_of_relative_triangles = relative.values().size();
  std::vector<std::uint32_t> infinite;
  {
    std::vector<typename Triangulation::Cell_handle> hull;
    dt.incident_cells(dt.infinite_vertex(), std::back_inserter(hull));
    for(const auto& c : hull) infinite.push_back(cells.index(&*c));
  }

  Contracted_homologous_graph_3<Arithmetic, Triangulation> contracted(
    dt, cells, infinite, gamma0, relative, Stage_progress{&callback, progress_from, progress_from + 0.7 * span},
    parameters::choose_parameter(parameters::get_parameter(np, Lex_optimal_chains::internal_np::number_of_threads), 1u));
  report_order_statistics(contracted, watch.lap(), report);
  if(verbose)
    std::cerr << "Lex_optimal_chains: contracted the cells across their largest facets ("
              << contracted.number_of_exact_comparisons() << " comparisons made exactly), then ordered the "
              << contracted.graph().records().size() << " of " << report.number_of_triangles
              << " triangles between components or with a non-zero intersection product in " << report.order_seconds
              << " s\n";
  // the chain is written over the sorted facets
  const Dual_edge_records chain = lexicographic_homologous_chain<Arithmetic>(
    contracted.graph(), contracted.sets(), gamma0, relative, Stage_progress{&callback, progress_from + 0.7 * span, 1.0});
  // the disjoint sets and the graph freed before the output grows: peak memory
  contracted.release_sets();
  contracted.release_graph();
  report.optimal_chain_seconds = watch.lap();
  if(verbose)
    std::cerr << "Lex_optimal_chains: optimal chain of " << chain.size() << " triangles in "
              << report.optimal_chain_seconds << " s\n";
  write_chain<Arithmetic>(dt, cells, chain, out, report);
  report.output_seconds += watch.lap();
}

template <class NamedParameters>
Coefficient_field coefficient_field_of(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, Lex_optimal_chains::internal_np::coefficient_field),
                                      Coefficient_field::Q);
}

// Algorithm 11 then Algorithm 10 for the cycle given as (source, target) vertex pairs.
template <class Arithmetic, class Triangulation, class EdgeRange, class NamedParameters, class OutputIterator>
void optimal_chain_with_boundary(const Triangulation& dt, const EdgeRange& cycle, const NamedParameters& np,
                                 const std::function<bool(double)>& callback, double progress_from,
                                 OutputIterator out, Open_surface_report& report)
{
  using Representative = Representative_chain_3<Triangulation, Arithmetic>;
  Stopwatch watch;
  std::vector<typename Representative::Edge> edges;
  for(const auto& e : cycle) edges.push_back({e.first, e.second, Arithmetic::from_integer(1)});
  const Representative representative(dt, edges);
  report.number_of_swept_vertices = representative.number_of_swept_vertices();
  report.number_of_representative_triangles = representative.chain().size();
  report.representative_seconds = watch.lap();
  optimal_chain<Arithmetic>(dt, np, [&](const auto& add) {
      for(const auto& t : representative.chain()) {
        const auto f = oriented_facet(dt, t.vertices[0], t.vertices[1], t.vertices[2]);
        add(f.first, f.second ? Arithmetic::to_integer(t.coefficient) : -Arithmetic::to_integer(t.coefficient));
      }
    }, callback, progress_from, out, report);
}

// Algorithm 11 then Algorithm 10 over Z2 for each cycle of `cycles` (each given as
// (source, target) vertex pairs), the cycles 64 at a time: in each group, bit i of every
// value stands for cycle i (Z2_word_arithmetic), so that one run of the two algorithms makes
// 64 chains, each the one that a run for its cycle alone makes. `np` as for
// `lex_optimal_chain_with_boundary()` (its relative facets, threads and verbosity). Returns
// the facets of each chain, in decreasing order.
template <class Triangulation, class Cycle, class NamedParameters>
std::vector<std::vector<typename Triangulation::Facet>>
optimal_chains_with_boundaries(const Triangulation& dt, const std::vector<Cycle>& cycles, const NamedParameters& np)
{
  using Arithmetic = Z2_word_arithmetic;
  using Representative = Representative_chain_3<Triangulation, Arithmetic>;
  constexpr std::size_t group = 64;
  std::vector<std::vector<typename Triangulation::Facet>> chains(cycles.size());
  const std::function<bool(double)> no_callback;
  for(std::size_t first = 0; first < cycles.size(); first += group) {
    const std::size_t count = (std::min)(group, cycles.size() - first);
    std::vector<typename Representative::Edge> edges;
    for(std::size_t i = 0; i < count; ++i)
      for(const auto& e : cycles[first + i]) edges.push_back({e.first, e.second, Arithmetic::Value(1) << i});
    const Representative representative(dt, edges);
    std::vector<std::pair<typename Triangulation::Facet, std::int64_t>> chain;
    Open_surface_report report;
    optimal_chain<Arithmetic>(dt, np, [&](const auto& add) {
        for(const auto& t : representative.chain()) // no signs: the orientation does not matter
          add(oriented_facet(dt, t.vertices[0], t.vertices[1], t.vertices[2]).first, Arithmetic::to_integer(t.coefficient));
      }, no_callback, 0.0, std::back_inserter(chain), report);
    for(const auto& [facet, bits] : chain)
      for(std::size_t i = 0; i < count; ++i)
        if(Arithmetic::Value(bits) >> i & 1) chains[first + i].push_back(facet);
  }
  return chains;
}

// The frame of the public functions on a triangulation: the callback, the checks, the timing,
// and the choice of the coefficients; `run(arithmetic, callback, report)` does the work.
template <class Triangulation, class NamedParameters, class Run>
Open_surface_report run_on_triangulation(const Triangulation& dt, const NamedParameters& np, const Run& run)
{
  static_assert(internal::Has_double_coordinates<typename Triangulation::Geom_traits>::value, "");
  const std::function<bool(double)> callback = parameters::choose_parameter(
    parameters::get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  Open_surface_report report;
  Stopwatch total;
  check_dimension(dt);
  if(coefficient_field_of(np) == Coefficient_field::Z2) run(Z2_arithmetic(), callback, report);
  else run(Integer_arithmetic(), callback, report);
  report_progress(callback, 1.0); // after the output iterator was written: false still cancels
  report.total_seconds = total.lap();
  return report;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_OPTIMAL_CHAIN_3_H
