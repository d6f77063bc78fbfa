// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// All rights reserved.
//
// This file is part of CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s)     : The Progressive_medial_axis_2 authors
//
// Numeric core of the package: the disk tangent to three generators (point
// and segment sites), written once for any number type with a square root
// (double, CGAL::Interval_nt, CORE::Expr).  The traits models call these
// functions; the engine never does.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_CONSTRUCTIONS_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_CONSTRUCTIONS_H

#include <CGAL/Progressive_medial_axis_2/internal/Inlining.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/number_utils.h>
#include <CGAL/Uncertain.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// Thrown by the double-precision model when a decision is too close to
/// call (a near tie, an implausible circle, an ambiguous branch of a
/// construction): the merge is then redone with exact decisions.
struct Uncertain_decision {};

/// In double precision, a sign that rounding can have flipped: |x| within a
/// relative 1e-9 of the magnitude of its terms.  Other number types decide
/// exactly (intervals throw when they cannot).
template <class NT>
void check_sign_is_clear(const NT& x, const NT& magnitude)
{
  if constexpr(std::is_floating_point<NT>::value) {
    if(!(std::fabs(x) > 1e-9 * magnitude)) throw Uncertain_decision();
  } else {
    (void)x;
    (void)magnitude;
  }
}

/// A comparison as 1 (true) or 0 (false), or -1 where the number type (an
/// interval) cannot decide it.  The disk constructions and the tests of an
/// event time report an undecided comparison by this value rather than by
/// an exception: on integer grids the intervals leave many undecided, and
/// throwing costs about a microsecond each, more for the first throw of a
/// process (RESULTS.md, "Start-up of small runs").
inline int decided(bool b) { return b ? 1 : 0; }
inline int decided(const Uncertain<bool>& b) { return is_certain(b) ? (get_certain(b) ? 1 : 0) : -1; }

/// The decision `found` (1, 0 or -1 as `decided()` gives) as a bool, for the
/// callers that need one: where it is undecided, throws
/// Uncertain_conversion_exception (`what` names the caller), which sends
/// the evaluation on to the next stage.
inline bool certain_or_throw(int found, const char* what)
{
  if(found < 0)
    throw Uncertain_conversion_exception(what);
  return found == 1;
}

/// A generator in number type `NT`: a point `(ax, ay)`, or the open segment
/// from `(ax, ay)` to `(bx, by)` whose interior side (the shape) is on its left.
template <class NT>
struct Site_nt {
  bool is_point;
  NT ax, ay, bx, by;
  // the segment is vertical or horizontal (decided on the input coordinates)
  bool axis_parallel = false;
  // the input coordinates are doubles (set by site_nt()): in intervals,
  // points, which the interval stage's line hook then need not test
  bool double_coordinates = false;
};

// Square root and absolute value found by argument-dependent lookup, so
// that number types outside CGAL's algebraic traits work as well.
/// The square root of a number type, through a hook that a number type
/// can specialise (see the CORE::Expr one in the traits).
template <class NT>
struct Sqrt_hook {
  static NT apply(const NT& x)
  {
    using CGAL::sqrt;
    return sqrt(x);
  }
};

#if !defined(__AVX512F__) && !defined(CGAL_ALWAYS_ROUND_TO_NEAREST)
/// The square root of a double interval, in the upward rounding that
/// `Interval_nt<false>` arithmetic runs in, without leaving it.  CGAL's
/// `sqrt()` switches the rounding to downward for the lower bound and back
/// (without AVX-512), and the two switches were most of the time of the
/// interval stage's square roots (`perf annotate`, RESULTS.md, thirty-eighth
/// session).  The lower bound is the same double: `r`, the square root of
/// the lower end rounded up, is exact if `r * r` rounded up is that end
/// (else `r * r` would exceed it), and otherwise the double below `r` is
/// the root rounded down.  (CGAL's own code suggests this in a comment.)
template <>
struct Sqrt_hook<Interval_nt<false> > {
  static Interval_nt<false> apply(const Interval_nt<false>& x)
  {
    double lower = 0;
    if(x.inf() > 0) {
      const double r = IA_sqrt_up(x.inf());
      lower = r;
      if(IA_opacify(r) * IA_opacify(r) != x.inf()) {
        std::uint64_t bits;
        std::memcpy(&bits, &r, sizeof bits);
        --bits;   // (r > 0: the next double towards zero)
        std::memcpy(&lower, &bits, sizeof bits);
      }
    }
    return Interval_nt<false>(lower, IA_sqrt_up(x.sup()));
  }
};
#endif

/// The rounding mode of `Interval_nt<false>` arithmetic (upward) for the
/// life of the object, as `Protect_FPU_rounding<true>`, with one read of the
/// SSE control register instead of two: the destructor writes back the
/// register as it was, so floating-point exception flags raised inside are
/// dropped (nothing here reads them).  The interval stage of the event
/// times and disks enters and leaves upward rounding once per evaluation,
/// and the register reads and writes were about half of the time of
/// `Filtered_model::time()` (`perf annotate`, RESULTS.md, thirty-ninth
/// session).
#if defined(CGAL_SAFE_SSE2) && !defined(CGAL_ALWAYS_ROUND_TO_NEAREST)
class Upward_rounding {
public:
  Upward_rounding() : saved_(_mm_getcsr()) { _mm_setcsr((saved_ & ~_MM_ROUND_MASK) | _MM_ROUND_UP); }
  ~Upward_rounding() { _mm_setcsr(saved_); }
  Upward_rounding(const Upward_rounding&) = delete;
  Upward_rounding& operator=(const Upward_rounding&) = delete;

private:
  unsigned int saved_;
};
#else
class Upward_rounding {
public:
  Upward_rounding() = default;
  Upward_rounding(const Upward_rounding&) = delete;
  Upward_rounding& operator=(const Upward_rounding&) = delete;

private:
  Protect_FPU_rounding<true> protection_;
};
#endif

