// The stages of the LOD2 pipeline called one by one on CGAL's points_3/building.ply: planes
// (from its `segment_index` property), 2D segments, their kinetic partition, its simplification,
// and the model. With a directory as second argument, every stage is written there as text, one
// item per line (the manual's figure of the stages is drawn from these files):
//   points.txt     x y z plane           (plane -1: on no plane)
//   segments.txt   x0 y0 x1 y1 facade
//   partition.txt, simplified.txt        x0 y0 x1 y1 (the edges)
//   model.txt      type plane x0 y0 z0 x1 y1 z1 ... (a face; type 0 roof, 1 wall, 2 floor)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/lod2_building_reconstruction.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PPS = CGAL::Polygon_partition_simplification;
using Partition = PPS::Line_partition_2<K>;

// the edges of a partition, one per line
void write_edges(const Partition& partition, const std::string& path)
{
  std::ofstream out(path);
  out.precision(17);
  for(std::size_t e = 0; e < partition.number_of_edges(); ++e) out << partition.segment(e) << "\n";
}

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : CGAL::data_file_path("points_3/building.ply");
  const std::string directory = argc > 2 ? argv[2] : "";
  CGAL::Point_set_3<K::Point_3, K::Vector_3> points;
  if(!CGAL::IO::read_point_set(input, points) || points.empty()) {
    std::cerr << "cannot read " << input << std::endl;
    return 1;
  }
  if(!points.has_property_map<int>("segment_index")) {
    std::cerr << input << " has no segment_index property" << std::endl;
    return 1;
  }
  // add_property_map() returns the existing map
  const auto plane_index = points.add_property_map<int>("segment_index").first;
  const auto np = CGAL::parameters::point_map(points.point_map()).plane_index_map(plane_index);

  // 1. planes, regularized (the same named parameters for every stage)
  const PPS::Building_planes_3<K> planes = CGAL::detect_building_planes_3(points, np);
  // 2. the 2D segments: intersections of adjacent planes and roof outlines
  const std::vector<PPS::Building_segment_2<K>> segments = CGAL::building_segments_2(points, planes, np);
  // 3. their kinetic partition (each segment once; the pipeline also snaps nearly collinear ones)
  std::vector<K::Segment_2> distinct;
  for(const auto& s : segments)
    if(s.segment.source() != s.segment.target())
      distinct.push_back(s.segment.source() < s.segment.target() ? s.segment : s.segment.opposite());
  std::sort(distinct.begin(), distinct.end(),
            [](const K::Segment_2& a, const K::Segment_2& b) { return std::make_pair(a.source(), a.target()) < std::make_pair(b.source(), b.target()); });
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  const Partition kinetic = CGAL::kinetic_partition_2(distinct, PPS::parameters::collinearity_distance(2 * planes.spacing));
  // 4. its simplification
  Partition simplified = kinetic;
  const PPS::Simplification_statistics simplification = CGAL::simplify_polygon_partition_2(simplified);
  // 5. the model (the whole pipeline: lift of the cells by a graph cut, extrusion)
  CGAL::Surface_mesh<K::Point_3> model;
  const PPS::LOD2_report report = CGAL::lod2_building_reconstruction(points, model, np);

  std::cout << planes.planes.size() << " planes, " << segments.size() << " segments (" << distinct.size()
            << " distinct), kinetic partition of " << kinetic.number_of_cells() << " cells, simplified to "
            << simplification.cells_after << " cells; model: " << report.buildings << " building(s), " << report.faces
            << " faces, closed: " << std::boolalpha << report.closed << " (its partition: " << report.cells_before << " -> " << report.cells_after << " cells)" << std::endl;
  if(directory.empty()) return report.closed ? 0 : 1;

  std::vector<int> plane_of(points.size(), -1);
  for(std::size_t p = 0; p < planes.planes.size(); ++p)
    for(std::size_t i : planes.planes[p].inliers) plane_of[i] = int(p);
  std::ofstream out_points(directory + "/points.txt");
  out_points.precision(17);
  for(std::size_t i = 0; i < points.size(); ++i) out_points << points.point(*(points.begin() + i)) << " " << plane_of[i] << "\n";
  std::ofstream out_segments(directory + "/segments.txt");
  out_segments.precision(17);
  for(const auto& s : segments) out_segments << s.segment.source() << " " << s.segment.target() << " " << s.is_facade << "\n";
  write_edges(kinetic, directory + "/partition.txt");
  write_edges(simplified, directory + "/simplified.txt");
  // the face properties of the model (add_property_map() returns the existing maps)
  using Face_index = CGAL::Surface_mesh<K::Point_3>::Face_index;
  const auto type = model.add_property_map<Face_index, PPS::Building_surface_type>("f:surface_type").first;
  const auto plane = model.add_property_map<Face_index, std::size_t>("f:plane").first;
  std::ofstream out_model(directory + "/model.txt");
  out_model.precision(17);
  for(auto f : model.faces()) {
    out_model << int(type[f]) << " " << (plane[f] == std::size_t(-1) ? -1 : long(plane[f]));
    for(auto v : CGAL::vertices_around_face(model.halfedge(f), model)) out_model << " " << model.point(v);
    out_model << "\n";
  }
  std::cout << "stages written to " << directory << std::endl;
  return report.closed ? 0 : 1;
}
