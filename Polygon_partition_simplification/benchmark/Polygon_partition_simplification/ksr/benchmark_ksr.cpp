// CGAL 6's Kinetic_surface_reconstruction_3 (KSR) as a peer of the LOD2 pipeline, on the inputs
// of the peer benchmarks (../lod2_peer_benchmark.h): a point file, or building by building on a
// synthetic classified tile, with the parameters of CGAL 6.0.1's example ksr_building.cpp
// (libcgal-demo 6.0.1, examples.tar.gz), made for points_3/building.ply, its lengths scaled from
// the spacing of building.ply (0.1723 m, the average distance to the 6 nearest neighbours) to
// that of the input s: region growing within 0.580 s (0.1 m in the example) and 10 degrees,
// regions of 100 points or more, a bounding box oriented along the planes, parallelism and
// coplanarity regularized within 5 degrees and 0.116 s (0.02 m), a kinetic partition of k = 2,
// then a labeling of its volumes by min-cut for each lambda of the example (0.3 ... 0.99), or
// for V only.
//   benchmark_ksr INPUT [--lambda V] [--box-outside] [--models PREFIX]
//   benchmark_ksr --synthetic-city N [--seed S] [--true-normals] [--lambda V] [--box-outside] [--models PREFIX]
// Inputs without normals get those of lod2_peer_benchmark.h (jet fitting, 12 neighbours,
// oriented by a minimum spanning tree), in the time, as the spacing. The labeling is that of the example,
// reconstruct_with_ground(), whose model is the ground, cut at the box of the partition, with
// the buildings on it; with --box-outside it is reconstruct() with the six sides of the box
// outside (method "ksr_box_outside"), whose model can be a closed solid. The model reported is
// the valid one closest to the points (smallest RMS), or the closest one when none is valid;
// its time is that of the normals, the detection and the partition plus its own labeling. One
// JSON line per input (lod2_peer_benchmark.h); every lambda's model and the stages on stderr.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kinetic_surface_reconstruction_3.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/compute_average_spacing.h>

#include "lod2_peer_benchmark.h"

#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace Peer = CGAL::Polygon_partition_simplification::benchmark;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_set = CGAL::Point_set_3<Peer::Point_3>;
using KSR = CGAL::Kinetic_surface_reconstruction_3<Kernel, Point_set, Point_set::Point_map, Point_set::Vector_map>;

// The spacing of building.ply, for which the lengths of the example are.
constexpr double example_spacing = 0.172311;

struct Options
{
  std::vector<double> lambdas{0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 0.99}; // those of ksr_building.cpp
  bool box_outside = false;
};

// Silences std::cout while it lives: KSR prints the size of its partition there.
struct Silent_cout
{
  std::ostringstream sink;
  std::streambuf* saved = std::cout.rdbuf(sink.rdbuf());
  ~Silent_cout() { std::cout.rdbuf(saved); }
};

// The labeling at one lambda: the example's, or with the sides of the box outside.
void label(KSR& ksr, double lambda, bool box_outside, std::vector<Peer::Point_3>& vertices,
           std::vector<Peer::Polygon>& polygons)
{
  using Support = KSR::KSP::Face_support;
  if(!box_outside) {
    ksr.reconstruct_with_ground(lambda, std::back_inserter(vertices), std::back_inserter(polygons));
    return;
  }
  std::map<Support, bool> outside;
  for(Support side : {Support::ZMIN, Support::YMIN, Support::XMAX, Support::YMAX, Support::XMIN, Support::ZMAX})
    outside[side] = false;
  ksr.reconstruct(lambda, outside, std::back_inserter(vertices), std::back_inserter(polygons));
}

// KSR on one input: the partition once, a model per lambda, the best one reported.
Peer::Peer_result run_ksr(Peer::Peer_input& input, const Options& options)
{
  Peer::Clock::time_point start = Peer::Clock::now();
  double normals_seconds = 0;
  if(!input.has_normals) normals_seconds = Peer::estimate_normals(input);
  Point_set points;
  points.add_normal_map();
  for(const Peer::Sample& sample : input.points) points.insert(sample.point, sample.normal);
  const double scale = CGAL::compute_average_spacing<CGAL::Sequential_tag>(points, 6) / example_spacing;
  const auto parameters = CGAL::parameters::maximum_distance(0.1 * scale)
                            .maximum_angle(10)
                            .minimum_region_size(100)
                            .reorient_bbox(true)
                            .regularize_parallelism(true)
                            .regularize_coplanarity(true)
                            .angle_tolerance(5)
                            .maximum_offset(0.02 * scale);
  Silent_cout silent;
  KSR ksr(points, parameters);
  ksr.detection_and_partition(2, parameters);
  const double partition_seconds = Peer::seconds_since(start);
  std::cerr << input.name << " " << input.building << ": " << ksr.detected_planar_shapes().size() << " planes, normals "
            << normals_seconds << " s, partition " << partition_seconds - normals_seconds << " s" << std::endl;
  Peer::Peer_result best;
  best.failed = "empty model at every lambda";
  auto rank = [](const Peer::Peer_result& r) { return std::make_tuple(!r.failed.empty(), !r.valid, r.distances.rms); };
  for(double lambda : options.lambdas) {
    Peer::Peer_result result;
    std::vector<Peer::Point_3> vertices;
    std::vector<Peer::Polygon> polygons;
    start = Peer::Clock::now();
    label(ksr, lambda, options.box_outside, vertices, polygons);
    result.seconds = partition_seconds + Peer::seconds_since(start);
    result.normals_seconds = normals_seconds;
    result.planes = ksr.detected_planar_shapes().size();
    result.note = "spacing " + Peer::internal::json_number(scale * example_spacing) + " m, lambda " +
                  Peer::internal::json_number(lambda);
    if(polygons.empty()) result.failed = "empty model";
    else Peer::measure_model(std::move(vertices), std::move(polygons), input.measured, result);
    std::cerr << "  " << Peer::json_line("lambda", input, result) << std::endl;
    if(rank(result) < rank(best)) best = std::move(result);
  }
  if(!best.failed.empty()) best.seconds = partition_seconds, best.normals_seconds = normals_seconds;
  return best;
}

int main(int argc, char** argv)
{
  Peer::Peer_options peer_options;
  Options options;
  const bool parsed = Peer::parse_peer_options(argc, argv, peer_options, [&](const std::string& argument, int& i) {
    if(argument == "--box-outside") return options.box_outside = true;
    if(argument != "--lambda" || i + 1 >= argc) return false;
    options.lambdas = {std::atof(argv[++i])};
    return true;
  });
  if(!parsed || peer_options.true_planes) { // KSR detects its planes
    std::cerr << "usage: " << argv[0] << " INPUT [--lambda V] [--box-outside] [--models PREFIX]\n       " << argv[0]
              << " --synthetic-city N [--seed S] [--true-normals] [--lambda V] [--box-outside] [--models PREFIX]\n";
    return 2;
  }
  return Peer::run_peer_benchmark(peer_options, options.box_outside ? "ksr_box_outside" : "ksr",
                                  [&](Peer::Peer_input& input) { return run_ksr(input, options); });
}
