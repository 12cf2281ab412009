// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_ARITHMETIC_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_ARITHMETIC_H

// The coefficient groups of the chains, as policies with the same interface:
// `Value`, `has_signs` (false: a value and its opposite are equal), `zero()`, `add(a, b)`,
// `negate(a)`, `from_integer(k)`, `to_integer(a)`.

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <cstdint>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Z/2Z: a bit; addition is exclusive or, every element is its own opposite.
struct Z2_arithmetic
{
  using Value = std::uint8_t;
  static constexpr bool has_signs = false; // the orientation of a simplex is irrelevant
  static Value zero() { return 0; }
  static Value add(Value a, Value b) { return Value(a ^ b); }
  static Value negate(Value a) { return a; }
  static Value from_integer(std::int64_t k) { return Value(k & 1); }
  static std::int64_t to_integer(Value a) { return a; }
};

// Z/2Z^64: 64 chains over Z/2Z at once, bit i of a value being the coefficient of chain i.
// Every operation of the algorithms on chains is linear and made in the same order whatever the
// coefficients, so one run with these values is 64 runs over Z/2Z: bit i of the result is the
// result for bit i of the input. `to_integer()` gives the bits as they are (not a number).
struct Z2_word_arithmetic
{
  using Value = std::uint64_t;
  static constexpr bool has_signs = false;
  static Value zero() { return 0; }
  static Value add(Value a, Value b) { return a ^ b; }
  static Value negate(Value a) { return a; }
  static Value from_integer(std::int64_t k) { return Value(k); }
  static std::int64_t to_integer(Value a) { return std::int64_t(a); }
};

// The integers, standing for Q (only additions and subtractions are made, so an integral
// input stays integral); overflow is detected.
struct Integer_arithmetic
{
  using Value = std::int64_t;
  static constexpr bool has_signs = true;
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
