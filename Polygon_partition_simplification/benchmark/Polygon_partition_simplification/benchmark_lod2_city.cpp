// benchmark_lod2_city [BUILDINGS...]: lod2_city_reconstruction() on synthetic classified tiles of
// the given numbers of buildings (synthetic_city.h: gable, hip, L, flat, stepped, courtyard,
// terraced, a building without wall points, trees; 10 points per m2, 3 cm noise), on 1 and 2
// threads in one run: the time per input point, the ratio of the two times, whether the two
// CityJSON outputs are byte-identical, valid buildings and fallbacks, the distances of the
// models to the truth both ways (mean and largest, sampled; without footprints, buildings that
// touch are one truth, the union of their solids), how many truths and models are farther than
// 1 m from the other, and the peak memory. With BENCHMARK_LOD2_CITY_LIST_ALL set in the
// environment, every truth and model farther than 1 m is listed.

#include "synthetic_city.h"

#include <CGAL/Polygon_partition_simplification/IO/CityJSON.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/lod2_city_reconstruction.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace PPS = CGAL::Polygon_partition_simplification;
namespace T = PPS::test;
using Building = PPS::City_building<T::Point_3>;

static PPS::LOD2_city_report run(const T::City& city, int threads, std::vector<Building>& buildings)
{
  return CGAL::lod2_city_reconstruction(
    city.samples, buildings,
    PPS::parameters::classification_map(T::City_class_map(), PPS::parameters::number_of_threads(threads))
      .point_map(T::City_point_map()));
}

// the same with the true footprints given
static PPS::LOD2_city_report run_with_footprints(const T::City& city, std::vector<Building>& buildings)
{
  const auto footprints = T::footprint_polygons(city);
  return CGAL::lod2_city_reconstruction(
    city.samples, buildings,
    PPS::parameters::footprints(footprints, PPS::parameters::classification_map(T::City_class_map(), PPS::parameters::number_of_threads(1)))
      .point_map(T::City_point_map()));
}

static std::string city_json(const std::vector<Building>& buildings)
{
  std::ostringstream out;
  PPS::IO::write_CityJSON(out, buildings);
  return out.str();
}

// `a` becomes the union of the solids `a` and `b` (triangle meshes), computed with exact
// constructions: the shared walls of terraced houses are coplanar, and rounded intersection
// points can make the union of rotated buildings fail
static bool unite(T::Mesh& a, const T::Mesh& b)
{
  using Exact_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_exact_constructions_kernel::Point_3>;
  Exact_mesh ea, eb, united;
  CGAL::copy_face_graph(a, ea);
  CGAL::copy_face_graph(b, eb);
  if(!CGAL::Polygon_mesh_processing::corefine_and_compute_union(ea, eb, united)) return false;
  a.clear();
  CGAL::copy_face_graph(united, a);
  return true;
}

// The surfaces of the truth: one solid per building, or, for a model made without footprints,
// the union of the solids of buildings that touch (computed by CGAL's corefinement), as
// touching buildings may then come out as one block (terraced houses: their shared wall is
// inside the block). Each with the names of its buildings.
static std::vector<std::pair<T::Mesh, std::string>> truth_surfaces(const T::City& city, bool unite_touching)
{
  const std::size_t n = city.buildings.size();
  std::vector<T::Mesh> solids;
  std::vector<CGAL::Bbox_3> boxes;
  for(const T::Building& b : city.buildings) {
    solids.push_back(T::truth_mesh(b));
    CGAL::Polygon_mesh_processing::triangulate_faces(solids.back()); // corefinement takes triangles
    CGAL::Bbox_3 box;
    for(auto v : solids.back().vertices()) box += solids.back().point(v).bbox();
    boxes.push_back(box);
  }
  std::vector<std::size_t> group(n);
  for(std::size_t b = 0; b < n; ++b) group[b] = b;
  auto root = [&](std::size_t b) { while(group[b] != b) b = group[b]; return b; };
  if(unite_touching)
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = a + 1; b < n; ++b)
        if(CGAL::do_overlap(boxes[a], boxes[b]) && CGAL::Polygon_mesh_processing::do_intersect(solids[a], solids[b]))
          group[root(b)] = root(a);
  std::vector<std::pair<T::Mesh, std::string>> surfaces;
  std::vector<std::size_t> surface_of_root(n, n);
  for(std::size_t b = 0; b < n; ++b) {
    const std::size_t r = root(b);
    const std::string name = std::to_string(b) + " (" + city.kinds[b] + ")";
    if(surface_of_root[r] == n) {
      surface_of_root[r] = surfaces.size();
      surfaces.push_back({solids[b], name});
      continue;
    }
    auto& [mesh, names] = surfaces[surface_of_root[r]];
    if(unite(mesh, solids[b])) {
      names += " + " + name;
      continue;
    }
    std::cout << "  (no union of the truth of " << names << " and " << name << ": scored apart)" << std::endl;
    surfaces.push_back({solids[b], name});
  }
  return surfaces;
}

