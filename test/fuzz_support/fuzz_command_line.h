// Copyright (c) 2026  The Lex_optimal_chains and Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What the fuzz harnesses of the three programs' command lines share: the fuzzer's bytes are
// the arguments, one per line (at most 64), and a parse ends in options or in a
// CLI::ParseError (which the programs print as one line with exit code 1); anything else is a
// finding.

#ifndef URBAN_FUZZ_COMMAND_LINE_H
#define URBAN_FUZZ_COMMAND_LINE_H

#include "fuzz_input_file.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

namespace urban_fuzz {

// Parses `program` followed by the lines of the `size` bytes with `command_line.parse(argc,
// argv)`: true when it parsed, false on a CLI::ParseError (a refusal, or --help); another
// exception is a finding.
template <class CommandLine>
bool parses(CommandLine& command_line, const std::uint8_t* data, std::size_t size, const std::string& program)
{
  std::vector<std::string> arguments{program};
  std::string argument;
  for(std::size_t i = 0; i < size && arguments.size() <= 64; ++i) {
    if(data[i] == '\n') {
      arguments.push_back(argument);
      argument.clear();
    } else {
      argument.push_back(char(data[i]));
    }
  }
  if(!argument.empty() && arguments.size() <= 64) arguments.push_back(argument);
  std::vector<const char*> argv;
  for(const std::string& a : arguments) argv.push_back(a.c_str());
  try {
    command_line.parse(int(argv.size()), argv.data());
  } catch(const CLI::ParseError&) {
    return false;
  } catch(const std::exception& e) {
    finding(std::string("the parse threw something else than CLI::ParseError: ") + e.what());
  }
  return true;
}

} // namespace urban_fuzz

#endif // URBAN_FUZZ_COMMAND_LINE_H
