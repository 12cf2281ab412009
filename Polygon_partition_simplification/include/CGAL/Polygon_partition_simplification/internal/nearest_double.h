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
//
// The exact number types are those of the exact constructions kernel of the geometric traits
// (`Exact_constructions_kernel`): a lazy number (`CGAL::Lazy_exact_nt`, the number type of
// `Exact_predicates_exact_constructions_kernel`) is taken through its exact value, any other
// exact field type (`CGAL::Exact_rational`, `CGAL::Gmpq`) directly.

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Lazy.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// The exact number type behind `NT`: `ET` for a lazy number `Lazy_exact_nt<ET>`, `NT` otherwise.
template <class NT>
struct Exact_number_of { using type = NT; static constexpr bool is_lazy = false; };
template <class ET>
struct Exact_number_of<CGAL::Lazy_exact_nt<ET>> { using type = ET; static constexpr bool is_lazy = true; };

// The exact number type of (the number type of) kernel `EK`.
template <class EK>
using Exact_number = typename Exact_number_of<typename EK::FT>::type;

// The exact value of an object of kernel `EK` (a number, a line): the object itself, or for a
// lazy kernel its exact counterpart (a reference into the lazy object, which must outlive it).
template <class EK, class T>
decltype(auto) exact_value(const T& x)
{
  if constexpr(Exact_number_of<typename EK::FT>::is_lazy) return CGAL::exact(x);
  else return (x); // a reference
}

template <class ET>
double nearest_double_of_exact(const ET& e)
{
  const double d = CGAL::to_double(e); // within one unit in the last place of e
  if(!std::isfinite(d)) return d;      // beyond the doubles (an exact number cannot be made of it)
  const CGAL::Comparison_result side = CGAL::compare(e, ET(d));
  if(side == CGAL::EQUAL) return d;
  const double low = side == CGAL::SMALLER ? std::nextafter(d, -HUGE_VAL) : d;
  const double high = side == CGAL::SMALLER ? d : std::nextafter(d, HUGE_VAL);
  if(!std::isfinite(low) || !std::isfinite(high)) return d;
  const CGAL::Comparison_result c = CGAL::compare(e, (ET(low) + ET(high)) / 2);
  if(c != CGAL::EQUAL) return c == CGAL::SMALLER ? low : high;
  std::uint64_t bits; // adjacent doubles: one has an even significand
  std::memcpy(&bits, &low, sizeof bits);
  return (bits & 1) == 0 ? low : high;
}

// The double nearest to `x`, a number of an exact number type (lazy or not); for a number type
// that is not exact, `CGAL::to_double()`; a double is returned as it is.
template <class NT>
double double_of(const NT& x)
{
  if constexpr(std::is_same<NT, double>::value) return x;
  else if constexpr(Exact_number_of<NT>::is_lazy) {
    const auto& i = x.approx();
    if(i.inf() == i.sup()) return i.inf();
    return nearest_double_of_exact(x.exact());
  } else if constexpr(std::is_same<typename CGAL::Algebraic_structure_traits<NT>::Is_exact, CGAL::Tag_true>::value)
    return nearest_double_of_exact(x);
  else
    return CGAL::to_double(x);
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_NEAREST_DOUBLE_H