template <class NT>
NT nt_sqrt(const NT& x)
{
  return Sqrt_hook<NT>::apply(x);
}

/// Square root of a number known to be non-negative; an exact zero gives 0
/// without a square root (exact number types would otherwise build a root
/// of zero).
template <class NT>
NT nt_sqrt_nonnegative(const NT& x)
{
  if(CGAL::certainly(x == 0))
    return NT(0);
  return nt_sqrt(x);
}

template <class NT>
NT nt_abs(const NT& x)
{
  using CGAL::abs;
  return abs(x);
}

/// Exact symbolic relations between the sites of a triple, decided by the
/// caller with exact predicates on the input coordinates.  Indices are
/// positions 0, 1, 2 in the triple.
struct Triple_relations {
  // point i equals the source (resp. target) of segment j
  bool point_is_source[3][3] = {};
  bool point_is_target[3][3] = {};
  // segments i and j lie on one line, and the target of i is the source of j
  // (a flat vertex of angle pi joins them)
  bool flat_join[3][3] = {};
  // segment i ends where segment j starts, at a corner that is not flat:
  // 1 where the boundary turns left there (a convex corner, the interior
  // being on the left), -1 where it turns right (reflex), else 0
  signed char corner_turn[3][3] = {};
  // sites i and j are the same generator
  bool same[3][3] = {};
  // exact sign of the orientation of three point sites (PPP only)
  int ppp_orientation = 0;
  // The relations below are looked for only where the double intervals
  // could not decide a branch (refine_relations() in the traits): each is an
  // exact tie of that branch, common where many vertices lie on a few lines
  // (straight borders of quantized GIS data, grids).
  // segments i and j lie on parallel lines in the same direction (their
  // interior normals are equal: no disk is tangent to both at a finite
  // point of the normal of one)
  bool same_direction[3][3] = {};
  // point site i lies on the line of segment site j: the disks through it
  // tangent to that line are tangent there, a double root
  bool point_on_line[3][3] = {};
  // the separator of an event time lies on the line of a segment site of
  // the triple: the disk, tangent to that line, touches the separator's
  // line at one point
  bool separator_on_line = false;
};

/// In floating point (the double model), a disk that misses a segment or
/// the separator's line by less than this relative amount (of the squared
/// length of the segment, of r^2 |d|^2 for the separator d) counts as
/// touching it: such a disk is an exact tie (through an end point, tangent)
/// that rounding left a hair short (touches_segments(),
/// chord_far_end_parts(), and the double model's
/// check_vanishing_decisions(), which must use the same margin).
constexpr double floating_contact_tolerance = 1e-12;

/// A circle: centre and radius.
template <class NT>
struct Circle_nt {
  NT x, y, r;
  // (double intervals only) the construction took the square root of a
  // radicand whose interval reaches below half its upper bound: rounding
  // errors near such a radicand's zero grow by a square root
  bool root_cancels = false;
};

/// Whether the radicand `x` of a disk construction can be close enough to
/// zero, relative to its rounding errors, for the square root to amplify
/// them beyond linear propagation: known for double intervals only (see
/// `rounds_within()` in Double_double.h); false for the other number types.
template <class NT>
bool radicand_cancels(const NT&)
{
  return false;
}
inline bool radicand_cancels(const Interval_nt<false>& x)
{
  return !(x.inf() > 0.5 * x.sup());
}

template <class NT>
struct Line_nt {
  // unit normal pointing to the interior side, and offset: n.x = k on the line
  NT nx, ny, k;
};

template <class NT>
Line_nt<NT> compute_oriented_line(const Site_nt<NT>& s)
{
  NT dx = s.bx - s.ax, dy = s.by - s.ay;
  // axis-parallel segments need no square root (this keeps exact
  // computations on rectilinear shapes rational)
  NT len = s.axis_parallel ? nt_abs(dx) + nt_abs(dy) : nt_sqrt(dx * dx + dy * dy);
  Line_nt<NT> l;
  NT inv = NT(1) / len;
  l.nx = -dy * inv;
  l.ny = dx * inv;
  l.k = l.nx * s.ax + l.ny * s.ay;
  return l;
}

/// The oriented line of a segment site, through a hook that a number type
/// can specialise (the interval stage of the filtered traits keeps the
/// lines of the segments it has seen: the same segments come back in many
/// constructions, and the line costs a square root and a division).
template <class NT>
struct Oriented_line_hook {
  static Line_nt<NT> apply(const Site_nt<NT>& s) { return compute_oriented_line(s); }
};

