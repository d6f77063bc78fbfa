// What users do with a medial axis (issue 14): the extended grassfire
// significance, pruning, centerlines and their width profile, the maximum
// inscribed circle and the exact Bezier form of parabolic arcs.
//
//   test_pruning
//
// Shapes with K arms keep exactly K ends, with and without boundary noise;
// the centerline of a noisy meandering band follows its known centre line;
// the invariants of the grassfire transform hold on random polygons with
// holes, and the linear algorithm gives the fire of an event simulation.
// (The maximum inscribed circle is compared with the oracle's
// branch points in test_medial_axis_oracle, on every shape it runs.)

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_centerline_2.h>
#include <CGAL/Progressive_medial_axis_2/maximum_inscribed_circle_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <pma_test/check.h>
#include <pma_test/pruned_graph.h>
#include <pma_test/random_polygons.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <queue>
#include <random>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef std::vector<std::vector<Point> > Rings;
typedef CGAL::Medial_axis_2<K> MA;
typedef CGAL::Pruned_medial_axis_2<K> Pruned;
const double pi = 3.14159265358979323846;

// A star of K smooth arms: r(t) = 1 + 2 ((1 + cos(K t)) / 2)^6, sampled at n
// points, each moved radially by a uniform noise in [-noise, noise].
Rings star(int arms, int n, double noise, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-noise, noise);
  Rings r(1);
  for(int i = 0; i < n; ++i) {
    const double t = 2 * pi * i / n;
    const double rho = 1 + 2 * std::pow(0.5 + 0.5 * std::cos(arms * t), 6) + (noise > 0 ? u(rng) : 0);
    r[0].push_back(Point(rho * std::cos(t), rho * std::sin(t)));
  }
  return r;
}

// The centre line of the meandering band: y = A sin(2 pi x / P).
const double band_amplitude = 1, band_period = 8, band_length = 24, band_width = 1;
std::pair<double, double> band_centre(double x)
{
  return {x, band_amplitude * std::sin(2 * pi * x / band_period)};
}
std::pair<double, double> band_normal(double x)
{
  const double dy = band_amplitude * 2 * pi / band_period * std::cos(2 * pi * x / band_period);
  const double n = std::hypot(1.0, dy);
  return {-dy / n, 1 / n};
}
// The band of width 1 around the centre line for 0 <= x <= 24, its sides
// sampled every `step` and moved along the normal by noise in [-noise, noise].
Rings band(double step, double noise, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-noise, noise);
  const int n = int(band_length / step);
  std::vector<Point> lower, upper;
  for(int i = 0; i <= n; ++i) {
    const double x = band_length * i / n;
    const auto c = band_centre(x);
    const auto m = band_normal(x);
    const double e1 = (i == 0 || i == n || noise == 0) ? 0 : u(rng), e2 = (i == 0 || i == n || noise == 0) ? 0 : u(rng);
    lower.push_back(Point(c.first - (0.5 * band_width + e1) * m.first, c.second - (0.5 * band_width + e1) * m.second));
    upper.push_back(Point(c.first + (0.5 * band_width + e2) * m.first, c.second + (0.5 * band_width + e2) * m.second));
  }
  Rings r(1);
  for(const Point& p : lower) r[0].push_back(p);
  for(auto it = upper.rbegin(); it != upper.rend(); ++it) r[0].push_back(*it);
  return r;
}
double distance_to_band_centre(double x, double y)
{
  // the centre line sampled finely (its curvature radius is 1.6 or more)
  double best = 1e300;
  for(int i = -100; i <= 24100; ++i) {
    const auto c = band_centre(band_length * i / 24000.0);
    best = std::min(best, std::hypot(x - c.first, y - c.second));
  }
  return best;
}

