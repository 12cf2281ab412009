// Kinetic partition and simplification of synthetic building footprints at the sizes of
// Table 3.1 of the thesis (330, 1,422, 2,724 polygons) and beyond (about 20,000), in one run:
// times, reduction ratios, the ratio to the thesis's simplification times, peak memory.
// Each partition is simplified four times: with the default collapse distance (1% of the
// half-diagonal, so a larger scene is a different problem per building), with a collapse
// distance of 1 m at every size (the same buildings, more of them: the growth of the time),
// with the default collapse distance and a faster step schedule (step ratio 0.94 instead
// of 0.97: half the gradient steps per descent, for a somewhat smaller reduction), and with the
// default collapse distance and the points sent outside the partition removed (case (b2) of the
// thesis, `remove_far_points`).
//   benchmark_partition_simplification [max_buildings]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include "synthetic_footprints.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PPS = CGAL::Polygon_partition_simplification;

int main(int argc, char** argv)
{
  const std::size_t max_buildings = argc > 1 ? std::size_t(std::atol(argv[1])) : 1000;
  // buildings, and the thesis's polygons and simplification time at that size (Table 3.1)
  struct Size { std::size_t buildings; double thesis_polygons, thesis_seconds; };
  const Size sizes[] = {{15, 330, 0.4}, {64, 1422, 1.5}, {124, 2724, 5.3}, {900, 0, 0}};
  std::printf("%9s %9s %9s %10s %8s %5s %9s %9s %11s %9s %10s %9s %8s %9s %7s %8s\n", "buildings", "segments", "polygons",
              "kinetic_s", "epsilon", "r", "simpl_s", "polygons", "lines", "orthos", "reduction", "thesis_s", "speedup",
              "rejected", "rounds", "steps");
  double reference_seconds = 0; // with 1 m, per building, at 124 buildings
  for(const Size& size : sizes) {
    if(size.buildings > max_buildings) break;
    const auto f = synthetic::make_footprints(size.buildings, 0.05, 7);
    std::vector<K::Segment_2> segments;
    for(const auto& s : f.segments) segments.emplace_back(K::Point_2(s[0], s[1]), K::Point_2(s[2], s[3]));
    const auto t0 = std::chrono::steady_clock::now();
    const auto kinetic_partition = CGAL::kinetic_partition_2(segments);
    const double kinetic = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    struct Setting { double epsilon, ratio; bool remove_far_points; }; // epsilon 0: the default
    for(const Setting setting :
        {Setting{0., 0.97, false}, Setting{1., 0.97, false}, Setting{0., 0.94, false}, Setting{0., 0.97, true}}) {
      const double epsilon = setting.epsilon;
      auto partition = kinetic_partition;
      const double default_epsilon = 0.01 * kinetic_partition.frame().scale;
      const auto np = PPS::parameters::step_ratio(setting.ratio, PPS::parameters::remove_far_points(setting.remove_far_points));
      const auto stats = epsilon > 0 ? CGAL::simplify_polygon_partition_2(partition, PPS::parameters::collapse_distance(epsilon, np))
                                     : CGAL::simplify_polygon_partition_2(partition, np);
      char thesis[32] = "-", speedup[32] = "-", lines[32], eps[32];
      if(size.thesis_seconds > 0 && epsilon == 0) {
        std::snprintf(thesis, sizeof thesis, "%.2f", size.thesis_seconds);
        std::snprintf(speedup, sizeof speedup, "%.1fx", size.thesis_seconds / stats.seconds);
      }
      std::snprintf(lines, sizeof lines, "%zu->%zu", stats.lines_before, stats.lines_after);
      std::snprintf(eps, sizeof eps, "%.2f m", epsilon > 0 ? epsilon : default_epsilon);
      std::printf("%9zu %9zu %9zu %10.3f %8s %5.2f %9.3f %9zu %11s %9zu %9.2fx %9s %8s %9zu %7zu %8zu", size.buildings,
                  segments.size(), stats.cells_before, kinetic, eps, setting.ratio, stats.seconds, stats.cells_after, lines,
                  stats.orthogonal_pairs_after, double(stats.cells_before) / double(stats.cells_after), thesis, speedup,
                  stats.rejected_rounds, stats.rounds, stats.iterations);
      if(setting.remove_far_points) std::printf("   far points removed (%zu)", stats.far_point_removals);
      if(epsilon > 0 && setting.ratio == 0.97) {
        const double per_building = stats.seconds / double(size.buildings);
        if(size.buildings == 124) reference_seconds = per_building;
        if(size.buildings > 124 && reference_seconds > 0)
          std::printf("   time per building %.2fx that at 124", per_building / reference_seconds);
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  }
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  std::printf("peak memory: %.1f MB\n", double(usage.ru_maxrss) / 1024.);
  return 0;
}
