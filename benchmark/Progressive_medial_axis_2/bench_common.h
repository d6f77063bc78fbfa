// Shared helpers of the benchmark programs of Progressive_medial_axis_2
// (bench_time, bench_accuracy).  Benchmark-only code, never used by the library.
//
//  * run_in_child(): runs a measurement in a forked child process with a time limit; the
//    child's peak RSS is its own;
//  * Polygon_info: the input rings with the exact turn (convex / reflex / flat) of every
//    vertex;
//  * Sdg_interior<SDG>: a user's lean extraction of the interior medial axis from an already
//    built Segment_Delaunay_graph_2 (no MPFR, no multi-precision: inside/outside is decided
//    combinatorially, as in test/.../pma_test/sdg_oracle.h, see below);
//  * decimal_scale(): the power-of-ten scale at which the input is integral (Boost.Polygon).

#ifndef PMA_BENCH_COMMON_H
#define PMA_BENCH_COMMON_H

#include <pma_tool/polygon_io.h>

#include <CGAL/CORE_Expr.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Segment_Delaunay_graph_hierarchy_2.h>
#include <CGAL/Segment_Delaunay_graph_traits_2.h>
#include <CGAL/Simple_cartesian.h>

#include <poll.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pma_bench {

typedef CGAL::Epick::Point_2 Point;
typedef std::vector<std::vector<Point> > Rings;

inline double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline std::vector<std::string> split(const std::string& s, char c)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string x;
  while(std::getline(ss, x, c))
    if(!x.empty()) out.push_back(x);
  return out;
}

/// File name without directory and last extension.
inline std::string base_name(const std::string& path)
{
  std::string b = path.substr(path.find_last_of('/') + 1);
  return b.substr(0, b.find_last_of('.'));
}

inline Rings read_rings(const std::string& file) { return pma_tool::read_polygon_file<Point>(file); }

inline std::size_t number_of_vertices(const Rings& rings)
{
  std::size_t n = 0;
  for(const auto& r : rings) n += r.size();
  return n;
}

inline void make_directory(const std::string& dir)
{
  if(mkdir(dir.c_str(), 0777) != 0 && errno != EEXIST)
    throw std::runtime_error("cannot create directory " + dir);
}

// ------------------------------------------------------------------ child processes

struct Child_result
{
  bool ok = false;          // the child ran to its end and returned a payload
  bool timed_out = false;
  std::string payload;      // what the function returned (ok), or the error message
  std::string status;       // "ok", "did not finish in T s", "error: ...", "crashed (signal N)"
  double rss_mb = 0;        // the child's peak resident set size
};

/// Runs `fn` in a forked child process and returns its result (a string sent back through a
/// pipe).  The child is killed after `timeout` seconds.  Exceptions thrown by `fn` become
/// the status "error: <what>".  The child never writes to stdout.
inline Child_result run_in_child(const std::function<std::string()>& fn, double timeout)
{
  Child_result r;
  int fd[2];
  if(pipe(fd) != 0) {
    r.status = "error: pipe failed";
    return r;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if(pid < 0) {
    close(fd[0]);
    close(fd[1]);
    r.status = "error: fork failed";
    return r;
  }
  if(pid == 0) {
    close(fd[0]);
    std::string out;
    int code = 0;
    try {
      out = "OK\n" + fn();
    } catch(const std::exception& e) {
      out = std::string("ERR\n") + e.what();
      code = 1;
    } catch(...) {
      out = "ERR\nunknown exception";
      code = 1;
    }
    const char* p = out.data();
    std::size_t left = out.size();
    while(left > 0) {
      const ssize_t k = write(fd[1], p, left);
      if(k <= 0) break;
      p += k;
      left -= std::size_t(k);
    }
    close(fd[1]);
    _exit(code);
  }
  close(fd[1]);
  const double start = now();
  std::string data;
  char buf[65536];
  for(;;) {
    const double remaining = timeout - (now() - start);
    if(remaining <= 0) {
      r.timed_out = true;
      break;
    }
    struct pollfd pfd;
    pfd.fd = fd[0];
    pfd.events = POLLIN;
    pfd.revents = 0;
    const int ms = int(std::min(remaining * 1000.0 + 1.0, 1e9));
    const int k = poll(&pfd, 1, ms);
    if(k < 0) {
      if(errno == EINTR) continue;
      break;
    }
    if(k == 0) continue; // the loop checks the time
    const ssize_t n = read(fd[0], buf, sizeof(buf));
    if(n < 0) {
      if(errno == EINTR) continue;
      break;
    }
    if(n == 0) break; // EOF: the child has closed its end (finished or died)
    data.append(buf, std::size_t(n));
  }
  close(fd[0]);
  int status = 0;
  struct rusage ru;
  std::memset(&ru, 0, sizeof(ru));
  if(r.timed_out) kill(pid, SIGKILL);
  while(wait4(pid, &status, 0, &ru) < 0 && errno == EINTR) {
  }
  r.rss_mb = double(ru.ru_maxrss) / 1024.0;
  if(r.timed_out) {
    char b[64];
    std::snprintf(b, sizeof(b), "did not finish in %g s", timeout);
    r.status = b;
    return r;
  }
  if(WIFSIGNALED(status)) {
    r.status = "crashed (signal " + std::to_string(WTERMSIG(status)) + ")";
    return r;
  }
  if(data.compare(0, 3, "OK\n") == 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    r.ok = true;
    r.status = "ok";
    r.payload = data.substr(3);
    return r;
  }
  if(data.compare(0, 4, "ERR\n") == 0) {
    r.payload = data.substr(4);
    std::string msg = r.payload;
    std::replace(msg.begin(), msg.end(), '\t', ' ');
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    r.status = "error: " + msg;
    return r;
  }
  r.status = "crashed (exit status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")";
  return r;
}

