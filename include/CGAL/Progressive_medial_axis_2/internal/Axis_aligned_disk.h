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
// The coordinates of a medial disk that are sums and halves of input
// coordinates, computed exactly and rounded correctly, for the disk stage of
// the filtered traits.
//
// A disk tangent to two vertical lines x = a and x = b has its centre at
// x = (a + b) / 2 and the radius |a - b| / 2; a disk through two points of
// equal y has its centre at the midpoint of their x; a disk tangent to a
// horizontal line at a point of it has its centre straight above or below
// that point.  Such a coordinate needs a bit or two more than a double, and
// then lies exactly halfway between two doubles as a rule: no interval can
// round it, and it went on to MPFR and to GMP rationals.  Real maps are full
// of them: `countries-land-10m` has about 127,000 lakes in Russia alone that
// are small right triangles with axis-parallel legs (RESULTS.md,
// sixty-fifth session).

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_AXIS_ALIGNED_DISK_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_AXIS_ALIGNED_DISK_H

#include <CGAL/Progressive_medial_axis_2/internal/Float_bits.h>

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// n 2^e exactly, |n| < 2^125: the sums, differences and halves of a few
/// doubles.  An operation whose result would not fit clears `ok` (then the
/// caller leaves the coordinate to the exact stages).  (Hand-written:
/// Boost.Multiprecision's binary floats round to their precision without
/// saying so, and GMP allocates; this is what Small_rational's 128-bit
/// integers give for sums.)
struct Dyadic {
  __int128 n = 0;
  int e = 0;
  bool ok = true;

  /// The exact value of a finite double.
  static Dyadic of(double x)
  {
    Dyadic d;
    if(x == 0) return d;
    if(!std::isfinite(x)) {
      d.ok = false;
      return d;
    }
    std::int64_t n;
    integer_and_exponent(x, n, d.e);
    d.n = n;
    return d;
  }

  friend Dyadic operator-(const Dyadic& a)
  {
    Dyadic d = a;
    d.n = -a.n;
    return d;
  }
  friend Dyadic operator+(const Dyadic& a, const Dyadic& b)
  {
    if(!a.ok || !b.ok) return failed();
    if(a.n == 0) return b;
    if(b.n == 0) return a;
    // to the smaller exponent: the other's integer shifted left
    const Dyadic& lo = a.e <= b.e ? a : b;
    const Dyadic& hi = a.e <= b.e ? b : a;
    const int shift = hi.e - lo.e;
    if(shift > 124 - bits(hi.n) || bits(lo.n) > 124) return failed();
    Dyadic d;
    d.n = lo.n + hi.n * (__int128(1) << shift);
    d.e = lo.e;
    return d;
  }
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) { return a + (-b); }
  Dyadic half() const
  {
    Dyadic d = *this;
    --d.e;
    return d;
  }
  int sign() const { return n > 0 ? 1 : (n < 0 ? -1 : 0); }
  friend bool operator==(const Dyadic& a, const Dyadic& b) { return a.ok && b.ok && (a - b).ok && (a - b).n == 0; }

  /// The value rounded to the nearest double, ties to even; false where it
  /// is not a normal double (overflow, subnormal) or not exact.
  bool to_double(double& out) const
  {
    if(!ok) return false;
    if(n == 0) {
      out = 0;
      return true;
    }
    unsigned __int128 m = n < 0 ? -static_cast<unsigned __int128>(n) : static_cast<unsigned __int128>(n);
    int x = e;
    const int b = bits_unsigned(m);
    // the value is at least 2^(b - 1 + e): below 2^-1022 it may round to a
    // subnormal, and rounding twice (to 53 bits, then in ldexp) could be wrong
    if(b - 1 + e < -1022) return false;
    if(b > 53) {
      const int k = b - 53;
      const unsigned __int128 rest = m & ((static_cast<unsigned __int128>(1) << k) - 1);
      const unsigned __int128 halfway = static_cast<unsigned __int128>(1) << (k - 1);
      m >>= k;
      x += k;
      if(rest > halfway || (rest == halfway && (m & 1) != 0)) {
        ++m;
        if(m == (static_cast<unsigned __int128>(1) << 53)) {
          m >>= 1;
          ++x;
        }
      }
    }
    double r;
    if(!normal_double(static_cast<std::uint64_t>(m), x, r)) return false;
    out = n < 0 ? -r : r;
    return true;
  }

