// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_MERGE_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_MERGE_3_H

// merge_tile_meshes(): the meshes of the tiles welded at their common border vertices into one
// triangle soup, the triangles that two tiles both have cancelled, the soup made a valid
// polygon mesh, and the closed pockets removed.

#include <CGAL/Lex_optimal_chains/Coefficient_field.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Tiled_surface_report.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_soup_mesh.h>
#include <CGAL/Lex_optimal_chains/internal/Stopwatch.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <unordered_map>
#include <utility>
#include <vector>

#include <boost/functional/hash.hpp>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The triangles of the meshes of the tiles as one soup: one index per distinct point of the
// borders (hashed), and for each point the number of tiles where it is a vertex.
template <class Point>
struct Welded_tiles
{
  std::vector<Point> points;
  std::vector<std::uint32_t> tiles_of_point;
  std::vector<std::array<std::uint32_t, 3>> triangles;

  template <class PolygonMesh>
  explicit Welded_tiles(const std::vector<PolygonMesh>& tile_meshes)
  {
    std::unordered_map<Point, std::uint32_t, Point_hash> index_of;
    std::vector<std::uint32_t> last_tile;
    auto add_point = [&](const Point& p, std::size_t t) {
      points.push_back(p);
      last_tile.push_back(std::uint32_t(t));
      tiles_of_point.push_back(1);
    };
    for(std::size_t t = 0; t < tile_meshes.size(); ++t) {
      const PolygonMesh& m = tile_meshes[t];
      const auto vpm = get(vertex_point, m);
      auto global = get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), m);
      for(auto v : vertices(m)) {
        // Only a border vertex can be shared with another tile (a seam point is on the cycle of
        // its tiles): the others get their own index without a lookup.
        if(!CGAL::is_border(v, m)) {
          put(global, v, std::uint32_t(points.size()));
          add_point(get(vpm, v), t);
          continue;
        }
        const auto inserted = index_of.emplace(get(vpm, v), std::uint32_t(points.size()));
        if(inserted.second) {
          add_point(get(vpm, v), t);
        } else if(last_tile[inserted.first->second] != t) {
          last_tile[inserted.first->second] = std::uint32_t(t);
          ++tiles_of_point[inserted.first->second];
        }
        put(global, v, inserted.first->second);
      }
      for(auto f : faces(m)) add_triangle(m, f, global);
    }
  }

private:
  struct Point_hash
  {
    std::size_t operator()(const Point& p) const
    {
      std::size_t seed = 0;
      boost::hash_combine(seed, p.x());
      boost::hash_combine(seed, p.y());
      boost::hash_combine(seed, p.z());
      return seed;
    }
  };

  template <class PolygonMesh, class Face, class IndexMap>
  void add_triangle(const PolygonMesh& m, Face f, const IndexMap& global)
  {
    std::array<std::uint32_t, 3> tri;
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, m), m)) {
      if(k == 3) throw Input_error(Input_error_code::INVALID_PARAMETER, "a face of a tile mesh is not a triangle");
      tri[k++] = get(global, target(h, m));
    }
    if(k != 3) throw Input_error(Input_error_code::INVALID_PARAMETER, "a face of a tile mesh is not a triangle");
    triangles.push_back(tri);
  }
};

// The union is the sum of the chains of the tiles: a triangle that two tiles both have (where
// a seam makes a narrow excursion, up a wall and down again, both tiles span it, each with the
// orientation of its own cycle) cancels out, as the seam itself does. Only a triangle whose
// three points are vertices of several tiles can be one. Returns the number of triangles
// removed.
inline std::size_t cancel_shared_triangles(std::vector<std::array<std::uint32_t, 3>>& triangles,
                                           const std::vector<std::uint32_t>& tiles_of_point)
{
  std::vector<std::pair<std::array<std::uint32_t, 3>, std::size_t>> candidates;
  for(std::size_t i = 0; i < triangles.size(); ++i) {
    std::array<std::uint32_t, 3> key = triangles[i];
    if(tiles_of_point[key[0]] < 2 || tiles_of_point[key[1]] < 2 || tiles_of_point[key[2]] < 2) continue;
    std::sort(key.begin(), key.end());
    candidates.emplace_back(key, i);
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> kept(triangles.size(), true);
  for(std::size_t i = 0, j; i < candidates.size(); i = j) {
    for(j = i + 1; j < candidates.size() && candidates[j].first == candidates[i].first; ++j) {}
    // pairs cancel: an odd count leaves the first one
    for(std::size_t k = (j - i) % 2; k < j - i; ++k) kept[candidates[i + k].second] = false;
  }
  std::size_t n = 0;
  for(std::size_t i = 0; i < triangles.size(); ++i)
    if(kept[i]) triangles[n++] = triangles[i];
  const std::size_t cancelled = triangles.size() - n;
  triangles.resize(n);
  return cancelled;
}

// Where a seam makes an excursion (up a wall and down again), both tiles may also span the
// narrow curtain under it, each with its own triangles: their sum is a closed pocket. A closed
// component has no boundary: without it the union has the same boundary and is smaller in
// the lexicographic order. The closed components of `merged` are removed while one with a
// boundary is left.
template <class PolygonMesh>
void remove_closed_pockets(PolygonMesh& merged, Tile_merge_report& report)
{
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), merged);
  const std::size_t n = Polygon_mesh_processing::connected_components(merged, component);
  std::vector<bool> bounded(n, false);
  std::vector<std::size_t> size(n, 0);
  for(auto h : halfedges(merged))
    if(is_border(h, merged)) bounded[get(component, face(opposite(h, merged), merged))] = true;
  for(auto f : faces(merged)) ++size[get(component, f)];
  std::vector<std::size_t> closed;
  for(std::size_t c = 0; c < n; ++c)
    if(!bounded[c]) closed.push_back(c);
  if(closed.size() < n && !closed.empty()) {
    Polygon_mesh_processing::remove_connected_components(merged, closed, component);
    report.removed_closed_components = closed.size();
    for(std::size_t c : closed) report.removed_closed_faces += size[c];
  }
}

template <class PolygonMesh>
Tile_merge_report merge_tiles(const std::vector<PolygonMesh>& tile_meshes, PolygonMesh& merged, Coefficient_field field)
{
  using Point = typename boost::property_traits<typename boost::property_map<PolygonMesh, vertex_point_t>::const_type>::value_type;
  Stopwatch watch;
  Tile_merge_report report;
  Welded_tiles<Point> soup(tile_meshes);
  report.cancelled_faces = cancel_shared_triangles(soup.triangles, soup.tiles_of_point);
  clear(merged);
  const Chain_soup_statistics stats = add_chain_soup(soup.points, soup.triangles, field == Coefficient_field::Q, merged);
  remove_closed_pockets(merged, report);
  report.mesh_vertices = std::size_t(std::distance(vertices(merged).begin(), vertices(merged).end()));
  report.mesh_faces = std::size_t(std::distance(faces(merged).begin(), faces(merged).end()));
  report.non_manifold_vertices = stats.vertex_copies;
  report.non_manifold_edges = stats.non_manifold_edges;
  report.orientation_cuts = stats.orientation_cuts;
  report.seconds = watch.lap();
  return report;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_MERGE_3_H
