// Compiled by the tests execution___of__partition_geom_traits_refused_* (see CMakeLists.txt), not run:
// with PPS_REFUSED set, the code must be refused at compile time with the package's message
// (Geom_traits_check.h); without it, the same code with good traits compiles.
//   1: an exact constructions kernel with inexact constructions (Epick)
//   2: an exact predicates kernel with inexact predicates (Simple_cartesian<double>)
//   3: segments of another kernel than that of the traits given
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_partition_simplification_traits_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/kinetic_partition_2.h>

#include <vector>

#ifndef PPS_REFUSED
#define PPS_REFUSED 0
#endif

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

// a model whose exact predicates kernel is not exact
struct Inexact_predicates_traits : CGAL::Polygon_partition_simplification_traits_2<Epick>
{
  using Exact_predicates_kernel = CGAL::Simple_cartesian<double>;
};

int main()
{
  std::vector<Epick::Segment_2> segments{{{0, 0}, {1, 0}}, {{0, 0}, {0, 1}}};
#if PPS_REFUSED == 1
  using Traits = CGAL::Polygon_partition_simplification_traits_2<Epick, Epick>;
#elif PPS_REFUSED == 2
  using Traits = Inexact_predicates_traits;
#elif PPS_REFUSED == 3
  using Traits = CGAL::Polygon_partition_simplification_traits_2<Epeck>;
#else
  using Traits = CGAL::Polygon_partition_simplification_traits_2<Epick, Epeck>;
#endif
  const auto partition = CGAL::kinetic_partition_2(segments, CGAL::parameters::geom_traits(Traits()));
  return partition.is_valid() ? 0 : 1;
}
