// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_SEAMS_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_SEAMS_3_H

// The tiling of a terrain-like cloud for lex_optimal_tiled_surface_reconstruction(), in the
// spirit of Fig. 4.27 of the thesis: a grid of columns x rows tiles over the bounding rectangle
// of the points in the xy-plane, and between neighbouring tiles a seam, a polyline of input
// points, so that every tile is an open surface bounded by a cycle that its neighbours share.
//
// Every inner border line of the grid (x = x_i or y = y_j) carries one polyline from one side
// of a frame to the other:
//  - at each inner grid node, the corner point: the input point nearest to the node within the
//    square of side s around it (s: the seam spacing), or else a point at the node, at the
//    height of the nearest input point of the two bands through it; the horizontal and the
//    vertical polyline through the node share it;
//  - between two nodes, the border is cut into slices of length about s (leaving s free next
//    to a corner), and each slice gives the input point nearest to its centre within the band
//    of width s around the border (an empty slice gives none);
//  - an edge longer than s is split by points on it (refine()), and an edge whose diametral
//    ball holds another seam point is split at that point's projection until none does
//    (Gabriel_seams_3.h);
//  - at the ends, a point of the frame on the border line, at the height of the seam point next
//    to it.
// The frame is a rectangle just outside the cloud whose sides bulge outward (frame_point()), so
// that each frame edge is an edge of the triangulation of any tile whatever the heights. A
// vertical polyline stays in its band, is strictly increasing in y, and meets a horizontal one
// at their corner point only (near a corner both leave the corner in their own band), so the
// polylines cut the plane into the tiles. The cycle of a tile follows its four sides: the seams
// of its inner sides, the frame on the others (whose vertices are not input points: the
// triangles that touch them are dropped, as the skirt of an open surface).

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Gabriel_seams_3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The grid of the tiles over the bounding rectangle of the points: columns x rows cells of
// equal size, at most `tile_size` on a side, and what lies near its inner border lines.
class Tile_grid
{
public:
  // `tile_size` positive and finite (the caller checks it)
  Tile_grid(const Bbox_3& box, double tile_size)
  {
    low_ = {box.xmin(), box.ymin()};
    high_ = {box.xmax(), box.ymax()};
    for(int axis = 0; axis < 2; ++axis) {
      const double extent = high_[axis] - low_[axis];
      count_[axis] = std::max<std::size_t>(1, std::size_t(std::ceil(extent / tile_size)));
      step_[axis] = extent / double(count_[axis]);
    }
  }

  std::size_t columns() const { return count_[0]; }
  std::size_t rows() const { return count_[1]; }
  std::size_t number_of_tiles() const { return count_[0] * count_[1]; }

  // the x of border line i (0 <= i <= columns) or the y of border line j
  double border(int axis, std::size_t i) const
  {
    return i == count_[axis] ? high_[axis] : low_[axis] + double(i) * step_[axis];
  }

  // the index along `axis` (column or row) of the cell that holds coordinate c
  std::size_t cell_along(int axis, double c) const
  {
    const double f = std::floor((c - low_[axis]) / step_[axis]);
    return f < 0 ? 0 : std::min(count_[axis] - 1, std::size_t(f));
  }

  // the cell (column + columns * row) that holds (x, y), by its coordinates
  std::size_t cell_of(double x, double y) const { return cell_along(0, x) + count_[0] * cell_along(1, y); }

  // The inner border line of `axis` (1 to count - 1) within `half_width` of coordinate c, or 0.
  std::size_t inner_border_near(int axis, double c, double half_width) const
  {
    if(count_[axis] < 2) return 0;
    const double i = std::round((c - low_[axis]) / step_[axis]);
    if(i < 1 || i > double(count_[axis] - 1)) return 0;
    return std::abs(c - border(axis, std::size_t(i))) <= half_width ? std::size_t(i) : 0;
  }

protected:
  std::array<double, 2> low_{}, high_{}, step_{};
  std::array<std::size_t, 2> count_{};
};