template <class NT>
Line_nt<NT> oriented_line(const Site_nt<NT>& s)
{
  return Oriented_line_hook<NT>::apply(s);
}

/// A direct-mapped table of constructions, kept per thread: the lines of
/// segments, for the number types whose lines cost much (a square root and
/// a division), and the disks of triples (the traits).  The same segments
/// come back in many constructions, and the same triples in many
/// decisions.  `Entry` is default-constructible, its default value is an
/// unused entry, and it has `max_bits` (the table's largest size, as a
/// power of two), `misses_per_page` (below), `holds(key)`, `value()` and
/// `set(key, value)`.  The table starts with 64 entries, or fewer where 64
/// are more than a 4 KB page (the disks of triples in intervals, 21 KB, were
/// 4 of the 37 page faults of a glyph of 8 vertices), and grows by a factor
/// of four as misses come, up to 2^max_bits entries (a new table each time,
/// the old entries dropped), so that a small polygon touches a few pages only: a table of
/// 4,096 interval lines at once was a third of the page faults of a polygon
/// of 268 vertices, and one of 256 (20 KB) still 2% of the first call on a
/// glyph of 14 vertices (RESULTS.md, "The cold first call of tiny glyphs").
/// It grows once the misses since it was made are at least twice its
/// entries and at least `misses_per_page` for each 4 KB page of the larger
/// table: the misses a page fault is worth, in computations of the entry's
/// value (a fault cost 8 to 16 microseconds on the 2-core VM of RESULTS.md).
/// On grid polygons and Koch snowflakes of 670 to 4,700 vertices, growing
/// at twice the entries alone cost the process 8% to 17% more page faults
/// (RESULTS.md, "Page faults and the sequential phases", thirty-fourth
/// session).
/// Entries of plain data come zeroed from calloc, whose fresh pages the
/// system gives zeroed.
template <class Entry>
class Cache_table
{
public:
  ~Cache_table() { release(); }
  /// The value for `key` of hash `hash`: the entry's, or compute() kept
  /// in the entry.
  template <class Key, class Compute>
  auto value(std::uint64_t hash, const Key& key, const Compute& compute) -> decltype(compute())
  {
    if(!entries_ && !make(first_bits()))
      return compute();
    Entry* e = &entries_[std::size_t(hash >> (64 - bits_))];
    if(e->holds(key))
      return e->value();
    const auto value = compute();
    // (once there were many misses, in a larger table)
    if(++misses_ > (std::max)(std::size_t(2) << bits_, (sizeof(Entry) << (bits_ + 2)) / 4096 * Entry::misses_per_page) &&
       bits_ < Entry::max_bits && make((std::min)(bits_ + 2, unsigned(Entry::max_bits))))
      e = &entries_[std::size_t(hash >> (64 - bits_))];
    e->set(key, value);
    return value;
  }

private:
  // the first table: 64 entries, or fewer where that is more than a page
  static constexpr unsigned first_bits()
  {
    unsigned b = 6;
    while(b > 2 && (sizeof(Entry) << b) > 4096) --b;
    return b;
  }
  void release()
  {
    if constexpr(std::is_trivial<Entry>::value)
      std::free(entries_);
    else
      delete[] entries_;
  }
  bool make(unsigned b)
  {
    Entry* e;
    if constexpr(std::is_trivial<Entry>::value)
      e = static_cast<Entry*>(std::calloc(std::size_t(1) << b, sizeof(Entry)));
    else
      e = new(std::nothrow) Entry[std::size_t(1) << b]();
    if(!e) return false;
    release();
    entries_ = e;
    bits_ = b;
    misses_ = 0;
    return true;
  }

  Entry* entries_ = nullptr;
  unsigned bits_ = 0;          // 2^bits entries
  std::size_t misses_ = 0;     // since the table was made
};

/// Mixes 64-bit words into a hash (for Cache_table).
inline std::uint64_t mix_hash(std::uint64_t h, std::uint64_t word)
{
  return (h ^ word) * 0xff51afd7ed558ccdull;
}

/// The interval stage's lines of segments whose end points are doubles
/// (a hit costs a hash and four comparisons).
template <>
struct Oriented_line_hook<Interval_nt<false> > {
  typedef Interval_nt<false> I;
  struct Entry {   // (plain data: all zeros is an unused entry)
    static constexpr unsigned max_bits = 12;
    static constexpr std::size_t misses_per_page = 128;   // (a line: a square root and a division)
    double key[4];   // ax, ay, bx, by
    double bounds[6];   // nx, ny, k: inf and sup of each
    bool holds(const double* c) const { return key[0] == c[0] && key[1] == c[1] && key[2] == c[2] && key[3] == c[3]; }
    Line_nt<I> value() const { return Line_nt<I>{I(bounds[0], bounds[1]), I(bounds[2], bounds[3]), I(bounds[4], bounds[5])}; }
    void set(const double* c, const Line_nt<I>& l)
    {
      std::memcpy(key, c, sizeof key);
      bounds[0] = l.nx.inf(); bounds[1] = l.nx.sup();
      bounds[2] = l.ny.inf(); bounds[3] = l.ny.sup();
      bounds[4] = l.k.inf(); bounds[5] = l.k.sup();
    }
  };
  static Line_nt<I> apply(const Site_nt<I>& s)
  {
    if(!(s.double_coordinates || (s.ax.is_point() && s.ay.is_point() && s.bx.is_point() && s.by.is_point())))
      return compute_oriented_line(s);
    const double c[4] = {s.ax.inf(), s.ay.inf(), s.bx.inf(), s.by.inf()};
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for(double x : c) {
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      h = mix_hash(h, b);
    }
    static thread_local Cache_table<Entry> table;
    return table.value(h, c, [&] { return compute_oriented_line(s); });
  }
};

