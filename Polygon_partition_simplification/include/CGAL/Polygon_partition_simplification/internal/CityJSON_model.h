// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CITYJSON_MODEL_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CITYJSON_MODEL_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Building_surface_type.h>
#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// appends `text` as a JSON string (RFC 8259): quotation mark, backslash and control characters
// escaped, other bytes (UTF-8 included) copied
inline void append_JSON_string(std::string& out, const std::string& text)
{
  static const char hexadecimal[] = "0123456789abcdef";
  out += '"';
  for(char character : text) {
    const unsigned char byte = static_cast<unsigned char>(character);
    switch(character) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if(byte < 0x20) {
          out += "\\u00";
          out += hexadecimal[byte >> 4];
          out += hexadecimal[byte & 15];
        } else {
          out += character;
        }
    }
  }
  out += '"';
}

// appends a number with std::to_chars: independent of any locale, and for a double the
// shortest text that reads back to the same value
template <class Number>
void append_JSON_number(std::string& out, Number value)
{
  char buffer[64];
  const std::to_chars_result written = std::to_chars(buffer, buffer + sizeof(buffer), value);
  CGAL_assertion(written.ec == std::errc());
  out.append(buffer, written.ptr);
}

// The content of a CityJSON file, checked and quantized before anything is written.
struct CityJSON_model
{
  struct Building
  {
    std::size_t index;                              // value of "f:building"
    std::vector<std::vector<std::size_t>> rings;    // one outer ring per surface (vertex indices)
    std::vector<Building_surface_type> types;       // one per surface
  };
  double scale = 1;
  std::array<double, 3> translate{{0, 0, 0}};
  std::vector<std::array<long long, 3>> vertices;   // integer coordinates, no two equal
  std::vector<Building> buildings;                  // by increasing index
};

// the number of decimals of the coordinates given by `stream_precision` (3 when absent)
template <class NamedParameters>
int CityJSON_decimals(const NamedParameters& np)
{
  const double decimals = static_cast<double>(
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::stream_precision), 3));
  if(!(decimals >= 0 && decimals <= 15 && decimals == std::floor(decimals)))
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "write_CityJSON: stream_precision is the number of decimals of the written coordinates "
                      "(3: millimetres), an integer from 0 to 15");
  return static_cast<int>(decimals);
}

