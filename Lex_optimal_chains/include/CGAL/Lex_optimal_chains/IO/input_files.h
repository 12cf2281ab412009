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
#include <CGAL/Lex_optimal_chains/internal/Declared_counts.h>
#include <CGAL/Lex_optimal_chains/internal/PLY_structure_check.h>

#include <CGAL/IO/read_points.h>

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// An output iterator that calls a function with each point put through it, with the point type
// as its value type (CGAL 5.5's PLY reader needs it; boost's function_output_iterator has none).
template <class Point_3, class Function>
struct Calling_output_iterator
{
  using iterator_category = std::output_iterator_tag;
  using value_type = Point_3;
  using difference_type = std::ptrdiff_t;
  using pointer = void;
  using reference = void;
  const Function* function;
  Calling_output_iterator& operator*() { return *this; }
  Calling_output_iterator& operator++() { return *this; }
  Calling_output_iterator operator++(int) { return *this; }
  Calling_output_iterator& operator=(const Point_3& p)
  {
    (*function)(p);
    return *this;
  }
};

} // namespace internal

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
  std::string extension = std::filesystem::path(path).extension().string();
  for(char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if(extension == ".laz")
    throw Input_error(Input_error_code::UNREADABLE_FILE, "'" + path + "': compressed LAS (LAZ) is not supported: "
                                                         "decompress it first (laszip, or pdal translate in.laz out.las)");
  if(extension == ".las") return for_each_las_point<Point_3>(path, classes, f);
  if(extension != ".xyz" && extension != ".pwn" && extension != ".ply" && extension != ".off")
    throw Input_error(Input_error_code::UNREADABLE_FILE, "input '" + path + "' must end in .xyz, .pwn, .ply, .off or .las");
  if(!classes.empty())
    throw Input_error(Input_error_code::UNREADABLE_FILE, "classes are read from LAS files only, not from '" + path + "'");
  if(!std::filesystem::is_regular_file(path))
    throw Input_error(Input_error_code::UNREADABLE_FILE, "cannot open input '" + path + "'");
  if(extension == ".ply") internal::check_PLY_structure(path, {"x", "y", "z"}); // read as double
  std::ostringstream reader_messages;
  std::streambuf* saved = std::cerr.rdbuf(reader_messages.rdbuf());
  bool read = false;
  try {
    read = CGAL::IO::read_points<Point_3>(path, internal::Calling_output_iterator<Point_3, Function>{&f});
  } catch(...) { // from f
    std::cerr.rdbuf(saved);
    throw;
  }
  std::cerr.rdbuf(saved);
  if(!read) throw Input_error(Input_error_code::UNREADABLE_FILE, "cannot read points from '" + path + "'");
  internal::check_declared_counts(path, extension);
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
  std::ifstream in(path);
  if(!in) throw Input_error(Input_error_code::UNREADABLE_FILE, "cannot open boundary file '" + path + "'");
  std::vector<std::vector<Point_3>> polylines;
  std::string line;
  for(int number = 1; std::getline(in, line); ++number) {
    const std::string where = "line " + std::to_string(number) + " of '" + path + "'";
    std::istringstream ls(line);
    std::vector<std::string> tokens;
    for(std::string t; ls >> t;) tokens.push_back(t);
    if(tokens.empty()) continue; // blank line
    char* end = nullptr;
    const long n = std::strtol(tokens[0].c_str(), &end, 10);
    if(*end != '\0' || end == tokens[0].c_str())
      throw Input_error(Input_error_code::UNREADABLE_FILE, where + " does not start with a whole number of points, but '" + tokens[0] + "'");
    if(n < 0 || n > 100000000) throw Input_error(Input_error_code::UNREADABLE_FILE, where + ": bad number of points " + tokens[0]);
    if(tokens.size() != std::size_t(1 + 3 * n))
      throw Input_error(Input_error_code::UNREADABLE_FILE, where + " announces " + tokens[0] + " points (" + std::to_string(3 * n) +
                                  " coordinates) but has " + std::to_string(tokens.size() - 1) + " coordinates");
    std::vector<Point_3> polyline;
    double c[3];
    for(long i = 0; i < n; ++i) {
      for(int k = 0; k < 3; ++k) {
        const std::string& t = tokens[std::size_t(1 + 3 * i + k)];
        c[k] = std::strtod(t.c_str(), &end);
        if(*end != '\0' || end == t.c_str() || !std::isfinite(c[k]))
          throw Input_error(Input_error_code::UNREADABLE_FILE, where + ": coordinate '" + t + "' of point " + std::to_string(i + 1) +
                                      " is not a finite number");
      }
      polyline.emplace_back(c[0], c[1], c[2]);
    }
    polylines.push_back(std::move(polyline));
  }
  return polylines;
}

} // namespace IO
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_IO_INPUT_FILES_H
