// progressive_medial_axis: the command-line tool of Progressive_medial_axis_2.
//
//   progressive_medial_axis [options] INPUT.wkt|INPUT.geojson
//
// Reads one polygon (WKT POLYGON or GeoJSON Polygon), computes its medial
// axis (in one shot, or progressively by region growing with --step or
// --frames), and prints or writes it.  Run with
// --help for the options.  Exit status: 0 on success, 2 on invalid input or
// usage, 1 on any other failure.

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/CORE_Expr.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_centerline_2.h>
#include <CGAL/Progressive_medial_axis_2/maximum_inscribed_circle_2.h>

#include <pma_tool/polygon_io.h>
#include <pma_tool/medial_axis_io.h>
#include <pma_tool/medial_axis_drawing.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

const char* usage_text =
  "usage: progressive_medial_axis [options] INPUT.wkt|INPUT.geojson\n"
  "\n"
  "Computes the medial axis of one polygon: in one shot (divide and conquer, in\n"
  "parallel), or progressively by region growing with --step or --frames.\n"
  "Generator ids: e<r>.<i> is the edge from vertex i to vertex i+1 of ring r\n"
  "(ring 0 the outer ring, ring k the k-th hole), v<r>.<i> the reflex vertex i.\n"
  "\n"
  "options:\n"
  "  --pairs            print 'pair A B L' for every medial curve (A < B, L its length)\n"
  "  --branches         print 'branch A B C ... x y r' for every branch point\n"
  "  --step K           stop after K merges; ids then refer to the shape of that\n"
  "                     step, as written by --shape-out\n"
  "  --shape-out FILE   write the shape of the last step done as a WKT POLYGON\n"
  "  --svg FILE         draw the shape and its medial axis as SVG\n"
  "  --geojson FILE     write the medial axis (curves and branch points) as GeoJSON\n"
  "  --wkt-out FILE     write the medial axis as a WKT MULTILINESTRING\n"
  "  --frames N         with --frames-prefix P, draw N pictures of progressive steps,\n"
  "                     P_000.svg ... (the last one is the final axis)\n"
  "  --frames-prefix P  file name prefix of the progressive pictures\n"
  "  --traits T         filtered (default: exact decisions), epick (double), exact (CORE::Expr)\n"
  "  --threads N        threads of the one-shot computation (default: all hardware threads)\n"
  "  --prune SPEC       prune every axis output by erosion thickness (extended\n"
  "                     grassfire): SPEC is et=T, ratio=Q or et=T,ratio=Q; keeps the\n"
  "                     points with ET >= T (input units) and ET >= Q * EDF\n"
  "  --centerline FILE  write the centerline as WKT (LINESTRING, or MULTILINESTRING\n"
  "                     with holes), pruned by --prune or by default by et=R, R the\n"
  "                     radius of the maximum inscribed circle\n"
  "  --extend           extend the centerline's ends straight to the boundary\n"
  "  --width FILE       write the centerline's width profile as CSV: s,x,y,width\n"
  "  --inscribed-circle print 'circle X Y R': the maximum inscribed circle\n"
  "  --tolerance D      distance within which WKT and GeoJSON polylines follow the\n"
  "                     curves (default: 1e-6 of the shape's diagonal)\n"
  "  --stats            print the input size, step count, times and the largest n_v\n"
  "  --help             print this text\n";

[[noreturn]] void usage_error(const std::string& msg);

struct Options {
  bool pairs = false, branches = false, stats = false;
  long long step = -1;
  std::string input, shape_out, svg, geojson, wkt_out, frames_prefix, traits = "filtered";
  int frames = 0;
  int threads = 0;   // 0: all hardware threads
  bool prune = false, extend = false, inscribed_circle = false;
  double prune_et = 0, prune_ratio = 0, tolerance = -1;
  std::string centerline, width;
};

// a finite number >= 0 from option text
double parse_number(const std::string& option, const std::string& v)
{
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if(v.empty() || *end != '\0' || !std::isfinite(x) || x < 0)
    usage_error(option + " needs a finite number >= 0, got '" + v + "'");
  return x;
}

