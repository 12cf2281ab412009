// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_IS_PRIME_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_IS_PRIME_H

#include <cstdint>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// whether p is prime, by trial division (at compile time: the modulus of Zp_field)
constexpr bool is_prime(std::uint32_t p)
{
  if(p < 2) return false;
  for(std::uint32_t d = 2; std::uint64_t(d) * d <= p; ++d)
    if(p % d == 0) return false;
  return true;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_IS_PRIME_H