template <class Point>
class Tile_seams_3 : public Tile_grid
{
  using Kernel = typename Kernel_traits<Point>::Kernel;
  using Point_2 = typename Kernel::Point_2;

public:
  // `points`: finite, sorted, distinct, not all on one vertical line; `tile_size` and
  // `seam_spacing` positive and finite (the caller checks them).
  Tile_seams_3(const std::vector<Point>& points, double tile_size, double seam_spacing)
    : Tile_seams_3(bbox_3(points.begin(), points.end()), points, tile_size, seam_spacing)
  {}

  // The same seams from the bounding box `box` of the points and from those of them that lie
  // within half the spacing of an inner border line (`in_band()`; others may be given too):
  // the seams are made of these only.
  Tile_seams_3(const Bbox_3& box, const std::vector<Point>& band_points, double tile_size, double seam_spacing)
    : Tile_grid(box, tile_size), spacing_(seam_spacing)
  {
    const double side = std::max(high_[0] - low_[0], high_[1] - low_[1]);
    margin_ = std::max(seam_spacing, 0.01 * side);
    drop_ = 1e-3 * side;
    frame_z_ = box.zmin() - drop_; // below the points: a flat cloud is not coplanar with the frame
    build_polylines(band_points);
  }

  // whether p is near an inner border line of `grid`, where the seams of spacing `spacing` take their points
  static bool in_band(const Tile_grid& grid, const Point& p, double spacing)
  {
    return grid.inner_border_near(0, p.x(), 0.5 * spacing) != 0 || grid.inner_border_near(1, p.y(), 0.5 * spacing) != 0;
  }

  // the input points that lie on a seam (on the cycles of two tiles or more), sorted
  const std::vector<Point>& seam_points() const { return seam_points_; }
  bool is_seam_point(const Point& p) const { return std::binary_search(seam_points_.begin(), seam_points_.end(), p); }

  // The tile (column + columns * row) whose region holds p, which is not a seam point. A point
  // on a seam (between two of its points) goes to the tile on the left of a vertical seam and
  // below a horizontal one.
  std::size_t tile_of(const Point& p) const
  {
    return index_along(0, p) + count_[0] * index_along(1, p);
  }

  // The cycle of tile (column, row), counterclockwise, closed (its last point is its first).
  std::vector<Point> cycle(std::size_t column, std::size_t row) const
  {
    std::vector<Point> result;
    auto append = [&](const std::vector<Point>& piece) {
      result.insert(result.end(), piece.begin(), piece.end() - 1); // the last is the next piece's first
    };
    append(side(1, row, column, false));        // bottom, left to right
    append(side(0, column + 1, row, false));    // right, upwards
    append(side(1, row + 1, column, true));     // top, right to left
    append(side(0, column, row, true));         // left, downwards
    result.push_back(result.front());
    return result;
  }

private:
  // The polyline of border line i on `axis` (0: the vertical line x = x_i, 1: the horizontal
  // line y = y_i), from the frame to the frame; `nodes[k]` is the index in it of the node of
  // the k-th crossing border line.
  using Polyline = Seam_polyline<Point>;

  // coordinate `axis` of p
  static double coordinate(const Point& p, int axis) { return axis == 0 ? p.x() : p.y(); }

  // the point of the plane with coordinate `along` on `axis` and `across` on the other
  Point planar(int axis, double along, double across, double z) const
  {
    return axis == 0 ? Point(along, across, z) : Point(across, along, z);
  }

