// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PLY_STRUCTURE_CHECK_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PLY_STRUCTURE_CHECK_H

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// What CGAL's PLY reader (5.5 and 6.0) needs of a file to read it without undefined behaviour
// or an allocation that the file cannot justify: it takes a property before any element as
// one of the last element of an empty list, it loops over the declared items of an element
// even when they have no property or the data has ended, and it resizes a list to the count
// the data gives (up to 2^32 - 1 values). The file is refused when a property comes before the
// first element, an element count is not a whole number, two elements or two properties of
// an element have one name (the reader looks a value up by name, finds the first, and asserts
// its type; names are compared as C strings, so a header line with a control character is
// refused), an
// element with items has no property, the data cannot hold the declared items (at least one byte per property), or a
// list's count is not a whole number of its type or more values than the rest of the file can
// hold. `floating_point` names the properties of the points (of the element "vertex" or
// "vertices") that the caller's reader reads as floating-point numbers, which must then be
// scalars of type float or double, and all of one type if `one_type`: CGAL's read_points()
// reads x, y and z as double from a float or a double; CGAL's read_point_set() reads x, y, z,
// nx, ny and nz all as float if x, y or z is a float, and as double otherwise. Either asserts
// that the types match, and reads through a null pointer without assertions. A header without
// "end_header" ends with the file for the reader (no data). Other defects (unknown types, data
// that does not parse) are left to CGAL's reader, which fails on them.

struct PLY_property_layout
{
  bool is_list = false;
  int count_bytes = 0, value_bytes = 0; // sizes of the list's count and of a value (a scalar: value_bytes)
  bool count_is_signed = false;
};

