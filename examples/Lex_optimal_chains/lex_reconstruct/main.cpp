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
// tiles_command.h), what they share in options_and_output.h; this file registers them, parses
// the command line and handles the errors. lex_reconstruct_mpi is this file compiled with
// PROCESS_GROUP_WITH_MPI (../Process_group.h).
// On error: a one-line reason on stderr, exit code 1, and no output file.

#include "closed_command.h"
#include "features_command.h"
#include "open_command.h"
#include "options_and_output.h"
#include "tiles_command.h"

#include <exception>
#include <string>

int main(int argc, char** argv)
{
  using namespace lex_reconstruct;
  Process_group group(argc, argv); // MPI_Init under lex_reconstruct_mpi
  CLI::App app{"Surface reconstruction as a lexicographic optimal chain (Lex_optimal_chains)"};
  app.require_subcommand(1);
  Closed_command closed(app); // each holds the values of its options
  Open_command open(app);
  Features_command features(app);
  Tiles_command tiles(app);
  try {
    app.parse(argc, argv);
    open.check();
    if(group.size() > 1 && !tiles.parsed())
      throw CLI::ValidationError("only the tiles subcommand runs on several MPI ranks (" +
                                 std::to_string(group.size()) + " here): run the others with one");
  } catch(const CLI::CallForHelp& e) {
    return group.is_root() ? app.exit(e) : 0;
  } catch(const CLI::CallForAllHelp& e) {
    return group.is_root() ? app.exit(e) : 0;
  } catch(const CLI::ParseError& e) { // one line and exit code 1, as for bad input
    if(group.is_root()) print_error(std::string(e.what()) + " (see --help)");
    return 1;
  }
  try {
    if(closed.parsed()) return closed.run();
    if(tiles.parsed()) return tiles.run(group);
    if(features.parsed()) return features.run();
    return open.run();
  } catch(const Reported_by_another_rank&) {
    return 1;
  } catch(const std::exception& e) {
    print_error(e.what());
    return 1;
  }
}
