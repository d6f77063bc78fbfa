// Test-only oracle: the medial axis of a polygon with holes, read off CGAL's segment
// Voronoi diagram (Segment_Delaunay_graph_2 with exact predicates), in the canonical ids
// of design/algorithm.md section 7. Used by tests and benchmarks only, never by the
// library.
//
// Conventions (algorithm.md section 7):
//  * rings: ring 0 the outer ring, ring k the k-th hole; closing point not repeated; either
//    orientation for any ring; vertex order is never changed.
//  * generators: every edge `e<r>.<i>` (vertex i -> vertex i+1 mod n of ring r) as an open
//    segment; every reflex vertex `v<r>.<i>` (interior angle > pi, decided exactly) as a
//    point. Convex and flat vertices are not generators.
//  * a medial curve is a Voronoi edge inside the polygon between two generators, named by
//    the two ids sorted with std::string operator<. Edges between a segment and its own
//    endpoint, edges involving a non-reflex vertex, and edges outside the polygon are
//    dropped. Two distinct Voronoi edges between the same generators are two curves.
//
// Inside/outside is decided combinatorially, from the SDG (whose predicates are exact:
// interval filter, then Gmpq) and from exact orientation tests on the input; nothing there
// is decided from a constructed coordinate. CORE::Expr is used only to confirm that two
// Voronoi vertices are equal, in its plain exact mode: CGAL 5.5's CORE, with its default
// progressive evaluation, was seen to return a wrong sign for an exactly-zero difference
// (a vertex of syn_sliver500), and the same expression gets the right sign without it.
//
// Inside / outside. Every finite Delaunay face (Voronoi vertex) is classified as
//  * BOUNDARY (radius 0): its three sites contain a common point, i.e. they are a polygon
//    vertex and its two edges (no other triple of sites of a simple polygon meets);
//  * otherwise from any one of its sites, all of which must agree (checked):
//    - a point site p: the empty disk D(c, r) touches p, the edges at p leave p in
//      directions d1, d2 with d_k . (c - p) <= 0, so c - p is never in the closed convex cone
//      of d1, d2, and the open segment (p, c] lies in D and meets no boundary point: c is
//      inside iff p is reflex, outside iff p is convex (flat p: no information);
//    - a segment site s: going counter-clockwise around the vertex of s in the Delaunay
//      graph, the faces from the edge (s, target) to the edge (s, source) are the Voronoi
//      vertices on the boundary of the half of s's cell to the LEFT of source->target, the
//      others those on the right (the cell of s lies in the slab of s and is cut by s; a
//      vertex of positive radius is never on the line of s inside the slab). The disk
//      touches s at its foot, so c is inside iff it is on the interior side of s.
//    Faces whose sites are all flat vertices (cocircular degenerate cases) take the class of
//    a neighbour across a Voronoi edge between two disjoint sites (such an edge stays at
//    positive distance from the boundary, so both its ends are on the same side). This
//    equality is also checked for every such edge.
//  * a kept Voronoi edge between two finite faces meets the boundary at most at an
//    endpoint of radius 0, so it is inside iff an end of positive radius is inside; both ends
//    must agree, and for two consecutive polygon edges the answer must be "inside iff their
//    common vertex is convex" (both checked; std::logic_error means an oracle bug).
//  * edges dual to a Delaunay edge with an infinite face are unbounded, hence outside.
//
// Coincident Voronoi vertices (cocircular sites) are merged: all faces of one empty circle
// are connected through Delaunay edges, and two adjacent inside faces are merged when their
// vertices are equal: their 512-bit values agree to 2^-216 relative, CORE::Expr (exact mode)
// finds them equal, and their 2048-bit values agree to 2^-984 (any disagreement among
// these, or with the SDG's is_degenerate_edge when it says "degenerate", throws). The SDG's
// is_degenerate_edge alone is not enough: it follows symbolic conventions when a segment's
// endpoint is another site of the circle (a flat vertex with its two edges, say) and then
// calls two faces with the same vertex "not degenerate". A curve between merged faces has
// length 0.
//
// Numbers. Coordinates and radii of inside vertices come from CGAL's Voronoi vertex
// construction (Segment_Delaunay_graph_traits over Simple_cartesian<Gmpfr>, Field_with_sqrt)
// evaluated with 512-bit MPFR, rounded to the nearest double. The branches the construction
// takes are on polynomials of the double inputs (computed exactly at 512 bits), on signs it
// asserts non-zero, or on signs whose zero case does not matter (sigma/rho in its
// point-line-line case multiply a square root that is then zero), so the result is the
// exact vertex to ~2^-250 relative or better (the square root of an exact zero, rounded, is
// ~2^-256; typically ~2^-500), and rounding it gives the correctly rounded double unless the
// exact value is that close to a rounding boundary. A value within 2^-(bits/2 - 40) of the
// coordinates' scale of 0 or of the midpoint of two doubles is taken to be exactly there
// (the ties of symmetric and decimal input) and rounded to 0 or to even: the correctly
// rounded double (ties to even) of every vertex but one that close to a rounding boundary
// without being on it. Each such vertex is verified (equal
// distances to its three closed sites, and the side of every segment site agreeing with the
// combinatorial side); a failure is retried at 2048 bits and then throws std::logic_error.
// Lengths: straight for segment/segment and point/point pairs, closed-form parabolic arc
// length for point/segment pairs, from the rounded vertices.
//
// Global state: while it runs, the oracle changes MPFR's default precision and CORE's
// evaluation flags, restoring them afterwards; do not run it concurrently with other code
// that uses CORE::Expr or Gmpfr.
//
// Preconditions (not checked, except as noted): the rings form a valid polygon with holes
// (rings pairwise disjoint except at shared vertices, holes inside the outer ring, not
// nested). Rings may touch themselves and each other at vertices (OGC touching holes,
// pinches, inverted islands): the SDG then has one point site there, named after the first
// vertex at that place in input order, a generator if one of the interior sectors there
// is reflex; such a point does not vote inside/outside (its faces are classified by their
// segments), and the checks on the corner bisectors skip it.  A vertex may lie inside an
// edge (a T): the oracle splits the edge there (both halves named after the edge), and the
// place is then one where rings touch at vertices. Checked: at least 3 vertices
// per ring, no spike, no crossing at a shared vertex; violations throw
// std::invalid_argument. Coordinates are converted with CGAL::to_double (inputs whose
// coordinates are not doubles are rounded).

#ifndef PMA_TEST_SDG_ORACLE_H
#define PMA_TEST_SDG_ORACLE_H

#include <CGAL/CORE_Expr.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Segment_Delaunay_graph_traits_2.h>
#include <CGAL/Simple_cartesian.h>

#include <mpfr.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <deque>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pma_test {

/// One medial curve: generators a < b (std::string order) and its length.
struct Oracle_curve
{
  std::string a, b;
  double length;
};

