// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INPUT_ERROR_H
#define CGAL_LEX_OPTIMAL_CHAINS_INPUT_ERROR_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
What was wrong with the input of a function of this package.
*/
enum class Input_error_code
{
  EMPTY_INPUT,                 ///< no point at all
  TOO_FEW_POINTS,              ///< fewer than 4 distinct points
  NON_FINITE_COORDINATE,       ///< a coordinate is NaN or infinite
  DEGENERATE_POINT_SET,        ///< all points coplanar (or collinear, or equal): no tetrahedron
  CONSTRAINT_OUTSIDE_HULL,     ///< an interior point lies outside the convex hull of the points
  CONFLICTING_CONSTRAINTS,     ///< an interior and an exterior constraint fall in the same cell
  NO_INTERIOR_FOUND,           ///< no interior point was given and none could be chosen
  TOO_LARGE,                   ///< the input exceeds a size limit (2^30 cells, 2^31 in an intersection product, simplex dimension, a footprint beyond the range of doubles)
  INVALID_GRAPH,               ///< a graph given to the generic min-cut is not valid
  OPEN_POLYLINE,               ///< a boundary polyline does not end where it starts
  SELF_INTERSECTING_BOUNDARY,  ///< a boundary polyline repeats a vertex or crosses itself or another one
  BOUNDARY_EDGE_NOT_IN_TRIANGULATION, ///< a boundary edge is not an edge of the Delaunay triangulation
  BOUNDARY_NOT_A_CYCLE,        ///< the given boundary edges do not form a cycle
  BOUNDARY_FAR_FROM_POINTS,    ///< a boundary polyline is farther from the points than their own extent
  INVALID_CHAIN,               ///< a triangle of a given chain is not a facet of the triangulation
  EMPTY_RESULT,                ///< every triangle of the result was dropped (`drop_boundary_triangles`): the points do not span the boundary
  UNREADABLE_FILE,             ///< an input file cannot be opened or read, is malformed, or holds more than its header declares
  UNSUPPORTED_OPTION,          ///< an option needs a library the program was built without (`robust` needs Eigen)
  INVALID_PARAMETER,           ///< a named parameter is out of its range (`smoothing_neighbors` from 1 to 7)
  WRITE_FAILED                 ///< a working file cannot be written (the bucket files of the out-of-core tiles: no space, no permission)
};

/*!
\ingroup PkgLexOptimalChainsRef
Exception thrown on input a user can get wrong. `what()` says what was wrong and what to do;
`code()` tells it to a program. Nothing the user gave is modified when it is thrown.
*/
class Input_error : public std::invalid_argument
{
public:
  /// builds an error with its code and its message
  Input_error(Input_error_code code, const std::string& message)
    : std::invalid_argument(message), code_(code)
  {}

  /// what was wrong
  Input_error_code code() const { return code_; }

private:
  Input_error_code code_;
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INPUT_ERROR_H