  // A point of the frame: on its side along border line 0 (`far` false) or `count_[axis]` of
  // `axis`, at coordinate `along` on the other axis, at height z. The sides bulge outward on a
  // parabola (at most half the margin, at the middle of a side), so that the frame is strictly
  // convex in the xy-plane: each of its edges then has a vertical plane through it with all
  // the other points on one side, and is an edge of every Delaunay triangulation of the points
  // of a tile and of its cycle, whatever the heights of the frame points.
  Point frame_point(int axis, bool far, double along, double z) const
  {
    const int other = 1 - axis;
    const double lo = low_[other] - margin_, hi = high_[other] + margin_;
    const double t = std::clamp((along - lo) / (hi - lo), 0., 1.);
    const double bulge = 2 * margin_ * t * (1 - t);
    const double across = far ? high_[axis] + margin_ + bulge : low_[axis] - margin_ - bulge;
    return planar(axis, across, along, z);
  }

  // the corner of the frame at the ends of its sides (`far_x`: at the high x, `far_y`: at the high y)
  Point frame_corner(bool far_x, bool far_y) const
  {
    return frame_point(0, far_x, far_y ? high_[1] + margin_ : low_[1] - margin_, frame_z_);
  }

  // The piece of the cycle along border line i on `axis` between crossing lines k and k + 1,
  // from k to k + 1 (or back if `reversed`): the seam, or a straight side of the frame.
  std::vector<Point> side(int axis, std::size_t i, std::size_t k, bool reversed) const
  {
    std::vector<Point> piece;
    if(i == 0 || i == count_[axis]) { // the frame, from node k to node k + 1 of its side
      const int other = 1 - axis;
      const bool far = i != 0;
      for(std::size_t n : {k, k + 1}) {
        if(n == 0 || n == count_[other]) // a corner of the frame
          piece.push_back(axis == 0 ? frame_corner(far, n != 0) : frame_corner(n != 0, far));
        else { // the end of the seam along border line n of the other axis
          const std::vector<Point>& seam = polylines_[other][n - 1].points;
          piece.push_back(far ? seam.back() : seam.front());
        }
      }
    } else {
      const Polyline& line = polylines_[axis][i - 1];
      piece.assign(line.points.begin() + line.nodes[k], line.points.begin() + line.nodes[k + 1] + 1);
    }
    if(reversed) std::reverse(piece.begin(), piece.end());
    return piece;
  }

  // The nearest candidate to `target` in the xy-plane (ties: the smaller point), among those
  // with coordinate `axis` in [lo, hi); `candidates` sorted by that coordinate. Null if none.
  static const Point* nearest(const std::vector<const Point*>& candidates, int axis, double lo, double hi,
                              const std::array<double, 2>& target)
  {
    auto first = std::lower_bound(candidates.begin(), candidates.end(), lo,
                                  [axis](const Point* p, double v) { return coordinate(*p, axis) < v; });
    const Point* best = nullptr;
    double best_d = std::numeric_limits<double>::infinity();
    for(auto it = first; it != candidates.end() && coordinate(**it, axis) < hi; ++it) {
      const double dx = (*it)->x() - target[0], dy = (*it)->y() - target[1];
      const double d = dx * dx + dy * dy;
      if(d < best_d || (d == best_d && **it < *best)) { best = *it; best_d = d; }
    }
    return best;
  }

