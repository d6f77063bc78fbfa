// bench_time: running time and peak memory of our medial axis and of its
// peers, on polygon files, in one run.
//
//   bench_time [--runs N] [--timeout SECONDS] [--methods m1,m2,...] FILE.wkt...
//
// Methods:
//   pma_filtered      our full progressive sequence, filtered traits (exact decisions),
//                     then the coordinates of every vertex of the final axis
//   pma_epick         the same with the double-precision traits
//   sdg               Segment_Delaunay_graph_2, filtered traits without intersections
//                     over Simple_cartesian<double> (construction of the diagram)
//   sdg_hierarchy     the same with Segment_Delaunay_graph_hierarchy_2
//
// Every measurement runs in a child process (fork), so that its peak memory
// (maxrss) is its own and a time limit can stop it.  Times are medians of
// N runs.  Output: one tab-separated row per file and method:
//   shape vertices holes method median_seconds runs peak_rss_mb status
// then, for pma methods, a row "nv" with the distribution of n_v per merge.

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/IO/polygon_io.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_hierarchy_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Epick::Point_2 Point;
typedef std::vector<std::vector<Point> > Rings;

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// ---- the methods; each returns its time in seconds and a short note ----

template <class Traits>
double run_pma(const Rings& rings, std::string& note)
{
  typedef CGAL::Progressive_medial_axis_2<Traits> PMA;
  typename PMA::Rings r;
  for(const auto& ring : rings) {
    r.emplace_back();
    for(const Point& p : ring) r.back().push_back(typename PMA::Point_2(p.x(), p.y()));
  }
  double t0 = now();
  PMA pma(r);
  pma.refine_all();
  // coordinates are computed on first use: read them all
  double checksum = 0;
  for(const auto& v : pma.medial_axis().vertices()) checksum += CGAL::to_double(v.radius());
  double t = now() - t0;
  if(!(checksum >= 0)) note = "bad radius";
  const auto& s = pma.statistics();
  std::map<std::uint32_t, std::size_t> hist;
  for(std::uint32_t v : s.queue_per_step) ++hist[v];
  std::ostringstream o;
  o << "edges=" << pma.medial_axis().number_of_edges() << ";nv_max=" << s.max_queue << ";nv_hist=";
  bool first = true;
  for(const auto& kv : hist) {
    o << (first ? "" : ",") << kv.first << ":" << kv.second;
    first = false;
  }
  note = o.str();
  return t;
}

template <class SDG>
double run_sdg(const Rings& rings, std::string& note)
{
  typedef typename SDG::Point_2 P;
  std::vector<P> points;
  std::vector<std::pair<std::size_t, std::size_t> > segments;
  for(const auto& ring : rings) {
    std::size_t base = points.size();
    for(const Point& p : ring) points.push_back(P(p.x(), p.y()));
    for(std::size_t i = 0; i < ring.size(); ++i)
      segments.emplace_back(base + i, base + (i + 1) % ring.size());
  }
  double t0 = now();
  SDG sdg;
  sdg.insert_segments(points, segments.begin(), segments.end());
  double t = now() - t0;
  note = "vertices=" + std::to_string(sdg.number_of_vertices());
  return t;
}

typedef CGAL::Simple_cartesian<double> SC;
typedef CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<SC, CGAL::Field_with_sqrt_tag> Sdg_traits;
typedef CGAL::Segment_Delaunay_graph_2<Sdg_traits> Sdg;
typedef CGAL::Segment_Delaunay_graph_hierarchy_2<Sdg_traits> Sdg_hierarchy;

double run_method(const std::string& m, const Rings& rings, std::string& note)
{
  if(m == "pma_filtered") return run_pma<CGAL::Progressive_medial_axis_filtered_traits_2<> >(rings, note);
  if(m == "pma_epick") return run_pma<CGAL::Progressive_medial_axis_traits_2<CGAL::Epick> >(rings, note);
  if(m == "sdg") return run_sdg<Sdg>(rings, note);
  if(m == "sdg_hierarchy") return run_sdg<Sdg_hierarchy>(rings, note);
  throw std::runtime_error("unknown method " + m);
}

