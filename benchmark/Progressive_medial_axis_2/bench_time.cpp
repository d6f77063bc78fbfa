// bench_time: running time and peak memory of our medial axis and of its
// peers, on polygon files, in one run.
//
//   bench_time [--runs N] [--timeout SECONDS] [--exact-timeout SECONDS]
//              [--methods m1,m2,...] [--no-baseline] [--nv-dump DIR] [--warm] FILE.wkt...
//
// Methods (default: all, in this order):
//   pma_filtered      our full progressive sequence, filtered traits (exact decisions),
//                     then the coordinates of every vertex of the final axis
//   pma_oneshot_1     the one-shot divide and conquer (CGAL::medial_axis_2), filtered
//                     traits, in a TBB arena of 1 thread, vertices read as above
//   pma_oneshot_2     the same on 2 threads
//   pma_epick         the full progressive sequence with the double-precision traits
//   pma_exact         the same with the CORE::Expr traits (Simple_cartesian<CORE::Expr>)
//   pma_evolution     the discrete curve evolution alone (the simplification of
//                     the boundary-evolved mode)
//   pma_boundary      the full boundary-evolved progressive sequence (curve evolution,
//                     step 0, every refinement step), filtered traits; the note has
//                     the evolution's time, the refinement's (after step 0), the
//                     time to step 0 and the merge, cut and split counts
//   sdg               Segment_Delaunay_graph_2, filtered traits without intersections
//                     over Simple_cartesian<double> (construction of the diagram)
//   sdg_hierarchy     the same with Segment_Delaunay_graph_hierarchy_2
//   sdg_extract       extraction of the interior medial axis from an already built `sdg`
//                     diagram (its construction is NOT in this row's time; its median is
//                     in the note as build_median_seconds): every interior Voronoi edge
//                     with its two generators and its two end points in double
//                     (construct_svd_vertex_2 of the SDG's traits); inside/outside decided
//                     combinatorially (bench_common.h, Sdg_interior)
//   sdg_exact         Segment_Delaunay_graph_2 with Segment_Delaunay_graph_traits_2 over
//                     Simple_cartesian<CORE::Expr>, Field_with_sqrt_tag (construction)
//   boost_voronoi     boost::polygon::construct_voronoi on the polygon's segments, the
//                     coordinates scaled to 32-bit integers by the smallest 10^k (k = 0..9)
//                     at which they are all integral (construction of the diagram);
//                     "not applicable" when there is no such k
//
// The one-shot rows (medial_axis_2: divide and conquer) and the progressive rows
// (region growing to the whole shape) give the same axis.
//
// Every measurement runs in a child process (fork), so that its peak memory
// (maxrss) is its own and a time limit can stop it (--timeout, default 600 s;
// --exact-timeout, default the same, for pma_exact and sdg_exact); the first run
// that fails or does not finish in time ends the method's runs, and a method that
// did not finish in time is not run again on files with as many vertices or more
// (status "not run: did not finish in T s on N vertices").  Times are medians of N runs.
// Each run is thus the method's first call in its process, which pays for the first
// touch of its code and data (page faults: 10 to 25 us each on the 2-core VM of
// RESULTS.md, sixty-sixth session).  With --warm, the child calls the method once
// on the same polygon before the timed call, untimed: what a program that computes
// many polygons pays for each after its first (the note then starts with "warm;").
// pma_filtered is always measured (first, for every file) unless --no-baseline,
// so that every row has a ratio to it taken in the same invocation.
//
// Output: one tab-separated row per file and method:
//   shape vertices holes method median_seconds runs peak_rss_mb status note ratio_to_pma_filtered
// median_seconds is -1 when no run finished; ratio_to_pma_filtered is
// median_seconds / (pma_filtered's median_seconds for the same file in this
// invocation), "-" when either is missing.  The note of pma methods has the
// number of medial curves and the distribution of n_v (the largest number of
// live vanishing candidates of a merge) as n_v:count.
//
// --nv-dump DIR: for pma_filtered, writes DIR/<shape>.nv.txt, one line "step n_v" per
// refinement step (step 1 is the first merge); for pma_boundary DIR/<shape>.boundary.nv.txt
// (n_v 0 for a cut or a split).

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/internal/Curve_evolution.h>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include "bench_common.h"

#include <boost/polygon/polygon.hpp>
#include <boost/polygon/voronoi.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace pma_bench;

struct Options {
  std::string nv_dump_dir;
};

// ---- the methods; each returns its time in seconds and a short note; `aux`
// ---- receives a second time (sdg_extract: the construction of the diagram)