/// One branch point: the sorted ids of its (>= 3) generators, centre and radius.
struct Oracle_branch
{
  std::vector<std::string> generators;
  double x, y, r;
};

struct Oracle_result
{
  std::vector<Oracle_curve> curves;
  std::vector<Oracle_branch> branches;
  double bbox_diagonal;
};

/// A vertex of the oracle's medial axis graph: one exact point, i.e. a class of inside SDG
/// faces with the same Voronoi vertex (positive radius), or one radius-0 vertex (a polygon
/// vertex with its two edges: the end of a corner bisector, or a reflex corner).
struct Oracle_node
{
  double x, y, r;
  bool zero_radius;
  std::vector<std::string> sites; // sorted ids of all SDG sites of the class (points of
                                  // non-reflex vertices are named v<r>.<i> too)
  bool all_generators;            // no site is a convex or flat vertex
};

/// A medial curve with its end nodes (indices into Oracle_graph::nodes).
struct Oracle_edge
{
  std::string a, b;
  double length;
  int node0, node1;
};

struct Oracle_stats
{
  std::size_t sdg_vertices = 0, sdg_faces = 0, inside_faces = 0, constructions = 0,
              coincidence_candidates = 0, exact_coincidence_tests = 0, coincident_pairs = 0,
              propagated_faces = 0;
  double seconds_sdg = 0, seconds_classify = 0, seconds_total = 0;
};

struct Oracle_graph
{
  std::vector<Oracle_node> nodes;
  std::vector<Oracle_edge> edges;
  double bbox_diagonal = 0;
  Oracle_stats stats;
};

struct Oracle_options
{
  /// Also construct the Voronoi vertex of every OUTSIDE face and verify it like the inside
  /// ones (equidistance, side of every segment site). For the oracle's self-test.
  bool cross_check = false;
};

namespace oracle_detail {

typedef CGAL::Exact_predicates_inexact_constructions_kernel EK;
typedef EK::Point_2 EPoint;

typedef CGAL::Simple_cartesian<double> DK;
typedef CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<
  DK, CGAL::Field_with_sqrt_tag> Gt;
typedef CGAL::Segment_Delaunay_graph_2<Gt> SDG;

typedef CGAL::Gmpfr MT;
typedef CGAL::Simple_cartesian<MT> MK;
typedef MK::Point_2 MPoint;
typedef CGAL::Segment_Delaunay_graph_traits_without_intersections_2<
  MK, CGAL::Field_with_sqrt_tag> MGt;
typedef MGt::Site_2 MSite;

typedef CORE::Expr XT;
typedef CGAL::Simple_cartesian<XT> XK;
typedef XK::Point_2 XPoint;
typedef CGAL::Segment_Delaunay_graph_traits_without_intersections_2<
  XK, CGAL::Field_with_sqrt_tag> XGt;
typedef XGt::Site_2 XSite;

enum Face_class { OUTSIDE = -1, BOUNDARY = 0, INSIDE = 1, UNKNOWN = 2 };

/// Sets MPFR's default precision (used by every Gmpfr operation) and restores it.
class Mpfr_precision_guard
{
public:
  explicit Mpfr_precision_guard(long bits)
    : old_(MT::set_default_precision(static_cast<MT::Precision_type>(bits)))
  {}
  ~Mpfr_precision_guard() { MT::set_default_precision(old_); }
  Mpfr_precision_guard(const Mpfr_precision_guard&) = delete;
  Mpfr_precision_guard& operator=(const Mpfr_precision_guard&) = delete;

private:
  MT::Precision_type old_;
};

/// Puts CORE in its plain exact mode (no floating-point filter, no progressive
/// evaluation: CGAL 5.5's CORE was seen to return a wrong sign with progressive evaluation)
/// and restores the previous mode.
class Core_exact_mode_guard
{
public:
  Core_exact_mode_guard()
    : filter_(CORE::setFpFilterFlag(false)), progressive_(CORE::setProgressiveEvalFlag(false))
  {}
  ~Core_exact_mode_guard()
  {
    CORE::setFpFilterFlag(filter_);
    CORE::setProgressiveEvalFlag(progressive_);
  }
  Core_exact_mode_guard(const Core_exact_mode_guard&) = delete;
  Core_exact_mode_guard& operator=(const Core_exact_mode_guard&) = delete;

private:
  bool filter_, progressive_;
};

inline double nearest_double(const MT& v) { return mpfr_get_d(v.fr(), MPFR_RNDN); }

/// The double nearest to the exact value that v approximates to within tol, ties to even.
/// A v within tol of 0, or of the midpoint of two doubles, is taken to be exactly that: the
/// exact zeros and midpoints of symmetric and decimal input (a point halfway between two
/// input points), which the approximation alone would round to either side.
inline double nearest_double(const MT& v, double tol)
{
  if(CGAL::compare(CGAL::abs(v), MT(tol)) <= 0) return 0;
  const double d = nearest_double(v);
  const CGAL::Comparison_result side = CGAL::compare(v, MT(d));
  if(side == CGAL::EQUAL || !std::isfinite(d)) return d;
  const double neighbour = std::nextafter(d, side == CGAL::LARGER ? HUGE_VAL : -HUGE_VAL);
  const MT midpoint = (MT(d) + MT(neighbour)) / MT(2);   // exact: 54 bits
  if(CGAL::compare(CGAL::abs(v - midpoint), MT(tol)) > 0) return d;
  std::int64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  return (bits & 1) == 0 ? d : neighbour;
}

/// The polygon, converted to doubles, with the exact turn of every vertex.
struct Polygon_data
{
  std::vector<EPoint> pts;
  std::vector<int> ring, index, next, prev;
  std::vector<int> turn;            // +1 convex, -1 reflex, 0 flat (w.r.t. the interior)
  // Where rings touch (several vertices at one place): rep[g] is the first vertex at g's
  // place (input order), touching[g] whether there are several, and place_turn[g] the
  // turn of the place: -1 if one of its interior sectors is reflex (the point is then a
  // generator, named after rep), +1 otherwise.  Elsewhere rep[g] == g and
  // place_turn[g] == turn[g].
  std::vector<int> rep, place_turn;
  std::vector<char> touching;
  std::vector<int> ring_offset;     // first global index of each ring
  std::vector<char> left_interior;  // per ring: polygon interior on the left of its edges
  double bbox_diagonal = 0;
  double max_abs_coordinate = 0;

