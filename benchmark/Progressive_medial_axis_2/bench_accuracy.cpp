// bench_accuracy: the accuracy E(x) = 1 - r_min / r_max of branch points (Liu et al. 2016,
// section 6.3; algorithm.md section 6) of our medial axis and of CGAL's segment Delaunay
// graph, with the topology of each against the oracle, on polygon files.
//
//   bench_accuracy [--timeout S] [--exact-timeout S] [--methods m1,m2,...] [--dump DIR] FILE...
//
// Methods (default: all, in this order); each runs in a forked child process, stopped
// after S seconds (--timeout, default 600; --exact-timeout, default the same, for
// pma_exact and sdg_exact).  A method that did not finish in time is not run again on
// files with as many vertices or more (status "not run: ..."):
//   pma_filtered   our full progressive run, filtered traits: E(x) of every branch point
//                  (branch_point_errors: vertices where >= 3 medial curves meet)
//   pma_epick      the same with the double-precision traits
//   pma_exact      the same with the CORE::Expr traits (coordinates rounded by to_double)
//   floor          floor_branch_point_errors of the filtered axis: E(x) of the exact
//                  branch points correctly rounded to double, the best any double answer
//                  can do
//   sdg_filtered   Segment_Delaunay_graph_2 (filtered traits without intersections over
//                  Simple_cartesian<double>): E(x) at its interior Voronoi vertices of
//                  positive radius whose three sites are all generators (segments, reflex
//                  vertices) and that are branch points of the medial axis, i.e. not the
//                  degree-2 junctions where a curve crosses the normal of a segment at its
//                  reflex endpoint (a point site and a segment ending there: counted in the
//                  note as junctions, not in the statistics); each vertex constructed in
//                  double by the SDG's construct_svd_vertex_2, its generators its three sites
//   sdg_exact      the same vertices of Segment_Delaunay_graph_2 built with
//                  Segment_Delaunay_graph_traits_2<Simple_cartesian<CORE::Expr>,
//                  Field_with_sqrt_tag>, constructed exactly and rounded with
//                  CGAL::to_double
//
// E(x) is computed by CGAL::Progressive_medial_axes::medial_point_error (distances in 256-bit intervals).
// topology: for pma_*, "same" if the medial curves of that run match the oracle's
// (pma_test::sdg_medial_axis, compared by pma_test::compare_curves with the degenerate
// tolerance), else "differs (N curves)" with N the number of unmatched or mismatched
// curves; for sdg_*, "same" if the multiset of generator pairs of the interior Voronoi
// edges read off by the benchmarks' lean extraction (bench_common.h, Sdg_interior: the one
// bench_time's sdg_extract times) equals the oracle's, else "differs (N curves)" with N
// the size of the symmetric difference; "-" for floor.  The oracle runs once per file, in
// this process (its time goes to stderr).
//
// Output: one tab-separated row per file and method:
//   shape vertices holes method branch_points mean sd max topology status note
// (mean, sd, max: -1 when the method did not finish or failed).
//
// --dump DIR: writes DIR/<shape>.<method>.txt, the E(x) values in decreasing order, one
// per line (%.9g).

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Accuracy.h>
#include <pma_tool/medial_axis_io.h>

#include "bench_common.h"

#include <pma_test/compare_curves.h>
#include <pma_test/sdg_oracle.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace pma_bench;
using CGAL::Progressive_medial_axes::Accuracy_site;

const std::vector<std::string> all_methods = {"pma_filtered", "pma_epick", "pma_exact",
                                              "floor",        "sdg_filtered", "sdg_exact"};

struct Row {
  std::vector<double> errors;
  std::string topology = "-";
  std::string note;
};

void dump_errors(std::vector<double> e, const std::string& file)
{
  if(file.empty()) return;
  std::sort(e.begin(), e.end(), [](double a, double b) { return a > b; });
  std::FILE* out = std::fopen(file.c_str(), "w");
  if(!out) throw std::runtime_error("cannot write " + file);
  for(double v : e) std::fprintf(out, "%.9g\n", v);
  if(std::fclose(out) != 0) throw std::runtime_error("cannot write " + file);
}

std::string differs(std::size_t n) { return "differs (" + std::to_string(n) + " curves)"; }

