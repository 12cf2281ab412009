// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SEGMENT_GRID_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SEGMENT_GRID_2_H

// A uniform grid of square cells over a rectangle, each cell listing the segments that pass
// near it: to visit segments by increasing distance from a point, ring of cells by ring of
// cells, or the segments near a segment. Every segment is listed in every cell it meets (and possibly in a few neighbouring
// ones: the test is conservative), so after the rings 0 to k around the cell of a point P
// every segment closer to P than (k - 1) times the cell size has been visited, whatever the
// rounding of the cell indices. About one cell per segment.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

class Segment_grid_2
{
public:
  // `segments`: (x0, y0, x1, y1); `low`, `high`: corners of a rectangle containing them
  Segment_grid_2(const std::vector<std::array<double, 4>>& segments, std::array<double, 2> low,
                 std::array<double, 2> high)
    : low_(low)
  {
    double width = std::max(high[0] - low[0], 0.), height = std::max(high[1] - low[1], 0.);
    if(!std::isfinite(width) || !std::isfinite(height)) width = height = 0; // one cell
    const double n = double(std::max<std::size_t>(segments.size(), 1));
    cell_ = std::sqrt(width * height / n);
    // at most 4096 cells along a side (a very elongated rectangle gets larger cells)
    cell_ = std::max({cell_, width / 4096, height / 4096});
    if(!(cell_ > 0)) cell_ = 1;
    columns_ = count_of(width / cell_);
    rows_ = count_of(height / cell_);
    std::vector<std::uint32_t> count(std::size_t(columns_) * rows_ + 1, 0);
    for(const auto& s : segments) for_each_cell(s, [&](std::size_t c) { ++count[c + 1]; });
    for(std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    first_ = count;
    entries_.resize(count.back());
    for(std::uint32_t i = 0; i < segments.size(); ++i)
      for_each_cell(segments[i], [&](std::size_t c) { entries_[count[c]++] = i; });
  }

  double cell_size() const { return cell_; }

  // Calls f(cell) for the cells that segment s may meet (all those it meets): row by row, the
  // columns where the segment is within the rows around it, one more on each side for rounding,
  // and among them the cells whose center is closer to the segment's line than a cell's side
  // (more than the half-diagonal). About 3 cells per row and one per column it crosses.
  template <class F>
  void for_each_cell(const std::array<double, 4>& s, F&& f) const
  {
    const int x0 = column(std::min(s[0], s[2])), x1 = column(std::max(s[0], s[2]));
    const int y0 = row(std::min(s[1], s[3])), y1 = row(std::max(s[1], s[3]));
    if(x0 == x1 && y0 == y1) { f(std::size_t(y0) * columns_ + x0); return; } // the usual case
    const double dx = s[2] - s[0], dy = s[3] - s[1];
    const double length = std::sqrt(dx * dx + dy * dy);
    for(int y = y0; y <= y1; ++y) {
      int from = x0, to = x1;
      if(dy != 0 && y0 < y1) { // the x extent of the part of s in the band of row y
        auto x_at = [&](double band_y) {
          const double t = std::clamp((band_y - s[1]) / dy, 0., 1.);
          return s[0] + t * dx;
        };
        // the band of rows y - 1 to y + 1: a point that row() puts in row y lies in it whatever
        // the rounding of the band's limits and of the point's row
        const double xa = x_at(low_[1] + (y - 1) * cell_), xb = x_at(low_[1] + (y + 2) * cell_);
        from = std::max(x0, column(std::min(xa, xb)) - 1);
        to = std::min(x1, column(std::max(xa, xb)) + 1);
      }
      for(int x = from; x <= to; ++x) {
        const double cx = low_[0] + (x + 0.5) * cell_, cy = low_[1] + (y + 0.5) * cell_;
        if(length > 0 && std::abs(dx * (cy - s[1]) - dy * (cx - s[0])) > cell_ * length) continue;
        f(std::size_t(y) * columns_ + x);
      }
    }
  }

  // calls f(segment) for the segments listed in cell c
  template <class F>
  void for_each_in_cell(std::size_t c, F&& f) const
  {
    for(std::uint32_t e = first_[c]; e < first_[c + 1]; ++e) f(entries_[e]);
  }
  int column(double x) const { return index((x - low_[0]) / cell_, columns_); }
  int row(double y) const { return index((y - low_[1]) / cell_, rows_); }

  // do the rings 0 to k around cell (x, y) cover the whole grid?
  bool covers_all(int x, int y, int k) const
  {
    return x - k <= 0 && y - k <= 0 && x + k >= columns_ - 1 && y + k >= rows_ - 1;
  }

  // calls f(segment) for the segments listed in the cells at Chebyshev distance k from (x, y)
  // (a segment may come several times)
  template <class F>
  void for_each_in_ring(int x, int y, int k, F&& f) const
  {
    auto cell = [&](int cx, int cy) {
      if(cx < 0 || cy < 0 || cx >= columns_ || cy >= rows_) return;
      for_each_in_cell(std::size_t(cy) * columns_ + cx, f);
    };
    if(k == 0) { cell(x, y); return; }
    for(int cx = x - k; cx <= x + k; ++cx) { cell(cx, y - k); cell(cx, y + k); }
    for(int cy = y - k + 1; cy <= y + k - 1; ++cy) { cell(x - k, cy); cell(x + k, cy); }
  }

private:
  static int count_of(double cells) { return cells > 1 ? int(std::min(std::ceil(cells), 4096.)) : 1; }
  // floor(position), clamped to [0, count - 1] before the conversion (NaN gives 0)
  static int index(double position, int count)
  {
    const double c = std::floor(position);
    return c >= 0 ? int(std::min(c, double(count - 1))) : 0;
  }

  std::array<double, 2> low_;
  double cell_ = 1;
  int columns_ = 1, rows_ = 1;
  std::vector<std::uint32_t> first_;   // per cell, where its segments start in entries_
  std::vector<std::uint32_t> entries_; // segment indices, cell by cell
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SEGMENT_GRID_2_H