private:
  static Dyadic failed()
  {
    Dyadic d;
    d.ok = false;
    return d;
  }
  static int bits_unsigned(unsigned __int128 m)
  {
    const std::uint64_t h = std::uint64_t(m >> 64), l = std::uint64_t(m);
    return h != 0 ? 128 - __builtin_clzll(h) : (l != 0 ? 64 - __builtin_clzll(l) : 0);
  }
  static int bits(__int128 n) { return bits_unsigned(n < 0 ? -static_cast<unsigned __int128>(n) : static_cast<unsigned __int128>(n)); }
};

/// The coordinates of the disk tangent to the three sites `s` (Site, over
/// points with double coordinates) that the linear relations of its
/// axis-parallel sites fix, exactly: for i = 0, 1, 2 (x and y of the centre,
/// the radius) sets known[i] and v[i] where fixed, and returns whether any
/// is.  The disk must exist (its branches decided): each
/// segment site's line is tangent to it, on the segment's left, and it goes
/// through each point site.  The relations:
/// - a vertical segment at x = a: x = a - r going up, a + r going down (a
///   horizontal one at y = b: y = b + r going right, b - r going left);
/// - two point sites of equal y: x is the midpoint of theirs (of equal x: y);
/// - a point site on the line of a vertical segment: the disk touches the
///   line there, y is the point's (on a horizontal one: x);
/// - two segments one after the other on one line (a flat vertex): the disk
///   touches the line at their common end, which counts as a point site.
/// Every relation is checked against the values found; if one fails (it
/// cannot, for a disk that exists) or a value does not fit a Dyadic,
/// nothing is found.
template <class Site>
bool axis_aligned_disk_exact(const Site* s, Dyadic v[3], bool known[3])
{
  known[0] = known[1] = known[2] = false;
  // x = (known value), and x = a + sigma r, for x (0) and y (1)
  // (at most 3 segments times 3 points on the disk, and 3 pairs of points)
  Dyadic fixed[2][12];
  int n_fixed[2] = {0, 0};
  Dyadic offset[2][3];
  int sigma[2][3];
  int n_offset[2] = {0, 0};
  auto coordinate = [](const auto& p, int axis) { return axis == 0 ? p.x() : p.y(); };
  // the points on the disk: the point sites, and the common end of two
  // segments one after the other on a vertical or horizontal line
  typedef std::decay_t<decltype(s[0].p)> Point;
  const Point* on_disk[3];
  int n_on_disk = 0;
  for(int i = 0; i < 3; ++i) {
    if(s[i].is_point) {
      on_disk[n_on_disk++] = &s[i].p;
      continue;
    }
    for(int j = 0; j < 3; ++j) {
      if(j == i || s[j].is_point || !(s[i].q.x() == s[j].p.x() && s[i].q.y() == s[j].p.y()) ||
         (s[i].p.x() == s[i].q.x() && s[i].p.y() == s[i].q.y()) || (s[j].p.x() == s[j].q.x() && s[j].p.y() == s[j].q.y()))
        continue;
      const bool vertical = s[i].p.x() == s[i].q.x() && s[j].p.x() == s[j].q.x() &&
                            (s[i].q.y() > s[i].p.y()) == (s[j].q.y() > s[j].p.y());
      const bool horizontal = s[i].p.y() == s[i].q.y() && s[j].p.y() == s[j].q.y() &&
                              (s[i].q.x() > s[i].p.x()) == (s[j].q.x() > s[j].p.x());
      if(vertical || horizontal)
        on_disk[n_on_disk++] = &s[i].q;
    }
  }
  for(int i = 0; i < 3; ++i) {
    if(s[i].is_point) continue;
    for(int axis = 0; axis < 2; ++axis) {
      // a segment at constant `axis` coordinate (not of length zero)
      if(coordinate(s[i].p, axis) != coordinate(s[i].q, axis) ||
         coordinate(s[i].p, 1 - axis) == coordinate(s[i].q, 1 - axis))
        continue;
      const bool increasing = coordinate(s[i].q, 1 - axis) > coordinate(s[i].p, 1 - axis);
      offset[axis][n_offset[axis]] = Dyadic::of(coordinate(s[i].p, axis));
      // the left of a vertical segment going up is at smaller x; of a
      // horizontal one going right, at larger y
      sigma[axis][n_offset[axis]] = (axis == 0) == increasing ? -1 : 1;
      ++n_offset[axis];
      for(int j = 0; j < n_on_disk; ++j)
        if(coordinate(*on_disk[j], axis) == coordinate(s[i].p, axis))
          fixed[1 - axis][n_fixed[1 - axis]++] = Dyadic::of(coordinate(*on_disk[j], 1 - axis));
    }
  }
  for(int i = 0; i < n_on_disk; ++i)
    for(int j = i + 1; j < n_on_disk; ++j)
      for(int axis = 0; axis < 2; ++axis)
        if(coordinate(*on_disk[i], 1 - axis) == coordinate(*on_disk[j], 1 - axis) &&
           coordinate(*on_disk[i], axis) != coordinate(*on_disk[j], axis))
          fixed[axis][n_fixed[axis]++] =
            (Dyadic::of(coordinate(*on_disk[i], axis)) + Dyadic::of(coordinate(*on_disk[j], axis))).half();
  if(n_fixed[0] + n_fixed[1] == 0 && n_offset[0] < 2 && n_offset[1] < 2)
    return false;

  auto set = [&](int i, const Dyadic& d) {
    if(!known[i] && d.ok) {
      v[i] = d;
      known[i] = true;
    }
  };
  for(int axis = 0; axis < 2; ++axis) {
    if(n_fixed[axis] > 0) set(axis, fixed[axis][0]);
    // two parallel lines, on opposite sides: a1 + s1 r = a2 - s1 r
    for(int i = 0; i < n_offset[axis]; ++i)
      for(int j = i + 1; j < n_offset[axis]; ++j)
        if(sigma[axis][i] != sigma[axis][j]) {
          set(axis, (offset[axis][i] + offset[axis][j]).half());
          const Dyadic d = (offset[axis][j] - offset[axis][i]).half();
          set(2, sigma[axis][i] > 0 ? d : -d);
        }
  }
  // x = a + sigma r: r from x, then x or y from r (twice: x -> r -> y)
  for(int round = 0; round < 2; ++round)
    for(int axis = 0; axis < 2; ++axis)
      if(n_offset[axis] > 0) {
        if(known[axis] && !known[2]) {
          const Dyadic d = v[axis] - offset[axis][0];
          set(2, sigma[axis][0] > 0 ? d : -d);
        }
        if(known[2] && !known[axis])
          set(axis, sigma[axis][0] > 0 ? offset[axis][0] + v[2] : offset[axis][0] - v[2]);
      }
  if(!(known[0] || known[1] || known[2]))
    return false;
  // every relation holds, and the radius is positive
  if(known[2] && v[2].sign() <= 0)
    return false;
  for(int axis = 0; axis < 2; ++axis) {
    if(!known[axis]) continue;
    for(int i = 0; i < n_fixed[axis]; ++i)
      if(!(fixed[axis][i] == v[axis])) return false;
    if(known[2])
      for(int i = 0; i < n_offset[axis]; ++i)
        if(!(v[axis] == (sigma[axis][i] > 0 ? offset[axis][i] + v[2] : offset[axis][i] - v[2]))) return false;
  }
  return true;
}

/// The same, correctly rounded (ties to even): sets found[i] and value[i]
/// for the coordinates fixed, and returns whether any is.
template <class Site>
bool axis_aligned_disk(const Site* s, bool found[3], double value[3])
{
  Dyadic v[3];
  bool known[3];
  if(!axis_aligned_disk_exact(s, v, known))
    return false;
  bool any = false;
  for(int i = 0; i < 3; ++i)
    if(known[i] && v[i].to_double(value[i])) {
      value[i] += 0.0;   // (an exact zero as +0)
      found[i] = true;
      any = true;
    }
  return any;
}

/// Whether the disks of the triples `s` and `t` (which exist) are one disk,
/// as the relations of their axis-parallel sites show: every coordinate of
/// both fixed, and equal.  False where that does not show it.
template <class Site>
bool same_axis_aligned_disk(const Site* s, const Site* t)
{
  Dyadic a[3], b[3];
  bool known_a[3], known_b[3];
  if(!axis_aligned_disk_exact(s, a, known_a) || !known_a[0] || !known_a[1] || !known_a[2] ||
     !axis_aligned_disk_exact(t, b, known_b) || !known_b[0] || !known_b[1] || !known_b[2])
    return false;
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_AXIS_ALIGNED_DISK_H
