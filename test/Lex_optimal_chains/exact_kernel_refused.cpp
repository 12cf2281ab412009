// Compiled by expect_compile_error.cmake, not built: with LEX_KERNEL an exact-constructions
// kernel, the reconstruction must be refused at compile time with the package's message; with
// Epick, the same code must compile (so that the failure is the check, not the code).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lex_optimal_closed_surface.h>

#include <vector>

using Kernel = LEX_KERNEL;

int main()
{
  std::vector<Kernel::Point_3> points;
  CGAL::Surface_mesh<Kernel::Point_3> mesh;
  CGAL::lex_optimal_closed_surface_reconstruction(points, mesh);
  return 0;
}
