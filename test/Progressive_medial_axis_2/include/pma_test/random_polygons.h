// Test-only random polygons, deterministic from a seed: the same seed gives the same
// polygon on every platform (std::mt19937_64 is fully specified; the mappings from its
// output to reals and integers below are our own, not the standard distributions).
// Used by tests and benchmarks only.
//
// Every generated ring is simple, has distinct vertices and is counter-clockwise; this is
// verified with exact predicates (Epick) before a polygon is returned (a candidate that
// fails is replaced by a new one drawn from a derived seed, deterministically).

#ifndef PMA_TEST_RANDOM_POLYGONS_H
#define PMA_TEST_RANDOM_POLYGONS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace pma_test {

using Ring = std::vector<CGAL::Epick::Point_2>;

namespace random_detail {

typedef CGAL::Epick K;
typedef K::Point_2 Point;
typedef K::Segment_2 Segment;

const double pi = 3.141592653589793238462643383279502884;

/// Deterministic random numbers: std::mt19937_64 with our own mappings.
class Rng
{
public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  /// uniform in [0, 1), 53 random bits
  double uniform() { return static_cast<double>(g_() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  /// uniform in [0, n), unbiased (rejection)
  std::uint64_t below(std::uint64_t n)
  {
    if(n <= 1) return 0;
    const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                                std::numeric_limits<std::uint64_t>::max() % n;
    std::uint64_t x;
    do { x = g_(); } while(x >= limit);
    return x % n;
  }
  /// uniform in [lo, hi] (inclusive)
  int integer(int lo, int hi)
  {
    return lo + static_cast<int>(below(static_cast<std::uint64_t>(hi - lo) + 1));
  }

private:
  std::mt19937_64 g_;
};

/// A seed for attempt `k` of the generator `salt` from the user's seed.
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t salt, std::uint64_t k)
{
  // splitmix64 finaliser of a combination
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (salt * 1000003ull + k + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

struct Box
{
  double xmin, ymin, xmax, ymax;
};

inline Box box_of(const Point& a, const Point& b)
{
  return Box{(std::min)(a.x(), b.x()), (std::min)(a.y(), b.y()), (std::max)(a.x(), b.x()),
             (std::max)(a.y(), b.y())};
}

/// Edges of rings as (ring, index) pairs; true iff no two edges meet except consecutive
/// edges of one ring at their common vertex (exact). O(m log m + k) with an x-sweep.
inline bool edges_are_disjoint(const std::vector<Ring>& rings)
{
  struct E { int r, i; Box b; };
  std::vector<E> edges;
  for(std::size_t r = 0; r < rings.size(); ++r) {
    const std::size_t n = rings[r].size();
    for(std::size_t i = 0; i < n; ++i)
      edges.push_back(E{static_cast<int>(r), static_cast<int>(i),
                        box_of(rings[r][i], rings[r][(i + 1) % n])});
  }
  std::sort(edges.begin(), edges.end(), [](const E& a, const E& b) { return a.b.xmin < b.b.xmin; });
  for(std::size_t u = 0; u < edges.size(); ++u) {
    const E& A = edges[u];
    const Ring& ra = rings[A.r];
    const int na = static_cast<int>(ra.size());
    const Point& a0 = ra[A.i];
    const Point& a1 = ra[(A.i + 1) % na];
    for(std::size_t v = u + 1; v < edges.size() && edges[v].b.xmin <= A.b.xmax; ++v) {
      const E& B = edges[v];
      if(B.b.ymin > A.b.ymax || B.b.ymax < A.b.ymin) continue;
      const Ring& rb = rings[B.r];
      const int nb = static_cast<int>(rb.size());
      const Point& b0 = rb[B.i];
      const Point& b1 = rb[(B.i + 1) % nb];
      if(A.r == B.r) {
        const bool b_after_a = (B.i == (A.i + 1) % na);
        const bool a_after_b = (A.i == (B.i + 1) % na);
        if(b_after_a || a_after_b) {
          // consecutive edges p->q->s: they meet only at q unless p, q, s fold back
          const Point& p = b_after_a ? a0 : b0;
          const Point& q = b_after_a ? a1 : b1;
          const Point& s = b_after_a ? b1 : a1;
          if(CGAL::collinear(p, q, s) && !CGAL::collinear_are_strictly_ordered_along_line(p, q, s))
            return false;
          continue;
        }
      }
      if(CGAL::do_intersect(Segment(a0, a1), Segment(b0, b1))) return false;
    }
  }
  return true;
}

inline bool vertices_distinct(const std::vector<Ring>& rings)
{
  std::vector<Point> all;
  for(const Ring& r : rings) all.insert(all.end(), r.begin(), r.end());
  std::sort(all.begin(), all.end(), [](const Point& a, const Point& b) {
    return CGAL::compare_xy(a, b) == CGAL::SMALLER;
  });
  for(std::size_t i = 1; i < all.size(); ++i)
    if(all[i] == all[i - 1]) return false;
  return true;
}

/// Exact orientation of a simple ring (COLLINEAR if degenerate).
inline CGAL::Orientation ring_orientation(const Ring& ring)
{
  if(ring.size() < 3) return CGAL::COLLINEAR;
  std::size_t m = 0;
  for(std::size_t i = 1; i < ring.size(); ++i)
    if(CGAL::compare_xy(ring[i], ring[m]) == CGAL::SMALLER) m = i;
  const std::size_t n = ring.size();
  return CGAL::orientation(ring[(m + n - 1) % n], ring[m], ring[(m + 1) % n]);
}

} // namespace random_detail

/// True iff `ring` is a simple polygon (>= 3 distinct vertices, edges meeting only at
/// common vertices of consecutive edges, no zero-area ring). Exact.
inline bool is_simple_polygon(const Ring& ring)
{
  using namespace random_detail;
  if(ring.size() < 3) return false;
  const std::vector<Ring> rings(1, ring);
  return vertices_distinct(rings) && edges_are_disjoint(rings) &&
         ring_orientation(ring) != CGAL::COLLINEAR;
}

/// True iff `rings` is a valid polygon with holes: every ring simple, no two rings meet,
/// every hole strictly inside ring 0, no hole inside another hole. Exact.
inline bool is_valid_polygon_with_holes(const std::vector<Ring>& rings)
{
  using namespace random_detail;
  if(rings.empty()) return false;
  for(const Ring& r : rings)
    if(r.size() < 3 || ring_orientation(r) == CGAL::COLLINEAR) return false;
  if(!vertices_distinct(rings) || !edges_are_disjoint(rings)) return false;
  // rings do not meet, so one vertex decides containment
  std::vector<Box> boxes;
  for(const Ring& r : rings) {
    Box b{r[0].x(), r[0].y(), r[0].x(), r[0].y()};
    for(const Point& p : r) {
      b.xmin = (std::min)(b.xmin, p.x()); b.xmax = (std::max)(b.xmax, p.x());
      b.ymin = (std::min)(b.ymin, p.y()); b.ymax = (std::max)(b.ymax, p.y());
    }
    boxes.push_back(b);
  }
  for(std::size_t h = 1; h < rings.size(); ++h) {
    if(CGAL::bounded_side_2(rings[0].begin(), rings[0].end(), rings[h][0], K()) !=
       CGAL::ON_BOUNDED_SIDE)
      return false;
  }
  // holes not nested: sort by xmin and test only overlapping boxes
  std::vector<std::size_t> order;
  for(std::size_t h = 1; h < rings.size(); ++h) order.push_back(h);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].xmin < boxes[b].xmin; });
  for(std::size_t u = 0; u < order.size(); ++u) {
    const std::size_t a = order[u];
    for(std::size_t v = u + 1; v < order.size() && boxes[order[v]].xmin <= boxes[a].xmax; ++v) {
      const std::size_t b = order[v];
      if(boxes[b].ymin > boxes[a].ymax || boxes[b].ymax < boxes[a].ymin) continue;
      if(CGAL::bounded_side_2(rings[a].begin(), rings[a].end(), rings[b][0], K()) !=
           CGAL::ON_UNBOUNDED_SIDE ||
         CGAL::bounded_side_2(rings[b].begin(), rings[b].end(), rings[a][0], K()) !=
           CGAL::ON_UNBOUNDED_SIDE)
        return false;
    }
  }
  return true;
}

