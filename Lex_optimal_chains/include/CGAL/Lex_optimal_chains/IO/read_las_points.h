// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_IO_READ_LAS_POINTS_H
#define CGAL_LEX_OPTIMAL_CHAINS_IO_READ_LAS_POINTS_H

/// \file read_las_points.h
/// A reader of uncompressed LAS files (ASPRS LAS 1.0 to 1.4, point data record formats 0 to
/// 10): Debian 12 ships no LAS library that CGAL 5.5 uses (CGAL's own reader needs LASlib).

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/LAS_records.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace IO {

/*!
\ingroup PkgLexOptimalChainsRef

Calls `f(p, c)` with each point `p` of an uncompressed LAS file and its classification `c`, in
the order of the file, as it reads them (the points are not kept). The file is read as
`for_each_las_point()` reads it; the classification is the 5 low bits of the classification
byte for point formats 0 to 5 (the ASPRS classes 0 to 31), the whole byte for formats 6 to 10.

\tparam Point_3 a point type constructible from three `double`
\tparam Function a callable `void(const Point_3&, int)`
\throws Input_error as `for_each_las_point()`
*/
template <class Point_3, class Function>
void for_each_las_record(const std::string& path, const Function& f)
{
  internal::read_las_records<Point_3>(path, f);
}

/*!
\ingroup PkgLexOptimalChainsRef

Calls `f(p)` with each point `p` of an uncompressed LAS file, in the order of the file, as it
reads them (the points are not kept: for clouds larger than memory). The file is read as
`read_las_points()` reads it (versions 1.0 to 1.4, point data record formats 0 to 10), with
the scale and offset of the header applied: \f$x = X \cdot s_x + o_x\f$, and likewise for
\f$y\f$ and \f$z\f$. With `classes` not empty, only the points whose classification is in it
are given (for instance 2, ground, and 6, building, of the ASPRS
classes): the 5 low bits of the classification byte for formats 0 to 5, the whole byte for
formats 6 to 10.

\tparam Point_3 a point type constructible from three `double`
\tparam Function a callable `void(const Point_3&)`
\throws Input_error with code `UNREADABLE_FILE` for a file that cannot be opened, is not a
LAS file, is compressed (LAZ: decompress it first, with `laszip` or `pdal translate`), has a
point format or a record length that does not match, or is shorter than its header says.
*/
template <class Point_3, class Function>
void for_each_las_point(const std::string& path, const std::vector<int>& classes, const Function& f)
{
  std::vector<bool> wanted(256, classes.empty());
  for(int c : classes)
    if(c >= 0 && c < 256) wanted[std::size_t(c)] = true;
  for_each_las_record<Point_3>(path, [&](const Point_3& p, int c) {
    if(wanted[std::size_t(c)]) f(p);
  });
}

/*!
\ingroup PkgLexOptimalChainsRef

Reads the points of an uncompressed LAS file (versions 1.0 to 1.4, point data record formats
0 to 10), with the scale and offset of the header applied: \f$x = X \cdot s_x + o_x\f$, and
likewise for \f$y\f$ and \f$z\f$. With `classes` not empty, only the points whose
classification is in it are kept (for instance 2, ground, and 6, building, of the ASPRS
classes): the 5 low bits of the classification byte for formats 0 to 5, the whole byte for
formats 6 to 10.

\tparam Point_3 a point type constructible from three `double`
\throws Input_error with code `UNREADABLE_FILE` for a file that cannot be opened, is not a
LAS file, is compressed (LAZ: decompress it first, with `laszip` or `pdal translate`), has a
point format or a record length that does not match, or is shorter than its header says.
*/
template <class Point_3>
std::vector<Point_3> read_las_points(const std::string& path, const std::vector<int>& classes = {})
{
  std::vector<Point_3> points;
  for_each_las_point<Point_3>(path, classes, [&](const Point_3& p) { points.push_back(p); });
  return points;
}

} // namespace IO
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_IO_READ_LAS_POINTS_H