// ------------------------------------------------------------------ time limits

/// The time limits of the methods (--timeout, and --exact-timeout for the CORE::Expr
/// methods pma_exact and sdg_exact), and the methods that did not finish in time: such a
/// method is not run again on files with as many vertices or more.
struct Time_limits
{
  double timeout = 600, exact_timeout = -1; // exact_timeout < 0: the same as timeout

  double limit(const std::string& m) const
  {
    const bool exact = (m == "pma_exact" || m == "sdg_exact");
    return (exact && exact_timeout >= 0) ? exact_timeout : timeout;
  }

  /// Empty if `m` is to run on a file of `n` vertices, else the status to print.
  std::string skip(const std::string& m, std::size_t n) const
  {
    const auto it = unfinished_.find(m);
    if(it == unfinished_.end() || n < it->second) return "";
    char b[128];
    std::snprintf(b, sizeof(b), "not run: did not finish in %g s on %zu vertices", limit(m), it->second);
    return b;
  }

  void record(const std::string& m, std::size_t n, bool timed_out)
  {
    if(!timed_out) return;
    const auto it = unfinished_.find(m);
    if(it == unfinished_.end() || n < it->second) unfinished_[m] = n;
  }

private:
  std::map<std::string, std::size_t> unfinished_; // method -> fewest vertices it timed out on
};

/// False, after a message on stderr, if a method is not one of `all`.
inline bool known_methods(const std::vector<std::string>& methods, const std::vector<std::string>& all)
{
  for(const std::string& m : methods)
    if(std::find(all.begin(), all.end(), m) == all.end()) {
      std::cerr << "unknown method " << m << "\n";
      return false;
    }
  return true;
}

/// Reads a polygon file; false, after a message on stderr, if it cannot.
inline bool read_rings_or_report(const std::string& file, Rings& rings)
{
  try {
    rings = read_rings(file);
    return true;
  } catch(const std::exception& e) {
    std::cerr << file << ": " << e.what() << "\n";
    return false;
  }
}

// ------------------------------------------------------------------ the polygon

/// The input rings with the exact turn of every vertex (ring 0 outer, then holes; global
/// vertex index g, ring-local index index[g]).
struct Polygon_info
{
  std::vector<Point> pts;
  std::vector<int> next, prev, ring, index, ring_offset;
  std::vector<signed char> turn;      // +1 convex, -1 reflex, 0 flat (w.r.t. the interior)
  std::vector<char> left_interior;    // per ring: the interior is left of its edges
  double bbox_diagonal = 0;

  std::string vertex_id(int g) const { return "v" + std::to_string(ring[g]) + "." + std::to_string(index[g]); }
  std::string edge_id(int g) const { return "e" + std::to_string(ring[g]) + "." + std::to_string(index[g]); }
};

