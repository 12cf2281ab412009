// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CITYJSON_BUILDINGS_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CITYJSON_BUILDINGS_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/City_building.h>
#include <CGAL/Polygon_partition_simplification/internal/CityJSON_model.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// The integer vertices of a CityJSON document (or of one feature of a text sequence), each once.
struct CityJSON_vertex_pool
{
  std::map<std::array<long long, 3>, std::size_t> index;
  std::vector<std::array<long long, 3>> vertices;

  std::size_t add(const std::array<long long, 3>& q)
  {
    const auto inserted = index.emplace(q, vertices.size());
    if(inserted.second) vertices.push_back(q);
    return inserted.first->second;
  }
};

/// The transform of a document: integer coordinates in units of `scale` from `translate`.
struct CityJSON_transform
{
  double scale = 0.001, factor = 1000;
  std::array<double, 3> translate{{0, 0, 0}};
};

/// the transform of the buildings: `translate` is the lowest corner of their models' vertices;
/// throws `Input_error` on a non-finite vertex or an extent beyond 2^53 units
template <class Point>
CityJSON_transform CityJSON_transform_of(const std::vector<City_building<Point>>& buildings, int decimals)
{
  CityJSON_transform t;
  t.factor = 1;
  for(int i = 0; i < decimals; ++i) t.factor *= 10;
  t.scale = 1 / t.factor;
  const double infinity = std::numeric_limits<double>::infinity();
  std::array<double, 3> lowest{{infinity, infinity, infinity}}, highest{{-infinity, -infinity, -infinity}};
  for(const auto& building : buildings)
    for(const Surface_mesh<Point>* mesh : {&building.lod12, &building.lod22})
      for(auto v : mesh->vertices())
        for(int i = 0; i < 3; ++i) {
          const double c = CGAL::to_double(mesh->point(v)[i]);
          if(!std::isfinite(c))
            throw Input_error(Input_error_code::NON_FINITE_COORDINATE,
                              "write_CityJSON: building " + std::to_string(building.id) + " has a non-finite vertex");
          lowest[i] = (std::min)(lowest[i], c);
          highest[i] = (std::max)(highest[i], c);
        }
  if(lowest[0] == infinity) return t;
  t.translate = lowest;
  for(int i = 0; i < 3; ++i)
    if((highest[i] - lowest[i]) * t.factor >= 9007199254740992.)
      throw Input_error(Input_error_code::INVALID_PARAMETER,
                        "write_CityJSON: the model is too large for " + std::to_string(decimals) +
                        " decimals (integer coordinates beyond 2^53): lower stream_precision");
  return t;
}