// mean distances both ways between the models (LoD 2.2, or LoD 1.2 on fallback) and the truth
// (truth_surfaces()), and the buildings farthest from the other surface
static void print_distances(const std::vector<Building>& buildings, const T::City& city, bool unite_touching)
{
  const std::vector<std::pair<T::Mesh, std::string>> surfaces = truth_surfaces(city, unite_touching);
  T::Mesh model, truth;
  for(const Building& b : buildings)
    model.join(b.status == PPS::Building_model_status::LOD22 ? b.lod22 : b.lod12);
  for(const auto& surface : surfaces) truth.join(surface.first);
  const T::Distance_to_mesh to_model(model), to_truth(truth);
  auto mean_max = [](const std::vector<T::Point_3>& samples, const T::Distance_to_mesh& surface) {
    double sum = 0, max = 0;
    for(const T::Point_3& p : samples) {
      const double d = surface(p);
      sum += d;
      max = std::max(max, d);
    }
    return std::make_pair(sum / double(samples.size()), max);
  };
  const auto t2m = mean_max(T::sample_triangles(to_truth.triangles(), 4), to_model);
  const auto m2t = mean_max(T::sample_triangles(to_model.triangles(), 4), to_truth);
  std::vector<std::pair<double, std::string>> worst;
  for(const auto& [mesh, names] : surfaces) {
    const T::Distance_to_mesh one(mesh);
    worst.push_back({mean_max(T::sample_triangles(one.triangles(), 4), to_model).second, "truth " + names});
  }
  for(const Building& b : buildings) {
    const T::Distance_to_mesh one(b.status == PPS::Building_model_status::LOD22 ? b.lod22 : b.lod12);
    worst.push_back({mean_max(T::sample_triangles(one.triangles(), 4), to_truth).second, "model " + std::to_string(b.id)});
  }
  std::sort(worst.rbegin(), worst.rend());
  const auto beyond = [&](const char* side) {
    return std::count_if(worst.begin(), worst.end(), [&](const auto& w) {
      return w.first > 1.0 && w.second.rfind(side, 0) == 0;
    });
  };
  std::cout << "  beyond 1 m: " << beyond("truth") << " of " << surfaces.size() << " truths, " << beyond("model")
            << " of " << buildings.size() << " models; farthest:";
  for(std::size_t i = 0; i < std::min<std::size_t>(6, worst.size()); ++i)
    std::cout << " " << worst[i].second << " " << worst[i].first << " m;";
  std::cout << std::endl;
  if(std::getenv("BENCHMARK_LOD2_CITY_LIST_ALL"))
    for(const auto& [distance, name] : worst)
      if(distance > 1.0) std::cout << "    " << name << " " << distance << " m" << std::endl;
  std::cout << "  truth to model: mean " << t2m.first << " m, max " << t2m.second << " m; model to truth: mean "
            << m2t.first << " m, max " << m2t.second << " m" << std::endl;
}

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes;
  for(int i = 1; i < argc; ++i) sizes.push_back(std::size_t(std::atol(argv[i])));
  if(sizes.empty()) sizes = {30, 120};
  std::cout << "buildings | points | modelled | valid | LoD 1.2 only | 1 thread (s) | us/point | 2 threads (s) | ratio | identical" << std::endl;
  for(std::size_t n : sizes) {
    T::City_options options;
    options.buildings = n;
    const T::City city = T::make_city(options);
    std::vector<Building> one, two;
    const PPS::LOD2_city_report r1 = run(city, 1, one);
    const PPS::LOD2_city_report r2 = run(city, 2, two);
    std::cout << n << " | " << r1.points << " | " << r1.buildings << " | " << r1.buildings_valid << " | "
              << r1.buildings_lod12_fallback << " | " << r1.seconds << " | " << 1e6 * r1.seconds / double(r1.points)
              << " | " << r2.seconds << " | " << r2.seconds / r1.seconds << " | "
              << (city_json(one) == city_json(two) ? "yes" : "NO") << std::endl;
    std::cout << "  stages (1 thread, summed): split " << r1.split_seconds << " planes " << r1.planes_seconds << " segments "
              << r1.segments_seconds << " partition " << r1.partition_seconds << " simplification " << r1.simplification_seconds
              << " lift " << r1.lift_seconds << " extrusion " << r1.extrusion_seconds << " validation " << r1.validation_seconds
              << std::endl;
    for(const Building& b : one)
      if(!b.reason.empty()) std::cout << "  building " << b.id << ": " << b.reason << std::endl;
    print_distances(one, city, true);
    std::vector<Building> with_footprints;
    const PPS::LOD2_city_report r3 = run_with_footprints(city, with_footprints);
    std::cout << "  with the footprints, 1 thread: " << r3.buildings << " buildings, " << r3.buildings_valid << " valid, "
              << r3.seconds << " s" << std::endl;
    for(const Building& b : with_footprints)
      if(!b.reason.empty()) std::cout << "  building " << b.id << ": " << b.reason << std::endl;
    print_distances(with_footprints, city, false);
  }
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  std::cout << "peak memory: " << double(usage.ru_maxrss) / 1024.0 << " MB" << std::endl;
  return 0;
}
