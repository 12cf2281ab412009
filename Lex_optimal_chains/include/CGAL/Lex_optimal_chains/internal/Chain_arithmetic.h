// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_ARITHMETIC_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_ARITHMETIC_H

// The two coefficient groups of the chains, as policies with the same interface:
// `Value`, `zero()`, `add(a, b)`, `negate(a)`, `from_integer(k)`, `to_integer(a)`.

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <cstdint>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Z/2Z: a bit; addition is exclusive or, every element is its own opposite.
struct Z2_arithmetic
{
  using Value = std::uint8_t;
  static Value zero() { return 0; }
  static Value add(Value a, Value b) { return Value(a ^ b); }
  static Value negate(Value a) { return a; }
  static Value from_integer(std::int64_t k) { return Value(k & 1); }
  static std::int64_t to_integer(Value a) { return a; }
};

// The integers, standing for Q (only additions and subtractions are made, so an integral
// input stays integral); overflow is detected.
struct Integer_arithmetic
{
  using Value = std::int64_t;
  static Value zero() { return 0; }
  static Value add(Value a, Value b)
  {
    if((b > 0 && a > INT64_MAX - b) || (b < 0 && a < INT64_MIN - b)) overflow();
    return a + b;
  }
  static Value negate(Value a)
  {
    if(a == INT64_MIN) overflow();
    return -a;
  }
  static Value from_integer(std::int64_t k) { return k; }
  static std::int64_t to_integer(Value a) { return a; }

private:
  [[noreturn]] static void overflow()
  {
    throw Input_error(Input_error_code::TOO_LARGE, "a chain coefficient overflows 64-bit integers");
  }
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_ARITHMETIC_H
