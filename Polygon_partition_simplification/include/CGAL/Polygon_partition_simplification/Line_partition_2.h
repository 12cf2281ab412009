// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification_traits_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Geom_traits_check.h>
#include <CGAL/Polygon_partition_simplification/internal/Geom_traits_of.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_validity_2.h>

#include <CGAL/Arr_non_caching_segment_basic_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/assertions.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {

/*!
\ingroup PkgPolygonPartitionSimplificationRef
The fidelity metric of a line (Eq. 3.5 of the thesis without its \f$l_{min}\f$ term): the
symmetric matrix \f$\frac12\sum_{s}\sum_{(x,y)\in s}(x,y,1)^T(x,y,1)\f$ summed over the
endpoints of the segments the line comes from. \f$L^T M L\f$ is the sum of the squared
distances from these endpoints to the line \f$L\f$ (in normal form), halved.
*/
struct Line_metric
{
  /// entries xx, xy, x, yy, y, 1 of the symmetric 3x3 matrix
  std::array<double, 6> entries{{0, 0, 0, 0, 0, 0}};

  /// adds the contribution of the segment (x0, y0)-(x1, y1)
  void add_segment(double x0, double y0, double x1, double y1)
  {
    entries[0] += 0.5 * (x0 * x0 + x1 * x1);
    entries[1] += 0.5 * (x0 * y0 + x1 * y1);
    entries[2] += 0.5 * (x0 + x1);
    entries[3] += 0.5 * (y0 * y0 + y1 * y1);
    entries[4] += 0.5 * (y0 + y1);
    entries[5] += 1.;
  }

  /// metric accumulation \f$M_f = M_i + M_j\f$ when two lines merge
  Line_metric& operator+=(const Line_metric& other)
  {
    for(int i = 0; i < 6; ++i) entries[i] += other.entries[i];
    return *this;
  }

  /// the entry (row, column) of the matrix
  double operator()(int row, int column) const
  {
    static const int index[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    return entries[index[row][column]];
  }
};

/*!
\ingroup PkgPolygonPartitionSimplificationRef

A 2D polygonal partition in line representation (section 3.3.2 of the thesis): the lines
carry explicit coordinates \f$(a, b, c)\f$ in Euclidean normal form \f$a^2 + b^2 = 1\f$,
and each point of the partition is defined by the lines through it (two lines: their
intersection; more lines, after points were merged: the point closest to them in the least-
squares sense). Edges are pieces of lines between two points, so collinear edges share one
line by construction. Cells are the bounded faces of the planar graph made by the edges.

Coordinates are stored in a normalized frame: the input is translated so that the center
of its smallest enclosing rectangle is the origin and scaled so that the rectangle's
half-diagonal is 1 (this makes the thresholds of the simplification scale-free, as in the
thesis). `point()` and `segment()` return input coordinates.

Partitions are built by `kinetic_partition_2()`, `line_partition_from_arrangement_2()` and
`line_partition_from_polygons_2()`, and simplified by `simplify_polygon_partition_2()`.

The predicates and constructions come from the geometric traits: the points, segments and
cells are given in its user-facing kernel, the exact arrangement is built with its
`Exact_constructions_kernel`, and every decision on the points (validity, cells) is taken with
the predicates of its `Exact_predicates_kernel` on their double coordinates.

\tparam GeomTraits a model of `PolygonPartitionSimplificationTraits_2`; a CGAL kernel `K` (any
model of `Kernel`, whose predicates need not be exact) stands for
`Polygon_partition_simplification_traits_2<K>`, so that `Line_partition_2<K>` is the partition
that the functions of the package return for input in `K` by default
*/
template <class GeomTraits>
class Line_partition_2
{
public:
  /// \name Types
  /// @{
#ifdef DOXYGEN_RUNNING
  /// the geometric traits: `GeomTraits`, or `Polygon_partition_simplification_traits_2<GeomTraits>`
  /// when `GeomTraits` is a kernel
  using Geom_traits = unspecified_type;
#else
  using Geom_traits = typename internal::Geom_traits_of<GeomTraits>::type;
#endif
  using FT = typename Geom_traits::FT;                              ///< number type
  using Point_2 = typename Geom_traits::Point_2;                    ///< point type
  using Segment_2 = typename Geom_traits::Segment_2;                ///< segment type
  using Polygon_2 = typename Geom_traits::Polygon_2;                ///< polygon type
  using Polygon_with_holes_2 = typename Geom_traits::Polygon_with_holes_2; ///< cell type
  /// the arrangement built (exactly) from the current edges, by `exact_arrangement()`
  using Exact_arrangement_2 =
    CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<typename Geom_traits::Exact_constructions_kernel>>;