  std::string vertex_id(int g) const
  {
    return "v" + std::to_string(ring[g]) + "." + std::to_string(index[g]);
  }
  // Where a vertex lies inside an edge (a T), the edge is split there: the
  // new vertex comes after the input vertices, edge_of[g] is the input edge
  // (its first vertex) that the edge from g is part of, and names it.
  std::vector<int> edge_of;
  std::string edge_id(int g) const
  {
    const int e = edge_of[g];
    return "e" + std::to_string(ring[e]) + "." + std::to_string(index[e]);
  }
};

template <class Point_2>
Polygon_data make_polygon_data(const std::vector<std::vector<Point_2> >& rings)
{
  Polygon_data P;
  if(rings.empty())
    throw std::invalid_argument("sdg_oracle: no rings");
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  bool first = true;
  for(std::size_t r = 0; r < rings.size(); ++r) {
    const std::size_t n = rings[r].size();
    if(n < 3)
      throw std::invalid_argument("sdg_oracle: ring " + std::to_string(r) +
                                  " has fewer than 3 vertices");
    const int off = static_cast<int>(P.pts.size());
    P.ring_offset.push_back(off);
    for(std::size_t i = 0; i < n; ++i) {
      const double x = CGAL::to_double(rings[r][i].x());
      const double y = CGAL::to_double(rings[r][i].y());
      if(!std::isfinite(x) || !std::isfinite(y))
        throw std::invalid_argument("sdg_oracle: non-finite coordinate");
      P.pts.push_back(EPoint(x, y));
      P.ring.push_back(static_cast<int>(r));
      P.index.push_back(static_cast<int>(i));
      P.next.push_back(off + static_cast<int>((i + 1) % n));
      P.prev.push_back(off + static_cast<int>((i + n - 1) % n));
      if(first) { xmin = xmax = x; ymin = ymax = y; first = false; }
      xmin = (std::min)(xmin, x); xmax = (std::max)(xmax, x);
      ymin = (std::min)(ymin, y); ymax = (std::max)(ymax, y);
    }
  }
  P.bbox_diagonal = std::hypot(xmax - xmin, ymax - ymin);
  P.max_abs_coordinate = (std::max)((std::max)(std::abs(xmin), std::abs(xmax)),
                                    (std::max)(std::abs(ymin), std::abs(ymax)));

  // Orientation of each ring, exactly, from the sign of its area (a ring may touch
  // itself, at its smallest vertex too).
  for(std::size_t r = 0; r < rings.size(); ++r) {
    const int off = P.ring_offset[r];
    const int n = static_cast<int>(rings[r].size());
    CGAL::Gmpq twice_area = 0;
    for(int g = off; g < off + n; ++g) {
      const EPoint& a = P.pts[g];
      const EPoint& b = P.pts[P.next[g]];
      twice_area += CGAL::Gmpq(a.x()) * CGAL::Gmpq(b.y()) - CGAL::Gmpq(a.y()) * CGAL::Gmpq(b.x());
    }
    if(CGAL::sign(twice_area) == CGAL::ZERO)
      throw std::invalid_argument("sdg_oracle: ring " + std::to_string(r) +
                                  " is degenerate (no orientation)");
    const bool ccw = CGAL::sign(twice_area) == CGAL::POSITIVE;
    P.left_interior.push_back(r == 0 ? ccw : !ccw);
  }

  // Turns, exact.
  P.turn.resize(P.pts.size());
  for(std::size_t g = 0; g < P.pts.size(); ++g) {
    const EPoint& a = P.pts[P.prev[g]];
    const EPoint& b = P.pts[g];
    const EPoint& c = P.pts[P.next[g]];
    const CGAL::Orientation o = CGAL::orientation(a, b, c);
    if(o == CGAL::COLLINEAR) {
      if(!CGAL::collinear_are_strictly_ordered_along_line(a, b, c))
        throw std::invalid_argument("sdg_oracle: spike or repeated point at vertex " +
                                    std::to_string(P.index[g]) + " of ring " +
                                    std::to_string(P.ring[g]));
      P.turn[g] = 0;
    } else {
      const bool left = (o == CGAL::LEFT_TURN);
      P.turn[g] = (left == static_cast<bool>(P.left_interior[P.ring[g]])) ? 1 : -1;
    }
  }

  // T's: a vertex inside an edge.  Candidates by x (fine for test shapes and
  // real outlines; quadratic only where many vertices share an x).
  P.edge_of.resize(P.pts.size());
  std::iota(P.edge_of.begin(), P.edge_of.end(), 0);
  {
    const int n = int(P.pts.size());
    std::vector<int> by_x(n);
    std::iota(by_x.begin(), by_x.end(), 0);
    std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return P.pts[a].x() < P.pts[b].x(); });
    for(int g = 0; g < n; ++g) {
      const EPoint a = P.pts[g], b = P.pts[P.next[g]];
      const double lo = (std::min)(a.x(), b.x()), hi = (std::max)(a.x(), b.x());
      auto it = std::lower_bound(by_x.begin(), by_x.end(), lo, [&](int v, double x) { return P.pts[v].x() < x; });
      std::vector<int> inside;
      for(; it != by_x.end() && P.pts[*it].x() <= hi; ++it)
        if(CGAL::orientation(a, b, P.pts[*it]) == CGAL::COLLINEAR &&
           CGAL::collinear_are_strictly_ordered_along_line(a, P.pts[*it], b))
          inside.push_back(*it);
      if(inside.empty()) continue;
      std::sort(inside.begin(), inside.end(), [&](int u, int v) {
        return CGAL::collinear_are_strictly_ordered_along_line(a, P.pts[u], P.pts[v]);
      });
      inside.erase(std::unique(inside.begin(), inside.end(), [&](int u, int v) { return P.pts[u] == P.pts[v]; }),
                   inside.end());
      int last = g;
      const int after = P.next[g];
      for(int v : inside) {
        const int s = int(P.pts.size());
        P.pts.push_back(P.pts[v]);
        P.ring.push_back(P.ring[g]);
        P.index.push_back(-1);
        P.edge_of.push_back(g);
        P.turn.push_back(0);
        P.next.push_back(after);
        P.prev.push_back(last);
        P.next[last] = s;
        P.prev[after] = s;
        last = s;
      }
    }
  }

  // Places where rings touch: the edges there, sorted by angle, bound interior and
  // exterior sectors alternately (the polygon is valid); the interior sector after an
  // edge (counterclockwise) is reflex if the next edge turns right from it.
  std::map<std::pair<double, double>, std::vector<int> > at;
  for(std::size_t g = 0; g < P.pts.size(); ++g) at[std::make_pair(P.pts[g].x(), P.pts[g].y())].push_back(int(g));
  P.rep.resize(P.pts.size());
  P.touching.assign(P.pts.size(), 0);
  P.place_turn = P.turn;
  for(const auto& kv : at) {
    const std::vector<int>& gs = kv.second;   // increasing
    for(int g : gs) P.rep[g] = gs.front();
    if(gs.size() < 2) continue;
    const EPoint& p = P.pts[gs.front()];
    struct Ray { int to; bool interior_after; };
    std::vector<Ray> rays;
    for(int g : gs) {
      const bool left = P.left_interior[P.ring[g]];
      rays.push_back(Ray{P.next[g], left});    // along the ring: interior on the left if left
      rays.push_back(Ray{P.prev[g], !left});   // against it
    }
    auto upper = [&](const EPoint& q) {
      return q.y() > p.y() || (q.y() == p.y() && q.x() > p.x());
    };
    std::sort(rays.begin(), rays.end(), [&](const Ray& a, const Ray& b) {
      const bool ua = upper(P.pts[a.to]), ub = upper(P.pts[b.to]);
      if(ua != ub) return ua;
      return CGAL::orientation(p, P.pts[a.to], P.pts[b.to]) == CGAL::LEFT_TURN;
    });
    int turn = 1;
    for(std::size_t i = 0; i < rays.size(); ++i) {
      const Ray& a = rays[i];
      const Ray& b = rays[(i + 1) % rays.size()];
      if(a.interior_after == b.interior_after)
        throw std::invalid_argument("sdg_oracle: rings cross at a shared vertex");
      if(a.interior_after && CGAL::orientation(p, P.pts[a.to], P.pts[b.to]) == CGAL::RIGHT_TURN) turn = -1;
    }
    for(int g : gs) {
      P.touching[g] = 1;
      P.place_turn[g] = turn;
    }
  }
  return P;
}