template <class Traits>
double run_pma(const Rings& rings, std::string& note, const std::string& nv_dump_file,
               CGAL::Progressive_medial_axis_driver driver = CGAL::REGION_GROWING)
{
  typedef CGAL::Progressive_medial_axis_2<Traits> PMA;
  // records n_v of every step
  struct Queue_recorder : CGAL::Default_progressive_medial_axis_visitor {
    std::vector<std::uint32_t> queue_per_step;
    void on_step(std::size_t, std::size_t n_v) { queue_per_step.push_back(std::uint32_t(n_v)); }
  } recorder;
  double t0 = now();
  PMA pma(rings, driver);
  const double step0 = now() - t0;
  pma.refine_all(recorder);
  // the vertices are resolved when the axis is read: read them all
  double checksum = 0;
  for(const auto& v : pma.medial_axis().vertices()) checksum += CGAL::to_double(v.radius());
  double t = now() - t0;
  const auto& s = pma.statistics();
  std::map<std::uint32_t, std::size_t> hist;
  for(std::uint32_t v : recorder.queue_per_step) ++hist[v];
  std::ostringstream o;
  if(!(checksum >= 0)) o << "bad radius;";
  o << "edges=" << pma.medial_axis().number_of_edges() << ";first_step=" << s.first_step_seconds
    << ";until_step0=" << step0 << ";steps=" << pma.number_of_steps() << ";merges=" << s.merges;
  if(driver == CGAL::BOUNDARY_EVOLUTION)
    o << ";evolution=" << s.evolution_seconds << ";refinement=" << (t - step0) << ";cuts=" << s.cuts
      << ";splits=" << s.splits << ";recomputed=" << s.recomputed_steps;
  o << ";nv_max=" << s.max_queue << ";nv_hist=";
  bool first = true;
  for(const auto& kv : hist) {
    o << (first ? "" : ",") << kv.first << ":" << kv.second;
    first = false;
  }
  note = o.str();
  if(!nv_dump_file.empty()) {
    std::ofstream out(nv_dump_file);
    for(std::size_t i = 0; i < recorder.queue_per_step.size(); ++i) out << (i + 1) << ' ' << recorder.queue_per_step[i] << '\n';
    if(!out) throw std::runtime_error("cannot write " + nv_dump_file);
  }
  return t;
}

// The one-shot divide and conquer (CGAL::medial_axis_2) on `threads` threads.
double run_oneshot(const Rings& rings, std::string& note, int threads)
{
  typedef CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> Traits;
  CGAL::Medial_axis_2<CGAL::Epick> ma;
  auto compute = [&]() { ma = CGAL::medial_axis_2(rings, Traits()); };
#ifdef CGAL_LINKED_WITH_TBB
  // The arena and oneTBB's start (its threads, and libtbbmalloc loaded with
  // dlopen: 0.5 to 0.8 ms here) are set up before the clock starts: a
  // program pays them once, not for each polygon, and SDG has none.
  tbb::task_arena arena(threads);
  arena.execute([] {});
  double t0 = now();
  arena.execute(compute);
#else
  (void)threads;
  double t0 = now();
  compute();
#endif
  double checksum = 0;
  for(const auto& v : ma.vertices()) checksum += CGAL::to_double(v.radius());
  double t = now() - t0;
  std::ostringstream o;
  if(!(checksum >= 0)) o << "bad radius;";
  o << "edges=" << ma.number_of_edges() << ";threads=" << threads;
  note = o.str();
  return t;
}

// The discrete curve evolution alone (the paper's Table 2, time a): the
// simplification that the boundary-evolved progressive mode undoes.
double run_evolution(const Rings& rings, std::string& note)
{
  double t0 = now();
  CGAL::Progressive_medial_axes::internal::Curve_evolution<CGAL::Epick> evolution(rings);
  evolution.run();
  double t = now() - t0;
  const auto end = evolution.shape(evolution.removals().size());
  std::size_t left = 0;
  for(const auto& r : end) left += r.size();
  note = "steps=" + std::to_string(evolution.removals().size()) + ";rings_left=" + std::to_string(end.size()) +
         ";vertices_left=" + std::to_string(left);
  return t;
}

template <class SDG>
double run_sdg(const Rings& rings, std::string& note)
{
  double t0 = now();
  SDG sdg;
  build_sdg(sdg, rings);
  double t = now() - t0;
  note = "vertices=" + std::to_string(sdg.number_of_vertices());
  return t;
}

