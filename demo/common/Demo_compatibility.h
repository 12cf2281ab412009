// Copyright (c) 2026  The Lex_optimal_chains and Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What the plugins use differently in the demo they are built for, CGAL's Polyhedron demo
// (CGAL 5.x, Qt5) or CGAL Lab (CGAL 6.x, Qt6); the build (demo/CMakeLists.txt) defines
// URBAN_DEMO_CGAL_LAB for CGAL Lab.
// - The plugin interfaces, renamed from Polyhedron_demo_* to CGAL_Lab_*, with new interface
//   ids. The ids must be written out where moc reads them, in each plugin's class
//   (Q_INTERFACES, Q_PLUGIN_METADATA), under the same URBAN_DEMO_CGAL_LAB, and the interface
//   headers included by the plugin's source too: the Polyhedron demo's moc is not given the
//   folder of this header.
// - The property maps of Surface_mesh and Point_set_3 looked up by name: a pair (map, found)
//   in CGAL 5.x, an optional map in CGAL 6.x (`found_property_map()`).

#ifndef URBAN_DEMO_COMPATIBILITY_H
#define URBAN_DEMO_COMPATIBILITY_H

#ifdef URBAN_DEMO_CGAL_LAB
#include <CGAL/Three/CGAL_Lab_io_plugin_interface.h>
#include <CGAL/Three/CGAL_Lab_plugin_helper.h>
#include <CGAL/Three/CGAL_Lab_plugin_interface.h>
#else
#include <CGAL/Three/Polyhedron_demo_io_plugin_interface.h>
#include <CGAL/Three/Polyhedron_demo_plugin_helper.h>
#include <CGAL/Three/Polyhedron_demo_plugin_interface.h>
#endif

#include <optional>
#include <utility>

namespace Urban_demo {

#ifdef URBAN_DEMO_CGAL_LAB
using Plugin_helper = CGAL::Three::CGAL_Lab_plugin_helper;
using Io_plugin_interface = CGAL::Three::CGAL_Lab_io_plugin_interface;
#else
using Plugin_helper = CGAL::Three::Polyhedron_demo_plugin_helper;
using Io_plugin_interface = CGAL::Three::Polyhedron_demo_io_plugin_interface;
#endif

// the property map that `property_map(name)` found, or nothing
template <class Map>
std::optional<Map> found_property_map(const std::pair<Map, bool>& found)
{
  return found.second ? std::optional<Map>(found.first) : std::nullopt;
}
template <class Map>
std::optional<Map> found_property_map(const std::optional<Map>& found)
{
  return found;
}

} // namespace Urban_demo

#endif // URBAN_DEMO_COMPATIBILITY_H
