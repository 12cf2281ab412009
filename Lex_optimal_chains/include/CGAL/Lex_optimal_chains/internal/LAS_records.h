// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LAS_RECORDS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LAS_RECORDS_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// little-endian fields of a byte buffer
template <class T>
T las_field(const unsigned char* bytes)
{
  T value;
  unsigned char ordered[sizeof(T)];
  for(std::size_t i = 0; i < sizeof(T); ++i) ordered[i] = bytes[i]; // the file is little-endian
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  std::reverse(ordered, ordered + sizeof(T));
#endif
  std::memcpy(&value, ordered, sizeof(T));
  return value;
}


// The reader behind IO::for_each_las_record(): checks the header (LAS 1.0 to 1.4, point formats
// 0 to 10, no LASzip, a record length that holds the format, finite scales and offsets, a file
// as long as the header says), then calls f(point, classification) for each record, read in
// chunks of at most 4 MB.
template <class Point_3, class Function>
void read_las_records(const std::string& path, const Function& f)
{
  auto fail = [&](const std::string& why) {
    return Input_error(Input_error_code::UNREADABLE_FILE, "'" + path + "': " + why);
  };
  std::ifstream in(path, std::ios::binary);
  if(!in) throw fail("cannot open it");
  std::array<unsigned char, 375> header{};
  in.read(reinterpret_cast<char*>(header.data()), 227);
  if(in.gcount() < 227 || std::memcmp(header.data(), "LASF", 4) != 0) throw fail("not a LAS file (no LASF signature)");
  const unsigned major = header[24], minor = header[25];
  const std::uint16_t header_size = las_field<std::uint16_t>(&header[94]);
  const std::uint32_t data_offset = las_field<std::uint32_t>(&header[96]);
  const unsigned format_byte = header[104];
  const std::uint16_t record_length = las_field<std::uint16_t>(&header[105]);
  if(major != 1 || minor > 4)
    throw fail("LAS version " + std::to_string(major) + "." + std::to_string(minor) + " is not supported (1.0 to 1.4)");
  // LASzip marks compressed data by the two high bits of the format
  if(format_byte & 0xC0)
    throw fail("compressed LAS (LAZ) is not supported: decompress it first (laszip, or pdal translate in.laz out.las)");
  const unsigned format = format_byte;
  static const std::uint16_t minimal_length[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  if(format > 10) throw fail("point data record format " + std::to_string(format) + " is not supported (0 to 10)");
  if(record_length < minimal_length[format])
    throw fail("records of " + std::to_string(record_length) + " bytes are too short for point format " +
               std::to_string(format) + " (" + std::to_string(minimal_length[format]) + ")");
  std::uint64_t count = las_field<std::uint32_t>(&header[107]);
  if(minor >= 4) {
    if(header_size < 375) throw fail("a LAS 1.4 header has 375 bytes, not " + std::to_string(header_size));
    in.read(reinterpret_cast<char*>(header.data()) + 227, 375 - 227);
    if(in.gcount() < 375 - 227) throw fail("the header is cut short");
    const std::uint64_t count_64 = las_field<std::uint64_t>(&header[247]);
    if(count_64 != 0) count = count_64;
  }
  double scale[3], offset[3];
  for(int c = 0; c < 3; ++c) {
    scale[c] = las_field<double>(&header[131 + 8 * c]);
    offset[c] = las_field<double>(&header[155 + 8 * c]);
    if(!std::isfinite(scale[c]) || scale[c] == 0 || !std::isfinite(offset[c]))
      throw fail("the scale and offset of the header are not finite, nonzero numbers");
  }
  // the file holds the records its header declares
  in.seekg(0, std::ios::end);
  const std::uint64_t size = std::uint64_t(in.tellg());
  if(data_offset < header_size || data_offset > size || (size - data_offset) / record_length < count)
    throw fail("the file is shorter than its header says (" + std::to_string(count) + " points of " +
               std::to_string(record_length) + " bytes from byte " + std::to_string(data_offset) + ")");
  in.seekg(data_offset);
  const std::size_t class_offset = format <= 5 ? 15 : 16;
  const unsigned class_mask = format <= 5 ? 0x1F : 0xFF;
  // records read in chunks of at most 4 MB (a record can be 65,535 bytes long)
  const std::uint64_t chunk = std::max<std::uint64_t>(1, std::min<std::uint64_t>(count, (std::uint64_t(1) << 22) / record_length));
  std::vector<unsigned char> buffer(std::size_t(chunk * record_length));
  for(std::uint64_t done = 0; done < count;) {
    const std::uint64_t n = std::min<std::uint64_t>(chunk, count - done);
    in.read(reinterpret_cast<char*>(buffer.data()), std::streamsize(n * record_length));
    if(std::uint64_t(in.gcount()) != n * record_length) throw fail("cannot read the points");
    for(std::uint64_t i = 0; i < n; ++i) {
      const unsigned char* record = buffer.data() + i * record_length;
      f(Point_3(las_field<std::int32_t>(record) * scale[0] + offset[0],
                las_field<std::int32_t>(record + 4) * scale[1] + offset[1],
                las_field<std::int32_t>(record + 8) * scale[2] + offset[2]),
        int(record[class_offset] & class_mask));
    }
    done += n;
  }
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LAS_RECORDS_H
