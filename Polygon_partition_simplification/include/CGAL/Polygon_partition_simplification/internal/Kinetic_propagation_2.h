// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_KINETIC_PROPAGATION_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_KINETIC_PROPAGATION_2_H

// The kinetic framework of section 3.2.2: every segment grows from both ends at unit speed,
// so a point I of its supporting line is reached at time T_S(I) = d(I, S). A growing end
// (a "ray") that reaches the current extent of another segment stops there if it arrives
// last (the other segment covers I strictly earlier; equal times: the ray with the larger
// index stops); it crosses instead while it has crossings left, or when its next
// intersection is closer than the crossing distance. Rays stop at the bounding rectangle.
// An end that lies on another segment stops there at time 0 (two segments sharing an endpoint
// stop each other): the corners of a footprint stay corners.
//
// Exactness: intersection points and arrival times are exact (`EK`, the exact constructions
// kernel of the geometric traits, lazy by default); events are
// processed in exact time order (candidates are found in double precision, and candidates
// of a ray whose double parameters are close are ordered exactly). The result is the final
// extent of every segment.
//
// Events that cannot stop a ray are not queued: a segment S_j can cover the point I where a
// ray meets its line only if it gets there first, so only if d(I, S_j) <= T_ray(I), whether
// S_j is stopped before or not. A candidate is dropped when d(I, S_j) exceeds T_ray(I) by more
// than a bound on the rounding errors of the double computation (see `cannot_cover()`), so
// the extents are the same as with every intersection of supporting lines processed, and most
// rays, which cross many supporting lines far from their segments, make a few exact events
// instead of hundreds. Such a segment is also within 2 T_ray(I) of the ray's origin, so the
// candidates are searched in a grid of the segments, by increasing distance from the origin
// (see `refill()`), instead of among all segments.

#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Polygon_partition_simplification/internal/Segment_grid_2.h>
#include <CGAL/Polygon_partition_simplification/internal/nearest_double.h>

#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <queue>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

template <class ExactKernel>
class Kinetic_propagation_2
{
public:
  using EK = ExactKernel;
  using FT = typename EK::FT;
  using Point = typename EK::Point_2;
  using Segment = typename EK::Segment_2;
  using Line = typename EK::Line_2;
  using Vector = typename EK::Vector_2;
  using Direction = typename EK::Direction_2;

  struct Statistics
  {
    std::size_t events = 0;     // candidate intersections examined
    std::size_t crossings = 0;  // times a ray crossed a segment that would have stopped it
    std::size_t refills = 0;    // candidate scans
  };

