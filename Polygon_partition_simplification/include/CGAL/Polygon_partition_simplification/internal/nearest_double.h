// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_NEAREST_DOUBLE_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_NEAREST_DOUBLE_H

// The double nearest to an exact number (ties to even). The conversion of an exact number
// rounds as its number type does (GMP's mpq truncates, Boost's rational does not), and
// `CGAL::to_double()` of a lazy number returns the middle of its interval, which depends on
// whether its exact value was needed before. What the package computes in double from exact
// values must depend on neither, so that the same input gives the same simplification in every
// build.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

using Exact_kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Exact_number = Exact_kernel::FT::ET; // the exact number type behind the lazy one

inline double double_of(const Exact_number& e)
{
  const double d = CGAL::to_double(e); // within one unit in the last place of e
  if(!std::isfinite(d)) return d;      // beyond the doubles (an exact number cannot be made of it)
  const CGAL::Comparison_result side = CGAL::compare(e, Exact_number(d));
  if(side == CGAL::EQUAL) return d;
  const double low = side == CGAL::SMALLER ? std::nextafter(d, -HUGE_VAL) : d;
  const double high = side == CGAL::SMALLER ? d : std::nextafter(d, HUGE_VAL);
  if(!std::isfinite(low) || !std::isfinite(high)) return d;
  const CGAL::Comparison_result c = CGAL::compare(e, (Exact_number(low) + Exact_number(high)) / 2);
  if(c != CGAL::EQUAL) return c == CGAL::SMALLER ? low : high;
  std::uint64_t bits; // adjacent doubles: one has an even significand
  std::memcpy(&bits, &low, sizeof bits);
  return (bits & 1) == 0 ? low : high;
}

inline double double_of(const Exact_kernel::FT& x)
{
  const auto& i = x.approx();
  if(i.inf() == i.sup()) return i.inf();
  return double_of(x.exact());
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_NEAREST_DOUBLE_H