struct Site_info
{
  bool is_point;
  int g;            // point: the polygon vertex; segment: the edge g -> next[g]
  int src, tgt;     // segment: polygon vertices of the SDG site's source and target
  bool generator;
  std::string id;
};

struct Face_info
{
  int site[3];
  int side[3] = {0, 0, 0};  // segment sites: +1 if the Voronoi vertex is on the interior
                            // side of the segment, -1 if on the exterior side
  bool zero_radius = false;
  int cls = UNKNOWN;
  double cx = 0, cy = 0, r = 0; // vertex and radius rounded to nearest (non-OUTSIDE faces)
};

class Oracle_builder
{
public:
  Oracle_builder(const Polygon_data& P, const Oracle_options& opt) : P(P), opt(opt) {}

  Oracle_graph run()
  {
    typedef std::chrono::steady_clock Clock;
    const Clock::time_point t0 = Clock::now();
    build_sdg();
    const Clock::time_point t1 = Clock::now();
    map_sites();
    collect_faces();
    compute_segment_sides();
    classify_faces();
    check_classes_across_edges();
    compute_coordinates();
    merge_coincident_faces();
    Oracle_graph G = make_graph();
    const Clock::time_point t2 = Clock::now();
    G.stats = stats;
    G.stats.seconds_sdg = std::chrono::duration<double>(t1 - t0).count();
    G.stats.seconds_classify = std::chrono::duration<double>(t2 - t1).count();
    G.stats.seconds_total = std::chrono::duration<double>(t2 - t0).count();
    return G;
  }

  /// Arc length of the parabola with focus (px,py) and directrix the line through
  /// (ax,ay),(bx,by), between the points of the parabola over the projections of (x1,y1)
  /// and (x2,y2) on the directrix.
  static double parabola_arc_length(double px, double py, double ax, double ay, double bx,
                                    double by, double x1, double y1, double x2, double y2)
  {
    const double dx = bx - ax, dy = by - ay;
    const double l = std::hypot(dx, dy);
    const double ux = dx / l, uy = dy / l;
    const double f = std::abs(ux * (py - ay) - uy * (px - ax)); // focus to directrix
    const double t1 = (x1 - px) * ux + (y1 - py) * uy;
    const double t2 = (x2 - px) * ux + (y2 - py) * uy;
    if(!(f > 0)) return std::hypot(x2 - x1, y2 - y1);
    // the parabola is y = (t^2 + f^2) / (2 f), so ds = sqrt(f^2 + t^2) / f dt
    auto F = [f](double t) {
      const double s = std::hypot(t, f);
      return 0.5 * (t * (s / f) + f * std::asinh(t / f));
    };
    return std::abs(F(t2) - F(t1));
  }

private:
  const Polygon_data& P;
  Oracle_options opt;
  SDG sdg;
  Oracle_stats stats;
  std::vector<Site_info> sites;
  std::unordered_map<const void*, int> site_of_vertex;
  std::vector<SDG::Vertex_handle> point_vertex; // polygon vertex -> its SDG vertex
  std::vector<Face_info> faces;
  std::vector<SDG::Face_handle> face_handle;
  std::unordered_map<const void*, int> index_of_face;
  std::vector<int> uf_parent;

  // ---------------------------------------------------------------- SDG
  void build_sdg()
  {
    std::vector<Gt::Point_2> points;
    points.reserve(P.pts.size());
    for(const EPoint& p : P.pts) points.push_back(Gt::Point_2(p.x(), p.y()));
    std::vector<std::pair<std::size_t, std::size_t> > segs;
    segs.reserve(P.pts.size());
    for(std::size_t g = 0; g < P.pts.size(); ++g)
      segs.push_back(std::make_pair(g, static_cast<std::size_t>(P.next[g])));
    sdg.insert_segments(points, segs.begin(), segs.end());
    stats.sdg_vertices = sdg.number_of_vertices();
    std::size_t places = 0;
    for(std::size_t g = 0; g < P.pts.size(); ++g) places += (P.rep[g] == int(g));
    if(sdg.number_of_vertices() != places + P.pts.size())
      throw std::invalid_argument(
        "sdg_oracle: the segment Delaunay graph has " +
        std::to_string(sdg.number_of_vertices()) + " sites instead of " +
        std::to_string(places + P.pts.size()) + " (overlapping edges?)");
    if(sdg.dimension() != 2)
      throw std::invalid_argument("sdg_oracle: degenerate input (SDG dimension < 2)");
  }