namespace random_detail {

// A star polygon around (cx, cy): angles increasing with every gap < pi, radii in
// [rmin, rmax] * scale. Not checked.
inline Ring star_candidate(Rng& rng, int n, double cx, double cy, double scale, double rmin,
                           double rmax)
{
  const double jitter = (n >= 4) ? 0.8 : 0.4; // gap <= (1 + jitter) 2 pi / n < pi
  const double phase = rng.uniform(0, 2 * pi);
  Ring ring;
  ring.reserve(n);
  for(int i = 0; i < n; ++i) {
    const double t = phase + 2 * pi * (i + jitter * rng.uniform()) / n;
    const double rho = scale * rng.uniform(rmin, rmax);
    ring.push_back(Point(cx + rho * std::cos(t), cy + rho * std::sin(t)));
  }
  return ring;
}

inline void make_ccw(Ring& ring)
{
  if(ring_orientation(ring) == CGAL::CLOCKWISE) std::reverse(ring.begin(), ring.end());
}

} // namespace random_detail

/// A random star-shaped polygon with n >= 3 vertices: random angles (every gap < pi) and
/// radii in [0.2, 1] around the origin. Simple, counter-clockwise.
inline Ring random_star_polygon(std::uint64_t seed, int n)
{
  using namespace random_detail;
  if(n < 3) throw std::invalid_argument("random_star_polygon: n < 3");
  for(std::uint64_t k = 0;; ++k) {
    Rng rng(derive_seed(seed, 1, k));
    Ring ring = star_candidate(rng, n, 0, 0, 1, 0.2, 1.0);
    if(is_simple_polygon(ring) && ring_orientation(ring) == CGAL::COUNTERCLOCKWISE) return ring;
  }
}

