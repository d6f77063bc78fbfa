// progressive_medial_axis: the command-line tool of Progressive_medial_axis_2.
//
//   progressive_medial_axis [options] INPUT.wkt|INPUT.geojson
//
// Reads polygons (WKT POLYGON, MULTIPOLYGON, GEOMETRYCOLLECTION; GeoJSON
// geometries, Feature, FeatureCollection), computes the medial axis of each
// (in one shot, or progressively by region growing with --step or --frames,
// for one polygon), or of the union of two polygons from their two axes
// (--union), and prints or writes them.  Run with
// --help for the options.  Exit status: 0 on success, 2 on invalid input or
// usage, 1 on any other failure.

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/CORE_Expr.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_centerline_2.h>
#include <CGAL/Progressive_medial_axis_2/maximum_inscribed_circle_2.h>
#include <CGAL/Progressive_medial_axis_2/medial_axis_union_2.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>

#include <pma_tool/polygon_io.h>
#include <pma_tool/medial_axis_io.h>
#include <pma_tool/medial_axis_drawing.h>
#include <pma_tool/html_viewer.h>
#include <pma_tool/repair.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>
#endif

#include <unistd.h>
#ifdef __GLIBC__
#include <gnu/libc-version.h>
#include <malloc.h>
#include <sys/auxv.h>
#endif

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

const char* usage_text =
  "usage: progressive_medial_axis [options] INPUT.wkt|INPUT.geojson\n"
  "\n"
  "Computes the medial axis of each polygon of the input (WKT POLYGON, MULTIPOLYGON,\n"
  "GEOMETRYCOLLECTION; GeoJSON Polygon, MultiPolygon, GeometryCollection, Feature,\n"
  "FeatureCollection; Z and M values are ignored, points and lines skipped): in one\n"
  "shot (divide and conquer, in parallel), or for one polygon progressively (region\n"
  "growing, or boundary evolution with --progressive boundary) with --step,\n"
  "--frames, --html or --progressive.\n"
  "Generator ids: e<r>.<i> is the edge from vertex i to vertex i+1 of ring r\n"
  "(ring 0 the outer ring, ring k the k-th hole), v<r>.<i> the reflex vertex i;\n"
  "with several polygons, p<k>: in front (k the polygon's index in input order).\n"
  "\n"
  "options:\n"
  "  --pairs            print 'pair A B L' for every medial curve (A < B, L its length)\n"
  "  --branches         print 'branch A B C ... x y r' for every branch point\n"
  "  --step K           stop after K progressive steps; ids then refer to the shape\n"
  "                     of that step, as written by --shape-out\n"
  "  --progressive D    the progressive driver: region (region growing, the default)\n"
  "                     or boundary (boundary evolution: the boundary simplified by\n"
  "                     discrete curve evolution, then refined vertex by vertex); alone,\n"
  "                     a full progressive run\n"
  "  --shape-out FILE   write the shape of the last step done (with --union, the\n"
  "                     union) as a WKT POLYGON\n"
  "  --svg FILE         draw the shape and its medial axis as SVG\n"
  "  --geojson FILE     write the medial axis (curves and branch points) as GeoJSON\n"
  "  --wkt-out FILE     write the medial axis as a WKT MULTILINESTRING\n"
  "  --frames N         with --frames-prefix P, draw N pictures of progressive steps,\n"
  "                     P_000.svg ... (the last one is the final axis)\n"
  "  --frames-prefix P  file name prefix of the progressive pictures\n"
  "  --html FILE        write a progressive viewer: one self-contained HTML page with\n"
  "                     the pictures of N progressive steps (--frames N, default 20),\n"
  "                     a slider over them, pan and zoom\n"
  "  --traits T         filtered (default: exact decisions), epick (double), exact (CORE::Expr)\n"
  "  --threads N        threads of the one-shot computation (default: all hardware threads)\n"
  "  --union OTHER      OTHER is a second polygon whose boundary shares chains of edges\n"
  "                     with INPUT's (same points, opposite directions): compute both\n"
  "                     axes in one shot, merge them, and output the axis of the union;\n"
  "                     ids then refer to the union polygon, as --shape-out writes it;\n"
  "                     given again, each OTHER is merged in turn with the union of\n"
  "                     those before it\n"
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
  "  --repair           turn invalid polygons (crossings, overlapping edges, spikes,\n"
  "                     zero-length edges, holes outside) into valid ones as GEOS\n"
  "                     MakeValid (structure method) does, locally where it can;\n"
  "                     ids then refer to the polygons after repair, as\n"
  "                     --repaired-out writes them\n"
  "  --repaired-out FILE  write the polygons after --repair as WKT\n"
  "  --stats            print the input size, step count, times and the largest n_v\n"
  "  --help             print this text\n";

[[noreturn]] void usage_error(const std::string& msg);

struct Options {
  bool pairs = false, branches = false, stats = false;
  long long step = -1;
  std::string input, shape_out, svg, geojson, wkt_out, frames_prefix, html, traits = "filtered";
  std::vector<std::string> union_with;   // --union, in the order given
  int frames = 0;
  int threads = 0;   // 0: all hardware threads
  bool prune = false, extend = false, inscribed_circle = false, repair = false;
  std::string repaired_out;
  std::string progressive;   // "", "region" or "boundary"
  double prune_et = 0, prune_ratio = 0, tolerance = -1;
  std::string centerline, width;
  // whether a centerline or its width profile is asked for
  bool centerline_asked() const { return !centerline.empty() || !width.empty(); }
  // whether the axis is analysed after it is computed (significance,
  // pruning, centerline)
  bool analysed() const { return prune || centerline_asked(); }
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
    else if(a == "--union") o.union_with.push_back(value("--union"));
    else if(a == "--svg") o.svg = value("--svg");
    else if(a == "--geojson") o.geojson = value("--geojson");
    else if(a == "--wkt-out") o.wkt_out = value("--wkt-out");
    else if(a == "--frames-prefix") o.frames_prefix = value("--frames-prefix");
    else if(a == "--html") o.html = value("--html");
    else if(a == "--progressive") {
      o.progressive = value("--progressive");
      if(o.progressive != "region" && o.progressive != "boundary")
        usage_error("--progressive must be region or boundary, got '" + o.progressive + "'");
    }
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
    else if(a == "--repair") o.repair = true;
    else if(a == "--repaired-out") o.repaired_out = value("--repaired-out");
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
  if(o.frames > 0 && o.frames_prefix.empty() && o.html.empty()) usage_error("--frames needs --frames-prefix or --html");
  if(!o.repaired_out.empty() && !o.repair) usage_error("--repaired-out needs --repair");
  if(!o.union_with.empty() && (o.step >= 0 || o.frames > 0 || !o.html.empty() || o.repair || !o.progressive.empty()))
    usage_error("--union cannot be combined with --step, --frames, --html, --progressive or --repair");
  if(o.repair && !pma_tool::can_repair())
    usage_error("--repair needs GEOS: this build of the tool has none (install libgeos-dev and rebuild)");
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

#if defined(__GLIBC__) && defined(__linux__)
// Whether this process runs as it was started: nothing preloaded (valgrind,
// heaptrack and other allocators come with LD_PRELOAD, and follow this
// process, not necessarily one it execs) and not in secure mode (where
// glibc drops its tunables).  Only then does the tool start itself again
// or its other build (restart_if_worth_it()).
[[maybe_unused]] bool plain_process()
{
  const char* preload = std::getenv("LD_PRELOAD");
  return !(preload && *preload) && !getauxval(AT_SECURE);
}
#endif

// Whether glibc's malloc can back its heaps with transparent huge pages in
// this process: glibc 2.35 or later, its malloc in use (no LD_PRELOAD, which
// valgrind, heaptrack and other allocators use; not a sanitized build), not
// in secure mode (glibc drops the tunable there), and a kernel that gives
// such pages on request (THP "madvise", the default of Debian and most
// distributions).
bool huge_page_heap_possible()
{
#if defined(__GLIBC__) && defined(__linux__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
  return false;
#endif
#endif
  if(!plain_process()) return false;
  int major = 0, minor = 0;
  if(std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor) != 2 || major < 2 || (major == 2 && minor < 35))
    return false;
  std::string mode;
  {
    std::ifstream thp("/sys/kernel/mm/transparent_hugepage/enabled");
    if(!std::getline(thp, mode)) return false;
  }
  return mode.find("[madvise]") != std::string::npos;
#else
  return false;
#endif
}