void test_arms()
{
  for(int arms = 3; arms <= 8; ++arms)
    for(int noisy = 0; noisy < 2; ++noisy) {
      const Rings r = star(arms, 400 * arms / 3 + 100, noisy ? 0.01 : 0, 1000u + std::uint64_t(arms));
      const MA ma = CGAL::medial_axis_2(r);
      const CGAL::Medial_axis_significance_2<K> sig(ma);
      const Pruned p = CGAL::prune_medial_axis_2(sig, 0.2);
      const pma_test::Pruned_graph g = pma_test::pruned_graph(p);
      const std::string what = std::to_string(arms) + " arms" + (noisy ? ", noisy" : "");
      CHECK(g.ends == arms, what << ": " << g.ends << " ends after pruning et=0.2 (axis: " << ma.number_of_edges()
                                 << " curves)");
      CHECK(g.components == 1 && g.cycles == 0, what << ": " << g.components << " components, " << g.cycles << " cycles");
      // the ratio threshold alone is free of scale: the same ends
      const pma_test::Pruned_graph q = pma_test::pruned_graph(CGAL::prune_medial_axis_2(sig, 0, 0.5));
      CHECK(q.ends == arms, what << ": " << q.ends << " ends after pruning ratio=0.5");
    }
}

void test_band()
{
  for(int noisy = 0; noisy < 2; ++noisy) {
    const std::string what = noisy ? "noisy band" : "band";
    const Rings r = band(0.05, noisy ? 0.01 : 0, 7);
    const MA ma = CGAL::medial_axis_2(r);
    const CGAL::Medial_axis_significance_2<K> sig(ma);
    const double R = CGAL::to_double(CGAL::maximum_inscribed_circle_2(ma).radius);
    CHECK(std::fabs(R - 0.5 * band_width) < 0.02, what << ": maximum inscribed radius " << R);
    const Pruned p = CGAL::prune_medial_axis_2(sig, R);
    for(int extend = 0; extend < 2; ++extend) {
      const auto c = CGAL::medial_axis_centerline_2(p, extend != 0);
      CHECK(c.paths().size() == 1 && !c.paths()[0].closed, what << ": " << c.paths().size() << " centerline paths");
      if(c.paths().size() != 1) continue;
      const auto lines = c.polylines(1e-4);
      const auto& line = lines[0];
      double worst = 0;
      for(const auto& q : line) worst = std::max(worst, distance_to_band_centre(q.first, q.second));
      CHECK(worst <= 0.1 * band_width, what << ": the centerline is " << worst << " from the centre line");
      const double xs = std::min(line.front().first, line.back().first);
      const double xe = std::max(line.front().first, line.back().first);
      if(extend) {
        CHECK(xs < 1e-6 && xe > band_length - 1e-6,
              what << ": the extended centerline runs from x=" << xs << " to x=" << xe);
      } else {
        CHECK(xs > 0.3 && xs < 2 && xe < band_length - 0.3 && xe > band_length - 2,
              what << ": the centerline runs from x=" << xs << " to x=" << xe);
      }
      // the width profile, away from the ends
      const auto profile = c.width_profile();
      CHECK(profile.size() > 10 * band_length, what << ": " << profile.size() << " width samples");
      double worst_width = 0, last_s = -1;
      bool increasing = true;
      for(const auto& w : profile) {
        increasing = increasing && w.s > last_s;
        last_s = w.s;
        if(w.x < 2 || w.x > band_length - 2) continue;
        worst_width = std::max(worst_width, std::fabs(w.width - band_width) / band_width);
      }
      CHECK(increasing, what << ": the arc lengths of the width profile do not increase");
      CHECK(worst_width <= 0.05, what << ": the width profile is off by " << 100 * worst_width << "%");
      // samples at least every tenth of the width
      for(std::size_t i = 1; i < profile.size(); ++i)
        if(profile[i].x > 2 && profile[i].x < band_length - 2)
          CHECK(profile[i].s - profile[i - 1].s <= 0.1 * profile[i - 1].width + 1e-9,
                what << ": width samples " << profile[i].s - profile[i - 1].s << " apart");
    }
  }
}

