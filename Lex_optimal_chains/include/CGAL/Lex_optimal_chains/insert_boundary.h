// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INSERT_BOUNDARY_H
#define CGAL_LEX_OPTIMAL_CHAINS_INSERT_BOUNDARY_H

/// \file insert_boundary.h
/// Insertion of an imposed boundary into a user's 3D Delaunay triangulation.

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Geom_traits_check.h>
#include <CGAL/Lex_optimal_chains/parameters.h>
#include <CGAL/Lex_optimal_chains/internal/Imposed_boundary_3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Named_function_parameters.h>

#include <set>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
The boundary inserted into a triangulation by `insert_boundary()`.
\tparam DT the triangulation type
*/
template <class DT>
struct Inserted_boundary
{
  /// The boundary cycle: each edge of each polyline as the pair of its vertices, oriented
  /// from a polyline vertex to the next, in the order of the polylines. This is the `cycle`
  /// argument of `lex_optimal_chain_with_boundary()` and `lex_optimal_open_surface_mesh()`.
  std::vector<std::pair<typename DT::Vertex_handle, typename DT::Vertex_handle>> edges;
  /// The boundary vertices that were not vertices of the triangulation before, in the order
  /// of the polylines.
  std::vector<typename DT::Vertex_handle> new_vertices;
  /// The points of the vertices removed because they kept a boundary edge out of the
  /// triangulation (`remove_blocking_points`), in the order of their removal.
  std::vector<typename DT::Point> removed_points;
};

/*!
\ingroup PkgLexOptimalChainsRef

Inserts the vertices of closed polylines into the Delaunay triangulation `dt` and makes sure
that every polyline edge is an edge of `dt`, so that the polylines can be the boundary of a
lexicographic optimal chain (`lex_optimal_chain_with_boundary()`,
`lex_optimal_open_surface_mesh()`).

A polyline edge that is not an edge of the triangulation after the insertion is kept out by
the vertices in its closed diametral ball (a Delaunay triangulation has every Gabriel edge).
With `remove_blocking_points(true)`, the vertices in these balls that are not polyline
vertices are removed until every edge is in; otherwise such an edge is an error.

The polylines are checked first, as in `lex_optimal_open_surface_reconstruction()`: closed,
finite, simple and disjoint, and not farther from the bounding box of the vertices of `dt`
than its diagonal. On an error `dt` is left with the vertices it had: the vertices inserted
are removed and the points removed are inserted again (the information of a vertex base
with info is then default-constructed).

\tparam DT a `Delaunay_triangulation_3` whose points have `double` coordinates
\tparam PolylineRange a range of ranges of `DT::Point`
\param dt the triangulation, of dimension 3
\param polylines closed polylines (last vertex equal to the first), simple and disjoint
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{remove_blocking_points}
    \cgalParamDescription{removes the vertices in the diametral balls of the polyline edges that are not edges of `dt`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`: such an edge is an error}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the boundary cycle, the vertices inserted and the points removed.
\throws Input_error with code `NON_FINITE_COORDINATE`, `OPEN_POLYLINE`,
`SELF_INTERSECTING_BOUNDARY`, `BOUNDARY_NOT_A_CYCLE` (no polyline),
`BOUNDARY_FAR_FROM_POINTS`, `DEGENERATE_POINT_SET` (`dt` has dimension below 3), or
`BOUNDARY_EDGE_NOT_IN_TRIANGULATION` (the message names the edge).
*/
template <class DT, class PolylineRange, class NamedParameters = parameters::Default_named_parameters>
Inserted_boundary<DT> insert_boundary(DT& dt, const PolylineRange& polylines,
                                      const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Has_double_coordinates<typename DT::Geom_traits>::value, "");
  using Point = typename DT::Point;
  if(dt.dimension() < 3)
    throw Input_error(Input_error_code::DEGENERATE_POINT_SET,
                      "the triangulation has dimension " + std::to_string(dt.dimension()) +
                        ": a boundary is inserted into a triangulation of dimension 3");
  Bbox_3 box;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) box += v->point().bbox();
  const auto checked = internal::checked_polylines<typename DT::Geom_traits>(polylines, box);
  const bool remove =
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::remove_blocking_points), false);

  Inserted_boundary<DT> result;
  std::set<typename DT::Vertex_handle> inserted;
  try {
    result.edges = internal::insert_boundary(dt, checked, remove, inserted, result.removed_points);
  } catch(...) {
    for(const auto& v : inserted) dt.remove(v);
    dt.insert(result.removed_points.begin(), result.removed_points.end());
    throw;
  }
  // the new vertices in the order of the polylines (the set is ordered by addresses)
  for(const auto& polyline : checked)
    for(const Point& p : polyline) {
      typename DT::Locate_type lt;
      int li, lj;
      const auto c = dt.locate(p, lt, li, lj);
      CGAL_assertion(lt == DT::VERTEX);
      if(inserted.count(c->vertex(li)) != 0) result.new_vertices.push_back(c->vertex(li));
    }
  return result;
}

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INSERT_BOUNDARY_H
