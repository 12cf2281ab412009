// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_HOMOLOGOUS_CHAIN_H
#define CGAL_LEX_OPTIMAL_HOMOLOGOUS_CHAIN_H

/// \file lex_optimal_homologous_chain.h
/// Lexicographic optimal 2-chains of a 3D Delaunay triangulation homologous to a given chain,
/// or bounded by a given 1-cycle, absolute or relative (thesis sections 4.5 and 4.6).

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/Open_surface_report.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Optimal_chain_3.h>

#include <CGAL/Named_function_parameters.h>

#include <cstdint>

namespace CGAL {

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
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{threads (with TBB) for the contraction of the cells across their largest facets and for the keys and the sort of the triangles, from 200,000 cells; the result does not depend on it}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{1}
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
the triangulation has \f$2^{30}\f$ cells or more.
\throws Lex_optimal_chains::Cancelled when the callback returns `false` (the output iterator
may then have been written: the last call, with 1, comes after it).
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
`lex_optimal_homologous_chain()` (`TOO_LARGE`).
\throws Lex_optimal_chains::Cancelled when the callback returns `false`, as
`lex_optimal_homologous_chain()`.
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
