// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_HOMOLOGOUS_CHAIN_H
#define CGAL_LEX_OPTIMAL_HOMOLOGOUS_CHAIN_H

/// \file lex_optimal_homologous_chain.h
/// Lexicographic optimal 2-chains of a 3D Delaunay triangulation homologous to a given chain,
/// or bounded by a given 1-cycle, absolute or relative (thesis sections 4.5 and 4.6).

#include <CGAL/Lex_optimal_chains/Coefficient_field.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_arithmetic.h>
#include <CGAL/Lex_optimal_chains/internal/Homologous_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Representative_chain_3.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstdint>
#include <functional>
#include <iostream>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
What an open-surface computation did: sizes, timings and the topology of the output. Fields
that a function does not compute stay at zero.
*/
struct Open_surface_report
{
  std::size_t number_of_input_points = 0;        ///< points given (reconstruction only)
  std::size_t number_of_boundary_vertices = 0;   ///< boundary vertices that are not input points (reconstruction only)
  std::size_t number_of_removed_points = 0;      ///< input points removed so that the boundary is in the triangulation
  std::size_t number_of_vertices = 0;            ///< vertices of the triangulation
  std::size_t number_of_triangles = 0;           ///< finite facets of the triangulation (dual edges)
  std::size_t number_of_triangles_in_close_runs = 0;   ///< triangles whose fast keys were too close to be ordered by them
  std::size_t number_of_exactly_ordered_triangles = 0; ///< of those, triangles ordered by the exact comparator
  std::size_t number_of_relative_triangles = 0;  ///< triangles of the subcomplex B
  std::size_t number_of_swept_vertices = 0;      ///< vertices handled by Algorithm 11
  std::size_t number_of_representative_triangles = 0; ///< triangles of the representative chain
  std::size_t number_of_facets = 0;              ///< triangles of the optimal chain
  std::size_t number_of_multiple_facets = 0;     ///< of those, triangles whose coefficient is not 1 or -1 (Q only)
  std::size_t resolved_non_manifold_vertices = 0; ///< local changes of the chain that made a non-manifold vertex manifold (reconstruction only)
  std::size_t resolution_changed_facets = 0;     ///< triangles in the symmetric difference of the optimal chain and the output chain (reconstruction only)
  double delaunay_seconds = 0;                   ///< time to build the Delaunay triangulation
  double representative_seconds = 0;             ///< time of Algorithm 11
  double order_seconds = 0;                      ///< time to contract the dual graph and sort the triangles left
  double optimal_chain_seconds = 0;              ///< time of Algorithm 10
  double resolution_seconds = 0;                 ///< time to find and resolve the non-manifold vertices (reconstruction only)
  double output_seconds = 0;                     ///< time to write the chain (and to build the mesh, for a reconstruction)
  double total_seconds = 0;                      ///< time of the whole call
  std::size_t mesh_vertices = 0;                 ///< vertices of the output mesh (reconstruction only)
  std::size_t mesh_faces = 0;                    ///< faces of the output mesh (reconstruction only)
  std::size_t dropped_triangles = 0;             ///< triangles dropped because they touch a boundary-only vertex
  std::size_t non_manifold_vertices = 0;         ///< vertex copies added to separate umbrellas: the non-manifold vertices left by the resolution, or all with `keep_non_manifold` (reconstruction only)
  std::size_t non_manifold_edges = 0;            ///< edges of more than two triangles of the output chain, split in the mesh (reconstruction only)
  std::size_t orientation_cuts = 0;              ///< edges cut to orient the mesh: over Z2, where the chain is not orientable (reconstruction only)
};

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
// the owner for a positive coefficient, of the other cell for a negative one.
template <class Arithmetic, class Triangulation, class OutputIterator>
void write_chain(const Triangulation& dt, const Handle_index_map<typename Triangulation::Cell>& cells,
                 const std::vector<Dual_edge_record>& chain, OutputIterator out, Open_surface_report& report)
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
    if(k != 1 && k != -1) ++report.number_of_multiple_facets;
    if(k > 0) *out++ = std::make_pair(Facet(owner, j), k);
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
    dt, cells, infinite, gamma0, relative, Stage_progress{&callback, progress_from, progress_from + 0.7 * span});
  report_order_statistics(contracted, watch.lap(), report);
  if(verbose)
    std::cerr << "Lex_optimal_chains: contracted the cells across their largest facets ("
              << contracted.number_of_exact_comparisons() << " comparisons made exactly), then ordered the "
              << contracted.graph().records().size() << " of " << report.number_of_triangles
              << " triangles between components or with a non-zero intersection product in " << report.order_seconds
              << " s\n";
  // the chain is written over the sorted facets
  const std::vector<Dual_edge_record> chain = lexicographic_homologous_chain<Arithmetic>(
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


// The frame of the public functions on a triangulation: the callback, the checks, the timing,
// and the choice of the coefficients; `run(arithmetic, callback, report)` does the work.
template <class Triangulation, class NamedParameters, class Run>
Open_surface_report run_on_triangulation(const Triangulation& dt, const NamedParameters& np, const Run& run)
{
  static_assert(std::is_same<typename Triangulation::Geom_traits::FT, double>::value,
                "the lexicographic chains need a triangulation with double coordinates (e.g. Epick)");
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

/*!
\ingroup PkgLexOptimalChainsRef

Computes the lexicographic optimal 2-chain homologous to `chain` in the Delaunay
triangulation `dt` completed to \f$S^3\f$ by its infinite vertex, optionally relative to a
subcomplex \f$B\f$ given by its triangles (Algorithm 10 of the thesis, with the augmented
disjoint sets of Algorithm 9, on the dual graph; triangles ordered by Lemma 4.14).

As \f$H_2(S^3) = 0\f$, in the absolute case this is the lexicographic minimal chain with the
same boundary as `chain`. Relative to \f$B\f$, the result is the minimal chain that differs
from `chain` by a boundary plus a chain of \f$B\f$: its boundary may move inside \f$B\f$,
and it has no triangle of \f$B\f$.

Chains are given and returned as pairs `(f, k)` of a `DT::Facet` `f = (c, i)` and an
integer coefficient `k` of the triangle `c->vertex((i+1)&3), c->vertex((i+2)&3),
c->vertex((i+3)&3)` (last two vertices swapped when `i` is odd), which is oriented outward of
`c`. The output has positive coefficients (over Z2, all equal to 1), in decreasing triangle
order.

\tparam DT a `Delaunay_triangulation_3` whose points have `double` coordinates
\param dt the triangulation; it is not modified
\param chain a range of `std::pair<DT::Facet, std::int64_t>`, finite facets; a facet given
twice has the sum of its coefficients
\param out output iterator accepting `std::pair<DT::Facet, std::int64_t>`
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{coefficient_field}
    \cgalParamDescription{the coefficients of the chains}
    \cgalParamType{`Lex_optimal_chains::Coefficient_field`}
    \cgalParamDefault{`Coefficient_field::Q` (oriented result)}
  \cgalParamNEnd
  \cgalParamNBegin{relative_facets}
    \cgalParamDescription{the triangles of the subcomplex \f$B\f$; they are not dual edges}
    \cgalParamType{a range of `DT::Facet`}
    \cgalParamDefault{empty (absolute chains)}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{called with the progress in [0,1]; returning `false` cancels (the last
                          call, with 1, comes after the output iterator was written)}
    \cgalParamType{`std::function<bool(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{prints the stages and their timings to `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a report; its triangulation, order and optimal chain fields are filled.
\throws Lex_optimal_chains::Input_error on a triangulation of dimension below 3, or a facet
with the infinite vertex in `chain` or in \f$B\f$ (`INVALID_CHAIN`); with code `TOO_LARGE`
when an intersection product exceeds 32 bits (see `Lex_optimal_chains::Coefficient_field`) or
the triangulation has \f$2^{30}\f$ cells or more; `CANCELLED` when the callback cancels.
*/
template <class DT, class ChainRange, class OutputIterator, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Open_surface_report
lex_optimal_homologous_chain(const DT& dt, const ChainRange& chain, OutputIterator out,
                             const NamedParameters& np = parameters::default_values())
{
  return Lex_optimal_chains::internal::run_on_triangulation(dt, np, [&](auto arithmetic, const auto& callback, auto& report) {
    using Arithmetic = decltype(arithmetic);
    auto add_chain = [&](const auto& add) { for(const auto& fk : chain) add(fk.first, std::int64_t(fk.second)); };
    Lex_optimal_chains::internal::optimal_chain<Arithmetic>(dt, np, add_chain, callback, 0.0, out, report);
  });
}

/*!
\ingroup PkgLexOptimalChainsRef

Computes the lexicographic optimal 2-chain of the Delaunay triangulation `dt` bounded by the
1-cycle `cycle`, optionally relative to a subcomplex \f$B\f$: a representative chain bounded
by the cycle is found by Algorithm 11 of the thesis (a downward sweep of the cycle through
the lower links of its highest vertices, heights compared along \f$(z, x, y)\f$), then made
optimal by `lex_optimal_homologous_chain()`.

\tparam DT a `Delaunay_triangulation_3` whose points have `double` coordinates
\param dt the triangulation; it is not modified
\param cycle a range of `std::pair<DT::Vertex_handle, DT::Vertex_handle>`: the edges of the
cycle, each oriented from its first to its second vertex, with coefficient 1 (edges given
twice add up). Over Q, a closed polyline \f$p_0 p_1 \dots p_n = p_0\f$ is the edges
\f$(p_i, p_{i+1})\f$.
\param out output iterator accepting `std::pair<DT::Facet, std::int64_t>`, as in
`lex_optimal_homologous_chain()`; over Q, the boundary of the output is `cycle` with its
orientation
\param np the named parameters of `lex_optimal_homologous_chain()`

\returns a report; its triangulation, representative, order and optimal chain fields are filled.
\throws Lex_optimal_chains::Input_error with code `BOUNDARY_EDGE_NOT_IN_TRIANGULATION` if an
edge of `cycle` is not a finite edge of `dt` (the message gives its vertices),
`BOUNDARY_NOT_A_CYCLE` if the edges do not form a cycle, and the errors of
`lex_optimal_homologous_chain()` (`TOO_LARGE`, `CANCELLED`).
*/
template <class DT, class EdgeRange, class OutputIterator, class NamedParameters = parameters::Default_named_parameters>
Lex_optimal_chains::Open_surface_report
lex_optimal_chain_with_boundary(const DT& dt, const EdgeRange& cycle, OutputIterator out,
                                const NamedParameters& np = parameters::default_values())
{
  return Lex_optimal_chains::internal::run_on_triangulation(dt, np, [&](auto arithmetic, const auto& callback, auto& report) {
    using Arithmetic = decltype(arithmetic);
    Lex_optimal_chains::internal::optimal_chain_with_boundary<Arithmetic>(dt, cycle, np, callback, 0.0, out, report);
  });
}

} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_HOMOLOGOUS_CHAIN_H