/// Signed distance of `(x, y)` to the line, positive on the interior side.
template <class NT>
NT signed_distance(const Line_nt<NT>& l, const NT& x, const NT& y)
{
  return l.nx * x + l.ny * y - l.k;
}

template <class NT>
NT cross2(const NT& ax, const NT& ay, const NT& bx, const NT& by)
{
  return ax * by - ay * bx;
}

/// Strict counter-clockwise cyclic order of three directions: at least two
/// of the three consecutive cross products are positive.  1 if so, 0 if not,
/// -1 if the number type cannot decide it (see `decided()`).
template <class NT>
int ccw_directions(const NT& ux, const NT& uy, const NT& vx, const NT& vy,
                   const NT& wx, const NT& wy)
{
  int positive = 0;
  const NT a = cross2(ux, uy, vx, vy), b = cross2(vx, vy, wx, wy), c = cross2(wx, wy, ux, uy);
  if constexpr(std::is_floating_point<NT>::value) {
    const NT nu = std::sqrt(ux * ux + uy * uy), nv = std::sqrt(vx * vx + vy * vy), nw = std::sqrt(wx * wx + wy * wy);
    check_sign_is_clear(a, nu * nv);
    check_sign_is_clear(b, nv * nw);
    check_sign_is_clear(c, nw * nu);
  }
  for(const NT* x : {&a, &b, &c}) {
    const int d = decided(*x > 0);
    if(d < 0) return -1;
    positive += d;
  }
  return positive >= 2 ? 1 : 0;
}

// The disk constructions below return 1 if the disk exists (and set `c`),
// 0 if it does not, -1 if the number type cannot decide which (see
// `decided()`).

/// Circle centred on the normal of `l` at `(zx, zy)` (tangent to the line
/// there) and tangent to the line `m` on its interior side.
template <class NT>
int tangent_at_point_and_line(const NT& zx, const NT& zy, const Line_nt<NT>& l,
                              const Line_nt<NT>& m, Circle_nt<NT>& c)
{
  // 1 - cos(angle) of the two unit normals, without cancellation
  NT ex = l.nx - m.nx, ey = l.ny - m.ny;
  NT denom = (ex * ex + ey * ey) / NT(2);
  const int turns = decided(denom > 0);
  if(turns <= 0)
    return turns;
  NT lambda = signed_distance(m, zx, zy) / denom;
  const int positive = decided(lambda > 0);
  if(positive <= 0)
    return positive;
  c.x = zx + lambda * l.nx;
  c.y = zy + lambda * l.ny;
  c.r = lambda;
  return 1;
}

/// Circle centred on the normal of `l` at `(zx, zy)` and through the point `(px, py)`.
template <class NT>
int tangent_at_point_and_point(const NT& zx, const NT& zy, const Line_nt<NT>& l,
                               const NT& px, const NT& py, Circle_nt<NT>& c)
{
  NT vx = px - zx, vy = py - zy;
  NT denom = NT(2) * (l.nx * vx + l.ny * vy);
  const int inside = decided(denom > 0);
  if(inside <= 0)
    return inside;
  NT lambda = (vx * vx + vy * vy) / denom;
  c.x = zx + lambda * l.nx;
  c.y = zy + lambda * l.ny;
  c.r = lambda;
  return 1;
}

/// PPP: the circle through three points in counter-clockwise order.
template <class NT>
int circle_ppp(const Site_nt<NT>& p, const Site_nt<NT>& q, const Site_nt<NT>& s,
               Circle_nt<NT>& c)
{
  NT bx = q.ax - p.ax, by = q.ay - p.ay;
  NT cx = s.ax - p.ax, cy = s.ay - p.ay;
  NT d = NT(2) * cross2(bx, by, cx, cy);
  NT b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  NT ux = (cy * b2 - by * c2) / d;
  NT uy = (bx * c2 - cx * b2) / d;
  c.x = p.ax + ux;
  c.y = p.ay + uy;
  c.r = nt_sqrt(ux * ux + uy * uy);
  return 1;
}

