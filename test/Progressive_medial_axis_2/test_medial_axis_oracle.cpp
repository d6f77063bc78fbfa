// Tests the medial axis against CGAL's Segment_Delaunay_graph_2 (the test
// oracle) on random simple polygons, at every progressive step of some of
// them, and on the shapes shipped in data/; checks the invariants of the
// axis at every step compared.
//
//   test_medial_axis_oracle [--quick] [--only SECTION,...] [--skip SHAPE]
//       sections: regressions, random, holes, data, lakes, degenerate, fine, touching, union, double
//                           [--traits filtered|epick|exact] [--seed-base N]
//                           [--driver region|boundary]
//
// On a failure it prints the seed and the polygon as WKT, to be minimised
// and added to data/regressions/.

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>
#include <CGAL/Progressive_medial_axis_2/maximum_inscribed_circle_2.h>
#include <CGAL/Progressive_medial_axis_2/medial_axis_union_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/CORE_Expr.h>
#include <pma_tool/medial_axis_io.h>
#include <pma_tool/polygon_io.h>

#include <pma_test/check.h>
#include <pma_test/sdg_oracle.h>
#include <pma_test/random_polygons.h>
#include <pma_test/degenerate_shapes.h>
#include <pma_test/compare_curves.h>
#include <pma_test/pruned_graph.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <iostream>
#include <functional>
#include <iomanip>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace {

typedef CGAL::Epick::Point_2 Point;
typedef std::vector<std::vector<Point> > Rings;


std::string wkt(const Rings& rings)
{
  std::ostringstream s;
  pma_tool::write_wkt_polygon(s, rings);
  return s.str();
}

double distance_to_segment(double px, double py, double ax, double ay, double bx, double by)
{
  double dx = bx - ax, dy = by - ay;
  double t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
  t = (std::max)(0.0, (std::min)(1.0, t));
  return std::hypot(px - ax - t * dx, py - ay - t * dy);
}

// Even-odd point in polygon test on the shape's rings (double precision; used
// only for points well inside).
bool inside(const std::vector<std::vector<std::pair<double, double> > >& rings, double x, double y)
{
  bool in = false;
  for(const auto& r : rings)
    for(std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
      if((r[i].second > y) != (r[j].second > y) &&
         x < (r[j].first - r[i].first) * (y - r[i].second) / (r[j].second - r[i].second) + r[i].first)
        in = !in;
    }
  return in;
}

