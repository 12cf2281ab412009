// The command line of simplify_partition: its options, their checks and the parse, shared by
// simplify_partition.cpp and the fuzz harness of the option parsing
// (test/Polygon_partition_simplification/fuzz_simplify_command_line.cpp). The output format is
// checked at the parse; the weights, the angle and epsilon are checked by the library, whose
// reason the program prints (the demo's plugin gives the same).

#ifndef URBAN_SIMPLIFY_PARTITION_COMMAND_LINE_H
#define URBAN_SIMPLIFY_PARTITION_COMMAND_LINE_H

#include <CLI/CLI.hpp>

#include <cctype>
#include <string>

namespace simplify_partition {

// the extension of `file`, in lower case, without the dot
inline std::string extension(const std::string& file)
{
  const auto dot = file.rfind('.');
  std::string e = dot == std::string::npos ? "" : file.substr(dot + 1);
  for(char& ch : e) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return e;
}

struct Options
{
  std::string input, output, svg;
  double lambda1 = 0.5, lambda2 = 5, alpha_max = 5;
  double epsilon = 0;
  bool epsilon_given = false; // if not: 1% of the half-diagonal of the partition
  bool json = false, remove_far_points = false;
};

class Command_line
{
public:
  Command_line()
  {
    Options& o = options;
    app.add_option("SEGMENTS", o.input, "segments, one per line: x0 y0 x1 y1")->required();
    app.add_option("OUTPUT", o.output, "cells of the simplified partition (.geojson, .json or .wkt)")
      ->required()
      ->check(CLI::Validator(
        [](std::string& name) {
          const std::string e = extension(name);
          return e == "geojson" || e == "json" || e == "wkt" ? std::string()
                                                             : "must end in .geojson, .json or .wkt, not " + name;
        },
        "CELLS"));
    app.add_option("--lambda1", o.lambda1, "weight of the concurrency term (edge collapses), default 0.5");
    app.add_option("--lambda2", o.lambda2, "weight of the orthogonality term, default 5");
    app.add_option("--epsilon", o.epsilon, "longest edge to collapse, input units, also the unit of length of the energy (default: 1% of the half-diagonal)");
    app.add_option("--alpha-max", o.alpha_max, "angle to 90 degrees under which lines are pulled to orthogonality (0 to 90, default 5)");
    app.add_option("--svg", o.svg, "draws the partition before and after, side by side");
    app.add_flag("--remove-far-points", o.remove_far_points,
                 "case (b2) of the thesis: remove the points sent outside the partition with their edges");
    app.add_flag("--json", o.json, "prints one JSON line of statistics");
  }
  Command_line(const Command_line&) = delete; // the options point into `options`
  Command_line& operator=(const Command_line&) = delete;

  // Parses the arguments; afterwards the options passed their checks. Throws CLI::ParseError
  // otherwise (CLI::CallForHelp for --help).
  void parse(int argc, const char* const* argv)
  {
    app.parse(argc, argv);
    options.epsilon_given = app.count("--epsilon") > 0;
  }

  CLI::App app{"Kinetic partition of 2D segments and its simplification in line space"};
  Options options;
};

} // namespace simplify_partition

#endif // URBAN_SIMPLIFY_PARTITION_COMMAND_LINE_H
