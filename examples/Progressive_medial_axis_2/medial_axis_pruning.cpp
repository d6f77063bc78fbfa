// What users do with a medial axis: the significance of its points by the
// extended grassfire transform, a pruned axis without the branches of
// boundary noise, the centerline of an elongated shape with its width
// profile, and the maximum inscribed circle.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_centerline_2.h>
#include <CGAL/Progressive_medial_axis_2/maximum_inscribed_circle_2.h>

#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main()
{
  // a winding band of width about 1, its sides slightly wavy (boundary noise
  // of amplitude 0.02)
  CGAL::Polygon_2<K> band;
  const int n = 200;
  for(int i = 0; i <= n; ++i) {
    const double x = 20.0 * i / n;
    band.push_back(K::Point_2(x, std::sin(x / 2) - 0.5 + 0.02 * std::sin(7.0 * i)));
  }
  for(int i = n; i >= 0; --i) {
    const double x = 20.0 * i / n;
    band.push_back(K::Point_2(x, std::sin(x / 2) + 0.5 + 0.02 * std::cos(5.0 * i)));
  }

  const auto axis = CGAL::medial_axis_2(band);

  // the largest disk inside the shape
  const auto circle = CGAL::maximum_inscribed_circle_2(axis);
  std::cout << "maximum inscribed circle: centre (" << circle.center << "), radius " << circle.radius << "\n";

  // significance, then keep what is at least half the band's width thick
  const CGAL::Medial_axis_significance_2<K> significance(axis);
  const auto pruned = CGAL::prune_medial_axis_2(significance, CGAL::to_double(circle.radius));
  std::cout << axis.number_of_edges() << " medial curves, " << pruned.curves().size() << " kept after pruning\n";

  // the centerline, extended to the boundary, and its width every so often
  const auto centerline = CGAL::medial_axis_centerline_2(pruned, true);
  std::cout << "centerline: " << centerline.paths().size() << " path, length " << centerline.length() << "\n";
  const auto profile = centerline.width_profile();
  for(std::size_t i = 0; i < profile.size(); i += profile.size() / 8)
    std::cout << "  s = " << profile[i].s << ": width " << profile[i].width << " at (" << profile[i].x << ", "
              << profile[i].y << ")\n";
  return 0;
}
