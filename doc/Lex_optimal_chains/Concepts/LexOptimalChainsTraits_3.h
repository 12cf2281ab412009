/*!
\ingroup PkgLexOptimalChainsConcepts
\cgalConcept

The geometric traits of the functions of the package that build a Delaunay triangulation from
points (`CGAL::lex_optimal_closed_surface_reconstruction()`,
`CGAL::lex_optimal_open_surface_reconstruction()`, named parameter `geom_traits`): the
triangulation is built with its predicates.

The coordinates are `double`: the order on triangles (Lemma 4.14 of the thesis, see
`CGAL::Lex_optimal_chains_traits_3`) is evaluated exactly from them, with certified
floating-point filters and an exact fallback. The predicates must be exact
(`Has_filtered_predicates` is `true`), or the triangulation would not be a Delaunay
triangulation. Other traits are refused at compile time with a message that says why; a kernel
with exact constructions is refused because its coordinates are not doubles (convert the points
to `CGAL::Exact_predicates_inexact_constructions_kernel`, which represents input doubles
exactly).

The functions that take a user's triangulation (`CGAL::lex_optimal_closed_surface()`,
`CGAL::lex_optimal_chain_with_boundary()`, `CGAL::lex_optimal_closed_surface_mesh()`, ...)
only need `double` coordinates from the triangulation's own traits.

\cgalRefines `DelaunayTriangulationTraits_3`

\cgalHasModel `CGAL::Exact_predicates_inexact_constructions_kernel`, and
`CGAL::Lex_optimal_chains_traits_3<K>` of it, which adds the order on triangles for the user's
own code
*/
class LexOptimalChainsTraits_3
{
public:
  /// \name Types
  /// @{

  /// `double`
  typedef unspecified_type FT;

  /// The point type.
  typedef unspecified_type Point_3;

  /// @}

  /// \name Constants
  /// @{

  /// `true`: the predicates are exact
  static const bool Has_filtered_predicates = true;

  /// @}
};
