// Draws the medial axis of a polygon with holes in CGAL's basic viewer
// (needs CGAL_Qt5; the example is built only when it is found).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/draw_medial_axis_2.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;

int main()
{
  CGAL::Polygon_2<K> outer, hole;
  for(const Point& p : {Point(0, 0), Point(8, 0), Point(8, 3), Point(5, 3), Point(5, 6), Point(0, 6)}) outer.push_back(p);
  for(const Point& p : {Point(1, 1), Point(1, 4), Point(3, 4), Point(3, 1)}) hole.push_back(p);
  CGAL::Polygon_with_holes_2<K> shape(outer);
  shape.add_hole(hole);
  CGAL::draw(CGAL::medial_axis_2(shape));
  return 0;
}