  // ---------------------------------------------------------------- sites
  void map_sites()
  {
    std::map<std::pair<double, double>, int> vertex_at;   // the first vertex at each place
    for(std::size_t g = 0; g < P.pts.size(); ++g)
      vertex_at.emplace(std::make_pair(P.pts[g].x(), P.pts[g].y()), P.rep[g]);
    std::map<std::pair<int, int>, int> edge_between;     // places of the ends -> the edge
    for(std::size_t g = 0; g < P.pts.size(); ++g) {
      edge_between[std::make_pair(P.rep[g], P.rep[P.next[g]])] = static_cast<int>(g);
      edge_between[std::make_pair(P.rep[P.next[g]], P.rep[g])] = static_cast<int>(g);
    }
    auto lookup = [&](const Gt::Point_2& p) {
      auto it = vertex_at.find(std::make_pair(p.x(), p.y()));
      if(it == vertex_at.end())
        throw std::logic_error("sdg_oracle: SDG site point is not a polygon vertex");
      return it->second;
    };
    point_vertex.assign(P.pts.size(), SDG::Vertex_handle());
    std::vector<char> seen_edge(P.pts.size(), 0);
    for(SDG::Finite_vertices_iterator v = sdg.finite_vertices_begin();
        v != sdg.finite_vertices_end(); ++v) {
      const SDG::Site_2 s = v->site();
      Site_info info;
      if(!s.is_input())
        throw std::logic_error("sdg_oracle: non-input site");
      if(s.is_point()) {
        info.is_point = true;
        info.g = lookup(s.point());
        info.src = info.tgt = info.g;
        info.generator = P.place_turn[info.g] < 0;
        info.id = P.vertex_id(info.g);
        if(point_vertex[info.g] != SDG::Vertex_handle())
          throw std::logic_error("sdg_oracle: point site twice");
        point_vertex[info.g] = v;
      } else {
        info.is_point = false;
        info.src = lookup(s.source());
        info.tgt = lookup(s.target());
        const auto e = edge_between.find(std::make_pair(info.src, info.tgt));
        if(e == edge_between.end()) throw std::logic_error("sdg_oracle: segment site is not a polygon edge");
        info.g = e->second;
        info.generator = true;
        info.id = P.edge_id(info.g);
        if(seen_edge[info.g]++) throw std::logic_error("sdg_oracle: segment site twice");
      }
      site_of_vertex[&*v] = static_cast<int>(sites.size());
      sites.push_back(info);
    }
  }

  int site_of(SDG::Vertex_handle v) const { return site_of_vertex.at(&*v); }

  int face_index(SDG::Face_handle f) const
  {
    if(sdg.is_infinite(f)) return -1;
    return index_of_face.at(&*f);
  }

  bool is_zero_radius(const Face_info& F) const
  {
    int npoints = 0, p = -1;
    for(int k = 0; k < 3; ++k)
      if(sites[F.site[k]].is_point) { ++npoints; p = sites[F.site[k]].g; }
    if(npoints != 1) return false;
    for(int k = 0; k < 3; ++k) {
      const Site_info& S = sites[F.site[k]];
      if(!S.is_point && S.src != p && S.tgt != p) return false;
    }
    return true;
  }

  int common_point(const Face_info& F) const
  {
    for(int k = 0; k < 3; ++k) if(sites[F.site[k]].is_point) return sites[F.site[k]].g;
    return -1;
  }

  void collect_faces()
  {
    for(SDG::Finite_faces_iterator f = sdg.finite_faces_begin(); f != sdg.finite_faces_end();
        ++f) {
      Face_info F;
      for(int k = 0; k < 3; ++k) F.site[k] = site_of(f->vertex(k));
      F.zero_radius = is_zero_radius(F);
      index_of_face[&*f] = static_cast<int>(faces.size());
      faces.push_back(F);
      face_handle.push_back(f);
    }
    stats.sdg_faces = faces.size();
  }

  // ---------------------------------------------------------------- combinatorial sides
  // For every segment site s, walk counter-clockwise around its vertex from the edge
  // (s, target) to the edge (s, source): these faces are left of source->target.
  void compute_segment_sides()
  {
    for(SDG::Finite_vertices_iterator v = sdg.finite_vertices_begin();
        v != sdg.finite_vertices_end(); ++v) {
      const int s = site_of(v);
      const Site_info& S = sites[s];
      if(S.is_point) continue;
      const SDG::Vertex_handle vsrc = point_vertex[S.src], vtgt = point_vertex[S.tgt];
      // interior side: left of the polygon direction g -> next[g] iff left_interior
      const bool polygon_dir = (S.src == P.rep[S.g]);
      const bool left_is_interior = (static_cast<bool>(P.left_interior[P.ring[S.g]]) == polygon_dir);

      SDG::Face_handle start_tgt, start_src;
      int n_tgt = 0, n_src = 0;
      SDG::Face_circulator fc = sdg.incident_faces(v), done = fc;
      do {
        const int i = fc->index(v);
        if(fc->vertex(SDG::ccw(i)) == vtgt) { start_tgt = fc; ++n_tgt; }
        if(fc->vertex(SDG::ccw(i)) == vsrc) { start_src = fc; ++n_src; }
      } while(++fc != done);
      if(n_tgt != 1 || n_src != 1)
        throw std::logic_error("sdg_oracle: segment " + S.id + " has " + std::to_string(n_tgt) +
                               "/" + std::to_string(n_src) + " Delaunay edges to its endpoints");

      bool left = true;
      SDG::Face_handle f = start_tgt;
      std::size_t guard = 0;
      do {
        if(f == start_src) left = false;
        if(!sdg.is_infinite(f)) {
          Face_info& F = faces[face_index(f)];
          for(int k = 0; k < 3; ++k)
            if(F.site[k] == s) F.side[k] = (left == left_is_interior) ? 1 : -1;
        }
        const int i = f->index(v);
        f = f->neighbor(SDG::ccw(i));
        if(++guard > 4 * faces.size() + 16)
          throw std::logic_error("sdg_oracle: face walk around " + S.id + " does not close");
      } while(f != start_tgt);
    }
  }

  // ---------------------------------------------------------------- classification
  void classify_faces()
  {
    for(std::size_t fi = 0; fi < faces.size(); ++fi) {
      Face_info& F = faces[fi];
      if(F.zero_radius) {
        F.cls = BOUNDARY;
        const EPoint& p = P.pts[common_point(F)];
        F.cx = p.x();
        F.cy = p.y();
        F.r = 0;
        continue;
      }
      int cls = UNKNOWN;
      for(int k = 0; k < 3; ++k) {
        const Site_info& S = sites[F.site[k]];
        int ck = UNKNOWN;
        if(S.is_point) {
          // (where rings touch, a point has interior and exterior sectors: no vote)
          if(P.turn[S.g] != 0 && !P.touching[S.g]) ck = (P.turn[S.g] < 0) ? INSIDE : OUTSIDE;
        } else {
          if(F.side[k] == 0)
            throw std::logic_error("sdg_oracle: face without a side for segment " + S.id);
          ck = (F.side[k] > 0) ? INSIDE : OUTSIDE;
        }
        if(ck == UNKNOWN) continue;
        if(cls == UNKNOWN) cls = ck;
        else if(cls != ck)
          throw std::logic_error("sdg_oracle: the sites " + sites[F.site[0]].id + " " +
                                 sites[F.site[1]].id + " " + sites[F.site[2]].id +
                                 " of one Voronoi vertex disagree on inside/outside");
      }
      F.cls = cls;
    }

    // propagate across Voronoi edges between disjoint sites (only all-flat-point faces)
    std::deque<int> queue;
    for(std::size_t fi = 0; fi < faces.size(); ++fi)
      if(faces[fi].cls == INSIDE || faces[fi].cls == OUTSIDE) queue.push_back(static_cast<int>(fi));
    while(!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      const SDG::Face_handle fh = face_handle[f];
      for(int i = 0; i < 3; ++i) {
        const int g = face_index(fh->neighbor(i));
        if(g < 0 || faces[g].cls != UNKNOWN) continue;
        if(!disjoint_sites(site_of(fh->vertex(SDG::ccw(i))), site_of(fh->vertex(SDG::cw(i)))))
          continue;
        faces[g].cls = faces[f].cls;
        ++stats.propagated_faces;
        queue.push_back(g);
      }
    }
    for(const Face_info& F : faces)
      if(F.cls == UNKNOWN) throw std::logic_error("sdg_oracle: unclassified Voronoi vertex");
  }

