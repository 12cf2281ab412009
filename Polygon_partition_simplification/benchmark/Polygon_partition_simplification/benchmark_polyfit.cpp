// CGAL's PolyFit (Polygonal_surface_reconstruction, GLPK) on the inputs of the peer benchmarks
// of the LOD2 pipeline (lod2_peer_benchmark.h), with the planes of CGAL's region growing as in
// CGAL 5.5's example polyfit_example_with_region_growing.cpp, its lengths scaled from the
// spacing of the example's data (points_3/cube.pwn: 0.00771 m, the average distance to the 6
// nearest neighbours) to that of the input s: neighbours within 2.59 s (0.02 m in the example),
// points within 0.259 s of their plane (0.002 m), normals within 25 degrees, regions of 200
// points or more; the weights of the example (fitting 0.43, coverage 0.27, complexity 0.3).
// With --true-planes (a synthetic tile) the planes are the true ones instead. Inputs without
// normals get those of lod2_peer_benchmark.h (jet fitting, 12 neighbours, oriented by a minimum
// spanning tree), in the time. The candidate faces and the solver run in a
// child process killed at the time limit (default 300 s per input).
//   benchmark_polyfit INPUT [--time-limit SECONDS] [--models PREFIX]
//   benchmark_polyfit --synthetic-city N [--seed S] [--true-normals] [--true-planes] [--time-limit SECONDS]
//                     [--models PREFIX]
// One JSON line per input (lod2_peer_benchmark.h).
#include <CGAL/GLPK_mixed_integer_program_traits.h>
#include <CGAL/Polygonal_surface_reconstruction.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing_on_point_set.h>
#include <CGAL/compute_average_spacing.h>

#include "benchmark_child_process.h"
#include "lod2_peer_benchmark.h"

#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace Peer = CGAL::Polygon_partition_simplification::benchmark;
namespace Test = CGAL::Polygon_partition_simplification::test;
using Kernel = Test::Kernel;

// The lengths of CGAL's example in units of the spacing of its data, cube.pwn.
constexpr double example_spacing = 0.00771419;
constexpr double search_radius_in_spacings = 0.02 / example_spacing;
constexpr double distance_in_spacings = 0.002 / example_spacing;
constexpr double maximum_angle = 25;
constexpr std::size_t minimum_region_size = 200;

// Sets the plane index of the points by region growing (the example's parameters scaled to
// the spacing); returns the number of planes.
std::size_t detect_planes(std::vector<Test::Sample>& points, double spacing)
{
  using Neighbor_query = CGAL::Shape_detection::Point_set::Sphere_neighbor_query<Kernel, std::vector<Test::Sample>,
                                                                                  Test::Sample_point_map>;
  using Region_type = CGAL::Shape_detection::Point_set::Least_squares_plane_fit_region<
    Kernel, std::vector<Test::Sample>, Test::Sample_point_map, Test::Sample_normal_map>;
  using Region_growing = CGAL::Shape_detection::Region_growing<std::vector<Test::Sample>, Neighbor_query, Region_type>;
  Neighbor_query neighbor_query(points, search_radius_in_spacings * spacing);
  Region_type region_type(points, distance_in_spacings * spacing, maximum_angle, minimum_region_size);
  Region_growing region_growing(points, neighbor_query, region_type);
  std::vector<std::vector<std::size_t>> regions;
  region_growing.detect(std::back_inserter(regions));
  for(Test::Sample& sample : points) sample.plane_index = -1;
  for(std::size_t r = 0; r < regions.size(); ++r)
    for(std::size_t index : regions[r]) points[index].plane_index = int(r);
  return regions.size();
}

// PolyFit on one input: normals if it has none, planes, then the candidate faces and the
// solver in a child process.
Peer::Peer_result run_polyfit(Peer::Peer_input& input, double time_limit)
{
  Peer::Peer_result result;
  const Peer::Clock::time_point start = Peer::Clock::now();
  if(!input.has_normals) result.normals_seconds = Peer::estimate_normals(input);
  const double spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(
    input.points, 6, CGAL::parameters::point_map(Test::Sample_point_map()));
  std::ostringstream note;
  note << "spacing " << spacing << " m";
  if(input.has_planes) {
    std::set<int> planes;
    for(const Test::Sample& sample : input.points)
      if(sample.plane_index >= 0) planes.insert(sample.plane_index);
    result.planes = planes.size();
    note << ", planes given";
  } else {
    result.planes = detect_planes(input.points, spacing);
    note << ", region growing within " << search_radius_in_spacings * spacing << " m, " << distance_in_spacings * spacing << " m";
  }
  result.note = note.str();
  Test::Mesh model;
  try {
    model = Peer::compute_in_child([&] {
      CGAL::Polygonal_surface_reconstruction<Kernel> polyfit(input.points, Test::Sample_point_map(), Test::Sample_normal_map(),
                                                             Test::Sample_plane_index_map());
      Test::Mesh mesh;
      if(!polyfit.error_message().empty() ||
         !polyfit.reconstruct<CGAL::GLPK_mixed_integer_program_traits<double>>(mesh, 0.43, 0.27, 0.3))
        throw std::runtime_error(polyfit.error_message());
      return mesh;
    }, time_limit);
  } catch(const std::exception& error) {
    result.seconds = Peer::seconds_since(start);
    result.failed = error.what();
    return result;
  }
  result.seconds = Peer::seconds_since(start);
  if(model.number_of_faces() == 0) result.failed = "empty model";
  else Peer::measure_model(model, input.measured, result);
  return result;
}

int main(int argc, char** argv)
{
  Peer::Peer_options options;
  double time_limit = 300;
  const bool parsed = Peer::parse_peer_options(argc, argv, options, [&](const std::string& argument, int& i) {
    if(argument != "--time-limit" || i + 1 >= argc) return false;
    time_limit = std::atof(argv[++i]);
    return time_limit > 0;
  });
  if(!parsed) {
    std::cerr << "usage: " << argv[0] << " INPUT [--time-limit SECONDS] [--models PREFIX]\n       " << argv[0]
              << " --synthetic-city N [--seed S] [--true-normals] [--true-planes] [--time-limit SECONDS] [--models PREFIX]\n";
    return 2;
  }
  return Peer::run_peer_benchmark(options, "polyfit", [&](Peer::Peer_input& input) { return run_polyfit(input, time_limit); });
}