/// PPS: the circle through p and q, tangent to segment s on its interior
/// side, with p, q, s in counter-clockwise order around the centre.
template <class NT>
int circle_pps(const Site_nt<NT>& p, const Site_nt<NT>& q, const Site_nt<NT>& s,
               Circle_nt<NT>& c, bool double_root = false)
{
  Line_nt<NT> l = oriented_line(s);
  // local frame at p
  NT qx = q.ax - p.ax, qy = q.ay - p.ay;
  NT e = signed_distance(l, p.ax, p.ay);      // distance of p to the line
  NT mx = qx / NT(2), my = qy / NT(2);
  NT wx = -qy, wy = qx;                        // perpendicular to pq
  NT h = l.nx * mx + l.ny * my + e;            // distance of the midpoint
  NT sp = l.nx * wx + l.ny * wy;
  NT a2 = (qx * qx + qy * qy) / NT(4);
  NT nq = l.nx * qx + l.ny * qy;
  NT M = nq * nq;
  NT hs = h * sp;
  NT D = hs * hs + M * (h * h - a2);
  // (a double root: p or q on the line, the disk tangent there; D is 0)
  const int no_root = double_root ? 0 : decided(D < 0);
  if(no_root != 0)
    return no_root < 0 ? -1 : 0;
  NT sd = double_root ? NT(0) : nt_sqrt_nonnegative(D);
  c.root_cancels = !double_root && radicand_cancels(D);
  NT lambda;
  // (a double root is hs / M whatever the sign of hs: D = 0 makes the two
  // forms below equal)
  const int hs_nonnegative = double_root ? 1 : decided(hs >= 0);
  if(hs_nonnegative < 0)
    return -1;
  if(hs_nonnegative) {
    const int m_positive = decided(M > 0);
    if(m_positive <= 0)
      return m_positive;
    lambda = (hs + sd) / M;
  } else {
    lambda = (a2 - h * h) / (hs - sd);
  }
  NT r = h + lambda * sp;
  const int r_positive = decided(r > 0);
  if(r_positive <= 0)
    return r_positive;
  c.x = p.ax + mx + lambda * wx;
  c.y = p.ay + my + lambda * wy;
  c.r = r;
  return 1;
}

/// PSS: the circle through p tangent to segments s1 and s2 on their
/// interior sides, with p, s1, s2 in counter-clockwise order (on
/// rectilinear input the discriminant is often exactly 0).
template <class NT>
int circle_pss(const Site_nt<NT>& p, const Site_nt<NT>& s1, const Site_nt<NT>& s2,
               Circle_nt<NT>& c)
{
  Line_nt<NT> l1 = oriented_line(s1), l2 = oriented_line(s2);
  NT e1 = signed_distance(l1, p.ax, p.ay);
  NT e2 = signed_distance(l2, p.ax, p.ay);
  NT gx = l1.nx - l2.nx, gy = l1.ny - l2.ny;
  NT g2 = gx * gx + gy * gy;
  const int apart = decided(g2 > 0);
  if(apart <= 0)
    return apart;                               // (0: parallel, same side)
  // centre x (relative to p) on the bisector g.x = e2 - e1
  NT x0x = (e2 - e1) * gx / g2, x0y = (e2 - e1) * gy / g2;
  NT ux = -gy, uy = gx;
  NT R0 = l1.nx * x0x + l1.ny * x0y + e1;
  NT rho = l1.nx * ux + l1.ny * uy;
  NT one_minus_cos = g2 / NT(2);        // for unit normals, without cancellation
  NT A = one_minus_cos * one_minus_cos;
  NT B = R0 * rho;
  NT C = x0x * x0x + x0y * x0y - R0 * R0;
  NT disc = B * B - A * C;
  const int no_root = decided(disc < 0);
  if(no_root != 0)
    return no_root < 0 ? -1 : 0;
  NT sd = nt_sqrt_nonnegative(disc);
  c.root_cancels = radicand_cancels(disc);
  const int b_nonnegative = decided(B >= 0);
  if(b_nonnegative < 0)
    return -1;
  NT q = b_nonnegative ? B + sd : B - sd;
  bool found = false;
  NT best_r(0);
  for(int i = 0; i < 2; ++i) {
    NT lambda;
    if(i == 0) {
      const int a_positive = decided(A > 0);
      if(a_positive < 0) return -1;
      if(!a_positive) continue;
      lambda = q / A;
    } else {
      const int q_zero = decided(q == 0);
      if(q_zero < 0) return -1;
      if(q_zero) continue;
      lambda = C / q;
    }
    NT xx = x0x + lambda * ux, xy = x0y + lambda * uy;
    NT r = R0 + lambda * rho;
    const int r_positive = decided(r > 0);
    if(r_positive < 0) return -1;
    if(!r_positive) continue;
    const int ccw = ccw_directions(xx, xy, l1.nx, l1.ny, l2.nx, l2.ny);
    if(ccw < 0) return -1;
    if(!ccw) continue;
    if(found) check_sign_is_clear(NT(r - best_r), NT(r + best_r));
    const int smaller = found ? decided(r < best_r) : 1;
    if(smaller < 0) return -1;
    if(smaller) {
      found = true;
      best_r = r;
      c.x = p.ax + xx;
      c.y = p.ay + xy;
      c.r = r;
    }
  }
  return found ? 1 : 0;
}

/// The number types in which circle_sss() computes the disk of a chain of
/// three segments from the bisectors of its corners (see there): double
/// intervals, and the plain double-double whose disks the filtered traits
/// round with the error bound of the same operations in double intervals
/// (`rounds_within()` needs the same operations in both).  Not the
/// double-double intervals (no gain on a 20,000-gon) nor the exact stages,
/// which keep their expressions.
template <class NT>
struct Sss_from_corner_bisectors : std::false_type {};
template <>
struct Sss_from_corner_bisectors<Interval_nt<false> > : std::true_type {};
class Double_double;
template <>
struct Sss_from_corner_bisectors<Double_double> : std::true_type {};