/// A random simple polygon with n >= 3 vertices that is in general not star-shaped: n
/// random points in the unit square, joined in nearest-neighbour order from a random
/// start, untangled by 2-opt moves (each strictly shortens the tour) until no two edges
/// cross. Counter-clockwise.
inline Ring random_walk_polygon(std::uint64_t seed, int n)
{
  using namespace random_detail;
  if(n < 3) throw std::invalid_argument("random_walk_polygon: n < 3");
  for(std::uint64_t k = 0;; ++k) {
    Rng rng(derive_seed(seed, 2, k));
    std::vector<Point> pts;
    pts.reserve(n);
    for(int i = 0; i < n; ++i) pts.push_back(Point(rng.uniform(), rng.uniform()));
    // nearest-neighbour tour
    std::vector<int> tour;
    std::vector<char> used(n, 0);
    int cur = static_cast<int>(rng.below(n));
    for(int step = 0; step < n; ++step) {
      tour.push_back(cur);
      used[cur] = 1;
      int best = -1;
      double bd = 0;
      for(int j = 0; j < n; ++j) {
        if(used[j]) continue;
        const double d = CGAL::squared_distance(pts[cur], pts[j]);
        if(best < 0 || d < bd) { best = j; bd = d; }
      }
      cur = best;
    }
    // 2-opt untangling
    bool changed = true;
    int passes = 0;
    while(changed && passes < 10 * n + 100) {
      changed = false;
      ++passes;
      for(int i = 0; i + 2 < n; ++i) {
        for(int j = i + 2; j < n; ++j) {
          if(i == 0 && j == n - 1) continue; // consecutive through the closing edge
          const Point& a = pts[tour[i]];
          const Point& b = pts[tour[i + 1]];
          const Point& c = pts[tour[j]];
          const Point& d = pts[tour[(j + 1) % n]];
          if(CGAL::do_intersect(Segment(a, b), Segment(c, d))) {
            std::reverse(tour.begin() + i + 1, tour.begin() + j + 1);
            changed = true;
          }
        }
      }
    }
    Ring ring;
    for(int i : tour) ring.push_back(pts[i]);
    if(!is_simple_polygon(ring)) continue;
    make_ccw(ring);
    return ring;
  }
}