// The value of the last glibc.malloc.hugetlb in GLIBC_TUNABLES ("" if none).
std::string hugetlb_tunable()
{
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string t = tunables ? tunables : "", name = "glibc.malloc.hugetlb=";
  std::string value;
  for(std::size_t at = t.find(name); at != std::string::npos; at = t.find(name, at + 1))
    if(at == 0 || t[at - 1] == ':') value = t.substr(at + name.size(), t.find(':', at) - at - name.size());
  return value;
}

// Whether glibc's malloc backs its heaps with transparent huge pages
// (glibc.malloc.hugetlb=1, set by restart_if_worth_it() below or by the user,
// where it can); `huge_pages` in --stats.
bool heap_on_huge_pages() { return hugetlb_tunable() == "1" && huge_page_heap_possible(); }

#if defined(__GLIBC__) && defined(__linux__)
// An input file from this size on (about 20,000 vertices) is read by a
// process whose heap has transparent huge pages, and by the tool's build for
// the CPU's instruction set: one exec for both.  An exec costs 3 to 5 ms on
// the VM of RESULTS.md, a few per cent of a run of that size; the build
// with fused multiply-add alone would not pay for it on small inputs
// (RESULTS.md, sixty-fourth session).
constexpr std::uintmax_t min_huge_pages_input_bytes = 512 << 10;
#endif

// The instruction set this build of the tool was compiled for
// (`instruction_set` in --stats): CMake builds the tool a second time with
// fused multiply-add (below).
const char* instruction_set()
{
#if defined(PMA_TOOL_INSTRUCTION_SET)
  return PMA_TOOL_INSTRUCTION_SET;
#elif defined(__x86_64__)
  return "x86-64";
#else
  return "default";
#endif
}

// The tool's build with fused multiply-add (FMA3 and AVX: x86-64 CPUs from
// 2013 on), when this process should run it instead: the file beside this
// executable with ".fma" after its name, built from the same sources with
// -mfma -ffp-contract=off, where the CPU has FMA and AVX, for a large input
// (`large`).  "" if none.  The double-double stage, which rounds every
// branch point, computes the error of each product there in one fused
// multiply-add instead of Dekker's ten operations: the one-shot on
// c1m_CHN_0 took 5% to 7% less CPU time, and a build for all of x86-64-v3
// (AVX2, BMI2) no less (RESULTS.md, sixty-fourth session).  Without
// contraction (-ffp-contract=off) every double operation rounds as in the
// baseline build, and the double-double products are exact in both, so
// the axes are the same bit for bit.  The environment variable
// PMA_TOOL_INSTRUCTION_SET chooses: x86-64 (this build) or x86-64+fma (that
// build whatever the input's size, where the CPU has it).  Not under
// LD_PRELOAD (valgrind, heaptrack: they follow this process, not
// necessarily the one it execs) nor in secure mode.  (-mfma implies AVX,
// with which CGAL's Interval_nt takes its SSE code: the same bounds; the
// output of the two builds was compared on 1,503 runs, and the tests
// compare it.)
std::string build_for_this_cpu(bool large)
{
#if defined(__x86_64__) && defined(__linux__) && defined(__GLIBC__) && defined(__GNUC__) && !defined(PMA_TOOL_INSTRUCTION_SET)
  const char* chosen = std::getenv("PMA_TOOL_INSTRUCTION_SET");
  const std::string choice = chosen ? chosen : "";
  if(!choice.empty() && choice != "x86-64" && choice != "x86-64+fma")
    usage_error("PMA_TOOL_INSTRUCTION_SET must be x86-64 or x86-64+fma, not '" + choice + "'");
  if(choice == "x86-64" || (choice.empty() && !large)) return "";
  if(!plain_process()) return "";
  __builtin_cpu_init();
  if(!__builtin_cpu_supports("avx") || !__builtin_cpu_supports("fma")) return "";
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if(error) return "";
  const std::string build = self.string() + ".fma";
  // (not this executable itself, under another name: it would exec itself forever)
  if(access(build.c_str(), X_OK) != 0 || std::filesystem::equivalent(self, build, error) || error) return "";
  return build;
#else
  (void)large;
  return "";
#endif
}