/// Turns decided with Epick's exact (filtered) orientation predicate.  Throws
/// std::invalid_argument on rings of fewer than 3 vertices, collinear rings and spikes.
inline Polygon_info polygon_info(const Rings& rings)
{
  Polygon_info P;
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  bool first = true;
  for(std::size_t r = 0; r < rings.size(); ++r) {
    const int n = int(rings[r].size());
    if(n < 3) throw std::invalid_argument("ring with fewer than 3 vertices");
    const int off = int(P.pts.size());
    P.ring_offset.push_back(off);
    for(int i = 0; i < n; ++i) {
      const Point& p = rings[r][std::size_t(i)];
      P.pts.push_back(p);
      P.ring.push_back(int(r));
      P.index.push_back(i);
      P.next.push_back(off + (i + 1) % n);
      P.prev.push_back(off + (i + n - 1) % n);
      if(first) {
        xmin = xmax = p.x();
        ymin = ymax = p.y();
        first = false;
      }
      xmin = std::min(xmin, p.x());
      xmax = std::max(xmax, p.x());
      ymin = std::min(ymin, p.y());
      ymax = std::max(ymax, p.y());
    }
  }
  P.bbox_diagonal = std::hypot(xmax - xmin, ymax - ymin);
  for(std::size_t r = 0; r < rings.size(); ++r) {
    // the lexicographically smallest vertex is strictly convex for the ring's own region
    const int off = P.ring_offset[r], n = int(rings[r].size());
    int m = off;
    for(int g = off; g < off + n; ++g)
      if(CGAL::compare_xy(P.pts[std::size_t(g)], P.pts[std::size_t(m)]) == CGAL::SMALLER) m = g;
    const CGAL::Orientation o = CGAL::orientation(P.pts[std::size_t(P.prev[m])], P.pts[std::size_t(m)],
                                                  P.pts[std::size_t(P.next[m])]);
    if(o == CGAL::COLLINEAR) throw std::invalid_argument("degenerate ring");
    const bool ccw = (o == CGAL::LEFT_TURN);
    P.left_interior.push_back(r == 0 ? ccw : !ccw);
  }
  P.turn.resize(P.pts.size());
  for(std::size_t g = 0; g < P.pts.size(); ++g) {
    const Point &a = P.pts[std::size_t(P.prev[g])], &b = P.pts[g], &c = P.pts[std::size_t(P.next[g])];
    const CGAL::Orientation o = CGAL::orientation(a, b, c);
    if(o == CGAL::COLLINEAR) {
      if(!CGAL::collinear_are_strictly_ordered_along_line(a, b, c)) throw std::invalid_argument("spike");
      P.turn[g] = 0;
    } else {
      P.turn[g] = ((o == CGAL::LEFT_TURN) == bool(P.left_interior[std::size_t(P.ring[g])])) ? 1 : -1;
    }
  }
  return P;
}

// ------------------------------------------------------------------ segment Delaunay graphs

typedef CGAL::Simple_cartesian<double> SC;
typedef CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<SC, CGAL::Field_with_sqrt_tag>
  Sdg_traits;
typedef CGAL::Segment_Delaunay_graph_2<Sdg_traits> Sdg;
typedef CGAL::Segment_Delaunay_graph_hierarchy_2<Sdg_traits> Sdg_hierarchy;

typedef CGAL::Simple_cartesian<CORE::Expr> XK;
typedef CGAL::Segment_Delaunay_graph_traits_2<XK, CGAL::Field_with_sqrt_tag> Sdg_exact_traits;
typedef CGAL::Segment_Delaunay_graph_2<Sdg_exact_traits> Sdg_exact;

/// Inserts the polygon's edges (spatially sorted points, then segments), as a user would.
template <class SDG>
void build_sdg(SDG& sdg, const Rings& rings)
{
  typedef typename SDG::Point_2 P;
  std::vector<P> points;
  std::vector<std::pair<std::size_t, std::size_t> > segments;
  for(const auto& ring : rings) {
    const std::size_t base = points.size();
    for(const Point& p : ring) points.push_back(P(p.x(), p.y()));
    for(std::size_t i = 0; i < ring.size(); ++i) segments.emplace_back(base + i, base + (i + 1) % ring.size());
  }
  sdg.insert_segments(points, segments.begin(), segments.end());
}

