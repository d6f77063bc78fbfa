// The medial axis of the union of two polygons from their two axes: a
// square with a notch, and the piece that fills the notch.  The two share a
// chain of three edges; only the cells along it are merged.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/medial_axis_union_2.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
typedef CGAL::Polygon_2<K> Polygon_2;

int main()
{
  // a 4 x 4 square with a rectangular notch cut into its top edge
  Polygon_2 notched;
  for(const Point_2& p : {Point_2(0, 0), Point_2(4, 0), Point_2(4, 4), Point_2(3, 4), Point_2(3, 2),
                          Point_2(1, 2), Point_2(1, 4), Point_2(0, 4)})
    notched.push_back(p);
  // the piece that fills the notch, and sticks out above it
  Polygon_2 piece;
  for(const Point_2& p : {Point_2(1, 2), Point_2(3, 2), Point_2(3, 4), Point_2(3, 5), Point_2(1, 5), Point_2(1, 4)})
    piece.push_back(p);

  const auto a = CGAL::medial_axis_2(notched);
  const auto b = CGAL::medial_axis_2(piece);
  CGAL::Progressive_medial_axes::Medial_axis_union_statistics stats;
  const auto u = CGAL::medial_axis_union_2(a, b, CGAL::Progressive_medial_axis_traits_2<K>(), &stats);

  std::cout << "shared edges " << stats.shared_edges << " in " << stats.chains << " chain(s)\n";
  std::cout << "the union has " << u.input_ring_size(0) << " vertices:";
  for(std::size_t i = 0; i < u.input_ring_size(0); ++i) std::cout << "  " << u.point({0, int(i)});
  std::cout << "\n";
  for(const auto& e : u.edges())
    std::cout << e.first_generator().id() << " / " << e.second_generator().id() << "  length " << e.length() << "\n";
  return 0;
}
