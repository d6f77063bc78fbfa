// libFuzzer harness for the engine: the bytes are read as a small polygon
// with holes on an integer grid (or on the grid scaled by 1/7 and shifted, so
// that coordinates are not exact decimals), near-degenerate on purpose:
// repeated coordinates, collinear and cocircular vertices.  Valid polygons
// (as validate_polygon() says) get their medial axis computed three times,
// in one shot (divide and conquer), by region growing and by boundary
// evolution to the last step; all must have the same curves (pairs of
// generators and lengths).  A polygon of
// one ring is also split along the segment from its first vertex to another
// one (chosen by the last byte); where both parts are valid, the union of
// their two axes (medial_axis_union_2) must have the curves of the whole
// (generators compared by their points: the union numbers its polygon its
// own way), or report an input error (the segment leaves the polygon).
// The double model (traits over Simple_cartesian<double>) must give the
// same curves in one shot and by boundary evolution, up to curves shorter
// than 1e-9 of the coordinates, unless it reports the events it forced
// (statistics' anomalies): it may be wrong only where it says so.  Every
// axis made must pass Medial_axis_2::is_valid() (the half-edge structure).
// Built with AddressSanitizer and UBSan; any crash or difference is a failure.
//
//   fuzz_engine [libFuzzer options] [CORPUS_DIR ...]
//
// Byte layout: byte 0 selects the coordinate mode; then each byte is a
// vertex, x = high nibble, y = low nibble; 0xFF ends a ring.

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/medial_axis_union_2.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