/// SSS: the circle tangent to three segments on their interior sides, in
/// counter-clockwise order.  `chain` is -1, or the index i of the first
/// segment of a chain: s_i ends where s_i+1 starts, which ends where s_i+2
/// starts (indices modulo 3).
template <class NT>
int circle_sss(const Site_nt<NT>& s1, const Site_nt<NT>& s2, const Site_nt<NT>& s3,
               Circle_nt<NT>& c, int chain = -1)
{
  // local frame at the source of s1
  const NT ox = s1.ax, oy = s1.ay;
  Line_nt<NT> l[3] = {oriented_line(s1), oriented_line(s2), oriented_line(s3)};
  const Site_nt<NT>* s[3] = {&s1, &s2, &s3};
  NT g2x = l[1].nx - l[0].nx, g2y = l[1].ny - l[0].ny;
  NT g3x = l[2].nx - l[0].nx, g3y = l[2].ny - l[0].ny;
  NT det = cross2(g2x, g2y, g3x, g3y);
  const int det_positive = decided(det > 0);
  if(det_positive <= 0)
    return det_positive;
  if constexpr(Sss_from_corner_bisectors<NT>::value) {
    if(chain >= 0) {
      // The linear system above subtracts unit normals, which on a finely
      // sampled curve (consecutive segments that turn by 1e-4 rad) lose
      // most of their digits: the centre's interval was then about 1e-7
      // of the radius wide, and the event times of such a curve, which
      // differ in the ninth digit, went to double-double intervals.  Here
      // the centre is where the bisectors of the two corners V1 (start of
      // the middle segment B) and V2 (its end) meet: V1 + t (nA + nB) =
      // V2 + u (nB + nC), t = (V2 - V1) x (nB + nC) / ((nA + nB) x (nB +
      // nC)).  The corners are input points and the sums of unit normals
      // keep their digits, so the error grows as 1 / angle, not 1 /
      // angle^2 (a 20,000-gon: 23% less time, RESULTS.md, fifty-eighth
      // session).  The radius is the distance to B's line: r = t nB.(nA +
      // nB) = t (1 + nA.nB).  The same disk as the system's, in another
      // enclosure (the sign of det above decides the same question).
      const Line_nt<NT>& A = l[chain];
      const Line_nt<NT>& B = l[(chain + 1) % 3];
      const Line_nt<NT>& C = l[(chain + 2) % 3];
      const Site_nt<NT>& sb = *s[(chain + 1) % 3];
      const NT d1x = A.nx + B.nx, d1y = A.ny + B.ny, d2x = B.nx + C.nx, d2y = B.ny + C.ny;
      const NT Dx = sb.bx - sb.ax, Dy = sb.by - sb.ay;
      const NT t = cross2(Dx, Dy, d2x, d2y) / cross2(d1x, d1y, d2x, d2y);
      const NT r = t * (NT(1) + A.nx * B.nx + A.ny * B.ny);
      const int r_positive = decided(r > 0);
      if(r_positive <= 0)
        return r_positive;
      c.x = sb.ax + t * d1x;
      c.y = sb.ay + t * d1y;
      c.r = r;
      return 1;
    }
  }
  NT k[3];
  for(int i = 0; i < 3; ++i)
    k[i] = l[i].nx * (s[i]->ax - ox) + l[i].ny * (s[i]->ay - oy);
  NT b2 = k[1] - k[0], b3 = k[2] - k[0];
  NT x = (b2 * g3y - b3 * g2y) / det;
  NT y = (g2x * b3 - b2 * g3x) / det;
  NT r = l[0].nx * x + l[0].ny * y - k[0];
  const int r_positive = decided(r > 0);
  if(r_positive <= 0)
    return r_positive;
  c.x = ox + x;
  c.y = oy + y;
  c.r = r;
  return 1;
}

