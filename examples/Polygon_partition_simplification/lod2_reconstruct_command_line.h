// The command line of lod2_reconstruct: its options, their checks and the parse, shared by
// lod2_reconstruct.cpp and the fuzz harness of the option parsing
// (test/Polygon_partition_simplification/fuzz_lod2_command_line.cpp). Everything that can be
// checked without reading a file is checked at the parse.

#ifndef URBAN_LOD2_RECONSTRUCT_COMMAND_LINE_H
#define URBAN_LOD2_RECONSTRUCT_COMMAND_LINE_H

#include "../Lex_optimal_chains/Command_line_checks.h"

#include <CLI/CLI.hpp>

#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace lod2_reconstruct {

struct Options
{
  std::string input, output, planes = "detect", classes = "2:6", footprints_file;
  double lambda1 = 0.5, lambda2 = 5, epsilon = 0; // epsilon 0: not given
  int threads = 0;
  bool json = false, walls_at_eaves = false;
  std::vector<int> ground_classes, building_classes; // of `classes`, after the parse
};

inline bool ends_with(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// the ground and building classes of --classes G[,G...]:B[,B...]; throws CLI::ValidationError
inline std::pair<std::vector<int>, std::vector<int>> parse_classes(const std::string& text)
{
  auto refuse = [&text](const std::string& what) {
    return CLI::ValidationError("--classes", what + ", as 2:6 or 2,9:6, not '" + text + "'");
  };
  auto list = [&](const std::string& part) {
    std::vector<int> values;
    std::stringstream in(part);
    std::string item;
    while(std::getline(in, item, ',')) {
      std::size_t used = 0;
      int value = -1;
      try { value = std::stoi(item, &used); } catch(const std::exception&) { used = 0; }
      if(used != item.size() || value < 0 || value > 255)
        throw refuse("takes ground classes, a colon and building classes (0 to 255)");
      values.push_back(value);
    }
    if(values.empty()) throw refuse("needs at least one ground and one building class");
    return values;
  };
  const std::size_t colon = text.find(':');
  if(colon == std::string::npos) throw refuse("takes ground classes, a colon and building classes");
  return {list(text.substr(0, colon)), list(text.substr(colon + 1))};
}

class Command_line
{
public:
  Command_line()
  {
    Options& o = options;
    app.add_option("INPUT", o.input, "points: .ply, .xyz, .pwn, .off or .las")->required();
    app.add_option("OUTPUT", o.output, "model: .off, .ply, .obj, .city.json (CityJSON 1.1) or .city.jsonl (CityJSON Text Sequences, tiles)")
      ->required()
      ->check(CLI::Validator(
        [](std::string& name) {
          for(const char* e : {".off", ".ply", ".obj", ".city.json", ".city.jsonl"})
            if(ends_with(name, e)) return std::string();
          return "must end in .off, .ply, .obj, .city.json or .city.jsonl, not " + name;
        },
        "MODEL"));
    app.add_option("--planes", o.planes, "detect (region growing, default) or the name of an int point property giving the plane of each point (scenes only)");
    app.add_option("--classes", o.classes, "ground and building classes of a classified input, as GROUND[,...]:BUILDING[,...] (default 2:6)");
    app.add_option("--footprints", o.footprints_file, "GeoJSON polygons: one building per footprint, made of the building points inside it");
    app.add_option("--threads", o.threads, "threads modelling the buildings of a tile, 0 for all cores (default; per rank under MPI)")
      ->check(CLI::Range(0, 4096));
    app.add_option("--lambda1", o.lambda1, "weight of the concurrency term of the simplification, default 0.5")
      ->check(urban_programs::non_negative_number());
    app.add_option("--lambda2", o.lambda2, "weight of the orthogonality term, default 5")->check(urban_programs::non_negative_number());
    app.add_option("--epsilon", o.epsilon, "longest edge to collapse in the simplification, input units (default: 1% of the half-diagonal)")
      ->check(urban_programs::positive_number());
    app.add_flag("--walls-at-eaves", o.walls_at_eaves,
                 "put the walls at the edges of the roofs, as seen from above (default: on the facades, where facade points show them)");
    app.add_flag("--json", o.json, "print one line of JSON statistics");
  }
  Command_line(const Command_line&) = delete; // the options point into `options`
  Command_line& operator=(const Command_line&) = delete;

  // Parses the arguments; afterwards the options passed their checks and the classes are
  // read. Throws CLI::ParseError otherwise (CLI::CallForHelp for --help).
  void parse(int argc, const char* const* argv)
  {
    app.parse(argc, argv);
    std::tie(options.ground_classes, options.building_classes) = parse_classes(options.classes);
  }

  CLI::App app{"LOD2 building models from a point cloud (planes, segments, kinetic partition, simplification, lift)"};
  Options options;
};

} // namespace lod2_reconstruct

#endif // URBAN_LOD2_RECONSTRUCT_COMMAND_LINE_H
