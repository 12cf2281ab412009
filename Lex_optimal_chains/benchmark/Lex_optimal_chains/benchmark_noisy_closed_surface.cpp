// Closed surfaces of noisy and unevenly sampled points: the lexicographic optimal surface as it
// is and in its robust mode, against CGAL's Poisson reconstruction (normals estimated by jet
// fitting and oriented by a minimum spanning tree, as for points without normals; and with the
// file's normals when it has some) and the advancing front, on the same points. Noisy spheres
// and tori with a known truth (Gaussian radial noise, a fraction of the radius), and CGAL's
// scans sphere_20k_normal.xyz (a unit sphere with noise), oni.ply, blobby.xyz and kitten.xyz.
//
//   benchmark_noisy_closed_surface [CGAL_DATA_DIR]
//
// One row per input and method: time (and its ratio to the Delaunay triangulation of the same
// points), faces, closed, components, area (the truth's when known), the area-weighted mean
// distance of the surface to the truth, and the mean distance of the input points to the
// surface in % of the bounding box diagonal, with its ratio to Poisson's (estimated normals).
// All in one process pinned to one CPU.
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/lex_optimal_closed_surface.h>

#include "benchmark_support.h"
#include "noisy_shapes.h"

#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

using namespace noisy_shapes;
namespace LOC = CGAL::Lex_optimal_chains;
namespace PMP = CGAL::Polygon_mesh_processing;

struct Input
{
  std::string name;
  std::vector<Point_with_normal> points; // normals (0, 0, 0) when the input has none
  bool has_normals = false;
  double true_area = 0;                  // 0: unknown
  std::function<double(const Point&)> truth;
};

Input synthetic(const Shape& s)
{
  return Input{s.name, without_normals(s.points), false, s.area, s.distance};
}

std::optional<Input> scan(const std::string& data, const std::string& file, bool unit_sphere)
{
  Input in;
  in.name = file;
  if(!CGAL::IO::read_points(data + "/points_3/" + file, std::back_inserter(in.points),
                            CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
                              .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>())))
    return std::nullopt;
  for(const auto& p : in.points) in.has_normals |= p.second != CGAL::NULL_VECTOR;
  if(unit_sphere) {
    in.true_area = 4 * 3.14159265358979323846;
    in.truth = [](const Point& p) { return std::abs(std::sqrt((p - CGAL::ORIGIN).squared_length()) - 1); };
  }
  return in;
}

Mesh advancing_front(const std::vector<Point>& points)
{
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(), std::back_inserter(facets));
  std::vector<Point> soup_points = points;
  std::vector<std::vector<std::size_t>> polygons;
  for(const auto& f : facets) polygons.push_back({f[0], f[1], f[2]});
  PMP::orient_polygon_soup(soup_points, polygons);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, mesh);
  return mesh;
}

// Prints one row; returns the points' mean distance to the mesh in % of the diagonal (0 when
// refused). `reference`: Poisson's, for the last ratio (0: this row is Poisson's, ratio 1).
double row(const Input& in, const std::string& method, double seconds, double delaunay_seconds, const Mesh* mesh,
           const std::vector<Point>& points, double diagonal, double reference, const std::string& note = "")
{
  std::printf("| %-24s | %-22s | %7.3f | %5.2f |", in.name.c_str(), method.c_str(), seconds, seconds / delaunay_seconds);
  if(!mesh || num_faces(*mesh) == 0) {
    std::printf(" refused: %s |\n", note.c_str());
    return 0;
  }
  std::vector<std::size_t> component(num_faces(*mesh));
  const std::size_t components = PMP::connected_components(
    *mesh, CGAL::make_property_map(component));
  const double area = PMP::area(*mesh);
  const double distance = mean_distance_to_mesh(points, *mesh) / diagonal * 100;
  std::printf(" %6zu | %-3s | %2zu | %7.3f", std::size_t(num_faces(*mesh)), CGAL::is_closed(*mesh) ? "yes" : "no", components, area);
  if(in.true_area > 0) std::printf(" (%+5.1f%%)", 100 * (area / in.true_area - 1));
  else std::printf("          ");
  if(in.truth) std::printf(" | %8.5f", area_weighted_mean_distance(*mesh, in.truth));
  else std::printf(" |        -");
  std::printf(" | %6.3f | %5.2f | %s\n", distance, reference > 0 ? distance / reference : 1.0, note.c_str());
  std::fflush(stdout);
  return distance;
}

void measure(const Input& in)
{
  std::vector<Point> points;
  for(const auto& p : in.points) points.push_back(p.first);
  CGAL::Bbox_3 box;
  for(const Point& p : points) box += p.bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  CGAL::Real_timer t;
  t.start();
  { CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end()); }
  t.stop();
  const double dt_seconds = t.time();
  // Poisson first: the ratios of the last column are to it
  t.reset(); t.start();
  Mesh peer = poisson(in.points, false);
  t.stop();
  const double poisson_distance = row(in, "Poisson", t.time(), dt_seconds, &peer, points, diagonal, 0);
  if(in.has_normals) {
    t.reset(); t.start();
    Mesh with_normals = poisson(in.points, true);
    t.stop();
    row(in, "Poisson, file normals", t.time(), dt_seconds, &with_normals, points, diagonal, poisson_distance);
  }
  t.reset(); t.start();
  Mesh afsr = advancing_front(points);
  t.stop();
  row(in, "advancing front", t.time(), dt_seconds, &afsr, points, diagonal, poisson_distance);
  for(const bool robust : {false, true}) {
    Mesh mesh;
    std::string note;
    t.reset(); t.start();
    try {
      const LOC::Closed_surface_report r =
        CGAL::lex_optimal_closed_surface_reconstruction(points, mesh, LOC::parameters::robust(robust));
      note = "persistence " + std::to_string(r.interior_persistence).substr(0, 6) + " / " +
             std::to_string(r.runner_up_persistence).substr(0, 5) + ", through " + std::to_string(r.mesh_vertices) +
             " points, genus " + std::to_string(r.genus);
      if(robust)
        note += ", k " + std::to_string(r.smoothing_neighbors) + ", " + std::to_string(r.smoothing_passes) +
                " passes, noise " + std::to_string(r.noise_estimate / r.average_spacing).substr(0, 4) + " spacing";
    } catch(const LOC::Input_error& e) {
      note = e.what();
      mesh.clear();
    }
    t.stop();
    row(in, robust ? "lex, robust" : "lex", t.time(), dt_seconds, &mesh, points, diagonal, poisson_distance, note);
  }
}

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : CGAL_DATA_DIR;
  pin_measurements_to_one_cpu();
  std::printf("| input | method | time s | /DT | faces | closed | comp. | area (vs truth) | mean dist. to truth | "
              "points' mean dist. %% diag | /Poisson | notes |\n");
  unsigned seed = 1;
  for(const double noise : {0.01, 0.02, 0.04}) measure(synthetic(noisy_sphere(20000, noise, seed++)));
  for(const double noise : {0.01, 0.02, 0.04}) measure(synthetic(noisy_torus(20000, noise, seed++)));
  const std::vector<std::pair<std::string, bool>> scans{
    {"sphere_20k_normal.xyz", true}, {"oni.ply", false}, {"blobby.xyz", false}, {"kitten.xyz", false}};
  for(const auto& [file, sphere] : scans) {
    const std::optional<Input> in = scan(data, file, sphere);
    if(in) measure(*in);
    else std::printf("| %s | cannot be read from %s |\n", file.c_str(), data.c_str());
  }
  return 0;
}