  void build_polylines(const std::vector<Point>& points)
  {
    // candidates: the points within half the spacing of an inner border line, per line
    std::array<std::vector<std::vector<const Point*>>, 2> band;
    for(int axis = 0; axis < 2; ++axis) band[axis].resize(count_[axis] > 1 ? count_[axis] - 1 : 0);
    for(const Point& p : points)
      for(int axis = 0; axis < 2; ++axis)
        if(const std::size_t i = inner_border_near(axis, coordinate(p, axis), 0.5 * spacing_))
          band[axis][i - 1].push_back(&p);
    // sorted along their line (then as points: deterministic)
    for(int axis = 0; axis < 2; ++axis)
      for(auto& b : band[axis])
        std::sort(b.begin(), b.end(), [axis](const Point* p, const Point* q) {
          const int other = 1 - axis;
          return std::make_tuple(coordinate(*p, other), *p) < std::make_tuple(coordinate(*q, other), *q);
        });
    // the corner points, from the bands of the vertical lines; a node without an input point
    // within half a spacing gets a point of its own, at the height of the nearest point of the
    // two bands through it (the seams still meet there, and the four tiles share it)
    std::vector<std::vector<Point>> corners(count_[0] + 1, std::vector<Point>(count_[1] + 1));
    for(std::size_t i = 1; i < count_[0]; ++i)
      for(std::size_t j = 1; j < count_[1]; ++j) {
        const std::array<double, 2> node{border(0, i), border(1, j)};
        const Point* c = nearest(band[0][i - 1], 1, node[1] - 0.5 * spacing_, std::nextafter(node[1] + 0.5 * spacing_, HUGE_VAL), node);
        if(c != nullptr) {
          corners[i][j] = *c;
          continue;
        }
        const Point* a = nearest(band[0][i - 1], 1, -HUGE_VAL, HUGE_VAL, node);
        const Point* b = nearest(band[1][j - 1], 0, -HUGE_VAL, HUGE_VAL, node);
        auto d2 = [&node](const Point* p) { return std::pow(p->x() - node[0], 2) + std::pow(p->y() - node[1], 2); };
        if(b != nullptr && (a == nullptr || std::make_tuple(d2(b), *b) < std::make_tuple(d2(a), *a))) a = b;
        if(a == nullptr)
          throw Input_error(Input_error_code::INVALID_PARAMETER,
                            "no input point within " + std::to_string(0.5 * spacing_) + " of the border lines through the tile corner (" +
                              std::to_string(node[0]) + ", " + std::to_string(node[1]) +
                              "): the seams between tiles run through the points; give a larger seam spacing or "
                              "tile size, or tiles that avoid the gaps of the cloud");
        corners[i][j] = Point(node[0], node[1], a->z());
      }
    for(int axis = 0; axis < 2; ++axis) {
      const int other = 1 - axis;
      polylines_[axis].resize(band[axis].size());
      for(std::size_t i = 1; i < count_[axis]; ++i) {
        Polyline& line = polylines_[axis][i - 1];
        for(std::size_t k = 0; k <= count_[other]; ++k) {
          // node k
          line.nodes.push_back(line.points.size());
          if(k == 0 || k == count_[other]) line.points.push_back(Point(0, 0, 0)); // a frame point, below
          else line.points.push_back(axis == 0 ? corners[i][k] : corners[k][i]);
          if(k == count_[other]) break;
          // the slices between node k and node k + 1
          const double lo = k == 0 ? low_[other] : border(other, k) + spacing_;
          const double hi = k + 1 == count_[other] ? high_[other] : border(other, k + 1) - spacing_;
          if(!(hi > lo)) continue;
          const std::size_t slices = std::max<std::size_t>(1, std::size_t((hi - lo) / spacing_));
          const double width = (hi - lo) / double(slices);
          for(std::size_t s = 0; s < slices; ++s) {
            const double a = lo + double(s) * width;
            const double b = s + 1 == slices ? std::nextafter(hi, HUGE_VAL) : lo + double(s + 1) * width;
            std::array<double, 2> centre;
            centre[axis] = border(axis, i);
            centre[other] = 0.5 * (a + b);
            if(const Point* p = nearest(band[axis][i - 1], other, a, b, centre)) line.points.push_back(*p);
          }
        }
        // the ends on the frame, at the heights of the seam points next to them (short edges to
        // the frame: small diametral balls, few points removed near the frame by the tiles),
        // lowered as the frame is (a flat cloud is not coplanar with them)
        const std::size_t last = line.points.size() - 1;
        const double z_first = last > 1 ? line.points[1].z() - drop_ : frame_z_;
        const double z_last = last > 1 ? line.points[last - 1].z() - drop_ : frame_z_;
        line.points.front() = frame_point(other, false, border(axis, i), z_first);
        line.points.back() = frame_point(other, true, border(axis, i), z_last);
        refine(line);
      }
    }
    // edges that every tile can impose (Gabriel_seams_3.h)
    std::vector<Polyline*> lines;
    for(int axis = 0; axis < 2; ++axis)
      for(Polyline& line : polylines_[axis]) lines.push_back(&line);
    Gabriel_seams_3<Point>(lines, spacing_).split_until_gabriel();
    for(const Polyline* line : lines)
      for(std::size_t n = 1; n + 1 < line->points.size(); ++n) seam_points_.push_back(line->points[n]);
    std::sort(seam_points_.begin(), seam_points_.end());
    seam_points_.erase(std::unique(seam_points_.begin(), seam_points_.end()), seam_points_.end());
  }

