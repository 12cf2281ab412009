// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What several test programs of the package share: the checks of an expected input error and
// of a cancellation, and a synthetic terrain.

#ifndef CGAL_LEX_OPTIMAL_CHAINS_TEST_SUPPORT_H
#define CGAL_LEX_OPTIMAL_CHAINS_TEST_SUPPORT_H

#include <CGAL/Random.h>
#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <cassert>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <type_traits>
#include <vector>

// Runs f, which must throw Lex_optimal_chains::Input_error with the given code; prints its message.
template <class F>
void expect_error(CGAL::Lex_optimal_chains::Input_error_code code, const F& f)
{
  try {
    f();
  } catch(const CGAL::Lex_optimal_chains::Input_error& e) {
    std::cout << "  expected error: " << e.what() << std::endl;
    assert(e.code() == code);
    return;
  }
  assert(!"an Input_error was expected");
}

// A cancellation is not an input error: a program that reports the input errors tells it apart.
static_assert(std::is_base_of<std::runtime_error, CGAL::Lex_optimal_chains::Cancelled>::value &&
                !std::is_base_of<std::invalid_argument, CGAL::Lex_optimal_chains::Cancelled>::value,
              "Cancelled is a std::runtime_error, not an Input_error");

// Runs f, which must throw Lex_optimal_chains::Cancelled (and nothing else); prints its message.
template <class F>
void expect_cancelled(const F& f)
{
  try {
    f();
  } catch(const CGAL::Lex_optimal_chains::Input_error& e) {
    std::cout << "  unexpected error: " << e.what() << std::endl;
    assert(!"a cancellation was expected, not an Input_error");
    return;
  } catch(const CGAL::Lex_optimal_chains::Cancelled& e) {
    std::cout << "  expected cancellation: " << e.what() << std::endl;
    return;
  }
  assert(!"a cancellation was expected");
}

// n points of the height field sin(0.7x) cos(0.5y) + 0.03x over [0,10]^2, with uniform noise
// in [-noise, noise] on the height.
template <class Point>
std::vector<Point> height_field(CGAL::Random& rng, int n, double noise)
{
  std::vector<Point> points;
  for(int i = 0; i < n; ++i) {
    const double x = rng.get_double(0, 10), y = rng.get_double(0, 10);
    points.emplace_back(x, y, std::sin(0.7 * x) * std::cos(0.5 * y) + 0.3 * x / 10 + rng.get_double(-noise, noise));
  }
  return points;
}

#endif // CGAL_LEX_OPTIMAL_CHAINS_TEST_SUPPORT_H
