// compare_pairs SHAPE.wkt OURS.txt ORACLE.txt
//
// Compares two lists of "pair A B L" lines (from progressive_medial_axis
// --pairs and sdg_pairs) for the polygon in SHAPE, allowing curves shorter
// than 1e-9 of its bounding-box diagonal to differ.  Prints the differences;
// exit status 0 if they match, 1 if not, 2 on bad usage or input.
#include <pma_test/compare_curves.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <pma_tool/polygon_io.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>

int main(int argc, char** argv)
{
  if(argc != 4) {
    std::cerr << "usage: compare_pairs SHAPE.wkt OURS.txt ORACLE.txt\n";
    return 2;
  }
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  try {
    for(const auto& ring : pma_tool::read_polygon_file<CGAL::Epick::Point_2>(argv[1]))
      for(const auto& p : ring) {
        x0 = std::min(x0, p.x()); x1 = std::max(x1, p.x());
        y0 = std::min(y0, p.y()); y1 = std::max(y1, p.y());
      }
  } catch(const std::exception& e) {
    std::cerr << argv[1] << ": " << e.what() << "\n";
    return 2;
  }
  std::ifstream a(argv[2]), b(argv[3]);
  if(!a || !b) {
    std::cerr << "compare_pairs: cannot read " << (!a ? argv[2] : argv[3]) << "\n";
    return 2;
  }
  std::vector<pma_test::Oracle_curve> ca = pma_test::parse_pairs(a), cb = pma_test::parse_pairs(b);
  pma_test::Curve_diff d = pma_test::compare_curves(ca, cb, std::hypot(x1 - x0, y1 - y0));
  std::cout << ca.size() << " curves vs " << cb.size() << " oracle curves: " << (d.ok() ? "match" : "DIFFER") << "\n";
  if(!d.ok()) std::cout << d.report();
  return d.ok() ? 0 : 1;
}
