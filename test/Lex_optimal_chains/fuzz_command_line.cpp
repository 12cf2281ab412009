// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fuzz harness of the command-line parsing of lex_reconstruct (command_line.h, what main()
// parses before anything is read or written): the input is the arguments, one per line (at
// most 64). A parse ends in exactly one parsed subcommand whose options passed their checks,
// or in a CLI::ParseError, which main() prints as one line with exit code 1. A crash, another
// exception, a parse with no or several subcommands, or a sanitizer report is a finding.
#include "../fuzz_support/fuzz_command_line.h"

#include "../../examples/Lex_optimal_chains/lex_reconstruct/command_line.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  lex_reconstruct::Command_line command_line;
  if(!urban_fuzz::parses(command_line, data, size, "lex_reconstruct")) return 0; // a refusal (or --help)
  const int parsed = int(command_line.closed.parsed()) + int(command_line.open.parsed()) +
                     int(command_line.features.parsed()) + int(command_line.tiles.parsed());
  if(parsed != 1) urban_fuzz::finding(std::to_string(parsed) + " subcommands parsed, not one");
  return 0;
}