  // `segments`: exact, non-degenerate, pairwise distinct; `box`: the 4 corners of a convex
  // rectangle, counterclockwise, containing every segment strictly inside.
  Kinetic_propagation_2(const std::vector<Segment>& segments, const std::array<Point, 4>& box,
                        std::size_t maximum_crossings, double crossing_distance)
    : segments_(segments), maximum_crossings_(maximum_crossings),
      crossing_distance_(crossing_distance)
  {
    const std::size_t n = segments.size();
    lines_.reserve(n);
    double_segments_.reserve(n);
    for(const auto& s : segments) {
      lines_.emplace_back(s.source(), s.target());
      // nearest doubles: the doubles of the propagation (candidate searches, crossing
      // distances) must not depend on which exact values were evaluated before
      double_segments_.push_back({double_of(s.source().x()), double_of(s.source().y()),
                                  double_of(s.target().x()), double_of(s.target().y())});
    }
    {
      std::array<double, 2> low{{double_of(box[0].x()), double_of(box[0].y())}}, high = low;
      for(const Point& p : box)
        for(int c = 0; c < 2; ++c) {
          low[c] = std::min(low[c], double_of(p[c]));
          high[c] = std::max(high[c], double_of(p[c]));
        }
      grid_ = Segment_grid_2(double_segments_, low, high);
      visited_.assign(n, 0);
    }
    // parallel classes: segments sorted by their exact direction (up to orientation), so
    // that testing two segments for parallelism is comparing two integers
    {
      std::vector<Direction> directions;
      directions.reserve(n);
      for(const auto& s : segments) {
        Vector d = s.target() - s.source();
        const CGAL::Sign sx = CGAL::sign(d.x());
        if(sx == CGAL::NEGATIVE || (sx == CGAL::ZERO && CGAL::sign(d.y()) == CGAL::NEGATIVE)) d = -d;
        directions.emplace_back(d);
      }
      std::vector<std::uint32_t> order(n);
      for(std::uint32_t i = 0; i < n; ++i) order[i] = i;
      std::sort(order.begin(), order.end(),
                [&](std::uint32_t x, std::uint32_t y) { return directions[x] < directions[y]; });
      parallel_class_.assign(n, 0);
      for(std::size_t k = 1; k < n; ++k)
        parallel_class_[order[k]] = parallel_class_[order[k - 1]] +
                                    (directions[order[k - 1]] == directions[order[k]] ? 0 : 1);
    }
    for(int k = 0; k < 4; ++k) box_[k] = Line(box[k], box[(k + 1) % 4]);
    rays_.resize(2 * n);
    for(std::size_t r = 0; r < rays_.size(); ++r) {
      Ray& ray = rays_[r];
      const auto& s = segments[r / 2];
      ray.origin = (r % 2 == 1) ? s.target() : s.source();
      ray.direction = (r % 2 == 1) ? s.target() - s.source() : s.source() - s.target();
      const Ray_in_double d = in_double(r);
      ray.direction_length = std::hypot(d.vx, d.vy);
      // exit parameter through the rectangle: the smallest positive one over its sides
      bool found = false;
      for(int k = 0; k < 4; ++k) {
        const Line& side = box_[k];
        const FT den = side.a() * ray.direction.x() + side.b() * ray.direction.y();
        // the inside is on the left of a counterclockwise side: leaving it means den < 0
        if(CGAL::sign(den) != CGAL::NEGATIVE) continue;
        const FT t = -(side.a() * ray.origin.x() + side.b() * ray.origin.y() + side.c()) / den;
        if(!found || t < ray.box_parameter) { ray.box_parameter = t; ray.box_side = k; found = true; }
      }
      CGAL_assertion(found);
      { // in double, from the doubles of the ray and of the side's corners
        const double ax = double_of(box[ray.box_side].x()), ay = double_of(box[ray.box_side].y());
        const double bx = double_of(box[(ray.box_side + 1) % 4].x()), by = double_of(box[(ray.box_side + 1) % 4].y());
        const double nx = ay - by, ny = bx - ax; // a normal of the side
        ray.box_parameter_double = (nx * (ax - d.ox) + ny * (ay - d.oy)) / (nx * d.vx + ny * d.vy);
      }
    }
  }

  std::size_t number_of_rays() const { return rays_.size(); }
  // did ray r stop at its origin, at time 0 (and what is its origin)?
  bool stopped_at_origin(std::size_t r) const
  {
    return rays_[r].stopped && CGAL::sign(rays_[r].stop_parameter) == CGAL::ZERO;
  }
  const Point& origin(std::size_t r) const { return rays_[r].origin; }
  // the direction ray r grows in: away from its segment
  const Vector& direction(std::size_t r) const { return rays_[r].direction; }

  void run()
  {
    for(std::size_t r = 0; r < rays_.size(); ++r) {
      refill(r);
      push_next(r);
    }
    while(!queue_.empty()) {
      const Queued q = queue_.top();
      queue_.pop();
      process(q.ray);
    }
  }

  // final extent of segment i
  Segment extent(std::size_t i) const
  {
    return Segment(rays_[2 * i].stop, rays_[2 * i + 1].stop);
  }

  const Statistics& statistics() const { return statistics_; }

private:
  static constexpr std::uint32_t box_candidate = std::numeric_limits<std::uint32_t>::max();

  struct Candidate
  {
    double parameter;     // along the ray direction, in units of its length
    std::uint32_t segment; // or box_candidate
    bool operator<(const Candidate& o) const
    {
      return parameter < o.parameter || (parameter == o.parameter && segment < o.segment);
    }
  };

  struct Ray
  {
    Point origin;
    Vector direction;
    double direction_length = 0;
    FT box_parameter;
    int box_side = 0; // the side of the rectangle at `box_parameter`
    double box_parameter_double = 0;
    std::vector<Candidate> candidates; // current batch, sorted, from `cursor` on
    // their exact parameters, once computed: a cluster of nearly equal parameters is searched
    // for its exact minimum at every event of the ray (n lines through one point: n events of
    // n candidates each), and each new exact parameter is a new expression to evaluate
    std::vector<std::optional<FT>> exact_parameters;
    std::size_t cursor = 0;
    Candidate last{-1., 0};           // last candidate taken (double order)
    bool box_listed = false;
    // exact data of the current head candidate
    FT head_parameter;
    bool stopped = false;
    Point stop;
    FT stop_parameter; // stop = origin + stop_parameter * direction
    std::size_t crossings = 0;
  };

