// Meshes an aerial LiDAR tile as an open surface bounded by a polygon around its footprint,
// and writes it as an OFF file.
//   lex_optimal_open_surface_example [points.ply] [out.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>

#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : CGAL::data_file_path("points_3/b9_training.ply");
  const std::string output = argc > 2 ? argv[2] : "b9_open.off";

  std::vector<Point> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points))) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }

  Mesh mesh;
  try {
    // the boundary: a convex polygon just outside the xy-footprint, on the convex hull
    const std::vector<std::vector<Point>> boundary{LOC::footprint_boundary(points)};
    // oriented chains (Q); the triangles joining the polygon to the points are dropped
    const auto report = CGAL::lex_optimal_open_surface_reconstruction(
      points, boundary, mesh,
      LOC::parameters::coefficient_field(LOC::Coefficient_field::Q, LOC::parameters::drop_boundary_triangles(true)));
    std::cout << report.mesh_faces << " faces; representative chain of " << report.number_of_representative_triangles
              << " triangles, optimal chain of " << report.number_of_facets << " triangles ("
              << report.dropped_triangles << " dropped)\n";
  } catch(const LOC::Input_error& e) {
    std::cerr << "cannot reconstruct: " << e.what() << "\n";
    return 1;
  }
  return CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)) ? 0 : 1;
}
