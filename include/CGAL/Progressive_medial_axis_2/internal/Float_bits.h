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
// The neighbours of a double, and a double taken apart into an integer and a
// power of two, from its bits.  (Hand-written: std::nextafter, std::frexp and
// std::ldexp are calls into libm, whose first call in a process binds the
// symbol and faults in libm's pages: on a glyph of 8 vertices, 2 of the 37
// page faults of the one-shot, RESULTS.md, "The first call on tiny
// polygons", sixty-sixth session; boost::math::float_next calls frexp and
// ldexp in turn.)

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_FLOAT_BITS_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_FLOAT_BITS_H

#include <cstdint>
#include <cstring>
#include <limits>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

static_assert(std::numeric_limits<double>::is_iec559, "IEEE 754 binary64 doubles");

inline std::uint64_t bits_of(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

inline double double_of_bits(std::uint64_t b)
{
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

/// std::nextafter(x, +infinity): the smallest double above x (x itself for
/// +infinity and NaN).
inline double next_up(double x)
{
  if(!(x < std::numeric_limits<double>::infinity()))
    return x;
  if(x == 0)
    return std::numeric_limits<double>::denorm_min();
  const std::uint64_t b = bits_of(x);
  return double_of_bits(x > 0 ? b + 1 : b - 1);
}

/// std::nextafter(x, -infinity).
inline double next_down(double x) { return -next_up(-x); }

/// std::nextafter(x, 0.0).
inline double next_toward_zero(double x) { return x > 0 ? next_down(x) : (x < 0 ? next_up(x) : (x == 0 ? 0.0 : x)); }

/// The finite double x as n 2^e exactly, n an integer of at most 53 bits
/// (n = 0 for a zero).
inline void integer_and_exponent(double x, std::int64_t& n, int& e)
{
  const std::uint64_t b = bits_of(x);
  const int biased = int((b >> 52) & 0x7ff);
  const std::int64_t f = std::int64_t(b & ((std::uint64_t(1) << 52) - 1));
  n = biased == 0 ? f : f | (std::int64_t(1) << 52);   // (a subnormal: no hidden bit)
  e = (biased == 0 ? 1 : biased) - 1075;
  if(b >> 63)
    n = -n;
}

/// m 2^e for 0 < m < 2^53, in `out`, where it is a normal double (then
/// exact); false where it is above the largest double or below the
/// smallest normal one.
inline bool normal_double(std::uint64_t m, int e, double& out)
{
  if(m == 0 || (m >> 53) != 0)
    return false;
  const int shift = __builtin_clzll(m) - 11;   // to 53 bits
  m <<= shift;
  e -= shift;
  const int biased = e + 1075;
  if(biased <= 0 || biased >= 2047)
    return false;
  out = double_of_bits((std::uint64_t(biased) << 52) | (m & ((std::uint64_t(1) << 52) - 1)));
  return true;
}

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_FLOAT_BITS_H
