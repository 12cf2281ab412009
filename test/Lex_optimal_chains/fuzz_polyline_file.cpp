// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fuzz harness of the boundary polylines reader (IO::read_polyline_file(), what
// lex_reconstruct open --boundary reads): any bytes give polylines of finite points, or an
// Input_error. A crash, another exception or a sanitizer report is a finding.
#include "../fuzz_support/fuzz_input_file.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lex_optimal_chains/IO/input_files.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = urban_fuzz::input_file(data, size, ".polylines.txt");
  try {
    for(const auto& polyline : CGAL::Lex_optimal_chains::IO::read_polyline_file<K::Point_3>(path))
      for(const auto& p : polyline)
        if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
          urban_fuzz::finding("a coordinate that is not finite was read");
  } catch(const CGAL::Lex_optimal_chains::Input_error&) {
    // a refusal: the documented outcome of bad input
  }
  urban_fuzz::remove_input_file(path);
  return 0;
}
