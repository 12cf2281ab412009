// The checks of numeric options that CLI11 does not have: finite numbers (CLI11's
// PositiveNumber and NonNegativeNumber let NaN and infinity through). Shared by
// lex_reconstruct, lod2_reconstruct and simplify_partition.

#ifndef URBAN_PROGRAMS_COMMAND_LINE_CHECKS_H
#define URBAN_PROGRAMS_COMMAND_LINE_CHECKS_H

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <string>

namespace urban_programs {

// the check of an option that takes a positive finite number
inline CLI::Validator positive_number()
{
  return CLI::Validator(
    [](std::string& text) {
      const double v = std::strtod(text.c_str(), nullptr);
      return std::isfinite(v) && v > 0 ? std::string() : "must be a positive finite number, not " + text;
    },
    "POSITIVE");
}

// the check of an option that takes a finite number, zero or more
inline CLI::Validator non_negative_number()
{
  return CLI::Validator(
    [](std::string& text) {
      const double v = std::strtod(text.c_str(), nullptr);
      return std::isfinite(v) && v >= 0 ? std::string() : "must be a finite number >= 0, not " + text;
    },
    "NONNEGATIVE");
}

} // namespace urban_programs

#endif // URBAN_PROGRAMS_COMMAND_LINE_CHECKS_H