  /// Similarity between input coordinates and the normalized frame:
  /// normalized = (input - center) / scale.
  struct Frame
  {
    double center_x = 0; ///< x of the origin of the normalized frame
    double center_y = 0; ///< y of the origin of the normalized frame
    double scale = 1;    ///< input length of a unit of the normalized frame
  };

  /// A line of the partition.
  struct Line
  {
    std::array<double, 3> coefficients{{1, 0, 0}}; ///< (a, b, c), a^2 + b^2 = 1, normalized frame
    Line_metric metric;                             ///< fidelity metric (normalized frame)
    std::size_t number_of_segments = 0;            ///< segments accumulated in `metric`
    bool is_fixed = false; ///< a side of the bounding rectangle of a kinetic partition: never moved nor merged; when some lines are fixed, only edges on them may bound the unbounded face (see `defect()`)
  };

  /// A point of the partition: the sorted indices of its lines (at least two).
  struct Vertex
  {
    std::vector<std::size_t> lines; ///< sorted line indices
  };

  /// An edge: a piece of a line between two points that both lie on that line.
  struct Edge
  {
    std::size_t line;   ///< supporting line
    std::size_t source; ///< first point
    std::size_t target; ///< second point
  };
  /// @}

  /// \name Creation
  /// @{

  /// an empty partition
  Line_partition_2() = default;

  /// an empty partition with the geometric traits `gt`
  explicit Line_partition_2(const Geom_traits& gt) : traits_(gt) {}

  /// a partition from its parts (no check: call `is_valid()`)
  Line_partition_2(const Frame& frame, std::vector<Line> lines, std::vector<Vertex> vertices,
                   std::vector<Edge> edges, const Geom_traits& gt = Geom_traits())
    : frame_(frame), lines_(std::move(lines)), vertices_(std::move(vertices)),
      edges_(std::move(edges)), traits_(gt)
  {}
  /// @}

  /// \name Access
  /// @{

  /// the geometric traits
  const Geom_traits& geom_traits() const { return traits_; }
  /// the similarity to the normalized frame
  const Frame& frame() const { return frame_; }
  /// the lines
  const std::vector<Line>& lines() const { return lines_; }
  /// the points
  const std::vector<Vertex>& vertices() const { return vertices_; }
  /// the edges
  const std::vector<Edge>& edges() const { return edges_; }
  /// number of lines
  std::size_t number_of_lines() const { return lines_.size(); }
  /// number of points
  std::size_t number_of_vertices() const { return vertices_.size(); }
  /// number of edges
  std::size_t number_of_edges() const { return edges_.size(); }

  /// coordinates of point `v` in the normalized frame
  /// \pre `v < number_of_vertices()`
  std::array<double, 2> normalized_point(std::size_t v) const
  {
    CGAL_precondition(v < vertices_.size());
    return internal::point_of_lines(
      vertices_[v].lines, [this](std::size_t l) -> const internal::Vector_3d& { return lines_[l].coefficients; },
      [this](std::size_t l) { return lines_[l].is_fixed; });
  }

  /// coordinates of point `v` (input frame)
  /// \pre `v < number_of_vertices()`
  Point_2 point(std::size_t v) const
  {
    const std::array<double, 2> p = normalized_point(v);
    return input_point(frame_.center_x + frame_.scale * p[0], frame_.center_y + frame_.scale * p[1]);
  }

  /// edge `e` as a segment (input frame)
  /// \pre `e < number_of_edges()`
  Segment_2 segment(std::size_t e) const
  {
    CGAL_precondition(e < edges_.size());
    return traits_.construct_segment_2_object()(point(edges_[e].source), point(edges_[e].target));
  }

