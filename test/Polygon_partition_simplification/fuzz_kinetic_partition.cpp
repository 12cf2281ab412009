// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fuzz harness of the kinetic partition: the bytes are decoded into at most 64 segments
// (the first byte chooses how: endpoints on a 16 x 16 integer grid, 16-bit coordinates, raw
// doubles, or millimetre grids at an offset of 1e7 with moves of a few units in the last
// place), and the partition of the segments must be valid for the oracle of
// kinetic_stress_scenes.h (CGAL's exact Arrangement_2 of the output edges, with the
// coordinates the user gets and with those of the normalized frame), valid for the package's
// own check, and cover every input segment. Segments that kinetic_partition_2() documents as
// refused (zero length, too short for double precision, a coordinate beyond 1e100) are not
// produced, so a refusal is a finding too.
#include "kinetic_stress_scenes.h"
#include "../fuzz_support/fuzz_input_file.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

// Reads the bytes in order; past the end, it gives zeros.
struct Byte_reader
{
  const std::uint8_t* data;
  std::size_t size, next = 0;
  bool done() const { return next >= size; }
  std::uint8_t byte() { return next < size ? data[next++] : 0; }
  std::int16_t int16() { return std::int16_t(std::uint16_t(byte()) | std::uint16_t(byte()) << 8); }
  double raw_double()
  {
    std::uint64_t bits = 0;
    for(int k = 0; k < 8; ++k) bits |= std::uint64_t(byte()) << (8 * k);
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }
};

double coordinate(int mode, Byte_reader& in)
{
  switch(mode) {
  case 0: return double(in.byte() % 16);
  case 1: return in.int16() / 64.;
  case 2: {
    const double x = in.raw_double();
    return std::isfinite(x) ? std::fmod(x, 1e9) : 0.;
  }
  default: { // a millimetre grid at 1e7, moved by -8 to 7 units in the last place
    const std::uint8_t b = in.byte();
    const double on_grid = 1e7 + 1e-3 * double(b % 16);
    const double ulp = std::nextafter(1e7, 2e7) - 1e7;
    return on_grid + ulp * double(int(b / 16) - 8);
  }
  }
}

std::vector<kinetic_stress::Segment> decoded_segments(const std::uint8_t* data, std::size_t size)
{
  Byte_reader in{data, size};
  const int mode = in.byte() % 4;
  std::vector<kinetic_stress::Segment> segments;
  while(!in.done() && segments.size() < 64) {
    kinetic_stress::Segment s;
    for(double& c : s) c = coordinate(mode, in);
    const double dx = s[2] - s[0], dy = s[3] - s[1];
    if(dx * dx + dy * dy >= 1e-200) segments.push_back(s); // what kinetic_partition_2() accepts
  }
  return segments;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::vector<kinetic_stress::Segment> segments = decoded_segments(data, size);
  if(segments.empty()) return 0;
  const kinetic_stress::Scene_result r = kinetic_stress::run_scene(segments);
  const std::string scene = std::to_string(segments.size()) + " segments: ";
  if(r.refused) urban_fuzz::finding(scene + "refused: " + r.error);
  if(!r.defect.empty()) urban_fuzz::finding(scene + "invalid in input coordinates: " + r.defect);
  if(!r.normalized_defect.empty()) urban_fuzz::finding(scene + "invalid in the normalized frame: " + r.normalized_defect);
  if(!r.package_says_valid) urban_fuzz::finding(scene + "Line_partition_2::is_valid() is false");
  if(r.uncovered > 0) urban_fuzz::finding(scene + std::to_string(r.uncovered) + " segments not covered by edges");
  return 0;
}
