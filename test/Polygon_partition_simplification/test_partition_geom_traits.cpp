// The geometric traits (PolygonPartitionSimplificationTraits_2): the functions take their exact
// constructions and their predicates from the traits given with `geom_traits` (or deduced from
// the kernel of the input), and the result does not depend on the kernels as long as they are
// exact where they must be:
// - the default model given explicitly gives the same partition as the default;
// - an exact constructions kernel other than Epeck (Simple_cartesian<Exact_rational>, not lazy)
//   gives the same partition, and is the one used (types of the arrangements);
// - the user-facing kernels Epick, Epeck and Simple_cartesian<double> give the same partitions,
//   cells and simplifications; Epeck coordinates that are not doubles are read as their nearest
//   doubles;
// - a traits object with counting functors is the one used (input read and output made with it,
//   kept through the simplification).
// The compile-time refusals are checked by test_partition_geom_traits_refused.cpp (see CMakeLists.txt).
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_partition_simplification/line_partition_from_geometry_2.h>
#include <CGAL/Polygon_partition_simplification_traits_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include "synthetic_footprints.h"

#include <cassert>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <memory>
#include <type_traits>
#include <vector>


using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Cartesian_double = CGAL::Simple_cartesian<double>;
using Rational_kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>; // exact, not lazy
namespace PPS = CGAL::Polygon_partition_simplification;
using Default_traits = CGAL::Polygon_partition_simplification_traits_2<Epick>;
using Rational_traits = CGAL::Polygon_partition_simplification_traits_2<Epick, Rational_kernel>;

// The types: a kernel stands for the default model of it; the exact arrangement and the cells
// are in the kernels of the traits.
static_assert(std::is_same<PPS::Line_partition_2<Epick>::Geom_traits, Default_traits>::value, "");
static_assert(std::is_same<PPS::Line_partition_2<Default_traits>::Geom_traits, Default_traits>::value, "");
static_assert(std::is_same<Default_traits::Exact_constructions_kernel, Epeck>::value, "");
static_assert(std::is_same<PPS::Line_partition_2<Epick>::Polygon_with_holes_2, CGAL::Polygon_with_holes_2<Epick>>::value, "");
static_assert(std::is_same<PPS::Line_partition_2<Epeck>::Point_2, Epeck::Point_2>::value, "");
static_assert(std::is_same<PPS::Line_partition_2<Rational_traits>::Exact_arrangement_2::Point_2,
                           Rational_kernel::Point_2>::value, "");
static_assert(std::is_same<PPS::Line_partition_2<Epick>::Exact_arrangement_2::Point_2, Epeck::Point_2>::value, "");
// the return types follow `geom_traits`
static_assert(std::is_same<decltype(CGAL::kinetic_partition_2(std::vector<Epick::Segment_2>())),
                           PPS::Line_partition_2<Epick>>::value, "");
static_assert(std::is_same<decltype(CGAL::kinetic_partition_2(std::vector<Epick::Segment_2>(),
                                                              CGAL::parameters::geom_traits(Rational_traits()))),
                           PPS::Line_partition_2<Rational_traits>>::value, "");
static_assert(std::is_same<decltype(PPS::line_partition_from_polygons_2(std::vector<CGAL::Polygon_2<Epeck>>())),
                           PPS::Line_partition_2<Epeck>>::value, "");

template <class K>
std::vector<typename K::Segment_2> segments_in(const std::vector<synthetic::Segment>& s)
{
  std::vector<typename K::Segment_2> result;
  for(const auto& c : s) result.emplace_back(typename K::Point_2(c[0], c[1]), typename K::Point_2(c[2], c[3]));
  return result;
}

template <class K>
std::vector<CGAL::Polygon_2<K>> polygons_in(const std::vector<std::vector<synthetic::Point>>& polygons)
{
  std::vector<CGAL::Polygon_2<K>> result;
  for(const auto& p : polygons) {
    result.emplace_back();
    for(const auto& q : p) result.back().push_back(typename K::Point_2(q[0], q[1]));
  }
  return result;
}