// Runs the tool again, in this process, when that pays: with glibc's malloc
// backing its heaps with transparent huge pages, when the input (INPUT and
// the files of --union together) is large and huge_page_heap_possible();
// and as the build for this CPU's instruction set (build_for_this_cpu()).
// A large one-shot writes its structures once,
// front to back: with 4 KB pages, one page fault per page took 10% to 30%
// of the run on a 2-core VM, and 2 MB pages took 14% to 22% off the whole
// process on real outlines and 27% on a plate of 100,000 holes, for 5% to
// 35% more peak memory (RESULTS.md, "Huge pages for large inputs",
// twenty-first session).  glibc reads GLIBC_TUNABLES only when a process
// starts, and offers no call to set this one later, hence exec.  Huge pages
// are not asked for when GLIBC_TUNABLES already names the setting (so
// GLIBC_TUNABLES=glibc.malloc.hugetlb=0 turns them off).  Nothing is done
// when the tool was started through the dynamic loader (/proc/self/exe is
// then the loader).  Should the exec fail, the run goes on here as it is.
void restart_if_worth_it(const Options& o, char** argv)
{
#if defined(__GLIBC__) && defined(__linux__)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string before = tunables ? tunables : "";
  if(getauxval(AT_BASE) == 0) return;
  // (the input and, with --union, the other polygon's file)
  std::uintmax_t size = 0;
  std::vector<std::string> files = o.union_with;
  files.push_back(o.input);
  for(const std::string& file : files) {
    std::error_code error;
    size += std::filesystem::file_size(file, error);
    if(error) return;
  }
  const bool large = size >= min_huge_pages_input_bytes;
  const bool huge = large && before.find("glibc.malloc.hugetlb") == std::string::npos && huge_page_heap_possible();
  const std::string build = build_for_this_cpu(large);
  if(!huge && build.empty()) return;
  if(huge) {
    const std::string value = (before.empty() ? "" : before + ":") + "glibc.malloc.hugetlb=1";
    if(setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  }
  std::fflush(nullptr);
  if(!build.empty()) execv(build.c_str(), argv);
  if(huge) execv("/proc/self/exe", argv);   // (no other build, or it failed to start)
  if(tunables)
    setenv("GLIBC_TUNABLES", before.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
#else
  (void)o;
  (void)argv;
#endif
}

// Where the heap has transparent huge pages (heap_on_huge_pages()), makes
// the next block of the heap start at a huge-page boundary, in a heap that
// already reaches a huge page beyond it.  The kernel backs only whole,
// aligned 2 MB ranges of the heap with huge pages, and only where no 4 KB
// page was faulted in before.  The heap starts anywhere, and glibc had
// written the header of its free space into the range of the first
// boundary before the heap reached past it: the text of the input file,
// the first large block, was then faulted in 4 KB at a time, about 500 of
// c1m_CHN_0's 820 page faults (12 us each on the VM of RESULTS.md), before
// any thread works (RESULTS.md, thirty-ninth session).  The block that
// fills the gap below the boundary is never written beyond its header, so
// it takes no memory; it stays allocated (`heap_gap`).  glibc offers no
// call for this.
void align_heap_to_huge_pages()
{
#if defined(__GLIBC__) && defined(__linux__)
  // (volatile: a block that nothing reads, the compiler would not allocate;
  // static: kept reachable to the end)
  static void* volatile heap_gap = nullptr;
  std::uintptr_t huge = std::uintptr_t(2) << 20;
  {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/hpage_pmd_size");
    std::uintptr_t size = 0;
    if(in >> size && size != 0 && (size & (size - 1)) == 0) huge = size;
  }
  // A block larger than the heap's free space and than any block freed yet
  // comes from the start of the free space, once the heap has grown past it
  // (by the block and by M_TOP_PAD); freed, it goes back to the free space.
  void* probe = std::malloc(std::size_t(2 * huge));
  if(probe == nullptr) return;
  const std::uintptr_t at = reinterpret_cast<std::uintptr_t>(probe);
  std::free(probe);
  // A block of `gap - 8` bytes takes `gap` bytes of heap (its header
  // included; `at` and the boundary are multiples of 16), so that the free
  // space after it starts 16 bytes below the boundary, its header below it.
  const std::uintptr_t gap = (huge - at % huge) % huge;
  if(gap >= (std::uintptr_t(64) << 10))
    heap_gap = std::malloc(std::size_t(gap - 8));
#endif
}

// The counters of the stages of the exact-decision traits.
template <class Traits>
auto print_filter_statistics(const Traits&, int) -> decltype(Traits::filter_statistics(), void())
{
  const auto& f = Traits::filter_statistics();
  std::printf("filter_interval_evaluations %zu\nfilter_double_double_evaluations %zu\nfilter_mpfr_evaluations %zu\n"
              "filter_rational_evaluations %zu\nfilter_exact_evaluations %zu\nfilter_mpfr_comparisons %zu\n"
              "filter_rational_comparisons %zu\nfilter_exact_comparisons %zu\nfilter_exact_ties %zu\n"
              "filter_small_rational_overflows %zu\nfilter_dd_interval_evaluations %zu\n"
              "filter_dd_interval_comparisons %zu\nfilter_dd_interval_disks %zu\nfilter_mirror_ties %zu\n"
              "filter_hinted_switch_times %zu\nfilter_axis_aligned_disks %zu\nfilter_axis_aligned_ties %zu\n",
              f.interval_evaluations, f.double_double_evaluations, f.mpfr_evaluations, f.rational_evaluations,
              f.exact_evaluations, f.mpfr_comparisons, f.rational_comparisons, f.exact_comparisons, f.exact_ties,
              f.small_rational_overflows, f.dd_interval_evaluations, f.dd_interval_comparisons,
              f.dd_interval_disks, f.mirror_ties, f.hinted_switch_times, f.axis_aligned_disks,
              f.axis_aligned_ties);
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

// Adds the counters and times of t to s (the largest queue: the larger; the
// longest part of a divide and conquer: the longer).
void add_statistics(CGAL::Progressive_medial_axis_statistics& s, const CGAL::Progressive_medial_axis_statistics& t)
{
  s.input_vertices += t.input_vertices;
  s.holes += t.holes;
  s.triangles += t.triangles;
  s.merges += t.merges;
  s.validation_seconds += t.validation_seconds;
  s.triangulation_seconds += t.triangulation_seconds;
  s.overlapped_seconds += t.overlapped_seconds;
  s.split_triangulations += t.split_triangulations;
  s.split_triangulation_holes += t.split_triangulation_holes;
  s.triangulation_parallel_seconds += t.triangulation_parallel_seconds;
  s.merge_seconds += t.merge_seconds;
  s.switches += t.switches;
  s.vanishings += t.vanishings;
  s.anomalies += t.anomalies;
  s.undecided_ties += t.undecided_ties;
  s.redone_merges += t.redone_merges;
  s.max_queue = std::max(s.max_queue, t.max_queue);
  s.parts += t.parts;
  s.parts_seconds_sum += t.parts_seconds_sum;
  s.parts_seconds_max = std::max(s.parts_seconds_max, t.parts_seconds_max);
  s.join_seconds += t.join_seconds;
  s.first_step_seconds += t.first_step_seconds;
  s.evolution_seconds += t.evolution_seconds;
  s.cuts += t.cuts;
  s.splits += t.splits;
  s.recomputed_steps += t.recomputed_steps;
  s.boundary_evolution_one_shots += t.boundary_evolution_one_shots;
  s.region_growing_one_shots += t.region_growing_one_shots;
  s.abandoned_divide_and_conquers += t.abandoned_divide_and_conquers;
}

// One polygon of the input, its axis and what is computed from it.
template <class Traits>
struct Polygon_job {
  typedef typename Traits::Kernel Kernel;
  typedef CGAL::Medial_axis_2<Kernel> Medial_axis;
  const pma_tool::Input_polygon<CGAL::Epick::Point_2>* input = nullptr;
  std::string prefix;                    // "p<k>:" with several polygons, "" with one
  const Medial_axis* ma = nullptr;       // the axis output (one_shot, or a progressive step)
  Medial_axis one_shot;
  CGAL::Progressive_medial_axis_statistics stats;
  std::size_t steps = 0;
  std::unique_ptr<CGAL::Medial_axis_significance_2<Kernel> > significance;
  std::unique_ptr<CGAL::Pruned_medial_axis_2<Kernel> > pruned;
  std::unique_ptr<CGAL::Medial_axis_centerline_2<Kernel> > center;
  double prune_seconds = 0;
  double validation_seconds = 0;
  std::string error;                     // the input error of this polygon, if any
};

// Significance, pruning and centerline of one axis, as the options ask.
template <class Traits>
void analyse(const Options& o, Polygon_job<Traits>& job)
{
  typedef typename Traits::Kernel Kernel;
  const auto tp = std::chrono::steady_clock::now();
  const bool centerline = o.centerline_asked();
  if(o.analysed()) {
    job.significance.reset(new CGAL::Medial_axis_significance_2<Kernel>(*job.ma));
    double et = o.prune_et, ratio = o.prune_ratio;
    if(!o.prune) {   // the default pruning of a centerline: et = the largest radius
      et = job.significance->largest_radius();
      ratio = 0;
    }
    job.pruned.reset(new CGAL::Pruned_medial_axis_2<Kernel>(CGAL::prune_medial_axis_2(*job.significance, et, ratio)));
    if(centerline)
      job.center.reset(new CGAL::Medial_axis_centerline_2<Kernel>(CGAL::medial_axis_centerline_2(*job.pruned, o.extend)));
  }
  job.prune_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tp).count();
}

// A line of progress on stderr, when it is a terminal and the work has
// taken more than a second.
class Progress {
public:
  Progress(std::size_t total, const char* unit = "polygons")
    : total_(total), unit_(unit), start_(std::chrono::steady_clock::now()), tty_(isatty(2) != 0) {}
  void done_one()
  {
    if(!tty_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if(s < 1 || s - last_ < 0.2) return;
    last_ = s;
    std::fprintf(stderr, "\rprogressive_medial_axis: %zu of %zu %s, %.0f s", done_, total_, unit_, s);
    shown_ = true;
  }
  ~Progress()
  {
    if(shown_) std::fprintf(stderr, "\rprogressive_medial_axis: %zu of %zu %s, done%20s\n", done_, total_, unit_, "");
  }

private:
  std::size_t total_;
  const char* unit_;
  std::size_t done_ = 0;
  std::chrono::steady_clock::time_point start_;
  bool tty_, shown_ = false;
  double last_ = 0;
  std::mutex mutex_;
};

// What --repair repaired: the input polygons repaired, by the problem the
// check found first, and the polygons after repair.
struct Repair_counts {
  std::size_t polygons = 0, self_intersections = 0, repeated_vertices = 0, spikes = 0, zero_length_edges = 0,
              holes_outside = 0, other = 0, output_polygons = 0;
  double seconds = 0;
  void count(const std::string& error)
  {
    ++polygons;
    auto has = [&](const char* s) { return error.find(s) != std::string::npos; };
    if(has("self-intersection")) ++self_intersections;
    else if(has("repeated vertex")) ++repeated_vertices;
    else if(has("spike")) ++spikes;
    else if(has("zero-length edge")) ++zero_length_edges;
    else if(has("not inside the outer ring") || has("lies inside hole")) ++holes_outside;
    else ++other;
  }
};

#ifdef CGAL_LINKED_WITH_TBB
/// Writes to `out` the texts of pieces of an output, formatted on every
/// thread of the current arena and written in order, so that at most a few
/// pieces' text is held at a time.  `next(piece)` (in order, on one thread
/// at a time) sets the next piece, or returns false when there is none;
/// `format(piece)` (on any thread) returns its text; `written(piece)` (in
/// order, on one thread at a time) is called once its text is written.
/// `before` is written before the first text that is not empty, whose first
/// `skip` characters are not written (the separator before its first
/// item).  Returns whether any text was written.
template <class Piece, class Next, class Format, class Written>
bool write_in_pieces(std::ostream& out, int threads, const std::string& before, std::size_t skip, const Next& next,
                     const Format& format, const Written& written)
{
  bool any = false;
  tbb::parallel_pipeline(
    std::size_t(4 * threads),
    tbb::make_filter<void, Piece>(tbb::filter_mode::serial_in_order,
                                  [&](tbb::flow_control& control) -> Piece {
                                    Piece p;
                                    if(!next(p)) control.stop();
                                    return p;
                                  }) &
      tbb::make_filter<Piece, std::pair<Piece, std::string> >(
        tbb::filter_mode::parallel, [&](const Piece& p) { return std::make_pair(p, format(p)); }) &
      tbb::make_filter<std::pair<Piece, std::string>, void>(
        tbb::filter_mode::serial_in_order, [&](const std::pair<Piece, std::string>& t) {
          const std::string& text = t.second;
          if(!text.empty()) {
            const std::size_t s = any ? 0 : skip;
            if(!any) out << before;
            out.write(text.data() + s, std::streamsize(text.size() - s));
            any = true;
          }
          written(t.first);
        }));
  return any;
}
#endif

template <class Traits>
int run(const Options& o)
{
  typedef CGAL::Progressive_medial_axis_2<Traits> PMA;
  typedef typename PMA::Medial_axis Medial_axis;
  typedef pma_tool::Generator_names<Medial_axis> Names;
  typedef Polygon_job<Traits> Job;

  auto t0 = std::chrono::steady_clock::now();
  int threads = 1;
#ifdef CGAL_LINKED_WITH_TBB
  threads = o.threads > 0 ? o.threads : tbb::info::default_concurrency();
  // exact kernels run sequentially (see CGAL::medial_axis_2)
  if(!std::is_floating_point<typename Traits::Kernel::FT>::value) threads = 1;
  tbb::task_arena arena(threads);
  // start the worker threads now, while this thread reads the input (not
  // for a small file: see on_this_thread below)
  std::error_code size_error;
  const auto file_size = std::filesystem::file_size(o.input, size_error);
  const bool small_file = !size_error && file_size < 16384;
  if(threads > 1 && !small_file) arena.enqueue([] {});
#endif
  // (time_read is the reading alone; time_total counts TBB's start too)
  const auto t_read = std::chrono::steady_clock::now();
  std::vector<pma_tool::Input_polygon<CGAL::Epick::Point_2> > input;
  pma_tool::Skipped_geometries skipped;
  auto warn_skipped = [](const std::string& file, const pma_tool::Skipped_geometries& k) {
    if(k.count > 0)
      std::cerr << "progressive_medial_axis: warning: " << file << ": skipped " << k.count
                << (k.count == 1 ? " point or line geometry, which has" : " point and line geometries, which have")
                << " no medial axis (the first: " << k.first << ")\n";
  };
  try {
    input = pma_tool::read_polygons_file<CGAL::Epick::Point_2>(o.input, &skipped);
  } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
    std::cerr << o.input << ": " << e.what() << "\n";
    return 2;
  }
  warn_skipped(o.input, skipped);
  // --union: the other polygons, read and checked here (INPUT's is checked
  // below, with every input polygon)
  std::vector<pma_tool::Input_polygon<CGAL::Epick::Point_2> > other;
  if(!o.union_with.empty()) {
    const std::string* file = &o.input;
    auto one_polygon = [](std::size_t n) {
      if(n != 1)
        throw CGAL::Progressive_medial_axes::Input_error("--union needs one polygon in each file, found " + std::to_string(n));
    };
    try {
      one_polygon(input.size());
      for(const std::string& name : o.union_with) {
        file = &name;
        pma_tool::Skipped_geometries other_skipped;
        std::vector<pma_tool::Input_polygon<CGAL::Epick::Point_2> > read =
          pma_tool::read_polygons_file<CGAL::Epick::Point_2>(name, &other_skipped);
        warn_skipped(name, other_skipped);
        one_polygon(read.size());
        CGAL::Progressive_medial_axes::validate_polygon(read[0].rings);
        other.push_back(std::move(read[0]));
      }
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      std::cerr << *file << ": " << e.what() << "\n";
      return 2;
    }
  }
  double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_read).count();
#ifdef __GLIBC__
  // One polygon: one heap for all the threads.  What the other threads free
  // in heaps of their own stays with the process (glibc's malloc_trim()
  // gives back the top of the main heap only): 13 MiB of the peak of a
  // plate of 100,000 holes on two threads, 8 MiB of c1m_USA_3's.  With
  // thousands of polygons at once, one heap raised the peak of a
  // whole-world file by 6% (RESULTS.md, fifty-fourth session).
  if(input.size() == 1)
    mallopt(M_ARENA_MAX, 1);
#endif

  // A plain one-shot of one polygon from a small file, on the default
  // number of threads, runs on this thread outside the arena: the library
  // then starts oneTBB only if the polygon's parts are worth it (see
  // internal::min_parallel_seconds), and on a small polygon starting it
  // costs more than the axis.
  bool on_this_thread = false;
  auto in_arena = [&](const auto& f) {
#ifdef CGAL_LINKED_WITH_TBB
    if(on_this_thread)
      f();
    else
      arena.execute(f);
#else
    (void)on_this_thread;
    f();
#endif
  };
  // f(k) for k in order, in parallel over the polygons where the kernel allows.
  // Every polygon is a task of its own that an idle thread can take
  // (simple_partitioner, grain 1): the default partitioner keeps a range of
  // polygons on the thread that runs the first of them until that one is
  // done, so with one polygon far larger than the others (a country of a
  // million vertices) the other threads ran out of work while it was
  // computed (RESULTS.md, "Idle threads on a whole-world file").  Each
  // polygon runs isolated: a thread that waits for the parts of its polygon
  // takes no other polygon meanwhile, which would hold the first one up
  // until the second is done (and count the second's filter statistics
  // twice, in both polygons' counted tasks).
  auto for_each_polygon = [&](const std::vector<std::size_t>& order, const auto& f) {
#ifdef CGAL_LINKED_WITH_TBB
    if(order.size() > 1 && std::is_floating_point<typename Traits::Kernel::FT>::value) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, order.size(), 1),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for(std::size_t i = r.begin(); i != r.end(); ++i)
                            tbb::this_task_arena::isolate([&] { f(order[i]); });
                        },
                        tbb::simple_partitioner());
      return;
    }
