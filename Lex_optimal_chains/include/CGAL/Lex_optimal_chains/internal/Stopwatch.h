// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_STOPWATCH_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_STOPWATCH_H

// Stage timings and the mapping of a stage's progress to the user's callback.

#include <CGAL/Lex_optimal_chains/Cancelled.h>

#include <chrono>
#include <functional>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

class Stopwatch
{
public:
  // seconds since the previous lap (or the construction)
  double lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }
  // seconds since the previous lap (or the construction), without starting a new one
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count(); }
private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// Reports `progress` to the callback, if there is one; throws Cancelled when it returns false.
inline void report_progress(const std::function<bool(double)>& callback, double progress)
{
  if(callback && !callback(progress)) throw Cancelled();
}

// Maps the progress of one stage to [from, to] of the user's callback.
struct Stage_progress
{
  const std::function<bool(double)>* callback;
  double from, to;
  bool operator()(double x) const { return !*callback || (*callback)(from + (to - from) * x); }
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_STOPWATCH_H
