// The medial axis of a polygon in one call, then its branch points and curves.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Progressive_medial_axis_2.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polygon_2<K> Polygon_2;

int main()
{
  // an L-shaped hexagon: one reflex vertex, at (1, 1)
  Polygon_2 polygon;
  polygon.push_back(K::Point_2(0, 0));
  polygon.push_back(K::Point_2(2, 0));
  polygon.push_back(K::Point_2(2, 1));
  polygon.push_back(K::Point_2(1, 1));
  polygon.push_back(K::Point_2(1, 2));
  polygon.push_back(K::Point_2(0, 2));

  auto axis = CGAL::medial_axis_2(polygon);   // every decision exact

  typedef decltype(axis) Medial_axis;
  for(const auto& v : axis.vertices())
    if(v.kind() == Medial_axis::BRANCH_POINT)
      std::cout << "branch point " << v.point() << " radius " << v.radius() << "\n";
  for(const auto& e : axis.edges())
    std::cout << (e.curve_kind() == Medial_axis::LINE_SEGMENT ? "line     " : "parabola ")
              << e.first_generator().id() << " / " << e.second_generator().id()
              << "  length " << e.length() << "\n";
  return 0;
}
