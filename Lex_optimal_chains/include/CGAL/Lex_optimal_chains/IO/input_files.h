// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_IO_INPUT_FILES_H
#define CGAL_LEX_OPTIMAL_CHAINS_IO_INPUT_FILES_H

/// \file input_files.h
/// Reading of point clouds and boundary polylines with the checks that a command-line program
/// needs: one typed error with a one-line reason, never a file read in part.

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/IO/read_las_points.h>
#include <CGAL/Lex_optimal_chains/internal/Point_files.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace IO {

/*!
\ingroup PkgLexOptimalChainsRef

Calls `f(p)` with each point `p` of a point file as it is read, the points not kept (for
clouds larger than memory): the file is read as `read_point_file()` reads it, the LAS files
by `for_each_las_point()`, the others by CGAL's readers, which stream. The checks of
`read_point_file()` that need the whole file come after the last point (a PLY or OFF file
that holds more points than its header declares throws then).

\tparam Point_3 the point type, as for `CGAL::IO::read_points()`
\tparam Function a callable `void(const Point_3&)`
\throws Input_error as `read_point_file()`
*/
template <class Point_3, class Function>
void for_each_point_in_file(const std::string& path, const std::vector<int>& classes, const Function& f)
{
  internal::stream_point_file<Point_3>(path, classes, f);
}

/*!
\ingroup PkgLexOptimalChainsRef

Reads the points of an XYZ, PLY or OFF file (by its extension, in any case; `.pwn`, CGAL's
points with normals, is XYZ) with CGAL's readers, or of an uncompressed LAS file with `read_las_points()` (keeping the points whose
classification is in `classes`, if not empty), and refuses what they would read in part: CGAL's readers stop after the number of
points that an OFF or PLY header declares, so a header that declares fewer than the file holds
would drop points silently. For ASCII files whose points come last (an OFF file without faces,
a PLY file whose last element is the vertices) the data lines are counted against the header;
for binary PLY files whose properties are all scalars, the size of the data is compared with
the size that the header gives. Binary PLY files with list properties, binary OFF files and
ASCII files with faces after the points are not checked for this. The diagnostics that CGAL's
readers print to `std::cerr` are kept out of it: the error says what was wrong.

\tparam Point_3 the point type, as for `CGAL::IO::read_points()`
\throws Input_error with code `UNREADABLE_FILE`: another extension, a file that cannot be
opened or read, more data than its header declares, a compressed LAS file (`.laz`), or
`classes` given for a file that is not LAS.
*/
template <class Point_3>
std::vector<Point_3> read_point_file(const std::string& path, const std::vector<int>& classes = {})
{
  std::vector<Point_3> points;
  for_each_point_in_file<Point_3>(path, classes, [&](const Point_3& p) { points.push_back(p); });
  return points;
}

/*!
\ingroup PkgLexOptimalChainsRef

Reads boundary polylines in CGAL's polylines text format: one polyline per line,
`n x1 y1 z1 ... xn yn zn`; blank lines are skipped. Every line is checked: a whole number of
points that matches the number of coordinates, each a finite number. Whether the polylines
are closed and simple is checked by the functions that take them.

\tparam Point_3 a point type constructible from three `double`
\throws Input_error with code `UNREADABLE_FILE`, the message naming the line and the token.
*/
template <class Point_3>
std::vector<std::vector<Point_3>> read_polyline_file(const std::string& path)
{
  return internal::parse_polyline_file<Point_3>(path);
}

} // namespace IO
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_IO_INPUT_FILES_H
