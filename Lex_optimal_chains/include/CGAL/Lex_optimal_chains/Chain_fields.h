// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_CHAIN_FIELDS_H
#define CGAL_LEX_OPTIMAL_CHAINS_CHAIN_FIELDS_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/internal/is_prime.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <cstdint>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
The field with two elements, for the matrix algorithms: unoriented chains.
All coefficient fields have the same static interface: `Value`, `zero()`, `one()`,
`add()`, `subtract()`, `multiply()`, `divide()`, `is_zero()`, `from_integer()`.
*/
struct Z2_field
{
  typedef std::uint8_t Value; ///< 0 or 1
  /// the neutral element of the addition
  static Value zero() { return 0; }
  /// the neutral element of the multiplication
  static Value one() { return 1; }
  /// the sum
  static Value add(Value a, Value b) { return Value(a ^ b); }
  /// the difference
  static Value subtract(Value a, Value b) { return Value(a ^ b); }
  /// the product
  static Value multiply(Value a, Value b) { return Value(a & b); }
  /// the quotient by a non-zero element
  /// \pre `b == 1`
  static Value divide(Value a, Value b)
  {
    CGAL_precondition(b == 1);
    CGAL_USE(b);
    return a;
  }
  /// true for zero
  static bool is_zero(Value a) { return a == 0; }
  /// the image of an integer
  static Value from_integer(long k) { return Value(k & 1); }
};

/*!
\ingroup PkgLexOptimalChainsRef
The prime field \f$\mathbb{Z}/p\mathbb{Z}\f$ (default \f$p = 2^{31}-1\f$): oriented chains,
a fast stand-in for \f$\mathbb{Q}\f$. It gives the result over \f$\mathbb{Q}\f$ reduced
modulo \f$p\f$ unless \f$p\f$ divides a pivot met by the elimination over \f$\mathbb{Q}\f$,
which for the small integer boundary matrices of simplicial complexes is vanishingly unlikely
with a large \f$p\f$; use `Q_field` when that must be excluded.
*/
template <std::uint32_t P = 2147483647u>
struct Zp_field
{
  static_assert(internal::is_prime(P), "Zp_field needs a prime P");
  typedef std::uint32_t Value; ///< in [0, P)
  /// the neutral element of the addition
  static Value zero() { return 0; }
  /// the neutral element of the multiplication
  static Value one() { return 1; }
  /// the sum
  static Value add(Value a, Value b) { return Value((std::uint64_t(a) + b) % P); }
  /// the difference
  static Value subtract(Value a, Value b) { return Value((std::uint64_t(a) + P - b) % P); }
  /// the product
  static Value multiply(Value a, Value b) { return Value(std::uint64_t(a) * b % P); }
  /// the quotient by a non-zero element
  /// \pre `!is_zero(b)` and `b < P`
  static Value divide(Value a, Value b) { return multiply(a, inverse(b)); }
  /// true for zero
  static bool is_zero(Value a) { return a == 0; }
  /// the image of an integer
  static Value from_integer(long k) { return Value(((k % long(P)) + long(P)) % long(P)); }
  /// the inverse of a non-zero element (Fermat)
  /// \pre `!is_zero(b)` and `b < P`
  static Value inverse(Value b)
  {
    CGAL_precondition(b != 0 && b < P);
    Value r = 1, x = b;
    for(std::uint32_t e = P - 2; e != 0; e >>= 1, x = multiply(x, x))
      if(e & 1) r = multiply(r, x);
    return r;
  }
};

/*!
\ingroup PkgLexOptimalChainsRef
The rationals, exactly (`CGAL::Exact_rational`): oriented chains.
*/
struct Q_field
{
  typedef Exact_rational Value; ///< a rational number
  /// the neutral element of the addition
  static Value zero() { return Value(0); }
  /// the neutral element of the multiplication
  static Value one() { return Value(1); }
  /// the sum
  static Value add(const Value& a, const Value& b) { return a + b; }
  /// the difference
  static Value subtract(const Value& a, const Value& b) { return a - b; }
  /// the product
  static Value multiply(const Value& a, const Value& b) { return a * b; }
  /// the quotient by a non-zero element
  /// \pre `!is_zero(b)`
  static Value divide(const Value& a, const Value& b)
  {
    CGAL_precondition(b != 0);
    return a / b;
  }
  /// true for zero
  static bool is_zero(const Value& a) { return a == 0; }
  /// the image of an integer
  static Value from_integer(long k) { return Value(k); }
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_CHAIN_FIELDS_H