#endif
    for(std::size_t k : order) f(k);
  };
  // the number of vertices of each polygon
  auto vertex_counts = [](const auto& polygons) {
    std::vector<std::size_t> size(polygons.size(), 0);
    for(std::size_t k = 0; k < size.size(); ++k)
      for(const auto& r : polygons[k].rings) size[k] += r.size();
    return size;
  };
  // the polygons of these numbers of vertices, largest first
  auto largest_of = [](const std::vector<std::size_t>& size) {
    std::vector<std::size_t> order(size.size());
    for(std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return size[a] > size[b]; });
    return order;
  };
  auto largest_first = [&](const auto& polygons) { return largest_of(vertex_counts(polygons)); };
  auto validate = [](const auto& rings, std::string& error) {
    const auto tv = std::chrono::steady_clock::now();
    try {
      CGAL::Progressive_medial_axes::validate_polygon(rings);
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      error = e.what();
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - tv).count();
  };
  // the first of the errors, and how many polygons have one
  auto report = [&](const std::vector<std::string>& errors, const std::string& what) {
    std::size_t first = errors.size(), count = 0;
    for(std::size_t k = 0; k < errors.size(); ++k)
      if(!errors[k].empty()) {
        if(first == errors.size()) first = k;
        ++count;
      }
    if(count == 0) return false;
    std::cerr << o.input << ": " << (errors.size() > 1 ? "polygon " + std::to_string(first) + ": " : "") << what
              << errors[first];
    if(count > 1) std::cerr << " (and " << count - 1 << " more invalid polygons)";
    std::cerr << "\n";
    return true;
  };

  const bool progressive = o.step >= 0 || o.frames > 0 || !o.html.empty() || !o.progressive.empty();
  const bool boundary = o.progressive == "boundary";
  // A plain one-shot (no progressive option, --union or --repair) checks
  // each polygon in CGAL::medial_axis_2(), while another thread triangulates
  // its points, and reports an invalid one once all are done; with --repair
  // it checks and repairs each polygon in the task that computes it (below).
  // Otherwise every polygon is checked before any is computed: an invalid
  // one stops the run at once, or is repaired with --repair.
  const bool check_in_one_shot = !progressive && o.union_with.empty() && !o.repair;
#ifdef CGAL_LINKED_WITH_TBB
  on_this_thread = check_in_one_shot && input.size() == 1 && small_file && threads == tbb::info::default_concurrency();