template <class Traits>
Row run_pma(const Rings& rings, const pma_test::Oracle_result* oracle, bool floor)
{
  typedef CGAL::Progressive_medial_axis_2<Traits> PMA;
  typedef typename PMA::Medial_axis MA;
  const double t0 = now();
  PMA pma(rings);
  pma.refine_all();
  const MA& ma = pma.medial_axis();
  Row row;
  row.errors = floor ? CGAL::Progressive_medial_axes::floor_branch_point_errors(ma) : CGAL::Progressive_medial_axes::branch_point_errors(ma);
  const double t = now() - t0;
  const pma_tool::Generator_names<MA> names(ma, pma_tool::Generator_names<MA>::INPUT);
  const auto curves = pma_tool::named_curves(ma, names);
  if(!floor) {
    if(!oracle) {
      row.topology = "no oracle";
    } else {
      std::vector<pma_test::Oracle_curve> ours;
      for(const auto& c : curves) ours.push_back(pma_test::Oracle_curve{c.a, c.b, c.length});
      const pma_test::Curve_diff d = pma_test::compare_curves(ours, oracle->curves, oracle->bbox_diagonal);
      row.topology = d.ok() ? "same"
                            : differs(d.only_in_a.size() + d.only_in_b.size() + d.length_mismatch.size());
    }
  }
  char b[128];
  std::snprintf(b, sizeof(b), "curves=%zu;seconds=%.3f", curves.size(), t);
  row.note = b;
  return row;
}

template <class SDG>
Row run_sdg(const Rings& rings, const pma_test::Oracle_result* oracle)
{
  typedef Sdg_interior<SDG> Interior;
  const double t0 = now();
  SDG sdg;
  build_sdg(sdg, rings);
  const double t_build = now() - t0;
  const Polygon_info P = polygon_info(rings);
  const Interior in(sdg, P);
  Row row;
  // the medial curves, by generator pairs
  std::vector<std::pair<std::string, std::string> > ours;
  in.for_each_curve([&](const typename Interior::Curve& c) {
    std::string a = in.generator_id(c.a), b = in.generator_id(c.b);
    if(b < a) std::swap(a, b);
    ours.emplace_back(a, b);
  });
  if(!oracle) {
    row.topology = "no oracle";
  } else {
    std::vector<std::pair<std::string, std::string> > theirs;
    for(const auto& c : oracle->curves) theirs.emplace_back(c.a < c.b ? c.a : c.b, c.a < c.b ? c.b : c.a);
    std::sort(ours.begin(), ours.end());
    std::sort(theirs.begin(), theirs.end());
    std::vector<std::pair<std::string, std::string> > diff;
    std::set_symmetric_difference(ours.begin(), ours.end(), theirs.begin(), theirs.end(), std::back_inserter(diff));
    row.topology = diff.empty() ? "same" : differs(diff.size());
  }
  // the branch points
  std::size_t junctions = 0;
  const double t1 = now();
  for(int f = 0; f < int(in.number_of_faces()); ++f) {
    if(in.face_class(f) != Interior::INSIDE) continue;
    bool generators = true, junction = false;
    for(int k = 0; k < 3; ++k) {
      const auto& S = in.face_site(f, k);
      if(!S.generator) generators = false;
    }
    if(!generators) continue;
    for(int k = 0; k < 3; ++k)
      for(int l = 0; l < 3; ++l) {
        const auto &A = in.face_site(f, k), &B = in.face_site(f, l);
        if(A.is_point && !B.is_point && (B.src == A.g || B.tgt == A.g)) junction = true;
      }
    if(junction) {
      ++junctions;
      continue;
    }
    std::vector<Accuracy_site> g;
    for(int k = 0; k < 3; ++k) {
      const auto& S = in.face_site(f, k);
      const Point &a = P.pts[std::size_t(S.src)], &b = P.pts[std::size_t(S.tgt)];
      g.push_back(Accuracy_site{S.is_point, a.x(), a.y(), b.x(), b.y()});
    }
    const typename SDG::Point_2 v = in.vertex(f);
    row.errors.push_back(CGAL::Progressive_medial_axes::medial_point_error(CGAL::to_double(v.x()), CGAL::to_double(v.y()), g));
  }
  const double t_vertices = now() - t1;
  char b[160];
  std::snprintf(b, sizeof(b), "curves=%zu;junctions=%zu;build_seconds=%.3f;vertex_seconds=%.3f", ours.size(),
                junctions, t_build, t_vertices);
  row.note = b;
  return row;
}

