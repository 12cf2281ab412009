// This package's LOD2 pipeline on the inputs of the peer benchmarks (lod2_peer_benchmark.h),
// against which benchmark_polyfit and ksr/benchmark_ksr measure CGAL's PolyFit and CGAL 6's
// Kinetic_surface_reconstruction_3: CGAL::lod2_building_reconstruction() with its default
// parameters, planes detected by its region growing (the true planes with --true-planes), the
// normals of the input when it has some (its PCA normals otherwise, in its time).
//   benchmark_lod2_buildings INPUT [--models PREFIX]
//   benchmark_lod2_buildings --synthetic-city N [--seed S] [--true-normals] [--true-planes] [--models PREFIX]
// One JSON line per input (lod2_peer_benchmark.h); the note gives the pipeline's planes,
// segments, cells before and after the simplification and buildings.
#include <CGAL/lod2_building_reconstruction.h>

#include "lod2_peer_benchmark.h"

#include <iostream>
#include <string>

namespace Peer = CGAL::Polygon_partition_simplification::benchmark;
namespace Test = CGAL::Polygon_partition_simplification::test;

Peer::Peer_result run_ours(const Peer::Peer_input& input)
{
  namespace parameters = CGAL::Polygon_partition_simplification::parameters;
  Peer::Peer_result result;
  Test::Mesh model;
  const Peer::Clock::time_point start = Peer::Clock::now();
  CGAL::Polygon_partition_simplification::LOD2_report report;
  const auto points = parameters::point_map(Test::Sample_point_map());
  const Test::Sample_normal_map normals;
  const Test::Sample_plane_index_map planes;
  if(input.has_normals && input.has_planes)
    report = CGAL::lod2_building_reconstruction(input.points, model, points.normal_map(normals).plane_index_map(planes));
  else if(input.has_normals)
    report = CGAL::lod2_building_reconstruction(input.points, model, points.normal_map(normals));
  else if(input.has_planes)
    report = CGAL::lod2_building_reconstruction(input.points, model, points.plane_index_map(planes));
  else
    report = CGAL::lod2_building_reconstruction(input.points, model, points);
  result.seconds = Peer::seconds_since(start);
  result.planes = report.planes;
  result.note = "segments " + std::to_string(report.segments) + ", cells " + std::to_string(report.cells_before) + "->" +
                std::to_string(report.cells_after) + ", buildings " + std::to_string(report.buildings);
  if(model.number_of_faces() == 0) {
    result.failed = "no building";
    return result;
  }
  Peer::measure_model(model, input.measured, result);
  return result;
}

int main(int argc, char** argv)
{
  Peer::Peer_options options;
  if(!Peer::parse_peer_options(argc, argv, options, [](const std::string&, int&) { return false; })) {
    std::cerr << "usage: " << argv[0] << " INPUT [--models PREFIX]\n       " << argv[0]
              << " --synthetic-city N [--seed S] [--true-normals] [--true-planes] [--models PREFIX]\n";
    return 2;
  }
  return Peer::run_peer_benchmark(options, "ours", [](Peer::Peer_input& input) { return run_ours(input); });
}
