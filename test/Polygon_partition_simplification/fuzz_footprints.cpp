// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fuzz harness of the footprints reader of lod2_reconstruct (GeoJSON_footprints.h): any
// bytes give polygons with finite coordinates, each ring with at least 3 vertices, or one
// std::runtime_error; nothing else (a crash, another exception, a sanitizer report) is allowed.
#include "GeoJSON_footprints.h"
#include "../fuzz_support/fuzz_input_file.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

namespace {

void check_ring(const CGAL::Polygon_2<K>& ring)
{
  if(ring.size() < 3) urban_fuzz::finding("a ring of " + std::to_string(ring.size()) + " vertices was read");
  for(const auto& p : ring.vertices())
    if(!std::isfinite(p.x()) || !std::isfinite(p.y())) urban_fuzz::finding("a coordinate that is not finite was read");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    for(const auto& polygon : lod2_reconstruct::read_GeoJSON_footprints<K>(in, "fuzz.geojson")) {
      check_ring(polygon.outer_boundary());
      for(const auto& hole : polygon.holes()) check_ring(hole);
    }
  } catch(const std::runtime_error&) {
    // a refusal: the documented outcome of bad input
  }
  return 0;
}
