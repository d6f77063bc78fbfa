// The medial axis of a polygon with holes, walked by handles: the cells of
// the generators, the half-edges around a cell, the cells around a vertex,
// and the cycle of the axis around each hole.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Progressive_medial_axis_2.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polygon_2<K> Polygon_2;
typedef CGAL::Polygon_with_holes_2<K> Polygon_with_holes_2;

int main()
{
  // a 10 x 6 plate with a square hole and a triangular hole
  Polygon_2 outer;
  outer.push_back(K::Point_2(0, 0));
  outer.push_back(K::Point_2(10, 0));
  outer.push_back(K::Point_2(10, 6));
  outer.push_back(K::Point_2(0, 6));
  Polygon_2 square, triangle;
  square.push_back(K::Point_2(2, 2));
  square.push_back(K::Point_2(2, 4));
  square.push_back(K::Point_2(4, 4));
  square.push_back(K::Point_2(4, 2));
  triangle.push_back(K::Point_2(6, 2));
  triangle.push_back(K::Point_2(7, 4));
  triangle.push_back(K::Point_2(8, 2));
  Polygon_with_holes_2 plate(outer);
  plate.add_hole(square);
  plate.add_hole(triangle);

  auto axis = CGAL::medial_axis_2(plate);
  typedef decltype(axis) Medial_axis;

  std::cout << axis.number_of_vertices() << " vertices, " << axis.number_of_edges() << " medial curves, "
            << axis.number_of_faces() << " generator cells\n";
  // a graph with V vertices, E edges, one component and h holes has E - V + 1 = h
  std::cout << "independent cycles: " << long(axis.number_of_edges()) - long(axis.number_of_vertices()) + 1 << "\n";

  // the cell of the first edge of the square hole, walked counter-clockwise
  for(const auto& f : axis.faces()) {
    if(f.is_point() || f.ring() != 1 || f.index() != 0) continue;
    std::cout << "cell of " << f.id() << ":";
    for(const auto& h : f.ccb()) {
      if(h.kind() == Medial_axis::MEDIAL_CURVE) std::cout << " curve with " << h.opposite().face().id();
      else if(h.kind() == Medial_axis::BOUNDARY_EDGE) std::cout << " [its edge]";
      else std::cout << " [normal]";
    }
    std::cout << "\n";
  }
  // the branch point of largest radius (the centre of a largest inscribed disk)
  Medial_axis::Vertex_handle best;
  for(const auto& v : axis.vertices())
    if(v.kind() == Medial_axis::BRANCH_POINT && (!best || v.radius() > best.radius())) best = v;
  std::cout << "largest inscribed disk: centre " << best.point() << ", radius " << best.radius() << ", touching";
  for(const auto& g : best.generators()) std::cout << " " << g.id();
  std::cout << "\n";
  return 0;
}