/// The interior medial axis of a polygon read off an already built segment Delaunay graph
/// whose sites are the polygon's edges and vertices (build_sdg).  Lean: site identification
/// by hashing the sites' double coordinates, inside/outside decided combinatorially from the
/// graph and the exact turns of the input (definitions of pma_test/sdg_oracle.h):
///
///  * a face (Voronoi vertex) whose sites are a polygon vertex p and two segments both
///    ending at p has radius 0 (BOUNDARY);
///  * otherwise, if one of its sites is a non-flat polygon vertex p, it is INSIDE iff p is
///    reflex (the segment from p to the vertex lies in the empty disk);
///  * otherwise (only segments, or segments and flat vertices) from a segment site s: the
///    faces met counter-clockwise around s's vertex from the Delaunay edge (s, target) to the
///    Delaunay edge (s, source) are the Voronoi vertices left of source->target, the others
///    those on the right; INSIDE iff on the interior side of s.  Each segment is walked
///    around at most once (only when one of its faces needs it);
///  * faces whose sites are three flat vertices take the class of a neighbour across a
///    Voronoi edge between disjoint sites.
///
/// A Voronoi edge between two finite faces is a medial curve iff both its sites are
/// generators (segments, reflex vertices), it is not the normal of a segment at its own
/// endpoint, nor the bisector of two edges at a flat vertex, and one of its ends is INSIDE.
/// Edges with an infinite face are unbounded, hence outside.
///
/// Generator codes: edge g (vertex g -> next[g]) is 2g, the reflex vertex g is 2g + 1.
template <class SDG>
class Sdg_interior
{
public:
  enum { OUTSIDE = -1, BOUNDARY = 0, INSIDE = 1, UNKNOWN = 2 };
  typedef typename SDG::Vertex_handle Vertex_handle;
  typedef typename SDG::Face_handle Face_handle;
  typedef typename SDG::Site_2 Site_2;

  struct Site
  {
    bool is_point;
    int g;        // point: the polygon vertex; segment: the polygon edge g -> next[g]
    int src, tgt; // segment: polygon vertices of the site's source and target
    bool generator;
    int code() const { return 2 * g + (is_point ? 1 : 0); }
  };

  /// A medial curve: generator codes a, b and the faces at its ends.
  struct Curve
  {
    int a, b, f0, f1;
  };

  Sdg_interior(const SDG& sdg, const Polygon_info& P) : sdg_(sdg), P_(P)
  {
    map_sites();
    collect_faces();
    classify();
  }

  const SDG& sdg() const { return sdg_; }
  std::size_t number_of_faces() const { return face_handle_.size(); }
  int face_class(int f) const { return cls_[std::size_t(f)]; }
  const Site& face_site(int f, int k) const { return sites_[std::size_t(face_site_[3 * std::size_t(f) + std::size_t(k)])]; }
  Face_handle face_handle(int f) const { return face_handle_[std::size_t(f)]; }
  const Site& site(int s) const { return sites_[std::size_t(s)]; }
  std::size_t walked_segments() const { return walked_; }
  std::size_t propagated_faces() const { return propagated_; }

  /// The Voronoi vertex of face f, constructed by the SDG's traits (construct_svd_vertex_2);
  /// for a BOUNDARY face, the polygon vertex.
  typename SDG::Point_2 vertex(int f) const
  {
    const Face_handle fh = face_handle_[std::size_t(f)];
    if(cls_[std::size_t(f)] == BOUNDARY) {
      int p = -1;
      for(int k = 0; k < 3; ++k)
        if(face_site(f, k).is_point) p = face_site(f, k).g;
      const Point& q = P_.pts[std::size_t(p)];
      return typename SDG::Point_2(q.x(), q.y());
    }
    return sdg_.geom_traits().construct_svd_vertex_2_object()(fh->vertex(0)->site(), fh->vertex(1)->site(),
                                                             fh->vertex(2)->site());
  }

