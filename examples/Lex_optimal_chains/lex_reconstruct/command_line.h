// The command line of lex_reconstruct: its four subcommands registered on one CLI11 app, and
// the parse, shared by main.cpp and the fuzz harness of the option parsing
// (test/Lex_optimal_chains/fuzz_command_line.cpp).
#ifndef URBAN_LEX_RECONSTRUCT_COMMAND_LINE_H
#define URBAN_LEX_RECONSTRUCT_COMMAND_LINE_H

#include "closed_command.h"
#include "features_command.h"
#include "open_command.h"
#include "options_and_output.h"
#include "tiles_command.h"

#include <cstddef>
#include <string>

namespace lex_reconstruct {

class Command_line
{
public:
  Command_line() { app.require_subcommand(1); }
  Command_line(const Command_line&) = delete; // the options point into the commands
  Command_line& operator=(const Command_line&) = delete;

  // Parses the arguments for a run on `number_of_ranks` MPI ranks: afterwards exactly one
  // subcommand is parsed, with options that passed their checks. Throws CLI::ParseError
  // otherwise (CLI::CallForHelp and CLI::CallForAllHelp for --help).
  void parse(int argc, const char* const* argv, std::size_t number_of_ranks = 1)
  {
    app.parse(argc, argv);
    open.check();
    if(number_of_ranks > 1 && !tiles.parsed())
      throw CLI::ValidationError("only the tiles subcommand runs on several MPI ranks (" +
                                 std::to_string(number_of_ranks) + " here): run the others with one");
  }

  CLI::App app{"Surface reconstruction as a lexicographic optimal chain (Lex_optimal_chains)"};
  Closed_command closed{app}; // each holds the values of its options
  Open_command open{app};
  Features_command features{app};
  Tiles_command tiles{app};
};

} // namespace lex_reconstruct

#endif // URBAN_LEX_RECONSTRUCT_COMMAND_LINE_H