// --prune et=T | ratio=Q | et=T,ratio=Q
void parse_prune(Options& o, const std::string& spec)
{
  o.prune = true;
  std::size_t start = 0;
  bool any = false;
  while(start <= spec.size()) {
    const std::size_t comma = spec.find(',', start);
    const std::string item = spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t eq = item.find('=');
    const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if(eq == std::string::npos || (key != "et" && key != "ratio"))
      usage_error("--prune needs et=T, ratio=Q or et=T,ratio=Q, got '" + spec + "'");
    if(key == "et") o.prune_et = parse_number("--prune et", value);
    else {
      o.prune_ratio = parse_number("--prune ratio", value);
      if(o.prune_ratio >= 1) usage_error("--prune ratio needs a number from 0 to less than 1, got '" + value + "'");
    }
    any = true;
    if(comma == std::string::npos) break;
    start = comma + 1;
  }
  if(!any) usage_error("--prune needs et=T, ratio=Q or et=T,ratio=Q");
}

[[noreturn]] void usage_error(const std::string& msg)
{
  std::cerr << "progressive_medial_axis: " << msg << "\n(see --help)\n";
  std::exit(2);
}

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if(i + 1 >= argc) usage_error(std::string("option ") + name + " needs a value");
      return argv[++i];
    };
    if(a == "--help" || a == "-h") { std::cout << usage_text; std::exit(0); }
    else if(a == "--pairs") o.pairs = true;
    else if(a == "--branches") o.branches = true;
    else if(a == "--stats") o.stats = true;
    else if(a == "--step") {
      std::string v = value("--step");
      char* end = nullptr;
      o.step = std::strtoll(v.c_str(), &end, 10);
      if(v.empty() || *end != '\0' || o.step < 0) usage_error("--step needs a non-negative integer, got '" + v + "'");
    }
    else if(a == "--shape-out") o.shape_out = value("--shape-out");
    else if(a == "--svg") o.svg = value("--svg");
    else if(a == "--geojson") o.geojson = value("--geojson");
    else if(a == "--wkt-out") o.wkt_out = value("--wkt-out");
    else if(a == "--frames-prefix") o.frames_prefix = value("--frames-prefix");
    else if(a == "--frames") {
      std::string v = value("--frames");
      char* end = nullptr;
      long n = std::strtol(v.c_str(), &end, 10);
      if(v.empty() || *end != '\0' || n < 1 || n > 10000) usage_error("--frames needs an integer from 1 to 10000, got '" + v + "'");
      o.frames = int(n);
    }
    else if(a == "--threads") {
      std::string v = value("--threads");
      char* end = nullptr;
      long n = std::strtol(v.c_str(), &end, 10);
      if(v.empty() || *end != '\0' || n < 1 || n > 4096) usage_error("--threads needs an integer from 1 to 4096, got '" + v + "'");
      o.threads = int(n);
    }
    else if(a == "--prune") parse_prune(o, value("--prune"));
    else if(a == "--centerline") o.centerline = value("--centerline");
    else if(a == "--width") o.width = value("--width");
    else if(a == "--extend") o.extend = true;
    else if(a == "--inscribed-circle") o.inscribed_circle = true;
    else if(a == "--tolerance") {
      o.tolerance = parse_number("--tolerance", value("--tolerance"));
      if(!(o.tolerance > 0)) usage_error("--tolerance needs a number > 0");
    }
    else if(a == "--traits") {
      o.traits = value("--traits");
      if(o.traits != "filtered" && o.traits != "epick" && o.traits != "exact")
        usage_error("--traits must be filtered, epick or exact, got '" + o.traits + "'");
    }
    else if(!a.empty() && a[0] == '-') usage_error("unknown option '" + a + "'");
    else if(o.input.empty()) o.input = a;
    else usage_error("more than one input file ('" + o.input + "' and '" + a + "')");
  }
  if(o.input.empty()) usage_error("no input file");
  if(o.frames > 0 && o.frames_prefix.empty()) usage_error("--frames needs --frames-prefix");
  return o;
}