  /// Calls out(Curve) for every medial curve (interior Voronoi edge), each once.
  template <class Out>
  void for_each_curve(Out out) const
  {
    for(auto e = sdg_.finite_edges_begin(); e != sdg_.finite_edges_end(); ++e) {
      const Face_handle fh = e->first;
      const int i = e->second;
      const Face_handle gh = fh->neighbor(i);
      if(sdg_.is_infinite(fh) || sdg_.is_infinite(gh)) continue;
      const int sa = site_of(fh->vertex(SDG::ccw(i))), sb = site_of(fh->vertex(SDG::cw(i)));
      const Site &A = sites_[std::size_t(sa)], &B = sites_[std::size_t(sb)];
      if(!A.generator || !B.generator) continue;
      if(A.is_point && !B.is_point && (B.src == A.g || B.tgt == A.g)) continue;
      if(B.is_point && !A.is_point && (A.src == B.g || A.tgt == B.g)) continue;
      if(!A.is_point && !B.is_point) {
        int common = -1;
        if(P_.next[std::size_t(A.g)] == B.g) common = B.g;
        else if(P_.next[std::size_t(B.g)] == A.g) common = A.g;
        if(common >= 0 && P_.turn[std::size_t(common)] == 0) continue; // flat vertex
      }
      const int f = face_index(fh), g = face_index(gh);
      if(cls_[std::size_t(f)] != INSIDE && cls_[std::size_t(g)] != INSIDE) continue;
      out(Curve{A.code(), B.code(), f, g});
    }
  }

  std::string generator_id(int code) const
  {
    return (code & 1) ? P_.vertex_id(code >> 1) : P_.edge_id(code >> 1);
  }

private:
  struct Point_hash
  {
    std::size_t operator()(const std::pair<double, double>& p) const
    {
      const std::size_t a = std::hash<double>()(p.first + 0.0), b = std::hash<double>()(p.second + 0.0);
      return a ^ (b + 0x9e3779b97f4a7c15ULL + (a << 6) + (a >> 2));
    }
  };

  int lookup(const typename SDG::Point_2& p) const
  {
    auto it = vertex_at_.find(std::make_pair(CGAL::to_double(p.x()), CGAL::to_double(p.y())));
    if(it == vertex_at_.end()) throw std::logic_error("SDG site point is not a polygon vertex");
    return it->second;
  }

  int site_of(Vertex_handle v) const { return site_of_vertex_.find(&*v)->second; }

  int face_index(Face_handle f) const { return index_of_face_.find(&*f)->second; }

  void map_sites()
  {
    vertex_at_.reserve(P_.pts.size());
    for(std::size_t g = 0; g < P_.pts.size(); ++g)
      vertex_at_.emplace(std::make_pair(P_.pts[g].x(), P_.pts[g].y()), int(g));
    point_vertex_.assign(P_.pts.size(), Vertex_handle());
    site_of_vertex_.reserve(2 * P_.pts.size());
    sites_.reserve(2 * P_.pts.size());
    vertex_of_site_.reserve(2 * P_.pts.size());
    for(auto v = sdg_.finite_vertices_begin(); v != sdg_.finite_vertices_end(); ++v) {
      const Site_2& s = v->site();
      Site info;
      if(s.is_point()) {
        info.is_point = true;
        info.g = info.src = info.tgt = lookup(s.point());
        info.generator = P_.turn[std::size_t(info.g)] < 0;
        point_vertex_[std::size_t(info.g)] = v;
      } else {
        info.is_point = false;
        info.src = lookup(s.source());
        info.tgt = lookup(s.target());
        info.g = (P_.next[std::size_t(info.src)] == info.tgt) ? info.src : info.tgt;
        info.generator = true;
      }
      site_of_vertex_.emplace(&*v, int(sites_.size()));
      sites_.push_back(info);
      vertex_of_site_.push_back(v);
    }
    walked_flag_.assign(sites_.size(), 0);
  }

  bool is_zero_radius(int f) const
  {
    int npoints = 0, p = -1;
    for(int k = 0; k < 3; ++k)
      if(face_site(f, k).is_point) {
        ++npoints;
        p = face_site(f, k).g;
      }
    if(npoints != 1) return false;
    for(int k = 0; k < 3; ++k) {
      const Site& S = face_site(f, k);
      if(!S.is_point && S.src != p && S.tgt != p) return false;
    }
    return true;
  }