  // Splits the seam edges (not those to the frame) longer than the spacing into equal parts:
  // a long edge (across a gap, or up a wall where a seam point on the ground is followed by one
  // on a roof) has a large diametral ball, which may hold other seam points (which would keep it
  // out of the Delaunay triangulation of a tile) and many input points (which the tile would
  // remove). The added points are seam points of both tiles, on the segment.
  void refine(Polyline& line) const
  {
    Polyline refined;
    std::size_t next_node = 0;
    for(std::size_t n = 0; n < line.points.size(); ++n) {
      if(next_node < line.nodes.size() && line.nodes[next_node] == n) { refined.nodes.push_back(refined.points.size()); ++next_node; }
      const Point& p = line.points[n];
      refined.points.push_back(p);
      if(n == 0 || n + 2 >= line.points.size()) continue; // the first and last edges go to the frame
      const Point& q = line.points[n + 1];
      const double length = std::sqrt(squared_distance(p, q));
      const double parts = std::ceil(length / spacing_);
      for(double k = 1; k < parts; ++k) {
        const double t = k / parts;
        refined.points.push_back(Point(p.x() + t * (q.x() - p.x()), p.y() + t * (q.y() - p.y()), p.z() + t * (q.z() - p.z())));
      }
    }
    line = std::move(refined);
  }

  // The index along `axis` (column or row) of the tile of p: from its coordinate, and far from
  // a border line only; near one, from the side of the seam where p lies (exact orientation).
  std::size_t index_along(int axis, const Point& p) const
  {
    const std::size_t n = count_[axis];
    if(n == 1) return 0;
    const double c = coordinate(p, axis);
    const std::size_t index = cell_along(axis, c);
    // the inner border lines whose band may hold p: index and index + 1
    for(std::size_t i : {index, index + 1}) {
      if(i < 1 || i >= n || std::abs(c - border(axis, i)) > 0.5 * spacing_) continue;
      return before_seam(axis, i, p) ? i - 1 : i;
    }
    return index;
  }

  // Is p before polyline i of `axis` (left of a vertical one, below a horizontal one)? On it:
  // yes. p lies within the polyline's extent along it (the frame ends beyond the points).
  bool before_seam(int axis, std::size_t i, const Point& p) const
  {
    const int other = 1 - axis;
    const std::vector<Point>& line = polylines_[axis][i - 1].points;
    const double t = coordinate(p, other);
    // the segment [a, b] of the polyline whose extent holds t (strictly increasing along it)
    auto it = std::upper_bound(line.begin(), line.end(), t, [other](double v, const Point& q) { return v < coordinate(q, other); });
    if(it == line.begin()) ++it;
    if(it == line.end()) --it;
    const Point& a = *(it - 1);
    const Point& b = *it;
    const Orientation o = typename Kernel::Orientation_2()(Point_2(a.x(), a.y()), Point_2(b.x(), b.y()), Point_2(p.x(), p.y()));
    // going up a vertical seam, the left is before; going right along a horizontal one, the right (below) is
    return axis == 0 ? o != RIGHT_TURN : o != LEFT_TURN;
  }

  double spacing_ = 0, margin_ = 0, drop_ = 0, frame_z_ = 0;
  std::array<std::vector<Polyline>, 2> polylines_;
  std::vector<Point> seam_points_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_SEAMS_3_H
