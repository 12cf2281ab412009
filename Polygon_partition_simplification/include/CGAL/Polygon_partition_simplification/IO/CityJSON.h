// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_CITYJSON_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_CITYJSON_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/City_building.h>
#include <CGAL/Polygon_partition_simplification/internal/CityJSON_buildings.h>
#include <CGAL/Polygon_partition_simplification/internal/CityJSON_model.h>
#include <CGAL/Polygon_partition_simplification/internal/write_text_file.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh.h>

#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {

namespace IO {

/*!
\ingroup PkgPolygonPartitionSimplificationRef

writes LOD2 building models to a CityJSON 1.1 file (https://www.cityjson.org/specs/1.1.3/): one
`Building` city object per building, named `"building_<index>"`, whose geometry is one `Solid`
of LOD 2.2 with one shell. Each face of `mesh` is a surface of the shell of its building, with
its vertices in the order of the mesh (CityJSON wants the surfaces of a shell counterclockwise
seen from outside, which is the order of the faces of a mesh that bounds its volume with
outward normals) and the semantic surface type of the face (`RoofSurface`, `WallSurface` or
`GroundSurface`). Vertices are written once, as integers with the file's `"transform"`:
`translate` is the lowest corner of the bounding box of the faces' vertices and `scale` is
\f$10^{-d}\f$ for \f$d\f$ decimals. Vertices that round to the same integer point are one
vertex; a face that keeps fewer than three distinct vertices after rounding (smaller than the
precision) is not written, and neither is a building left without faces. Buildings are written
by increasing index and their surfaces in the order of the mesh's faces. The output does not
depend on the locale of `os`.

\tparam Point a 3D point type whose coordinates convert with `CGAL::to_double()`

\param os the output stream
\param mesh the buildings, with the face property maps `"f:building"` (`std::size_t`, the index
of the building of a face) and `"f:surface_type"` (`Building_surface_type`)
\param np optional named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{stream_precision}
    \cgalParamDescription{the number of decimals of the written coordinates, from 0 to 15}
    \cgalParamType{int}
    \cgalParamDefault{3 (millimetres when coordinates are in metres)}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` if the stream is good after writing

\throws Input_error, and writes nothing, with the code `MISSING_PROPERTY` if a property map is
missing or has another value type, `NON_FINITE_COORDINATE` if a vertex of a face has a
coordinate that is not finite, and `INVALID_PARAMETER` if `stream_precision` is not an integer
from 0 to 15, if the extent of the model in units of \f$10^{-d}\f$ exceeds \f$2^{53}\f$, or if a
surface type is not one of the enumerators.
*/
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_CityJSON(std::ostream& os, const Surface_mesh<Point>& mesh,
                    const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string text =
    internal::CityJSON_text(internal::make_CityJSON_model(mesh, internal::CityJSON_decimals(np)));
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
  return os.good();
}

/*!
\ingroup PkgPolygonPartitionSimplificationRef

writes LOD2 building models to the CityJSON file `file_name`, as the stream overload does.
The input is checked before the file is opened: on an `Input_error` the file is not touched.

\returns `true` if the file was written; `false` if it cannot be opened or written (a file
whose writing failed is removed)
*/
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_CityJSON(const std::string& file_name, const Surface_mesh<Point>& mesh,
                    const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string text =
    internal::CityJSON_text(internal::make_CityJSON_model(mesh, internal::CityJSON_decimals(np)));
  return internal::write_text_file(file_name, text);
}

/*!
\ingroup PkgPolygonPartitionSimplificationRef

writes the buildings of `lod2_city_reconstruction()` to a CityJSON 1.1 file, as 3DBAG publishes
its buildings: one `Building` city object per building, named `"building_<id>"`, whose
geometries are its LoD 1.2 block and, when it has one, its LoD 2.2 solid (each a `Solid` of one
shell with semantic surfaces), and whose attributes are `status` (`"lod22"` or
`"lod12_fallback"`), `reason` (when the LoD 2.2 solid is missing), `points`, `h_ground`,
`h_50p`, `h_70p`, `h_max` and, with an LoD 2.2 solid, `rms_m` (see `City_building`). The
vertices are shared by all buildings and written as integers, as by the writer of one mesh.

\param os the output stream
\param buildings the buildings
\param np optional named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{stream_precision}
    \cgalParamDescription{the number of decimals of the coordinates, from 0 to 15}
    \cgalParamType{`int`}
    \cgalParamDefault{3}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` if the stream is good after writing
\throws Input_error, and writes nothing, on a non-finite vertex or an invalid `stream_precision`
*/
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_CityJSON(std::ostream& os, const std::vector<City_building<Point>>& buildings,
                    const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string text = internal::CityJSON_text_of_buildings(buildings, internal::CityJSON_decimals(np));
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
  return os.good();
}

/*!
\ingroup PkgPolygonPartitionSimplificationRef

writes the buildings of `lod2_city_reconstruction()` as CityJSON Text Sequences
(https://www.cityjson.org/specs/1.1.3/#text-sequences-and-streaming-with-cityjsonfeature): a
first line holding the `CityJSON` object with the transform and no city object, then one line
per building, a `CityJSONFeature` with the `Building` that `write_CityJSON()` writes and its own
vertices; each line is written when it is made, so that large tiles stream.

\param os the output stream
\param buildings the buildings
\param np optional named parameters: those of `write_CityJSON()` for buildings (`stream_precision`)

\returns `true` if the stream is good after writing
\throws Input_error, and writes nothing, on a non-finite vertex or an invalid `stream_precision`
*/
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_CityJSON_sequence(std::ostream& os, const std::vector<City_building<Point>>& buildings,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::write_CityJSON_features(os, buildings, internal::CityJSON_decimals(np));
}

} // namespace IO
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_IO_CITYJSON_H
