// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_SEGMENTS_FILE_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_SEGMENTS_FILE_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace IO {

/*!
\ingroup PkgPolygonPartitionSimplificationRef

reads the package's segments text file: one segment `x0 y0 x1 y1` per line (four numbers
separated by white space); blank lines and lines whose first word starts with `#` are skipped.
The segments are returned in the order of the file, as read (degenerate or repeated segments
are left to the partition functions, which refuse them with their own error codes).

\throws Input_error with the code `UNREADABLE_FILE` if the file cannot be opened or is not a
regular file, and with the code `MALFORMED_FILE`, naming the file and the line, if a line
holds anything else than four numbers.
*/
template <class Kernel>
std::vector<typename Kernel::Segment_2> read_segments_2(const std::string& file)
{
  std::ifstream in(file);
  std::error_code error;
  if(!in || !std::filesystem::is_regular_file(file, error))
    throw Input_error(Input_error_code::UNREADABLE_FILE, "cannot read " + file);
  std::vector<typename Kernel::Segment_2> segments;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream is(line);
    std::string first;
    if(!(is >> first) || first[0] == '#') continue;
    is.str(line);
    is.clear();
    double c[4];
    std::string rest;
    if(!(is >> c[0] >> c[1] >> c[2] >> c[3]) || (is >> rest))
      throw Input_error(Input_error_code::MALFORMED_FILE,
                        file + ":" + std::to_string(number) + ": expected four numbers x0 y0 x1 y1");
    segments.emplace_back(typename Kernel::Point_2(c[0], c[1]), typename Kernel::Point_2(c[2], c[3]));
  }
  return segments;
}

} // namespace IO
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_SEGMENTS_FILE_H