// A braided river: a straight band of width 3 with an island in the middle.
// The centerline keeps both channels: the paths from the two ends to the
// island and the two channels around it, four chains in all, one cycle.
void test_braided()
{
  Rings r(2);
  r[0] = {Point(0, 0), Point(20, 0), Point(20, 3), Point(0, 3)};
  for(int i = 0; i < 40; ++i) {   // an elliptic island, clockwise
    const double t = -2 * pi * i / 40;
    r[1].push_back(Point(10 + 3 * std::cos(t), 1.5 + 0.6 * std::sin(t)));
  }
  const MA ma = CGAL::medial_axis_2(r);
  const CGAL::Medial_axis_significance_2<K> sig(ma);
  const double R = CGAL::to_double(CGAL::maximum_inscribed_circle_2(ma).radius);
  const auto c = CGAL::medial_axis_centerline_2(CGAL::prune_medial_axis_2(sig, R), true);
  CHECK(c.paths().size() == 4, "braided river: " << c.paths().size() << " centerline paths");
  int extended = 0;
  for(const auto& p : c.paths()) {
    extended += int(p.has_start_extension) + int(p.has_end_extension);
    CHECK(!p.closed, "braided river: a closed path");
  }
  CHECK(extended == 2, "braided river: " << extended << " extended ends");
  // the channels pass on both sides of the island
  bool above = false, below = false;
  for(const auto& line : c.polylines(1e-3))
    for(const auto& q : line)
      if(std::fabs(q.first - 10) < 0.5) {
        above = above || q.second > 2.1;
        below = below || q.second < 0.9;
      }
  CHECK(above && below, "braided river: the centerline misses a channel");
  // the paths' pieces are shared by the copies of a centerline, and outlive
  // the pruned axis and the original (the sanitizer build checks the reads)
  std::unique_ptr<CGAL::Medial_axis_centerline_2<K> > original(
    new CGAL::Medial_axis_centerline_2<K>(CGAL::medial_axis_centerline_2(CGAL::prune_medial_axis_2(sig, R), true)));
  const CGAL::Medial_axis_centerline_2<K> copy = *original;
  const auto lines = original->polylines(1e-3);
  const double length = original->length();
  original.reset();
  CHECK(copy.polylines(1e-3) == lines && copy.length() == length && copy.paths()[0].pieces.size() > 0,
        "braided river: a copy of the centerline differs once the original is gone");
}

// The extended distance function as the definition states it: an event
// simulation of the fire in the order of time (a priority queue of the
// fronts' arrivals at vertices), through the public handles only.  Returns
// the time of every vertex by id number, and the latest burning time.
std::pair<std::map<std::size_t, double>, double> reference_fire(const MA& ma)
{
  const double inf = std::numeric_limits<double>::infinity();
  struct Arc { std::size_t u, w; double length, start[2]; bool arrived[2]; };
  std::vector<Arc> arcs;
  std::map<std::size_t, std::vector<int> > at;   // the curves at each vertex
  for(const auto& e : ma.edges()) {
    arcs.push_back(Arc{e.source().id_number(), e.target().id_number(), e.length(), {inf, inf}, {false, false}});
    at[arcs.back().u].push_back(int(arcs.size()) - 1);
    at[arcs.back().w].push_back(int(arcs.size()) - 1);
  }
  std::map<std::size_t, double> time;
  std::map<std::size_t, int> arrived;
  double last = 0;
  typedef std::pair<double, std::pair<int, int> > Event;   // time, (curve, end reached)
  std::priority_queue<Event, std::vector<Event>, std::greater<Event> > q;
  auto ignite = [&](std::size_t v, double t) {
    time[v] = t;
    last = (std::max)(last, t);
    for(int i : at[v]) {
      Arc& a = arcs[std::size_t(i)];
      const int end = a.u == v ? 0 : 1;
      if(a.arrived[end]) continue;
      a.start[end] = t;
      if(a.start[1 - end] == inf) q.push(Event(t + a.length, std::make_pair(i, 1 - end)));
      else last = (std::max)(last, 0.5 * (a.start[0] + a.start[1] + a.length));
      break;
    }
  };
  for(const auto& x : at)
    if(x.second.size() == 1) ignite(x.first, 0);
  while(!q.empty()) {
    const Event e = q.top();
    q.pop();
    Arc& a = arcs[std::size_t(e.second.first)];
    const int end = e.second.second;
    if(a.start[end] != inf) continue;   // the fronts met inside the curve
    a.arrived[end] = true;
    const std::size_t v = end == 0 ? a.u : a.w;
    if(a.u == a.w) a.arrived[1 - end] = true;
    if(time.count(v) == 0 && ++arrived[v] + 1 >= int(at[v].size())) ignite(v, e.first);
  }
  return {time, last};
}