// the same partition: frame, lines (coefficients, metrics), points and edges, bit for bit
template <class P, class Q>
bool same_partition(const P& p, const Q& q)
{
  if(p.frame().center_x != q.frame().center_x || p.frame().center_y != q.frame().center_y ||
     p.frame().scale != q.frame().scale)
    return false;
  if(p.number_of_lines() != q.number_of_lines() || p.number_of_vertices() != q.number_of_vertices() ||
     p.number_of_edges() != q.number_of_edges())
    return false;
  for(std::size_t l = 0; l < p.number_of_lines(); ++l) {
    const auto& a = p.lines()[l];
    const auto& b = q.lines()[l];
    if(a.coefficients != b.coefficients || a.metric.entries != b.metric.entries ||
       a.number_of_segments != b.number_of_segments || a.is_fixed != b.is_fixed)
      return false;
  }
  for(std::size_t v = 0; v < p.number_of_vertices(); ++v)
    if(p.vertices()[v].lines != q.vertices()[v].lines) return false;
  for(std::size_t e = 0; e < p.number_of_edges(); ++e) {
    const auto& a = p.edges()[e];
    const auto& b = q.edges()[e];
    if(a.line != b.line || a.source != b.source || a.target != b.target) return false;
  }
  return true;
}

// the same cells, vertex for vertex (coordinates as doubles)
template <class P, class Q>
bool same_cells(const P& p, const Q& q)
{
  std::vector<typename P::Polygon_with_holes_2> a;
  std::vector<typename Q::Polygon_with_holes_2> b;
  p.cells(std::back_inserter(a));
  q.cells(std::back_inserter(b));
  auto same_ring = [](const auto& x, const auto& y) {
    if(x.size() != y.size()) return false;
    for(std::size_t i = 0; i < x.size(); ++i)
      if(CGAL::to_double(x[i].x()) != CGAL::to_double(y[i].x()) || CGAL::to_double(x[i].y()) != CGAL::to_double(y[i].y()))
        return false;
    return true;
  };
  if(a.size() != b.size()) return false;
  for(std::size_t c = 0; c < a.size(); ++c) {
    if(!same_ring(a[c].outer_boundary(), b[c].outer_boundary())) return false;
    if(a[c].number_of_holes() != b[c].number_of_holes()) return false;
    auto h = b[c].holes_begin();
    for(auto g = a[c].holes_begin(); g != a[c].holes_end(); ++g, ++h)
      if(!same_ring(*g, *h)) return false;
  }
  return true;
}

template <class S, class T>
bool same_statistics(const S& s, const T& t)
{
  return s.lines_after == t.lines_after && s.points_after == t.points_after && s.cells_after == t.cells_after &&
         s.iterations == t.iterations && s.rounds == t.rounds && s.line_merges == t.line_merges &&
         s.point_merges == t.point_merges && s.rejected_rounds == t.rejected_rounds && s.energy_after == t.energy_after;
}

// A model whose functors count their calls (through a counter shared by the copies of the
// traits): the functions must read their input and make their output with the traits given.
struct Counting_traits : CGAL::Polygon_partition_simplification_traits_2<Epick>
{
  struct Counts { std::size_t points = 0, sources = 0, segments = 0; };
  std::shared_ptr<Counts> counts = std::make_shared<Counts>();

  struct Construct_point_2
  {
    Counts* counts;
    Point_2 operator()(const FT& x, const FT& y) const { ++counts->points; return Point_2(x, y); }
  };
  struct Construct_source_2
  {
    Counts* counts;
    Point_2 operator()(const Segment_2& s) const { ++counts->sources; return s.source(); }
  };
  struct Construct_segment_2
  {
    Counts* counts;
    Segment_2 operator()(const Point_2& p, const Point_2& q) const { ++counts->segments; return Segment_2(p, q); }
  };
  Construct_point_2 construct_point_2_object() const { return {counts.get()}; }
  Construct_source_2 construct_source_2_object() const { return {counts.get()}; }
  Construct_segment_2 construct_segment_2_object() const { return {counts.get()}; }
};

