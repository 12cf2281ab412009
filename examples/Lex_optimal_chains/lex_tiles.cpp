// Two tiles of an aerial LiDAR scan meshed independently so that their meshes coincide at
// the frontier (thesis Fig. 4.27): both tiles are bounded by the same seam, a polyline of
// input points along the frontier, closed on the outer side of each tile by an arc of the
// footprint polygon. Each tile is an open surface bounded by its cycle; the triangles that
// touch the arcs (the skirts) are dropped. The seam, made of input points, stays: it is the
// border of both meshes, and writing them together gives one seamless surface.
//
//   lex_tiles [points.ply] [left.off] [right.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <set>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace LOC = CGAL::Lex_optimal_chains;

std::set<std::pair<Point, Point>> border_edges(const Mesh& mesh)
{
  std::set<std::pair<Point, Point>> edges;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h)) edges.insert(std::minmax(mesh.point(mesh.source(h)), mesh.point(mesh.target(h))));
  return edges;
}

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : CGAL::data_file_path("points_3/b9_training.ply");
  std::vector<Point> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points)) || points.size() < 100) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());

  // the frontier: the vertical plane x = median; the seam: in each of 40 slices along y, the
  // point closest to the frontier, by increasing y
  std::vector<double> xs;
  for(const Point& p : points) xs.push_back(p.x());
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  const double frontier = xs[xs.size() / 2];
  const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
  const int slices = 40;
  std::vector<Point> seam;
  for(int s = 0; s < slices; ++s) {
    const double y0 = box.ymin() + (box.ymax() - box.ymin()) * s / slices, y1 = box.ymin() + (box.ymax() - box.ymin()) * (s + 1) / slices;
    const Point* best = nullptr;
    for(const Point& p : points)
      if(p.y() >= y0 && (p.y() < y1 || s == slices - 1) && (!best || std::abs(p.x() - frontier) < std::abs(best->x() - frontier))) best = &p;
    if(best && (seam.empty() || best->y() > seam.back().y())) seam.push_back(*best);
  }
  // the two tiles: the points on each side of the seam (between consecutive seam points, the
  // side of the segment joining them), the seam in both
  auto left_of_seam = [&](const Point& p) {
    if(p.y() <= seam.front().y()) return p.x() < seam.front().x();
    if(p.y() >= seam.back().y()) return p.x() < seam.back().x();
    const auto it = std::upper_bound(seam.begin(), seam.end(), p.y(), [](double y, const Point& q) { return y < q.y(); });
    const Point& a = *(it - 1);
    const Point& b = *it;
    return CGAL::orientation(Kernel::Point_2(a.x(), a.y()), Kernel::Point_2(b.x(), b.y()), Kernel::Point_2(p.x(), p.y())) == CGAL::LEFT_TURN;
  };
  const std::set<Point> on_seam(seam.begin(), seam.end());
  std::vector<Point> tile[2];
  for(const Point& p : points) {
    if(on_seam.count(p)) { tile[0].push_back(p); tile[1].push_back(p); }
    else tile[left_of_seam(p) ? 0 : 1].push_back(p);
  }

  // each tile's cycle: the seam, then an arc outside the footprint around the tile's side
  const std::vector<Point> polygon = LOC::footprint_boundary(points, CGAL::parameters::default_values(), 0.05, 8);
  Mesh mesh[2];
  for(int t = 0; t < 2; ++t) {
    std::vector<Point> cycle;
    // counterclockwise cycles: the left tile goes up the seam, the right one down it
    if(t == 0) cycle.assign(seam.begin(), seam.end());
    else cycle.assign(seam.rbegin(), seam.rend());
    // the polygon vertices on the tile's side, from the one after the seam's end, counterclockwise
    std::vector<Point> arc;
    for(std::size_t i = 0; i + 1 < polygon.size(); ++i)
      if((polygon[i].x() < frontier) == (t == 0)) arc.push_back(polygon[i]);
    // the polygon turns counterclockwise: start the arc after the seam's last point
    const Point& last = cycle.back();
    std::size_t first = 0;
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < arc.size(); ++i) {
      const double d = CGAL::squared_distance(Kernel::Point_2(arc[i].x(), arc[i].y()), Kernel::Point_2(last.x(), last.y()));
      if(d < best) best = d, first = i;
    }
    std::rotate(arc.begin(), arc.begin() + first, arc.end());
    cycle.insert(cycle.end(), arc.begin(), arc.end());
    cycle.push_back(cycle.front());
    try {
      const auto r = CGAL::lex_optimal_open_surface_reconstruction(
        tile[t], std::vector<std::vector<Point>>{cycle}, mesh[t],
        LOC::parameters::remove_blocking_points(true, LOC::parameters::drop_boundary_triangles(true)));
      std::cout << (t == 0 ? "left" : "right") << " tile: " << tile[t].size() << " points, " << r.mesh_faces << " faces, "
                << r.number_of_removed_points << " points removed near the boundary\n";
    } catch(const LOC::Input_error& e) {
      std::cerr << "tile " << t << ": " << e.what() << "\n";
      return 1;
    }
  }

  // the seam is a border of both meshes: they coincide at the frontier
  const auto b0 = border_edges(mesh[0]), b1 = border_edges(mesh[1]);
  std::size_t shared = 0;
  for(std::size_t i = 0; i + 1 < seam.size(); ++i) {
    const auto e = std::minmax(seam[i], seam[i + 1]);
    if(b0.count(e) && b1.count(e)) ++shared;
  }
  std::cout << shared << " of the " << seam.size() - 1 << " seam edges are borders of both meshes\n";
  if(argc > 3) {
    CGAL::IO::write_polygon_mesh(argv[2], mesh[0], CGAL::parameters::stream_precision(17));
    CGAL::IO::write_polygon_mesh(argv[3], mesh[1], CGAL::parameters::stream_precision(17));
  }
  return shared + 1 == seam.size() ? 0 : 1;
}