#endif
  std::vector<std::string> errors(input.size());
  std::vector<double> validation_seconds(input.size(), 0);
  std::vector<std::size_t> input_vertices;   // of each polygon (after repair)
  // With --repair, each polygon is checked and repaired in one task, and in a
  // one-shot run also computed there, so that the repair of a large polygon
  // runs while the other polygons are computed; the polygons after repair
  // are numbered once all are done.
  const bool repair_in_tasks = o.repair && !progressive;
  // --stats prints the steps of region growing, which the one-shots count
  // from their triangles (see below)
  if(o.stats && !progressive && o.union_with.empty())
    CGAL::Progressive_medial_axes::internal::one_shots_count_region_growing_steps() = true;
  typedef CGAL::Progressive_medial_axes::internal::Thread_counters<Traits> Counters;
  Counters counters;   // the filter counters of the other threads
  std::mutex counters_mutex;
  const std::thread::id caller = std::this_thread::get_id();
  // the one-shot axis of `rings` and its statistics (the filter counters of
  // every thread counted); the input error, if any
  auto one_shot = [&](auto&& rings, CGAL::Medial_axis_input_check checking, Medial_axis& axis,
                      CGAL::Progressive_medial_axis_statistics& stats) {
    std::string error;
    counters.run_counted(caller, counters_mutex, [&]() {
      try {
        axis = CGAL::medial_axis_2(std::forward<decltype(rings)>(rings), Traits(), checking, &stats);
      } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
        error = e.what();
      }
    });
    return error;
  };
  if(!check_in_one_shot && !o.repair)
    in_arena([&]() {
      for_each_polygon(largest_first(input), [&](std::size_t k) { validation_seconds[k] = validate(input[k].rings, errors[k]); });
    });
  Repair_counts repairs;
  // with repair_in_tasks: the axes of the polygons after repair, in order
  std::vector<Medial_axis> repaired_axes;
  std::vector<CGAL::Progressive_medial_axis_statistics> repaired_stats;
  if(o.repair) {
    typedef pma_tool::Input_polygon<CGAL::Epick::Point_2> Polygon;
    // for each input polygon, its polygons after repair (itself if it is
    // valid), and with repair_in_tasks their axes and statistics
    struct Part {
      Polygon polygon;
      std::size_t vertices = 0;
      Medial_axis axis;
      CGAL::Progressive_medial_axis_statistics stats;
    };
    std::vector<std::vector<Part> > parts(input.size());
    std::vector<std::string> repair_errors(input.size());
    std::vector<double> repair_seconds(input.size(), 0);
    Progress progress(input.size());
    in_arena([&]() {
      for_each_polygon(largest_first(input), [&](std::size_t k) {
        validation_seconds[k] = validate(input[k].rings, errors[k]);
        if(errors[k].empty()) {
          parts[k].resize(1);
          parts[k][0].polygon = std::move(input[k]);
        } else {
          const auto tr = std::chrono::steady_clock::now();
          try {
            for(auto& r : pma_tool::repair_polygon(input[k].rings)) {
              validate(r, repair_errors[k]);
              if(!repair_errors[k].empty()) break;
              parts[k].emplace_back();
              parts[k].back().polygon = Polygon{std::move(r), input[k].properties};
            }
          } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
            repair_errors[k] = e.what();
          }
          repair_seconds[k] = std::chrono::duration<double>(std::chrono::steady_clock::now() - tr).count();
        }
        for(Part& part : parts[k])
          for(const auto& r : part.polygon.rings) part.vertices += r.size();
        if(repair_in_tasks && repair_errors[k].empty()) {
          for(Part& part : parts[k]) {
            // (the rings given up, as below, unless --repaired-out writes them)
            repair_errors[k] = o.repaired_out.empty()
                                 ? one_shot(std::move(part.polygon.rings), CGAL::TRUST_INPUT, part.axis, part.stats)
                                 : one_shot(part.polygon.rings, CGAL::TRUST_INPUT, part.axis, part.stats);
            if(!repair_errors[k].empty()) break;
          }
        }
        progress.done_one();
      });
    });
    if constexpr(!std::is_empty<Counters>::value) counters.gather();
    if(report(repair_errors, "after repair: ")) return 2;
    std::vector<Polygon> out;
    std::vector<std::size_t> out_vertices;
    std::vector<double> seconds;   // of the checks of the valid input polygons
    // (reserved: grown by doubling, these vectors and the layers of the
    // outputs were about 27 MB more of the peak of a file of 72,000
    // islands; RESULTS.md, sixtieth session)
    std::size_t outputs = 0;
    for(const auto& p : parts) outputs += p.size();
    out.reserve(outputs);
    out_vertices.reserve(outputs);
    seconds.reserve(outputs);
    if(repair_in_tasks) {
      repaired_axes.reserve(outputs);
      repaired_stats.reserve(outputs);
    }
    for(std::size_t k = 0; k < input.size(); ++k) {
      if(!errors[k].empty()) repairs.count(errors[k]);
      repairs.seconds += repair_seconds[k];
      for(Part& part : parts[k]) {
        out.push_back(std::move(part.polygon));
        out_vertices.push_back(part.vertices);
        seconds.push_back(errors[k].empty() ? validation_seconds[k] : 0);
        if(repair_in_tasks) {
          repaired_axes.push_back(std::move(part.axis));
          repaired_stats.push_back(part.stats);
        }
      }
    }
    if(out.empty()) {
      std::cerr << o.input << ": after repair: no polygon of positive area is left\n";
      return 2;
    }
    input = std::move(out);
    input_vertices = std::move(out_vertices);
    validation_seconds = std::move(seconds);
    repairs.output_polygons = input.size();
  } else if(report(errors, "")) {
    return 2;
  }
  if(!o.repaired_out.empty()) {
    std::ofstream f = open_out(o.repaired_out);
    std::vector<CGAL::Progressive_medial_axes::Rings<CGAL::Epick::Point_2> > polygons;
    for(const auto& p : input) polygons.push_back(p.rings);
    pma_tool::write_wkt_polygons(f, polygons);
    f << "\n";
  }

  const bool multi = input.size() > 1;
  std::vector<Job> jobs(input.size());
  for(std::size_t k = 0; k < input.size(); ++k) {
    jobs[k].input = &input[k];
    jobs[k].validation_seconds = validation_seconds[k];
    if(multi) jobs[k].prefix = "p" + std::to_string(k) + ":";
  }
  // the order in which the polygons (after repair) are given to the threads
  // (by their numbers of vertices: the one-shots of the repairs gave their
  // rings up)
  if(!o.repair) input_vertices = vertex_counts(input);
  const std::vector<std::size_t> jobs_largest_first = largest_of(input_vertices);

  if(multi && (progressive || !o.shape_out.empty()))
    usage_error("--step, --frames, --html, --progressive and --shape-out need one polygon; " + o.input + " has " +
                std::to_string(input.size()));
  std::unique_ptr<PMA> pma;
  // (with --union given more than once: summed over the unions, and
  // `recomputed` 1 if any union was computed in one shot)
  CGAL::Progressive_medial_axes::Medial_axis_union_statistics union_stats;
  if(!o.union_with.empty()) {
    // the axes in one shot, then their union, with each other polygon in turn
    Job& job = jobs[0];
    std::vector<Medial_axis> axes(other.size() + 1);
    std::vector<CGAL::Progressive_medial_axis_statistics> so(other.size());
    in_arena([&]() {
      axes[0] = CGAL::medial_axis_2(input[0].rings, Traits(), CGAL::TRUST_INPUT, &job.stats);
      for(std::size_t k = 0; k < other.size(); ++k)
        axes[k + 1] = CGAL::medial_axis_2(other[k].rings, Traits(), CGAL::TRUST_INPUT, &so[k]);
    });
    for(std::size_t k = 0; k < other.size(); ++k) {
      CGAL::Progressive_medial_axes::Medial_axis_union_statistics u;
      try {
        job.one_shot = CGAL::medial_axis_union_2(k == 0 ? axes[0] : job.one_shot, axes[k + 1], Traits(), &u);
      } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
        // ("A and B: ...", then "A, B and C: ..." for the union of A and B with C)
        std::cerr << o.input;
        for(std::size_t i = 0; i < k; ++i) std::cerr << ", " << o.union_with[i];
        std::cerr << " and " << o.union_with[k] << ": " << e.what()
                  << (k == 0 ? "" : " (the first polygon: the union so far, numbered as --shape-out would write it)") << "\n";
        return 2;
      }
      add_statistics(job.stats, so[k]);
      job.stats.switches += u.switches;
      job.stats.vanishings += u.vanishings;
      // (where the merges met anomalies, the union's axis was computed again
      // in one shot: they do not touch it)
      if(!u.recomputed) job.stats.anomalies += u.anomalies;
      job.stats.undecided_ties += u.undecided_ties;
      union_stats.shared_edges += u.shared_edges;
      union_stats.chains += u.chains;
      union_stats.recomputed = (std::max)(union_stats.recomputed, u.recomputed);
      union_stats.merge_seconds += u.merge_seconds;
      union_stats.join_seconds += u.join_seconds;
    }
    job.stats.validation_seconds = 0;   // (counted in time_read with the reading)
    job.ma = &job.one_shot;
  } else if(repair_in_tasks) {
    // (computed with the repairs)
    for(std::size_t k = 0; k < jobs.size(); ++k) {
      jobs[k].one_shot = std::move(repaired_axes[k]);
      jobs[k].stats = repaired_stats[k];
      jobs[k].stats.validation_seconds = jobs[k].validation_seconds;
      jobs[k].ma = &jobs[k].one_shot;
    }
  } else if(!progressive) {
    // the one-shot divide and conquer of every polygon (in parallel over the
    // polygons, largest first, and within each), then what the options ask
    Progress progress(jobs.size());
    in_arena([&]() {
      for_each_polygon(jobs_largest_first, [&](std::size_t k) {
        Job& job = jobs[k];
        const auto checking = check_in_one_shot ? CGAL::CHECK_INPUT : CGAL::TRUST_INPUT;
        // The rings are given up to the one-shot, which gives their memory
        // back once it has copied the points (--stats rebuilds them from
        // the axis where it counts the steps of region growing apart).
        errors[k] = one_shot(std::move(input[k].rings), checking, job.one_shot, job.stats);
        if(errors[k].empty()) {
          if(!check_in_one_shot) job.stats.validation_seconds = job.validation_seconds;
          job.ma = &job.one_shot;
        }
        progress.done_one();
      });
    });
    if constexpr(!std::is_empty<Counters>::value) counters.gather();
    if(check_in_one_shot && report(errors, "")) return 2;
  } else {
    try {
      // (boundary evolution: the class's own check finds the vertices inside
      // edges that the evolution keeps, outside time_first_step; its step 0
      // is a one-shot on the --threads threads)
      in_arena([&]() {
        pma.reset(new PMA(input[0].rings, boundary ? CGAL::BOUNDARY_EVOLUTION : CGAL::REGION_GROWING, Traits(),
                          boundary ? CGAL::CHECK_INPUT : CGAL::TRUST_INPUT));
      });
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      std::cerr << o.input << ": " << e.what() << "\n";
      return 2;
    }

    const std::size_t last = (o.step >= 0) ? std::min<std::size_t>(std::size_t(o.step), pma->number_of_steps())
                                           : pma->number_of_steps();
    // progressive pictures: frames at steps spread over the run, the last one final
    std::vector<std::size_t> frame_steps;
    const int frames = o.frames > 0 ? o.frames : (o.html.empty() ? 0 : 20);
    for(int i = 0; i < frames; ++i) {
      double f = (frames == 1) ? 1.0 : double(i) / double(frames - 1);
      // spread on a square-root scale so that early, coarse steps are shown
      frame_steps.push_back(std::size_t(std::llround(f * f * double(last))));
    }
    std::size_t next_frame = 0;
    std::vector<pma_tool::Html_frame> html_frames;
    auto draw_frames = [&]() {
      while(next_frame < frame_steps.size() && frame_steps[next_frame] <= pma->current_step()) {
        std::ostringstream svg;
        pma_tool::write_svg(svg, pma->medial_axis(),
                              "step " + std::to_string(pma->current_step()) + " of " +
                                std::to_string(pma->number_of_steps()), 1000, true);
        if(!o.frames_prefix.empty()) {
          char name[32];
          std::snprintf(name, sizeof(name), "_%03zu.svg", next_frame);
          std::ofstream f = open_out(o.frames_prefix + name);
          f << svg.str();
        }
        if(!o.html.empty()) {
          pma_tool::Html_frame h;
          h.step = pma->current_step();
          h.steps = pma->number_of_steps();
          for(const auto& r : pma->medial_axis().shape_rings()) h.vertices += r.size();
          h.curves = pma->medial_axis().number_of_edges();
          h.svg = svg.str();
          html_frames.push_back(std::move(h));
        }
        ++next_frame;
      }
    };
    draw_frames();
    in_arena([&]() {   // (a recomputed step of boundary evolution is a one-shot)
      Progress progress(last - pma->current_step(), "steps");
      while(pma->current_step() < last) {
        pma->refine();
        progress.done_one();
        if(!frame_steps.empty()) draw_frames();
      }
    });
    if(!o.html.empty()) {
      std::ofstream f = open_out(o.html);
      const std::string name = o.input.substr(o.input.find_last_of('/') == std::string::npos ? 0 : o.input.find_last_of('/') + 1);
      pma_tool::write_html_viewer(f, html_frames, name);
    }
    Job& job = jobs[0];
    job.ma = &pma->medial_axis();
    job.stats = pma->statistics();
    job.steps = pma->number_of_steps();
  }
  const double total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  {
    // (a one-shot that meets an anomaly computes the axis again by region
    // growing, a union in one shot; a progressive run cannot, and says so)
    std::size_t anomalies = 0, undecided = 0;
    for(const Job& job : jobs) {
      anomalies += job.stats.anomalies;
      undecided += job.stats.undecided_ties;
    }
    if(anomalies != 0)
      std::cerr << "progressive_medial_axis: warning: " << anomalies
                << " merge anomalies: the axis may be wrong near them (please report the input)\n";
    if(undecided != 0)
      std::cerr << "progressive_medial_axis: warning: " << undecided
                << " ties of two vanishings left undecided: the axis may be wrong near them (please report the input)\n";
  }
  // significance, pruning and centerlines after the axes: time_total ends at
  // the final axis, they have time_prune of their own
  if(o.analysed())
    in_arena([&]() {
      for_each_polygon(jobs_largest_first, [&](std::size_t k) {
        if(jobs[k].ma) analyse(o, jobs[k]);
      });
    });
  if(o.stats && !progressive && o.union_with.empty()) {
    // the step count of region growing, out of the timing and the filter
    // counters (counting steps is not work of the one-shot)
    const auto filters = filter_counters<Traits>(0);
    in_arena([&]() {
      for_each_polygon(jobs_largest_first, [&](std::size_t k) {
        // (counted by the one-shot where its triangles are region growing's)
        const auto& counted = jobs[k].stats.region_growing_steps;
        if(!jobs[k].ma) return;
        jobs[k].steps = counted ? *counted : PMA(jobs[k].ma->input_rings(), Traits(), CGAL::TRUST_INPUT).number_of_steps();
      });
    });
    restore_filter_counters<Traits>(filters, 0);
  }

  const bool shape_mode = (o.step >= 0);
  if(!o.shape_out.empty()) {
    const Medial_axis& ma = *jobs[0].ma;
    std::ofstream f = open_out(o.shape_out);
    // the shape of the step, or the union polygon as its ids number it
    std::vector<std::vector<typename Medial_axis::Input_vertex> > rings = Names(ma, Names::SHAPE).rings();
    if(!o.union_with.empty()) {
      rings.assign(ma.number_of_input_rings(), {});
      for(std::size_t r = 0; r < rings.size(); ++r)
        for(std::size_t i = 0; i < ma.input_ring_size(r); ++i) rings[r].push_back({int(r), int(i)});
    }
    std::vector<std::vector<CGAL::Epick::Point_2> > out;
    for(const auto& r : rings) {
      out.emplace_back();
      for(const auto& v : r) {
        auto p = Medial_axis::to_xy(ma.point(v));
        out.back().push_back(CGAL::Epick::Point_2(p.first, p.second));
      }
    }
    pma_tool::write_wkt_polygon(f, out);
    f << "\n";
  }

  // the outputs, polygon after polygon, with the ids prefixed by p<k>: when
  // there are several
  typedef typename Medial_axis::Vertex_handle Vertex;
  std::vector<pma_tool::Axis_layer<Medial_axis> > layers;
  layers.reserve(jobs.size());
  for(std::size_t k = 0; k < jobs.size(); ++k) {
    const Job& job = jobs[k];
    pma_tool::Axis_layer<Medial_axis> layer;
    layer.ma = job.ma;
    if(o.prune) layer.keep = [p = job.pruned.get()](const Vertex& v) { return p->is_kept(v); };
    layer.names = pma_tool::prefixed_names(Names(*job.ma, shape_mode ? Names::SHAPE : Names::INPUT), job.prefix);
    layer.properties = job.input->properties;
    layer.polygon = multi ? long(k) : -1;
    layers.push_back(std::move(layer));
  }
  // the curves, for the outputs that list them (a plain run does not pay
  // for them), sorted (axis_parts()) on every thread
  auto curves_of = [&](std::size_t k) {
    return o.prune ? pma_tool::axis_parts(*jobs[k].pruned) : pma_tool::axis_parts(*jobs[k].ma);
  };
  const int listings = int(o.pairs) + int(!o.svg.empty()) + int(!o.geojson.empty()) + int(!o.wkt_out.empty());
