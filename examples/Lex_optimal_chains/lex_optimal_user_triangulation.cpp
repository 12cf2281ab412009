// Meshes a terrain on a Delaunay triangulation that the caller builds and keeps: the vertices
// carry the index of their input point (a vertex base with info), the boundary is inserted
// into it, and the open surface is read from it without copying it.
//   lex_optimal_user_triangulation [points.ply] [out.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>
#include <CGAL/Lex_optimal_chains/insert_boundary.h>

#include <iostream>
#include <limits>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::size_t, Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using DT = CGAL::Delaunay_triangulation_3<Kernel, Tds, CGAL::Fast_location>;
namespace LOC = CGAL::Lex_optimal_chains;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : CGAL::data_file_path("points_3/b9_training.ply");
  const std::string output = argc > 2 ? argv[2] : "b9_user_triangulation.off";
  std::vector<Point> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points)) || points.empty()) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }

  // the user's triangulation: each vertex knows the index of its point
  std::vector<std::pair<Point, std::size_t>> indexed;
  for(std::size_t i = 0; i < points.size(); ++i) indexed.emplace_back(points[i], i);
  DT dt(indexed.begin(), indexed.end());

  Mesh mesh;
  try {
    // a polygon just outside the footprint; its vertices are new vertices of `dt`
    const std::vector<std::vector<Point>> boundary{LOC::footprint_boundary(points)};
    const LOC::Inserted_boundary<DT> inserted = LOC::insert_boundary(dt, boundary);
    for(const auto& v : inserted.new_vertices) v->info() = std::numeric_limits<std::size_t>::max();

    const auto report = CGAL::lex_optimal_open_surface_mesh(dt, inserted.edges, mesh);
    std::cout << report.mesh_faces << " faces on " << dt.number_of_vertices() << " vertices ("
              << inserted.new_vertices.size() << " boundary vertices inserted), "
              << report.resolved_non_manifold_vertices << " non-manifold vertices resolved\n";
  } catch(const LOC::Input_error& e) {
    std::cerr << "cannot mesh: " << e.what() << "\n";
    return 1;
  }

  // the triangulation is still there: for instance, the input points that the surface leaves out
  std::vector<bool> used(points.size(), false);
  for(const auto v : mesh.vertices()) {
    const DT::Vertex_handle h = dt.nearest_vertex(mesh.point(v));
    if(h->info() < points.size()) used[h->info()] = true;
  }
  std::size_t unused = 0;
  for(bool u : used) unused += !u;
  std::cout << unused << " of " << points.size() << " input points are not vertices of the surface\n";
  return CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)) ? 0 : 1;
}
