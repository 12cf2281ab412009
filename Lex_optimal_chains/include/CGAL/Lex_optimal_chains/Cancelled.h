// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_CANCELLED_H
#define CGAL_LEX_OPTIMAL_CHAINS_CANCELLED_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <stdexcept>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
Exception thrown when the progress callback of a function of this package (the named
parameter `callback`) returns `false`. It is not an `Input_error`: the input was not wrong, the
user stopped the computation. The functions that take a callback leave their output as it was
(a mesh unchanged, nothing written to an output iterator) unless their documentation says
otherwise (the chain functions on a triangulation make their last call after writing).
*/
class Cancelled : public std::runtime_error
{
public:
  /// builds the exception; `what()` is "cancelled by the callback"
  Cancelled() : std::runtime_error("cancelled by the callback") {}
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_CANCELLED_H