struct Measure {
  bool ok = false;
  double seconds = 0;
  double rss_mb = 0;
  std::string note, status;
};

// Runs one measurement in a child process, with a time limit.
Measure measure(const std::string& m, const Rings& rings, double timeout)
{
  Measure r;
  int fd[2];
  if(pipe(fd) != 0) { r.status = "pipe failed"; return r; }
  pid_t pid = fork();
  if(pid == 0) {
    close(fd[0]);
    std::string note;
    double t = -1;
    try {
      t = run_method(m, rings, note);
    } catch(const std::exception& e) {
      note = std::string("error: ") + e.what();
    }
    std::string out = std::to_string(t) + "\n" + note + "\n";
    if(write(fd[1], out.data(), out.size()) < 0) {}
    close(fd[1]);
    _exit(t >= 0 ? 0 : 1);
  }
  close(fd[1]);
  double start = now();
  int status = 0;
  struct rusage ru;
  bool timed_out = false;
  for(;;) {
    pid_t w = wait4(pid, &status, WNOHANG, &ru);
    if(w == pid) break;
    if(now() - start > timeout) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &ru);
      timed_out = true;
      break;
    }
    usleep(2000);
  }
  std::string data;
  char buf[4096];
  ssize_t k;
  while((k = read(fd[0], buf, sizeof(buf))) > 0) data.append(buf, std::size_t(k));
  close(fd[0]);
  r.rss_mb = double(ru.ru_maxrss) / 1024.0;
  if(timed_out) {
    char b[64];
    std::snprintf(b, sizeof(b), "did not finish in %.0f s", timeout);
    r.status = b;
    return r;
  }
  std::istringstream in(data);
  std::string tline;
  std::getline(in, tline);
  std::getline(in, r.note);
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    r.status = r.note.empty() ? "crashed" : r.note;
    return r;
  }
  r.seconds = std::atof(tline.c_str());
  r.ok = true;
  r.status = "ok";
  return r;
}

std::vector<std::string> split(const std::string& s, char c)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string x;
  while(std::getline(ss, x, c)) if(!x.empty()) out.push_back(x);
  return out;
}

std::string base_name(const std::string& path)
{
  std::string b = path.substr(path.find_last_of('/') + 1);
  return b.substr(0, b.find_last_of('.'));
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3;
  double timeout = 600;
  std::vector<std::string> methods = {"pma_filtered", "pma_epick", "sdg", "sdg_hierarchy"};
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--timeout" && i + 1 < argc) timeout = std::atof(argv[++i]);
    else if(a == "--methods" && i + 1 < argc) methods = split(argv[++i], ',');
    else if(!a.empty() && a[0] == '-') { std::cerr << "unknown option " << a << "\n"; return 2; }
    else files.push_back(a);
  }
  std::cout << "shape\tvertices\tholes\tmethod\tmedian_seconds\truns\tpeak_rss_mb\tstatus\tnote\n";
  for(const std::string& f : files) {
    Rings rings;
    try {
      rings = CGAL::PMA2::read_polygon_file<Point>(f);
    } catch(const std::exception& e) {
      std::cerr << f << ": " << e.what() << "\n";
      return 2;
    }
    std::size_t n = 0;
    for(const auto& r : rings) n += r.size();
    for(const std::string& m : methods) {
      std::vector<double> times;
      Measure last;
      double rss = 0;
      for(int k = 0; k < runs; ++k) {
        last = measure(m, rings, timeout);
        rss = std::max(rss, last.rss_mb);
        if(!last.ok) break;
        times.push_back(last.seconds);
      }
      std::sort(times.begin(), times.end());
      double med = times.empty() ? -1 : times[times.size() / 2];
      std::printf("%s\t%zu\t%zu\t%s\t%.6f\t%zu\t%.1f\t%s\t%s\n", base_name(f).c_str(), n, rings.size() - 1,
                  m.c_str(), med, times.size(), rss, last.status.c_str(), last.note.c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