  void collect_faces()
  {
    const std::size_t nf = 2 * sites_.size() + 8;
    index_of_face_.reserve(nf);
    face_handle_.reserve(nf);
    face_site_.reserve(3 * nf);
    for(auto f = sdg_.finite_faces_begin(); f != sdg_.finite_faces_end(); ++f) {
      index_of_face_.emplace(&*f, int(face_handle_.size()));
      face_handle_.push_back(f);
      for(int k = 0; k < 3; ++k) face_site_.push_back(site_of(f->vertex(k)));
    }
  }

  // classify the faces around the segment site s by their side of s
  void walk(int s)
  {
    walked_flag_[std::size_t(s)] = 1;
    ++walked_;
    const Site& S = sites_[std::size_t(s)];
    const Vertex_handle v = vertex_of_site_[std::size_t(s)];
    const Vertex_handle vsrc = point_vertex_[std::size_t(S.src)], vtgt = point_vertex_[std::size_t(S.tgt)];
    const bool left_is_interior = (bool(P_.left_interior[std::size_t(P_.ring[std::size_t(S.g)])]) == (S.src == S.g));
    typename SDG::Face_circulator fc = sdg_.incident_faces(v), done = fc;
    Face_handle start_tgt, start_src;
    do {
      const int i = fc->index(v);
      if(fc->vertex(SDG::ccw(i)) == vtgt) start_tgt = fc;
      if(fc->vertex(SDG::ccw(i)) == vsrc) start_src = fc;
    } while(++fc != done);
    if(start_tgt == Face_handle() || start_src == Face_handle())
      throw std::logic_error("segment site without Delaunay edges to its endpoints");
    bool left = true;
    Face_handle f = start_tgt;
    do {
      if(f == start_src) left = false;
      if(!sdg_.is_infinite(f)) {
        const int fi = face_index(f);
        if(cls_[std::size_t(fi)] == UNKNOWN) cls_[std::size_t(fi)] = (left == left_is_interior) ? INSIDE : OUTSIDE;
      }
      f = f->neighbor(SDG::ccw(f->index(v)));
    } while(f != start_tgt);
  }

  bool disjoint_sites(int a, int b) const
  {
    const Site &A = sites_[std::size_t(a)], &B = sites_[std::size_t(b)];
    if(A.is_point && B.is_point) return A.g != B.g;
    if(A.is_point) return B.src != A.g && B.tgt != A.g;
    if(B.is_point) return A.src != B.g && A.tgt != B.g;
    return A.src != B.src && A.src != B.tgt && A.tgt != B.src && A.tgt != B.tgt;
  }

  void classify()
  {
    const int nf = int(face_handle_.size());
    cls_.assign(std::size_t(nf), UNKNOWN);
    // radius 0, then non-flat point sites
    for(int f = 0; f < nf; ++f) {
      if(is_zero_radius(f)) {
        cls_[std::size_t(f)] = BOUNDARY;
        continue;
      }
      for(int k = 0; k < 3; ++k) {
        const Site& S = face_site(f, k);
        if(S.is_point && P_.turn[std::size_t(S.g)] != 0) {
          cls_[std::size_t(f)] = (P_.turn[std::size_t(S.g)] < 0) ? INSIDE : OUTSIDE;
          break;
        }
      }
    }
    // segment sides, walking around a segment only when one of its faces needs it
    for(int f = 0; f < nf; ++f) {
      if(cls_[std::size_t(f)] != UNKNOWN) continue;
      for(int k = 0; k < 3; ++k) {
        const int s = face_site_[3 * std::size_t(f) + std::size_t(k)];
        if(!sites_[std::size_t(s)].is_point) {
          if(!walked_flag_[std::size_t(s)]) walk(s);
          break;
        }
      }
    }
    // faces of three flat vertices: across Voronoi edges between disjoint sites
    std::deque<int> queue;
    bool any_unknown = false;
    for(int f = 0; f < nf; ++f) {
      if(cls_[std::size_t(f)] == UNKNOWN) any_unknown = true;
      else if(cls_[std::size_t(f)] != BOUNDARY) queue.push_back(f);
    }
    if(!any_unknown) return;
    while(!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      const Face_handle fh = face_handle_[std::size_t(f)];
      for(int i = 0; i < 3; ++i) {
        const Face_handle gh = fh->neighbor(i);
        if(sdg_.is_infinite(gh)) continue;
        const int g = face_index(gh);
        if(cls_[std::size_t(g)] != UNKNOWN) continue;
        if(!disjoint_sites(site_of(fh->vertex(SDG::ccw(i))), site_of(fh->vertex(SDG::cw(i))))) continue;
        cls_[std::size_t(g)] = cls_[std::size_t(f)];
        ++propagated_;
        queue.push_back(g);
      }
    }
    for(int f = 0; f < nf; ++f)
      if(cls_[std::size_t(f)] == UNKNOWN) throw std::logic_error("unclassified Voronoi vertex");
  }