  struct Queued
  {
    FT time2; // squared arrival time at the head candidate
    std::uint32_t ray;
  };
  struct Later
  {
    bool operator()(const Queued& x, const Queued& y) const
    {
      const CGAL::Comparison_result c = CGAL::compare(x.time2, y.time2);
      if(c != CGAL::EQUAL) return c == CGAL::LARGER;
      return x.ray > y.ray;
    }
  };

  FT exact_parameter(const Ray& ray, std::uint32_t segment) const
  {
    if(segment == box_candidate) return ray.box_parameter;
    const Line& l = lines_[segment];
    const FT den = l.a() * ray.direction.x() + l.b() * ray.direction.y();
    return -(l.a() * ray.origin.x() + l.b() * ray.origin.y() + l.c()) / den;
  }

  // The next batch of candidates of ray r beyond `last`: intersections with supporting lines
  // whose segment may get there first. A segment S_j that covers the point O + t V no later
  // than the ray is within t |V| of it, so within 2 t |V| of the origin O: the segments are
  // visited ring of grid cells by ring of cells around O, and once every segment closer to O
  // than rho is visited, every candidate with 2 t |V| < rho is known. The batch is the known
  // candidates below such a cut (with slack for rounding and for the tolerance with which
  // `push_next()` groups nearly equal parameters, so that no group is split between batches).
  void refill(std::size_t r)
  {
    ++statistics_.refills;
    Ray& ray = rays_[r];
    const std::size_t own = r / 2;
    const Ray_in_double d = in_double(r);
    if(++stamp_ == 0) { std::fill(visited_.begin(), visited_.end(), 0); stamp_ = 1; }
    std::vector<Candidate> found;
    double smallest = std::numeric_limits<double>::infinity();
    auto visit = [&](std::uint32_t j) {
      if(visited_[j] == stamp_) return;
      visited_[j] = stamp_;
      if(j == own) return;
      double t, den;
      if(!line_candidate(d, j, t, den)) return;
      const Candidate c{t, j};
      if(!(ray.last < c) || cannot_cover(d, j, t, den)) return;
      found.push_back(c);
      smallest = std::min(smallest, t);
    };
    if(!ray.box_listed) smallest = ray.box_parameter_double;
    const int x = grid_.column(d.ox), y = grid_.row(d.oy);
    double cut = std::numeric_limits<double>::infinity();
    for(int k = 0;; ++k) {
      grid_.for_each_in_ring(x, y, k, visit);
      if(grid_.covers_all(x, y, k)) { cut = std::numeric_limits<double>::infinity(); break; }
      const double known = std::max(0., (k - 1) * grid_.cell_size() / (2 * ray.direction_length));
      cut = known * (1 - 1e-6) - 10 * cluster_tolerance(known);
      if(smallest <= cut) break;
    }
    found.erase(std::remove_if(found.begin(), found.end(), [&](const Candidate& c) { return c.parameter > cut; }),
                found.end());
    if(!ray.box_listed && ray.box_parameter_double <= cut) {
      found.push_back({ray.box_parameter_double, box_candidate});
      ray.box_listed = true;
    }
    std::sort(found.begin(), found.end());
    ray.candidates = std::move(found);
    ray.exact_parameters.assign(ray.candidates.size(), std::nullopt);
    ray.cursor = 0;
  }

  // A ray in double precision: origin O, direction V (of length |V|), and the largest parameter
  // of a candidate (the box's, with slack).
  struct Ray_in_double
  {
    double ox, oy, vx, vy, length, limit;
  };
  // from the nearest doubles of the segment's endpoints
  Ray_in_double in_double(std::size_t r) const
  {
    const auto& c = double_segments_[r / 2];
    const bool at_target = r % 2 == 1; // the ray leaves the target, away from the source
    const double ox = at_target ? c[2] : c[0], oy = at_target ? c[3] : c[1];
    const double vx = at_target ? c[2] - c[0] : c[0] - c[2], vy = at_target ? c[3] - c[1] : c[1] - c[3];
    return {ox, oy, vx, vy, rays_[r].direction_length, rays_[r].box_parameter_double * (1 + 1e-9) + 1e-12};
  }

  // Double parameters closer than this to p are ordered exactly (push_next() groups them).
  static double cluster_tolerance(double p) { return 1e-9 * std::max(1., std::abs(p)); }

