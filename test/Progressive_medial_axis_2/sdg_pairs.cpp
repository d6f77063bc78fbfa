// sdg_pairs [--branches] [--time] INPUT
//
// Prints the medial axis of the polygon in INPUT (a WKT POLYGON, or GeoJSON; see
// pma_tool::read_polygon_file) as computed by the test oracle (CGAL's segment Voronoi
// diagram, pma_test/sdg_oracle.h), in the canonical ids of algorithm.md section 7:
//
//   pair A B L              one line per medial curve, A < B, L its length
//   branch G1 G2 G3 ... x y r   with --branches: one line per branch point (>= 3 sorted
//                           generator ids, then centre and radius)
//
// Lines are sorted; numbers are printed with %.17g. With --time, timings go to stderr.
// Exit status: 0 on success, 2 on bad usage or bad input (one-line message on stderr),
// 3 on an internal error of the oracle.

#include <pma_test/random_polygons.h>
#include <pma_test/sdg_oracle.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <pma_tool/polygon_io.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <tuple>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;

int usage()
{
  std::fprintf(stderr, "usage: sdg_pairs [--branches] [--time] INPUT.wkt\n");
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  bool branches = false, timing = false;
  std::string path;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--branches") branches = true;
    else if(arg == "--time") timing = true;
    else if(arg == "-h" || arg == "--help") { usage(); return 0; }
    else if(!arg.empty() && arg[0] == '-' && arg != "-") return usage();
    else if(path.empty()) path = arg;
    else return usage();
  }
  if(path.empty()) return usage();

  typedef std::chrono::steady_clock Clock;
  const Clock::time_point t0 = Clock::now();
  std::vector<std::vector<Point_2> > rings;
  try {
    rings = pma_tool::read_polygon_file<Point_2>(path);
    CGAL::Progressive_medial_axes::validate_polygon_rings<K>(rings);
  } catch(const std::exception& e) {
    std::fprintf(stderr, "sdg_pairs: %s: %s\n", path.c_str(), e.what());
    return 2;
  }
  // the oracle's own (independent) validity check, for rings that do not touch (where
  // they touch, at shared vertices or at a vertex inside an edge, the oracle checks
  // the sectors there itself)
  std::vector<Point_2> all;
  for(const auto& r : rings) all.insert(all.end(), r.begin(), r.end());
  std::sort(all.begin(), all.end());
  bool touching = std::adjacent_find(all.begin(), all.end()) != all.end();
  try {
    touching = touching || pma_test::oracle_detail::make_polygon_data(rings).pts.size() > all.size();
  } catch(const std::invalid_argument&) {   // reported below
  }
  if(!touching && !pma_test::is_valid_polygon_with_holes(rings)) {
    std::fprintf(stderr, "sdg_pairs: %s: not a valid polygon with holes\n", path.c_str());
    return 2;
  }
  const Clock::time_point t1 = Clock::now();

  pma_test::Oracle_graph graph;
  try {
    graph = pma_test::sdg_medial_graph(rings);
  } catch(const std::invalid_argument& e) {
    std::fprintf(stderr, "sdg_pairs: %s: %s\n", path.c_str(), e.what());
    return 2;
  } catch(const std::exception& e) {
    std::fprintf(stderr, "sdg_pairs: %s: internal error: %s\n", path.c_str(), e.what());
    return 3;
  }
  const pma_test::Oracle_result result = pma_test::oracle_result_from_graph(graph);
  const Clock::time_point t2 = Clock::now();

  std::vector<pma_test::Oracle_curve> curves = result.curves;
  std::sort(curves.begin(), curves.end(),
            [](const pma_test::Oracle_curve& a, const pma_test::Oracle_curve& b) {
              return std::tie(a.a, a.b, a.length) < std::tie(b.a, b.b, b.length);
            });
  for(const pma_test::Oracle_curve& c : curves)
    std::printf("pair %s %s %.17g\n", c.a.c_str(), c.b.c_str(), c.length);

  if(branches) {
    std::vector<pma_test::Oracle_branch> bs = result.branches;
    std::sort(bs.begin(), bs.end(),
              [](const pma_test::Oracle_branch& a, const pma_test::Oracle_branch& b) {
                return std::tie(a.generators, a.x, a.y, a.r) < std::tie(b.generators, b.x, b.y, b.r);
              });
    for(const pma_test::Oracle_branch& b : bs) {
      std::printf("branch");
      for(const std::string& g : b.generators) std::printf(" %s", g.c_str());
      std::printf(" %.17g %.17g %.17g\n", b.x, b.y, b.r);
    }
  }
  if(std::fflush(stdout) != 0) {
    std::fprintf(stderr, "sdg_pairs: write error\n");
    return 2;
  }

  if(timing) {
    const pma_test::Oracle_stats& s = graph.stats;
    std::fprintf(stderr,
                 "sdg_pairs: %s: %zu vertices, %zu curves, %zu branches; read+validate %.3f s, "
                 "oracle %.3f s (SDG %.3f s, rest %.3f s); %zu SDG faces, %zu inside\n",
                 path.c_str(), s.sdg_vertices / 2, result.curves.size(), result.branches.size(),
                 std::chrono::duration<double>(t1 - t0).count(),
                 std::chrono::duration<double>(t2 - t1).count(), s.seconds_sdg,
                 s.seconds_classify, s.sdg_faces, s.inside_faces);
  }
  return 0;
}
