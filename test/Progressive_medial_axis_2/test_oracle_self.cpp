// Self-test of the test oracle (pma_test/sdg_oracle.h), the random polygon generators
// (pma_test/random_polygons.h) and the curve comparison (pma_test/compare_curves.h).
//
//  1. hand-derived medial axes (square, rectangle, triangle, L-shape with a reflex vertex,
//     square with a square hole, flat vertices), each also with its rings given in the
//     other orientation (ids follow the input order);
//  2. structural checks on the oracle's graph for every polygon: connected, cycle rank =
//     number of holes, degree-1 nodes are exactly the convex corners, degree-2 nodes have a
//     reason (a point site with one of its edges), every generator owns a curve;
//  3. brute-force sampling: points along every (or a sample of the) curve(s) are inside the
//     polygon and equidistant from the curve's two generators, which are the nearest;
//  4. the generators: simple (two independent exact checks), ccw, deterministic, sizes;
//  5. compare_curves / parse_pairs, the parabola length formula, invalid input.
//
// Uses a CHECK macro that is not compiled out by NDEBUG; exits 1 if any check failed.

#include <pma_test/check.h>
#include <pma_test/compare_curves.h>
#include <pma_test/random_polygons.h>
#include <pma_test/sdg_oracle.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <pma_tool/polygon_io.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {


typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef pma_test::Ring Ring;
typedef std::vector<Ring> Rings;
using pma_test::Oracle_curve;

const double s2 = std::sqrt(2.0);

// ------------------------------------------------------------------ id helpers
struct Id
{
  char kind; // 'e' or 'v'
  int ring, index;
};

Id parse_id(const std::string& s)
{
  Id id;
  id.kind = s[0];
  const std::size_t dot = s.find('.');
  id.ring = std::stoi(s.substr(1, dot - 1));
  id.index = std::stoi(s.substr(dot + 1));
  return id;
}

std::string make_id(char kind, int ring, int index)
{
  return std::string(1, kind) + std::to_string(ring) + "." + std::to_string(index);
}

// ids after reversing ring r (of size n) as R[j] = old[(n - j) % n]:
// old edge i becomes edge (n - 1 - i), old vertex i becomes vertex (n - i) % n
std::string reversed_id(const std::string& s, int r, int n)
{
  Id id = parse_id(s);
  if(id.ring != r) return s;
  if(id.kind == 'e') return make_id('e', r, (n - 1 - id.index + n) % n);
  return make_id('v', r, (n - id.index) % n);
}

Ring reversed_ring(const Ring& ring)
{
  const std::size_t n = ring.size();
  Ring out(n);
  for(std::size_t j = 0; j < n; ++j) out[j] = ring[(n - j) % n];
  return out;
}

// ------------------------------------------------------------------ geometry helpers
double seg_distance(const Point& p, const Point& a, const Point& b)
{
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double t = ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / (dx * dx + dy * dy);
  const double u = std::min(1.0, std::max(0.0, t));
  return std::hypot(p.x() - (a.x() + u * dx), p.y() - (a.y() + u * dy));
}

struct Generator_geometry
{
  bool is_point;
  Point a, b; // point: a
};

Generator_geometry geometry_of(const Rings& rings, const std::string& s)
{
  const Id id = parse_id(s);
  const Ring& r = rings.at(id.ring);
  Generator_geometry g;
  g.is_point = (id.kind == 'v');
  g.a = r.at(id.index);
  g.b = r.at((id.index + 1) % r.size());
  return g;
}

double distance_to(const Generator_geometry& g, const Point& p)
{
  if(g.is_point) return std::hypot(p.x() - g.a.x(), p.y() - g.a.y());
  return seg_distance(p, g.a, g.b);
}

bool strictly_inside(const Rings& rings, const Point& p)
{
  if(CGAL::bounded_side_2(rings[0].begin(), rings[0].end(), p, K()) != CGAL::ON_BOUNDED_SIDE)
    return false;
  for(std::size_t h = 1; h < rings.size(); ++h)
    if(CGAL::bounded_side_2(rings[h].begin(), rings[h].end(), p, K()) != CGAL::ON_UNBOUNDED_SIDE)
      return false;
  return true;
}

