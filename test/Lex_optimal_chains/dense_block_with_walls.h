// A synthetic dense scan with walls, with known structure: shared by the tests of the tiled
// reconstruction and its benchmark.
#ifndef LEX_OPTIMAL_CHAINS_TEST_DENSE_BLOCK_WITH_WALLS_H
#define LEX_OPTIMAL_CHAINS_TEST_DENSE_BLOCK_WITH_WALLS_H

#include <CGAL/Random.h>

#include <cmath>
#include <cstddef>
#include <vector>

// A dense scan of a block of side `side`: `density` points per square metre from above on
// gentle ground and on two flat-roofed buildings 4 and 7 high, and as many per square metre of
// their walls (a mobile or oblique scan sees them), every height with uniform noise in
// [-noise, noise]. Where a seam crosses a wall, its points are millimetres apart in xy and
// centimetres to metres apart in z.
template <class Point>
std::vector<Point> dense_block_with_walls(double side, double density, double noise, unsigned seed)
{
  CGAL::Random rng(seed);
  struct Box { double x0, y0, x1, y1, h; };
  const std::vector<Box> boxes{{0.2 * side, 0.15 * side, 0.55 * side, 0.5 * side, 4}, {0.6 * side, 0.55 * side, 0.9 * side, 0.85 * side, 7}};
  auto ground = [](double x, double y) { return 0.3 * std::sin(0.4 * x) * std::cos(0.3 * y) + 0.01 * x; };
  std::vector<Point> points;
  const std::size_t from_above = std::size_t(density * side * side);
  for(std::size_t i = 0; i < from_above; ++i) {
    const double x = rng.get_double(0, side), y = rng.get_double(0, side);
    double z = ground(x, y);
    for(const Box& b : boxes)
      if(x > b.x0 && x < b.x1 && y > b.y0 && y < b.y1) z = ground(b.x0, b.y0) + b.h;
    points.emplace_back(x, y, z + rng.get_double(-noise, noise));
  }
  for(const Box& b : boxes) { // the four walls, from the ground to the roof
    const double base = ground(b.x0, b.y0);
    const std::size_t per_wall = std::size_t(density * (b.x1 - b.x0) * b.h);
    for(int wall = 0; wall < 4; ++wall)
      for(std::size_t i = 0; i < per_wall; ++i) {
        const double t = rng.get_double(0, 1), z = base + rng.get_double(0, b.h) + rng.get_double(-noise, noise);
        const double x = wall < 2 ? b.x0 + t * (b.x1 - b.x0) : (wall == 2 ? b.x0 : b.x1);
        const double y = wall < 2 ? (wall == 0 ? b.y0 : b.y1) : b.y0 + t * (b.y1 - b.y0);
        points.emplace_back(x, y, z);
      }
  }
  return points;
}

#endif // LEX_OPTIMAL_CHAINS_TEST_DENSE_BLOCK_WITH_WALLS_H