std::ofstream open_out(const std::string& path)
{
  std::ofstream f(path);
  if(!f) {
    std::cerr << "progressive_medial_axis: cannot write '" << path << "'\n";
    std::exit(1);
  }
  return f;
}

// The counters of the stages of the exact-decision traits.
template <class Traits>
auto print_filter_statistics(const Traits&, int) -> decltype(Traits::filter_statistics(), void())
{
  const auto& f = Traits::filter_statistics();
  std::printf("filter_interval_evaluations %zu\nfilter_double_double_evaluations %zu\nfilter_mpfr_evaluations %zu\n"
              "filter_rational_evaluations %zu\nfilter_exact_evaluations %zu\nfilter_mpfr_comparisons %zu\n"
              "filter_rational_comparisons %zu\nfilter_exact_comparisons %zu\nfilter_exact_ties %zu\n",
              f.interval_evaluations, f.double_double_evaluations, f.mpfr_evaluations, f.rational_evaluations,
              f.exact_evaluations, f.mpfr_comparisons, f.rational_comparisons, f.exact_comparisons, f.exact_ties);
}

template <class Traits>
void print_filter_statistics(const Traits&, long) {}

// A copy of the counters of the exact-decision traits, and its restoration.
template <class Traits>
auto filter_counters(int) -> decltype(Traits::filter_statistics())
{
  return Traits::filter_statistics();
}
template <class Traits>
int filter_counters(long) { return 0; }
template <class Traits, class C>
auto restore_filter_counters(const C& c, int) -> decltype(Traits::filter_statistics() = c, void())
{
  Traits::filter_statistics() = c;
}
template <class Traits, class C>
void restore_filter_counters(const C&, long) {}