  /// number of pairs of lines meeting at a point whose angle differs from 90 degrees by less
  /// than `tolerance_in_degrees` ("Orthos" of Fig. 3.8 of the thesis, with 1e-4 degree)
  std::size_t number_of_orthogonal_pairs(double tolerance_in_degrees = 1e-4) const
  {
    const double bound = std::sin(tolerance_in_degrees * 3.14159265358979323846 / 180.);
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for(const Vertex& v : vertices_)
      for(std::size_t i = 0; i < v.lines.size(); ++i)
        for(std::size_t j = i + 1; j < v.lines.size(); ++j) {
          const auto& a = lines_[v.lines[i]].coefficients;
          const auto& b = lines_[v.lines[j]].coefficients;
          if(std::abs(a[0] * b[0] + a[1] * b[1]) < bound)
            pairs.emplace_back(v.lines[i], v.lines[j]);
        }
    std::sort(pairs.begin(), pairs.end());
    return std::size_t(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
  }
  /// @}

  /// \name Validity and cells
  /// @{
  /*!
  builds the arrangement of the edges, with exact predicates and constructions on the
  floating-point coordinates of the points (normalized frame); edges with an end at infinity
  or with coinciding ends (possible only in an invalid partition) are left out
  */
  Exact_arrangement_2 exact_arrangement() const
  {
    const auto segments = drawable_segments<typename Geom_traits::Exact_constructions_kernel>();
    Exact_arrangement_2 arrangement;
    CGAL::insert(arrangement, segments.begin(), segments.end());
    return arrangement;
  }

  /*!
  returns an empty string when the partition is valid, otherwise what is wrong with it.
  Valid means: every point has at least two lines and finite, distinct coordinates; every
  edge joins two distinct points of its line; the edges meet only at common endpoints (no
  crossing, overlap, or point inside an edge), which is checked with exact predicates on
  the computed coordinates; every edge separates two different cells; the boundary of
  every cell is made of simple polygons (cells may touch at a corner: only the boundary of the
  unbounded face, which is no cell, may pass twice through a point); when some lines are fixed
  (the sides of the bounding rectangle of a kinetic partition), the unbounded face is bounded
  by edges on fixed lines only, so that the cells tile the rectangle.
  */
  std::string defect() const { return analyze(nullptr); }

  /// `defect().empty()`
  bool is_valid() const { return defect().empty(); }

  /// the edges involved in the defects of the partition (sorted): edges that cross, overlap or
  /// pass through a point, edges at a point at infinity or at coinciding points, edges that
  /// bridge a cell or pinch its boundary; none if the partition is valid
  std::vector<std::size_t> defective_edges() const
  {
    std::vector<std::size_t> result;
    analyze(&result);
    return result;
  }

  /// writes the cells (bounded faces) as polygons with holes in input coordinates; returns
  /// the output iterator.
  /// \pre `is_valid()` (checked when `CGAL_CHECK_EXPENSIVE` is defined: it builds an arrangement)
  template <class OutputIterator>
  OutputIterator cells(OutputIterator out) const
  {
    CGAL_expensive_precondition(is_valid());
    const Planar_arrangement arrangement = planar_arrangement();
    // the orientation is decided on the double coordinates of the vertices, with the predicates
    // of the exact predicates kernel (not with those of the polygon's kernel, which may be inexact)
    std::vector<typename Exact_predicates_kernel::Point_2> ring;
    auto ccb_polygon = [this, &ring](typename Planar_arrangement::Ccb_halfedge_const_circulator start) {
      ring.clear();
      auto h = start;
      do {
        const auto& p = h->target()->point();
        ring.emplace_back(frame_.center_x + frame_.scale * p.x(), frame_.center_y + frame_.scale * p.y());
      } while(++h != start);
      Polygon_2 polygon;
      for(const auto& q : ring) polygon.push_back(input_point(q.x(), q.y()));
      if(CGAL::orientation_2(ring.begin(), ring.end(), Exact_predicates_kernel()) == CGAL::CLOCKWISE)
        polygon.reverse_orientation();
      return polygon;
    };
    for(auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
      if(f->is_unbounded()) continue;
      Polygon_with_holes_2 cell(ccb_polygon(f->outer_ccb()));
      for(auto h = f->holes_begin(); h != f->holes_end(); ++h) {
        Polygon_2 hole = ccb_polygon(*h);
        hole.reverse_orientation();
        cell.add_hole(hole);
      }
      *out++ = cell;
    }
    return out;
  }

  /// number of cells (bounded faces of the planar graph; of the arrangement of the edges if
  /// some of them cross)
  std::size_t number_of_cells() const
  {
    if(has_crossings()) {
      const Exact_arrangement_2 arrangement = exact_arrangement();
      return arrangement.number_of_faces() - arrangement.number_of_unbounded_faces();
    }
    const Planar_arrangement arrangement = planar_arrangement();
    return arrangement.number_of_faces() - arrangement.number_of_unbounded_faces();
  }
  /// @}

private:
  static_assert(internal::Is_geom_traits_checked<Geom_traits>::value, "");

  // The points and edges are exactly representable (double coordinates): once no two edges
  // cross, their arrangement needs exact predicates only (no constructions), which the
  // filtered predicates of the exact predicates kernel (Epick) and the non-caching segment
  // traits give at double speed.
  using Exact_predicates_kernel = typename Geom_traits::Exact_predicates_kernel;
  using Planar_arrangement =
    CGAL::Arrangement_2<CGAL::Arr_non_caching_segment_basic_traits_2<Exact_predicates_kernel>>;

  // the point of the user-facing kernel at (x, y)
  Point_2 input_point(double x, double y) const { return traits_.construct_point_2_object()(FT(x), FT(y)); }

  // The points (normalized frame) and the edges that can be drawn, as pairs of points. An edge
  // of an invalid partition may have an end at infinity or two coinciding ends: it bounds
  // nothing, and is left out (of the arrangements and of the crossing test).
  std::pair<std::vector<std::array<double, 2>>, std::vector<std::array<std::size_t, 2>>> drawable_edges() const
  {
    std::pair<std::vector<std::array<double, 2>>, std::vector<std::array<std::size_t, 2>>> result;
    auto& [points, edges] = result;
    points.resize(vertices_.size());
    for(std::size_t v = 0; v < vertices_.size(); ++v) points[v] = normalized_point(v);
    auto finite = [](const std::array<double, 2>& x) { return std::isfinite(x[0]) && std::isfinite(x[1]); };
    for(const Edge& e : edges_) {
      const auto& a = points[e.source];
      const auto& b = points[e.target];
      if(finite(a) && finite(b) && a != b) edges.push_back({{e.source, e.target}});
    }
    return result;
  }

  // the drawable edges as segments in kernel K (normalized frame)
  template <class K>
  std::vector<typename K::Segment_2> drawable_segments() const
  {
    const auto [points, edges] = drawable_edges();
    std::vector<typename K::Segment_2> result;
    for(const auto& e : edges)
      result.emplace_back(typename K::Point_2(points[e[0]][0], points[e[0]][1]),
                          typename K::Point_2(points[e[1]][0], points[e[1]][1]));
    return result;
  }

  // the arrangement of the edges, which must not cross (`has_crossings()` false)
  Planar_arrangement planar_arrangement() const
  {
    const auto segments = drawable_segments<Exact_predicates_kernel>();
    Planar_arrangement arrangement;
    CGAL::insert_non_intersecting_curves(arrangement, segments.begin(), segments.end());
    return arrangement;
  }

  // A view of the partition for internal::partition_defect()
  struct Validity_view
  {
    const Line_partition_2& p;
    std::size_t number_of_lines() const { return p.lines_.size(); }
    const internal::Vector_3d& coefficients(std::size_t l) const { return p.lines_[l].coefficients; }
    bool is_fixed(std::size_t l) const { return p.lines_[l].is_fixed; }
    std::size_t number_of_vertices() const { return p.vertices_.size(); }
    const std::vector<std::size_t>& vertex_lines(std::size_t v) const { return p.vertices_[v].lines; }
    std::size_t number_of_edges() const { return p.edges_.size(); }
    std::array<std::size_t, 3> edge(std::size_t e) const
    {
      return {{p.edges_[e].line, p.edges_[e].source, p.edges_[e].target}};
    }
  };

  // The first defect (empty if none); with `defective`, collects the edges of all defects.
  std::string analyze(std::vector<std::size_t>* defective) const
  {
    return internal::partition_defect<Geom_traits>(Validity_view{*this}, defective,
                                                   internal::All_crossing_pairs<Exact_predicates_kernel>());
  }

  // do two drawable edges meet elsewhere than at a common end?
  bool has_crossings() const
  {
    const auto [points, edges] = drawable_edges();
    return !internal::crossing_edge_pairs<Exact_predicates_kernel>(points, edges, false,
                                                                   [](const auto&, const auto&) { return true; })
              .empty();
  }

  Frame frame_;
  std::vector<Line> lines_;
  std::vector<Vertex> vertices_;
  std::vector<Edge> edges_;
  Geom_traits traits_;
};

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_2_H