void test_kinetic_partitions()
{
  const synthetic::Footprints f = synthetic::make_footprints(6, 0.05, 11);
  const auto reference = CGAL::kinetic_partition_2(segments_in<Epick>(f.segments));
  assert(reference.is_valid() && reference.number_of_cells() > 20);
  // the default model, explicitly
  const auto explicit_default =
    CGAL::kinetic_partition_2(segments_in<Epick>(f.segments), CGAL::parameters::geom_traits(Default_traits()));
  assert(same_partition(reference, explicit_default) && same_cells(reference, explicit_default));
  // a kernel given as `geom_traits` stands for the default model of it
  const auto kernel_given = CGAL::kinetic_partition_2(segments_in<Epick>(f.segments), CGAL::parameters::geom_traits(Epick()));
  assert(same_partition(reference, kernel_given));
  // another exact constructions kernel (not lazy): the same exact partition, the same doubles
  const auto rational =
    CGAL::kinetic_partition_2(segments_in<Epick>(f.segments), CGAL::parameters::geom_traits(Rational_traits()));
  assert(same_partition(reference, rational) && same_cells(reference, rational));
  assert(rational.exact_arrangement().number_of_faces() == reference.exact_arrangement().number_of_faces());
  // user-facing kernels with exact constructions, and with inexact predicates
  const auto epeck = CGAL::kinetic_partition_2(segments_in<Epeck>(f.segments));
  const auto cartesian = CGAL::kinetic_partition_2(segments_in<Cartesian_double>(f.segments));
  assert(same_partition(reference, epeck) && same_cells(reference, epeck));
  assert(same_partition(reference, cartesian) && same_cells(reference, cartesian));
  // with the other named parameters of the function
  const auto crossing = CGAL::kinetic_partition_2(segments_in<Epick>(f.segments),
                                                  PPS::parameters::maximum_number_of_crossings(std::size_t(1)));
  const auto crossing_rational = CGAL::kinetic_partition_2(
    segments_in<Epick>(f.segments),
    PPS::parameters::maximum_number_of_crossings(std::size_t(1), CGAL::parameters::geom_traits(Rational_traits())));
  assert(!same_partition(reference, crossing) && same_partition(crossing, crossing_rational));
  std::cout << "kinetic partition: " << reference.number_of_cells()
            << " cells, the same with Epick, Epeck, Simple_cartesian<double>, and Simple_cartesian<Exact_rational> "
               "as exact kernel"
            << std::endl;

  // Epeck coordinates that are not doubles (a third): read as their nearest doubles, whatever
  // was evaluated before
  std::vector<Epeck::Segment_2> thirds;
  std::vector<Epick::Segment_2> rounded;
  for(int i = 0; i < 6; ++i) {
    const Epeck::FT a = Epeck::FT(i) / 3, b = Epeck::FT(2 * i + 1) / 7;
    thirds.emplace_back(Epeck::Point_2(a, b), Epeck::Point_2(a + 5, b + Epeck::FT(i % 2 == 0 ? 3 : -3) / 11));
    thirds.emplace_back(Epeck::Point_2(b, a), Epeck::Point_2(b - Epeck::FT(1) / 9, a + 4));
  }
  // the nearest double, by exact comparison with the neighbours of the conversion (which may
  // truncate); no tie for these fractions
  auto nearest = [](const Epeck::FT& x) {
    const Epeck::FT::ET& e = x.exact();
    double best = CGAL::to_double(e);
    for(double c : {std::nextafter(best, -1e300), std::nextafter(best, 1e300)})
      if(CGAL::abs(e - Epeck::FT::ET(c)) < CGAL::abs(e - Epeck::FT::ET(best))) best = c;
    return best;
  };
  for(const auto& s : thirds)
    rounded.emplace_back(Epick::Point_2(nearest(s.source().x()), nearest(s.source().y())),
                         Epick::Point_2(nearest(s.target().x()), nearest(s.target().y())));
  const auto third_partition = CGAL::kinetic_partition_2(thirds);
  assert(same_partition(third_partition, CGAL::kinetic_partition_2(rounded)));
}