  // Does the ray meet the line of segment j ahead of its origin and before the box? Then t is
  // the parameter of the point O + t V and den = (a_j, b_j) . V (0 when they are parallel in
  // double precision, and then it does not). Computed from O - A, A the source of S_j, so
  // that the rounding errors are relative to the distances involved, not to the coordinates
  // (projected coordinates are millions of meters for segments of centimeters).
  bool line_candidate(const Ray_in_double& d, std::size_t j, double& t, double& den) const
  {
    const auto& s = double_segments_[j];
    const double a = s[1] - s[3], b = s[2] - s[0];
    den = a * d.vx + b * d.vy;
    if(den == 0) return false;
    t = -(a * (d.ox - s[0]) + b * (d.oy - s[1])) / den;
    return t > -1e-9 && t <= d.limit;
  }

  // Certainly (in spite of rounding) true when segment j does not reach the point I = O + t V
  // of the ray before the ray: d(I, S_j) > t |V|, with t and den from line_candidate(). Error
  // bound: with D = |O - A| + |S_j| + t |V| (A the source of S_j), t |V| and the position of I
  // relative to A are off by a few units in the last place of D / sin(theta), theta the angle
  // between the ray and S_j; the margin is 1e-9 D / sin(theta), a million times more. Nearly
  // parallel lines (sin(theta) < 1e-6) are always kept.
  bool cannot_cover(const Ray_in_double& d, std::size_t j, double t, double den) const
  {
    const auto& s = double_segments_[j];
    const double wx = s[2] - s[0], wy = s[3] - s[1];
    const double w_length = std::sqrt(wx * wx + wy * wy);
    const double sin_theta = std::abs(den) / (d.length * w_length);
    if(!(sin_theta > 1e-6)) return false;
    const double dx = d.ox - s[0], dy = d.oy - s[1];                // O - A
    const double ix = dx + t * d.vx, iy = dy + t * d.vy;            // I - A
    const double along = (ix * wx + iy * wy) / w_length;            // from A, along S_j
    const double beyond = std::max(-along, along - w_length);      // d(I, S_j)
    const double reach = std::abs(t) * d.length;                    // T_ray(I)
    const double margin = 1e-9 * (std::abs(dx) + std::abs(dy) + w_length + reach) / sin_theta;
    return beyond > reach + margin;
  }

  // Puts the exact minimum of the current cluster at the cursor and queues the ray.
  // Candidates on a line parallel to the ray (exactly) are skipped.
  void push_next(std::size_t r)
  {
    Ray& ray = rays_[r];
    for(;;) {
      if(ray.cursor == ray.candidates.size()) {
        if(ray.box_listed && ray.candidates.empty()) return; // cannot happen: the box stops it
        refill(r);
        if(ray.candidates.empty()) return;
      }
      auto& c = ray.candidates;
      const double tolerance = cluster_tolerance(c[ray.cursor].parameter);
      std::size_t end = ray.cursor + 1;
      while(end < c.size() && c[end].parameter <= c[ray.cursor].parameter + tolerance) ++end;
      // exact selection of the smallest parameter in [cursor, end)
      std::size_t best = c.size();
      FT best_parameter;
      for(std::size_t k = ray.cursor; k < end; ++k) {
        if(c[k].segment != box_candidate && is_parallel(r, c[k].segment)) continue;
        if(!ray.exact_parameters[k]) ray.exact_parameters[k] = exact_parameter(ray, c[k].segment);
        const FT& t = *ray.exact_parameters[k];
        if(best == c.size()) { best = k; best_parameter = t; continue; }
        const CGAL::Comparison_result cmp = CGAL::compare(t, best_parameter);
        if(cmp == CGAL::SMALLER ||
           (cmp == CGAL::EQUAL && c[k].segment < c[best].segment)) { best = k; best_parameter = t; }
      }
      if(best == c.size()) { // only parallel lines in the cluster
        ray.last = c[end - 1];
        ray.cursor = end;
        continue;
      }
      std::swap(c[ray.cursor], c[best]);
      std::swap(ray.exact_parameters[ray.cursor], ray.exact_parameters[best]);
      if(CGAL::sign(best_parameter) == CGAL::NEGATIVE) { // behind the origin: skip
        ray.last = std::max(ray.last, c[ray.cursor]);
        ++ray.cursor;
        continue;
      }
      ray.head_parameter = best_parameter;
      queue_.push({best_parameter * best_parameter * ray.direction.squared_length(),
                   std::uint32_t(r)});
      return;
    }
  }