// The linear algorithm gives the times of the event simulation at every
// vertex, and its latest burning time.
void check_against_simulation(const MA& ma, const CGAL::Medial_axis_significance_2<K>& sig, const std::string& what)
{
  const auto ref = reference_fire(ma);
  const double tol = 1e-9 * (1 + ref.second);
  CHECK(std::fabs(sig.last_burning_time() - ref.second) <= tol,
        what << ": latest burning time " << sig.last_burning_time() << ", by simulation " << ref.second);
  for(const auto& v : ma.vertices()) {
    const auto it = ref.first.find(v.id_number());
    const double expected = it == ref.first.end() ? std::numeric_limits<double>::infinity() : it->second;
    const double got = sig.extended_distance(v);
    CHECK(got == expected || std::fabs(got - expected) <= tol,
          what << ": a vertex burns at " << got << ", by simulation at " << expected);
  }
}

// Ties: symmetric shapes, where fronts arrive at a vertex at equal times
// and meet exactly at vertices (a regular polygon, a square with a square
// hole, a cross, a grid polygon).
void test_ties()
{
  std::vector<std::pair<std::string, Rings> > shapes;
  Rings ngon(1);
  for(int i = 0; i < 12; ++i) ngon[0].push_back(Point(std::cos(2 * pi * i / 12), std::sin(2 * pi * i / 12)));
  shapes.emplace_back("regular 12-gon", ngon);
  shapes.emplace_back("square with a square hole",
                      Rings{{Point(0, 0), Point(4, 0), Point(4, 4), Point(0, 4)},
                            {Point(1, 1), Point(1, 3), Point(3, 3), Point(3, 1)}});
  shapes.emplace_back("cross", Rings{{Point(1, 0), Point(2, 0), Point(2, 1), Point(3, 1), Point(3, 2), Point(2, 2),
                                      Point(2, 3), Point(1, 3), Point(1, 2), Point(0, 2), Point(0, 1), Point(1, 1)}});
  shapes.emplace_back("rectangle 2 x 1", Rings{{Point(0, 0), Point(2, 0), Point(2, 1), Point(0, 1)}});
  shapes.emplace_back("grid comb", Rings{{Point(0, 0), Point(5, 0), Point(5, 3), Point(4, 3), Point(4, 1), Point(3, 1),
                                          Point(3, 3), Point(2, 3), Point(2, 1), Point(1, 1), Point(1, 3), Point(0, 3)}});
  for(const auto& x : shapes) {
    const MA ma = CGAL::medial_axis_2(x.second);
    const CGAL::Medial_axis_significance_2<K> sig(ma);
    check_against_simulation(ma, sig, x.first);
    // pruning at every threshold keeps the topology
    for(double et : {0.01, 0.2, 0.5}) {
      const Pruned p = CGAL::prune_medial_axis_2(sig, et);
      const pma_test::Pruned_graph g = pma_test::pruned_graph(p);
      const bool point = p.curves().empty() && p.isolated_points().size() == 1;
      CHECK(point || (g.components == 1 && g.cycles == int(x.second.size()) - 1),
            x.first << ", et=" << et << ": " << g.components << " components, " << g.cycles << " cycles");
    }
  }
}

