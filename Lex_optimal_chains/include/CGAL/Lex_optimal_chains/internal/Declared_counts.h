// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DECLARED_COUNTS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DECLARED_COUNTS_H

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The size in bytes of a binary PLY file's data, from the element counts and property types
// of its header, when every property is a scalar (with a list property the size depends on
// the data) and the counts are below 2^48 bytes' worth: 0 otherwise.
inline unsigned long long binary_ply_data_size(const std::vector<std::pair<unsigned long long, std::vector<std::string>>>& elements)
{
  unsigned long long total = 0;
  for(const auto& [count, properties] : elements) {
    unsigned long long record = 0;
    for(const std::string& type : properties) {
      unsigned long long size = 0;
      if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") size = 1;
      else if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") size = 2;
      else if(type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") size = 4;
      else if(type == "double" || type == "float64") size = 8;
      else return 0; // a list, or a type this check does not know
      record += size;
    }
    // a count too large for the file is left to CGAL's reader (which then fails), not wrapped around
    if(record != 0 && count > (1ull << 48) / record) return 0;
    total += count * record;
  }
  return total;
}

// CGAL's readers stop after the number of points that an OFF or PLY header declares: a header
// that declares fewer than the file holds would drop points silently. For ASCII files (one
// record per line) whose points come last (an OFF file without faces, a PLY file whose last
// element is the vertices) the data lines are counted against the header; for binary PLY
// files whose properties are all scalars, the size of the data is compared with the size the
// header gives. Binary PLY files with list properties (faces), binary OFF files, and ASCII files
// with faces after the points (where an extra line may be an extra face) are not checked.
inline void check_declared_counts(const std::string& input, const std::string& ext)
{
  std::ifstream in(input, std::ios::binary);
  std::string line;
  auto next_line = [&](bool skip_comments) {
    while(std::getline(in, line)) {
      const auto first = line.find_first_not_of(" \t\r");
      if(first == std::string::npos) continue;
      if(skip_comments && line[first] == '#') continue;
      return true;
    }
    return false;
  };
  unsigned long long declared = 0; // records: points (OFF), elements (PLY)
  std::string what, last_element;
  if(ext == ".off") {
    if(!next_line(true)) return;
    std::istringstream header(line);
    std::string keyword;
    header >> keyword;
    if(keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) return; // CGAL decides
    std::string rest;
    std::getline(header, rest);
    if(rest.find("BINARY") != std::string::npos) return;
    if(rest.find_first_not_of(" \t\r") == std::string::npos) { if(!next_line(true)) return; rest = line; }
    if(keyword.find("ST") != std::string::npos || keyword.find("4") != std::string::npos || keyword.find("n") != std::string::npos)
      return; // dimension or texture variants: left to CGAL
    std::istringstream counts(rest);
    unsigned long long v = 0, f = 0;
    if(!(counts >> v >> f)) return;
    if(f != 0) return;
    declared = v;
    what = std::to_string(v) + " points";
  } else if(ext == ".ply") {
    if(!next_line(false) || line.rfind("ply", 0) != 0) return;
    bool binary = false, ended = false;
    std::vector<std::pair<unsigned long long, std::vector<std::string>>> elements; // count, property types
    while(next_line(false)) {
      if(line.rfind("end_header", 0) == 0) { ended = true; break; }
      std::istringstream words(line);
      std::string keyword, name;
      words >> keyword;
      if(keyword == "format") {
        std::string format;
        words >> format;
        if(format == "binary_little_endian" || format == "binary_big_endian") binary = true;
        else if(format != "ascii") return;
      } else if(keyword == "element") {
        unsigned long long count = 0;
        if(!(words >> name >> count)) return;
        declared += count;
        what += (what.empty() ? "" : ", ") + std::to_string(count) + " " + name;
        last_element = name;
        elements.push_back({count, {}});
      } else if(keyword == "property") {
        std::string type;
        if(!(words >> type) || elements.empty()) return;
        elements.back().second.push_back(type);
      }
    }
    if(binary) {
      if(!ended) return;
      const auto data_start = in.tellg(); // after the line "end_header" and its end of line
      const unsigned long long expected = binary_ply_data_size(elements);
      if(data_start < 0 || expected == 0) return;
      const unsigned long long size = std::filesystem::file_size(input);
      if(size > (unsigned long long)(data_start) + expected)
        throw Input_error(Input_error_code::UNREADABLE_FILE, "input '" + input + "' holds more data than its header declares (" + what + ", " +
                                    std::to_string(expected) + " bytes, against " +
                                    std::to_string(size - (unsigned long long)(data_start)) +
                                    "): the points beyond would be ignored; fix the header");
      return;
    }
    if(last_element != "vertex") return;
  } else
    return;
  unsigned long long records = 0;
  while(next_line(ext == ".off")) {
    if(++records > declared)
      throw Input_error(Input_error_code::UNREADABLE_FILE, "input '" + input + "' holds more records than its header declares (" + what +
                                  "): the points beyond would be ignored; fix the header");
  }
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DECLARED_COUNTS_H