/// The disk tangent to the three generators `s[0], s[1], s[2]` whose cells
/// meet at its centre in this counter-clockwise order: 1 if found, 0 when
/// no such disk exists, -1 when the number type cannot decide which.
/// `rel` carries the exact symbolic relations between the sites (shared
/// endpoints, flat joins), which select the degenerate constructions.
/// The construction must stay symmetric: the disk of the mirror image of a
/// triple (in the reversed order, each segment reversed) is the mirror image
/// of its disk, and the centre is at signed distance +r from the line of each
/// segment.  The filtered traits decide ties by symmetry on that ground
/// (mirror_tie() in Progressive_medial_axis_traits_2.h): no choice between
/// candidate circles may depend on the order of coordinates or indices.
/// The test build with CGAL_PMA2_CHECK_MIRROR_TIES checks every such tie.
template <class NT>
int medial_circle_decided(const Site_nt<NT> s[3], const Triple_relations& rel, Circle_nt<NT>& c)
{
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      if(i != j && rel.same[i][j])
        return 0;
  int np = int(s[0].is_point) + int(s[1].is_point) + int(s[2].is_point);
  if(np == 3) {
    if(rel.ppp_orientation <= 0)
      return 0;
    return circle_ppp(s[0], s[1], s[2], c);
  }
  if(np == 2) {
    // rotate to (p, q, segment)
    int k = s[0].is_point ? (s[1].is_point ? 2 : 1) : 0;   // index of the segment
    int ip = (k + 1) % 3, iq = (k + 2) % 3;
    if(rel.point_is_source[ip][k] || rel.point_is_target[iq][k])
      return 0;
    if(rel.point_is_target[ip][k] && rel.point_is_source[iq][k])
      return 0;
    if(rel.point_is_target[ip][k]) {
      Line_nt<NT> l = oriented_line(s[k]);
      return tangent_at_point_and_point(s[ip].ax, s[ip].ay, l, s[iq].ax, s[iq].ay, c);
    }
    if(rel.point_is_source[iq][k]) {
      Line_nt<NT> l = oriented_line(s[k]);
      return tangent_at_point_and_point(s[iq].ax, s[iq].ay, l, s[ip].ax, s[ip].ay, c);
    }
    return circle_pps(s[ip], s[iq], s[k], c, rel.point_on_line[ip][k] || rel.point_on_line[iq][k]);
  }
  if(np == 1) {
    int ip = s[0].is_point ? 0 : (s[1].is_point ? 1 : 2);
    int i1 = (ip + 1) % 3, i2 = (ip + 2) % 3;
    if(rel.point_is_target[ip][i1] || rel.point_is_source[ip][i2])
      return 0;
    if(rel.point_is_source[ip][i1] && rel.point_is_target[ip][i2])
      return 0;
    // (the refined relations: exact ties where the disk does not exist,
    // see Triple_relations)
    if(rel.point_is_source[ip][i1]) {
      if(rel.same_direction[i1][i2] || rel.point_on_line[ip][i2])   // (no turn, or a disk of radius 0)
        return 0;
      Line_nt<NT> l1 = oriented_line(s[i1]), l2 = oriented_line(s[i2]);
      return tangent_at_point_and_line(s[ip].ax, s[ip].ay, l1, l2, c);
    }
    if(rel.point_is_target[ip][i2]) {
      if(rel.same_direction[i1][i2] || rel.point_on_line[ip][i1])
        return 0;
      Line_nt<NT> l1 = oriented_line(s[i1]), l2 = oriented_line(s[i2]);
      return tangent_at_point_and_line(s[ip].ax, s[ip].ay, l2, l1, c);
    }
    if(rel.flat_join[i2][i1])
      return 0;
    if(rel.flat_join[i1][i2]) {
      Line_nt<NT> l = oriented_line(s[i1]);
      return tangent_at_point_and_point(s[i1].bx, s[i1].by, l, s[ip].ax, s[ip].ay, c);
    }
    // p on the line of s1 (or s2): the disk touches that line at p, a double
    // root, and p, s1, s2 are not in counter-clockwise order around it (the
    // centre is p plus r times s1's normal); parallel segments in the same
    // direction: no disk
    if(rel.point_on_line[ip][i1] || rel.point_on_line[ip][i2] || rel.same_direction[i1][i2])
      return 0;
    return circle_pss(s[ip], s[i1], s[i2], c);
  }
  // SSS
  for(int i = 0; i < 3; ++i) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    if(rel.flat_join[j][i])
      return 0;
    if(rel.flat_join[i][j]) {
      if(rel.same_direction[i][k])
        return 0;
      Line_nt<NT> l = oriented_line(s[i]), m = oriented_line(s[k]);
      return tangent_at_point_and_line(s[i].bx, s[i].by, l, m, c);
    }
  }
  // two segments in the same direction: two equal normals, no disk
  if(rel.same_direction[0][1] || rel.same_direction[1][2] || rel.same_direction[2][0])
    return 0;
  int chain = -1;
  for(int i = 0; i < 3; ++i)
    if(rel.corner_turn[i][(i + 1) % 3] != 0 && rel.corner_turn[(i + 1) % 3][(i + 2) % 3] != 0)
      chain = i;
  return circle_sss(s[0], s[1], s[2], c, chain);
}

/// The same, as a bool: where the number type (intervals) cannot decide a
/// branch, Uncertain_conversion_exception is thrown.
template <class NT>
bool medial_circle(const Site_nt<NT> s[3], const Triple_relations& rel, Circle_nt<NT>& c)
{
  return certain_or_throw(medial_circle_decided(s, rel, c), "medial_circle: undecided comparison");
}

/// Whether the contact of a disk of the triple with its segment site `i` is
/// known to be one of the segment's endpoints (a point site at that
/// endpoint, a flat join with another segment of the triple): such a
/// contact is not tested.
inline bool segment_contact_known(const Triple_relations& rel, int i)
{
  for(int j = 0; j < 3; ++j)
    if(j != i && (rel.point_is_source[j][i] || rel.point_is_target[j][i] || rel.flat_join[i][j] || rel.flat_join[j][i]))
      return true;
  return false;
}