inline int PLY_type_size(const std::string& type, bool* is_signed = nullptr)
{
  if(is_signed) *is_signed = type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" || type == "int32";
  if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if(type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
  if(type == "double" || type == "float64") return 8;
  return 0;
}

struct PLY_element_layout
{
  unsigned long long count = 0;
  std::vector<PLY_property_layout> properties;
  std::vector<std::string> names; // of the properties
  bool has_list() const
  {
    for(const auto& p : properties) if(p.is_list) return true;
    return false;
  }
};

// Walks the data of the elements with list properties, checking each list's count against
// the bytes left; `remaining` is the size of the data.
inline void check_PLY_lists(std::istream& in, const std::vector<PLY_element_layout>& elements, int format,
                            unsigned long long remaining, const std::string& refused)
{
  auto fail = [&](const std::string& why) { throw Input_error(Input_error_code::UNREADABLE_FILE, refused + why); };
  for(const PLY_element_layout& element : elements)
    for(unsigned long long item = 0; item < element.count; ++item)
      for(const PLY_property_layout& p : element.properties) {
        if(!in) return; // the data ended: CGAL's reader fails there
        unsigned long long values = 1;
        if(p.is_list) {
          if(format == 0) {
            std::string token;
            if(!(in >> token)) return;
            if(token.find_first_not_of("0123456789") != std::string::npos || token.size() > 10)
              fail("a list count is not a whole number: '" + token.substr(0, 20) + "'");
            values = std::stoull(token);
          } else {
            unsigned char b[4] = {0, 0, 0, 0};
            in.read(reinterpret_cast<char*>(b), p.count_bytes);
            values = 0;
            for(int k = 0; k < p.count_bytes; ++k)
              values |= (unsigned long long)(b[format == 1 ? k : p.count_bytes - 1 - k]) << (8 * k);
            if(p.count_is_signed && (values >> (8 * p.count_bytes - 1)) != 0) fail("a list count is negative");
            remaining -= std::min<unsigned long long>(remaining, (unsigned long long)(p.count_bytes));
          }
        }
        const unsigned long long bytes = values * (unsigned long long)(format == 0 ? 1 : p.value_bytes);
        if(values > remaining || bytes > remaining) {
          if(!p.is_list) return; // the data ends within a scalar: CGAL's reader fails there
          fail("a list of " + std::to_string(values) + " values is longer than the rest of the file");
        }
        if(format == 0) {
          std::string token;
          for(unsigned long long v = 0; v < values && (in >> token); ++v) {}
        } else {
          in.ignore(std::streamsize(bytes));
          remaining -= bytes;
        }
      }
}

// Throws Input_error (UNREADABLE_FILE) for a PLY file that CGAL's reader cannot read safely.
inline void check_PLY_structure(const std::string& path, const std::vector<std::string>& floating_point = {},
                                bool one_type = false)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::string magic; // the first word, as CGAL's reader reads it (after any white space)
  if(!in || !std::getline(in, line) || !(std::istringstream(line) >> magic) || magic != "ply") return; // CGAL's reader fails
  const std::string refused = "input '" + path + "' is not a PLY file that can be read: ";
  auto fail = [&](const std::string& why) { throw Input_error(Input_error_code::UNREADABLE_FILE, refused + why); };
  int format = 0; // 0 ASCII, 1 binary little endian, 2 binary big endian
  std::vector<PLY_element_layout> elements;
  std::vector<std::string> element_names;
  bool in_points = false, ended = false;
  std::string point_type; // of the first of `floating_point` met
  for(std::size_t number = 2; !ended && std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword, a, b, c, d;
    words >> keyword >> a >> b >> c >> d;
    const std::string where = "header line " + std::to_string(number) + ": ";
    for(char ch : line) // the reader compares names as C strings, which end at a NUL
      if((unsigned char)(ch) < 0x20 && ch != '\t' && ch != '\r') fail(where + "a control character in the header");
    if(number == 2) { // the format, whatever its first word (as CGAL's reader reads it)
      if(b.empty()) return; // CGAL's reader fails
      format = a == "binary_little_endian" ? 1 : a == "binary_big_endian" ? 2 : 0;
    } else if(keyword == "element") {
      if(b.empty() || b.find_first_not_of("0123456789") != std::string::npos || b.size() > 19)
        fail(where + "the count of element '" + a + "' is not a whole number");
      if(std::find(element_names.begin(), element_names.end(), a) != element_names.end())
        fail(where + "a second element named '" + a + "'");
      element_names.push_back(a);
      elements.push_back({std::stoull(b), {}, {}});
      in_points = a == "vertex" || a == "vertices";
    } else if(keyword == "property") {
      if(elements.empty()) fail(where + "a property before any element");
      PLY_property_layout p;
      p.is_list = a == "list";
      p.value_bytes = PLY_type_size(p.is_list ? c : a);
      if(p.is_list) p.count_bytes = PLY_type_size(b, &p.count_is_signed);
      if(p.value_bytes == 0 || (p.is_list && (p.count_bytes == 0 || b.find("float") == 0 || b == "double")))
        fail(where + "a property of an unknown type, or a list counted by a floating-point number");
      const std::string& name = p.is_list ? d : b; // property TYPE NAME, property list TYPE TYPE NAME
      if(in_points && std::find(floating_point.begin(), floating_point.end(), name) != floating_point.end()) {
        if(p.is_list || (a.find("float") != 0 && a != "double"))
          fail(where + "the point coordinate '" + name + "' is not a float or a double");
        const std::string type = p.value_bytes == 4 ? "float" : "double";
        if(one_type && !point_type.empty() && type != point_type)
          fail(where + "the point coordinates and normals are not all of one type (float or double)");
        point_type = type;
      }
      std::vector<std::string>& names = elements.back().names;
      if(std::find(names.begin(), names.end(), name) != names.end())
        fail(where + "a second property named '" + name + "' in one element");
      names.push_back(name);
      elements.back().properties.push_back(p);
    } else if(keyword == "end_header") ended = true;
  }
  // (the reader takes a header without "end_header" as ending with the file: no data)
  const std::streamoff start = ended ? std::streamoff(in.tellg()) : std::streamoff(-1);
  const unsigned long long size = std::filesystem::file_size(path);
  const unsigned long long data = start >= 0 && (unsigned long long)(start) < size ? size - (unsigned long long)(start) : 0;
  bool lists = false;
  for(const PLY_element_layout& e : elements) {
    if(e.count > 0 && e.properties.empty()) fail("an element of " + std::to_string(e.count) + " items has no property");
    if(!e.properties.empty() && e.count > data / e.properties.size())
      fail("the data (" + std::to_string(data) + " bytes) cannot hold the " + std::to_string(e.count) + " items declared");
    lists = lists || e.has_list();
  }
  if(lists && ended) check_PLY_lists(in, elements, format, data, refused);
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PLY_STRUCTURE_CHECK_H