double run_sdg_extract(const Rings& rings, std::string& note, double& aux)
{
  double t0 = now();
  Sdg sdg;
  build_sdg(sdg, rings);
  aux = now() - t0;
  // the user's extraction, from the built diagram
  t0 = now();
  const Polygon_info P = polygon_info(rings);
  Sdg_interior<Sdg> interior(sdg, P);
  std::size_t constructions = 0;
  const std::vector<Extracted_curve> curves = extract_interior(interior, &constructions);
  const double t = now() - t0;
  double checksum = 0;
  for(const Extracted_curve& c : curves) checksum += c.x0 + c.y1;
  std::ostringstream o;
  if(!std::isfinite(checksum)) o << "non-finite vertex;";
  o << "curves=" << curves.size() << ";vertices_constructed=" << constructions
    << ";segments_walked=" << interior.walked_segments();
  note = o.str();
  return t;
}

typedef boost::polygon::point_data<std::int32_t> Boost_point;
typedef boost::polygon::segment_data<std::int32_t> Boost_segment;

double run_boost(const Rings& rings, std::string& note)
{
  std::vector<std::vector<std::pair<std::int32_t, std::int32_t> > > scaled;
  const int k = decimal_scale(rings, scaled);
  if(k < 0) throw std::runtime_error("not applicable");
  std::vector<Boost_segment> segments;
  for(const auto& ring : scaled)
    for(std::size_t i = 0; i < ring.size(); ++i) {
      const auto& a = ring[i];
      const auto& b = ring[(i + 1) % ring.size()];
      segments.push_back(Boost_segment(Boost_point(a.first, a.second), Boost_point(b.first, b.second)));
    }
  double t0 = now();
  boost::polygon::voronoi_diagram<double> vd;
  boost::polygon::construct_voronoi(segments.begin(), segments.end(), &vd);
  double t = now() - t0;
  note = "scale=1e" + std::to_string(k) + ";cells=" + std::to_string(vd.num_cells()) +
         ";vertices=" + std::to_string(vd.num_vertices()) + ";edges=" + std::to_string(vd.num_edges());
  return t;
}

double run_method(const std::string& m, const Rings& rings, std::string& note, double& aux,
                  const std::string& nv_dump_file)
{
  aux = -1;
  if(m == "pma_filtered") return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> >(rings, note, nv_dump_file);
  if(m == "pma_epick") return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> > >(rings, note, "");
  if(m == "pma_exact")
    return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<CORE::Expr> > >(rings, note, "");
  if(m == "pma_oneshot_1") return run_oneshot(rings, note, 1);
  if(m == "pma_oneshot_2") return run_oneshot(rings, note, 2);
  if(m == "pma_evolution") return run_evolution(rings, note);
  if(m == "pma_boundary")
    return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> >(
      rings, note, nv_dump_file.empty() ? "" : nv_dump_file.substr(0, nv_dump_file.size() - 7) + ".boundary.nv.txt",
      CGAL::BOUNDARY_EVOLUTION);
  if(m == "sdg") return run_sdg<Sdg>(rings, note);
  if(m == "sdg_hierarchy") return run_sdg<Sdg_hierarchy>(rings, note);
  if(m == "sdg_extract") return run_sdg_extract(rings, note, aux);
  if(m == "sdg_exact") return run_sdg<Sdg_exact>(rings, note);
  if(m == "boost_voronoi") return run_boost(rings, note);
  throw std::runtime_error("unknown method " + m);
}

const std::vector<std::string> all_methods = {"pma_filtered", "pma_oneshot_1", "pma_oneshot_2", "pma_epick", "pma_exact", "pma_evolution", "pma_boundary", "sdg",
                                              "sdg_hierarchy", "sdg_extract", "sdg_exact", "boost_voronoi"};

struct Measure {
  bool ok = false;
  double seconds = 0, aux = -1;
  double rss_mb = 0;
  bool timed_out = false;
  std::string note, status;
};

// Runs one measurement in a child process, with a time limit.
Measure measure(const std::string& m, const Rings& rings, double timeout, const std::string& nv_dump_file, bool warm)
{
  Measure r;
  Child_result c = run_in_child(
    [&]() {
      std::string note;
      double aux = -1;
      if(warm) {   // (a first call, untimed)
        run_method(m, rings, note, aux, "");
        note.clear();
        aux = -1;
      }
      const double t = run_method(m, rings, note, aux, nv_dump_file);
      char b[128];
      std::snprintf(b, sizeof(b), "%.9g\n%.9g\n", t, aux);
      return std::string(b) + (warm ? "warm;" : "") + note;
    },
    timeout);
  r.rss_mb = c.rss_mb;
  r.status = c.status;
  r.timed_out = c.timed_out;
  if(!c.ok) return r;
  std::istringstream in(c.payload);
  std::string t, a;
  std::getline(in, t);
  std::getline(in, a);
  std::getline(in, r.note);
  r.seconds = std::atof(t.c_str());
  r.aux = std::atof(a.c_str());
  r.ok = true;
  return r;
}

