// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_FEATURE_RECONSTRUCTION_REPORT_H
#define CGAL_LEX_OPTIMAL_CHAINS_FEATURE_RECONSTRUCTION_REPORT_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
What `lex_optimal_feature_reconstruction()` did.
*/
struct Feature_reconstruction_report
{
  std::size_t number_of_input_points = 0;   ///< distinct input points (vertices of the triangulation)
  std::size_t number_of_feature_points = 0; ///< points of the feature set \f$S\f$
  std::size_t number_of_border_points = 0;  ///< points on the border of the sampled surface, with `border_features`
  std::size_t subcomplex_vertices = 0;      ///< vertices of the subcomplex \f$B\f$
  std::size_t subcomplex_edges = 0;         ///< edges of \f$B\f$
  std::size_t subcomplex_triangles = 0;     ///< triangles of \f$B\f$
  std::size_t number_of_cycles = 0;         ///< \f$\beta = \dim H_1(B) = \dim H_2(K, B)\f$
  std::vector<std::size_t> element_sizes;   ///< triangles of each element of the critical basis, in increasing order
  std::size_t number_of_dropped_elements = 0; ///< largest elements left out of the mesh
  std::size_t mesh_vertices = 0;            ///< vertices of the mesh
  std::size_t mesh_faces = 0;               ///< faces of the mesh
  /// points where elements of the basis meet in several umbrellas (fans of faces joined by
  /// edges), each split into one mesh vertex per umbrella: the mesh is then a 2-manifold with
  /// boundary, with several vertices at these points
  std::size_t non_manifold_vertices = 0;
  /// edges of three faces or more (three elements or more meeting along a feature), split into
  /// one mesh edge per face
  std::size_t non_manifold_edges = 0;
  double average_spacing = 0;               ///< mean distance of a point to its 6 nearest neighbours
  double offset = 0;                        ///< the offset \f$\epsilon\f$ used
  double delaunay_seconds = 0;              ///< the triangulation
  double feature_seconds = 0;               ///< the feature estimate (VCM, when the features are not given, and the border points)
  double subcomplex_seconds = 0;            ///< \f$B\f$ and its optimal 1-cycles
  double chain_seconds = 0;                 ///< the representative and optimal 2-chains (Algorithms 11 and 10)
  double basis_seconds = 0;                 ///< the critical basis (Observation 4.54)
  double mesh_seconds = 0;                  ///< the mesh
  double total_seconds = 0;                 ///< the whole call
};

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_FEATURE_RECONSTRUCTION_REPORT_H