template <class Point>
CityJSON_model make_CityJSON_model(const Surface_mesh<Point>& mesh, int decimals)
{
  using Mesh = Surface_mesh<Point>;
  using Face_index = typename Mesh::Face_index;
  using Vertex_index = typename Mesh::Vertex_index;
  const auto building_map = optional_property_map(mesh.template property_map<Face_index, std::size_t>("f:building"));
  const auto type_map =
    optional_property_map(mesh.template property_map<Face_index, Building_surface_type>("f:surface_type"));
  if(!building_map)
    throw Input_error(Input_error_code::MISSING_PROPERTY,
                      "write_CityJSON: the mesh has no face property map \"f:building\" of type std::size_t "
                      "(the index of the building of each face)");
  if(!type_map)
    throw Input_error(Input_error_code::MISSING_PROPERTY,
                      "write_CityJSON: the mesh has no face property map \"f:surface_type\" of type "
                      "Polygon_partition_simplification::Building_surface_type (roof, wall or ground)");

  // the faces of each building, in the order of the mesh, and the box of their vertices
  std::map<std::size_t, std::vector<Face_index>> faces_of_building;
  const double infinity = std::numeric_limits<double>::infinity();
  std::array<double, 3> lowest{{infinity, infinity, infinity}}, highest{{-infinity, -infinity, -infinity}};
  for(Face_index f : mesh.faces()) {
    if(static_cast<unsigned char>((*type_map)[f]) > static_cast<unsigned char>(Building_surface_type::GROUND))
      throw Input_error(Input_error_code::INVALID_PARAMETER,
                        "write_CityJSON: face " + std::to_string(std::size_t(f)) +
                        " has a surface type that is not ROOF, WALL or GROUND");
    faces_of_building[(*building_map)[f]].push_back(f);
    for(Vertex_index v : mesh.vertices_around_face(mesh.halfedge(f))) {
      const Point& p = mesh.point(v);
      const std::array<double, 3> c{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
      for(int i = 0; i < 3; ++i) {
        if(!std::isfinite(c[i]))
          throw Input_error(Input_error_code::NON_FINITE_COORDINATE,
                            "write_CityJSON: vertex " + std::to_string(std::size_t(v)) +
                            " has a coordinate that is not finite");
        lowest[i] = (std::min)(lowest[i], c[i]);
        highest[i] = (std::max)(highest[i], c[i]);
      }
    }
  }

  // integer coordinates relative to the lowest corner, exact in a double (below 2^53); powers
  // of ten up to 10^15 are exact doubles
  CityJSON_model model;
  double factor = 1;
  for(int i = 0; i < decimals; ++i)
    factor *= 10;
  model.scale = 1 / factor;
  if(faces_of_building.empty())
    return model;
  model.translate = lowest;
  for(int i = 0; i < 3; ++i)
    if((highest[i] - lowest[i]) * factor >= 9007199254740992.)
      throw Input_error(Input_error_code::INVALID_PARAMETER,
                        "write_CityJSON: the model is too large for " + std::to_string(decimals) +
                        " decimals (integer coordinates beyond 2^53): lower stream_precision");

  // vertices numbered in the order of their first use by a written surface; vertices that fall
  // on the same integer point are one vertex, a ring loses its repeated consecutive vertices, and
  // a surface with fewer than three vertices left (smaller than the precision) is not written
  std::map<std::array<long long, 3>, std::size_t> vertex_index;
  std::vector<std::array<long long, 3>> points;
  for(const auto& [building, faces] : faces_of_building) {
    CityJSON_model::Building written{building, {}, {}};
    for(Face_index f : faces) {
      points.clear();
      for(Vertex_index v : mesh.vertices_around_face(mesh.halfedge(f))) {
        const Point& p = mesh.point(v);
        const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
        std::array<long long, 3> q;
        for(int i = 0; i < 3; ++i)
          q[i] = std::llround((c[i] - lowest[i]) * factor);
        if(points.empty() || points.back() != q)
          points.push_back(q);
      }
      while(points.size() > 1 && points.back() == points.front())
        points.pop_back();
      if(points.size() < 3)
        continue;
      std::vector<std::size_t> ring;
      for(const std::array<long long, 3>& q : points) {
        const auto inserted = vertex_index.emplace(q, model.vertices.size());
        if(inserted.second)
          model.vertices.push_back(q);
        ring.push_back(inserted.first->second);
      }
      written.rings.push_back(std::move(ring));
      written.types.push_back((*type_map)[f]);
    }
    if(!written.rings.empty())
      model.buildings.push_back(std::move(written));
  }
  return model;
}

inline std::string CityJSON_text(const CityJSON_model& model)
{
  std::string out = "{\"type\":\"CityJSON\",\"version\":\"1.1\",\n\"transform\":{\"scale\":[";
  for(int i = 0; i < 3; ++i) {
    out += i ? "," : "";
    append_JSON_number(out, model.scale);
  }
  out += "],\"translate\":[";
  for(int i = 0; i < 3; ++i) {
    out += i ? "," : "";
    append_JSON_number(out, model.translate[i]);
  }
  out += "]},\n\"CityObjects\":{";
  for(std::size_t b = 0; b < model.buildings.size(); ++b) {
    const CityJSON_model::Building& building = model.buildings[b];
    out += b ? ",\n" : "\n";
    append_JSON_string(out, "building_" + std::to_string(building.index));
    out += ":{\"type\":\"Building\",\"geometry\":[{\"type\":\"Solid\",\"lod\":\"2.2\",\"boundaries\":[[";
    for(std::size_t s = 0; s < building.rings.size(); ++s) {
      out += s ? ",[[" : "[[";
      for(std::size_t i = 0; i < building.rings[s].size(); ++i) {
        out += i ? "," : "";
        append_JSON_number(out, building.rings[s][i]);
      }
      out += "]]";
    }
    // the order of the semantic surfaces is that of Building_surface_type
    out += "]],\"semantics\":{\"surfaces\":[{\"type\":\"RoofSurface\"},{\"type\":\"WallSurface\"},"
           "{\"type\":\"GroundSurface\"}],\"values\":[[";
    for(std::size_t s = 0; s < building.types.size(); ++s) {
      out += s ? "," : "";
      append_JSON_number(out, static_cast<unsigned int>(building.types[s]));
    }
    out += "]]}}]}";
  }
  out += "\n},\n\"vertices\":[";
  for(std::size_t v = 0; v < model.vertices.size(); ++v) {
    out += v ? ",\n[" : "\n[";
    for(int i = 0; i < 3; ++i) {
      out += i ? "," : "";
      append_JSON_number(out, model.vertices[v][i]);
    }
    out += ']';
  }
  out += "\n]}\n";
  return out;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_CITYJSON_MODEL_H