namespace {

typedef CGAL::Epick K;
typedef K::Point_2 Point;

typedef std::vector<std::tuple<std::string, std::string, double> > Curves;

// The curves of an axis (pairs of generators, as `name` names them, and
// lengths), sorted.
template <class Axis, class Name>
Curves curves(const Axis& ma, const Name& name)
{
  Curves out;
  for(const auto& e : ma.edges()) {
    std::string a = name(e.first_generator()), b = name(e.second_generator());
    if(b < a) std::swap(a, b);
    out.emplace_back(a, b, e.length());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// ... with generators named by their ids
template <class Axis>
Curves curves(const Axis& ma)
{
  return curves(ma, [](const typename Axis::Face_handle& g) { return g.id(); });
}

// ... with generators named by their points
template <class Axis>
Curves curves_by_points(const Axis& ma)
{
  return curves(ma, [](const typename Axis::Face_handle& g) {
    char buf[128];
    auto p = Axis::to_xy(g.source()), q = Axis::to_xy(g.target());
    if(!g.is_point() && q < p) std::swap(p, q);
    std::snprintf(buf, sizeof(buf), "%s%a,%a,%a,%a", g.is_point() ? "v" : "e", p.first, p.second, q.first, q.second);
    return std::string(buf);
  });
}

bool same_curves(const Curves& a, const Curves& b, double scale)
{
  bool same = a.size() == b.size();
  for(std::size_t i = 0; same && i < a.size(); ++i)
    same = std::get<0>(a[i]) == std::get<0>(b[i]) && std::get<1>(a[i]) == std::get<1>(b[i]) &&
           std::abs(std::get<2>(a[i]) - std::get<2>(b[i])) <= 1e-9 * scale;
  return same;
}

// The curves longer than `tiny`: where the double model's decisions and
// the exact ones part on a curve shorter than its rounding errors, both
// are right to that precision.
Curves without_tiny(const Curves& a, double tiny)
{
  Curves out;
  for(const auto& c : a)
    if(std::get<2>(c) > tiny) out.push_back(c);
  return out;
}

// Stops at an axis whose half-edge structure is not valid (is_valid()
// writes the first problem found).
template <class Axis>
void require_valid(const char* what, const Axis& axis)
{
  if(!axis.is_valid(true)) {
    std::fprintf(stderr, "%s: the half-edge structure is not valid\n", what);
    __builtin_trap();
  }
}

void print_difference(const char* what, const Curves& a, const Curves& b)
{
  std::fprintf(stderr, "%s differ: %zu and %zu curves\n", what, a.size(), b.size());
  for(std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    if(i < a.size()) std::fprintf(stderr, "  %s %s %.17g", std::get<0>(a[i]).c_str(), std::get<1>(a[i]).c_str(), std::get<2>(a[i]));
    if(i < b.size()) std::fprintf(stderr, "  | %s %s %.17g", std::get<0>(b[i]).c_str(), std::get<1>(b[i]).c_str(), std::get<2>(b[i]));
    std::fprintf(stderr, "\n");
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 4 || size > 200) return 0;
  const int mode = data[0] % 3;
  std::vector<std::vector<Point> > rings(1);
  for(std::size_t i = 1; i < size; ++i) {
    if(data[i] == 0xFF) {
      if(rings.size() == 4) break;
      rings.emplace_back();
      continue;
    }
    double x = data[i] >> 4, y = data[i] & 15;
    if(mode == 1) { x = x / 7 + 0.1; y = y / 7 - 0.3; }
    if(mode == 2) { x = std::ldexp(x, 400); y = std::ldexp(y, 400); }   // far from 1: scale invariance
    rings.back().push_back(Point(x, y));
  }
  while(!rings.empty() && rings.back().empty()) rings.pop_back();
  if(rings.empty()) return 0;
  try {
    CGAL::Progressive_medial_axes::validate_polygon(rings);
  } catch(const CGAL::Progressive_medial_axes::Input_error&) {
    return 0;
  }
  const auto one_shot = CGAL::medial_axis_2(rings);
  CGAL::Progressive_medial_axis_2<> pma(rings);
  while(pma.refine()) {}
  require_valid("one-shot", one_shot);
  require_valid("region growing", pma.medial_axis());
  const auto a = curves(one_shot), b = curves(pma.medial_axis());
  double scale = 1;
  for(const auto& r : rings)
    for(const auto& p : r) scale = std::max({scale, std::abs(p.x()), std::abs(p.y())});
  if(!same_curves(a, b, scale)) {
    print_difference("one-shot and region growing", a, b);
    __builtin_trap();
  }
  CGAL::Progressive_medial_axis_2<> evolved(rings, CGAL::BOUNDARY_EVOLUTION);
  while(evolved.refine()) {}
  require_valid("boundary evolution", evolved.medial_axis());
  const auto e = curves(evolved.medial_axis());
  if(!same_curves(a, e, scale)) {
    print_difference("one-shot and boundary evolution", a, e);
    __builtin_trap();
  }
  // the double model, in one shot and by boundary evolution
  {
    typedef CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> > Double_traits;
    typedef Double_traits::Kernel::Point_2 Double_point;
    std::vector<std::vector<Double_point> > double_rings;
    for(const auto& r : rings) {
      double_rings.emplace_back();
      for(const auto& p : r) double_rings.back().emplace_back(p.x(), p.y());
    }
    const Curves exact = without_tiny(a, 1e-9 * scale);
    const auto double_one_shot = CGAL::medial_axis_2(double_rings, Double_traits());
    require_valid("the double model's one-shot", double_one_shot);
    const Curves d = without_tiny(curves(double_one_shot), 1e-9 * scale);
    if(!same_curves(exact, d, scale)) {
      print_difference("one-shot and the double model's one-shot", exact, d);
      __builtin_trap();
    }
    CGAL::Progressive_medial_axis_2<Double_traits> double_evolved(double_rings, CGAL::BOUNDARY_EVOLUTION);
    while(double_evolved.refine()) {}
    require_valid("the double model's boundary evolution", double_evolved.medial_axis());
    const Curves de = without_tiny(curves(double_evolved.medial_axis()), 1e-9 * scale);
    if(double_evolved.statistics().anomalies == 0 && !same_curves(exact, de, scale)) {
      print_difference("one-shot and the double model's boundary evolution", exact, de);
      __builtin_trap();
    }
  }
  // the union of two parts along the segment from vertex 0 to vertex k
  const std::size_t n = rings[0].size();
  if(rings.size() == 1 && n >= 4) {
    const std::size_t k = 2 + data[size - 1] % (n - 3);
    std::vector<std::vector<Point> > A(1), B(1);
    A[0].assign(rings[0].begin(), rings[0].begin() + std::ptrdiff_t(k) + 1);
    B[0].assign(rings[0].begin() + std::ptrdiff_t(k), rings[0].end());
    B[0].push_back(rings[0][0]);
    try {
      CGAL::Progressive_medial_axes::validate_polygon(A);
      CGAL::Progressive_medial_axes::validate_polygon(B);
    } catch(const CGAL::Progressive_medial_axes::Input_error&) {
      return 0;
    }
    try {
      const auto u = CGAL::medial_axis_union_2(CGAL::medial_axis_2(A), CGAL::medial_axis_2(B));
      require_valid("union", u);
      const Curves c = curves_by_points(u), w = curves_by_points(one_shot);
      if(!same_curves(c, w, scale)) {
        print_difference("union and whole", c, w);
        __builtin_trap();
      }
    } catch(const CGAL::Progressive_medial_axes::Input_error&) {
    }
  }
  return 0;
}