#ifdef CGAL_LINKED_WITH_TBB
  // (where the GeoJSON or the WKT alone lists them, each polygon's when it
  // is written, and freed once it is: see write_in_pieces() below)
  const bool curves_when_written = listings == 1 && (!o.geojson.empty() || !o.wkt_out.empty());
#else
  const bool curves_when_written = false;
#endif
  if(listings > 0 && !curves_when_written)
    in_arena([&]() { for_each_polygon(jobs_largest_first, [&](std::size_t k) { layers[k].parts = curves_of(k); }); });
#ifdef CGAL_LINKED_WITH_TBB
  // the curves of polygon k for an output written in pieces, at its first
  // piece; freed after its last
  auto curves_due = [&](std::size_t k) {
    if(curves_when_written) layers[k].parts = curves_of(k);
  };
  auto curves_done = [&](std::size_t k) {
    if(curves_when_written) std::vector<pma_tool::Axis_part<Medial_axis> >().swap(layers[k].parts);
  };
  // the diagonal of each polygon's shape (the default tolerance of the
  // polylines, and the distance within which the GeoJSON merges branch
  // points), on every thread
  std::vector<double> diagonals;
  if(!o.geojson.empty() || !o.wkt_out.empty()) {
    diagonals.assign(layers.size(), 0);
    in_arena([&]() {
      for_each_polygon(jobs_largest_first,
                       [&](std::size_t k) { diagonals[k] = pma_tool::shape_box(*layers[k].ma).diagonal(); });
    });
  }
  auto tolerance_of = [&](std::size_t k) { return pma_tool::polyline_tolerance(o.tolerance, diagonals[k]); };
  // The outputs that list curves in pieces of at most `piece` curves or
  // branch points, formatted on every thread and written in order, so that
  // at most a few pieces' text is held at a time, and a large polygon is
  // formatted on every thread too.  (A polygon's text was held whole: 990 MB
  // and more for one of a million vertices, RESULTS.md, seventy-first
  // session.)
  constexpr std::size_t piece = 2048;
  struct Piece {
    std::size_t layer = 0, begin = 0, end = 0;
    bool branches = false, last = false;
  };
  // the items of `p`: the next `piece` of the `n` from `next_item`, which
  // moves on to them (back to 0 after the last); whether they end the n
  auto take_items = [&](Piece& p, std::size_t& next_item, std::size_t n) {
    p.begin = next_item;
    p.end = (std::min)(n, next_item + piece);
    next_item = p.end == n ? 0 : p.end;
    return p.end == n;
  };
