// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fuzz harness of the command-line parsing of simplify_partition
// (simplify_partition_command_line.h, what main() parses before anything is read or written):
// the input is the arguments, one per line (at most 64). A parse ends in options that hold what
// the checks promise (an output format the program writes; the numbers are the library's to
// check), or in a CLI::ParseError, which main() prints as one line with exit code 1. A crash,
// another exception, options that break a promise, or a sanitizer report is a finding.
#include "../fuzz_support/fuzz_command_line.h"

#include "../../examples/Polygon_partition_simplification/simplify_partition_command_line.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  simplify_partition::Command_line command_line;
  if(!urban_fuzz::parses(command_line, data, size, "simplify_partition")) return 0; // a refusal (or --help)
  const simplify_partition::Options& o = command_line.options;
  const std::string format = simplify_partition::extension(o.output);
  if(format != "geojson" && format != "json" && format != "wkt") urban_fuzz::finding("an output format the program does not write: " + o.output);
  if(o.epsilon_given != (command_line.app.count("--epsilon") > 0)) urban_fuzz::finding("--epsilon given but not said");
  return 0;
}
