// Kinetic partition of a few segments, simplified in line space; prints the cells.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PPS = CGAL::Polygon_partition_simplification;

int main(int argc, char** argv)
{
  // An L-shaped footprint seen by a segment detector: walls in pieces, slightly noisy.
  std::vector<K::Segment_2> segments;
  if(argc > 1) { // a file of segments "x0 y0 x1 y1", lines starting with '#' skipped
    std::ifstream in(argv[1]);
    std::string line;
    while(std::getline(in, line)) {
      std::istringstream is(line);
      double x0, y0, x1, y1;
      if(line.empty() || line[0] == '#' || !(is >> x0 >> y0 >> x1 >> y1)) continue;
      segments.emplace_back(K::Point_2(x0, y0), K::Point_2(x1, y1));
    }
  } else {
    segments = {{{0, 0.02}, {9.5, -0.03}},  {{10.3, 0.01}, {20, 0.04}},   {{20.02, 0.2}, {19.97, 10}},
                {{20, 10.03}, {12.2, 9.96}}, {{12.01, 10.2}, {11.98, 18}}, {{11.5, 18.02}, {0.3, 17.97}},
                {{-0.02, 18}, {0.01, 9.4}},  {{0.03, 8.8}, {-0.01, 0.3}},  {{1, 5.05}, {19, 4.93}}};
  }

  PPS::Line_partition_2<K> partition = CGAL::kinetic_partition_2(segments);
  std::cout << "kinetic partition: " << partition.number_of_lines() << " lines, "
            << partition.number_of_vertices() << " points, " << partition.number_of_cells() << " cells\n";

  const PPS::Simplification_statistics stats = CGAL::simplify_polygon_partition_2(
    partition, PPS::parameters::concurrency_weight(0.5, PPS::parameters::orthogonality_weight(5.)));
  std::cout << "simplified: " << stats.lines_after << " lines, " << stats.points_after << " points, "
            << stats.cells_after << " cells, " << stats.orthogonal_pairs_after << " orthogonal pairs, "
            << stats.line_merges << " line merges, " << stats.point_merges << " point merges\n";

  std::vector<PPS::Line_partition_2<K>::Polygon_with_holes_2> cells;
  partition.cells(std::back_inserter(cells));
  for(const auto& cell : cells) std::cout << "cell with " << cell.outer_boundary().size() << " vertices\n";
  return partition.is_valid() ? 0 : 1;
}