#endif

  if(o.pairs)
    for(const auto& l : layers) pma_tool::write_pairs(std::cout, pma_tool::named_curves(l.parts, l.names));
  if(o.branches)
    for(const auto& l : layers)
      pma_tool::write_branches(std::cout,
                               pma_tool::named_branches(*l.ma, l.names, 1e-12 * pma_tool::bbox_diagonal(*l.ma), l.keep));
  if(o.inscribed_circle)
    for(const Job& job : jobs) {
      const auto c = CGAL::maximum_inscribed_circle_2(*job.ma);
      const auto p = Medial_axis::to_xy(c.center);
      std::printf("circle %s%s%.17g %.17g %.17g\n", job.prefix.substr(0, job.prefix.size() ? job.prefix.size() - 1 : 0).c_str(),
                  multi ? " " : "", p.first, p.second, CGAL::to_double(c.radius));
    }
  if(!o.svg.empty()) {
    std::ofstream f = open_out(o.svg);
    pma_tool::write_svg(f, layers, "");
  }
  if(!o.geojson.empty()) {
    std::ofstream f = open_out(o.geojson);
#ifdef CGAL_LINKED_WITH_TBB
    // A polygon's branch points are found when its first piece of them is
    // due, and freed after its last piece is written.
    std::vector<std::vector<pma_tool::Named_branch> > branches(layers.size());
    f << pma_tool::geojson_head;
    // the next piece: of the curves of layer `next_layer`, or of its branch
    // points, from `next_item`
    std::size_t next_layer = 0, next_item = 0;
    bool next_branches = false;
    in_arena([&]() {
      write_in_pieces<Piece>(
        f, threads, "", 2,   // (the first feature's ",\n")
        [&](Piece& p) {
          if(next_layer == layers.size()) return false;
          p.layer = next_layer;
          auto& l = layers[p.layer];
          if(next_item == 0 && !next_branches) curves_due(p.layer);   // (the polygon's first piece)
          if(next_item == 0 && next_branches) branches[p.layer] = pma_tool::geojson_branches(l, diagonals[p.layer]);
          p.branches = next_branches;
          const bool ended = take_items(p, next_item, next_branches ? branches[p.layer].size() : l.parts.size());
          p.last = p.branches && ended;
          if(ended) next_branches = !next_branches;
          if(p.last) ++next_layer;
          return true;
        },
        [&](const Piece& p) {
          std::ostringstream text;
          bool none = false;   // (each feature after ",\n")
          if(p.branches)
            pma_tool::write_geojson_branches(text, layers[p.layer], branches[p.layer], p.begin, p.end, none);
          else
            pma_tool::write_geojson_curves(text, layers[p.layer], tolerance_of(p.layer), p.begin, p.end, none);
          return text.str();
        },
        [&](const Piece& p) {
          if(!p.last) return;   // (every piece of the polygon is written once its last is)
          std::vector<pma_tool::Named_branch>().swap(branches[p.layer]);
          curves_done(p.layer);
        });
    });
    f << pma_tool::geojson_tail;
#else
    pma_tool::write_geojson(f, layers, o.tolerance);
#endif
  }
  if(!o.wkt_out.empty()) {
    std::ofstream f = open_out(o.wkt_out);
#ifdef CGAL_LINKED_WITH_TBB
    // (as pma_tool::write_wkt_axis() writes it)
    std::size_t next_layer = 0, next_item = 0;
    bool any = false;
    in_arena([&]() {
      any = write_in_pieces<Piece>(
        f, threads, pma_tool::wkt_axis_head, std::strlen(pma_tool::wkt_axis_separator),   // (the first polyline's)
        [&](Piece& p) {
          if(next_layer == layers.size()) return false;
          p.layer = next_layer;
          auto& l = layers[p.layer];
          if(next_item == 0) curves_due(p.layer);
          p.last = take_items(p, next_item, l.parts.size());
          if(p.last) ++next_layer;
          return true;
        },
        [&](const Piece& p) {
          std::ostringstream text;
          for(std::size_t k = p.begin; k < p.end; ++k) {
            text << pma_tool::wkt_axis_separator;
            pma_tool::write_wkt_points(text, layers[p.layer].parts[k].polyline(tolerance_of(p.layer)));
          }
          return text.str();
        },
        [&](const Piece& p) {
          if(p.last) curves_done(p.layer);
        });
    });
    f << (any ? pma_tool::wkt_axis_tail : pma_tool::wkt_axis_empty);
#else
    pma_tool::write_wkt_axis(f, layers, o.tolerance);
#endif
  }
  if(!o.centerline.empty()) {
    std::ofstream f = open_out(o.centerline);
    std::vector<std::vector<std::pair<double, double> > > lines;
    bool single = true;
    for(const Job& job : jobs) {
      const double tol = pma_tool::shape_tolerance(*job.ma, o.tolerance);
      for(auto& l : job.center->polylines(tol)) lines.push_back(std::move(l));
      single = single && !(job.center->paths().size() == 1 && job.center->paths()[0].closed);
    }
    pma_tool::write_wkt_lines(f, lines, !(single && lines.size() == 1));
  }
  if(!o.width.empty()) {
    std::ofstream f = open_out(o.width);
    f << (multi ? "polygon,s,x,y,width\n" : "s,x,y,width\n");
    for(std::size_t k = 0; k < jobs.size(); ++k)
      for(const auto& w : jobs[k].center->width_profile()) {
        if(multi) f << k << ',';
        f << pma_tool::format_double(w.s) << ',' << pma_tool::format_double(w.x) << ','
          << pma_tool::format_double(w.y) << ',' << pma_tool::format_double(w.width) << '\n';
      }
  }
  if(o.stats) {
    CGAL::Progressive_medial_axis_statistics s;
    std::size_t nb = 0, curves = 0, steps = 0, pruned_curves = 0;
    double centerline_length = 0, prune_seconds = 0;
    // the branch points of each axis (in parallel: a vertex's kind looks at
    // its curves, seconds on a whole-world file)
    std::vector<std::size_t> branches(jobs.size(), 0);
    in_arena([&]() {
      for_each_polygon(jobs_largest_first, [&](std::size_t k) {
        for(const auto& v : jobs[k].ma->vertices())
          if(v.kind() == Medial_axis::BRANCH_POINT) ++branches[k];
      });
    });
    for(std::size_t k = 0; k < jobs.size(); ++k) {
      const Job& job = jobs[k];
      const auto& t = job.stats;
      add_statistics(s, t);
      steps += job.steps;
      curves += job.ma->number_of_edges();
      nb += branches[k];
      if(job.pruned) pruned_curves += job.pruned->number_of_pruned_curves();
      if(job.center) centerline_length += job.center->length();
      prune_seconds += job.prune_seconds;
    }
    std::printf("input_vertices %zu\nholes %zu\ntriangles %zu\nsteps %zu\nsteps_done %zu\n",
                s.input_vertices, s.holes, s.triangles, steps, progressive ? pma->current_step() : steps);
    std::printf("mode %s\nthreads %d\ntime_total %.6f\n", progressive ? (boundary ? "boundary" : "region") : "oneshot",
                threads, total_seconds);
    std::printf("polygons %zu\nskipped_geometries %zu\n", jobs.size(), skipped.count);
    std::printf("traits %s\n", o.traits.c_str());
    std::printf("huge_pages %d\n", heap_on_huge_pages() ? 1 : 0);
    std::printf("instruction_set %s\n", instruction_set());
    std::printf("time_read %.6f\ntime_validate %.6f\ntime_triangulate %.6f\ntime_merge %.6f\n",
                read_seconds, s.validation_seconds, s.triangulation_seconds, s.merge_seconds);
    std::printf("switch_events %zu\nvanishing_events %zu\nanomalies %zu\nmax_n_v %zu\n",
                s.switches, s.vanishings, s.anomalies, s.max_queue);
    std::printf("redone_merges %zu\nundecided_ties %zu\n", s.redone_merges, s.undecided_ties);
    if(progressive) std::printf("time_first_step %.6f\n", s.first_step_seconds);
    if(boundary)
      std::printf("time_evolution %.6f\ncut_steps %zu\nsplit_steps %zu\nrecomputed_steps %zu\n", s.evolution_seconds,
                  s.cuts, s.splits, s.recomputed_steps);
    if(!progressive) {
      // the task tree of the one-shot divide and conquer: its work (every
      // task, summed) and span (the longest chain of dependent tasks)
      // (the polygons are independent: the span is that of the longest one)
      const double work = read_seconds + s.validation_seconds + s.triangulation_seconds +
                          s.triangulation_parallel_seconds + s.parts_seconds_sum + s.join_seconds;
      double span = 0;
      for(const Job& job : jobs) {
        const auto& t = job.stats;
        span = std::max(span, t.validation_seconds + t.triangulation_seconds -
                                  std::min(t.validation_seconds, t.overlapped_seconds) + t.parts_seconds_max +
                                  t.join_seconds);
      }
      std::printf("dc_parts %zu\ntime_parts_sum %.6f\ntime_parts_max %.6f\ntime_parts_join %.6f\ntime_work %.6f\n"
                  "time_span %.6f\n",
                  s.parts, s.parts_seconds_sum, s.parts_seconds_max, s.join_seconds, work, read_seconds + span);
      std::printf("oneshot_boundary_evolution %zu\n", s.boundary_evolution_one_shots);
      std::printf("oneshot_region_growing %zu\n", s.region_growing_one_shots);
      std::printf("oneshot_dc_abandoned %zu\n", s.abandoned_divide_and_conquers);
      std::printf("triangulation_split %zu\ntriangulation_split_holes %zu\n", s.split_triangulations,
                  s.split_triangulation_holes);
    }
    if(!o.union_with.empty())
      std::printf("time_union_merge %.6f\ntime_union_join %.6f\nunion_shared_edges %zu\nunion_chains %zu\n"
                  "union_recomputed %zu\nunions %zu\n",
                  union_stats.merge_seconds, union_stats.join_seconds, union_stats.shared_edges, union_stats.chains,
                  union_stats.recomputed, o.union_with.size());
    std::printf("medial_curves %zu\nbranch_vertices %zu\n", curves, nb);
    print_filter_statistics(Traits(), 0);
    if(o.prune) std::printf("pruned_curves %zu\n", pruned_curves);
    if(jobs[0].center) std::printf("centerline_length %.17g\n", centerline_length);
    if(jobs[0].pruned) std::printf("time_prune %.6f\n", prune_seconds);
    if(o.repair)
      std::printf("repaired_polygons %zu\nrepaired_self_intersections %zu\nrepaired_repeated_vertices %zu\n"
                  "repaired_spikes %zu\nrepaired_zero_length_edges %zu\nrepaired_holes_outside %zu\nrepaired_other %zu\n"
                  "repair_output_polygons %zu\ntime_repair %.6f\n",
                  repairs.polygons, repairs.self_intersections, repairs.repeated_vertices, repairs.spikes,
                  repairs.zero_length_edges, repairs.holes_outside, repairs.other,
                  repairs.output_polygons, repairs.seconds);
  }
  // The process ends right after the output (main() calls std::_Exit):
  // the axes are left to the system rather than freed record by record.
  (void)new std::vector<Job>(std::move(jobs));
  if(pma) (void)pma.release();
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  Options o = parse(argc, argv);
  restart_if_worth_it(o, argv);
