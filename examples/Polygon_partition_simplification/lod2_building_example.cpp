// LOD2 model of a point cloud of buildings: planes from the `segment_index` property of CGAL's
// points_3/building.ply (or detected when the file has none), kinetic partition of the segments
// they give, simplification, lift and extrusion; the model written as CityJSON 1.1.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Polygon_partition_simplification/IO/CityJSON.h>
#include <CGAL/lod2_building_reconstruction.h>

#include <iostream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PPS = CGAL::Polygon_partition_simplification;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : CGAL::data_file_path("points_3/building.ply");
  CGAL::Point_set_3<K::Point_3, K::Vector_3> points;
  if(!CGAL::IO::read_point_set(input, points) || points.empty()) {
    std::cerr << "cannot read " << input << std::endl;
    return 1;
  }
  CGAL::Surface_mesh<K::Point_3> model;
  auto np = CGAL::parameters::point_map(points.point_map()).normal_map(points.normal_map());
  // the planes of the points, if the file gives them (add_property_map() returns the existing map)
  const PPS::LOD2_report report = points.has_property_map<int>("segment_index")
    ? CGAL::lod2_building_reconstruction(
        points, model, np.plane_index_map(points.add_property_map<int>("segment_index").first))
    : CGAL::lod2_building_reconstruction(points, model, np);

  std::cout << report.planes << " planes, " << report.segments << " segments, cells "
            << report.cells_before << " -> " << report.cells_after << ", " << report.buildings
            << " building(s), " << report.faces << " faces (" << report.roof_faces << " roof, "
            << report.wall_faces << " wall), closed: " << std::boolalpha << report.closed
            << ", RMS distance " << report.rms_distance << " in " << report.seconds << " s" << std::endl;

  // every face knows its building and whether it is a roof, a wall or the ground
  if(!PPS::IO::write_CityJSON("building_lod2.city.json", model)) return 1;
  std::cout << "written to building_lod2.city.json" << std::endl;
  return report.closed ? 0 : 1;
}
