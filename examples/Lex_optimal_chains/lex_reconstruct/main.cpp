// lex_reconstruct: surface reconstruction from a point cloud as a lexicographic optimal chain.
//
//   lex_reconstruct closed INPUT OUTPUT [--interior X,Y,Z]... [--exterior X,Y,Z]...
//                   [--min-persistence V] [--robust [--smoothing-neighbors K]]
//                   [--keep-non-manifold] [--threads N] [--ascii] [--json]
//   lex_reconstruct open INPUT OUTPUT (--boundary FILE | --auto-boundary)
//                   [--coefficients z2|q] [--remove-blocking-points]
//                   [--drop-boundary-triangles | --keep-boundary-triangles] [--keep-non-manifold]
//                   [--threads N] [--ascii] [--json]
//   lex_reconstruct tiles INPUT OUTPUT_DIR --tile-size S [--seam-spacing V] [--merged FILE]
//                   [--classes C,...] [--out-of-core [--bucket-dir DIR]] [--coefficients z2|q]
//                   [--keep-non-manifold] [--threads N] [--ascii] [--json]
//   mpirun -np K lex_reconstruct_mpi tiles ...   (the same, the tiles dealt out to K ranks)
//   lex_reconstruct features INPUT OUTPUT [--threshold V] [--offset E] [--drop-largest K]
//                   [--borders] [--relative] [--ascii] [--json]
//
// INPUT: points as XYZ, PLY, OFF or uncompressed LAS (1.0 to 1.4; --classes keeps the points of
// these classifications). OUTPUT: a mesh as OFF, PLY (binary unless --ascii) or
// OBJ, by extension.
// Boundary FILE: CGAL's polylines text format, one closed polyline per line:
// "n x1 y1 z1 ... xn yn zn" with the last point equal to the first.
// One header per subcommand (closed_command.h, open_command.h, features_command.h,
// tiles_command.h), what they share in options_and_output.h, their registration and the parse
// in command_line.h; this file runs the parsed subcommand and handles the errors. lex_reconstruct_mpi is this file compiled with
// PROCESS_GROUP_WITH_MPI (../Process_group.h).
// On error: a one-line reason on stderr, exit code 1, and no output file.

#include "command_line.h"

#include <exception>
#include <string>

int main(int argc, char** argv)
{
  using namespace lex_reconstruct;
  Process_group group(argc, argv); // MPI_Init under lex_reconstruct_mpi
  Command_line command_line;
  try {
    command_line.parse(argc, argv, group.size());
  } catch(const CLI::CallForHelp& e) {
    return group.is_root() ? command_line.app.exit(e) : 0;
  } catch(const CLI::CallForAllHelp& e) {
    return group.is_root() ? command_line.app.exit(e) : 0;
  } catch(const CLI::ParseError& e) { // one line and exit code 1, as for bad input
    if(group.is_root()) print_error(std::string(e.what()) + " (see --help)");
    return 1;
  }
  try {
    if(command_line.closed.parsed()) return command_line.closed.run();
    if(command_line.tiles.parsed()) return command_line.tiles.run(group);
    if(command_line.features.parsed()) return command_line.features.run();
    return command_line.open.run();
  } catch(const Reported_by_another_rank&) {
    return 1;
  } catch(const std::exception& e) {
    print_error(e.what());
    return 1;
  }
}