#ifdef __GLIBC__
  // glibc grows and shrinks each thread's heap in small steps, and with two
  // threads every shrink (and every growth of a thread's heap) makes the
  // kernel flush the other CPU's TLB: a few milliseconds of a run on a small
  // polygon (RESULTS.md, "Start-up of small runs").  Grow in 16 MB steps and
  // give memory back only above 256 MB; the pages never touched cost nothing.
  mallopt(M_TOP_PAD, 16 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  // Setting these also froze the size above which glibc maps each block
  // afresh (128 KB; it would otherwise rise as large blocks are freed, up
  // to 32 MB).  Freeze it at 32 MB: the blocks of one part, one polygon or
  // one stage then reuse the pages that earlier ones freed in the heaps,
  // instead of mapping new pages, which the kernel zeroes and faults in one
  // by one, and unmapping them, which flushes the other CPU's TLB
  // (c1m_CHN_0 0.71 -> 0.61 s, c1m_DEU_0 0.46 -> 0.39 s, the same peak on
  // syn_plate100k: RESULTS.md, "Blocks above 128 KB from the heaps (issues
  // 9 and 12)").  A large one-shot still gives the free pages back
  // (release_memory_of_large_one_shots()).  Set for every run in the
  // fourth session, when a one-shot did not give them back, it had raised
  // the plate's peak by 25%.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  if(heap_on_huge_pages())
    align_heap_to_huge_pages();
  // When the axis is analysed afterwards, the analysis reuses the pages the
  // axis left instead of faulting in new ones: 10% to 15% of the analysis
  // on real outlines (RESULTS.md, "Significance, pruning and centerline,
  // fourth session").
  // glibc maps blocks above 32 MB afresh all the same, unless the main
  // heap maps none: the arrays of the analysis of a plate of 100,000 holes
  // are larger, and their pages are then reused too, for the same peak
  // (RESULTS.md, "The analysis's share (issue 14), seventeenth session").
  // For the same reason, a large one-shot then keeps what it freed rather
  // than give it back to the system (release_memory_of_large_one_shots()).
  // And one heap for all the threads (M_ARENA_MAX): what the threads of the
  // axis freed in their own heaps is then there for the analysis, which
  // allocates on this thread (RESULTS.md, "The analysis's share (issue 14),
  // eighteenth session").
  if(o.analysed()) {
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_ARENA_MAX, 1);
    CGAL::Progressive_medial_axes::internal::release_memory_of_large_one_shots() = false;
  }
#endif
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
