// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fuzz harness of the segments file and of what simplify_partition does with it: any bytes
// are read by IO::read_segments_2() (segments, or an Input_error), and the segments read, when
// they are at most 32, are given to kinetic_partition_2() (an Input_error or a partition) and,
// if its partition is valid, to simplify_polygon_partition_2(), whose result must be valid (the
// validity of the kinetic partition itself is fuzz_kinetic_partition's). A crash, another
// exception or a sanitizer report is a finding.
#include "../fuzz_support/fuzz_input_file.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_partition_simplification/IO/segments_file.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PPS = CGAL::Polygon_partition_simplification;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = urban_fuzz::input_file(data, size, ".txt");
  std::vector<K::Segment_2> segments;
  try {
    segments = PPS::IO::read_segments_2<K>(path);
  } catch(const PPS::Input_error&) {
    urban_fuzz::remove_input_file(path);
    return 0;
  }
  urban_fuzz::remove_input_file(path);
  if(segments.empty() || segments.size() > 32) return 0;
  try {
    PPS::Line_partition_2<K> partition = CGAL::kinetic_partition_2(segments);
    if(!partition.is_valid()) return 0;
    CGAL::simplify_polygon_partition_2(partition, CGAL::parameters::number_of_iterations(20));
    if(!partition.is_valid()) urban_fuzz::finding("simplify_polygon_partition_2() returned an invalid partition");
  } catch(const PPS::Input_error&) {
    // a refusal: the documented outcome of bad input
  }
  return 0;
}