  // two sites whose closures do not meet
  bool disjoint_sites(int a, int b) const
  {
    const Site_info& A = sites[a];
    const Site_info& B = sites[b];
    if(A.is_point && B.is_point) return A.g != B.g;
    if(A.is_point) return B.src != A.g && B.tgt != A.g;
    if(B.is_point) return A.src != B.g && A.tgt != B.g;
    return A.src != B.src && A.src != B.tgt && A.tgt != B.src && A.tgt != B.tgt;
  }

  void check_classes_across_edges() const
  {
    for(SDG::Finite_edges_iterator e = sdg.finite_edges_begin(); e != sdg.finite_edges_end();
        ++e) {
      const int f = face_index(e->first);
      const int g = face_index(e->first->neighbor(e->second));
      if(f < 0 || g < 0) continue;
      if(faces[f].cls == BOUNDARY || faces[g].cls == BOUNDARY) continue;
      const int sa = site_of(e->first->vertex(SDG::ccw(e->second)));
      const int sb = site_of(e->first->vertex(SDG::cw(e->second)));
      if(disjoint_sites(sa, sb) && faces[f].cls != faces[g].cls)
        throw std::logic_error("sdg_oracle: Voronoi edge " + sites[sa].id + "/" + sites[sb].id +
                               " between disjoint sites has one end inside, one outside");
    }
  }

  // ---------------------------------------------------------------- numbers
  MPoint mpoint(int g) const { return MPoint(MT(P.pts[g].x()), MT(P.pts[g].y())); }

  MSite msite(int s) const
  {
    const Site_info& S = sites[s];
    if(S.is_point) return MSite::construct_site_2(mpoint(S.g));
    return MSite::construct_site_2(mpoint(S.src), mpoint(S.tgt));
  }

  // squared distance from c to the closed site s
  MT squared_distance_to_site(int s, const MPoint& c) const
  {
    const Site_info& S = sites[s];
    if(S.is_point) {
      const MPoint p = mpoint(S.g);
      return CGAL::square(c.x() - p.x()) + CGAL::square(c.y() - p.y());
    }
    const MPoint a = mpoint(S.src), b = mpoint(S.tgt);
    const MT dx = b.x() - a.x(), dy = b.y() - a.y();
    const MT t = (c.x() - a.x()) * dx + (c.y() - a.y()) * dy;
    const MT l2 = dx * dx + dy * dy;
    if(CGAL::sign(t) <= 0) return CGAL::square(c.x() - a.x()) + CGAL::square(c.y() - a.y());
    if(CGAL::compare(t, l2) >= 0) return CGAL::square(c.x() - b.x()) + CGAL::square(c.y() - b.y());
    const MT cr = dx * (c.y() - a.y()) - dy * (c.x() - a.x());
    return cr * cr / l2;
  }

  // the Voronoi vertex of face f by CGAL's construction, in MPFR at the current default
  // precision
  MPoint mvertex(int f)
  {
    const Face_info& F = faces[f];
    MGt gt;
    ++stats.constructions;
    return gt.construct_svd_vertex_2_object()(msite(F.site[0]), msite(F.site[1]), msite(F.site[2]));
  }

  XPoint xpoint(int g) const { return XPoint(XT(P.pts[g].x()), XT(P.pts[g].y())); }

  XSite xsite(int s) const
  {
    const Site_info& S = sites[s];
    if(S.is_point) return XSite::construct_site_2(xpoint(S.g));
    return XSite::construct_site_2(xpoint(S.src), xpoint(S.tgt));
  }

  // the Voronoi vertex of face f by CGAL's construction, in CORE::Expr
  XPoint xvertex(int f) const
  {
    const Face_info& F = faces[f];
    XGt gt;
    return gt.construct_svd_vertex_2_object()(xsite(F.site[0]), xsite(F.site[1]), xsite(F.site[2]));
  }

  double scale_of(int f) const
  {
    return (std::max)({P.max_abs_coordinate, std::abs(faces[f].cx), std::abs(faces[f].cy), 1e-300});
  }

  // construct and verify the Voronoi vertex of face f; returns false if verification fails
  bool construct(int f, long bits, double& cx, double& cy, double& r, std::string& why)
  {
    Mpfr_precision_guard guard(bits);
    const Face_info& F = faces[f];
    const MPoint c = mvertex(f);
    // verification: equal distances to the three closed sites...
    MT d2[3];
    for(int k = 0; k < 3; ++k) d2[k] = squared_distance_to_site(F.site[k], c);
    const double scale = (std::max)({P.max_abs_coordinate, std::abs(nearest_double(c.x())),
                                     std::abs(nearest_double(c.y())), 1e-300});
    // |d_k^2 - d_0^2| <= 2^-(bits/2 - 40) * scale^2: a square root of an exactly-zero
    // quantity (rounded to ~2^-bits) is off by ~2^-(bits/2); a wrong root by far more
    const MT tol = MT(std::ldexp(scale * scale, -static_cast<int>(bits / 2 - 40)));
    for(int k = 1; k < 3; ++k)
      if(CGAL::compare(CGAL::abs(d2[k] - d2[0]), tol) > 0) {
        why = "distances to the sites differ";
        return false;
      }
    if(CGAL::sign(d2[0]) <= 0) { why = "radius 0"; return false; }
    // ...and on the combinatorial side of each segment site (when numerically clear)
    for(int k = 0; k < 3; ++k) {
      const Site_info& S = sites[F.site[k]];
      if(S.is_point) continue;
      const MPoint a = mpoint(S.g), b = mpoint(P.next[S.g]);
      const MT cr = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
      const bool left = CGAL::sign(cr) > 0;
      const bool interior = (left == static_cast<bool>(P.left_interior[P.ring[S.g]]));
      const MT margin = MT(std::ldexp(scale * scale, -static_cast<int>(bits / 2 - 40)));
      if(CGAL::compare(CGAL::abs(cr), margin) > 0 && interior != (F.side[k] > 0)) {
        why = "on the wrong side of " + S.id;
        return false;
      }
    }
    // rounded as exactly as the construction allows: a square root of an exact zero is off by
    // ~2^-(bits/2) of the scale, the rest by ~2^-bits
    const double exact_to = std::ldexp(scale, -static_cast<int>(bits / 2 - 40));
    cx = nearest_double(c.x(), exact_to);
    cy = nearest_double(c.y(), exact_to);
    r = nearest_double(CGAL::sqrt(d2[0]), exact_to);
    return true;
  }