/// The boundary of a random simply connected polyomino of about `cells` unit squares on the
/// integer grid (random growth from one cell, rejecting cells that would create a hole or
/// make two cells touch only at a corner). Counter-clockwise, starting at the lowest of the
/// leftmost vertices. Without keep_flat_vertices every vertex is a corner; with it, about a
/// quarter of the collinear (180-degree) grid vertices along the boundary are kept.
inline Ring random_rectilinear_polygon(std::uint64_t seed, int cells, bool keep_flat_vertices)
{
  using namespace random_detail;
  if(cells < 1) throw std::invalid_argument("random_rectilinear_polygon: cells < 1");
  Rng rng(derive_seed(seed, 3, 0));
  typedef std::pair<int, int> C;
  std::set<C> filled;
  auto is_filled = [&](int x, int y) { return filled.count(C(x, y)) > 0; };
  filled.insert(C(0, 0));
  std::vector<C> candidates = {C(1, 0), C(-1, 0), C(0, 1), C(0, -1)};
  int xmin = 0, xmax = 0, ymin = 0, ymax = 0;

  // would filling (x, y) make a 2x2 block with only diagonal cells filled?
  auto pinch = [&](int x, int y) {
    for(int dx = -1; dx <= 0; ++dx)
      for(int dy = -1; dy <= 0; ++dy) {
        const int x0 = x + dx, y0 = y + dy;
        const bool a = (x0 == x && y0 == y) || is_filled(x0, y0);
        const bool b = (x0 + 1 == x && y0 == y) || is_filled(x0 + 1, y0);
        const bool c = (x0 == x && y0 + 1 == y) || is_filled(x0, y0 + 1);
        const bool d = (x0 + 1 == x && y0 + 1 == y) || is_filled(x0 + 1, y0 + 1);
        if((a && d && !b && !c) || (b && c && !a && !d)) return true;
      }
    return false;
  };
  // would filling (x, y) enclose an empty cell? (flood fill of the empty cells of the
  // bounding box grown by one, from its corner)
  auto encloses = [&](int x, int y) {
    const int x0 = (std::min)(xmin, x) - 1, x1 = (std::max)(xmax, x) + 1;
    const int y0 = (std::min)(ymin, y) - 1, y1 = (std::max)(ymax, y) + 1;
    const int w = x1 - x0 + 1, h = y1 - y0 + 1;
    std::vector<char> seen(static_cast<std::size_t>(w) * h, 0);
    auto blocked = [&](int cx, int cy) { return (cx == x && cy == y) || is_filled(cx, cy); };
    std::vector<C> stack = {C(x0, y0)};
    seen[0] = 1;
    std::size_t reached = 1;
    while(!stack.empty()) {
      const C c = stack.back();
      stack.pop_back();
      const int nx[4] = {c.first + 1, c.first - 1, c.first, c.first};
      const int ny[4] = {c.second, c.second, c.second + 1, c.second - 1};
      for(int k = 0; k < 4; ++k) {
        if(nx[k] < x0 || nx[k] > x1 || ny[k] < y0 || ny[k] > y1) continue;
        const std::size_t idx = static_cast<std::size_t>(ny[k] - y0) * w + (nx[k] - x0);
        if(seen[idx] || blocked(nx[k], ny[k])) continue;
        seen[idx] = 1;
        ++reached;
        stack.push_back(C(nx[k], ny[k]));
      }
    }
    std::size_t empty = 0;
    for(int cx = x0; cx <= x1; ++cx)
      for(int cy = y0; cy <= y1; ++cy)
        if(!blocked(cx, cy)) ++empty;
    return reached != empty;
  };

  int attempts = 0;
  while(static_cast<int>(filled.size()) < cells && !candidates.empty() &&
        attempts < 50 * cells + 100) {
    ++attempts;
    const std::size_t pick = rng.below(candidates.size());
    const C c = candidates[pick];
    candidates[pick] = candidates.back();
    candidates.pop_back();
    if(is_filled(c.first, c.second)) continue;
    int neighbours = 0;
    const int nx[4] = {c.first + 1, c.first - 1, c.first, c.first};
    const int ny[4] = {c.second, c.second, c.second + 1, c.second - 1};
    for(int k = 0; k < 4; ++k) neighbours += is_filled(nx[k], ny[k]) ? 1 : 0;
    if(pinch(c.first, c.second)) continue;
    if(neighbours >= 2 && encloses(c.first, c.second)) continue;
    filled.insert(c);
    xmin = (std::min)(xmin, c.first); xmax = (std::max)(xmax, c.first);
    ymin = (std::min)(ymin, c.second); ymax = (std::max)(ymax, c.second);
    for(int k = 0; k < 4; ++k)
      if(!is_filled(nx[k], ny[k])) candidates.push_back(C(nx[k], ny[k]));
  }

  // directed unit boundary edges, interior on the left; each boundary grid point has
  // exactly one outgoing edge (no pinches)
  std::map<C, C> out;
  for(const C& c : filled) {
    const int x = c.first, y = c.second;
    if(!is_filled(x, y - 1)) out[C(x, y)] = C(x + 1, y);
    if(!is_filled(x + 1, y)) out[C(x + 1, y)] = C(x + 1, y + 1);
    if(!is_filled(x, y + 1)) out[C(x + 1, y + 1)] = C(x, y + 1);
    if(!is_filled(x - 1, y)) out[C(x, y + 1)] = C(x, y);
  }
  const C start = out.begin()->first; // lowest of the leftmost points: a corner
  std::vector<C> loop;
  C p = start;
  do {
    loop.push_back(p);
    p = out.at(p);
  } while(p != start && loop.size() <= out.size());
  if(loop.size() != out.size())
    throw std::logic_error("random_rectilinear_polygon: boundary is not one loop");

  Ring ring;
  const std::size_t m = loop.size();
  for(std::size_t i = 0; i < m; ++i) {
    const C& a = loop[(i + m - 1) % m];
    const C& b = loop[i];
    const C& c = loop[(i + 1) % m];
    const bool straight = (b.first - a.first == c.first - b.first) &&
                          (b.second - a.second == c.second - b.second);
    if(straight && !(keep_flat_vertices && rng.below(4) == 0)) continue;
    ring.push_back(Point(b.first, b.second));
  }
  if(!is_simple_polygon(ring) || ring_orientation(ring) != CGAL::COUNTERCLOCKWISE)
    throw std::logic_error("random_rectilinear_polygon: generated polygon is not simple");
  return ring;
}

