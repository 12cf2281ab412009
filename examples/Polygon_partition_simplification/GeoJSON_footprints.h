// The building footprints of lod2_reconstruct --footprints: the Polygon and MultiPolygon
// features of a GeoJSON FeatureCollection (as 3DBAG's BAG footprints or OpenStreetMap give
// them), in file order. Anything else is refused with one line that says where: not JSON, not
// a FeatureCollection, another geometry, a ring with fewer than 4 positions or not closed, a
// position that is not two numbers, no polygon at all. Coordinates are taken as they are (no
// reprojection); whether the polygons are simple is checked by lod2_city_reconstruction().
#ifndef LOD2_RECONSTRUCT_GEOJSON_FOOTPRINTS_H
#define LOD2_RECONSTRUCT_GEOJSON_FOOTPRINTS_H

#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace lod2_reconstruct {

// a GeoJSON ring: [[x, y], ...], closed (the last position repeats the first, and is dropped)
template <class Kernel>
CGAL::Polygon_2<Kernel> GeoJSON_ring(const nlohmann::json& ring, const std::string& where)
{
  CGAL::Polygon_2<Kernel> polygon;
  if(!ring.is_array() || ring.size() < 4) throw std::runtime_error(where + ": a ring needs at least 4 positions");
  for(std::size_t i = 0; i < ring.size(); ++i) {
    const auto& position = ring[i];
    if(!position.is_array() || position.size() < 2 || !position[0].is_number() || !position[1].is_number())
      throw std::runtime_error(where + ": a position is not [x, y]");
    const double x = position[0].get<double>(), y = position[1].get<double>();
    if(!std::isfinite(x) || !std::isfinite(y)) throw std::runtime_error(where + ": a coordinate is not finite");
    if(i + 1 < ring.size()) polygon.push_back(typename Kernel::Point_2(x, y));
  }
  if(ring.front() != ring.back()) throw std::runtime_error(where + ": a ring is not closed (its last position is not its first)");
  return polygon;
}

// the polygons of the GeoJSON read from `in`; `name` (the file's) starts every error message
template <class Kernel>
std::vector<CGAL::Polygon_with_holes_2<Kernel>> read_GeoJSON_footprints(std::istream& in, const std::string& name)
{
  nlohmann::json document;
  try {
    in >> document;
  } catch(const std::exception&) {
    throw std::runtime_error("the footprints " + name + " are not JSON");
  }
  if(!document.is_object() || !document.contains("type") || document["type"] != "FeatureCollection" ||
     !document.contains("features") || !document["features"].is_array())
    throw std::runtime_error("the footprints " + name + " are not a GeoJSON FeatureCollection");
  std::vector<CGAL::Polygon_with_holes_2<Kernel>> footprints;
  auto add_polygon = [&](const nlohmann::json& rings, const std::string& where) {
    if(!rings.is_array() || rings.empty()) throw std::runtime_error(where + ": a polygon has no ring");
    CGAL::Polygon_with_holes_2<Kernel> polygon(GeoJSON_ring<Kernel>(rings[0], where));
    for(std::size_t r = 1; r < rings.size(); ++r) polygon.add_hole(GeoJSON_ring<Kernel>(rings[r], where));
    footprints.push_back(std::move(polygon));
  };
  const nlohmann::json& features = document["features"];
  for(std::size_t f = 0; f < features.size(); ++f) {
    const std::string where = name + ", feature " + std::to_string(f);
    const nlohmann::json& feature = features[f];
    const bool has_geometry = feature.is_object() && feature.contains("geometry") && feature["geometry"].is_object();
    const nlohmann::json& geometry = has_geometry ? feature["geometry"] : document; // document: no "coordinates"
    const nlohmann::json type = has_geometry && geometry.contains("type") ? geometry["type"] : nlohmann::json();
    const bool has_coordinates = has_geometry && geometry.contains("coordinates");
    if(type == "Polygon" && has_coordinates) add_polygon(geometry["coordinates"], where);
    else if(type == "MultiPolygon" && has_coordinates && geometry["coordinates"].is_array())
      for(const auto& polygon : geometry["coordinates"]) add_polygon(polygon, where);
    else throw std::runtime_error(where + ": its geometry is not a Polygon or a MultiPolygon");
  }
  if(footprints.empty()) throw std::runtime_error("no footprint in " + name);
  return footprints;
}

} // namespace lod2_reconstruct

#endif // LOD2_RECONSTRUCT_GEOJSON_FOOTPRINTS_H