void test_builders_and_simplification()
{
  const synthetic::Footprints f = synthetic::make_footprints(8, 0.05, 5);
  // polygons: Epick by default, the same with an explicit model, Epeck, Simple_cartesian<double>
  auto reference = PPS::line_partition_from_polygons_2(polygons_in<Epick>(f.polygons));
  assert(reference.is_valid());
  auto rational =
    PPS::line_partition_from_polygons_2(polygons_in<Epick>(f.polygons), CGAL::parameters::geom_traits(Rational_traits()));
  auto epeck = PPS::line_partition_from_polygons_2(polygons_in<Epeck>(f.polygons));
  auto cartesian = PPS::line_partition_from_polygons_2(polygons_in<Cartesian_double>(f.polygons));
  assert(same_partition(reference, rational) && same_partition(reference, epeck) && same_partition(reference, cartesian));
  // an arrangement in Epeck, the result with the traits given
  CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<Epeck>> arrangement;
  const auto exact_segments = segments_in<Epeck>({{0, 0, 2, 0}, {2, 0, 2, 1}, {2, 1, 0, 1}, {0, 1, 0, 0}, {1, 0, 1, 1}});
  CGAL::insert(arrangement, exact_segments.begin(), exact_segments.end());
  const auto from_arrangement = PPS::line_partition_from_arrangement_2<Epick>(arrangement);
  const auto from_arrangement_rational = PPS::line_partition_from_arrangement_2<Rational_traits>(
    arrangement, CGAL::parameters::geom_traits(Rational_traits()));
  assert(from_arrangement.number_of_cells() == 2 && same_partition(from_arrangement, from_arrangement_rational));

  // the simplification: the same rounds, the same result, whatever the kernels
  auto kinetic = CGAL::kinetic_partition_2(segments_in<Epick>(f.segments));
  auto kinetic_rational =
    CGAL::kinetic_partition_2(segments_in<Epick>(f.segments), CGAL::parameters::geom_traits(Rational_traits()));
  auto kinetic_epeck = CGAL::kinetic_partition_2(segments_in<Epeck>(f.segments));
  auto kinetic_cartesian = CGAL::kinetic_partition_2(segments_in<Cartesian_double>(f.segments));
  const auto s = CGAL::simplify_polygon_partition_2(kinetic);
  assert(s.line_merges > 0 && kinetic.is_valid());
  assert(same_statistics(s, CGAL::simplify_polygon_partition_2(kinetic_rational)) && same_partition(kinetic, kinetic_rational));
  assert(same_statistics(s, CGAL::simplify_polygon_partition_2(kinetic_epeck)) && same_partition(kinetic, kinetic_epeck));
  assert(same_statistics(s, CGAL::simplify_polygon_partition_2(kinetic_cartesian)) &&
        same_partition(kinetic, kinetic_cartesian));
  assert(same_cells(kinetic, kinetic_epeck) && same_cells(kinetic, kinetic_cartesian));
  std::cout << "builders and simplification: " << s.cells_before << " -> " << s.cells_after
            << " cells, the same with every kernel" << std::endl;
}

void test_traits_object_is_used()
{
  const synthetic::Footprints f = synthetic::make_footprints(3, 0.05, 3);
  const auto segments = segments_in<Epick>(f.segments);
  Counting_traits traits;
  auto p = CGAL::kinetic_partition_2(segments, CGAL::parameters::geom_traits(traits));
  static_assert(std::is_same<decltype(p)::Geom_traits, Counting_traits>::value, "");
  assert(traits.counts->sources >= segments.size()); // the input is read with the traits
  assert(same_partition(p, CGAL::kinetic_partition_2(segments)));
  assert(p.geom_traits().counts == traits.counts); // the partition keeps the traits object
  const std::size_t points = traits.counts->points;
  p.point(0);
  assert(traits.counts->points == points + 1);
  p.segment(0);
  assert(traits.counts->segments == 1);
  std::vector<Counting_traits::Polygon_with_holes_2> cells;
  p.cells(std::back_inserter(cells));
  assert(traits.counts->points > points + 1 + cells.size());
  CGAL::simplify_polygon_partition_2(p);
  assert(p.geom_traits().counts == traits.counts); // through the simplification
  const std::size_t before = traits.counts->points;
  p.point(0);
  assert(traits.counts->points == before + 1);
  // the polygons, too
  Counting_traits other;
  const auto q = PPS::line_partition_from_polygons_2(polygons_in<Epick>(f.polygons), CGAL::parameters::geom_traits(other));
  assert(q.geom_traits().counts == other.counts && other.counts->points == 0);
  q.point(0);
  assert(other.counts->points == 1);
  std::cout << "traits object: " << traits.counts->sources << " sources read, " << traits.counts->points
            << " points made with it" << std::endl;
}

int main()
{
  test_kinetic_partitions();
  test_builders_and_simplification();
  test_traits_object_is_used();
  std::cout << "test_partition_geom_traits: all checks passed" << std::endl;
  return 0;
}