  void compute_coordinates()
  {
    for(std::size_t fi = 0; fi < faces.size(); ++fi) {
      Face_info& F = faces[fi];
      if(F.cls == BOUNDARY) continue;
      if(F.cls == INSIDE) ++stats.inside_faces;
      if(F.cls != INSIDE && !opt.cross_check) continue;
      std::string why;
      double cx, cy, r;
      if(!construct(static_cast<int>(fi), 512, cx, cy, r, why) &&
         !construct(static_cast<int>(fi), 2048, cx, cy, r, why))
        throw std::logic_error("sdg_oracle: Voronoi vertex of " + sites[F.site[0]].id + " " +
                               sites[F.site[1]].id + " " + sites[F.site[2]].id +
                               " fails verification: " + why);
      F.cx = cx;
      F.cy = cy;
      F.r = r;
    }
  }

  // ---------------------------------------------------------------- coincident vertices
  int find(int f)
  {
    while(uf_parent[f] != f) { uf_parent[f] = uf_parent[uf_parent[f]]; f = uf_parent[f]; }
    return f;
  }

  // Are the exact Voronoi vertices of the inside faces f and g equal? Equal iff their
  // 512-bit values agree to 2^-216 relative AND CORE::Expr in exact mode finds them equal
  // AND their 2048-bit values agree to 2^-984 (MPFR errors reach ~2^-(bits/2) when an
  // exactly-zero quantity goes through a square root); any disagreement among these, or with the
  // SDG's is_degenerate_edge when that says "degenerate", throws std::logic_error.
  // (is_degenerate_edge alone is not enough: it applies symbolic conventions when an
  // endpoint of a segment site is one of the other sites, and then says "not degenerate"
  // for two faces with the same vertex.)
  bool same_vertex(int f, int g, bool sdg_degenerate)
  {
    const std::string what = "sdg_oracle: coincidence of the Voronoi vertices of " +
                             sites[faces[f].site[0]].id + " " + sites[faces[f].site[1]].id + " " +
                             sites[faces[f].site[2]].id + " and " + sites[faces[g].site[0]].id +
                             " " + sites[faces[g].site[1]].id + " " + sites[faces[g].site[2]].id;
    const double scale = (std::max)(scale_of(f), scale_of(g));
    auto agree = [&](long bits) {
      const int exponent = static_cast<int>(bits / 2 - 40);
      Mpfr_precision_guard guard(bits);
      const MPoint a = mvertex(f), b = mvertex(g);
      const MT tol(std::ldexp(scale, -exponent));
      return CGAL::compare(CGAL::abs(a.x() - b.x()), tol) <= 0 &&
             CGAL::compare(CGAL::abs(a.y() - b.y()), tol) <= 0;
    };
    if(!agree(512)) {
      if(sdg_degenerate) throw std::logic_error(what + ": SDG says equal, MPFR says different");
      return false;
    }
    bool equal;
    {
      Core_exact_mode_guard core_mode;
      const XPoint a = xvertex(f), b = xvertex(g);
      equal = (a.x() == b.x()) && (a.y() == b.y());
    }
    ++stats.exact_coincidence_tests;
    if(!equal)
      throw std::logic_error(what + ": equal to 2^-216 relative but CORE says different");
    if(!agree(2048))
      throw std::logic_error(what + ": CORE says equal, 2048-bit MPFR says different");
    return true;
  }

  void merge_coincident_faces()
  {
    uf_parent.resize(faces.size());
    std::iota(uf_parent.begin(), uf_parent.end(), 0);
    for(SDG::Finite_edges_iterator e = sdg.finite_edges_begin(); e != sdg.finite_edges_end();
        ++e) {
      const int f = face_index(e->first);
      const int g = face_index(e->first->neighbor(e->second));
      if(f < 0 || g < 0) continue;
      if(faces[f].cls != INSIDE || faces[g].cls != INSIDE) continue;
      // the SDG's exact predicate (as in its protected is_degenerate_edge(Face_handle, int))
      const SDG::Face_handle fh = e->first;
      const int i = e->second;
      // Where the two faces have the same three sites (the mirror vertex is
      // fh's own vertex i: a point between two segments, with its two
      // tangent circles), the predicate asks whether that site touches the
      // other face's circle, which it always does: it says "degenerate"
      // for two distinct vertices.  There the coordinates decide, as for
      // any other edge (a quadrilateral with a triangular hole cut from
      // land-10m, data/regressions/l10m_USA_point_between_two_segments.wkt).
      const SDG::Vertex_handle mirror = sdg.data_structure().mirror_vertex(fh, i);
      const bool sdg_degenerate = mirror != fh->vertex(i) &&
        sdg.geom_traits().is_degenerate_edge_2_object()(
          fh->vertex(SDG::ccw(i))->site(), fh->vertex(SDG::cw(i))->site(), fh->vertex(i)->site(),
          mirror->site());
      // the correctly rounded vertices of two equal vertices are equal; farther apart than
      // this, the vertices certainly differ
      const double tol = 1e-9 * (std::max)(scale_of(f), scale_of(g));
      if(!sdg_degenerate &&
         (std::abs(faces[f].cx - faces[g].cx) > tol || std::abs(faces[f].cy - faces[g].cy) > tol))
        continue;
      ++stats.coincidence_candidates;
      if(same_vertex(f, g, sdg_degenerate)) {
        ++stats.coincident_pairs;
        const int rf = find(f), rg = find(g);
        if(rf != rg) uf_parent[rf] = rg;
      }
    }
  }

  // ---------------------------------------------------------------- output
  double curve_length(int sa, int sb, const Face_info& F, const Face_info& G) const
  {
    const Site_info& A = sites[sa];
    const Site_info& B = sites[sb];
    if(A.is_point == B.is_point) return std::hypot(F.cx - G.cx, F.cy - G.cy);
    const Site_info& pt = A.is_point ? A : B;
    const Site_info& sg = A.is_point ? B : A;
    return parabola_arc_length(P.pts[pt.g].x(), P.pts[pt.g].y(), P.pts[sg.src].x(),
                               P.pts[sg.src].y(), P.pts[sg.tgt].x(), P.pts[sg.tgt].y(), F.cx,
                               F.cy, G.cx, G.cy);
  }

