/*!
\ingroup PkgPolygonPartitionSimplificationConcepts
\cgalConcept

The geometric traits of the package: the template parameter of
`CGAL::Polygon_partition_simplification::Line_partition_2` and the named parameter
`geom_traits` of `CGAL::kinetic_partition_2()`,
`CGAL::Polygon_partition_simplification::line_partition_from_polygons_2()` and
`CGAL::Polygon_partition_simplification::line_partition_from_arrangement_2()`.

A partition is computed in three kinds of geometry, each given by the traits:
- the <b>user-facing kernel</b> (`FT`, `Point_2`, `Segment_2`, `Polygon_2`,
  `Polygon_with_holes_2` and the functors below): the input segments are read with it, and the
  points, segments and cells of a partition are made with it. Its predicates are never used,
  so they need not be exact (`Simple_cartesian<double>` is fine); its coordinates are read as
  doubles (the nearest double of an exact coordinate), so a kernel with exact constructions is
  fine too.
- `Exact_constructions_kernel`: the exact constructions and predicates of the kinetic
  propagation (intersections of supporting lines, arrival times), of the snapping of nearly
  collinear segments onto one line (projections, intersections), of the exact arrangements and
  of the identification of the lines (their exact equations). Its number type must be an exact
  field type; it is converted to the nearest doubles wherever the package goes to double
  precision, so the result does not depend on which exact kernel is used, only the running time
  does (a lazy kernel, `Exact_predicates_exact_constructions_kernel`, is the fast one).
- `Exact_predicates_kernel`: the points of a partition are computed in double precision from
  its lines; every decision on them (crossing edges, the order of the edges around a point,
  the orientation of the cells, the enclosing rectangle) is taken with its predicates, which
  must be exact on doubles.

These requirements are checked at compile time: traits that do not meet them are refused
with a message that says why (an `Exact_constructions_kernel` with inexact constructions, an
`Exact_predicates_kernel` with inexact predicates or coordinates that are not doubles).

A type is taken for a model of this concept when it has a nested type
`Exact_constructions_kernel`; any other type given in its place (a CGAL kernel `K`) stands for
`CGAL::Polygon_partition_simplification_traits_2<K>`. (The name differs from the nested type
`Exact_kernel` that CGAL's filtered and lazy kernels already have, which is not an exact
constructions kernel of this kind for the filtered ones.)

\cgalHasModel `CGAL::Polygon_partition_simplification_traits_2<K, ExactConstructionsKernel>`
*/
class PolygonPartitionSimplificationTraits_2
{
public:
  /// \name Types
  /// @{

  /// The number type of the coordinates of the user-facing kernel: constructible from `double`
  /// and a model of `RealEmbeddable` (`CGAL::to_double()`).
  typedef unspecified_type FT;

  /// The point type of the user-facing kernel.
  typedef unspecified_type Point_2;

  /// The segment type of the user-facing kernel (the input of `CGAL::kinetic_partition_2()`).
  typedef unspecified_type Segment_2;

  /// The polygon type of the cells: a `CGAL::Polygon_2` whose points are `Point_2`.
  typedef unspecified_type Polygon_2;

  /// The cell type: a `CGAL::Polygon_with_holes_2` whose boundaries are `Polygon_2`.
  typedef unspecified_type Polygon_with_holes_2;

  /// A model of `Kernel` with exact constructions: its `FT` is an exact field number type
  /// (`Algebraic_structure_traits<FT>::Is_exact` and `Field_tag`), constructible from `double`;
  /// the points of the input (of `Point_2`, or of the kernel of an input arrangement) convert
  /// to it exactly with `CGAL::Cartesian_converter`.
  typedef unspecified_type Exact_constructions_kernel;

  /// A model of `Kernel` whose `FT` is `double`, with exact predicates
  /// (`Has_filtered_predicates` is `true`).
  typedef unspecified_type Exact_predicates_kernel;

  /// A construction object: `Point_2 operator()(const FT& x, const FT& y)`.
  typedef unspecified_type Construct_point_2;

  /// A construction object: `Segment_2 operator()(const Point_2& p, const Point_2& q)`.
  typedef unspecified_type Construct_segment_2;

  /// A construction object: `Point_2 operator()(const Segment_2& s)`, the source of `s`.
  typedef unspecified_type Construct_source_2;

  /// A construction object: `Point_2 operator()(const Segment_2& s)`, the target of `s`.
  typedef unspecified_type Construct_target_2;

  /// A construction object: `FT operator()(const Point_2& p)`, the x-coordinate of `p`.
  typedef unspecified_type Compute_x_2;

  /// A construction object: `FT operator()(const Point_2& p)`, the y-coordinate of `p`.
  typedef unspecified_type Compute_y_2;

  /// @}

  /// \name Operations
  /// @{

  /// returns a `Construct_point_2` object
  Construct_point_2 construct_point_2_object() const;
  /// returns a `Construct_segment_2` object
  Construct_segment_2 construct_segment_2_object() const;
  /// returns a `Construct_source_2` object
  Construct_source_2 construct_source_2_object() const;
  /// returns a `Construct_target_2` object
  Construct_target_2 construct_target_2_object() const;
  /// returns a `Compute_x_2` object
  Compute_x_2 compute_x_2_object() const;
  /// returns a `Compute_y_2` object
  Compute_y_2 compute_y_2_object() const;

  /// @}
};