// The invariants of the grassfire transform, and pruning keeps the topology,
// on random polygons with holes.
void test_invariants()
{
  for(int i = 0; i < 60; ++i) {
    const std::uint64_t seed = 5000u + std::uint64_t(i);
    const Rings r = pma_test::random_polygon_with_holes(seed, 20 + i * 7, i % 4);
    const MA ma = CGAL::medial_axis_2(r);
    const CGAL::Medial_axis_significance_2<K> sig(ma);
    const std::string what = "random polygon " + std::to_string(seed);
    const int holes = int(r.size()) - 1;
    check_against_simulation(ma, sig, what);
    for(const auto& v : ma.vertices()) {
      const double t = sig.extended_distance(v);
      CHECK(sig.erosion_thickness(v) >= 0, what << ": negative erosion thickness");
      if(v.kind() == MA::TERMINAL_POINT) CHECK(t == 0, what << ": an end burns at " << t);
      if(holes == 0) CHECK(std::isfinite(t), what << ": a vertex never burns without holes");
    }
    // ET never decreases in the direction the fire runs
    for(const auto& e : ma.edges()) {
      const auto b = sig.burning(e);
      const double L = e.length();
      if(b == CGAL::Medial_axis_significance_2<K>::FROM_SOURCE || b == CGAL::Medial_axis_significance_2<K>::FROM_TARGET) {
        const double s0 = b == CGAL::Medial_axis_significance_2<K>::FROM_SOURCE ? 0 : L;
        double last = sig.erosion_thickness(e, s0);
        for(int k = 1; k <= 8; ++k) {
          const double s = b == CGAL::Medial_axis_significance_2<K>::FROM_SOURCE ? L * k / 8 : L * (8 - k) / 8;
          const double et = sig.erosion_thickness(e, s);
          CHECK(et >= last - 1e-9 * (1 + std::fabs(last)), what << ": ET decreases along the fire, " << last << " then " << et);
          last = et;
        }
      }
      if(holes == 0) CHECK(b != CGAL::Medial_axis_significance_2<K>::NOT_BURNING, what << ": a curve never burns");
    }
    const double R = CGAL::to_double(CGAL::maximum_inscribed_circle_2(ma).radius);
    for(double f : {0.05, 0.3, 1.0}) {
      const Pruned p = CGAL::prune_medial_axis_2(sig, f * R, f == 1.0 ? 0.2 : 0);
      const pma_test::Pruned_graph g = pma_test::pruned_graph(p);
      const bool point = p.curves().empty() && p.isolated_points().size() == 1;
      CHECK(point || (g.components == 1 && g.cycles == holes),
            what << ", et=" << f << "R: " << g.components << " components, " << g.cycles << " cycles, " << holes
                 << " holes");
      CHECK(holes == 0 || !p.curves().empty(), what << ": cycles pruned away");
      // without holes the centerline is the longest path between two ends
      if(holes == 0 && !p.curves().empty()) {
        const auto c = CGAL::medial_axis_centerline_2(p, false);
        const double longest = pma_test::longest_path(p);
        CHECK(c.paths().size() == 1 && std::fabs(c.length() - longest) <= 1e-9 * (1 + longest),
              what << ", et=" << f << "R: centerline of " << c.paths().size() << " paths, length " << c.length()
                   << ", the longest path is " << longest);
      }
      for(const auto& c : p.curves())
        CHECK(c.begin >= 0 && c.end <= c.halfedge.length() && c.begin <= c.end, what << ": kept part out of its curve");
    }
  }
}

