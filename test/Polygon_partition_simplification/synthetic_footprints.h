// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Synthetic building footprints turned into what a segment detector gives: every wall is cut
// into 1 to 4 pieces with gaps, its endpoints moved by Gaussian noise, some pieces doubled by
// a nearly collinear copy, plus roof ridges and short clutter segments inside. Used by the
// tests, the benchmark and to make the example data (deterministic for a given seed).

#ifndef POLYGON_PARTITION_SIMPLIFICATION_SYNTHETIC_FOOTPRINTS_H
#define POLYGON_PARTITION_SIMPLIFICATION_SYNTHETIC_FOOTPRINTS_H

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace synthetic {

using Point = std::array<double, 2>;
using Segment = std::array<double, 4>;

struct Footprints
{
  std::vector<std::vector<Point>> polygons; // ground truth, counterclockwise
  std::vector<Segment> segments;            // noisy, fragmented walls, ridges and clutter
};

// One building shape in a unit cell, rectilinear or not.
inline std::vector<Point> shape(int kind)
{
  switch(kind % 5) {
  case 0: return {{0, 0}, {20, 0}, {20, 10}, {12, 10}, {12, 18}, {0, 18}};                // L
  case 1: return {{0, 0}, {24, 0}, {24, 16}, {16, 16}, {16, 8}, {8, 8}, {8, 16}, {0, 16}}; // U
  case 2: return {{0, 0}, {18, 0}, {18, 14}, {0, 14}};                                     // rectangle
  case 3: return {{0, 0}, {22, 0}, {16, 14}, {4, 14}};                                     // trapezoid
  default: return {{0, 0}, {8, -6}, {20, 0}, {20, 12}, {8, 16}, {0, 12}};                  // hexagon
  }
}

// `count` buildings on a grid with 40 m spacing, random rotations, noise sigma (m).
inline Footprints make_footprints(std::size_t count, double sigma, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, sigma);
  std::uniform_real_distribution<double> uniform(0, 1);
  Footprints result;
  const std::size_t columns = std::size_t(std::ceil(std::sqrt(double(count))));
  for(std::size_t b = 0; b < count; ++b) {
    const double angle = 2 * 3.14159265358979323846 * uniform(rng);
    const double ox = 40. * double(b % columns), oy = 40. * double(b / columns);
    auto place = [&](const Point& p) {
      const double x = p[0] - 10, y = p[1] - 8;
      return Point{ox + std::cos(angle) * x - std::sin(angle) * y, oy + std::sin(angle) * x + std::cos(angle) * y};
    };
    std::vector<Point> polygon;
    for(const Point& p : shape(int(b))) polygon.push_back(place(p));
    const std::size_t n = polygon.size();
    for(std::size_t i = 0; i < n; ++i) {
      const Point& a = polygon[i];
      const Point& c = polygon[(i + 1) % n];
      const int pieces = 1 + int(rng() % 4);
      for(int k = 0; k < pieces; ++k) {
        const double t0 = (k + 0.04 * uniform(rng)) / pieces, t1 = (k + 1 - 0.04 * uniform(rng)) / pieces;
        Segment s{a[0] + (c[0] - a[0]) * t0 + noise(rng), a[1] + (c[1] - a[1]) * t0 + noise(rng),
                  a[0] + (c[0] - a[0]) * t1 + noise(rng), a[1] + (c[1] - a[1]) * t1 + noise(rng)};
        result.segments.push_back(s);
        if(uniform(rng) < 0.2) // a nearly collinear double, shifted along the wall
          result.segments.push_back({s[0] + 0.3 * (s[2] - s[0]) + noise(rng), s[1] + 0.3 * (s[3] - s[1]) + noise(rng),
                                     s[2] + 0.1 * (s[2] - s[0]) + noise(rng), s[3] + 0.1 * (s[3] - s[1]) + noise(rng)});
      }
    }
    // a ridge across the building and two short clutter segments (chimneys, dormers)
    const Point r0 = place({2, 5}), r1 = place({16, 5});
    result.segments.push_back({r0[0] + noise(rng), r0[1] + noise(rng), r1[0] + noise(rng), r1[1] + noise(rng)});
    for(int k = 0; k < 2; ++k) {
      const Point c = place({4 + 10 * uniform(rng), 2 + 6 * uniform(rng)});
      const double d = 1 + uniform(rng), t = angle + 0.2 * noise(rng);
      result.segments.push_back({c[0], c[1], c[0] + d * std::cos(t), c[1] + d * std::sin(t)});
    }
    result.polygons.push_back(polygon);
  }
  return result;
}

} // namespace synthetic

#endif // POLYGON_PARTITION_SIMPLIFICATION_SYNTHETIC_FOOTPRINTS_H