namespace random_detail {

/// The cells 0 .. g*g - 1 of a g x g grid, the first `count` of them drawn
/// at random (a partial Fisher-Yates shuffle).
inline std::vector<int> random_cells(Rng& rng, int g, int count)
{
  std::vector<int> cells(static_cast<std::size_t>(g) * g);
  for(std::size_t i = 0; i < cells.size(); ++i) cells[i] = static_cast<int>(i);
  for(int h = 0; h < count; ++h) {
    const std::size_t j = h + rng.below(cells.size() - h);
    std::swap(cells[h], cells[j]);
  }
  return cells;
}

/// Whether the outer ring is counter-clockwise, the holes clockwise, and
/// the polygon valid (exactly).
inline bool oriented_and_valid(const std::vector<Ring>& rings)
{
  if(ring_orientation(rings[0]) != CGAL::COUNTERCLOCKWISE) return false;
  for(std::size_t h = 1; h < rings.size(); ++h)
    if(ring_orientation(rings[h]) != CGAL::CLOCKWISE) return false;
  return is_valid_polygon_with_holes(rings);
}

} // namespace random_detail

/// An outer ring (a rectangle [0, w] x [0, h] with w, h in [1, 2] if outer_vertices == 4,
/// else a star polygon of outer_vertices vertices with radii in [0.7, 1]) and `holes`
/// small star holes (3 to 8 vertices each) in distinct cells of a grid inside the
/// largest axis-parallel square that fits, hence pairwise disjoint and strictly inside.
/// Outer ring counter-clockwise, holes clockwise. Validity is checked exactly.
inline std::vector<Ring> random_polygon_with_holes(std::uint64_t seed, int outer_vertices,
                                                   int holes)
{
  using namespace random_detail;
  if(outer_vertices < 3) throw std::invalid_argument("random_polygon_with_holes: outer < 3");
  if(holes < 0) throw std::invalid_argument("random_polygon_with_holes: holes < 0");
  for(std::uint64_t k = 0;; ++k) {
    Rng rng(derive_seed(seed, 4, k));
    std::vector<Ring> rings;
    double cx, cy, half; // the square [cx - half, cx + half]^2 lies inside the outer ring
    if(outer_vertices == 4) {
      const double w = rng.uniform(1, 2), h = rng.uniform(1, 2);
      rings.push_back(Ring{Point(0, 0), Point(w, 0), Point(w, h), Point(0, h)});
      cx = w / 2;
      cy = h / 2;
      half = 0.45 * (std::min)(w, h);
    } else {
      rings.push_back(star_candidate(rng, outer_vertices, 0, 0, 1, 0.7, 1.0));
      // the star polygon contains the disk around the origin of radius min distance to an
      // edge (it is star-shaped from the origin)
      const Ring& o = rings[0];
      double d = std::numeric_limits<double>::max();
      for(std::size_t i = 0; i < o.size(); ++i)
        d = (std::min)(d, std::sqrt(CGAL::to_double(
                            CGAL::squared_distance(Point(0, 0), Segment(o[i], o[(i + 1) % o.size()])))));
      cx = 0;
      cy = 0;
      half = 0.9 * d / std::sqrt(2.0);
    }
    const int g = (holes > 0) ? static_cast<int>(std::ceil(std::sqrt(static_cast<double>(holes)))) : 1;
    const double cell = 2 * half / g;
    const std::vector<int> cellsv = random_cells(rng, g, holes);
    for(int h = 0; h < holes; ++h) {
      const int gi = cellsv[h] % g, gj = cellsv[h] / g;
      const double rho = cell * rng.uniform(0.2, 0.4);
      const double slack = 0.5 * cell - rho - 0.05 * cell;
      const double hx = cx - half + (gi + 0.5) * cell + rng.uniform(-slack, slack);
      const double hy = cy - half + (gj + 0.5) * cell + rng.uniform(-slack, slack);
      Ring hole = star_candidate(rng, rng.integer(3, 8), hx, hy, rho, 0.5, 1.0);
      std::reverse(hole.begin(), hole.end()); // clockwise
      rings.push_back(hole);
    }
    if(oriented_and_valid(rings)) return rings;
  }
}

