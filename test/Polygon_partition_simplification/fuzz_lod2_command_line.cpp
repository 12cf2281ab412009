// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fuzz harness of the command-line parsing of lod2_reconstruct (lod2_reconstruct_command_line.h,
// what main() parses before anything is read or written): the input is the arguments, one per
// line (at most 64). A parse ends in options that hold what the checks promise (an output
// format the program writes, classes in 0..255 on both sides of the colon, finite weights >= 0,
// threads >= 0), or in a CLI::ParseError, which main() prints as one line with exit code 1. A
// crash, another exception, options that break a promise, or a sanitizer report is a finding.
#include "../fuzz_support/fuzz_command_line.h"

#include "../../examples/Polygon_partition_simplification/lod2_reconstruct_command_line.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  lod2_reconstruct::Command_line command_line;
  if(!urban_fuzz::parses(command_line, data, size, "lod2_reconstruct")) return 0; // a refusal (or --help)
  const lod2_reconstruct::Options& o = command_line.options;
  bool format = false;
  for(const char* e : {".off", ".ply", ".obj", ".city.json", ".city.jsonl"}) format = format || lod2_reconstruct::ends_with(o.output, e);
  if(!format) urban_fuzz::finding("an output format the program does not write: " + o.output);
  if(o.ground_classes.empty() || o.building_classes.empty()) urban_fuzz::finding("no ground or no building class");
  for(const std::vector<int>* classes : {&o.ground_classes, &o.building_classes})
    for(const int c : *classes)
      if(c < 0 || c > 255) urban_fuzz::finding("a class out of 0..255: " + std::to_string(c));
  for(const double w : {o.lambda1, o.lambda2, o.epsilon}) // epsilon 0: not given
    if(!std::isfinite(w) || w < 0) urban_fuzz::finding("a weight or length that is not finite and >= 0");
  if(o.threads < 0) urban_fuzz::finding("a negative number of threads");
  return 0;
}
