// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_POINT_FILES_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_POINT_FILES_H

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


// The reader behind IO::for_each_point_in_file(): the file's kind by its extension (LAS by
// IO::for_each_las_point(), the others by CGAL's streaming readers, whose diagnostics on
// std::cerr are kept out), then the checks that need the whole file.
template <class Point_3, class Function>
void stream_point_file(const std::string& path, const std::vector<int>& classes, const Function& f)
{
  std::string extension = std::filesystem::path(path).extension().string();
  for(char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if(extension == ".laz")
    throw Input_error(Input_error_code::UNREADABLE_FILE, "'" + path + "': compressed LAS (LAZ) is not supported: "
                                                         "decompress it first (laszip, or pdal translate in.laz out.las)");
  if(extension == ".las") return IO::for_each_las_point<Point_3>(path, classes, f);
  if(extension != ".xyz" && extension != ".pwn" && extension != ".ply" && extension != ".off")
    throw Input_error(Input_error_code::UNREADABLE_FILE, "input '" + path + "' must end in .xyz, .pwn, .ply, .off or .las");
  if(!classes.empty())
    throw Input_error(Input_error_code::UNREADABLE_FILE, "classes are read from LAS files only, not from '" + path + "'");
  if(!std::filesystem::is_regular_file(path))
    throw Input_error(Input_error_code::UNREADABLE_FILE, "cannot open input '" + path + "'");
  if(extension == ".ply") check_PLY_structure(path, {"x", "y", "z"}); // read as double
  std::ostringstream reader_messages;
  std::streambuf* saved = std::cerr.rdbuf(reader_messages.rdbuf());
  bool read = false;
  try {
    read = CGAL::IO::read_points<Point_3>(path, Calling_output_iterator<Point_3, Function>{&f});
  } catch(...) { // from f
    std::cerr.rdbuf(saved);
    throw;
  }
  std::cerr.rdbuf(saved);
  if(!read) throw Input_error(Input_error_code::UNREADABLE_FILE, "cannot read points from '" + path + "'");
  check_declared_counts(path, extension);
}

// The parser behind IO::read_polyline_file(): every line checked, the reason naming the line
// and the token.
template <class Point_3>
std::vector<std::vector<Point_3>> parse_polyline_file(const std::string& path)
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

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_POINT_FILES_H