/// A map-like polygon: a rectangle with coordinates on a grid of 10^-5 (as
/// degrees near 30 E, 64.7 N, written with 5 decimals), and `holes` lakes
/// in distinct cells of a square grid inside it, as `countries-land-10m`
/// has by the hundred thousand: right triangles with axis-parallel legs (the
/// right angle at any of the four corners) and axis-parallel rectangles,
/// one in three of those with a vertex in the middle of an edge.  Lakes in
/// one column or row of cells share their x or y coordinates half of the
/// time.  Their medial disks have many coordinates halfway between two
/// doubles (the midpoint of two input coordinates).  Outer ring
/// counter-clockwise, holes clockwise; validity is checked exactly.
inline std::vector<Ring> random_lakes_polygon(std::uint64_t seed, int holes)
{
  using namespace random_detail;
  if(holes < 1) throw std::invalid_argument("random_lakes_polygon: holes < 1");
  const int cell = 1000;   // grid units of 10^-5
  auto X = [](int u) { return 30.0 + u * 1e-5; };
  auto Y = [](int u) { return 64.7 + u * 1e-5; };
  for(std::uint64_t k = 0;; ++k) {
    Rng rng(derive_seed(seed, 9, k));
    const int g = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(holes))));
    const int margin = rng.integer(50, 400);
    std::vector<Ring> rings;
    rings.push_back(Ring{Point(X(-margin), Y(-margin)), Point(X(g * cell + margin), Y(-margin)),
                         Point(X(g * cell + margin), Y(g * cell + margin)), Point(X(-margin), Y(g * cell + margin))});
    // the sides of the lakes in each column and row, shared or not
    std::vector<std::pair<int, int> > column(g), row(g);
    for(int i = 0; i < g; ++i) {
      column[i] = {rng.integer(100, 400), rng.integer(600, 900)};
      row[i] = {rng.integer(100, 400), rng.integer(600, 900)};
    }
    const std::vector<int> cells = random_cells(rng, g, holes);
    for(int h = 0; h < holes; ++h) {
      const int gi = cells[h] % g, gj = cells[h] / g;
      const bool share_x = rng.integer(0, 1) == 1, share_y = rng.integer(0, 1) == 1;
      const int x0 = gi * cell + (share_x ? column[gi].first : rng.integer(100, 400));
      const int x1 = gi * cell + (share_x ? column[gi].second : rng.integer(600, 900));
      const int y0 = gj * cell + (share_y ? row[gj].first : rng.integer(100, 400));
      const int y1 = gj * cell + (share_y ? row[gj].second : rng.integer(600, 900));
      // the corners, counter-clockwise
      std::vector<std::pair<int, int> > c = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
      const int kind = rng.integer(0, 5);
      if(kind < 4) {
        c.erase(c.begin() + kind);   // a right triangle
      } else if(rng.integer(0, 2) == 0) {
        const int side = rng.integer(0, 3);   // a flat vertex on that side
        const auto a = c[side], b = c[(side + 1) % 4];
        c.insert(c.begin() + side + 1, {(a.first + b.first) / 2 + (a.first == b.first ? 0 : rng.integer(-50, 50)),
                                        (a.second + b.second) / 2 + (a.second == b.second ? 0 : rng.integer(-50, 50))});
      }
      Ring hole;
      for(auto it = c.rbegin(); it != c.rend(); ++it) hole.push_back(Point(X(it->first), Y(it->second)));
      rings.push_back(hole);
    }
    if(oriented_and_valid(rings)) return rings;
  }
}

} // namespace pma_test

#endif // PMA_TEST_RANDOM_POLYGONS_H
