// The kinetic partition on random stress scenes (kinetic_stress_scenes.h): per generator, the
// scenes refused, the partitions that CGAL's exact arrangement of their edges finds invalid
// (with the coordinates the user gets, and with those of the normalized frame), those that the
// package's own check calls valid or invalid against the oracle, the scenes with an input
// segment left uncovered, the scenes where an end stopped at a corner went on to split a cell
// around a chain of corners hanging at a point, the scenes where the last step of the rounding
// removed edges to keep the partition valid, and the time of the kinetic partition, against that of CGAL's
// exact arrangement of the input segments (the baseline, measured in the same run).
//   benchmark_kinetic_partition_stress [scenes_per_generator=1000] [first_seed=0] [largest_scene=10000] [generator...]
#include "kinetic_stress_scenes.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

// time of CGAL's exact arrangement of the input segments (the baseline)
double arrangement_seconds(const std::vector<kinetic_stress::Segment>& scene)
{
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  std::vector<EK::Segment_2> segments;
  for(const auto& x : scene) segments.emplace_back(EK::Point_2(x[0], x[1]), EK::Point_2(x[2], x[3]));
  const auto t0 = std::chrono::steady_clock::now();
  CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>> arrangement;
  CGAL::insert(arrangement, segments.begin(), segments.end());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

int main(int argc, char** argv)
{
  const unsigned long long scenes = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000;
  const unsigned long long first = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 0;
  const std::size_t largest = argc > 3 ? std::size_t(std::strtoull(argv[3], nullptr, 10)) : 10000;
  std::vector<kinetic_stress::Generator> generators;
  for(int a = 4; a < argc; ++a)
    for(auto g : kinetic_stress::all_generators)
      if(std::strcmp(argv[a], kinetic_stress::name(g)) == 0) generators.push_back(g);
  if(generators.empty()) generators.assign(std::begin(kinetic_stress::all_generators), std::end(kinetic_stress::all_generators));

  std::printf("%-11s %7s %8s %8s %10s %12s %12s %10s %9s %8s %10s %10s %9s\n", "generator", "scenes", "refused",
              "invalid", "invalid_nf", "false_valid", "false_invld", "uncovered", "extended", "removed", "kinetic_s",
              "arrange_s", "ratio");
  std::size_t total_invalid = 0;
  for(const auto g : generators) {
    std::size_t refused = 0, invalid = 0, invalid_normalized = 0, false_valid = 0, false_invalid = 0, uncovered = 0,
                extended = 0, removed = 0;
    double kinetic = 0, baseline = 0;
    std::vector<std::string> examples;
    for(unsigned long long seed = first; seed < first + scenes; ++seed) {
      const auto scene = kinetic_stress::scene(g, seed, largest);
      const kinetic_stress::Scene_result r = kinetic_stress::run_scene(scene);
      auto note = [&](const std::string& what) {
        if(examples.size() < 5) examples.push_back("seed " + std::to_string(seed) + ": " + what);
      };
      if(r.refused) { ++refused; note("refused: " + r.error); continue; }
      kinetic += r.seconds;
      baseline += arrangement_seconds(scene);
      if(!r.defect.empty()) { ++invalid; note(r.defect); }
      if(!r.normalized_defect.empty()) { ++invalid_normalized; if(r.defect.empty()) note("normalized: " + r.normalized_defect); }
      if(r.package_says_valid && !r.normalized_defect.empty()) ++false_valid;
      if(!r.package_says_valid && r.normalized_defect.empty()) ++false_invalid;
      if(r.uncovered > 0) { ++uncovered; note(std::to_string(r.uncovered) + " segments uncovered"); }
      if(r.extended_corner_ends > 0) ++extended;
      if(r.removed_edges > 0) { ++removed; note(std::to_string(r.removed_edges) + " edges removed by the rounding"); }
    }
    total_invalid += invalid + invalid_normalized;
    std::printf("%-11s %7llu %8zu %8zu %10zu %12zu %12zu %10zu %9zu %8zu %10.3f %10.3f %9.2f\n", kinetic_stress::name(g),
                scenes, refused, invalid, invalid_normalized, false_valid, false_invalid, uncovered, extended, removed,
                kinetic, baseline, baseline > 0 ? kinetic / baseline : 0.);
    for(const auto& e : examples) std::printf("    %s\n", e.c_str());
    std::fflush(stdout);
  }
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  std::printf("invalid partitions: %zu; peak memory: %.1f MB\n", total_invalid, double(usage.ru_maxrss) / 1024.);
  return 0;
}
