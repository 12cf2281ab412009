// Reconstructs a closed surface from points and writes it as an OFF file.
//   lex_optimal_closed_surface_example [points.xyz] [out.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/lex_optimal_closed_surface.h>

#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : CGAL::data_file_path("points_3/kitten.xyz");
  const std::string output = argc > 2 ? argv[2] : "kitten_lex.off";

  std::vector<Point> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points))) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }

  Mesh mesh;
  try {
    // No interior point given: the most persistent void of the Delaunay filtration is used.
    const auto report = CGAL::lex_optimal_closed_surface_reconstruction(points, mesh);
    std::cout << report.mesh_faces << " faces, " << report.components << " component(s), genus "
              << report.genus << ", interior persistence " << report.interior_persistence << "\n";
  } catch(const CGAL::Lex_optimal_chains::Input_error& e) {
    std::cerr << "cannot reconstruct: " << e.what() << "\n";
    return 1;
  }
  return CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)) ? 0 : 1;
}