double median(std::vector<double> v)
{
  if(v.empty()) return -1;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3;
  Time_limits limits;
  bool baseline = true;
  std::vector<std::string> methods = all_methods;
  std::string nv_dump_dir;
  bool warm = false;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--timeout" && i + 1 < argc) limits.timeout = std::atof(argv[++i]);
    else if(a == "--exact-timeout" && i + 1 < argc) limits.exact_timeout = std::atof(argv[++i]);
    else if(a == "--methods" && i + 1 < argc) methods = split(argv[++i], ',');
    else if(a == "--no-baseline") baseline = false;
    else if(a == "--nv-dump" && i + 1 < argc) nv_dump_dir = argv[++i];
    else if(a == "--warm") warm = true;
    else if(a == "--help" || a == "-h") {
      std::cout << "usage: bench_time [--runs N] [--timeout S] [--exact-timeout S] [--methods m1,m2,...]\n"
                   "                  [--no-baseline] [--nv-dump DIR] [--warm] FILE...\n"
                   "methods:";
      for(const std::string& m : all_methods) std::cout << ' ' << m;
      std::cout << "\n";
      return 0;
    } else if(!a.empty() && a[0] == '-') {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    } else
      files.push_back(a);
  }
  if(!known_methods(methods, all_methods)) return 2;
  // the baseline, first
  const bool listed = std::find(methods.begin(), methods.end(), "pma_filtered") != methods.end();
  methods.erase(std::remove(methods.begin(), methods.end(), "pma_filtered"), methods.end());
  if(baseline || listed) methods.insert(methods.begin(), "pma_filtered");
  if(!nv_dump_dir.empty()) make_directory(nv_dump_dir);

  std::cout << "shape\tvertices\tholes\tmethod\tmedian_seconds\truns\tpeak_rss_mb\tstatus\tnote\tratio_to_pma_filtered\n";
  std::cout.flush();
  for(const std::string& f : files) {
    Rings rings;
    if(!read_rings_or_report(f, rings)) return 2;
    const std::string shape = base_name(f);
    const std::size_t n = number_of_vertices(rings);
    double base = -1;
    for(const std::string& m : methods) {
      if(m == "boost_voronoi") {
        std::vector<std::vector<std::pair<std::int32_t, std::int32_t> > > scaled;
        if(decimal_scale(rings, scaled) < 0) {
          std::printf("%s\t%zu\t%zu\t%s\t%.6f\t%d\t%.1f\t%s\t%s\t%s\n", shape.c_str(), n, rings.size() - 1, m.c_str(),
                      -1.0, 0, 0.0, "not applicable (coordinates not integral at any power-of-ten scale)", "", "-");
          std::fflush(stdout);
          continue;
        }
      }
      const double limit = limits.limit(m);
      const std::string skipped = limits.skip(m, n);
      if(!skipped.empty()) {
        std::printf("%s\t%zu\t%zu\t%s\t%.6f\t%d\t%.1f\t%s\t\t-\n", shape.c_str(), n, rings.size() - 1, m.c_str(), -1.0,
                    0, 0.0, skipped.c_str());
        std::fflush(stdout);
        continue;
      }
      std::vector<double> times, aux;
      Measure last;
      double rss = 0;
      for(int k = 0; k < runs; ++k) {
        const std::string dump =
          ((m == "pma_filtered" || m == "pma_boundary") && k == 0 && !nv_dump_dir.empty()) ? nv_dump_dir + "/" + shape + ".nv.txt" : "";
        last = measure(m, rings, limit, dump, warm);
        rss = std::max(rss, last.rss_mb);
        if(!last.ok) {
          limits.record(m, n, last.timed_out);
          break;
        }
        times.push_back(last.seconds);
        if(last.aux >= 0) aux.push_back(last.aux);
      }
      const double med = median(times);
      std::string note = last.note;
      if(!aux.empty()) {
        char b[64];
        std::snprintf(b, sizeof(b), "build_median_seconds=%.6f", median(aux));
        note = std::string(b) + ";" + note;
      }
      if(m == "pma_filtered") base = med;
      char ratio[32] = "-";
      if(med >= 0 && base > 0) std::snprintf(ratio, sizeof(ratio), "%.4g", med / base);
      std::printf("%s\t%zu\t%zu\t%s\t%.6f\t%zu\t%.1f\t%s\t%s\t%s\n", shape.c_str(), n, rings.size() - 1, m.c_str(),
                  med, times.size(), rss, last.status.c_str(), note.c_str(), ratio);
      std::fflush(stdout);
    }
  }
  return 0;
}
