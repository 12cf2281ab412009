// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_GEOJSON_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_GEOJSON_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <ostream>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace IO {

/*!
\ingroup PkgPolygonPartitionSimplificationRef

writes cells as a GeoJSON `FeatureCollection` (RFC 7946) of `Polygon` features, one per cell,
with the property `"cell"` (its index). Outer rings are counterclockwise and holes clockwise,
each ring closed (first position repeated), coordinates written with full double precision.
Coordinates are written as given: no reprojection is done.

\returns `true` if the stream is good after writing
*/
template <class Kernel>
bool write_GeoJSON(std::ostream& out, const std::vector<CGAL::Polygon_with_holes_2<Kernel>>& cells)
{
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  auto ring = [&](const auto& polygon, bool counterclockwise) {
    std::vector<typename Kernel::Point_2> points(polygon.vertices_begin(), polygon.vertices_end());
    if((polygon.orientation() == CGAL::COUNTERCLOCKWISE) != counterclockwise)
      std::reverse(points.begin(), points.end());
    out << '[';
    for(std::size_t i = 0; i <= points.size(); ++i) {
      const auto& p = points[i % points.size()];
      out << (i ? "," : "") << '[' << CGAL::to_double(p.x()) << ',' << CGAL::to_double(p.y()) << ']';
    }
    out << ']';
  };
  out << "{\"type\":\"FeatureCollection\",\"features\":[";
  for(std::size_t c = 0; c < cells.size(); ++c) {
    out << (c ? ",\n" : "\n") << "{\"type\":\"Feature\",\"properties\":{\"cell\":" << c
        << "},\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[";
    ring(cells[c].outer_boundary(), true);
    for(auto h = cells[c].holes_begin(); h != cells[c].holes_end(); ++h) {
      out << ',';
      ring(*h, false);
    }
    out << "]}}";
  }
  out << "\n]}\n";
  return out.good();
}

} // namespace IO
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_GEOJSON_H