// A parabolic arc is exactly its quadratic Bezier curve: every point of the
// Bezier curve is as far from the focus as from the directrix.
void test_bezier()
{
  const Rings r = pma_test::random_polygon_with_holes(77, 80, 2);
  const MA ma = CGAL::medial_axis_2(r);
  int arcs = 0;
  for(const auto& e : ma.edges()) {
    if(e.curve_kind() != MA::PARABOLIC_ARC) continue;
    ++arcs;
    const auto f = e.first_generator().is_point() ? e.first_generator() : e.second_generator();
    const auto s = e.first_generator().is_point() ? e.second_generator() : e.first_generator();
    const auto p = MA::to_xy(f.source()), a = MA::to_xy(s.source()), b = MA::to_xy(s.target());
    const double L = e.length();
    for(double lo : {0.0, 0.25 * L})
      for(double hi : {L, 0.75 * L}) {
        const auto z = e.quadratic_bezier(lo, hi);
        for(double t = 0; t <= 1; t += 0.125) {
          const double x = (1 - t) * (1 - t) * z[0].first + 2 * t * (1 - t) * z[1].first + t * t * z[2].first;
          const double y = (1 - t) * (1 - t) * z[0].second + 2 * t * (1 - t) * z[1].second + t * t * z[2].second;
          const double to_focus = std::hypot(x - p.first, y - p.second);
          const double to_line = std::fabs((b.first - a.first) * (y - a.second) - (b.second - a.second) * (x - a.first)) /
                                 std::hypot(b.first - a.first, b.second - a.second);
          CHECK(std::fabs(to_focus - to_line) <= 1e-9 * (1 + to_focus), "Bezier point off the parabola by "
                                                                          << to_focus - to_line);
        }
        // its ends are the ends of the part
        const auto q0 = e.point_at(lo), q1 = e.point_at(hi);
        CHECK(std::hypot(q0.first - z[0].first, q0.second - z[0].second) <= 1e-9 * (1 + L) &&
                std::hypot(q1.first - z[2].first, q1.second - z[2].second) <= 1e-9 * (1 + L),
              "Bezier ends are not the ends of the part");
      }
    // arc length: point_at(s) is at arc length s
    const auto poly = e.polyline(1e-9 * L, 0, 0.5 * L);
    double len = 0;
    for(std::size_t i = 1; i < poly.size(); ++i)
      len += std::hypot(poly[i].first - poly[i - 1].first, poly[i].second - poly[i - 1].second);
    CHECK(std::fabs(len - 0.5 * L) <= 1e-6 * L, "half the arc has length " << len << " of " << L);
  }
  CHECK(arcs > 10, "only " << arcs << " parabolic arcs");
}

// The maximum inscribed circle of simple shapes, with ties.
void test_circle()
{
  // a 10 x 2 rectangle: the largest disks slide along y = 1 from x = 1 to 9;
  // the tie is broken by the smallest x
  const Rings rect = {{Point(0, 0), Point(10, 0), Point(10, 2), Point(0, 2)}};
  const auto c = CGAL::maximum_inscribed_circle_2(CGAL::medial_axis_2(rect));
  CHECK(c.center == Point(1, 1) && c.radius == 1, "rectangle: circle " << c.center << " " << c.radius);
  // a square with a square hole: the largest disks sit in the four corners,
  // touching two outer edges and a corner of the hole, centre (c, c) with
  // c = sqrt(2) (2 - c); the tie is broken by the smallest (x, y)
  const Rings frame = {{Point(0, 0), Point(6, 0), Point(6, 6), Point(0, 6)},
                       {Point(2, 2), Point(2, 4), Point(4, 4), Point(4, 2)}};
  const auto f = CGAL::maximum_inscribed_circle_2(CGAL::medial_axis_2(frame));
  const double c0 = 2 * std::sqrt(2.0) / (1 + std::sqrt(2.0));
  CHECK(std::fabs(f.radius - c0) < 1e-15 && std::fabs(f.center.x() - c0) < 1e-15 && std::fabs(f.center.y() - c0) < 1e-15,
        "frame: circle " << f.center << " " << f.radius);
}

} // namespace

int main()
{
  test_circle();
  test_bezier();
  test_arms();
  test_band();
  test_braided();
  test_invariants();
  test_ties();
  return pma_test::report("test_pruning");
}