/// appends a `Solid` of the given LoD: one surface per face (faces that keep fewer than three
/// distinct vertices after rounding are left out), with its semantic surface type
template <class Point>
void append_CityJSON_solid(std::string& out, const Surface_mesh<Point>& mesh, const char* lod,
                           const CityJSON_transform& t, CityJSON_vertex_pool& pool)
{
  using Face_index = typename Surface_mesh<Point>::Face_index;
  const auto type = optional_property_map(mesh.template property_map<Face_index, Building_surface_type>("f:surface_type"));
  std::vector<unsigned> types;
  std::vector<std::array<long long, 3>> ring;
  out += "{\"type\":\"Solid\",\"lod\":\"";
  out += lod;
  out += "\",\"boundaries\":[[";
  for(Face_index f : mesh.faces()) {
    ring.clear();
    for(auto v : vertices_around_face(mesh.halfedge(f), mesh)) {
      std::array<long long, 3> q;
      for(int i = 0; i < 3; ++i) q[i] = std::llround((CGAL::to_double(mesh.point(v)[i]) - t.translate[i]) * t.factor);
      if(ring.empty() || ring.back() != q) ring.push_back(q);
    }
    while(ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    if(ring.size() < 3) continue;
    out += types.empty() ? "[[" : ",[[";
    for(std::size_t i = 0; i < ring.size(); ++i) {
      out += i ? "," : "";
      append_JSON_number(out, pool.add(ring[i]));
    }
    out += "]]";
    types.push_back(type ? static_cast<unsigned>((*type)[f]) : 1u);
  }
  // the order of the semantic surfaces is that of Building_surface_type
  out += "]],\"semantics\":{\"surfaces\":[{\"type\":\"RoofSurface\"},{\"type\":\"WallSurface\"},"
         "{\"type\":\"GroundSurface\"}],\"values\":[[";
  for(std::size_t s = 0; s < types.size(); ++s) {
    out += s ? "," : "";
    append_JSON_number(out, types[s]);
  }
  out += "]]}}";
}

/// appends `"building_<id>":{...}`: a `Building` with its LoD 1.2 block, its LoD 2.2 solid when
/// it has one, and its attributes
template <class Point>
void append_CityJSON_building(std::string& out, const City_building<Point>& building, const CityJSON_transform& t,
                              CityJSON_vertex_pool& pool)
{
  const bool lod22 = building.status == Building_model_status::LOD22;
  append_JSON_string(out, "building_" + std::to_string(building.id));
  out += ":{\"type\":\"Building\",\"attributes\":{\"status\":";
  append_JSON_string(out, lod22 ? "lod22" : "lod12_fallback");
  if(!building.reason.empty()) {
    out += ",\"reason\":";
    append_JSON_string(out, building.reason);
  }
  const std::pair<const char*, double> numbers[] = {
    {"h_ground", building.ground_height}, {"h_50p", building.roof_height_50p}, {"h_70p", building.roof_height_70p},
    {"h_max", building.roof_height_max}, {"rms_m", building.rms_distance}};
  out += ",\"points\":";
  append_JSON_number(out, building.points);
  for(const auto& [name, value] : numbers) {
    if(!lod22 && name == std::string("rms_m")) continue;
    out += ",\"";
    out += name;
    out += "\":";
    append_JSON_number(out, std::round(value * t.factor) / t.factor);
  }
  out += "},\"geometry\":[";
  append_CityJSON_solid(out, building.lod12, "1.2", t, pool);
  if(lod22) {
    out += ",";
    append_CityJSON_solid(out, building.lod22, "2.2", t, pool);
  }
  out += "]}";
}

inline void append_CityJSON_vertices(std::string& out, const CityJSON_vertex_pool& pool, const char* separator)
{
  out += "\"vertices\":[";
  for(std::size_t v = 0; v < pool.vertices.size(); ++v) {
    out += v ? "," : "";
    out += separator;
    out += '[';
    for(int i = 0; i < 3; ++i) {
      out += i ? "," : "";
      append_JSON_number(out, pool.vertices[v][i]);
    }
    out += ']';
  }
}

/// the first line of a document: its type, version and transform, then `"CityObjects":{`
inline std::string CityJSON_header(const CityJSON_transform& t)
{
  std::string out = "{\"type\":\"CityJSON\",\"version\":\"1.1\",\"transform\":{\"scale\":[";
  for(int i = 0; i < 3; ++i) {
    out += i ? "," : "";
    append_JSON_number(out, t.scale);
  }
  out += "],\"translate\":[";
  for(int i = 0; i < 3; ++i) {
    out += i ? "," : "";
    append_JSON_number(out, t.translate[i]);
  }
  out += "]},";
  return out;
}

/// the CityJSON text of `buildings`, their vertices shared by all and written as integers
template <class Point>
std::string CityJSON_text_of_buildings(const std::vector<City_building<Point>>& buildings, int decimals)
{
  const CityJSON_transform t = CityJSON_transform_of(buildings, decimals);
  CityJSON_vertex_pool pool;
  std::string text = CityJSON_header(t) + "\n\"CityObjects\":{";
  for(std::size_t b = 0; b < buildings.size(); ++b) {
    text += b ? ",\n" : "\n";
    append_CityJSON_building(text, buildings[b], t, pool);
  }
  text += "\n},\n";
  append_CityJSON_vertices(text, pool, "\n");
  text += "\n]}\n";
  return text;
}

/// writes `buildings` to `os` as CityJSON Text Sequences, a line at a time: the header, then a
/// `CityJSONFeature` per building with its own vertices; whether `os` is good after writing
template <class Point>
bool write_CityJSON_features(std::ostream& os, const std::vector<City_building<Point>>& buildings, int decimals)
{
  const CityJSON_transform t = CityJSON_transform_of(buildings, decimals);
  std::string line = CityJSON_header(t) + "\"CityObjects\":{},\"vertices\":[]}\n";
  os.write(line.data(), static_cast<std::streamsize>(line.size()));
  for(const auto& building : buildings) {
    CityJSON_vertex_pool pool;
    line = "{\"type\":\"CityJSONFeature\",\"id\":";
    append_JSON_string(line, "building_" + std::to_string(building.id));
    line += ",\"CityObjects\":{";
    append_CityJSON_building(line, building, t, pool);
    line += "},";
    append_CityJSON_vertices(line, pool, "");
    line += "]}\n";
    os.write(line.data(), static_cast<std::streamsize>(line.size()));
  }
  return os.good();
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CITYJSON_BUILDINGS_H