  // The point where ray r meets the line of `segment` (or the rectangle), which is
  // origin + head_parameter * direction, built as the intersection of two lines: one
  // construction in the lazy kernel, whose exact evaluation (by the arrangement of the extents,
  // at every T-junction) is one step from the exact lines, rather than a chain of a dozen
  // arithmetic operations, each evaluated and synchronized on its own.
  Point meeting_point(std::size_t r, std::uint32_t segment) const
  {
    const Line& other = segment == box_candidate ? box_[rays_[r].box_side] : lines_[segment];
    const auto x = CGAL::intersection(lines_[r / 2], other);
    const Point* p = get_if<Point>(x);
    CGAL_assertion(p != nullptr); // parallel candidates are skipped
    return *p;
  }

  bool is_parallel(std::size_t ray, std::uint32_t segment) const
  {
    return parallel_class_[segment] == parallel_class_[ray / 2];
  }

  // does segment j cover point I (exact) at the time ray r reaches it (squared time t2)?
  bool covers(std::size_t j, const Point& I, const FT& t2, std::size_t r) const
  {
    const auto& s = segments_[j];
    const Vector d = s.target() - s.source();
    const bool before_source = CGAL::sign((I - s.source()) * d) == CGAL::NEGATIVE;
    const bool after_target = CGAL::sign((I - s.target()) * d) == CGAL::POSITIVE;
    if(!before_source && !after_target) return true; // on the initial segment
    const std::size_t rj = 2 * j + (after_target ? 1 : 0);
    const Ray& other = rays_[rj];
    const FT tj2 = CGAL::squared_distance(I, other.origin);
    if(other.stopped &&
       CGAL::compare(other.stop_parameter * other.stop_parameter * other.direction.squared_length(),
                     tj2) == CGAL::SMALLER)
      return false; // stopped before reaching I
    const CGAL::Comparison_result c = CGAL::compare(tj2, t2);
    if(c != CGAL::EQUAL) return c == CGAL::SMALLER;
    return rj < r; // simultaneous arrival: the smaller ray index goes on
  }

  void process(std::size_t r)
  {
    Ray& ray = rays_[r];
    const Candidate head = ray.candidates[ray.cursor];
    ray.last = std::max(ray.last, head);
    ++ray.cursor;
    ++statistics_.events;
    const Point I = meeting_point(r, head.segment);
    bool stop = head.segment == box_candidate;
    if(!stop) {
      const FT t2 = ray.head_parameter * ray.head_parameter * ray.direction.squared_length();
      if(covers(head.segment, I, t2, r)) {
        stop = true;
        if(ray.crossings < maximum_crossings_) { stop = false; ++ray.crossings; }
        else if(crossing_distance_ > 0 && next_is_close(ray, head)) stop = false;
        if(!stop) ++statistics_.crossings;
      }
    }
    if(stop) {
      ray.stopped = true;
      ray.stop = I;
      ray.stop_parameter = ray.head_parameter;
      ray.candidates.clear();
      ray.candidates.shrink_to_fit();
      ray.exact_parameters.clear();
      ray.exact_parameters.shrink_to_fit();
      return;
    }
    push_next(r);
  }

  // Is the next intersection along the ray after its head (with a supporting line, wherever
  // its segment is, or with the box) closer than the crossing distance? The candidates of the
  // ray are only those that may stop it, so the supporting lines are scanned again. Another
  // line through the head's point (its double parameter within the tolerance of push_next()
  // of the head's, on either side) is at distance 0.
  bool next_is_close(const Ray& ray, const Candidate& head) const
  {
    const std::size_t own = std::size_t(&ray - rays_.data()) / 2;
    const Ray_in_double d = in_double(std::size_t(&ray - rays_.data()));
    const double from = head.parameter - cluster_tolerance(head.parameter);
    double next = ray.box_parameter_double;
    for(std::size_t j = 0; j < double_segments_.size(); ++j) {
      double t, den;
      if(j != own && j != head.segment && line_candidate(d, j, t, den) && t >= from) next = std::min(next, t);
    }
    return (std::max(next, head.parameter) - head.parameter) * ray.direction_length < crossing_distance_;
  }

  const std::vector<Segment>& segments_;
  std::vector<Line> lines_;
  std::vector<std::array<double, 4>> double_segments_; // endpoints, rounded to double
  Segment_grid_2 grid_{{}, {{0, 0}}, {{1, 1}}};        // the segments, by position
  std::vector<std::uint32_t> visited_;                 // stamp of the last refill that saw a segment
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> parallel_class_; // equal for parallel segments
  std::array<Line, 4> box_;
  std::vector<Ray> rays_;
  std::priority_queue<Queued, std::vector<Queued>, Later> queue_;
  std::size_t maximum_crossings_;
  double crossing_distance_;
  Statistics statistics_;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_KINETIC_PROPAGATION_2_H