double boundary_distance(const std::vector<std::vector<std::pair<double, double> > >& rings, double x, double y)
{
  double d = 1e300;
  for(const auto& r : rings)
    for(std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
      d = (std::min)(d, distance_to_segment(x, y, r[j].first, r[j].second, r[i].first, r[i].second));
  return d;
}

// The driver of the progressive runs (--driver region|boundary).
CGAL::Progressive_medial_axis_driver g_driver = CGAL::REGION_GROWING;
// one-shots whose triangulation was split along a chord (main() lowers the
// size from which it is, so that the random polygons take that path)
std::size_t g_split_one_shots = 0;
// ... of them, those split along a path through holes (every other one-shot
// looks for such a path before a chord)
std::size_t g_path_split_one_shots = 0;
// One-shots whose last parts were cut smaller (main() lowers the size from
// which this is done, for the test polygons, which are small).
std::size_t g_tapered_one_shots = 0;
// one-shots that counted the steps of region growing from their triangles
std::size_t g_counted_steps = 0;
int g_default_min_tail_target = 0;

// f() computed in a task arena of `threads` threads (0: where it is called;
// without oneTBB always there).
template <class F>
auto in_arena(int threads, const F& f) -> decltype(f())
{
#ifdef CGAL_LINKED_WITH_TBB
  if(threads > 0) {
    decltype(f()) r;
    tbb::task_arena(threads).execute([&] { r = f(); });
    return r;
  }
#else
  (void)threads;
#endif
  return f();
}

struct Options {
  bool quick = false;
  std::string only;
  std::vector<std::string> skip;   // data shapes not to test
  bool no_grid = false;            // no rectilinear random polygons (exact ties everywhere)
  std::string traits = "filtered";
  std::uint64_t seed_base = 0;
};

template <class Traits>
class Checker
{
public:
  typedef CGAL::Progressive_medial_axis_2<Traits> PMA;
  typedef typename PMA::Medial_axis MA;
  typedef pma_tool::Generator_names<MA> Names;

  // Compares the current axis of `pma` with the oracle and checks the
  // invariants.  `input_names`: name generators by the input (full shape).
  bool compare(const PMA& pma, bool input_names, const std::string& what, const Rings& input)
  {
    return compare(pma.medial_axis(), std::to_string(pma.current_step()), input_names, what, input);
  }

  // The same for an axis `ma`; `step` names it in messages.
  bool compare(const MA& ma, const std::string& step, bool input_names, const std::string& what, const Rings& input)
  {
    Names names(ma, input_names ? Names::INPUT : Names::SHAPE);
    Names shape_names(ma, Names::SHAPE);
    Rings shape;
    std::vector<std::vector<std::pair<double, double> > > shape_xy;
    for(const auto& r : shape_names.rings()) {
      shape.emplace_back();
      shape_xy.emplace_back();
      for(const auto& v : r) {
        auto p = MA::to_xy(ma.point(v));
        shape.back().push_back(Point(p.first, p.second));
        shape_xy.back().push_back(p);
      }
    }
    const Rings& oracle_rings = input_names ? input : shape;
    pma_test::Oracle_result oracle;
    try {
      oracle = pma_test::sdg_medial_axis(oracle_rings);
    } catch(const std::invalid_argument& e) {
      CHECK(false, what << " step " << step << ": the oracle rejects the shape: " << e.what() << "\n  shape: "
                        << wkt(oracle_rings));
      return false;
    }
    std::vector<pma_test::Oracle_curve> ours;
    for(const auto& c : pma_tool::named_curves(ma, names))
      ours.push_back(pma_test::Oracle_curve{c.a, c.b, c.length});
    pma_test::Curve_diff diff = pma_test::compare_curves(ours, oracle.curves, oracle.bbox_diagonal);
    const int before = pma_test::failures();
    CHECK(diff.ok(), what << " step " << step << ": pairs differ from the oracle (ours | oracle)\n"
                          << diff.report() << "  shape: " << wkt(oracle_rings));
    // Where rings touch, the interior may have several parts and a hole touching
    // another ring adds no cycle: the topological checks below assume neither.
    std::vector<std::pair<double, double> > all;
    for(const auto& r : shape_xy) all.insert(all.end(), r.begin(), r.end());
    std::sort(all.begin(), all.end());
    const bool touching = std::adjacent_find(all.begin(), all.end()) != all.end();
    check_invariants(ma, step, what, shape_xy, oracle.bbox_diagonal, int(shape.size()) - 1, !touching);
    check_inscribed_circle(ma, step, what, oracle, shape_xy);
    if(correctly_rounded)
      check_rounding(ma, names, step, what, oracle);
    if(input_names && !touching) check_pruning(ma, step, what, int(shape.size()) - 1);
    ++comparisons;
    return pma_test::failures() == before;
  }

  // With exact decisions, a branch point is the exact point correctly
  // rounded (ties to even), as is the oracle's: every branch point of three
  // generators equals the oracle's branch point of the same generators.
  // (Where four or more generators meet, ours is computed from one triple
  // of them and the oracle may list two nearly coincident points.)
  void check_rounding(const MA& ma, const Names& names, const std::string& step, const std::string& what,
                      const pma_test::Oracle_result& oracle)
  {
    std::map<std::vector<std::string>, const pma_test::Oracle_branch*> by_generators;
    for(const auto& b : oracle.branches)
      if(b.generators.size() == 3) {
        const auto inserted = by_generators.emplace(b.generators, &b);
        if(!inserted.second) inserted.first->second = nullptr;   // listed twice: not compared
      }
    std::size_t differ = 0;
    std::ostringstream first;
    for(const auto& v : ma.vertices()) {
      if(v.kind() != MA::BRANCH_POINT) continue;
      std::vector<std::string> g;
      for(const auto& gen : v.generators()) g.push_back(names(gen));
      if(g.size() != 3) continue;
      std::sort(g.begin(), g.end());
      const auto found = by_generators.find(g);
      if(found == by_generators.end() || found->second == nullptr) continue;
      const pma_test::Oracle_branch& b = *found->second;
      const auto p = MA::to_xy(v.point());
      const double r = CGAL::to_double(v.radius());
      ++rounding_comparisons;
      if(p.first == b.x && p.second == b.y && r == b.r) continue;
      if(differ++ == 0)
        first << g[0] << " " << g[1] << " " << g[2] << std::setprecision(17) << " at (" << p.first << ", "
              << p.second << ") r=" << r << ", the oracle's at (" << b.x << ", " << b.y << ") r=" << b.r;
    }
    CHECK(differ == 0, what << " step " << step << ": " << differ
                            << " branch points differ from the oracle's correctly rounded ones, the first: "
                            << first.str());
  }

  // The maximum inscribed circle: at least as large as the oracle's largest
  // branch point, and an empty disk (its centre is as far from the boundary
  // as its radius).  The oracle lists a point where four or more generators
  // meet only with all its generators, so it can miss the largest one.
  void check_inscribed_circle(const MA& ma, const std::string& step, const std::string& what,
                              const pma_test::Oracle_result& oracle,
                              const std::vector<std::vector<std::pair<double, double> > >& shape)
  {
    double best = 0;
    for(const auto& b : oracle.branches) best = (std::max)(best, b.r);
    const auto c = CGAL::maximum_inscribed_circle_2(ma);
    const double r = CGAL::to_double(c.radius);
    const auto p = MA::to_xy(c.center);
    const double tol = 1e-9 * oracle.bbox_diagonal;
    CHECK(r >= best - tol, what << " step " << step << ": maximum inscribed circle of radius " << r
                                << ", the oracle has a branch point of radius " << best);
    const double d = boundary_distance(shape, p.first, p.second);
    CHECK(std::fabs(d - r) <= tol && (d <= tol || inside(shape, p.first, p.second)),
          what << " step " << step << ": the maximum inscribed circle at (" << p.first << ", " << p.second
               << ") of radius " << r << " is at distance " << d << " from the boundary");
    CHECK(c.vertex && c.vertex.point() == c.center, what << " step " << step << ": the circle's vertex");
    // With exact decisions both are the exact points correctly rounded: the
    // oracle's largest branch point (ties broken by the smallest (x, y)) is
    // the circle, where both are points of three generators.
    if(!correctly_rounded || !c.vertex) return;
    const pma_test::Oracle_branch* top = nullptr;
    for(const auto& b : oracle.branches)
      if(!top || b.r > top->r || (b.r == top->r && std::make_pair(b.x, b.y) < std::make_pair(top->x, top->y)))
        top = &b;
    std::size_t generators = 0;
    for(const auto& g : c.vertex.generators()) { (void)g; ++generators; }
    if(top == nullptr || top->generators.size() != 3 || generators != 3) return;
    ++circle_comparisons;
    CHECK(r == top->r && p.first == top->x && p.second == top->y,
          what << " step " << step << std::setprecision(17) << ": the maximum inscribed circle (" << p.first << ", "
               << p.second << ") r=" << r << ", the oracle's largest branch point (" << top->x << ", " << top->y
               << ") r=" << top->r);
  }

  // Pruning keeps the topology of the shape: one component, one cycle per
  // hole (or a single point).
  void check_pruning(const MA& ma, const std::string& step, const std::string& what, int holes)
  {
    const CGAL::Medial_axis_significance_2<typename Traits::Kernel> sig(ma);
    const double R = CGAL::to_double(CGAL::maximum_inscribed_circle_2(ma).radius);
    const auto pruned = CGAL::prune_medial_axis_2(sig, 0.25 * R, 0.1);
    const pma_test::Pruned_graph g = pma_test::pruned_graph(pruned);
    const bool point = pruned.curves().empty() && pruned.isolated_points().size() == 1 && holes == 0;
    CHECK(point || (g.components == 1 && g.cycles == holes),
          what << " step " << step << ": the pruned axis has " << g.components << " components and " << g.cycles
               << " cycles, the shape " << holes << " holes");
  }

  void check_invariants(const MA& ma, const std::string& step, const std::string& what,
                        const std::vector<std::vector<std::pair<double, double> > >& shape,
                        double diagonal, int holes, bool topology = true)
  {
    // The half-edge structure is valid (linked both ways, one cycle a cell,
    // one fan a vertex), whatever the oracle says of the curves.
    CHECK(ma.is_valid(true), what << " step " << step << ": the half-edge structure is not valid");
    // The medial axis is connected and has one independent cycle per hole.
    typedef typename MA::Vertex_handle Vertex;
    std::size_t nv = 0, ne = 0;
    std::map<Vertex, Vertex> parent;
    for(const auto& v : ma.vertices()) { ++nv; parent[v] = v; }
    auto find = [&](Vertex x) {
      while(parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    int components = 0;
    for(const auto& e : ma.edges()) {
      ++ne;
      Vertex a = find(e.source()), b = find(e.target());
      if(a != b) parent[a] = b;
    }
    for(const auto& v : ma.vertices())
      if(find(v) == v) ++components;
    CHECK(!topology || components == 1, what << " step " << step << ": the axis has " << components << " components");
    CHECK(!topology || long(ne) - long(nv) + 1 == holes,
          what << " step " << step << ": the axis has " << (long(ne) - long(nv) + 1)
               << " independent cycles, the shape " << holes << " holes");

    // Branch points are equidistant from their generators.
    for(const auto& v : ma.vertices()) {
      if(v.kind() != MA::BRANCH_POINT) continue;
      auto p = MA::to_xy(v.point());
      double r = CGAL::to_double(v.radius());
      double scale = (std::max)(std::fabs(p.first), std::fabs(p.second));
      double tol = 1e-9 * r + 64 * scale * 2.220446049250313e-16;
      for(const auto& g : v.generators()) {
        auto a = MA::to_xy(g.source()), b = MA::to_xy(g.target());
        double d = g.is_point() ? std::hypot(p.first - a.first, p.second - a.second)
                                : distance_to_segment(p.first, p.second, a.first, a.second, b.first, b.second);
        CHECK(std::fabs(d - r) <= tol, what << " step " << step << ": branch point (" << p.first << ", "
                                             << p.second << ") r=" << r << " is at distance " << d << " of "
                                             << g.id());
      }
    }
    // Every curve lies inside the shape: vertices inside or on the boundary,
    // interior samples strictly inside.
    for(const auto& e : ma.edges()) {
      auto pl = e.polyline(1e-3 * diagonal);
      for(std::size_t i = 0; i < pl.size(); ++i) {
        double x = pl[i].first, y = pl[i].second;
        double bd = boundary_distance(shape, x, y);
        bool ok = bd <= 1e-9 * diagonal || inside(shape, x, y);
        CHECK(ok, what << " step " << step << ": curve " << e.first_generator().id() << "/"
                       << e.second_generator().id() << " leaves the shape at (" << x << ", " << y << ")");
        if(!ok) break;
      }
    }
  }

  // the default model (exact decisions): its branch points are the exact
  // points correctly rounded, comparable exactly with the oracle's
  static constexpr bool correctly_rounded = std::is_same<Traits, CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> >::value;

  std::size_t comparisons = 0;
  std::size_t rounding_comparisons = 0;   // branch points compared exactly with the oracle's
  std::size_t circle_comparisons = 0;     // maximum inscribed circles compared exactly
};

// Compares the full axis and, with every_step, the axis of every step, or
// else the axes of the steps at the given fractions of the step count.
template <class Traits>
bool run_polygon(Checker<Traits>& checker, const Rings& rings, const std::string& what, bool every_step,
                 std::vector<double> fractions = {})
{
  typedef CGAL::Progressive_medial_axis_2<Traits> PMA;
  PMA pma(rings, g_driver);
  const int before = pma_test::failures();
  if(every_step) {
    do {
      if(!checker.compare(pma, false, what, rings)) break;
    } while(pma.refine());
  } else {
    for(double f : fractions) {
      std::size_t s = std::size_t(f * double(pma.number_of_steps()));
      if(s >= pma.number_of_steps() || s < pma.current_step()) continue;
      pma.refine_to(s);
      if(!checker.compare(pma, false, what, rings)) break;
    }
  }
  pma.refine_all();
  if(pma_test::failures() == before)
    checker.compare(pma, true, what, rings);
  // exact decisions never force an event; the double model redoes such merges
  CHECK(pma.statistics().anomalies == 0, what << ": " << pma.statistics().anomalies << " forced events");
  CHECK(pma.statistics().undecided_ties == 0, what << ": " << pma.statistics().undecided_ties << " undecided ties");
  // the one-shot divide and conquer, cut into 1 to 9, 16 or 25 parts (with
  // region growing; many parts as the default gives large polygons: each
  // moved into the result while others are built)
  if(pma_test::failures() == before && g_driver == CGAL::REGION_GROWING) {
    static std::size_t count = 0;
    static const std::size_t part_counts[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 16, 25};
    const std::size_t cycle = sizeof(part_counts) / sizeof(part_counts[0]);
    const std::size_t parts = part_counts[count % cycle];
    // every other cycle on one thread, where all parts are built in the
    // result's structure instead of moved into it
    const bool one_thread = (count / cycle) % 2 == 1;
    // every third one-shot first probes 1 to 60 triangles of up to four
    // parts, which the divide and conquer then goes on from
    const std::size_t probe_limit = count % 3 == 2 ? 1 + (count * 7) % 60 : 0;
    ++count;
    CGAL::Progressive_medial_axis_statistics stats;
    CGAL::Progressive_medial_axes::internal::split_triangulation_paths_first() = count % 2 == 0;
    CGAL::Progressive_medial_axes::internal::one_shots_count_region_growing_steps() = true;
    auto one_shot = [&] {
      return CGAL::Progressive_medial_axes::internal::one_shot_medial_axis(
        CGAL::Progressive_medial_axes::internal::rings_of<typename Traits::Kernel>(rings), Traits(), CGAL::CHECK_INPUT,
        &stats, parts, probe_limit);
    };
    const auto ma = in_arena(one_thread ? 1 : 0, one_shot);
    checker.compare(ma,
                    "one-shot in " + std::to_string(parts) + " parts" + (one_thread ? " on one thread" : "") +
                      (probe_limit ? ", probed " + std::to_string(probe_limit) + " triangles a part" : ""),
                    true, what, rings);
    CHECK(stats.anomalies == 0, what << ": " << stats.anomalies << " forced events in the one-shot");
    CHECK(stats.undecided_ties == 0, what << ": " << stats.undecided_ties << " undecided ties in the one-shot");
    CHECK(stats.region_growing_one_shots == 0, what << ": the one-shot met an anomaly and was computed again by region growing");
    g_split_one_shots += stats.split_triangulations;
    g_path_split_one_shots += stats.split_triangulation_holes > 0 ? 1 : 0;
    CGAL::Progressive_medial_axes::internal::split_triangulation_paths_first() = false;
    CGAL::Progressive_medial_axes::internal::one_shots_count_region_growing_steps() = false;
    // the steps of region growing, counted from the one-shot's triangles
    // unless it triangulated the polygon in two sides (the tool's --stats)
    CHECK(stats.region_growing_steps.has_value() == (stats.split_triangulations == 0),
          what << ": the one-shot " << (stats.region_growing_steps ? "counted" : "did not count")
               << " the steps of region growing, split_triangulations " << stats.split_triangulations);
    if(stats.region_growing_steps) {
      ++g_counted_steps;
      CHECK(*stats.region_growing_steps == pma.number_of_steps(),
            what << ": the one-shot counted " << *stats.region_growing_steps << " steps of region growing, it takes "
                 << pma.number_of_steps());
    }
    // (the last parts cut smaller: several times the parts asked for)
    if(stats.parts > parts + 1) ++g_tapered_one_shots;
    // never where a vertex lies inside an edge: its point and its edge could
    // fall on different sides, unseen by both
    if(stats.split_triangulations != 0)
      CHECK(!CGAL::Progressive_medial_axes::internal::validate_and_find_vertices_on_edges(rings),
            what << ": a polygon with a vertex inside an edge triangulated in two sides");
  }
  return pma_test::failures() == before;
}

Rings reversed_if(const Rings& r, bool rev)
{
  Rings out = r;
  if(rev)
    for(auto& ring : out) std::reverse(ring.begin(), ring.end());
  return out;
}

template <class Traits>
void random_tests(Checker<Traits>& checker, const Options& o)
{
  const int per_kind = o.quick ? 40 : 400;
  const int step_polygons = o.quick ? 4 : 12;
  int done = 0;
  for(int kind = 0; kind < 3; ++kind) {
    if(kind == 2 && o.no_grid) {
      std::cout << "random: rectilinear polygons skipped\n";
      continue;
    }
    for(int i = 0; i < per_kind; ++i) {
      std::uint64_t seed = o.seed_base + std::uint64_t(kind) * 1000003u + std::uint64_t(i);
      int n = 3 + int((seed * 2654435761u) % 298);
      Rings rings(1);
      std::string name;
      switch(kind) {
      case 0: rings[0] = pma_test::random_star_polygon(seed, n); name = "star"; break;
      case 1: rings[0] = pma_test::random_walk_polygon(seed, (std::max)(n, 4)); name = "walk"; break;
      default: rings[0] = pma_test::random_rectilinear_polygon(seed, 1 + n / 3, (i % 2) == 1); name = "rectilinear"; break;
      }
      rings = reversed_if(rings, i % 5 == 4);
      std::string what = name + " seed " + std::to_string(seed) + " (" + std::to_string(rings[0].size()) + " vertices)";
      bool every = i < step_polygons;
      if(!run_polygon(checker, rings, what, every, {0.01, 0.33, 0.5, 0.75})) {
        std::cerr << "  failing polygon: " << wkt(rings) << "\n";
        if(pma_test::failures() > 20) return;
      }
      ++done;
    }
  }
  std::cout << "random: " << done << " polygons\n";
}

// Random polygons with 1 to 50 holes (small star-shaped holes inside a star
// or a rectangle), some of them compared at every step.
template <class Traits>
void hole_tests(Checker<Traits>& checker, const Options& o)
{
  const int count = o.quick ? 50 : 500;
  const int step_polygons = o.quick ? 3 : 10;
  int done = 0;
  for(int i = 0; i < count; ++i) {
    std::uint64_t seed = o.seed_base + 7000001u + std::uint64_t(i);
    int holes = 1 + int((seed * 2654435761u) % 50);
    int outer = (i % 3 == 0) ? 4 : 5 + int((seed * 40503u) % 60);
    Rings rings = pma_test::random_polygon_with_holes(seed, outer, holes);
    rings = reversed_if(rings, i % 4 == 3);
    std::size_t n = 0;
    for(const auto& r : rings) n += r.size();
    std::string what = "holes seed " + std::to_string(seed) + " (" + std::to_string(rings.size() - 1) + " holes, " +
                       std::to_string(n) + " vertices)";
    if(!run_polygon(checker, rings, what, i < step_polygons, {0.01, 0.2, 0.4, 0.6, 0.8, 0.95})) {
      std::cerr << "  failing polygon: " << wkt(rings) << "\n";
      if(pma_test::failures() > 20) return;
    }
    ++done;
  }
  std::cout << "holes: " << done << " polygons\n";
}

std::vector<std::string> list_wkt(const std::string& dir)
{
  std::vector<std::string> files;
  if(DIR* d = opendir(dir.c_str())) {
    while(dirent* e = readdir(d)) {
      std::string n = e->d_name;
      if(n.size() > 4 && n.substr(n.size() - 4) == ".wkt") files.push_back(dir + "/" + n);
    }
    closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

template <class Traits>
void data_tests(Checker<Traits>& checker, const Options& o)
{
  const std::string dir = PMA_TEST_DATA;
  // (quantized/: outlines with 5-decimal coordinates, ties on collinear and
  // flat vertices everywhere; see its README)
  for(const std::string& name : {"syn_comb50", "syn_maze20", "syn_spiral20", "syn_ngon64", "syn_star2k",
                                 "syn_sliver500", "syn_cheese1k", "c1m_GBR_0", "quantized/l10m_CAN_62_5806",
                                 "quantized/l10m_ESH_202_0"}) {
    if(o.quick && std::string(name) == "c1m_GBR_0") continue;
    if(std::find(o.skip.begin(), o.skip.end(), name) != o.skip.end()) {
      std::cout << "data: " << name << " skipped\n";
      continue;
    }
    Rings rings = pma_tool::read_polygon_file<Point>(dir + "/" + name + ".wkt");
    std::size_t n = rings[0].size();
    auto start = std::chrono::steady_clock::now();
    (void)n;
    run_polygon(checker, rings, name, false, {0.0001, 0.001, 0.1, 0.33, 0.67});
    std::cout << "data: " << name << " ("
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)\n";
  }
}

// A counter of the exact-decision traits' filter statistics, read by
// `get` (none for other traits): filter_counter<Traits>(get, 0).
template <class Traits, class Get>
auto filter_counter(const Get& get, int) -> decltype(Traits::filter_statistics(), std::optional<std::size_t>())
{
  return get(Traits::filter_statistics());
}
template <class Traits, class Get>
std::optional<std::size_t> filter_counter(const Get&, long)
{
  return std::nullopt;
}

// Map-like polygons (pma_test::random_lakes_polygon()): lakes as right
// triangles and rectangles with axis-parallel sides, on a grid of 10^-5
// near (30, 64.7).  Their disks have coordinates halfway between two
// doubles, which the exact-decision traits round from the linear relations
// of the axis-parallel sites (internal::axis_aligned_disk(); in the build
// with CGAL_PMA2_CHECK_AXIS_ALIGNED_DISKS each such coordinate is checked
// against the nested-root numbers).
template <class Traits>
void lake_tests(Checker<Traits>& checker, const Options& o)
{
  const int count = o.quick ? 20 : 150;
  int done = 0;
  for(int i = 0; i < count; ++i) {
    const std::uint64_t seed = o.seed_base + 9000011u + std::uint64_t(i);
    const int holes = 1 + int((seed * 2654435761u) % 40);
    Rings rings = pma_test::random_lakes_polygon(seed, holes);
    std::size_t n = 0;
    for(const auto& r : rings) n += r.size();
    const std::string what = "lakes seed " + std::to_string(seed) + " (" + std::to_string(holes) + " holes, " +
                             std::to_string(n) + " vertices)";
    if(!run_polygon(checker, rings, what, i < 3, {0.1, 0.5, 0.9})) {
      std::cerr << "  failing polygon: " << wkt(rings) << "\n";
      if(pma_test::failures() > 20) return;
    }
    ++done;
  }
  std::cout << "lakes: " << done << " polygons\n";
  if(const std::optional<std::size_t> axis =
       filter_counter<Traits>([](const auto& f) { return f.axis_aligned_disks; }, 0)) {
    std::cout << "lakes: " << *axis << " disks with coordinates from axis-parallel sites, in this thread\n";
    CHECK(*axis > 0, "no disk had a coordinate fixed by its axis-parallel sites");
  }
}

// Degenerate input, where exact ties are the rule: polygons of integer grid
// cells with and without holes and with 45-degree cuts, a closed Hilbert
// curve, nested Koch snowflakes with exact and decimal-rounded coordinates,
// regular polygons (also with holes), many concyclic vertices, flattened
// font glyphs.  Every tie must be decided exactly (same pairs as the
// oracle); the grid shapes are also compared at every 50th step.
template <class Traits>
void degenerate_tests(Checker<Traits>& checker, const Options& o)
{
  struct Shape {
    std::string name;
    Rings rings;
    bool every_50th;
  };
  std::vector<Shape> shapes;
  const int seeds = o.quick ? 2 : 16;
  for(int seed = 1; seed <= seeds; ++seed) {
    pma_test::Grid_cell_options few;
    few.holes = 3;
    shapes.push_back({"grid cells 30x30 seed " + std::to_string(seed), pma_test::grid_cell_polygon(seed, 30, false), true});
    shapes.push_back({"grid cells 30x30 with holes seed " + std::to_string(seed), pma_test::grid_cell_polygon(seed, 30, true, few), true});
    pma_test::Grid_cell_options flat = few;
    flat.keep_flat_vertices = true;
    flat.scale = 3;
    shapes.push_back({"grid cells 10x10, flat vertices, scale 3, seed " + std::to_string(seed), pma_test::grid_cell_polygon(seed, 10, true, flat), false});
    shapes.push_back({"grid cells 45-degree cuts seed " + std::to_string(seed), pma_test::grid_cell_polygon_45(seed, 20), true});
    shapes.push_back({"concyclic seed " + std::to_string(seed), pma_test::concyclic_polygon(seed, 24 + 8 * seed), false});
  }
  shapes.push_back({"syn_maze20", pma_tool::read_polygon_file<Point>(std::string(PMA_TEST_DATA) + "/syn_maze20.wkt"), true});
  shapes.push_back({"hilbert order 4", pma_test::hilbert_polygon(4), true});
  shapes.push_back({"hilbert order 5, no flat vertices", pma_test::hilbert_polygon(5, false), false});
  shapes.push_back({"koch order 3 exact", pma_test::koch_snowflake_nested(3, -1), false});
  shapes.push_back({"koch order 3, 6 decimals", pma_test::koch_snowflake_nested(3, 6), false});
  shapes.push_back({"koch order 4, 6 decimals", pma_test::koch_snowflake_nested(4, 6), false});
  for(int n : {5, 6, 8, 12, 60})
    shapes.push_back({"regular " + std::to_string(n) + "-gon, 6 decimals", pma_test::regular_ngon(n, 10.0, 6), false});
  shapes.push_back({"regular 96-gon", pma_test::regular_ngon(96, 1.0, -1), false});
  shapes.push_back({"regular 24-gon with 6 holes", pma_test::regular_ngon_with_holes(24, 6, 8, 10.0, 6), false});
  for(const std::string& f : list_wkt(std::string(PMA_TEST_DATA) + "/glyphs"))
    shapes.push_back({f.substr(f.find_last_of('/') + 1), pma_tool::read_polygon_file<Point>(f), false});

  for(const Shape& shape : shapes) {
    if(shape.every_50th) {
      typedef CGAL::Progressive_medial_axis_2<Traits> PMA;
      PMA pma(shape.rings, g_driver);
      std::vector<double> fractions;
      for(std::size_t s = 50; s < pma.number_of_steps(); s += 50) fractions.push_back(double(s) / double(pma.number_of_steps()));
      run_polygon(checker, shape.rings, shape.name, false, fractions);
    } else {
      run_polygon(checker, shape.rings, shape.name, false, {0.5});
    }
    if(pma_test::failures() > 20) return;
  }
  std::cout << "degenerate: " << shapes.size() << " shapes\n";
  // the symmetric shapes (regular polygons, the glyphs DejaVuSerif-Bold
  // question and FreeMono E) have ties that the exact-decision traits decide
  // by symmetry: the comparisons above tested that rule against the oracle
  // (and, in the build with CGAL_PMA2_CHECK_MIRROR_TIES, each such tie
  // against the nested-root numbers)
  if(const std::optional<std::size_t> mirror = filter_counter<Traits>([](const auto& f) { return f.mirror_ties; }, 0)) {
    std::cout << "degenerate: " << *mirror << " ties decided by symmetry in this thread\n";
    CHECK(*mirror > 0, "no tie was decided by symmetry");
  }
}

// Glyphs whose curves were flattened finely (data/glyphs_fine: 80 segments a
// curve, 2 decimals): a merge of the divide and conquer crosses about 30
// cells there, so the default one-shot (medial_axis_2()) computes the axis by
// boundary evolution instead (DejaVuSans_n, of 646 triangles, is small
// enough that the probe once passed it by).  On two threads (the choice depends on them)
// it must take that way, and give the oracle's axis; a boundary evolution
// whose budget runs out must give up, and one whose budget suffices must give
// the same axis.
template <class Traits>
void fine_tests(Checker<Traits>& checker, const Options&)
{
  namespace I = CGAL::Progressive_medial_axes::internal;
  typedef typename Traits::Kernel Kernel;
  // the driver is chosen on the default cut, which main() changed
  struct Default_tail {
    const int lowered = I::divide_and_conquer_min_tail_target().exchange(g_default_min_tail_target);
    ~Default_tail() { I::divide_and_conquer_min_tail_target() = lowered; }
  } default_tail;
  std::size_t count = 0;
  for(const std::string& f : list_wkt(std::string(PMA_TEST_DATA) + "/glyphs_fine")) {
    const Rings rings = pma_tool::read_polygon_file<Point>(f);
    const std::string what = f.substr(f.find_last_of('/') + 1);
    CGAL::Progressive_medial_axis_statistics stats;
    auto one_shot = [&] { return CGAL::medial_axis_2(rings, Traits(), CGAL::CHECK_INPUT, &stats); };
    const auto ma = in_arena(2, one_shot);
    // (exact kernels build one part, and are not probed)
    CHECK(!std::is_floating_point<typename Kernel::FT>::value || stats.boundary_evolution_one_shots == 1,
          what << ": the one-shot took the divide and conquer (" << stats.merges << " merges, "
               << stats.switches + stats.vanishings << " events)");
    checker.compare(ma, "one-shot", true, what, rings);
    if constexpr(std::is_same<Rings, std::vector<std::vector<typename Kernel::Point_2> > >::value) {
      // the rings given up to the one-shot: boundary evolution starts again
      // from the rings it rebuilds from its copy of the points
      Rings given = rings;
      CGAL::Progressive_medial_axis_statistics gs;
      const auto mg = in_arena(2, [&] { return CGAL::medial_axis_2(std::move(given), Traits(), CGAL::CHECK_INPUT, &gs); });
      CHECK(given.empty() && gs.boundary_evolution_one_shots == stats.boundary_evolution_one_shots,
            what << ": the one-shot of the rings given up");
      checker.compare(mg, "one-shot of the rings given up", true, what, rings);
    }

    const auto r = I::rings_of<Kernel>(rings);
    typename I::Medial_axis_engine<Traits>::Data starved, fed;
    CGAL::Progressive_medial_axis_statistics s;
    CHECK(!I::one_shot_by_boundary_evolution(r, Traits(), 100.0, starved, s),
          what << ": boundary evolution went on past its budget");
    const bool done = I::one_shot_by_boundary_evolution(r, Traits(), 1e12, fed, s);
    CHECK(done, what << ": boundary evolution gave up within a budget of 1e12 events");
    if(done)
      checker.compare(I::Medial_axis_access::make<Kernel>(std::make_shared<const decltype(fed)>(std::move(fed))),
                      "boundary evolution with a budget", true, what, rings);
    ++count;
    if(pma_test::failures() > 20) return;
  }
  CHECK(count > 0, "no shape in data/glyphs_fine");
  std::cout << "fine: " << count << " shapes\n";
}

// Shapes on which the double model got decisions wrong without tripping
// its checks (data/double_model): the one-shot, whichever way it takes (the
// way out takes exact decisions there), must give the oracle's axis on one
// and on two threads, never an error; and so must every step of region
// growing, and the one-shots of run_polygon(), without an anomaly (before
// the double model estimated the errors of its disks, steps 28 to 30 of 33
// of grid_perturbed_crop37 differed from the oracle without a warning;
// before its output tested folds with exact predicates, fold_2e-17 lost a
// curve in every run; before it checked its "no disk" decisions in
// intervals, point_near_line_2e-17 had a branch point outside the polygon).
template <class Traits>
void double_model_tests(Checker<Traits>& checker, const Options&)
{
  std::size_t count = 0, ways_out = 0;
  for(const std::string& f : list_wkt(std::string(PMA_TEST_DATA) + "/double_model")) {
    const Rings rings = pma_tool::read_polygon_file<Point>(f);
    const std::string what = f.substr(f.find_last_of('/') + 1);
    for(int threads : {1, 2}) {
      CGAL::Progressive_medial_axis_statistics stats;
      auto one_shot = [&] { return CGAL::medial_axis_2(rings, Traits(), CGAL::CHECK_INPUT, &stats); };
      try {
        const auto ma = in_arena(threads, one_shot);
        checker.compare(ma, "one-shot on " + std::to_string(threads) + " thread(s)", true, what, rings);
        ways_out += stats.region_growing_one_shots;
      } catch(const std::exception& e) {
        CHECK(false, what << ": the one-shot on " << threads << " thread(s) threw: " << e.what());
      }
    }
    run_polygon(checker, rings, what, true);
    ++count;
  }
  CHECK(count > 0, "no shape in data/double_model");
  std::cout << "double: " << count << " shapes, " << ways_out << " one-shots computed again by region growing\n";
}

// A rectangle of w x h unit cells with holes that touch the shell or each other
// with a vertex inside an edge (T's): in a cell, a triangle whose vertex lies
// at the middle of the cell's bottom side (on the shell, or on the top edge of
// a box hole in the cell below), a box whose top edge lies on the cell's top
// side, or, in the bottom row, an inward notch of the shell whose tip lies on
// the bottom edge of a box hole in the cell above.  x and y are swapped for
// odd seeds (vertical edges).
inline Rings t_touch_grid(int seed)
{
  pma_test::random_detail::Rng rng(std::uint64_t(104729 * seed + 3));
  const int w = 3 + int(rng.below(6)), h = 3 + int(rng.below(6));
  enum { EMPTY, TRIANGLE, BOX, NOTCH, BOX_ON_NOTCH };
  std::vector<int> cell(std::size_t(w * h), EMPTY);
  auto at = [&](int i, int j) -> int& { return cell[std::size_t(j * w + i)]; };
  for(int i = 0; i < w; ++i)
    if(rng.below(4) == 0) {
      at(i, 0) = NOTCH;
      at(i, 1) = BOX_ON_NOTCH;
    }
  for(int j = 0; j < h; ++j)
    for(int i = 0; i < w; ++i) {
      if(at(i, j) != EMPTY) continue;
      const int r = int(rng.below(5));
      if(r < 2) at(i, j) = TRIANGLE;
      else if(r < 4 && j + 1 < h) at(i, j) = BOX;
    }
  const bool swap = seed % 2 == 1;
  auto P = [&](double x, double y) { return swap ? Point(y, x) : Point(x, y); };
  Rings rings(1);
  for(int i = 0; i < w; ++i) {
    rings[0].push_back(P(i, 0));
    if(at(i, 0) == NOTCH) {
      rings[0].push_back(P(i + 0.25, 0));
      rings[0].push_back(P(i + 0.5, 1));
      rings[0].push_back(P(i + 0.75, 0));
    }
  }
  rings[0].push_back(P(w, 0));
  rings[0].push_back(P(w, h));
  rings[0].push_back(P(0, h));
  for(int j = 0; j < h; ++j)
    for(int i = 0; i < w; ++i) {
      const double x = i, y = j;
      if(at(i, j) == TRIANGLE) rings.push_back({P(x + 0.5, y), P(x + 0.8, y + 0.6), P(x + 0.25, y + 0.7)});
      else if(at(i, j) == BOX) rings.push_back({P(x + 0.2, y + 0.3), P(x + 0.8, y + 0.3), P(x + 0.8, y + 1), P(x + 0.2, y + 1)});
      else if(at(i, j) == BOX_ON_NOTCH) rings.push_back({P(x + 0.2, y), P(x + 0.8, y), P(x + 0.8, y + 0.7), P(x + 0.2, y + 0.7)});
      else continue;
      if(rng.below(2)) std::reverse(rings.back().begin(), rings.back().end());
    }
  if(swap) std::reverse(rings[0].begin(), rings[0].end());
  return rings;
}

// Rings touching at vertices: the shapes of data/touching (synthetic, and real
// outlines with such vertices), and random square shells (a vertex every 2
// units) with diamond holes in the cells of a lattice of spacing 4, which touch
// each other and the shell at vertices.  (Known limitation: where holes alone
// enclose a part of the interior, the shape of a progressive step is not one
// polygon; shape_rings() splices that part, as a lobe, into the first hole
// it touches, which makes a hole ring that touches other holes.)
template <class Traits>
void touching_tests(Checker<Traits>& checker, const Options& o)
{
  std::size_t count = 0;
  for(const std::string& f : list_wkt(std::string(PMA_TEST_DATA) + "/touching")) {
    Rings rings = pma_tool::read_polygon_file<Point>(f);
    std::size_t n = 0;
    for(const auto& r : rings) n += r.size();
    if(n < 1000) run_polygon(checker, rings, f, true);
    else run_polygon(checker, rings, f, false, {0.25, 0.5, 0.75});
    ++count;
  }
  const int seeds = o.quick ? 30 : 150;
  for(int seed = 0; seed < seeds; ++seed) {
    pma_test::random_detail::Rng rng(std::uint64_t(7919 * seed + 1));
    const int cells = 4 + int(rng.below(5));   // the shell is cells x cells cells of side 4
    Rings rings(1);
    const int side = 4 * cells;
    for(int i = 0; i < 2 * cells; ++i) rings[0].push_back(Point(2 * i, 0));
    for(int i = 0; i < 2 * cells; ++i) rings[0].push_back(Point(side, 2 * i));
    for(int i = 0; i < 2 * cells; ++i) rings[0].push_back(Point(side - 2 * i, side));
    for(int i = 0; i < 2 * cells; ++i) rings[0].push_back(Point(0, side - 2 * i));
    std::vector<char> used(std::size_t(cells * cells), 0);
    const int holes = 1 + int(rng.below(std::uint64_t(cells * cells / 2)));
    for(int h = 0; h < holes; ++h) {
      const int c = int(rng.below(std::uint64_t(cells * cells)));
      if(used[std::size_t(c)]) continue;
      // no 2 x 2 block of diamonds: it would enclose a part of the interior by holes
      // alone, which a progressive step's shape cannot write as one polygon
      const int ci = c % cells, cj = c / cells;
      auto full = [&](int i, int j) {
        if(i < 0 || j < 0 || i + 1 >= cells || j + 1 >= cells) return false;
        for(int a = 0; a < 2; ++a)
          for(int b = 0; b < 2; ++b) {
            const int d = (j + b) * cells + i + a;
            if(d != c && !used[std::size_t(d)]) return false;
          }
        return true;
      };
      if(full(ci - 1, cj - 1) || full(ci, cj - 1) || full(ci - 1, cj) || full(ci, cj)) continue;
      used[std::size_t(c)] = 1;
      const double x = 4 * (c % cells), y = 4 * (c / cells);
      rings.push_back({Point(x + 2, y), Point(x + 4, y + 2), Point(x + 2, y + 4), Point(x, y + 2)});
      if(rng.below(2)) std::reverse(rings.back().begin(), rings.back().end());
    }
    const std::string name = "touching diamonds seed " + std::to_string(seed);
    if(seed < 5) run_polygon(checker, rings, name, true);
    else run_polygon(checker, rings, name, false, {0.3, 0.6});
    ++count;
    if(pma_test::failures() > 20) return;
  }
  std::size_t with_t = 0, t_places = 0;
  for(int seed = 0; seed < seeds; ++seed) {
    const Rings rings = t_touch_grid(seed);
    std::size_t n = 0;
    for(const auto& r : rings) n += r.size();
    const std::size_t splits = pma_test::oracle_detail::make_polygon_data(rings).pts.size() - n;
    with_t += splits > 0;
    t_places += splits;
    run_polygon(checker, rings, "T-touch grid seed " + std::to_string(seed), seed < 5, {0.3, 0.6});
    ++count;
    if(pma_test::failures() > 20) return;
  }
  CHECK(with_t > std::size_t(seeds) / 2, "only " << with_t << " T-touch grids have a vertex inside an edge");
  std::cout << "touching: " << count << " shapes (" << with_t << " with " << t_places << " vertices inside edges)\n";
}


// A polygon split in two along chains of edges, for the union of two axes.
struct Split {
  Rings whole, a, b;
  int t_holes = 0;                 // holes that touch an edge at a T
  bool t_on_shared_edge = false;   // a hole of b touches the shared edge at a T
};

// A star-shaped polygon around the origin (n vertices, radii in [1, 2]),
// which contains the disk of radius 0.5 about the origin, split along a
// chain of `edges` edges from vertex ia to vertex ib: radially in from
// vertex ia to radius 0.5, then inside the disk, radially monotone (in a
// narrow sector about ia's ray down to the origin, out in a sector about
// ib's), so that the chain is simple.  With `hole`, the polygon has a small
// hole about the origin and two chains (ia and ib to the hole), so that the
// union encloses the hole.  `own_holes` small triangles lie in the parts;
// `t_holes` more touch an edge of the outer ring at its midpoint (a T), away
// from the chains.  With `t_on_diagonal` (a one-edge split without a hole),
// a hole of part b touches the diagonal at its midpoint: a T on the shared
// edge.
Split star_split(pma_test::random_detail::Rng& rng, int n, int edges, bool hole, int own_holes, int t_holes = 0,
                 bool t_on_diagonal = false)
{
  const double pi = pma_test::random_detail::pi;
  std::vector<double> theta(static_cast<std::size_t>(n)), radius(static_cast<std::size_t>(n));
  for(int i = 0; i < n; ++i) {
    theta[std::size_t(i)] = 2 * pi * (i + 0.8 * rng.uniform()) / n;
    radius[std::size_t(i)] = rng.uniform(1, 2);
  }
  const int ia = int(rng.below(std::uint64_t(n / 2)));
  // one edge: a diagonal to the next vertex but one, which lies beyond it
  const int ib = edges == 1 && !hole ? ia + 2 : ia + n / 4 + int(rng.below(std::uint64_t(n / 4)));
  if(edges == 1 && !hole) radius[std::size_t(ia + 1)] = 2.5;
  std::vector<Point> W;
  for(int i = 0; i < n; ++i)
    W.push_back(Point(radius[std::size_t(i)] * std::cos(theta[std::size_t(i)]), radius[std::size_t(i)] * std::sin(theta[std::size_t(i)])));
  const double ta = theta[std::size_t(ia)], tb = theta[std::size_t(ib)];
  const double sector = (std::min)(0.08, 0.25 * (tb - ta));
  auto polar = [](double r, double t) { return Point(r * std::cos(t), r * std::sin(t)); };
  auto on_ray = [&](int i, double r) { return Point(W[std::size_t(i)].x() * r / radius[std::size_t(i)], W[std::size_t(i)].y() * r / radius[std::size_t(i)]); };
  // a radially monotone run from radius r0 down to r1 (count points, the
  // last at r1) in the sector about angle t
  auto run = [&](double r0, double r1, int count, double t) {
    std::vector<Point> out;
    for(int k = 1; k <= count; ++k) {
      const double r = r0 + (r1 - r0) * (k - rng.uniform(0, 0.5)) / count;
      out.push_back(polar(k == count ? r1 : r, t + rng.uniform(-sector, sector)));
    }
    return out;
  };
  Split s;
  Rings hole_rings;
  std::vector<Point> chain_a, chain_b;   // from vertex ia (ib) inwards, ends excluded
  std::vector<Point> H;                  // the central hole, counter-clockwise
  int ha = -1, hb = -1;
  if(!hole) {
    // edges = 1 + the inner points: vertex ia, on_ray(ia, 0.5), ..., the
    // origin, ..., on_ray(ib, 0.5), vertex ib (none: the diagonal ia-ib)
    const int inner = edges - 1;
    if(inner == 1) {
      chain_a.push_back(Point(0, 0));
    } else if(inner >= 2) {
      const int down = inner / 2, up = inner - down;
      chain_a.push_back(on_ray(ia, 0.5));
      for(const Point& p : run(0.5, 0.0, down - 1, ta)) chain_a.push_back(p);
      std::vector<Point> rise;   // from ib's ray down, reversed later
      rise.push_back(on_ray(ib, 0.5));
      for(const Point& p : run(0.5, 0.0, up, tb)) rise.push_back(p);
      rise.pop_back();   // the origin is already the end of the first run (or close to it)
      if(down - 1 == 0) chain_a.push_back(Point(0, 0));
      else chain_a.back() = Point(0, 0);
      for(auto it = rise.rbegin(); it != rise.rend(); ++it) chain_a.push_back(*it);
    }
  } else {
    // the hole: m vertices at radius 0.15, two of them on the rays of ia and ib
    const int m = 6 + int(rng.below(6));
    for(int k = 0; k < m; ++k) {
      const double t = 2 * pi * (k + 0.5) / m;
      H.push_back(polar(0.15, t));
    }
    H.push_back(on_ray(ia, 0.15));
    H.push_back(on_ray(ib, 0.15));
    std::vector<std::pair<double, Point> > by_angle;
    for(const Point& p : H) {
      double t = std::atan2(p.y(), p.x());
      if(t < 0) t += 2 * pi;
      by_angle.emplace_back(t, p);
    }
    std::sort(by_angle.begin(), by_angle.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    H.clear();
    for(const auto& x : by_angle) {
      // drop hole vertices too close to the rays' (a thin hole edge is fine, a repeated point is not)
      const bool on_a = x.second == on_ray(ia, 0.15), on_b = x.second == on_ray(ib, 0.15);
      if(!on_a && !on_b && (std::fabs(x.first - ta) < 0.05 || std::fabs(x.first - tb) < 0.05)) continue;
      if(on_a) ha = int(H.size());
      if(on_b) hb = int(H.size());
      H.push_back(x.second);
    }
    // two chains of about edges / 2 edges each: radial from the vertex to
    // radius 0.5, a monotone run down to 0.32, then to radius 0.3 and
    // radially to the hole (with one edge: radially from the vertex to the hole)
    if(edges > 1) {
      const int each = (std::max)(3, edges / 2);
      chain_a.push_back(on_ray(ia, 0.5));
      for(const Point& p : run(0.5, 0.32, each - 3, ta)) chain_a.push_back(p);
      chain_a.push_back(on_ray(ia, 0.3));
      chain_b.push_back(on_ray(ib, 0.5));
      for(const Point& p : run(0.5, 0.32, each - 3, tb)) chain_b.push_back(p);
      chain_b.push_back(on_ray(ib, 0.3));
    }
  }
  // own holes: small triangles at radius 0.7, away from the rays of ia and ib
  std::vector<double> used{ta, tb};
  std::vector<std::pair<double, std::vector<Point> > > own;
  for(int k = 0; k < own_holes; ++k) {
    const double t = rng.uniform(0, 2 * pi);
    bool ok = true;
    for(double u : used) ok = ok && std::fabs(std::remainder(t - u, 2 * pi)) > 0.15;
    if(!ok) continue;
    used.push_back(t);
    own.emplace_back(t, std::vector<Point>{polar(0.7, t), polar(0.74, t + 0.03), polar(0.74, t - 0.03)});
  }
  // T holes: a thin triangle from the midpoint of edge i of the outer ring
  // inwards, inside the triangle of the edge and the origin (which lies in
  // the polygon: it is star-shaped about the origin); the edge's ends are
  // rounded to multiples of 2^-20 first, so that the midpoint is exact
  std::vector<std::pair<int, std::vector<Point> > > t_own;
  for(int k = 0; k < t_holes; ++k) {
    const int i = int(rng.below(std::uint64_t(n))), i1 = (i + 1) % n;
    if(i == ia || i == ib || i1 == ia || i1 == ib) continue;
    auto snap = [](const Point& x) {
      return Point(std::ldexp(std::round(std::ldexp(x.x(), 20)), -20), std::ldexp(std::round(std::ldexp(x.y(), 20)), -20));
    };
    const Point p = snap(W[std::size_t(i)]), q = snap(W[std::size_t(i1)]);
    const Point m((p.x() + q.x()) / 2, (p.y() + q.y()) / 2);
    const double t = std::atan2(m.y(), m.x()), r = std::sqrt(m.x() * m.x() + m.y() * m.y());
    bool ok = r > 0.9;
    for(double u : used) ok = ok && std::fabs(std::remainder(t - u, 2 * pi)) > 0.15;
    if(!ok) continue;
    used.push_back(t);
    W[std::size_t(i)] = p;
    W[std::size_t(i1)] = q;
    auto inward = [&](double f) {
      return Point(0.85 * (p.x() + f * (q.x() - p.x())), 0.85 * (p.y() + f * (q.y() - p.y())));
    };
    t_own.emplace_back(i, std::vector<Point>{m, inward(0.45), inward(0.55)});
  }
  std::vector<Point> t_diagonal;
  if(t_on_diagonal && edges == 1 && !hole) {
    auto snap = [](const Point& x) {
      return Point(std::ldexp(std::round(std::ldexp(x.x(), 20)), -20), std::ldexp(std::round(std::ldexp(x.y(), 20)), -20));
    };
    const Point p = snap(W[std::size_t(ia)]), q = snap(W[std::size_t(ib)]);
    W[std::size_t(ia)] = p;
    W[std::size_t(ib)] = q;
    auto inward = [&](double f) {
      return Point(0.85 * (p.x() + f * (q.x() - p.x())), 0.85 * (p.y() + f * (q.y() - p.y())));
    };
    t_diagonal = {Point((p.x() + q.x()) / 2, (p.y() + q.y()) / 2), inward(0.45), inward(0.55)};
  }
  // (with a one-edge diagonal part a is the triangle beyond it)
  auto in_a = [&](double t) { return (hole || edges > 1) && t > ta && t < tb; };
  // the whole polygon
  s.whole.push_back(W);
  if(hole) {
    s.whole.push_back(std::vector<Point>(H.rbegin(), H.rend()));
  }
  for(const auto& h : own) s.whole.push_back(h.second);
  for(const auto& h : t_own) s.whole.push_back(h.second);
  if(!t_diagonal.empty()) s.whole.push_back(t_diagonal);
  // part a: vertices ia..ib, then back to ia
  std::vector<Point> A(W.begin() + ia, W.begin() + ib + 1), B;
  for(int i = ib; i < n; ++i) B.push_back(W[std::size_t(i)]);
  for(int i = 0; i <= ia; ++i) B.push_back(W[std::size_t(i)]);
  if(!hole) {
    A.insert(A.end(), chain_a.rbegin(), chain_a.rend());
    B.insert(B.end(), chain_a.begin(), chain_a.end());
  } else {
    const int mh = int(H.size());
    A.insert(A.end(), chain_b.begin(), chain_b.end());
    for(int k = hb;; k = (k + mh - 1) % mh) {   // clockwise on the hole from hb to ha
      A.push_back(H[std::size_t(k)]);
      if(k == ha) break;
    }
    A.insert(A.end(), chain_a.rbegin(), chain_a.rend());
    B.insert(B.end(), chain_a.begin(), chain_a.end());
    for(int k = ha;; k = (k + mh - 1) % mh) {   // clockwise from ha to hb
      B.push_back(H[std::size_t(k)]);
      if(k == hb) break;
    }
    B.insert(B.end(), chain_b.rbegin(), chain_b.rend());
  }
  s.a.push_back(A);
  s.b.push_back(B);
  for(const auto& h : own) (in_a(h.first) ? s.a : s.b).push_back(h.second);
  for(const auto& h : t_own) (h.first >= ia && h.first < ib ? s.a : s.b).push_back(h.second);
  if(!t_diagonal.empty()) s.b.push_back(t_diagonal);
  s.t_holes = int(t_own.size());
  s.t_on_shared_edge = !t_diagonal.empty();
  return s;
}

// The union of two axes (medial_axis_union_2) against the oracle, on star
// polygons split along chains of 1 to 100 edges, or along two chains around
// a hole (the union encloses it), with holes in the parts; the inputs are
// left as they were; and the errors.
template <class Traits>
void union_tests(Checker<Traits>& checker, const Options& o)
{
  typedef typename Checker<Traits>::MA MA;
  auto axis = [](const Rings& r) { return CGAL::medial_axis_2(r, Traits()); };
  auto pairs = [](const MA& ma) {
    std::vector<std::pair<std::string, std::string> > out;
    for(const auto& e : ma.edges()) out.emplace_back(e.first_generator().id(), e.second_generator().id());
    return out;
  };
  auto rings_of = [](const MA& ma) {
    Rings r(ma.number_of_input_rings());
    for(std::size_t k = 0; k < r.size(); ++k)
      for(std::size_t i = 0; i < ma.input_ring_size(k); ++i)
      {
        const auto p = MA::to_xy(ma.point(typename MA::Input_vertex{int(k), int(i)}));
        r[k].push_back(Point(p.first, p.second));
      }
    return r;
  };
  std::size_t count = 0, with_t = 0, t_shared = 0, capped_unions = 0;
  const int seeds = o.quick ? 40 : 200;
  const int chain_lengths[] = {1, 2, 3, 5, 10, 30, 100};
  for(int seed = 0; seed < seeds; ++seed) {
    pma_test::random_detail::Rng rng(std::uint64_t(seed) * 7919 + 17 + o.seed_base);
    const bool hole = seed % 3 == 2;
    const int edges = chain_lengths[seed % 7];
    const int n = 12 + int(rng.below(40));
    const int t_holes = seed % 5 == 3 ? 2 : 0;
    const bool t_diagonal = edges == 1 && !hole && seed % 2 == 0;
    const Split s = star_split(rng, n, hole ? (std::max)(2, edges) : edges, hole, seed % 4 == 1 ? 3 : 0, t_holes, t_diagonal);
    const std::string name = "union seed " + std::to_string(seed) + " (" + std::to_string(edges) + " chain edges" +
                             (hole ? ", around a hole" : "") + (t_holes ? ", holes touching edges (T's)" : "") +
                             (t_diagonal ? ", a hole touching the shared edge (a T)" : "") + ")";
    MA a, b;
    try {
      a = axis(s.a);
      b = axis(s.b);
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      CHECK(false, name << ": a part is not valid: " << e.what() << "\n  a: " << wkt(s.a) << "\n  b: " << wkt(s.b));
      continue;
    }
    const auto pa = pairs(a), pb = pairs(b);
    MA u;
    CGAL::Progressive_medial_axes::Medial_axis_union_statistics stats;
    try {
      u = seed % 2 ? CGAL::medial_axis_union_2(b, a, Traits(), &stats) : CGAL::medial_axis_union_2(a, b, Traits(), &stats);
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      CHECK(false, name << ": " << e.what() << "\n  a: " << wkt(s.a) << "\n  b: " << wkt(s.b));
      continue;
    } catch(...) {
      CHECK(false, name << ": an exception\n  a: " << wkt(s.a) << "\n  b: " << wkt(s.b));
      continue;
    }
    CHECK(pairs(a) == pa && pairs(b) == pb, name << ": an input axis changed");
    CHECK(u.number_of_input_rings() == s.whole.size(), name << ": the union has " << u.number_of_input_rings()
                                                            << " rings, the polygon " << s.whole.size());
    checker.compare(u, "union", true, name, rings_of(u));
    // (a T on the shared edge: computed in one shot of the union, the only way)
    CHECK(stats.anomalies == 0 && stats.recomputed == (s.t_on_shared_edge ? 1u : 0u) && stats.undecided_ties == 0,
          name << ": the merges met " << stats.anomalies << " anomalies and " << stats.undecided_ties
               << " undecided ties (computed again: " << stats.recomputed << ")");
    if(seed % 4 == 0) {
      // the union's way out, forced: the axis again, in one shot of the
      // union polygon, in the same numbering
      struct Forced {
        Forced() { CGAL::Progressive_medial_axes::internal::union_way_out_forced() = true; }
        ~Forced() { CGAL::Progressive_medial_axes::internal::union_way_out_forced() = false; }
      } forced;
      CGAL::Progressive_medial_axes::Medial_axis_union_statistics redone;
      const MA again = CGAL::medial_axis_union_2(a, b, Traits(), &redone);
      CHECK(redone.recomputed == 1, name << ": the forced way out was not taken");
      checker.compare(again, "union's way out", true, name, rings_of(again));
      auto sorted = [&](const MA& ma) {
        auto p = pairs(ma);
        for(auto& q : p)
          if(q.second < q.first) std::swap(q.first, q.second);
        std::sort(p.begin(), p.end());
        return p;
      };
      CHECK(rings_of(again) == rings_of(u) && sorted(again) == sorted(u),
            name << ": the way out numbers the union otherwise than its merges");
    }
    if(seed % 3 == 0 && s.whole.size() == 1 && stats.recomputed == 0) {
      // the union merged once more: with a thin cap outside one edge of the
      // outer ring (a union's axis is the axis of a whole polygon too)
      const std::vector<Point>& W = s.whole[0];
      const std::size_t i = std::size_t(rng.below(std::uint64_t(W.size()))), i1 = (i + 1) % W.size();
      const Point &p = W[i], &q = W[i1];
      const Point apex(0.5 * (p.x() + q.x()) + 0.05 * (q.y() - p.y()), 0.5 * (p.y() + q.y()) - 0.05 * (q.x() - p.x()));
      Rings capped{W};
      capped[0].insert(capped[0].begin() + std::ptrdiff_t(i + 1), apex);
      bool valid = true;
      try {
        CGAL::Progressive_medial_axes::validate_polygon(capped);
      } catch(const CGAL::Progressive_medial_axes::Input_error&) {
        valid = false;   // (the cap crosses a neighbouring edge)
      }
      if(valid) {
        const Rings cap{{q, p, apex}};
        try {
          CGAL::Progressive_medial_axes::Medial_axis_union_statistics again;
          const MA c = axis(cap);
          const MA v = seed % 2 ? CGAL::medial_axis_union_2(c, u, Traits(), &again) : CGAL::medial_axis_union_2(u, c, Traits(), &again);
          CHECK(again.recomputed == 0 && again.shared_edges == 1 && v.number_of_input_rings() == 1,
                name << ", with a cap: recomputed " << again.recomputed << ", " << again.shared_edges << " shared edges, "
                     << v.number_of_input_rings() << " rings");
          checker.compare(v, "union of a union", true, name + ", with a cap on edge " + std::to_string(i), rings_of(v));
          ++capped_unions;
        } catch(const std::exception& e) {
          CHECK(false, name << ", with a cap on edge " << i << ": " << e.what() << "\n  a: " << wkt(s.a) << "\n  b: " << wkt(s.b)
                            << "\n  cap: " << wkt(cap));
        }
      }
    }
    ++count;
    with_t += s.t_holes > 0;
    t_shared += s.t_on_shared_edge;
    if(pma_test::failures() > 20) return;
  }
  CHECK(with_t >= std::size_t(seeds) / 10 && t_shared >= std::size_t(seeds) / 40 && capped_unions >= std::size_t(seeds) / 10,
        "only " << with_t << " splits with holes touching an edge at a T, " << t_shared << " on the shared edge, "
                << capped_unions << " unions merged again");
  // a hole filled exactly (a ring shared as a whole): not merged, computed
  // in one shot of the union polygon; the filler has a hole of its own in
  // every other seed, and the order of the two axes alternates
  std::size_t filled = 0;
  for(int seed = 0; seed < (o.quick ? 8 : 30); ++seed) {
    pma_test::random_detail::Rng rng(std::uint64_t(seed) * 104729 + 5 + o.seed_base);
    const int n = 5 + int(rng.below(20));
    std::vector<Point> star;
    for(int i = 0; i < n; ++i) {
      const double t = 2 * pma_test::random_detail::pi * (i + rng.uniform(0.1, 0.9)) / n, r = rng.uniform(1, 3);
      star.push_back(Point(r * std::cos(t), r * std::sin(t)));
    }
    const Rings with_hole{{Point(-10, -10), Point(10, -10), Point(10, 10), Point(-10, 10)},
                          std::vector<Point>(star.rbegin(), star.rend())};
    Rings filler{star};
    if(seed % 2 == 1) filler.push_back({Point(0.2, 0), Point(-0.1, -0.2), Point(-0.1, 0.2)});
    const std::string name = "union of a hole filled exactly, seed " + std::to_string(seed);
    try {
      CGAL::Progressive_medial_axes::Medial_axis_union_statistics stats;
      const MA a = axis(with_hole), b = axis(filler);
      const MA u = seed % 4 < 2 ? CGAL::medial_axis_union_2(a, b, Traits(), &stats)
                                : CGAL::medial_axis_union_2(b, a, Traits(), &stats);
      CHECK(stats.recomputed == 1 && stats.chains == 1 && stats.shared_edges == std::size_t(n),
            name << ": recomputed " << stats.recomputed << ", " << stats.chains << " chains, " << stats.shared_edges
                 << " shared edges");
      CHECK(u.number_of_input_rings() == filler.size(), name << ": the union has " << u.number_of_input_rings() << " rings");
      checker.compare(u, "union", true, name, rings_of(u));
    } catch(const std::exception& e) {
      CHECK(false, name << ": " << e.what() << "\n  a: " << wkt(with_hole) << "\n  b: " << wkt(filler));
    }
    ++filled;
  }
  // real and synthetic outlines split along diagonals of their constrained
  // Delaunay triangulation (one shared edge between two parts with long
  // cells of real data), three diagonals each
  typedef CGAL::Triangulation_vertex_base_with_info_2<int, CGAL::Epick> Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<CGAL::Epick> Fb;
  typedef CGAL::Constrained_Delaunay_triangulation_2<CGAL::Epick, CGAL::Triangulation_data_structure_2<Vb, Fb> > CDT;
  std::size_t diagonals = 0;
  for(const char* shape : {"syn_comb50", "syn_maze20", "syn_spiral20", "syn_star2k", "syn_sliver500", "c1m_GBR_0"}) {
    const Rings rings = pma_tool::read_polygon_file<Point>(std::string(PMA_TEST_DATA) + "/" + shape + ".wkt");
    if(rings.size() != 1 || (o.quick && std::string(shape) == "c1m_GBR_0")) continue;
    const std::vector<Point>& ring = rings[0];
    const int n = int(ring.size());
    CDT cdt;
    std::vector<CDT::Vertex_handle> vh;
    for(int i = 0; i < n; ++i) {
      vh.push_back(cdt.insert(ring[std::size_t(i)]));
      vh.back()->info() = i;
    }
    for(int i = 0; i < n; ++i) cdt.insert_constraint(vh[std::size_t(i)], vh[std::size_t((i + 1) % n)]);
    std::vector<std::pair<int, int> > found;
    for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
      if(cdt.is_constrained(*e)) continue;
      int i = e->first->vertex(CDT::cw(e->second))->info(), j = e->first->vertex(CDT::ccw(e->second))->info();
      if(i > j) std::swap(i, j);
      const Point mid = CGAL::midpoint(ring[std::size_t(i)], ring[std::size_t(j)]);
      if(CGAL::bounded_side_2(ring.begin(), ring.end(), mid, CGAL::Epick()) == CGAL::ON_BOUNDED_SIDE) found.emplace_back(i, j);
    }
    std::sort(found.begin(), found.end());
    for(int k = 1; k <= 3 && !found.empty(); ++k) {
      const auto d = found[found.size() * std::size_t(k) / 4];
      Rings a{std::vector<Point>(ring.begin() + d.first, ring.begin() + d.second + 1)}, b(1);
      for(int i = d.second; i < n; ++i) b[0].push_back(ring[std::size_t(i)]);
      for(int i = 0; i <= d.first; ++i) b[0].push_back(ring[std::size_t(i)]);
      const std::string name = std::string("union of ") + shape + " split along the diagonal " + std::to_string(d.first) +
                               "-" + std::to_string(d.second);
      try {
        const MA u = CGAL::medial_axis_union_2(axis(a), axis(b), Traits());
        checker.compare(u, "union", true, name, rings_of(u));
      } catch(const std::exception& e) {
        CHECK(false, name << ": " << e.what());
      }
      ++diagonals;
    }
  }
  // integer grid shapes (exact ties everywhere): two skylines of unit columns
  // split along the vertical line between them, a chain of unit edges with
  // flat vertices
  std::size_t grids = 0;
  for(int seed = 0; seed < (o.quick ? 30 : 100); ++seed) {
    pma_test::random_detail::Rng rng(std::uint64_t(seed) * 15485863 + 11);
    const int k = 2 + int(rng.below(5)), H = 3 + int(rng.below(6));
    std::vector<int> top(std::size_t(2 * k));
    for(int& t : top) t = 1 + int(rng.below(std::uint64_t(H)));
    const int h = (std::min)(top[std::size_t(k - 1)], top[std::size_t(k)]);
    std::vector<Point> A{Point(0, 0), Point(k, 0)}, B{Point(k, 0), Point(2 * k, 0), Point(2 * k, top[std::size_t(2 * k - 1)])};
    for(int y = 1; y <= h; ++y) A.push_back(Point(k, y));
    if(top[std::size_t(k - 1)] > h) A.push_back(Point(k, top[std::size_t(k - 1)]));
    for(int x = k - 1; x > 0; --x)
      if(top[std::size_t(x)] != top[std::size_t(x - 1)]) {
        A.push_back(Point(x, top[std::size_t(x)]));
        A.push_back(Point(x, top[std::size_t(x - 1)]));
      }
    A.push_back(Point(0, top[0]));
    for(int x = 2 * k - 1; x > k; --x)
      if(top[std::size_t(x)] != top[std::size_t(x - 1)]) {
        B.push_back(Point(x, top[std::size_t(x)]));
        B.push_back(Point(x, top[std::size_t(x - 1)]));
      }
    if(top[std::size_t(k)] > h) B.push_back(Point(k, top[std::size_t(k)]));
    for(int y = h; y > 0; --y) B.push_back(Point(k, y));
    const std::string name = "union of grid skylines seed " + std::to_string(seed);
    try {
      const MA u = CGAL::medial_axis_union_2(axis(Rings{A}), axis(Rings{B}), Traits());
      checker.compare(u, "union", true, name, rings_of(u));
    } catch(const std::exception& e) {
      CHECK(false, name << ": " << e.what() << "\n  a: " << wkt(Rings{A}) << "\n  b: " << wkt(Rings{B}));
    }
    ++grids;
  }
  // T's (a vertex inside an edge; data/union/README.md): in a part (merged;
  // the union is noded there), in the union only, and on an edge that one
  // part splits and the other shares whole, also where that other part has
  // T's too, and both ways (all computed in one shot)
  // (with the number of rings of the union: holes touching the outer ring
  // at a point are rings of their own, as OGC has them)
  std::size_t ts = 0;
  struct T_case {
    std::string name;
    std::size_t recomputed, rings;
  };
  for(const T_case& t : std::vector<T_case>{{"t_notch", 0, 2},
                                            {"t_two_holes", 0, 3},
                                            {"t_both_sides", 0, 3},
                                            {"t_union", 1, 2},   // (its own T noded: the loop there is a hole)
                                            {"t_shared", 1, 2},
                                            {"t_shared_both", 1, 3},
                                            {"t_shared_crossed", 1, 3},
                                            {"t_shared_two_places", 1, 3},
                                            {"touch_at_smallest", 0, 2}}) {
    const std::string f = std::string(PMA_TEST_DATA) + "/union/" + t.name;
    const MA a = axis(pma_tool::read_polygon_file<Point>(f + "_a.wkt")), b = axis(pma_tool::read_polygon_file<Point>(f + "_b.wkt"));
    for(int order = 0; order < 2; ++order) {
      const std::string name = "union " + t.name + (order ? " (b, a)" : " (a, b)");
      try {
        CGAL::Progressive_medial_axes::Medial_axis_union_statistics stats;
        const MA u = order ? CGAL::medial_axis_union_2(b, a, Traits(), &stats) : CGAL::medial_axis_union_2(a, b, Traits(), &stats);
        CHECK(stats.recomputed == t.recomputed && stats.anomalies == 0 && u.number_of_input_rings() == t.rings,
              name << ": recomputed " << stats.recomputed << ", anomalies " << stats.anomalies << ", "
                   << u.number_of_input_rings() << " rings");
        checker.compare(u, "union", true, name, rings_of(u));
      } catch(const std::exception& e) {
        CHECK(false, name << ": " << e.what());
      }
      ++ts;
    }
  }
  // T's that only the union has, at random: part a lies below the line
  // y = 0 with its top edge from q = (1, 0) to r = (-1, 0), part b to the
  // right of a's right side (the shared chain) and above that edge, where it
  // comes down in notches whose tips touch the edge at points inside it (a
  // vertex of b inside an edge of a that is not shared).  The union's ring
  // touches its own edge at each tip: the union is noded there, and each
  // loop between two tips, or between the last tip and q, is a hole, as OGC
  // has it; its axis is computed in one shot of that union polygon.
  std::size_t union_ts = 0;
  for(int seed = 0; seed < (o.quick ? 10 : 40); ++seed) {
    pma_test::random_detail::Rng rng(std::uint64_t(seed) * 7727 + 3 + o.seed_base);
    const double pi = pma_test::random_detail::pi, d = rng.uniform(0.3, 0.6);
    auto snap = [](double v) { return std::ldexp(std::round(std::ldexp(v, 10)), -10); };
    std::vector<Point> A{Point(-1, 0)}, B{Point(1, 0)};
    const int lower = 2 + int(rng.below(8)), chain = 1 + int(rng.below(5));
    for(int k = 0; k < lower; ++k) {
      const double t = pi + 0.1 + (pi - 0.7) * (k + rng.uniform(0.1, 0.9)) / lower, radius = rng.uniform(0.5, 1);
      A.push_back(Point(radius * std::cos(t), radius * std::sin(t)));
    }
    std::vector<Point> right;   // the shared chain, from s = (1, -d) up to q (excluded)
    for(int k = 0; k < chain; ++k) right.push_back(Point(k == 0 ? 1 : snap(1 + rng.uniform(0, 0.05)), snap(-d * (chain - k) / chain)));
    A.insert(A.end(), right.begin(), right.end());
    A.push_back(Point(1, 0));
    B.insert(B.end(), right.rbegin(), right.rend());
    const double sy = right.front().y();
    for(const Point& p : {Point(2, sy), Point(2, 1), Point(-1.2, 1), Point(-1.2, 0.5)}) B.push_back(p);
    const int tips = 1 + int(rng.below(3));
    for(int k = 0; k < tips; ++k) {   // tips in (-0.8, 0.8), 1.6 / tips apart
      const double m = snap(-0.8 + 1.6 * (k + rng.uniform(0.3, 0.7)) / tips), w = 0.25 / tips;
      for(const Point& p : {Point(m - w, 0.5), Point(m, 0), Point(m + w, 0.5)}) B.push_back(p);
    }
    B.push_back(Point(1, 0.5));
    const std::string name = "union with " + std::to_string(tips) + " T's of its own, seed " + std::to_string(seed);
    try {
      CGAL::Progressive_medial_axes::Medial_axis_union_statistics stats;
      const MA ma = axis(Rings{A}), mb = axis(Rings{B});
      const MA u = seed % 2 ? CGAL::medial_axis_union_2(mb, ma, Traits(), &stats) : CGAL::medial_axis_union_2(ma, mb, Traits(), &stats);
      const Rings r = rings_of(u);
      bool twice = false;   // (OGC: no ring passes a place twice)
      for(std::vector<Point> ring : r) {
        std::sort(ring.begin(), ring.end());
        twice = twice || std::adjacent_find(ring.begin(), ring.end()) != ring.end();
      }
      CHECK(stats.recomputed == 1 && r.size() == std::size_t(1 + tips) && !twice,
            name << ": recomputed " << stats.recomputed << ", " << r.size() << " rings" << (twice ? ", a ring passes a place twice" : "")
                 << "\n  a: " << wkt(Rings{A}) << "\n  b: " << wkt(Rings{B}));
      checker.compare(u, "union", true, name, r);
    } catch(const std::exception& e) {
      CHECK(false, name << ": " << e.what() << "\n  a: " << wkt(Rings{A}) << "\n  b: " << wkt(Rings{B}));
    }
    ++union_ts;
  }
  // the errors
  auto square = [](double x, double y, double d) {
    return Rings{{Point(x, y), Point(x + d, y), Point(x + d, y + d), Point(x, y + d)}};
  };
  auto error_of = [](const MA& a, const MA& b) {
    try {
      CGAL::medial_axis_union_2(a, b, Traits());
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  auto expect_error = [&](const Rings& ra, const Rings& rb, const std::string& words) {
    const std::string what = error_of(axis(ra), axis(rb));
    CHECK(what.find(words) != std::string::npos, "union of " << wkt(ra) << " and " << wkt(rb) << ": error '" << what
                                                           << "', expected '" << words << "'");
  };
  expect_error(square(0, 0, 1), square(2, 0, 1), "share no edge");
  expect_error(square(0, 0, 1), square(0, 0, 1), "overlap");
  expect_error(square(0, 0, 2), Rings{{Point(2, 0), Point(2, 2), Point(1, 1)}}, "overlap");   // an edge in the same direction
  expect_error(square(0, 0, 2), Rings{{Point(2, 2), Point(2, 0), Point(3, 0), Point(3, 3), Point(1, 3), Point(1, 1.5)}},
               "not a valid polygon");   // shares an edge, and crosses the square's top edge
  {
    // step 0 of a hexagon: one triangle of it
    CGAL::Progressive_medial_axis_2<Traits> p(Rings{{Point(0, 0), Point(1, -1), Point(2, 0), Point(2, 1), Point(1, 2), Point(0, 1)}});
    const std::string what = error_of(p.medial_axis(), axis(Rings{{Point(2, 0), Point(0, 0), Point(1, -3)}}));
    CHECK(what.find("not the axis of a whole polygon") != std::string::npos, "union with a progressive step: '" << what << "'");
  }
  std::cout << "union: " << count << " splits (" << with_t << " with T's, " << t_shared << " with one on the shared edge; "
            << capped_unions << " merged again with a cap), " << filled << " holes filled exactly, " << diagonals
            << " outlines split along a diagonal, " << grids << " grid skylines, " << ts << " unions with T's, " << union_ts
            << " with T's of their own\n";
}

template <class Traits>
void regression_tests(Checker<Traits>& checker, const Options&)
{
  std::size_t count = 0, steps = 0, stopped = 0;
  for(const std::string& f : list_wkt(std::string(PMA_TEST_DATA) + "/regressions")) {
    Rings rings = pma_tool::read_polygon_file<Point>(f);
    // the whole axis, and the one-shot in the test's cycle of parts
    run_polygon(checker, rings, f, false);
    // The steps: every one up to 400 steps (a shape cut down to a wrong
    // step has a few hundred at most), else five.  (Until the forty-seventh
    // session, steps where the oracle threw "SDG says equal, MPFR says
    // different" were skipped: the oracle took the two tangent circles of a
    // point between two segments for one.  It no longer does, and no step
    // is skipped.)
    {
      CGAL::Progressive_medial_axis_2<Traits> pma(rings, g_driver);
      std::vector<std::size_t> at;
      if(pma.number_of_steps() <= 400) {
        for(std::size_t s = 1; s <= pma.number_of_steps(); ++s) at.push_back(s);
      } else {
        for(double q : {0.1, 0.3, 0.5, 0.7, 0.9}) at.push_back(std::size_t(q * double(pma.number_of_steps())));
      }
      for(std::size_t s : at) {
        if(s < pma.current_step()) continue;
        pma.refine_to(s);
        checker.compare(pma, false, f, rings);
        ++steps;
      }
    }
    // the one-shot as the tool runs it (its default parts)
    CGAL::Progressive_medial_axis_statistics stats;
    const auto ma = CGAL::medial_axis_2(rings, Traits(), CGAL::CHECK_INPUT, &stats);
    checker.compare(ma, "default one-shot", true, f, rings);
    CHECK(stats.anomalies == 0 && stats.region_growing_one_shots == 0,
          f << ": the default one-shot met " << stats.anomalies << " anomalies ("
            << stats.region_growing_one_shots << " computed again)");
    // the one-shot's way out, forced: the axis again, by region growing
    {
      struct Forced {
        Forced() { CGAL::Progressive_medial_axes::internal::one_shot_way_out_forced() = true; }
        ~Forced() { CGAL::Progressive_medial_axes::internal::one_shot_way_out_forced() = false; }
      } forced;
      CGAL::Progressive_medial_axis_statistics redone;
      const auto again = CGAL::medial_axis_2(rings, Traits(), CGAL::CHECK_INPUT, &redone);
      checker.compare(again, "one-shot's way out", true, f, rings);
      CHECK(redone.region_growing_one_shots == 1 && redone.anomalies == 0,
            f << ": the forced way out was not taken (" << redone.region_growing_one_shots << ")");
      // the same with rings given up: freed once copied, the way out starts
      // again from rings rebuilt from the engine's points (input_rings())
      auto given_up = CGAL::Progressive_medial_axes::internal::rings_of<typename Traits::Kernel>(rings);
      CGAL::Progressive_medial_axis_statistics rebuilt;
      const auto from_rebuilt = CGAL::medial_axis_2(std::move(given_up), Traits(), CGAL::CHECK_INPUT, &rebuilt);
      checker.compare(from_rebuilt, "one-shot's way out from rings given up", true, f, rings);
      CHECK(rebuilt.region_growing_one_shots == 1 && rebuilt.anomalies == 0 && given_up.empty(),
            f << ": with rings given up, the forced way out was not taken (" << rebuilt.region_growing_one_shots
              << ") or the rings were kept (" << given_up.size() << ")");
    }
    // The divide and conquer stopped (abandon_events_per_triangle), forced
    // where the probe kept it: (1) boundary evolution computes the axis,
    // (2) it gives up too and the divide and conquer runs again without
    // stopping; from rings given up, which are rebuilt from the engine's
    // points before its structure is dropped.
    for(int mode : {1, 2}) {
      struct Forced {
        explicit Forced(int m) { CGAL::Progressive_medial_axes::internal::one_shot_abandon_forced() = m; }
        ~Forced() { CGAL::Progressive_medial_axes::internal::one_shot_abandon_forced() = 0; }
      } forced(mode);
      auto given_up = CGAL::Progressive_medial_axes::internal::rings_of<typename Traits::Kernel>(rings);
      CGAL::Progressive_medial_axis_statistics st;
      const auto again = CGAL::medial_axis_2(std::move(given_up), Traits(), CGAL::CHECK_INPUT, &st);
      checker.compare(again, mode == 1 ? "divide and conquer stopped" : "divide and conquer stopped, then again",
                      true, f, rings);
      // (where the one-shot probes its parts, and the probe kept the divide and conquer)
      if(CGAL::Progressive_medial_axes::internal::default_parts(stats.triangles) >=
           CGAL::Progressive_medial_axes::internal::probe_seeds &&
         std::is_floating_point<typename Traits::FT>::value && stats.boundary_evolution_one_shots == 0) {
        CHECK(st.abandoned_divide_and_conquers == 1 && st.boundary_evolution_one_shots == (mode == 1 ? 1u : 0u) &&
                st.anomalies == 0,
              f << ": the divide and conquer stopped (mode " << mode << "): " << st.abandoned_divide_and_conquers
                << " stopped, " << st.boundary_evolution_one_shots << " by boundary evolution, " << st.anomalies
                << " anomalies");
        ++stopped;
      }
    }
    ++count;
  }
  std::cout << "regressions: " << count << " shapes, whole, " << steps
            << " steps, the default one-shot and its way out; the divide and conquer stopped " << stopped
            << " times\n";
}

// The exact-decision traits' centre hints (Disk_hint): kept as a centre
// and an error bound in doubles, they must still enclose the intervals they
// came from (random intervals, of widths from none to wide; other traits
// have none).
template <class Traits>
auto disk_hint_tests(int) -> decltype(typename Traits::Disk_hint(), void())
{
  typedef typename Traits::Disk_hint Hint;
  typedef CGAL::Interval_nt<false> I;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> centre(-1e6, 1e6), exponent(-60, 0);
  int failures = 0;
  for(int i = 0; i < 100000; ++i) {
    Hint h;
    h.valid = true;
    const double x = centre(rng), y = i % 7 == 0 ? 0.0 : centre(rng) * std::pow(2.0, exponent(rng));
    const double wx = i % 5 == 0 ? 0.0 : std::fabs(x) * std::pow(2.0, exponent(rng));
    const double wy = i % 3 == 0 ? 0.0 : (std::fabs(y) + 1e-300) * std::pow(2.0, exponent(rng));
    h.x = I(x - wx, x + wx);
    h.y = I(std::nextafter(y, -1e300) - wy, y + wy);
    double cx, cy, err;
    if(!h.to_doubles(cx, cy, err)) {
      ++failures;
      continue;
    }
    const Hint back = Hint::from_doubles(cx, cy, err);
    if(!(back.valid && back.x.inf() <= h.x.inf() && h.x.sup() <= back.x.sup() && back.y.inf() <= h.y.inf() &&
         h.y.sup() <= back.y.sup() && err >= 0))
      ++failures;
  }
  CHECK(failures == 0, "a centre hint in doubles does not enclose its intervals (" << failures << " of 100000)");
}
template <class Traits>
void disk_hint_tests(long) {}

template <class Traits>
int run_all(const Options& o)
{
  disk_hint_tests<Traits>(0);
  Checker<Traits> checker;
  auto start = std::chrono::steady_clock::now();
  auto wanted = [&](const std::string& section) {
    return o.only.empty() || ("," + o.only + ",").find("," + section + ",") != std::string::npos;
  };
  if(wanted("regressions")) regression_tests(checker, o);
  if(wanted("random")) random_tests(checker, o);
  if(wanted("holes")) hole_tests(checker, o);
  if(wanted("data")) data_tests(checker, o);
  if(wanted("lakes")) lake_tests(checker, o);
  if(wanted("degenerate")) degenerate_tests(checker, o);
  if(wanted("fine")) fine_tests(checker, o);
  if(wanted("touching")) touching_tests(checker, o);
  if(wanted("double")) double_model_tests(checker, o);
  if(wanted("union")) union_tests(checker, o);
  // the split triangulation runs where a one-shot has two threads or more,
  // on double coordinates; the random polygons have chords
  std::cout << g_split_one_shots << " one-shots triangulated in two sides (" << g_path_split_one_shots
            << " along a path through holes)\n";
#ifdef CGAL_PMA2_USE_TBB
  if(std::is_floating_point<typename Traits::FT>::value && tbb::this_task_arena::max_concurrency() > 1 &&
     g_driver == CGAL::REGION_GROWING && (wanted("random") || wanted("holes")))
    CHECK(g_split_one_shots > 0, "no one-shot triangulated its polygon in two sides");
  if(std::is_floating_point<typename Traits::FT>::value && tbb::this_task_arena::max_concurrency() > 1 &&
     g_driver == CGAL::REGION_GROWING && wanted("holes"))
    CHECK(g_path_split_one_shots > 0, "no one-shot triangulated its polygon in two sides along a path through holes");
#endif
  std::cout << g_tapered_one_shots << " one-shots with their last parts cut smaller\n";
  std::cout << g_counted_steps << " one-shots counted the steps of region growing\n";
  if(g_driver == CGAL::REGION_GROWING && (wanted("random") || wanted("holes")))
    CHECK(g_counted_steps > 0, "no one-shot counted the steps of region growing");
#ifdef CGAL_PMA2_USE_TBB
  if(tbb::this_task_arena::max_concurrency() > 1 && g_driver == CGAL::REGION_GROWING &&
     (wanted("random") || wanted("holes")))
    CHECK(g_tapered_one_shots > 0, "no one-shot cut its last parts smaller");
#endif
  // the switch times at vertices made by vanishing events, computed from
  // the centres kept with them, were compared with the oracle above
  if(const std::optional<std::size_t> hinted =
       filter_counter<Traits>([](const auto& f) { return f.hinted_switch_times; }, 0)) {
    std::cout << *hinted << " switch times computed from a centre kept with their vertex, in this thread\n";
    if(wanted("random") || wanted("holes") || wanted("data"))
      CHECK(*hinted > 0, "no switch time was computed from a centre kept with its vertex");
  }
#ifdef CGAL_PMA2_SMALL_RATIONAL_TEST_BITS
  // this build's 128-bit rationals overflow early (engine.cmake): the
  // comparisons above tested the fallbacks to GMP rationals only if some ran
  if(o.traits == "filtered") {
    // (the exact-decision traits' computations in 128-bit rationals that
    // overflowed and were redone in GMP rationals)
    const std::size_t overflows =
      filter_counter<Traits>([](const auto& f) { return f.small_rational_overflows; }, 0).value_or(0);
    std::cout << overflows << " computations in 128-bit rationals redone in GMP rationals (limit "
              << CGAL_PMA2_SMALL_RATIONAL_TEST_BITS << " bits)\n";
    CHECK(overflows > 0, "no computation in 128-bit rationals overflowed");
  }
#endif
  std::cout << checker.comparisons << " comparisons with the oracle (" << checker.rounding_comparisons
            << " branch points and " << checker.circle_comparisons << " inscribed circles compared exactly), " << pma_test::failures() << " failures, "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
  return pma_test::failures() == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if(a == "--quick") o.quick = true;
    else if(a == "--only" && i + 1 < argc) o.only = argv[++i];
    else if(a == "--traits" && i + 1 < argc) o.traits = argv[++i];
    else if(a == "--seed-base" && i + 1 < argc) o.seed_base = std::strtoull(argv[++i], nullptr, 10);
    else if(a == "--skip" && i + 1 < argc) o.skip.push_back(argv[++i]);
    else if(a == "--no-grid") o.no_grid = true;
    else if(a == "--driver" && i + 1 < argc) {
      const std::string d = argv[++i];
      if(d != "region" && d != "boundary") { std::cerr << "--driver region|boundary\n"; return 2; }
      g_driver = d == "boundary" ? CGAL::BOUNDARY_EVOLUTION : CGAL::REGION_GROWING;
    }
    else { std::cerr << "unknown argument " << a << "\n"; return 2; }
  }
  // (every one-shot of 16 vertices or more on two threads tries to split
  // its triangulation, not only those of 32,768 or more)
  CGAL::Progressive_medial_axes::internal::split_triangulation_min_vertices() = 16;
  // (and every one-shot on two threads whose parts hold 8 triangles or more
  // cuts its last parts smaller, not only those whose parts hold 2,048)
  g_default_min_tail_target = CGAL::Progressive_medial_axes::internal::divide_and_conquer_min_tail_target().exchange(1);
  if(o.traits == "epick") return run_all<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> > >(o);
  if(o.traits == "exact") return run_all<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<CORE::Expr> > >(o);
  return run_all<CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> >(o);
}