  const SDG& sdg_;
  const Polygon_info& P_;
  std::unordered_map<std::pair<double, double>, int, Point_hash> vertex_at_;
  std::unordered_map<const void*, int> site_of_vertex_, index_of_face_;
  std::vector<Site> sites_;
  std::vector<Vertex_handle> point_vertex_;    // polygon vertex -> its SDG vertex
  std::vector<Vertex_handle> vertex_of_site_;  // site -> its SDG vertex
  std::vector<Face_handle> face_handle_;
  std::vector<int> face_site_;                 // 3 per face
  std::vector<signed char> cls_;
  std::vector<char> walked_flag_;
  std::size_t walked_ = 0, propagated_ = 0;
};

/// A medial curve of an extraction with its end points in double.
struct Extracted_curve
{
  int a, b;
  double x0, y0, x1, y1;
};

/// The user's extraction: every interior Voronoi edge with its two generators and its two
/// end points in double (each Voronoi vertex of positive radius constructed once, by the
/// SDG's traits; `constructions` receives their number).
template <class SDG>
std::vector<Extracted_curve> extract_interior(const Sdg_interior<SDG>& in, std::size_t* constructions = nullptr)
{
  const std::size_t nf = in.number_of_faces();
  std::vector<double> vx(nf, std::numeric_limits<double>::quiet_NaN()), vy(nf);
  std::vector<char> done(nf, 0);
  std::size_t built = 0;
  auto point = [&](int f) {
    if(!done[std::size_t(f)]) {
      const typename SDG::Point_2 p = in.vertex(f);
      vx[std::size_t(f)] = CGAL::to_double(p.x());
      vy[std::size_t(f)] = CGAL::to_double(p.y());
      done[std::size_t(f)] = 1;
      if(in.face_class(f) != Sdg_interior<SDG>::BOUNDARY) ++built;
    }
  };
  std::vector<Extracted_curve> out;
  out.reserve(nf);
  in.for_each_curve([&](const typename Sdg_interior<SDG>::Curve& c) {
    point(c.f0);
    point(c.f1);
    out.push_back(Extracted_curve{c.a, c.b, vx[std::size_t(c.f0)], vy[std::size_t(c.f0)], vx[std::size_t(c.f1)],
                                  vy[std::size_t(c.f1)]});
  });
  if(constructions) *constructions = built;
  return out;
}

// ------------------------------------------------------------------ Boost.Polygon input

/// The smallest k in 0..9 such that every coordinate x is x = r / 10^k for an integer r
/// with |r| < 2^31 (tested as: r = round(x * 10^k), and r / 10^k == x in double, i.e. the
/// decimal r * 10^-k reads back as x); the scaled integers in `scaled` (ring by ring,
/// x then y per vertex).  Returns -1 if there is no such k.
inline int decimal_scale(const Rings& rings, std::vector<std::vector<std::pair<std::int32_t, std::int32_t> > >& scaled)
{
  double p = 1;
  for(int k = 0; k <= 9; ++k, p *= 10) {
    bool ok = true;
    scaled.assign(rings.size(), {});
    auto convert = [&](double x, std::int32_t& out) {
      const double r = std::nearbyint(x * p);
      if(!(std::abs(r) <= 2147483647.0)) return false;
      if(r / p != x) return false;
      out = std::int32_t(r);
      return true;
    };
    for(std::size_t i = 0; i < rings.size() && ok; ++i)
      for(const Point& q : rings[i]) {
        std::pair<std::int32_t, std::int32_t> s;
        if(!convert(q.x(), s.first) || !convert(q.y(), s.second)) {
          ok = false;
          break;
        }
        scaled[i].push_back(s);
      }
    if(ok) return k;
  }
  scaled.clear();
  return -1;
}

} // namespace pma_bench

#endif // PMA_BENCH_COMMON_H