/// Whether the disk touches every segment site of the triple within the
/// closed segment (not only its supporting line): 1 if it does, 0 if not,
/// -1 if the number type cannot decide it (see `decided()`).  A segment
/// whose contact is known to be one of its endpoints (a point site at that
/// endpoint, a flat join) is not tested.  `tolerance` (relative, 0 for exact
/// number types) admits contacts just beyond an endpoint.
template <class NT>
int touches_segments(const Site_nt<NT> s[3], const Triple_relations& rel, const Circle_nt<NT>& c,
                     double tolerance)
{
  for(int i = 0; i < 3; ++i) {
    if(s[i].is_point || segment_contact_known(rel, i)) continue;
    // At a corner shared with another segment of the triple, a disk of
    // positive radius tangent to both lines on their interior sides touches
    // them at the distance r cot(alpha / 2) from the corner, alpha the
    // interior angle: on both segments' sides of it at a convex corner,
    // beyond them at a reflex one.  Decided so, exactly, rather than by the
    // sign of a contact that may lie a hair from the corner (flattened
    // curves: consecutive segments that turn by 1e-14 rad).  Not in
    // floating point: the double model's disk of such a corner can be off
    // by more than its contact, and the tolerance below keeps its merges
    // consistent (a sliver polygon gave a wrong axis).
    int at_source = 0, at_target = 0;
    if constexpr(!std::is_floating_point<NT>::value)
      for(int j = 0; j < 3; ++j) {
        if(rel.corner_turn[j][i] != 0) at_source = rel.corner_turn[j][i];
        if(rel.corner_turn[i][j] != 0) at_target = rel.corner_turn[i][j];
      }
    const bool at_corner = (at_source != 0 || at_target != 0) && decided(c.r > 0) == 1;
    if(at_corner && (at_source < 0 || at_target < 0)) return 0;
    NT dx = s[i].bx - s[i].ax, dy = s[i].by - s[i].ay;
    // (without a tolerance, no slack to compute: a fifth of this function's
    // instructions in intervals)
    const NT low = tolerance != 0 ? NT(-(NT(tolerance) * (dx * dx + dy * dy))) : NT(0);
    if(!(at_corner && at_source > 0)) {
      const int before = decided((c.x - s[i].ax) * dx + (c.y - s[i].ay) * dy < low);
      if(before != 0) return before < 0 ? -1 : 0;
    }
    if(!(at_corner && at_target > 0)) {
      const int beyond = decided((s[i].bx - c.x) * dx + (s[i].by - c.y) * dy < low);
      if(beyond != 0) return beyond < 0 ? -1 : 0;
    }
  }
  return 1;
}

/// Position, along the separator from `P` to `Q`, of the point where the
/// retracting tip meets the circle: the end of the chord nearer to `Q`,
/// scaled by |PQ|^2 (0 at P, |PQ|^2 at Q), as `alpha + sqrt(rad)`.  1 if
/// found, 0 if the circle misses the line, -1 if the number type cannot
/// decide which (see `decided()`).
/// With `tangent`, the circle is known to touch the line at one point
/// (rad is 0).
template <class NT>
int chord_far_end_parts(const NT& px, const NT& py, const NT& qx, const NT& qy,
                        const Circle_nt<NT>& c, NT& alpha, NT& rad, bool tangent = false)
{
  NT dx = qx - px, dy = qy - py;
  NT vx = c.x - px, vy = c.y - py;
  NT d2 = dx * dx + dy * dy;
  NT h = cross2(dx, dy, vx, vy);
  NT r2d2 = c.r * c.r * d2;
  rad = tangent ? NT(0) : NT(r2d2 - h * h);
  const int misses = tangent ? 0 : decided(rad < 0);
  if(misses < 0) return -1;
  if(misses) {
    // With floating-point numbers, a circle through an endpoint of the
    // separator or tangent to it (an exact tie, common on integer grids)
    // can come out a rounding error short of the line: count it as tangent.
    if(!std::is_floating_point<NT>::value || rad < -NT(floating_contact_tolerance) * r2d2)
      return 0;
    rad = NT(0);
  }
  alpha = dx * vx + dy * vy;
  return 1;
}

/// The same position as one number.
template <class NT>
int chord_far_end(const NT& px, const NT& py, const NT& qx, const NT& qy,
                  const Circle_nt<NT>& c, NT& t, bool tangent = false)
{
  NT alpha, rad;
  const int found = chord_far_end_parts(px, py, qx, qy, c, alpha, rad, tangent);
  if(found <= 0)
    return found;
  t = alpha + nt_sqrt_nonnegative(rad);
  return 1;
}

/// The squared distance from the centre of `c` to the closed segment from
/// `P` to `Q`, minus the squared radius: negative exactly when the open disk
/// meets the segment.
template <class NT>
NT conflict_value(const NT& px, const NT& py, const NT& qx, const NT& qy, const Circle_nt<NT>& c)
{
  const NT dx = qx - px, dy = qy - py;
  const NT vx = c.x - px, vy = c.y - py;
  const NT f = dx * vx + dy * vy;
  const NT r2 = c.r * c.r;
  if(!(f > 0))
    return vx * vx + vy * vy - r2;
  const NT d2 = dx * dx + dy * dy;
  if(!(f < d2)) {
    const NT wx = c.x - qx, wy = c.y - qy;
    return wx * wx + wy * wy - r2;
  }
  const NT h = cross2(dx, dy, vx, vy);
  return (h * h - r2 * d2) / d2;
}

/// Position along the separator of the foot of the centre.
template <class NT>
NT foot_position(const NT& px, const NT& py, const NT& qx, const NT& qy, const Circle_nt<NT>& c)
{
  return (qx - px) * (c.x - px) + (qy - py) * (c.y - py);
}

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_CONSTRUCTIONS_H