template <class Traits>
int run(const Options& o)
{
  typedef CGAL::Progressive_medial_axis_2<Traits> PMA;
  typedef typename PMA::Medial_axis Medial_axis;
  typedef pma_tool::Generator_names<Medial_axis> Names;

  auto t0 = std::chrono::steady_clock::now();
  pma_tool::Rings<CGAL::Epick::Point_2> rings;
  try {
    rings = pma_tool::read_polygon_file<CGAL::Epick::Point_2>(o.input);
  } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
    std::cerr << o.input << ": " << e.what() << "\n";
    return 2;
  }
  double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const bool progressive = o.step >= 0 || o.frames > 0;
  std::unique_ptr<PMA> pma;
  Medial_axis one_shot;
  CGAL::Progressive_medial_axis_statistics one_shot_stats;
  int threads = 1;
  if(!progressive) {
    // the one-shot divide and conquer, on o.threads threads
    auto compute = [&]() { one_shot = CGAL::medial_axis_2(rings, Traits(), CGAL::CHECK_INPUT, &one_shot_stats); };
    try {
#ifdef CGAL_LINKED_WITH_TBB
      threads = o.threads > 0 ? o.threads : tbb::info::default_concurrency();
      // exact kernels run sequentially (see CGAL::medial_axis_2)
      if(!std::is_floating_point<typename Traits::Kernel::FT>::value) threads = 1;
      tbb::task_arena arena(threads);
      arena.execute(compute);
#else
      compute();
#endif
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      std::cerr << o.input << ": " << e.what() << "\n";
      return 2;
    }
  } else {
    try {
      pma.reset(new PMA(rings));
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      std::cerr << o.input << ": " << e.what() << "\n";
      return 2;
    }

    const std::size_t last = (o.step >= 0) ? std::min<std::size_t>(std::size_t(o.step), pma->number_of_steps())
                                           : pma->number_of_steps();
    // progressive pictures: frames at steps spread over the run, the last one final
    std::vector<std::size_t> frame_steps;
    if(o.frames > 0) {
      for(int i = 0; i < o.frames; ++i) {
        double f = (o.frames == 1) ? 1.0 : double(i) / double(o.frames - 1);
        // spread on a square-root scale so that early, coarse steps are shown
        frame_steps.push_back(std::size_t(std::llround(f * f * double(last))));
      }
    }
    std::size_t next_frame = 0;
    auto draw_frames = [&]() {
      while(next_frame < frame_steps.size() && frame_steps[next_frame] <= pma->current_step()) {
        char name[32];
        std::snprintf(name, sizeof(name), "_%03zu.svg", next_frame);
        std::ofstream f = open_out(o.frames_prefix + name);
        pma_tool::write_svg(f, pma->medial_axis(),
                              "step " + std::to_string(pma->current_step()) + " of " +
                                std::to_string(pma->number_of_steps()), 1000, true);
        ++next_frame;
      }
    };
    draw_frames();
    while(pma->current_step() < last) {
      pma->refine();
      if(!frame_steps.empty()) draw_frames();
    }
  }
  const double total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const Medial_axis& ma = progressive ? pma->medial_axis() : one_shot;
  const bool shape_mode = (o.step >= 0);
  Names names(ma, shape_mode ? Names::SHAPE : Names::INPUT);

  if(!o.shape_out.empty()) {
    std::ofstream f = open_out(o.shape_out);
    typename Names::Mode mode = Names::SHAPE;
    Names shape_names(ma, mode);
    std::vector<std::vector<CGAL::Epick::Point_2> > out;
    for(const auto& r : shape_names.rings()) {
      out.emplace_back();
      for(const auto& v : r) {
        auto p = Medial_axis::to_xy(ma.point(v));
        out.back().push_back(CGAL::Epick::Point_2(p.first, p.second));
      }
    }
    pma_tool::write_wkt_polygon(f, out);
    f << "\n";
  }
  // significance, pruning and centerline (timed together: time_prune)
  typedef typename Traits::Kernel Kernel;
  const auto tp = std::chrono::steady_clock::now();
  const bool centerline = !o.centerline.empty() || !o.width.empty();
  std::unique_ptr<CGAL::Medial_axis_significance_2<Kernel> > significance;
  std::unique_ptr<CGAL::Pruned_medial_axis_2<Kernel> > pruned;
  std::unique_ptr<CGAL::Medial_axis_centerline_2<Kernel> > center;
  if(o.prune || centerline) {
    significance.reset(new CGAL::Medial_axis_significance_2<Kernel>(ma));

    double et = o.prune_et, ratio = o.prune_ratio;
    if(!o.prune) {   // the default pruning of a centerline: et = the largest radius
      et = CGAL::to_double(CGAL::maximum_inscribed_circle_2(ma).radius);
      ratio = 0;
    }
    pruned.reset(new CGAL::Pruned_medial_axis_2<Kernel>(CGAL::prune_medial_axis_2(*significance, et, ratio)));
    if(centerline) center.reset(new CGAL::Medial_axis_centerline_2<Kernel>(CGAL::medial_axis_centerline_2(*pruned, o.extend)));
  }
  const double prune_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tp).count();
  typedef typename Medial_axis::Vertex_handle Vertex;
  const auto parts = o.prune ? pma_tool::axis_parts(*pruned) : pma_tool::axis_parts(ma);
  std::function<bool(const Vertex&)> keep;
  if(o.prune) keep = [&](const Vertex& v) { return pruned->is_kept(v); };

  if(o.pairs)
    pma_tool::write_pairs(std::cout, pma_tool::named_curves(parts, names));
  if(o.branches)
    pma_tool::write_branches(std::cout, pma_tool::named_branches(ma, names, 1e-12 * pma_tool::bbox_diagonal(ma), keep));
  if(o.inscribed_circle) {
    const auto c = CGAL::maximum_inscribed_circle_2(ma);
    const auto p = Medial_axis::to_xy(c.center);
    std::printf("circle %.17g %.17g %.17g\n", p.first, p.second, CGAL::to_double(c.radius));
  }
  if(!o.svg.empty()) {
    std::ofstream f = open_out(o.svg);
    pma_tool::write_svg(f, ma, parts, keep, "");
  }
  if(!o.geojson.empty()) {
    std::ofstream f = open_out(o.geojson);
    pma_tool::write_geojson(f, ma, parts, keep, names, o.tolerance);
  }
  if(!o.wkt_out.empty()) {
    std::ofstream f = open_out(o.wkt_out);
    pma_tool::write_wkt_axis(f, ma, parts, o.tolerance);
  }
  if(!o.centerline.empty()) {
    std::ofstream f = open_out(o.centerline);
    const double tol = o.tolerance > 0 ? o.tolerance : 1e-6 * pma_tool::shape_box(ma).diagonal();
    const auto lines = center->polylines(tol);
    const bool single = center->paths().size() == 1 && !center->paths()[0].closed;
    pma_tool::write_wkt_lines(f, lines, !single);
  }
  if(!o.width.empty()) {
    std::ofstream f = open_out(o.width);
    f << "s,x,y,width\n";
    for(const auto& w : center->width_profile())
      f << pma_tool::format_double(w.s) << ',' << pma_tool::format_double(w.x) << ',' << pma_tool::format_double(w.y)
        << ',' << pma_tool::format_double(w.width) << '\n';
  }
  if(o.stats) {
    const CGAL::Progressive_medial_axis_statistics& s = progressive ? pma->statistics() : one_shot_stats;
    std::size_t nb = 0;
    for(const auto& v : ma.vertices())
      if(v.kind() == Medial_axis::BRANCH_POINT) ++nb;
    // the step count of region growing (in one-shot mode, counted now: all done)
    std::size_t steps = 0;
    if(progressive) {
      steps = pma->number_of_steps();
    } else {
      const auto filters = filter_counters<Traits>(0);   // counting steps does not count as work
      steps = PMA(rings, Traits(), CGAL::TRUST_INPUT).number_of_steps();
      restore_filter_counters<Traits>(filters, 0);
    }
    std::printf("input_vertices %zu\nholes %zu\ntriangles %zu\nsteps %zu\nsteps_done %zu\n",
                s.input_vertices, s.holes, s.triangles, steps, progressive ? pma->current_step() : steps);
    std::printf("mode %s\nthreads %d\ntime_total %.6f\n", progressive ? "region" : "oneshot", threads, total_seconds);
    std::printf("traits %s\n", o.traits.c_str());
    std::printf("time_read %.6f\ntime_validate %.6f\ntime_triangulate %.6f\ntime_merge %.6f\n",
                read_seconds, s.validation_seconds, s.triangulation_seconds, s.merge_seconds);
    std::printf("switch_events %zu\nvanishing_events %zu\nanomalies %zu\nmax_n_v %zu\n",
                s.switches, s.vanishings, s.anomalies, s.max_queue);
    std::printf("redone_merges %zu\n", s.redone_merges);
    std::printf("medial_curves %zu\nbranch_vertices %zu\n", ma.number_of_edges(), nb);
    print_filter_statistics(Traits(), 0);
    if(o.prune) std::printf("pruned_curves %zu\n", pruned->number_of_pruned_curves());
    if(center) std::printf("centerline_length %.17g\n", center->length());
    if(pruned) std::printf("time_prune %.6f\n", prune_seconds);
  }
  // The process ends right after the output (main() calls std::_Exit):
  // the axis is left to the system rather than freed record by record.
  (void)significance.release();
  (void)pruned.release();
  (void)center.release();
  if(pma) (void)pma.release();
  else (void)new Medial_axis(std::move(one_shot));
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  Options o = parse(argc, argv);
  int status = 1;
  try {
    if(o.traits == "epick")   // every decision in double
      status = run<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> > >(o);
    else if(o.traits == "exact")
      status = run<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<CORE::Expr> > >(o);
    else
      status = run<CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> >(o);
  } catch(const std::exception& e) {
    std::cerr << "progressive_medial_axis: " << e.what() << "\n";
    status = 1;
  }
  std::cout.flush();
  std::fflush(nullptr);
  std::_Exit(status);
}