Row run_method(const std::string& m, const Rings& rings, const pma_test::Oracle_result* oracle)
{
  if(m == "pma_filtered") return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> >(rings, oracle, false);
  if(m == "pma_epick") return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> > >(rings, oracle, false);
  if(m == "pma_exact")
    return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<CORE::Expr> > >(rings, oracle, false);
  if(m == "floor") return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> >(rings, oracle, true);
  if(m == "sdg_filtered") return run_sdg<Sdg>(rings, oracle);
  if(m == "sdg_exact") return run_sdg<Sdg_exact>(rings, oracle);
  throw std::runtime_error("unknown method " + m);
}

} // namespace

int main(int argc, char** argv)
{
  Time_limits limits;
  std::string dump_dir;
  std::vector<std::string> methods = all_methods;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--timeout" && i + 1 < argc) limits.timeout = std::atof(argv[++i]);
    else if(a == "--exact-timeout" && i + 1 < argc) limits.exact_timeout = std::atof(argv[++i]);
    else if(a == "--dump" && i + 1 < argc) dump_dir = argv[++i];
    else if(a == "--methods" && i + 1 < argc) methods = split(argv[++i], ',');
    else if(a == "--help" || a == "-h") {
      std::cout << "usage: bench_accuracy [--timeout S] [--exact-timeout S] [--methods m1,m2,...] [--dump DIR] FILE...\nmethods:";
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
  if(!dump_dir.empty()) make_directory(dump_dir);

  std::cout << "shape\tvertices\tholes\tmethod\tbranch_points\tmean\tsd\tmax\ttopology\tstatus\tnote\n";
  std::cout.flush();
  for(const std::string& f : files) {
    Rings rings;
    if(!read_rings_or_report(f, rings)) return 2;
    const std::string shape = base_name(f);
    const std::size_t n = number_of_vertices(rings);

    // the oracle, once per file
    std::unique_ptr<pma_test::Oracle_result> oracle;
    bool need_oracle = false;
    for(const std::string& m : methods) need_oracle = need_oracle || m != "floor";
    if(need_oracle) {
      const double t0 = now();
      try {
        oracle.reset(new pma_test::Oracle_result(pma_test::sdg_medial_axis(rings)));
        std::fprintf(stderr, "%s: oracle %.3f s, %zu curves\n", shape.c_str(), now() - t0, oracle->curves.size());
      } catch(const std::exception& e) {
        std::fprintf(stderr, "%s: oracle failed: %s\n", shape.c_str(), e.what());
      }
    }

    for(const std::string& m : methods) {
      const std::string skipped = limits.skip(m, n);
      if(!skipped.empty()) {
        std::printf("%s\t%zu\t%zu\t%s\t-1\t-1\t-1\t-1\t-\t%s\t\n", shape.c_str(), n, rings.size() - 1, m.c_str(),
                    skipped.c_str());
        std::fflush(stdout);
        continue;
      }
      const std::string dump = dump_dir.empty() ? "" : dump_dir + "/" + shape + "." + m + ".txt";
      const Child_result c = run_in_child(
        [&]() {
          const Row row = run_method(m, rings, oracle.get());
          dump_errors(row.errors, dump);
          const CGAL::Progressive_medial_axes::Accuracy_statistics s = CGAL::Progressive_medial_axes::accuracy_statistics(row.errors);
          char b[256];
          std::snprintf(b, sizeof(b), "%zu\t%.6g\t%.6g\t%.6g\t", s.count, s.mean, s.standard_deviation, s.max);
          return std::string(b) + row.topology + "\t" + row.note;
        },
        limits.limit(m));
      limits.record(m, n, c.timed_out);
      std::string fields = "-1\t-1\t-1\t-1\t-", note;
      if(c.ok) {
        const std::size_t cut = c.payload.rfind('\t');
        fields = c.payload.substr(0, cut);
        note = c.payload.substr(cut + 1);
      }
      std::printf("%s\t%zu\t%zu\t%s\t%s\t%s\t%s\n", shape.c_str(), n, rings.size() - 1, m.c_str(), fields.c_str(),
                  c.status.c_str(), note.c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
