// A progressive medial axis: refine step by step, watch the steps with a
// visitor, and look at the axis of an intermediate shape; with either driver
// (region growing, boundary evolution).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Progressive_medial_axis_2.h>

#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Progressive_medial_axis_traits_2<K> Traits;       // exact decisions
typedef CGAL::Progressive_medial_axis_2<Traits> Progressive_medial_axis;

// Counts the steps and the events, and remembers the largest priority queue
// of a merge (a model of ProgressiveMedialAxisVisitor_2).
struct Step_watcher : CGAL::Default_progressive_medial_axis_visitor {
  std::size_t steps = 0, vanishings = 0, largest_queue = 0;
  void on_vanish() { ++vanishings; }
  void on_step(std::size_t /*step*/, std::size_t n_v)
  {
    ++steps;
    if(n_v > largest_queue) largest_queue = n_v;
  }
};

int main()
{
  // a star-shaped polygon with 40 vertices
  CGAL::Polygon_2<K> star;
  for(int i = 0; i < 40; ++i) {
    double a = 2 * CGAL_PI * i / 40, r = (i % 2 == 0) ? 1.0 : 0.45;
    star.push_back(K::Point_2(r * std::cos(a), r * std::sin(a)));
  }

  Progressive_medial_axis pma(star);
  std::cout << pma.number_of_steps() << " refinement steps\n";

  // a coarse axis at once: the first ten steps
  pma.refine_to(10);
  std::cout << "after step " << pma.current_step() << ": the shape has "
            << pma.current_shape().outer_boundary().size() << " vertices, its axis "
            << pma.medial_axis().number_of_edges() << " curves\n";

  // then all the others, watched
  Step_watcher watcher;
  pma.refine_all(watcher);
  std::cout << "complete after " << watcher.steps << " more steps (" << watcher.vanishings
            << " vanishing points); largest queue n_v = " << watcher.largest_queue << "; the axis has "
            << pma.medial_axis().number_of_edges() << " curves\n";

  // the other driver: boundary evolution, whose step 0 is the outline
  // simplified down to a triangle, and every step puts a vertex back
  Progressive_medial_axis evolved(star, CGAL::BOUNDARY_EVOLUTION);
  evolved.refine_to(12);
  std::cout << "boundary evolution, after step " << evolved.current_step() << " of " << evolved.number_of_steps()
            << ": the shape has " << evolved.current_shape().outer_boundary().size() << " vertices\n";
  evolved.refine_all();
  const auto& s = evolved.statistics();
  std::cout << "complete: " << s.cuts << " triangles cut out, " << s.merges << " merges; the axis has "
            << evolved.medial_axis().number_of_edges() << " curves\n";
  return 0;
}
