// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_PARAMETERS_H
#define CGAL_LEX_OPTIMAL_CHAINS_PARAMETERS_H

#include <CGAL/license/Lex_optimal_chains.h>

// Named parameters of this package that CGAL 5.5 does not have. Each `foo(x)` starts a
// pack and `foo(x, np)` appends to one; all of CGAL's own parameters are re-exported, so
// `Lex_optimal_chains::parameters::verbose(true)` works as well.

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal_np {

enum interior_points_t { interior_points };
enum exterior_points_t { exterior_points };
enum number_of_threads_t { number_of_threads };
enum minimum_interior_persistence_t { minimum_interior_persistence };
enum coefficient_field_t { coefficient_field };
enum relative_facets_t { relative_facets };
enum remove_blocking_points_t { remove_blocking_points };
enum drop_boundary_triangles_t { drop_boundary_triangles };
enum keep_non_manifold_t { keep_non_manifold };
enum robust_t { robust };
enum smoothing_neighbors_t { smoothing_neighbors };
enum seam_spacing_t { seam_spacing };
enum tile_visitor_t { tile_visitor };
enum tile_filter_t { tile_filter };
enum feature_points_t { feature_points };
enum feature_threshold_t { feature_threshold };
enum vcm_offset_radius_t { vcm_offset_radius };
enum vcm_convolution_radius_t { vcm_convolution_radius };
enum feature_offset_t { feature_offset };
enum relative_to_features_t { relative_to_features };
enum drop_largest_elements_t { drop_largest_elements };
enum border_features_t { border_features };
enum face_element_map_t { face_element_map };

} // namespace internal_np

namespace parameters {

using namespace CGAL::parameters;

#define CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(NAME)                                                   \
  template <class T>                                                                              \
  Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& t)                           \
  {                                                                                               \
    return Named_function_parameters<T, internal_np::NAME##_t>(t);                                \
  }                                                                                               \
  template <class T, class U, class Tag, class Base>                                              \
  Named_function_parameters<T, internal_np::NAME##_t, Named_function_parameters<U, Tag, Base>>    \
  NAME(const T& t, const Named_function_parameters<U, Tag, Base>& np)                            \
  {                                                                                               \
    return Named_function_parameters<T, internal_np::NAME##_t,                                    \
                                     Named_function_parameters<U, Tag, Base>>(t, np);             \
  }

/// Points inside the surface to reconstruct (a range of `Point_3`): their cells are merged
/// into the interior constraint \f$\alpha_1\f$.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(interior_points)
/// Points outside the surface (a range of `Point_3`), added to the exterior constraint
/// \f$\alpha_2\f$ (which always holds the infinite vertex).
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(exterior_points)
/// Number of threads (needs TBB) for the Delaunay triangulation and the passes over its cells; the result does not depend on it.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(number_of_threads)
/// Smallest persistence ratio accepted for an automatically chosen interior.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(minimum_interior_persistence)
/// Coefficients of the open-surface chains (`Coefficient_field::Z2` or `Coefficient_field::Q`).
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(coefficient_field)
/// The triangles of a subcomplex \f$B\f$ (a range of `DT::Facet`): chains are relative to \f$B\f$.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(relative_facets)
/// Removes the input points that keep a boundary edge out of the Delaunay triangulation.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(remove_blocking_points)
/// Drops the triangles that touch a vertex of the boundary that is not an input point.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(drop_boundary_triangles)
/// Keeps the optimal chain as it is, without resolving its non-manifold vertices.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(keep_non_manifold)
/// Smooths noisy points by jet fitting before the closed surface reconstruction.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(robust)
/// Number of neighbours of the jet fits of the robust mode (0: chosen from the data).
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(smoothing_neighbors)
/// Distance between consecutive seam points of the tiles of `lex_optimal_tiled_surface_reconstruction()` (0: chosen from the data).
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(seam_spacing)
/// Called with each tile of `lex_optimal_tiled_surface_reconstruction()` as soon as it is reconstructed (to write it and free it).
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(tile_visitor)
/// Which tiles of `lex_optimal_tiled_surface_reconstruction()` to reconstruct: a callable
/// `std::vector<bool>(const std::vector<std::size_t>& points_per_tile)`, called once before any tile.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(tile_filter)
/// The feature set \f$S\f$ of `lex_optimal_feature_reconstruction()` (a range of `Point_3`).
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(feature_points)
/// The threshold of the VCM feature estimate of `lex_optimal_feature_reconstruction()`.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(feature_threshold)
/// The offset radius of the VCM of `lex_optimal_feature_reconstruction()`.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(vcm_offset_radius)
/// The convolution radius of the VCM of `lex_optimal_feature_reconstruction()`.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(vcm_convolution_radius)
/// The offset \f$\epsilon\f$ of the feature set that bounds the subcomplex \f$B\f$ of `lex_optimal_feature_reconstruction()`.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(feature_offset)
/// Optimal 2-chains relative to \f$B\f$ in `lex_optimal_feature_reconstruction()`.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(relative_to_features)
/// The number of largest elements of the critical basis that `lex_optimal_feature_reconstruction()` leaves out.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(drop_largest_elements)
/// Adds the points on the border of the sampled surface to the feature set of `lex_optimal_feature_reconstruction()`.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(border_features)
/// Receives the element of the critical basis of each face of `lex_optimal_feature_reconstruction()`.
CGAL_LEX_OPTIMAL_CHAINS_PARAMETER(face_element_map)

#undef CGAL_LEX_OPTIMAL_CHAINS_PARAMETER

} // namespace parameters
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_PARAMETERS_H