int turn_at(const Rings& rings, int r, int i)
{
  // +1 convex, -1 reflex, 0 flat, w.r.t. the polygon interior (independent of the oracle)
  const Ring& ring = rings[r];
  const int n = static_cast<int>(ring.size());
  const CGAL::Orientation ro = CGAL::orientation_2(ring.begin(), ring.end(), K());
  const bool left_interior = (r == 0) ? (ro == CGAL::COUNTERCLOCKWISE) : (ro == CGAL::CLOCKWISE);
  const CGAL::Orientation o = CGAL::orientation(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
  if(o == CGAL::COLLINEAR) return 0;
  return ((o == CGAL::LEFT_TURN) == left_interior) ? 1 : -1;
}

double parabola_length_numeric(double fx, double fy, double ax, double ay, double bx, double by,
                               double x1, double y1, double x2, double y2, int N = 200000)
{
  // chord sum over a fine subdivision of the parabola between the projections (not the
  // closed form used by the oracle)
  const double l = std::hypot(bx - ax, by - ay);
  const double ux = (bx - ax) / l, uy = (by - ay) / l;
  double nx = -uy, ny = ux;
  double f = (fx - ax) * nx + (fy - ay) * ny;
  if(f < 0) { nx = -nx; ny = -ny; f = -f; }
  const double qx = fx - f * nx, qy = fy - f * ny;
  const double t0 = (x1 - qx) * ux + (y1 - qy) * uy, t1 = (x2 - qx) * ux + (y2 - qy) * uy;
  // points t = f sinh(u), u uniform: chords of nearly equal length even for thin parabolas
  const double u0 = std::asinh(t0 / f), u1 = std::asinh(t1 / f);
  double sum = 0, px = 0, py = 0;
  for(int i = 0; i <= N; ++i) {
    const double t = (i == 0) ? t0 : (i == N) ? t1 : f * std::sinh(u0 + (u1 - u0) * i / N);
    const double h = (t * t + f * f) / (2 * f);
    const double x = qx + t * ux + h * nx, y = qy + t * uy + h * ny;
    if(i > 0) sum += std::hypot(x - px, y - py);
    px = x;
    py = y;
  }
  return sum;
}

// ------------------------------------------------------------------ structural checks
// max_sampled_curves: the brute-force sampling (O(curves * vertices)) is limited to that
// many curves, evenly spread.
void structural_checks(const std::string& name, const Rings& rings, const pma_test::Oracle_graph& G,
                       std::size_t max_sampled_curves = 100000)
{
  const double D = G.bbox_diagonal;
  const std::size_t holes = rings.size() - 1;

  // graph: nodes incident to non-loop edges
  std::vector<std::vector<int> > adj(G.nodes.size());
  std::size_t E = 0;
  for(const pma_test::Oracle_edge& e : G.edges) {
    CHECK(e.node0 >= 0 && e.node1 >= 0, name);
    CHECK(e.a < e.b, name + ": unsorted pair " + e.a + " " + e.b);
    CHECK(e.length >= 0 && std::isfinite(e.length), name);
    if(e.node0 == e.node1) {
      CHECK(e.length == 0, name + ": loop with positive length");
      continue;
    }
    ++E;
    adj[e.node0].push_back(e.node1);
    adj[e.node1].push_back(e.node0);
  }
  std::size_t V = 0, C = 0;
  std::vector<int> comp(G.nodes.size(), -1);
  for(std::size_t n = 0; n < G.nodes.size(); ++n) {
    if(adj[n].empty() || comp[n] >= 0) continue;
    ++C;
    std::vector<int> stack(1, static_cast<int>(n));
    comp[n] = static_cast<int>(C);
    while(!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      ++V;
      for(int w : adj[u])
        if(comp[w] < 0) { comp[w] = static_cast<int>(C); stack.push_back(w); }
    }
  }
  CHECK(C == 1, name + ": medial axis has " + std::to_string(C) + " components");
  CHECK(E + C == V + holes,
            name + ": cycle rank " + std::to_string(static_cast<long>(E + C) - static_cast<long>(V)) +
              " != holes " + std::to_string(holes));

  // degrees
  std::size_t convex = 0;
  for(std::size_t r = 0; r < rings.size(); ++r)
    for(std::size_t i = 0; i < rings[r].size(); ++i)
      if(turn_at(rings, static_cast<int>(r), static_cast<int>(i)) > 0) ++convex;
  std::size_t degree1 = 0;
  for(std::size_t n = 0; n < G.nodes.size(); ++n) {
    const pma_test::Oracle_node& node = G.nodes[n];
    const std::size_t d = adj[n].size();
    if(d == 0) continue;
    if(node.zero_radius) {
      CHECK(d == 1, name + ": radius-0 node of degree " + std::to_string(d));
    } else {
      CHECK(node.r > 0, name);
      CHECK(d >= 2, name + ": dangling medial curve end at a node of positive radius");
    }
    if(d == 1) ++degree1;
    if(d == 2 && !node.zero_radius) {
      // a junction needs a point site with one of its own edges among its sites
      bool reason = false;
      for(const std::string& s : node.sites) {
        const Id id = parse_id(s);
        if(id.kind != 'v') continue;
        const int n_r = static_cast<int>(rings[id.ring].size());
        const std::string e1 = make_id('e', id.ring, id.index);
        const std::string e0 = make_id('e', id.ring, (id.index + n_r - 1) % n_r);
        if(std::count(node.sites.begin(), node.sites.end(), e0) ||
           std::count(node.sites.begin(), node.sites.end(), e1))
          reason = true;
      }
      CHECK(reason, name + ": degree-2 node without a reason");
    }
  }
  CHECK(degree1 == convex, name + ": " + std::to_string(degree1) + " curve ends on the boundary, " +
                                 std::to_string(convex) + " convex vertices");

  // every generator (edge, reflex vertex) appears in some curve; no non-generator does
  std::set<std::string> used;
  for(const pma_test::Oracle_edge& e : G.edges) { used.insert(e.a); used.insert(e.b); }
  for(std::size_t r = 0; r < rings.size(); ++r)
    for(std::size_t i = 0; i < rings[r].size(); ++i) {
      CHECK(used.count(make_id('e', static_cast<int>(r), static_cast<int>(i))),
                name + ": edge without a curve");
      const bool reflex = turn_at(rings, static_cast<int>(r), static_cast<int>(i)) < 0;
      CHECK(reflex == (used.count(make_id('v', static_cast<int>(r), static_cast<int>(i))) > 0),
                name + ": vertex " + make_id('v', static_cast<int>(r), static_cast<int>(i)) +
                  (reflex ? " is reflex but owns no curve" : " is not reflex but owns a curve"));
    }

  // brute-force sampling
  std::vector<Generator_geometry> all_edges;
  for(std::size_t r = 0; r < rings.size(); ++r)
    for(std::size_t i = 0; i < rings[r].size(); ++i)
      all_edges.push_back(geometry_of(rings, make_id('e', static_cast<int>(r), static_cast<int>(i))));
  const std::size_t step = std::max<std::size_t>(1, G.edges.size() / std::max<std::size_t>(1, max_sampled_curves));
  const double tol = 1e-9 * D;
  for(std::size_t k = 0; k < G.edges.size(); k += step) {
    const pma_test::Oracle_edge& e = G.edges[k];
    if(e.node0 == e.node1 || e.length < 1e-7 * D) continue;
    const pma_test::Oracle_node& n0 = G.nodes[e.node0];
    const pma_test::Oracle_node& n1 = G.nodes[e.node1];
    const Generator_geometry A = geometry_of(rings, e.a), B = geometry_of(rings, e.b);
    {
      // the length, independently: a chord sum along the curve between its end nodes
      double numeric;
      if(A.is_point != B.is_point) {
        const Generator_geometry& F = A.is_point ? A : B;
        const Generator_geometry& S = A.is_point ? B : A;
        numeric = parabola_length_numeric(F.a.x(), F.a.y(), S.a.x(), S.a.y(), S.b.x(), S.b.y(), n0.x,
                                          n0.y, n1.x, n1.y, 4000);
      } else {
        numeric = std::hypot(n1.x - n0.x, n1.y - n0.y);
      }
      CHECK(std::abs(numeric - e.length) <= 1e-6 * e.length + 1e-9 * D,
                name + ": length of " + e.a + "/" + e.b + " " + std::to_string(e.length) +
                  " vs numeric " + std::to_string(numeric));
    }
    for(double s : {0.25, 0.5, 0.75}) {
      Point x;
      if(A.is_point != B.is_point) {
        const Generator_geometry& F = A.is_point ? A : B;
        const Generator_geometry& S = A.is_point ? B : A;
        const double l = std::hypot(S.b.x() - S.a.x(), S.b.y() - S.a.y());
        const double ux = (S.b.x() - S.a.x()) / l, uy = (S.b.y() - S.a.y()) / l;
        double nx = -uy, ny = ux;
        double f = (F.a.x() - S.a.x()) * nx + (F.a.y() - S.a.y()) * ny;
        if(f < 0) { nx = -nx; ny = -ny; f = -f; }
        const double qx = F.a.x() - f * nx, qy = F.a.y() - f * ny; // foot of the focus
        const double t0 = (n0.x - qx) * ux + (n0.y - qy) * uy;
        const double t1 = (n1.x - qx) * ux + (n1.y - qy) * uy;
        const double t = t0 + s * (t1 - t0);
        const double h = (t * t + f * f) / (2 * f);
        x = Point(qx + t * ux + h * nx, qy + t * uy + h * ny);
      } else {
        x = Point(n0.x + s * (n1.x - n0.x), n0.y + s * (n1.y - n0.y));
      }
      const double da = distance_to(A, x), db = distance_to(B, x);
      double dmin = std::numeric_limits<double>::max();
      for(const Generator_geometry& g : all_edges) dmin = std::min(dmin, distance_to(g, x));
      CHECK(std::abs(da - db) <= tol,
                name + ": sample of " + e.a + "/" + e.b + " not equidistant");
      CHECK(std::min(da, db) <= dmin + tol,
                name + ": a boundary point is closer than " + e.a + "/" + e.b);
      if(dmin > 1e-6 * D)
        CHECK(strictly_inside(rings, x), name + ": sample of " + e.a + "/" + e.b + " outside");
    }
  }
}

// ------------------------------------------------------------------ hand-derived cases
pma_test::Oracle_graph run_oracle(const std::string& name, const Rings& rings)
{
  pma_test::Oracle_options opt;
  opt.cross_check = true;
  try {
    return pma_test::sdg_medial_graph(rings, opt);
  } catch(const std::exception& e) {
    CHECK(false, name + ": oracle threw: " + e.what());
    return pma_test::Oracle_graph();
  }
}

void expect_axis(const std::string& name, const Rings& rings, const std::vector<Oracle_curve>& expected,
                 std::size_t expected_branches = static_cast<std::size_t>(-1))
{
  const pma_test::Oracle_graph G = run_oracle(name, rings);
  const pma_test::Oracle_result R = pma_test::oracle_result_from_graph(G);
  const pma_test::Curve_diff diff = pma_test::compare_curves(R.curves, expected, R.bbox_diagonal, 1e-12);
  CHECK(diff.ok(), name + ":\n" + diff.report());
  if(expected_branches != static_cast<std::size_t>(-1))
    CHECK(R.branches.size() == expected_branches,
              name + ": " + std::to_string(R.branches.size()) + " branches");
  structural_checks(name, rings, G);
}

// checks the shape, then again with each ring reversed in turn (ids remapped)
void expect_axis_all_orientations(const std::string& name, const Rings& rings,
                                  const std::vector<Oracle_curve>& expected, std::size_t branches)
{
  expect_axis(name, rings, expected, branches);
  for(std::size_t r = 0; r < rings.size(); ++r) {
    Rings rev = rings;
    rev[r] = reversed_ring(rings[r]);
    std::vector<Oracle_curve> exp_rev;
    for(const Oracle_curve& c : expected) {
      std::string a = reversed_id(c.a, static_cast<int>(r), static_cast<int>(rings[r].size()));
      std::string b = reversed_id(c.b, static_cast<int>(r), static_cast<int>(rings[r].size()));
      if(b < a) std::swap(a, b);
      exp_rev.push_back(Oracle_curve{a, b, c.length});
    }
    expect_axis(name + " (ring " + std::to_string(r) + " reversed)", rev, exp_rev, branches);
  }
}

pma_test::Oracle_result oracle_result(const std::string& name, const Rings& rings)
{
  return pma_test::oracle_result_from_graph(run_oracle(name, rings));
}

const pma_test::Oracle_branch* find_branch(const pma_test::Oracle_result& R, std::vector<std::string> gens)
{
  std::sort(gens.begin(), gens.end());
  for(const pma_test::Oracle_branch& b : R.branches)
    if(b.generators == gens) return &b;
  return nullptr;
}

void check_branch(const std::string& name, const pma_test::Oracle_result& R,
                  const std::vector<std::string>& gens, double x, double y, double r)
{
  const pma_test::Oracle_branch* b = find_branch(R, gens);
  std::string g;
  for(const std::string& s : gens) g += " " + s;
  CHECK(b != nullptr, name + ": missing branch" + g);
  if(b) {
    CHECK(std::abs(b->x - x) <= 1e-15 * (1 + std::abs(x)) && std::abs(b->y - y) <= 1e-15 * (1 + std::abs(y)),
              name + ": branch" + g + " misplaced");
    CHECK(std::abs(b->r - r) <= 1e-15 * (1 + r), name + ": branch" + g + " radius");
  }
}

Rings rings_of(std::initializer_list<std::initializer_list<std::pair<double, double> > > rs)
{
  Rings out;
  for(const auto& r : rs) {
    out.emplace_back();
    for(const auto& p : r) out.back().push_back(Point(p.first, p.second));
  }
  return out;
}

void test_hand_cases()
{
  const double h = std::sqrt(0.5);
  // unit square: 4 corner bisectors, possibly a zero-length curve at the centre
  {
    const Rings sq = rings_of({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
    expect_axis_all_orientations("square", sq,
                                 {{"e0.0", "e0.1", h}, {"e0.1", "e0.2", h}, {"e0.2", "e0.3", h},
                                  {"e0.0", "e0.3", h}},
                                 1);
    const pma_test::Oracle_result R = oracle_result("square", sq);
    check_branch("square", R, {"e0.0", "e0.1", "e0.2", "e0.3"}, 0.5, 0.5, 0.5);
    for(const Oracle_curve& c : R.curves)
      if((c.a == "e0.0" && c.b == "e0.2") || (c.a == "e0.1" && c.b == "e0.3"))
        CHECK(c.length == 0, "square: centre curve has positive length");
  }
  // 2 x 1 rectangle: corner bisectors and the middle curve of length 1
  {
    const Rings rect = rings_of({{{0, 0}, {2, 0}, {2, 1}, {0, 1}}});
    expect_axis_all_orientations("rectangle", rect,
                                 {{"e0.0", "e0.1", h}, {"e0.1", "e0.2", h}, {"e0.2", "e0.3", h},
                                  {"e0.0", "e0.3", h}, {"e0.0", "e0.2", 1.0}},
                                 2);
    const pma_test::Oracle_result R = oracle_result("rectangle", rect);
    check_branch("rectangle", R, {"e0.0", "e0.2", "e0.3"}, 0.5, 0.5, 0.5);
    check_branch("rectangle", R, {"e0.0", "e0.1", "e0.2"}, 1.5, 0.5, 0.5);
  }
  // 3-4-5 right triangle: incentre (1, 1), radius 1
  {
    const Rings tri = rings_of({{{0, 0}, {4, 0}, {0, 3}}});
    expect_axis_all_orientations("triangle", tri,
                                 {{"e0.0", "e0.2", s2}, {"e0.0", "e0.1", std::sqrt(10.0)},
                                  {"e0.1", "e0.2", std::sqrt(5.0)}},
                                 1);
    check_branch("triangle", oracle_result("triangle", tri), {"e0.0", "e0.1", "e0.2"}, 1, 1, 1);
  }
  // L-shaped hexagon, reflex vertex v0.3 = (1, 1). Arms [1,2]x[0,1] and [0,1]x[1,2].
  //  corners: bisectors of length sqrt(1/2) at (2,0), (2,1), (1,2), (0,2);
  //  arm middles e0.0/e0.2 from (1.5,.5) to (1,.5) and e0.3/e0.5 from (.5,1.5) to (.5,1): 0.5;
  //  then parabolas e0.0/v0.3 (focus (1,1), directrix y=0) from (1,.5) to the branch
  //  point b = (2-sqrt2, 2-sqrt2) where the bisector y = x of the corner (0,0) meets them,
  //  and symmetrically e0.5/v0.3; the bisector e0.0/e0.5 from (0,0) to b.
  //  Parabola y = (t^2+1)/2 over t in [1-sqrt2, 0]: length (t s + asinh t)/2, s = sqrt(1+t^2).
  {
    const double t = s2 - 1, s = std::sqrt(1 + t * t);
    const double lp = 0.5 * (t * s + std::asinh(t));
    const double b = 2 - s2;
    const Rings L = rings_of({{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}});
    expect_axis_all_orientations("L-shape", L,
                                 {{"e0.0", "e0.1", h}, {"e0.1", "e0.2", h}, {"e0.3", "e0.4", h},
                                  {"e0.4", "e0.5", h}, {"e0.0", "e0.2", 0.5}, {"e0.3", "e0.5", 0.5},
                                  {"e0.0", "v0.3", lp}, {"e0.5", "v0.3", lp}, {"e0.0", "e0.5", s2 * b}},
                                 5);
    const pma_test::Oracle_result R = oracle_result("L-shape", L);
    check_branch("L-shape", R, {"e0.0", "e0.5", "v0.3"}, b, b, b);
    check_branch("L-shape", R, {"e0.0", "e0.2", "v0.3"}, 1, 0.5, 0.5); // junction at the normal
    check_branch("L-shape", R, {"e0.3", "e0.5", "v0.3"}, 0.5, 1, 0.5);
    check_branch("L-shape", R, {"e0.0", "e0.1", "e0.2"}, 1.5, 0.5, 0.5);
    check_branch("L-shape", R, {"e0.3", "e0.4", "e0.5"}, 0.5, 1.5, 0.5);
  }
  // the L-shape scaled by 3 and shifted: every length times 3
  {
    const double t = s2 - 1, s = std::sqrt(1 + t * t);
    const double lp = 3 * 0.5 * (t * s + std::asinh(t));
    const double b = 3 * (2 - s2);
    const Rings L = rings_of({{{10, -5}, {16, -5}, {16, -2}, {13, -2}, {13, 1}, {10, 1}}});
    expect_axis_all_orientations("L-shape x3", L,
                                 {{"e0.0", "e0.1", 3 * h}, {"e0.1", "e0.2", 3 * h}, {"e0.3", "e0.4", 3 * h},
                                  {"e0.4", "e0.5", 3 * h}, {"e0.0", "e0.2", 1.5}, {"e0.3", "e0.5", 1.5},
                                  {"e0.0", "v0.3", lp}, {"e0.5", "v0.3", lp}, {"e0.0", "e0.5", s2 * b}},
                                 5);
    check_branch("L-shape x3", oracle_result("L-shape x3", L), {"e0.0", "e0.5", "v0.3"}, 10 + b, -5 + b, b);
  }
  // square [0,4]^2 with the hole [1,3]^2: a corridor of width 1, one cycle.
  //  side k: e0.k / e1.k straight, length 2;
  //  hole corner v1.j: two parabolas (focus the corner, directrix an outer side) of the
  //  L-shape's length; outer corner: bisector to (b, b)-like points, length sqrt2 (2-sqrt2).
  {
    const double t = s2 - 1, s = std::sqrt(1 + t * t);
    const double lp = 0.5 * (t * s + std::asinh(t));
    const double lb = s2 * (2 - s2);
    const Rings sh = rings_of({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}});
    std::vector<Oracle_curve> exp = {
      {"e0.0", "e1.0", 2}, {"e0.1", "e1.1", 2}, {"e0.2", "e1.2", 2}, {"e0.3", "e1.3", 2},
      {"e0.0", "v1.0", lp}, {"e0.3", "v1.0", lp}, {"e0.0", "v1.1", lp}, {"e0.1", "v1.1", lp},
      {"e0.1", "v1.2", lp}, {"e0.2", "v1.2", lp}, {"e0.2", "v1.3", lp}, {"e0.3", "v1.3", lp},
      {"e0.0", "e0.1", lb}, {"e0.1", "e0.2", lb}, {"e0.2", "e0.3", lb}, {"e0.0", "e0.3", lb}};
    expect_axis_all_orientations("square with hole", sh, exp, 12);
    // hole given clockwise and outer clockwise at once
    Rings both = sh;
    both[0] = reversed_ring(sh[0]);
    both[1] = reversed_ring(sh[1]);
    std::vector<Oracle_curve> exp2;
    for(const Oracle_curve& c : exp) {
      std::string a = reversed_id(reversed_id(c.a, 0, 4), 1, 4);
      std::string b = reversed_id(reversed_id(c.b, 0, 4), 1, 4);
      if(b < a) std::swap(a, b);
      exp2.push_back(Oracle_curve{a, b, c.length});
    }
    expect_axis("square with hole (both reversed)", both, exp2, 12);
  }
  // flat vertex (1,0) in the bottom side of the 2 x 1 rectangle: the middle curve is cut at
  // the normal x = 1 into e0.0/e0.3 and e0.1/e0.3; no curve e0.0/e0.1, no v0.1
  {
    const Rings f = rings_of({{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}});
    expect_axis_all_orientations("flat vertex", f,
                                 {{"e0.0", "e0.4", h}, {"e0.1", "e0.2", h}, {"e0.2", "e0.3", h},
                                  {"e0.3", "e0.4", h}, {"e0.0", "e0.3", 0.5}, {"e0.1", "e0.3", 0.5}},
                                 2);
  }
  // flat vertex (0.25,0) whose normal cuts the corner bisector at (0.25, 0.25)
  {
    const double q = 0.25 * s2;
    const Rings f = rings_of({{{0, 0}, {0.25, 0}, {2, 0}, {2, 1}, {0, 1}}});
    expect_axis_all_orientations("flat vertex in a corner", f,
                                 {{"e0.0", "e0.4", q}, {"e0.1", "e0.4", q}, {"e0.3", "e0.4", h},
                                  {"e0.1", "e0.3", 1.0}, {"e0.1", "e0.2", h}, {"e0.2", "e0.3", h}},
                                 2);
  }
  // two flat vertices on opposite sides at the same abscissa: the junction point (1, .5)
  // touches both flat vertices
  {
    const Rings f = rings_of({{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}}});
    expect_axis_all_orientations("two flat vertices", f,
                                 {{"e0.0", "e0.5", h}, {"e0.1", "e0.2", h}, {"e0.2", "e0.3", h},
                                  {"e0.4", "e0.5", h}, {"e0.0", "e0.4", 0.5}, {"e0.1", "e0.3", 0.5}},
                                 2);
  }
  // parabola length formula against a fine chord sum
  {
    typedef pma_test::oracle_detail::Oracle_builder B;
    const double l = B::parabola_arc_length(0.3, 1.7, -1, 0.2, 3, -0.4, -0.8, 3.1, 2.5, 2.0);
    // endpoints are projected: use the parabola points over the same parameters
    const double n = parabola_length_numeric(0.3, 1.7, -1, 0.2, 3, -0.4, -0.8, 3.1, 2.5, 2.0);
    CHECK(std::abs(l - n) <= 1e-9 * n, "parabola length " + std::to_string(l) + " vs " + std::to_string(n));
    const double l2 = B::parabola_arc_length(0, 1e-3, 0, 0, 1, 0, -0.01, 0, 0.02, 0);
    const double n2 = parabola_length_numeric(0, 1e-3, 0, 0, 1, 0, -0.01, 0, 0.02, 0);
    CHECK(std::abs(l2 - n2) <= 1e-8 * n2, "thin parabola length");
  }
}

// ------------------------------------------------------------------ invalid input
void test_invalid_input()
{
  auto throws_invalid = [](const Rings& r) {
    try {
      pma_test::sdg_medial_axis(r);
    } catch(const std::invalid_argument&) {
      return true;
    } catch(...) {
      return false;
    }
    return false;
  };
  CHECK(throws_invalid(rings_of({{{0, 0}, {1, 0}}})));
  CHECK(throws_invalid(rings_of({{{0, 0}, {1, 0}, {1, 1}, {1, 0}, {0, 1}}}))); // repeated vertex
  CHECK(throws_invalid(rings_of({{{0, 0}, {2, 0}, {1, 0}, {1, 1}}})));         // spike
}

// ------------------------------------------------------------------ compare_curves
void test_compare()
{
  using pma_test::compare_curves;
  const std::vector<Oracle_curve> a = {{"e0.0", "e0.1", 1.0}, {"e0.1", "e0.2", 2.0}, {"e0.1", "e0.2", 3.0},
                                       {"e0.0", "e0.2", 0.0}};
  // same, other order, pair written backwards, degenerate curve missing
  const std::vector<Oracle_curve> b = {{"e0.2", "e0.1", 3.0 + 1e-9}, {"e0.0", "e0.1", 1.0}, {"e0.1", "e0.2", 2.0}};
  CHECK(compare_curves(a, b, 10.0).ok(), compare_curves(a, b, 10.0).report());
  CHECK(compare_curves(b, a, 10.0).ok());
  // multiplicity
  const std::vector<Oracle_curve> c = {{"e0.0", "e0.1", 1.0}, {"e0.1", "e0.2", 2.0}};
  pma_test::Curve_diff d = compare_curves(a, c, 10.0);
  CHECK(!d.ok() && d.only_in_a.size() == 1 && d.only_in_b.empty() && d.length_mismatch.empty());
  CHECK(d.only_in_a.size() == 1 && d.only_in_a[0].find("e0.1 e0.2 3") == 0, d.report());
  // length mismatch
  const std::vector<Oracle_curve> e = {{"e0.0", "e0.1", 1.1}, {"e0.1", "e0.2", 2.0}, {"e0.1", "e0.2", 3.0}};
  d = compare_curves(a, e, 10.0);
  CHECK(d.length_mismatch.size() == 1 && d.only_in_a.empty() && d.only_in_b.empty());
  // extra curve
  std::vector<Oracle_curve> f = e;
  f[0].length = 1.0;
  f.push_back({"e0.3", "v0.1", 0.5});
  d = compare_curves(a, f, 10.0);
  CHECK(d.only_in_b.size() == 1 && d.only_in_a.empty() && d.length_mismatch.empty());
  CHECK(!d.report().empty());
  // a short non-degenerate curve matched by a degenerate one of nearly the same length
  const std::vector<Oracle_curve> g1 = {{"e0.0", "e0.1", 1.5e-8}};
  const std::vector<Oracle_curve> g2 = {{"e0.0", "e0.1", 0.5e-8}};
  CHECK(compare_curves(g1, g2, 10.0).ok());
  CHECK(!compare_curves(g1, {}, 10.0).ok());
  CHECK(compare_curves(g2, {}, 10.0).ok());
  // NaN never matches
  const std::vector<Oracle_curve> n1 = {{"e0.0", "e0.1", std::nan("")}};
  CHECK(!compare_curves(n1, c, 10.0).ok());
  // parse_pairs
  std::istringstream in("# comment\npair e0.1 e0.0 0.5\nbranch e0.0 e0.1 e0.2 1 2 3\npair v0.3 e0.2 2.25\n\n");
  const std::vector<Oracle_curve> p = pma_test::parse_pairs(in);
  CHECK(p.size() == 2);
  CHECK(p.size() == 2 && p[0].a == "e0.0" && p[0].b == "e0.1" && p[0].length == 0.5);
  CHECK(p.size() == 2 && p[1].a == "e0.2" && p[1].b == "v0.3" && p[1].length == 2.25);
}

// ------------------------------------------------------------------ generators
bool library_valid(const Rings& rings)
{
  try {
    CGAL::Progressive_medial_axes::validate_polygon_rings<K>(rings);
    return true;
  } catch(const std::exception&) {
    return false;
  }
}

double ring_area2(const Ring& r) // twice the signed area (exact for small integers)
{
  double a = 0;
  for(std::size_t i = 0; i < r.size(); ++i) {
    const Point& p = r[i];
    const Point& q = r[(i + 1) % r.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a;
}

void check_polygon(const std::string& name, const Rings& rings, std::size_t max_sampled = 100000)
{
  CHECK(pma_test::is_valid_polygon_with_holes(rings), name + ": not valid (pma_test check)");
  CHECK(library_valid(rings), name + ": not valid (validate_polygon_rings)");
  CHECK(CGAL::orientation_2(rings[0].begin(), rings[0].end(), K()) == CGAL::COUNTERCLOCKWISE,
            name + ": outer ring not ccw");
  const pma_test::Oracle_graph G = run_oracle(name, rings);
  if(G.edges.empty()) return;
  structural_checks(name, rings, G, max_sampled);
}

void test_rng()
{
  // std::mt19937_64 with seed 5489 starts with 14514284786278117030 (the standard fixes
  // the engine); our mappings of it are plain arithmetic
  pma_test::random_detail::Rng rng(5489);
  CHECK(rng.uniform() == static_cast<double>(14514284786278117030ull >> 11) / 9007199254740992.0);
  pma_test::random_detail::Rng r2(1);
  for(int i = 0; i < 1000; ++i) {
    const int v = r2.integer(-3, 5);
    CHECK(v >= -3 && v <= 5);
    const double u = r2.uniform();
    CHECK(u >= 0 && u < 1);
  }
}

int skipped_snapped = 0;

void test_generators(int seeds, std::uint64_t base_seed)
{
  // deterministic
  CHECK(pma_test::random_star_polygon(11, 40) == pma_test::random_star_polygon(11, 40));
  CHECK(pma_test::random_walk_polygon(11, 40) == pma_test::random_walk_polygon(11, 40));
  CHECK(pma_test::random_rectilinear_polygon(11, 40, true) == pma_test::random_rectilinear_polygon(11, 40, true));
  CHECK(pma_test::random_polygon_with_holes(11, 9, 7) == pma_test::random_polygon_with_holes(11, 9, 7));
  CHECK(pma_test::random_star_polygon(11, 40) != pma_test::random_star_polygon(12, 40));

  for(int s = 0; s < seeds; ++s) {
    const std::uint64_t seed = base_seed + s;
    const int n = 3 + (s * 37) % 298; // 3 .. 300
    {
      const Ring r = pma_test::random_star_polygon(seed, n);
      CHECK(static_cast<int>(r.size()) == n);
      CHECK(pma_test::is_simple_polygon(r), "star " + std::to_string(s));
      check_polygon("star seed " + std::to_string(seed) + " n " + std::to_string(n), Rings(1, r));
    }
    {
      const Ring r = pma_test::random_walk_polygon(seed, n);
      CHECK(static_cast<int>(r.size()) == n);
      check_polygon("walk seed " + std::to_string(seed) + " n " + std::to_string(n), Rings(1, r));
    }
    {
      const int cells = 1 + (s * 53) % 300;
      const bool flat = (s % 2 == 1);
      const Ring r = pma_test::random_rectilinear_polygon(seed, cells, flat);
      bool grid = true, axis = true;
      std::size_t flats = 0;
      for(std::size_t i = 0; i < r.size(); ++i) {
        const Point& p = r[i];
        const Point& q = r[(i + 1) % r.size()];
        grid = grid && p.x() == std::floor(p.x()) && p.y() == std::floor(p.y());
        axis = axis && (p.x() == q.x() || p.y() == q.y());
        if(CGAL::collinear(r[(i + r.size() - 1) % r.size()], p, q)) ++flats;
      }
      CHECK(grid && axis);
      CHECK(flat || flats == 0, "rectilinear without flat vertices has one");
      CHECK(ring_area2(r) == 2.0 * cells, "rectilinear area " + std::to_string(ring_area2(r) / 2) +
                                                  " for " + std::to_string(cells) + " cells");
      check_polygon("rectilinear seed " + std::to_string(seed) + " cells " + std::to_string(cells) +
                      (flat ? " flat" : ""),
                    Rings(1, r));
    }
    {
      // snapped to a coarse grid: many collinear and cocircular configurations (kept only
      // when still a valid polygon)
      const double grid = (s % 3 == 0) ? 8 : 32;
      auto snap = [grid](Ring r) {
        for(Point& p : r) p = Point(std::round(p.x() * grid), std::round(p.y() * grid));
        return r;
      };
      const Ring a = snap(pma_test::random_star_polygon(seed, 3 + n % 40));
      if(pma_test::is_simple_polygon(a))
        check_polygon("snapped star seed " + std::to_string(seed), Rings(1, a));
      else
        ++skipped_snapped;
      Ring b = snap(pma_test::random_walk_polygon(seed, 3 + n % 30));
      if(CGAL::orientation_2(b.begin(), b.end(), K()) == CGAL::CLOCKWISE) std::reverse(b.begin(), b.end());
      if(pma_test::is_simple_polygon(b))
        check_polygon("snapped walk seed " + std::to_string(seed), Rings(1, b));
      else
        ++skipped_snapped;
    }
    if(s % 4 == 0) {
      const int outer = (s % 8 == 0) ? 4 : 3 + (s * 11) % 60;
      const int holes = (s * 7) % 40;
      const Rings r = pma_test::random_polygon_with_holes(seed, outer, holes);
      CHECK(r.size() == static_cast<std::size_t>(holes) + 1 && r[0].size() == static_cast<std::size_t>(outer));
      for(std::size_t h = 1; h < r.size(); ++h)
        CHECK(CGAL::orientation_2(r[h].begin(), r[h].end(), K()) == CGAL::CLOCKWISE);
      check_polygon("holes seed " + std::to_string(seed) + " outer " + std::to_string(outer) + " holes " +
                      std::to_string(holes),
                    r);
    }
  }
  // regressions: a flat vertex and its two edges touch a circle at one point, with two
  // more sites on it; CGAL's is_degenerate_edge calls the faces of that circle distinct
  check_polygon("rectilinear seed 1701 (regression)", Rings(1, pma_test::random_rectilinear_polygon(1701, 254, true)));
  check_polygon("rectilinear seed 1735 (regression)", Rings(1, pma_test::random_rectilinear_polygon(1735, 256, true)));
  // 1000 holes
  {
    const Rings r = pma_test::random_polygon_with_holes(77, 300, 1000);
    CHECK(r.size() == 1001);
    check_polygon("1000 holes", r, 3000);
  }
  // a polygon with a flat vertex on every edge of a random star (shared circles)
  {
    const Ring star = pma_test::random_rectilinear_polygon(5, 60, false);
    Ring r;
    for(std::size_t i = 0; i < star.size(); ++i) {
      const Point& p = star[i];
      const Point& q = star[(i + 1) % star.size()];
      r.push_back(p);
      r.push_back(Point((p.x() + q.x()) / 2, (p.y() + q.y()) / 2)); // exact (integers / 2)
    }
    check_polygon("rectilinear with midpoints", Rings(1, r));
  }
}

// ------------------------------------------------------------------ data files
void test_data_files()
{
  const char* files[] = {"syn_comb50.wkt", "syn_maze20.wkt", "syn_spiral20.wkt", "syn_ngon64.wkt",
                         "syn_sliver500.wkt", "syn_star2k.wkt", "syn_cheese1k.wkt", "c1m_GBR_0.wkt"};
  for(const char* f : files) {
    const std::string path = std::string(PMA_TEST_DATA) + "/" + f;
    Rings rings;
    try {
      rings = pma_tool::read_polygon_file<Point>(path);
    } catch(const std::exception& e) {
      CHECK(false, path + ": " + e.what());
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    CHECK(pma_test::is_valid_polygon_with_holes(rings), path);
    const pma_test::Oracle_graph G = run_oracle(f, rings);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("  %-18s %7zu vertices %7zu curves  oracle+checks %.2f s\n", f, G.stats.sdg_vertices / 2,
                G.edges.size(), t);
    if(!G.edges.empty()) structural_checks(f, rings, G, 2000);
  }
}

} // namespace

int main(int argc, char** argv)
{
  // test_oracle_self [SEEDS [BASE_SEED]]: random polygons use seeds BASE_SEED .. +SEEDS-1
  const int seeds = (argc > 1) ? std::atoi(argv[1]) : 300;
  const std::uint64_t base_seed = (argc > 2) ? std::strtoull(argv[2], nullptr, 10) : 1000;
  const auto t0 = std::chrono::steady_clock::now();
  test_rng();
  test_compare();
  test_invalid_input();
  test_hand_cases();
  std::printf("hand-derived cases: %ld checks, %d failures\n", pma_test::checks(), pma_test::failures());
  test_generators(seeds, base_seed);
  std::printf("generators (%d seeds): %ld checks, %d failures (%d snapped polygons not simple, skipped)\n",
              seeds, pma_test::checks(), pma_test::failures(), skipped_snapped);
  test_data_files();
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("test_oracle_self: %.1f s\n", t);
  return pma_test::report("test_oracle_self");
}
