// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INPUT_ERROR_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INPUT_ERROR_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
What was wrong with the input of a function of this package.
*/
enum class Input_error_code
{
  EMPTY_INPUT,            ///< no segment, no polygon, or an arrangement without edges
  NON_FINITE_COORDINATE,  ///< a coordinate is NaN or infinite, or beyond 1e100 in magnitude
  ZERO_LENGTH_SEGMENT,    ///< a segment whose two endpoints are equal, or too close for double precision
  DUPLICATED_SEGMENT,     ///< the same segment given twice (in either orientation); `kinetic_partition_2()` merges such segments and does not throw it
  NO_CELL,                ///< the input bounds no cell (all its edges dangle)
  INVALID_PARAMETER,      ///< a parameter is out of its range (negative weight, step ratio not in (0,1), ...)
  UNREADABLE_FILE,        ///< an input file cannot be opened, or is not a regular file
  MALFORMED_FILE,         ///< a line of an input file is not in the expected format
  NO_PLANE,               ///< no roof plane found in a point cloud (too few points, or too noisy for the plane distance)
  NO_HORIZONTAL_EXTENT,   ///< the points of a building reconstruction have no extent in the horizontal plane
  MISSING_PROPERTY,       ///< a mesh lacks a property map that the function reads, or has it with another value type
  NO_BUILDING             ///< a city tile holds no building: no point of a building class, or no cluster or footprint with enough of them
};

/*!
\ingroup PkgPolygonPartitionSimplificationRef
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

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INPUT_ERROR_H