  Oracle_graph make_graph()
  {
    Oracle_graph G;
    G.bbox_diagonal = P.bbox_diagonal;
    std::vector<int> node_of_face(faces.size(), -1);
    std::vector<int> node_of_root(faces.size(), -1);
    std::vector<std::set<int> > node_sites;
    for(std::size_t f = 0; f < faces.size(); ++f) {
      if(faces[f].cls == OUTSIDE) continue;
      const int root = faces[f].cls == INSIDE ? find(static_cast<int>(f)) : static_cast<int>(f);
      if(node_of_root[root] < 0) {
        node_of_root[root] = static_cast<int>(G.nodes.size());
        Oracle_node n;
        n.zero_radius = faces[root].zero_radius;
        n.x = faces[root].cx;
        n.y = faces[root].cy;
        n.r = faces[root].r;
        n.all_generators = true;
        G.nodes.push_back(n);
        node_sites.emplace_back();
      }
      const int n = node_of_root[root];
      node_of_face[f] = n;
      for(int k = 0; k < 3; ++k) node_sites[n].insert(faces[f].site[k]);
    }
    for(std::size_t n = 0; n < G.nodes.size(); ++n) {
      for(int s : node_sites[n]) {
        G.nodes[n].sites.push_back(sites[s].id);
        if(!sites[s].generator) G.nodes[n].all_generators = false;
      }
      std::sort(G.nodes[n].sites.begin(), G.nodes[n].sites.end());
    }

    for(SDG::Finite_edges_iterator e = sdg.finite_edges_begin(); e != sdg.finite_edges_end();
        ++e) {
      const SDG::Face_handle fh = e->first;
      const int i = e->second;
      const int f = face_index(fh);
      const int g = face_index(fh->neighbor(i));
      if(f < 0 || g < 0) continue; // unbounded Voronoi edge: outside
      const int sa = site_of(fh->vertex(SDG::ccw(i)));
      const int sb = site_of(fh->vertex(SDG::cw(i)));
      const Site_info& A = sites[sa];
      const Site_info& B = sites[sb];
      if(!A.generator || !B.generator) continue; // involves a convex or flat vertex
      if(A.is_point && !B.is_point && (B.src == A.g || B.tgt == A.g)) continue; // normal line
      if(B.is_point && !A.is_point && (A.src == B.g || A.tgt == B.g)) continue;

      const int cf = faces[f].cls, cg = faces[g].cls;
      if(cf == BOUNDARY && cg == BOUNDARY)
        throw std::logic_error("sdg_oracle: Voronoi edge " + A.id + "/" + B.id +
                               " between two radius-0 vertices");
      if(cf != BOUNDARY && cg != BOUNDARY && cf != cg)
        throw std::logic_error("sdg_oracle: Voronoi edge " + A.id + "/" + B.id +
                               " has one end inside and one outside");
      const bool inside = (cf == INSIDE || cg == INSIDE);

      if(!A.is_point && !B.is_point) {
        int common = -1;
        if(P.next[A.g] == B.g) common = B.g;
        else if(P.next[B.g] == A.g) common = A.g;
        if(common >= 0 && !P.touching[common]) {
          if(P.turn[common] == 0) continue; // flat vertex: no medial curve
          if(inside != (P.turn[common] > 0))
            throw std::logic_error("sdg_oracle: bisector of " + A.id + " and " + B.id +
                                   " classified against the turn at their common vertex");
        }
      }
      if(!inside) continue;

      Oracle_edge E;
      E.a = A.id;
      E.b = B.id;
      if(E.b < E.a) std::swap(E.a, E.b);
      E.node0 = node_of_face[f];
      E.node1 = node_of_face[g];
      E.length = (E.node0 == E.node1) ? 0.0 : curve_length(sa, sb, faces[f], faces[g]);
      G.edges.push_back(E);
    }

    // Every convex vertex is the end of one medial curve, the bisector of its two edges; no
    // reflex or flat vertex is. Without holes the two edges share no other curve (a second
    // one needs a hole between the corner and the disk; with holes only ">= 1" is checked).
    // A ring that touches itself may enclose such a hole too (a vertex inside one of its
    // own edges, as in a union whose ring touches its own edge; the halves of the edge
    // keep its id, and each may share a curve with the corner's other edge).
    std::map<std::pair<std::string, std::string>, int> count;
    for(const Oracle_edge& e : G.edges) ++count[std::make_pair(e.a, e.b)];
    const bool has_holes = P.ring_offset.size() > 1 || std::any_of(P.touching.begin(), P.touching.end(), [](char t) { return t != 0; });
    for(std::size_t g = 0; g < P.pts.size(); ++g) {
      if(P.touching[g]) continue;   // (the edges of a vertex where rings touch may bound no sector)
      std::string a = P.edge_id(P.prev[g]), b = P.edge_id(static_cast<int>(g));
      if(b < a) std::swap(a, b);
      auto it = count.find(std::make_pair(a, b));
      const int k = (it == count.end()) ? 0 : it->second;
      const bool ok = (P.turn[g] > 0) ? (k == 1 || (has_holes && k > 1)) : (k == 0);
      if(!ok)
        throw std::logic_error("sdg_oracle: " + std::to_string(k) + " bisector curves " + a +
                               "/" + b + " at vertex " + P.vertex_id(static_cast<int>(g)));
    }
    return G;
  }
};

} // namespace oracle_detail

/// The oracle's medial axis graph (curves with their end nodes, nodes with all sites).
template <class Point_2>
Oracle_graph sdg_medial_graph(const std::vector<std::vector<Point_2> >& rings,
                              const Oracle_options& opt = Oracle_options())
{
  const oracle_detail::Polygon_data P = oracle_detail::make_polygon_data(rings);
  oracle_detail::Oracle_builder builder(P, opt);
  return builder.run();
}

/// Curves and branches from an oracle graph. A branch is a node of positive radius all of
/// whose sites are generators (so no convex or flat vertex among them); there are >= 3.
/// Note that this includes the degree-2 junctions where a curve crosses the normal at a
/// reflex vertex v (sites v, an edge at v, and a third generator).
inline Oracle_result oracle_result_from_graph(const Oracle_graph& G)
{
  Oracle_result R;
  R.bbox_diagonal = G.bbox_diagonal;
  R.curves.reserve(G.edges.size());
  for(const Oracle_edge& e : G.edges) R.curves.push_back(Oracle_curve{e.a, e.b, e.length});
  for(const Oracle_node& n : G.nodes) {
    if(n.zero_radius || !n.all_generators || n.sites.size() < 3) continue;
    R.branches.push_back(Oracle_branch{n.sites, n.x, n.y, n.r});
  }
  return R;
}

template <class Point_2>
Oracle_result sdg_medial_axis(const std::vector<std::vector<Point_2> >& rings)
{
  return oracle_result_from_graph(sdg_medial_graph(rings));
}

} // namespace pma_test

#endif // PMA_TEST_SDG_ORACLE_H
