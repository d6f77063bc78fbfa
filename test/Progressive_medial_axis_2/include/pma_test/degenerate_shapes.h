// Test-only generators of DEGENERATE polygons with holes: exact ties on purpose (integer
// grids, repeated coordinates, exact mirror symmetry, exactly cocircular points), for
// tests and benchmarks. Deterministic: the same arguments give the same polygon on every
// platform, except where a function says it calls std::cos / std::sin (the C library's
// last bit may differ between platforms).
//
// Every function returns rings as random_polygons.h does: ring 0 the outer ring,
// counter-clockwise, then the holes, clockwise, the closing point not repeated. Every
// result is checked before it is returned (require_valid below): rings simple, no vertex
// repeated anywhere, no zero-length edge, no spike, no two rings touching or crossing (not
// even at one vertex), every hole strictly inside the outer ring and outside the others.
// Flat vertices (angle pi, collinear with both neighbours) are allowed and some kinds have
// them on purpose. Write a result with pma_tool::write_wkt_polygon (IO/polygon_io.h).

#ifndef PMA_TEST_DEGENERATE_SHAPES_H
#define PMA_TEST_DEGENERATE_SHAPES_H

#include <pma_test/random_polygons.h>

#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numeric> // std::gcd
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pma_test {

/// The first reason why `rings` is not a valid polygon with holes in the strict sense of
/// this header, or an empty string if it is valid. Two independent exact checks: the
/// library's own validator (CGAL::Progressive_medial_axes::validate_polygon_rings, what the library accepts
/// today) and pma_test::is_valid_polygon_with_holes, plus the orientations (outer ring
/// counter-clockwise, holes clockwise), which neither of them requires.
inline std::string validity_problem(const std::vector<Ring>& rings)
{
  using namespace random_detail;
  if(rings.empty()) return "no ring";
  for(const Ring& r : rings)
    for(const Point& p : r)
      if(!std::isfinite(p.x()) || !std::isfinite(p.y())) return "non-finite coordinate";
  try {
    CGAL::Progressive_medial_axes::validate_polygon_rings<K>(rings);
  } catch(const std::exception& e) {
    return std::string("library validator: ") + e.what();
  }
  if(!is_valid_polygon_with_holes(rings)) return "is_valid_polygon_with_holes says invalid";
  if(ring_orientation(rings[0]) != CGAL::COUNTERCLOCKWISE) return "outer ring not counter-clockwise";
  for(std::size_t h = 1; h < rings.size(); ++h)
    if(ring_orientation(rings[h]) != CGAL::CLOCKWISE)
      return "hole " + std::to_string(h) + " not clockwise";
  return std::string();
}

/// Throws std::logic_error naming `what` unless validity_problem(rings) is empty.
inline void require_valid(const std::vector<Ring>& rings, const char* what)
{
  const std::string problem = validity_problem(rings);
  if(!problem.empty()) throw std::logic_error(std::string(what) + ": invalid output: " + problem);
}

/// The number of vertices of all rings.
inline std::size_t vertex_count(const std::vector<Ring>& rings)
{
  std::size_t n = 0;
  for(const Ring& r : rings) n += r.size();
  return n;
}

namespace degenerate_detail {

using random_detail::Point;
using random_detail::Rng;
using random_detail::derive_seed;
using random_detail::pi;

/// -0.0 becomes +0.0, so that written files and mirror images show no "-0".
inline double clean_zero(double x) { return x + 0.0; }

/// `x` written with `decimals` digits after the point and read back (the double nearest
/// to that decimal number), as a file written by another program gives it; `x` itself if
/// decimals < 0. Locale-independent.
inline double round_to_decimals(double x, int decimals)
{
  if(decimals < 0) return clean_zero(x);
  if(decimals > 30 || !(std::abs(x) < 1e300))
    throw std::invalid_argument("round_to_decimals: too many decimals or too large");
  char buf[400];
  double y = 0;
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  const std::to_chars_result w =
    std::to_chars(buf, buf + sizeof(buf), x, std::chars_format::fixed, decimals);
  std::from_chars(buf, w.ptr, y);
#else
  // depends on the decimal point of the current C locale
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, x);
  y = std::strtod(buf, nullptr);
#endif
  return clean_zero(y);
}

inline Point rounded(double x, double y, int decimals)
{
  return Point(round_to_decimals(x, decimals), round_to_decimals(y, decimals));
}

// ------------------------------------------------------------------ cell grids

struct Cell
{
  int x, y;
};

/// An n x n grid of unit cells [x, x+1] x [y, y+1], 0 <= x, y < n, surrounded by a frame
/// of cells that are always empty (so that the empty cells outside the shape form one
/// 4-connected region around it).
class Cell_grid
{
public:
  explicit Cell_grid(int n) : n_(n), w_(n + 2), cells_(static_cast<std::size_t>(n + 2) * (n + 2), 0) {}
  int size() const { return n_; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < n_ && y < n_; }
  bool filled(int x, int y) const { return inside(x, y) && cells_[index(x, y)] != 0; }
  void set(int x, int y, bool f) { cells_[index(x, y)] = f ? 1 : 0; }
  std::size_t index(int x, int y) const
  {
    return static_cast<std::size_t>(y + 1) * w_ + static_cast<std::size_t>(x + 1);
  }
  std::size_t cell_count() const { return cells_.size(); }
  Cell cell_at(std::size_t i) const
  {
    return Cell{static_cast<int>(i % w_) - 1, static_cast<int>(i / w_) - 1};
  }

private:
  int n_, w_;
  std::vector<char> cells_;
};

/// The 4-connected components of the cells (frame included) whose filled state is
/// `filled`: label per grid index (-1 for the other cells), components in scan order.
inline std::vector<std::vector<std::size_t> > cell_components(const Cell_grid& g, bool filled,
                                                               std::vector<int>& label)
{
  const int n = g.size();
  label.assign(g.cell_count(), -1);
  std::vector<std::vector<std::size_t> > comps;
  for(std::size_t i = 0; i < g.cell_count(); ++i) {
    const Cell c0 = g.cell_at(i);
    if(label[i] >= 0 || g.filled(c0.x, c0.y) != filled) continue;
    const int id = static_cast<int>(comps.size());
    comps.emplace_back();
    std::vector<std::size_t> stack(1, i);
    label[i] = id;
    while(!stack.empty()) {
      const std::size_t j = stack.back();
      stack.pop_back();
      comps.back().push_back(j);
      const Cell c = g.cell_at(j);
      const int nx[4] = {c.x + 1, c.x - 1, c.x, c.x};
      const int ny[4] = {c.y, c.y, c.y + 1, c.y - 1};
      for(int k = 0; k < 4; ++k) {
        if(nx[k] < -1 || ny[k] < -1 || nx[k] > n || ny[k] > n) continue;
        const std::size_t q = g.index(nx[k], ny[k]);
        if(label[q] >= 0 || g.filled(nx[k], ny[k]) != filled) continue;
        label[q] = id;
        stack.push_back(q);
      }
    }
  }
  return comps;
}

/// Fills cells until no grid point has its four cells filled in a diagonal pattern (two
/// filled cells touching only at that point: a pinch vertex, where the boundary would
/// touch itself). Each pinch is resolved by filling one of the two empty cells, chosen at
/// random; filling can create a new pinch elsewhere, hence the repetition (it ends since
/// cells are only ever filled). The frame is never filled: a diagonal pair of filled cells
/// lies in the grid, and so do the two cells completing it.
inline void resolve_pinches(Cell_grid& g, Rng& rng)
{
  const int n = g.size();
  for(bool changed = true; changed;) {
    changed = false;
    for(int x = 0; x <= n; ++x)
      for(int y = 0; y <= n; ++y) {
        const bool a = g.filled(x - 1, y - 1), b = g.filled(x, y - 1);
        const bool c = g.filled(x - 1, y), d = g.filled(x, y);
        if(a && d && !b && !c) {
          if(rng.below(2) == 0) g.set(x, y - 1, true); else g.set(x - 1, y, true);
          changed = true;
        } else if(b && c && !a && !d) {
          if(rng.below(2) == 0) g.set(x - 1, y - 1, true); else g.set(x, y, true);
          changed = true;
        }
      }
  }
}

/// Resolves the pinches, keeps only the largest 4-connected component of filled cells,
/// then fills every enclosed empty region (hole) but `keep` of them, chosen at random
/// (keep < 0: all are kept). Neither removing a whole other component nor filling a whole
/// hole creates a pinch: a pinch would need the two diagonal cells of the other state to
/// be 4-adjacent, through the 2x2 block, to the cells that changed, hence in their
/// component.
inline void clean_up_cells(Cell_grid& g, Rng& rng, int keep)
{
  resolve_pinches(g, rng);
  std::vector<int> label;
  std::vector<std::vector<std::size_t> > comps = cell_components(g, true, label);
  std::size_t best = 0;
  for(std::size_t k = 1; k < comps.size(); ++k)
    if(comps[k].size() > comps[best].size()) best = k;
  for(std::size_t k = 0; k < comps.size(); ++k)
    if(k != best)
      for(std::size_t i : comps[k]) {
        const Cell c = g.cell_at(i);
        g.set(c.x, c.y, false);
      }
  // empty components: the first one in scan order contains the frame's corner, the others
  // are holes
  std::vector<std::vector<std::size_t> > empty = cell_components(g, false, label);
  std::vector<std::size_t> holes;
  for(std::size_t k = 1; k < empty.size(); ++k) holes.push_back(k);
  std::size_t kept = holes.size();
  if(keep >= 0 && static_cast<std::size_t>(keep) < holes.size()) {
    for(std::size_t h = 0; h < static_cast<std::size_t>(keep); ++h) // partial Fisher-Yates
      std::swap(holes[h], holes[h + rng.below(holes.size() - h)]);
    kept = static_cast<std::size_t>(keep);
  }
  for(std::size_t h = kept; h < holes.size(); ++h)
    for(std::size_t i : empty[holes[h]]) {
      const Cell c = g.cell_at(i);
      g.set(c.x, c.y, true);
    }
}

/// The number of holes (enclosed empty regions) of the cells.
inline std::size_t hole_count(const Cell_grid& g)
{
  std::vector<int> label;
  return cell_components(g, false, label).size() - 1;
}

/// Empties random rectangles of 1 to 3 cells a side whose cells and eight neighbours are
/// all filled, until the cells have `holes` holes (or too many attempts failed). A
/// rectangle with a filled margin (corners included) is a new hole touching nothing, and
/// the margin keeps the filled cells connected.
inline void punch_holes(Cell_grid& g, Rng& rng, int holes)
{
  const int n = g.size();
  int have = static_cast<int>(hole_count(g));
  for(int attempt = 0; have < holes && attempt < 200 * holes + 1000; ++attempt) {
    const int w = rng.integer(1, 3), h = rng.integer(1, 3);
    if(n < w + 2 || n < h + 2) continue;
    const int x0 = rng.integer(1, n - w - 1), y0 = rng.integer(1, n - h - 1);
    bool ok = true;
    for(int x = x0 - 1; x <= x0 + w && ok; ++x)
      for(int y = y0 - 1; y <= y0 + h && ok; ++y) ok = g.filled(x, y);
    if(!ok) continue;
    for(int x = x0; x < x0 + w; ++x)
      for(int y = y0; y < y0 + h; ++y) g.set(x, y, false);
    ++have;
  }
}

/// The boundary loops of the filled cells (which must have no pinch), interior on the
/// left: the outer loop first (counter-clockwise), then the holes (clockwise). Each loop
/// starts at its lexicographically smallest point, a corner. Coordinates multiplied by
/// `scale`. Without keep_flat_vertices only the corners are kept.
inline std::vector<Ring> trace_cells(const Cell_grid& g, bool keep_flat_vertices, int scale)
{
  const int n = g.size();
  const int m = n + 1; // grid points (x, y), 0 <= x, y <= n, index x * m + y
  std::vector<int> next(static_cast<std::size_t>(m) * m, -1);
  auto id = [m](int x, int y) { return x * m + y; };
  auto link = [&](int from, int to) {
    if(next[from] >= 0) throw std::logic_error("trace_cells: pinch vertex");
    next[from] = to;
  };
  for(int x = 0; x < n; ++x)
    for(int y = 0; y < n; ++y) {
      if(!g.filled(x, y)) continue;
      if(!g.filled(x, y - 1)) link(id(x, y), id(x + 1, y));
      if(!g.filled(x + 1, y)) link(id(x + 1, y), id(x + 1, y + 1));
      if(!g.filled(x, y + 1)) link(id(x + 1, y + 1), id(x, y + 1));
      if(!g.filled(x - 1, y)) link(id(x, y + 1), id(x, y));
    }
  std::vector<char> seen(next.size(), 0);
  std::vector<Ring> rings;
  // scanning x-major finds the leftmost-lowest point of the shape first: it is on the outer
  // loop, since everything to its left is outside
  for(int start = 0; start < static_cast<int>(next.size()); ++start) {
    if(next[start] < 0 || seen[start]) continue;
    std::vector<int> loop;
    for(int v = start; !seen[v]; v = next[v]) {
      seen[v] = 1;
      loop.push_back(v);
    }
    Ring ring;
    const std::size_t k = loop.size();
    for(std::size_t i = 0; i < k; ++i) {
      const int a = loop[(i + k - 1) % k], b = loop[i], c = loop[(i + 1) % k];
      if(!keep_flat_vertices && b - a == c - b) continue; // straight on: a flat vertex
      ring.push_back(Point(static_cast<double>(b / m) * scale, static_cast<double>(b % m) * scale));
    }
    rings.push_back(ring);
  }
  return rings;
}

/// A random shape on the n x n grid: a smoothed random field minus a radial fall-off,
/// thresholded so that a fraction `fill` of the cells is set (see Grid_cell_options).
inline void random_cells(Cell_grid& g, Rng& rng, int feature, double fill, double falloff)
{
  const int n = g.size();
  const int f = (std::max)(feature, 0);
  const int w = n + 2 * f;
  std::vector<double> noise(static_cast<std::size_t>(w) * w);
  for(double& v : noise) v = rng.uniform();
  // box filter of (2f+1)^2 cells, separable: rows then columns, sums in a fixed order
  std::vector<double> rows(static_cast<std::size_t>(n) * w, 0.0);
  for(int y = 0; y < w; ++y)
    for(int x = 0; x < n; ++x) {
      double s = 0;
      for(int k = 0; k <= 2 * f; ++k) s += noise[static_cast<std::size_t>(y) * w + x + k];
      rows[static_cast<std::size_t>(y) * n + x] = s;
    }
  const double side = 2 * f + 1;
  const double mean = 0.5 * side * side, sd = side * std::sqrt(1.0 / 12.0);
  std::vector<double> score(static_cast<std::size_t>(n) * n);
  for(int x = 0; x < n; ++x)
    for(int y = 0; y < n; ++y) {
      double s = 0;
      for(int k = 0; k <= 2 * f; ++k) s += rows[static_cast<std::size_t>(y + k) * n + x];
      // the fall-off makes one blob in the middle of the grid rather than a shape cut off
      // by the grid's square
      const double dx = (x + 0.5) / n - 0.5, dy = (y + 0.5) / n - 0.5;
      score[static_cast<std::size_t>(y) * n + x] = (s - mean) / sd - falloff * (dx * dx + dy * dy);
    }
  std::vector<double> sorted = score;
  const std::size_t cut = static_cast<std::size_t>(
    std::floor((1.0 - (std::min)((std::max)(fill, 0.0), 1.0)) * static_cast<double>(sorted.size())));
  std::nth_element(sorted.begin(), sorted.begin() + (std::min)(cut, sorted.size() - 1), sorted.end());
  const double threshold = sorted[(std::min)(cut, sorted.size() - 1)];
  for(int x = 0; x < n; ++x)
    for(int y = 0; y < n; ++y) g.set(x, y, score[static_cast<std::size_t>(y) * n + x] >= threshold);
  g.set(n / 2, n / 2, true); // never empty
}

// ------------------------------------------------------------------ exact unit circle

/// (cos, sin) of 2 pi num / den, exactly mirror-symmetric: the angle is reduced to
/// [0, pi/4] by the reflections of the square, so that the points of a regular polygon
/// that are mirror images (across the axes and the diagonals) have exactly equal or
/// opposite coordinates. Exact at multiples of pi/4 and pi/6 (sin 30 degrees = 0.5).
/// Calls std::cos / std::sin (last bit platform-dependent) for the other angles.
inline std::pair<double, double> unit_point(std::int64_t num, std::int64_t den)
{
  num %= den;
  if(num < 0) num += den;
  // f = num / den in [0, 1) turns; work in multiples of 1 / (8 den)
  std::int64_t t = 8 * num; // f = t / (8 den)
  const std::int64_t d8 = 8 * den;
  bool negate_y = false, negate_x = false, swap_xy = false;
  if(2 * t > d8) { t = d8 - t; negate_y = true; }     // f -> 1 - f
  if(4 * t > d8) { t = d8 / 2 - t; negate_x = true; } // f -> 1/2 - f
  if(8 * t > d8) { t = d8 / 4 - t; swap_xy = true; }  // f -> 1/4 - f
  double c, s;
  if(t == 0) { c = 1; s = 0; }
  else if(8 * t == d8) { c = s = std::sqrt(0.5); }          // pi/4
  else if(12 * t == d8) { c = std::sqrt(0.75); s = 0.5; }   // pi/6
  else {
    const std::int64_t g = std::gcd(t, d8);
    const double angle = 2 * pi * static_cast<double>(t / g) / static_cast<double>(d8 / g);
    c = std::cos(angle);
    s = std::sin(angle);
  }
  if(swap_xy) std::swap(c, s);
  if(negate_x) c = -c;
  if(negate_y) s = -s;
  return std::make_pair(clean_zero(c), clean_zero(s));
}

/// A regular polygon with m vertices, counter-clockwise from angle 0, centre (cx, cy),
/// circumradius r, coordinates rounded to `decimals` (exact mirror images before rounding
/// if the centre is symmetric too, see unit_point; rounding is symmetric).
inline Ring regular_ring(int m, double cx, double cy, double r, int decimals)
{
  Ring ring;
  ring.reserve(m);
  for(int i = 0; i < m; ++i) {
    const std::pair<double, double> u = unit_point(i, m);
    ring.push_back(rounded(cx + r * u.first, cy + r * u.second, decimals));
  }
  return ring;
}

// ------------------------------------------------------------------ Koch snowflake

/// A Koch snowflake in the integer coordinates (a, b) of the triangular lattice a e1 + b e2,
/// e1 = (1, 0), e2 = (1/2, sqrt(3)/2): the counter-clockwise triangle (c + s (u - c)) for the
/// corners u = (0, 0), (side, 0), (0, side) scaled by s = 1 / shrink around c = (cen, cen),
/// with order - 1 subdivisions, bumps outwards. All coordinates stay integers because the
/// triangle's side is a multiple of 3^(order - 1).
inline std::vector<std::pair<std::int64_t, std::int64_t> >
koch_lattice(int order, std::int64_t side, std::int64_t cen, std::int64_t shrink)
{
  typedef std::pair<std::int64_t, std::int64_t> L;
  auto corner = [&](std::int64_t a, std::int64_t b) {
    return L(cen + (a - cen) / shrink, cen + (b - cen) / shrink);
  };
  std::vector<L> ring = {corner(0, 0), corner(side, 0), corner(0, side)};
  for(int k = 1; k < order; ++k) {
    std::vector<L> finer;
    finer.reserve(4 * ring.size());
    for(std::size_t i = 0; i < ring.size(); ++i) {
      const L p = ring[i], q = ring[(i + 1) % ring.size()];
      const std::int64_t da = (q.first - p.first) / 3, db = (q.second - p.second) / 3;
      const L a(p.first + da, p.second + db);
      // outwards is to the right of a counter-clockwise ring: d turned by -60 degrees,
      // which maps e1 -> e1 - e2 and e2 -> e1, i.e. (da, db) -> (da + db, -da)
      const L apex(a.first + da + db, a.second - da);
      finer.push_back(p);
      finer.push_back(a);
      finer.push_back(apex);
      finer.push_back(L(p.first + 2 * da, p.second + 2 * db));
    }
    ring.swap(finer);
  }
  return ring;
}

// ------------------------------------------------------------------ concyclic points

struct Gaussian
{
  std::int64_t re, im;
};

inline Gaussian operator*(const Gaussian& a, const Gaussian& b)
{
  return Gaussian{a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}

/// The primes = 1 mod 4 used for circle radii, with a^2 + b^2 = p. Their product is below
/// 2^26, so that the cross products of the tests below (at most 8 R^2) fit in 64 bits.
inline const std::vector<std::pair<std::int64_t, Gaussian> >& circle_primes()
{
  static const std::vector<std::pair<std::int64_t, Gaussian> > primes = {
    {5, {2, 1}}, {13, {3, 2}}, {17, {4, 1}}, {29, {5, 2}}, {37, {6, 1}}, {41, {5, 4}}};
  return primes;
}

/// All integer points on the circle of radius R = p_first ... p_(first+count-1), primes of
/// circle_primes() (from the first: R = 5, 65, 1105, 32045, ...): 4 * 3^count points,
/// exactly concyclic. With p = w conj(w), the Gaussian integers z with |z|^2 = R^2 are the
/// unit multiples of the products of one of w^2, w conj(w) = p, conj(w)^2 per prime. Sorted
/// counter-clockwise from angle 0 (exact comparisons in 64-bit integers).
inline std::vector<Gaussian> circle_lattice_points(int first, int count, std::int64_t& radius)
{
  std::vector<Gaussian> points = {Gaussian{1, 0}};
  radius = 1;
  for(int i = first; i < first + count; ++i) {
    const std::int64_t p = circle_primes()[i].first;
    const Gaussian w = circle_primes()[i].second, wc{w.re, -w.im};
    const Gaussian factors[3] = {w * w, Gaussian{p, 0}, wc * wc};
    std::vector<Gaussian> more;
    for(const Gaussian& z : points)
      for(const Gaussian& f : factors) more.push_back(z * f);
    points.swap(more);
    radius *= p;
  }
  std::vector<Gaussian> all;
  for(const Gaussian& z : points) {
    all.push_back(z);
    all.push_back(Gaussian{-z.im, z.re});
    all.push_back(Gaussian{-z.re, -z.im});
    all.push_back(Gaussian{z.im, -z.re});
  }
  auto half = [](const Gaussian& z) { return (z.im > 0 || (z.im == 0 && z.re > 0)) ? 0 : 1; };
  std::sort(all.begin(), all.end(), [&](const Gaussian& a, const Gaussian& b) {
    if(half(a) != half(b)) return half(a) < half(b);
    return a.re * b.im - a.im * b.re > 0;
  });
  return all;
}

/// Is z strictly inside the angle from a to b (counter-clockwise, less than pi)?
inline bool strictly_between(const Gaussian& a, const Gaussian& z, const Gaussian& b)
{
  return a.re * z.im - a.im * z.re > 0 && z.re * b.im - z.im * b.re > 0;
}

} // namespace degenerate_detail

// ====================================================================== generators

/// Options of grid_cell_polygon() and grid_cell_polygon_45().
struct Grid_cell_options
{
  /// Radius, in cells, of the box filter that smooths the random field: larger gives a
  /// rounder shape with fewer vertices and fewer natural holes.
  int feature = 1;
  /// Fraction of the n x n cells set before the clean-up (pinches, components, holes).
  double fill = 0.5;
  /// Radial fall-off: the field is lowered by falloff * d^2 standard deviations at the
  /// distance d from the grid's centre, in grid widths (falloff / 4 at the middle of a
  /// side). 0 gives a ragged, percolation-like shape over the whole grid, 12 a round blob
  /// in its middle.
  double falloff = 12;
  /// With want_holes: the number of holes wanted; extra natural holes are filled, missing
  /// ones are punched (1x1 to 3x3 cells, as room allows). -1: the natural holes (at
  /// least one).
  int holes = -1;
  /// Keep the collinear grid vertices along straight runs of the boundary (every unit
  /// edge is then an edge); grid_cell_polygon_45() ignores it.
  bool keep_flat_vertices = false;
  /// Integer factor applied to the coordinates; grid_cell_polygon_45() ignores it.
  int scale = 1;
};

/// A union of unit cells of the n x n integer grid [0, n]^2 (coordinates times
/// options.scale), connected, as a polygon whose rings follow the cell boundaries. The
/// cells come from a random field (options.feature, options.fill); two cells touching only
/// at a corner, a pinch vertex, get one of the two other cells of that corner added; only
/// the largest 4-connected component is kept. Without want_holes every enclosed empty
/// region is filled; with it the polygon has holes (options.holes). Exact ties everywhere:
/// integer coordinates, repeated x and y values, equal edge lengths, axis-parallel edges.
inline std::vector<Ring> grid_cell_polygon(std::uint64_t seed, int n, bool want_holes,
                                           const Grid_cell_options& options = Grid_cell_options())
{
  using namespace degenerate_detail;
  if(n < 1) throw std::invalid_argument("grid_cell_polygon: n < 1");
  if(options.scale < 1) throw std::invalid_argument("grid_cell_polygon: scale < 1");
  Rng rng(derive_seed(seed, 101, 0));
  Cell_grid g(n);
  random_cells(g, rng, options.feature, options.fill, options.falloff);
  const int keep = want_holes ? options.holes : 0;
  clean_up_cells(g, rng, keep);
  if(want_holes) punch_holes(g, rng, options.holes >= 0 ? options.holes : 1);
  std::vector<Ring> rings = trace_cells(g, options.keep_flat_vertices, options.scale);
  require_valid(rings, "grid_cell_polygon");
  return rings;
}

/// grid_cell_polygon(seed, n, true, options) scaled by 4 (flat vertices dropped) with every
/// corner, convex and reflex, cut at 45 degrees: the corner p is replaced by the two points
/// at distance 1 from it along its two edges. Integer coordinates. Still valid: grid
/// points of different corners are at least 4 apart in x or in y, and an edge that comes
/// within distance 1 of a corner p of another ring or of a non-adjacent edge would have to
/// pass through p itself.
inline std::vector<Ring> grid_cell_polygon_45(std::uint64_t seed, int n,
                                              const Grid_cell_options& options = Grid_cell_options())
{
  using namespace degenerate_detail;
  Grid_cell_options o = options;
  o.keep_flat_vertices = false;
  o.scale = 4;
  const std::vector<Ring> grid = grid_cell_polygon(seed, n, true, o);
  std::vector<Ring> rings;
  for(const Ring& r : grid) {
    Ring cut;
    const std::size_t k = r.size();
    for(std::size_t i = 0; i < k; ++i) {
      const Point& a = r[(i + k - 1) % k];
      const Point& p = r[i];
      const Point& b = r[(i + 1) % k];
      auto sign = [](double v) { return static_cast<double>((v > 0) - (v < 0)); };
      // unit directions of the incoming and outgoing axis-parallel edges
      const double ix = sign(p.x() - a.x()), iy = sign(p.y() - a.y());
      const double ox = sign(b.x() - p.x()), oy = sign(b.y() - p.y());
      cut.push_back(Point(p.x() - ix, p.y() - iy));
      cut.push_back(Point(p.x() + ox, p.y() + oy));
    }
    rings.push_back(cut);
  }
  require_valid(rings, "grid_cell_polygon_45");
  return rings;
}

/// The closed Hilbert curve of the given order (1 to 12) as a simple polygon: the Hilbert
/// path through the 2^order x 2^order grid points (0..2^order-1)^2 with unit steps, from
/// (0, 0) to (2^order - 1, 0) (the standard d2xy construction), closed by the row of points
/// (2^order - 1, -1), ..., (0, -1) below it, then shifted up by 1 so that all coordinates
/// are non-negative integers. 4^order + 2^order vertices (16,512 at order 7), most of them
/// flat; without keep_flat_vertices only the corners are kept. Every grid point of the box
/// is on the boundary, so the interior is a union of unit cells without a 2 x 2 block:
/// corridors one cell wide, every edge of length 1 (integer lengths without the flat
/// vertices), with exact ties everywhere.
inline std::vector<Ring> hilbert_polygon(int order, bool keep_flat_vertices = true)
{
  using namespace degenerate_detail;
  if(order < 1 || order > 12) throw std::invalid_argument("hilbert_polygon: order not in [1, 12]");
  const std::int64_t n = std::int64_t(1) << order;
  std::vector<std::pair<std::int64_t, std::int64_t> > path;
  path.reserve(static_cast<std::size_t>(n * n + n));
  for(std::int64_t d = 0; d < n * n; ++d) {
    std::int64_t x = 0, y = 0, t = d;
    for(std::int64_t s = 1; s < n; s *= 2) {
      const std::int64_t rx = 1 & (t / 2);
      const std::int64_t ry = 1 & (t ^ rx);
      if(ry == 0) {
        if(rx == 1) { x = s - 1 - x; y = s - 1 - y; }
        std::swap(x, y);
      }
      x += s * rx;
      y += s * ry;
      t /= 4;
    }
    path.push_back(std::make_pair(x, y + 1));
  }
  for(std::int64_t x = n - 1; x >= 0; --x) path.push_back(std::make_pair(x, std::int64_t(0)));
  Ring ring;
  const std::size_t k = path.size();
  for(std::size_t i = 0; i < k; ++i) {
    const auto& a = path[(i + k - 1) % k];
    const auto& b = path[i];
    const auto& c = path[(i + 1) % k];
    const bool flat =
      (b.first - a.first == c.first - b.first) && (b.second - a.second == c.second - b.second);
    if(flat && !keep_flat_vertices) continue;
    ring.push_back(Point(static_cast<double>(b.first), static_cast<double>(b.second)));
  }
  random_detail::make_ccw(ring);
  std::vector<Ring> rings(1, ring);
  require_valid(rings, "hilbert_polygon");
  return rings;
}

/// Two concentric Koch snowflakes of the given order (>= 1; 3 * 4^(order-1) vertices per
/// ring: 192 at order 4, so 384 in all; order 1 is a triangle): the outer one with a
/// triangle of side `side` centred at the origin, the hole the same snowflake scaled by
/// 1/3 around the centre. The snowflake contains its initial triangle, hence the disk of
/// radius side / (2 sqrt 3) (the inscribed circle), and the hole lies in the disk of radius
/// side / (3 sqrt 3): the rings are well apart. Every vertex of both rings is a point of
/// one triangular lattice, so in exact arithmetic many triples are collinear, many
/// distances equal and many vertices cocircular; the coordinates are computed once as
/// x = (2a + b) * (h / 2), y = b * (h sqrt(3) / 2) from the integer lattice coordinates
/// (a, b) relative to the centre, which keeps the left-right mirror images exact, then
/// rounded to `decimals` places (decimals < 0: the doubles as computed). Throws
/// std::logic_error if `decimals` is too small for the order (rounded vertices merge).
inline std::vector<Ring> koch_snowflake_nested(int order, int decimals, double side = 100.0)
{
  using namespace degenerate_detail;
  if(order < 1 || order > 10) throw std::invalid_argument("koch_snowflake_nested: order not in [1, 10]");
  // outer triangle of lattice side 3 cen, cen = 3^order, so that its centroid, the lattice
  // point (cen, cen), and the hole's corners (cen +- (u - cen) / 3) are lattice points and
  // the hole's side, cen, is still a multiple of 3^(order-1)
  std::int64_t cen = 1;
  for(int i = 0; i < order; ++i) cen *= 3;
  const double half_h = side / static_cast<double>(3 * cen) / 2;            // h / 2
  const double height_h = side / static_cast<double>(3 * cen) * std::sqrt(0.75); // h sqrt(3) / 2
  std::vector<Ring> rings;
  for(std::int64_t shrink : {1, 3}) {
    Ring ring;
    for(const auto& l : koch_lattice(order, 3 * cen, cen, shrink)) {
      // lattice point (a, b) relative to the centroid is the plane point
      // (a + b/2, b sqrt(3)/2) h; its mirror image (-a - b, b) gets exactly -x
      const std::int64_t a = l.first - cen, b = l.second - cen;
      ring.push_back(Point(clean_zero(static_cast<double>(2 * a + b) * half_h),
                           static_cast<double>(b) * height_h));
    }
    rings.push_back(ring);
  }
  for(Ring& r : rings)
    for(Point& p : r) p = rounded(p.x(), p.y(), decimals);
  std::reverse(rings[1].begin(), rings[1].end()); // the hole, clockwise
  require_valid(rings, "koch_snowflake_nested");
  return rings;
}

/// The regular n-gon (n >= 3) around the origin with circumradius `radius`, a vertex at
/// angle 0, counter-clockwise; coordinates rounded to `decimals` places (decimals < 0: the
/// cos / sin doubles). The vertices are cocircular only up to rounding, but mirror images
/// across the axes (and the diagonals, if 8 divides n) are exact, so there are exact ties
/// among the distances (see degenerate_detail::unit_point). Throws std::logic_error if
/// `decimals` is too small for n (rounded vertices merge).
inline std::vector<Ring> regular_ngon(int n, double radius = 1.0, int decimals = -1)
{
  using namespace degenerate_detail;
  if(n < 3) throw std::invalid_argument("regular_ngon: n < 3");
  std::vector<Ring> rings(1, regular_ring(n, 0, 0, radius, decimals));
  require_valid(rings, "regular_ngon");
  return rings;
}

/// A regular n-gon of circumradius `radius` with `holes` regular holes of hole_vertices
/// vertices each (0: n), arranged symmetrically: one hole at the centre if holes == 1, else
/// `holes` equal holes centred at angles 2 pi j / holes on the circle of half the outer
/// ring's inradius, with a circumradius leaving 40% of the room to their neighbours and to
/// the outer ring. Mirror images exact as in regular_ngon().
inline std::vector<Ring> regular_ngon_with_holes(int n, int holes, int hole_vertices = 0,
                                                 double radius = 1.0, int decimals = -1)
{
  using namespace degenerate_detail;
  if(n < 3) throw std::invalid_argument("regular_ngon_with_holes: n < 3");
  if(holes < 0) throw std::invalid_argument("regular_ngon_with_holes: holes < 0");
  const int m = hole_vertices > 0 ? hole_vertices : n;
  if(m < 3) throw std::invalid_argument("regular_ngon_with_holes: hole_vertices < 3");
  std::vector<Ring> rings(1, regular_ring(n, 0, 0, radius, decimals));
  const double inradius = radius * std::cos(pi / n);
  const double ring_radius = holes == 1 ? 0.0 : 0.5 * inradius;
  double room = inradius - ring_radius;
  if(holes >= 2) room = (std::min)(room, ring_radius * std::sin(pi / holes));
  const double r = 0.6 * room;
  for(int j = 0; j < holes; ++j) {
    const std::pair<double, double> c = unit_point(j, holes);
    Ring hole = regular_ring(m, ring_radius * c.first, ring_radius * c.second, r, decimals);
    std::reverse(hole.begin(), hole.end());
    rings.push_back(hole);
  }
  require_valid(rings, "regular_ngon_with_holes");
  return rings;
}

/// A polygon with n (>= 4) vertices exactly on one circle: integer points of the circle of
/// radius R = 5, 65 = 5 * 13, 1105 = 5 * 13 * 17, ... (the smallest with at least n integer
/// points: 4 * 3^k points for k primes, up to 2,916 points at R = 48,612,265), n of them
/// chosen at random but always the four on the axes, joined in angular order. A third of
/// the gaps get an inward notch, a vertex strictly inside the triangle of the gap and the
/// centre and strictly on the centre's side of the gap's chord: an integer point of the
/// circle of radius 4R/5 (4 times a point of the circle of radius R/5: the notches are
/// exactly concyclic too; each lies on the ray of a point of the outer circle, so it fits
/// only where that point is not chosen) if one fits, else the integer point nearest to t
/// times the chord's midpoint, t random in [0.6, 0.95], if that fits. Star-shaped from the
/// origin (all vertices in strictly increasing angle, gaps at most pi/2), integer
/// coordinates.
inline std::vector<Ring> concyclic_polygon(std::uint64_t seed, int n)
{
  using namespace degenerate_detail;
  if(n < 4) throw std::invalid_argument("concyclic_polygon: n < 4");
  int k = 1;
  std::int64_t count = 12;
  while(count < n) {
    if(k == static_cast<int>(circle_primes().size()))
      throw std::invalid_argument("concyclic_polygon: n too large");
    ++k;
    count *= 3;
  }
  std::int64_t radius = 0, inner_radius = 0;
  const std::vector<Gaussian> circle = circle_lattice_points(0, k, radius);
  std::vector<Gaussian> inner = circle_lattice_points(1, k - 1, inner_radius);
  for(Gaussian& z : inner) z = Gaussian{4 * z.re, 4 * z.im};
  Rng rng(derive_seed(seed, 106, 0));
  // choose n points, the four on the axes first (they keep every gap at most pi/2)
  std::vector<std::size_t> chosen, rest;
  for(std::size_t i = 0; i < circle.size(); ++i) {
    const Gaussian& z = circle[i];
    if(z.re == 0 || z.im == 0) chosen.push_back(i); else rest.push_back(i);
  }
  for(std::size_t h = 0; chosen.size() < static_cast<std::size_t>(n); ++h) {
    std::swap(rest[h], rest[h + rng.below(rest.size() - h)]);
    chosen.push_back(rest[h]);
  }
  std::sort(chosen.begin(), chosen.end()); // circle is in angular order
  Ring ring;
  for(std::size_t c = 0; c < chosen.size(); ++c) {
    const Gaussian& a = circle[chosen[c]];
    const Gaussian& b = circle[chosen[(c + 1) % chosen.size()]];
    ring.push_back(Point(static_cast<double>(a.re), static_cast<double>(a.im)));
    if(rng.below(3) != 0) continue;
    // strictly inside the angle and strictly on the centre's side of the chord
    auto fits = [&](const Gaussian& z) {
      return strictly_between(a, z, b) &&
             (b.re - a.re) * (z.im - a.im) - (b.im - a.im) * (z.re - a.re) > 0;
    };
    std::vector<Gaussian> candidates;
    for(const Gaussian& z : inner)
      if(fits(z)) candidates.push_back(z);
    Gaussian notch;
    if(!candidates.empty()) {
      notch = candidates[rng.below(candidates.size())];
    } else {
      const double t = rng.uniform(0.6, 0.95);
      notch = Gaussian{static_cast<std::int64_t>(std::llround(t * 0.5 * static_cast<double>(a.re + b.re))),
                       static_cast<std::int64_t>(std::llround(t * 0.5 * static_cast<double>(a.im + b.im)))};
      if(!fits(notch)) continue;
    }
    ring.push_back(Point(static_cast<double>(notch.re), static_cast<double>(notch.im)));
  }
  std::vector<Ring> rings(1, ring);
  require_valid(rings, "concyclic_polygon");
  return rings;
}

/// `rings` with every vertex moved by a random amount in [-eps, eps] in x and in y: the
/// non-degenerate control of a degenerate shape (no exact ties left, in general). The
/// result is checked; if it is invalid (eps too large for the shape), new offsets are
/// drawn from a derived seed, up to 100 times, then std::invalid_argument is thrown.
inline std::vector<Ring> perturbed(const std::vector<Ring>& rings, std::uint64_t seed, double eps)
{
  using namespace degenerate_detail;
  for(std::uint64_t attempt = 0; attempt < 100; ++attempt) {
    Rng rng(derive_seed(seed, 107, attempt));
    std::vector<Ring> out = rings;
    for(Ring& r : out)
      for(Point& p : r) p = Point(p.x() + rng.uniform(-eps, eps), p.y() + rng.uniform(-eps, eps));
    if(validity_problem(out).empty()) return out;
  }
  throw std::invalid_argument("perturbed: no valid perturbation found (eps too large?)");
}

} // namespace pma_test

#endif // PMA_TEST_DEGENERATE_SHAPES_H
