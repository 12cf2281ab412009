// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SIMPLIFICATION_ROUND_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SIMPLIFICATION_ROUND_2_H

// One round of Algorithm 1 (section 3.3 of the thesis): a descent on the lines
// (Partition_descent_2.h), then the reductions, redone until the partition is valid
// (Validated_reductions_2.h).

#include <CGAL/Polygon_partition_simplification/internal/Partition_descent_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Simplification_settings_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Validated_reductions_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Working_partition_2.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// A round on `w`, which must be valid and is replaced by the (valid) result. `changed`: the
// lines that the previous round changed (empty for the first round: every line moves);
// `iterations`: the gradient steps made so far, incremented by those of the descent. The validity
// is checked with the predicates of `GeomTraits`.
template <class GeomTraits>
Round_reductions simplification_round(Working_partition& w, const std::vector<bool>& changed,
                                             const Simplification_settings& s, std::size_t& iterations)
{
  const Working_partition start = w;
  const std::vector<Vector_3d> moved = descend(w, changed, s, iterations);
  Round_reductions result = reduce_until_valid<GeomTraits>(w, start, moved, s.thresholds, changed.empty());
  // the next round starts with no line frozen and no record of the merges of this one
  for(auto& l : w.lines) { l.is_frozen = false; l.members.clear(); }
  return result;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_SIMPLIFICATION_ROUND_2_H
