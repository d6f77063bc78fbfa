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
// Exact rationals with 128-bit numerator and denominator, for the fast path
// of the one-root stage of the filtered traits.  The exact ties of
// degenerate input (integer grids, CAD parts) come in thousands; their
// numbers are small, and GMP's heap-allocated rationals spent most of the
// time of a tie in malloc and free.  This type lives on the stack; any
// result that does not fit throws Small_rational_overflow, and the caller
// redoes the computation with Gmpq.  (Boost.Multiprecision's fixed-width
// rationals would serve, but its checked 128-bit integers have no cheap gcd
// and reduce at every operation through generic code; the type needed is a
// hundred lines.)

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_SMALL_RATIONAL_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_SMALL_RATIONAL_H

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Progressive_medial_axis_2/internal/Float_bits.h>
#include <CGAL/enum.h>

#include <cmath>
#include <cstdint>
#include <exception>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// Thrown when a Small_rational result does not fit in 128 bits.
struct Small_rational_overflow : std::exception {
  const char* what() const noexcept override { return "small rational overflow"; }
};

class Small_rational
{
public:
  typedef __int128 Int;
  typedef unsigned __int128 Uint;

  Small_rational() : n_(0), d_(1) {}
  Small_rational(int i) : n_(i), d_(1) {}
  /// The exact value of a finite double; throws if it needs more than 120 bits.
  Small_rational(double x) : n_(0), d_(1)
  {
    if(x == 0) return;
    if(!std::isfinite(x)) throw Small_rational_overflow();
    if(std::fabs(x) < 4611686018427387904.0) {   // 2^62: the common case of integer coordinates
      const std::int64_t i = std::int64_t(x);
      if(double(i) == x) {
        n_ = i;
        return;
      }
    }
    int e;
    std::int64_t mi;
    integer_and_exponent(x, mi, e);   // x = mi 2^e
    const int zeros = __builtin_ctzll(std::uint64_t(mi < 0 ? -mi : mi));
    mi >>= zeros;
    e += zeros;
    if(e >= 0) {
      if(e > 62) throw Small_rational_overflow();
      n_ = Int(mi) << e;
    } else {
      if(-e > 120) throw Small_rational_overflow();
      n_ = mi;
      d_ = Int(1) << (-e);
    }
  }

  /// The value of a Gmpq; throws if it does not fit.
  explicit Small_rational(const Gmpq& q) : n_(0), d_(1)
  {
    const mpz_srcptr num = mpq_numref(q.mpq()), den = mpq_denref(q.mpq());
    if(mpz_sizeinbase(num, 2) > 126 || mpz_sizeinbase(den, 2) > 126) throw Small_rational_overflow();
    n_ = from_mpz(num);
    d_ = from_mpz(den);
  }

  const Int& numerator() const { return n_; }
  const Int& denominator() const { return d_; }

  Sign sign() const { return n_ > 0 ? POSITIVE : (n_ < 0 ? NEGATIVE : ZERO); }

  Small_rational operator-() const
  {
    if(n_ == min_int()) throw Small_rational_overflow();
    return raw(-n_, d_);
  }

  friend Small_rational operator*(const Small_rational& a, const Small_rational& b)
  {
    if(a.n_ == 0 || b.n_ == 0) return Small_rational();
    if(a.d_ == 1 && b.d_ == 1) return raw(mul(a.n_, b.n_), 1);
    const Int g1 = gcd(a.n_, b.d_), g2 = gcd(b.n_, a.d_);
    return raw(mul(quotient(a.n_, g1), quotient(b.n_, g2)), mul(quotient(a.d_, g2), quotient(b.d_, g1)));
  }
  friend Small_rational operator/(const Small_rational& a, const Small_rational& b)
  {
    if(b.n_ == 0) throw Small_rational_overflow();   // not a number: let the caller decide with Gmpq
    if(a.n_ == 0) return Small_rational();
    const Int g1 = gcd(a.n_, b.n_), g2 = gcd(a.d_, b.d_);
    Int n = mul(quotient(a.n_, g1), quotient(b.d_, g2)), d = mul(quotient(a.d_, g2), quotient(b.n_, g1));
    if(d < 0) {
      if(n == min_int() || d == min_int()) throw Small_rational_overflow();
      n = -n;
      d = -d;
    }
    return raw(n, d);
  }
  friend Small_rational operator+(const Small_rational& a, const Small_rational& b) { return sum(a, b, false); }
  friend Small_rational operator-(const Small_rational& a, const Small_rational& b) { return sum(a, b, true); }
  Small_rational& operator+=(const Small_rational& b) { return *this = *this + b; }
  Small_rational& operator-=(const Small_rational& b) { return *this = *this - b; }
  Small_rational& operator*=(const Small_rational& b) { return *this = *this * b; }
  Small_rational& operator/=(const Small_rational& b) { return *this = *this / b; }

  friend bool operator==(const Small_rational& a, const Small_rational& b) { return a.n_ == b.n_ && a.d_ == b.d_; }
  friend bool operator!=(const Small_rational& a, const Small_rational& b) { return !(a == b); }

  /// Whether the value is the square of a rational, with its root.
  friend bool rational_square_root(const Small_rational& q, Small_rational& root)
  {
    if(q.n_ < 0) return false;
    Int rn, rd;
    if(!integer_root(q.n_, rn) || !integer_root(q.d_, rd)) return false;
    root = raw(rn, rd);
    return true;
  }

  Interval_nt<false> to_interval() const
  {
    Protect_FPU_rounding<true> protection;
    return int_interval(n_) / int_interval(d_);
  }

  Gmpq to_gmpq() const { return Gmpq(to_mpz(n_), to_mpz(d_)); }

private:
  static Int min_int() { return Int(Uint(1) << 127); }

  static Small_rational raw(Int n, Int d)
  {
    Small_rational r;
    r.n_ = n;
    r.d_ = d;
    return r;
  }

  static bool fits_64(Int x) { return x >= Int(INT64_MIN) && x <= Int(INT64_MAX); }

  // The 128-bit operations of libgcc (__divti3, __muloti4) cost tens of
  // cycles; the numbers of grid coordinates mostly fit in 64 bits.
  static Int mul(Int a, Int b)
  {
    if(fits_64(a) && fits_64(b)) return limited(Int(std::int64_t(a)) * Int(std::int64_t(b)));   // cannot overflow
    Int r;
    if(__builtin_mul_overflow(a, b, &r)) throw Small_rational_overflow();
    return limited(r);
  }
  static Int add(Int a, Int b)
  {
    Int r;
    if(__builtin_add_overflow(a, b, &r)) throw Small_rational_overflow();
    return limited(r);
  }
#ifdef CGAL_PMA2_SMALL_RATIONAL_TEST_BITS
  // For the tests only: products and sums of CGAL_PMA2_SMALL_RATIONAL_TEST_BITS
  // bits or more overflow, so that the fallbacks to GMP rationals run in the
  // middle of real computations (no shape overflows 128 bits with short
  // coordinates).
  static Int limited(Int r)
  {
    static_assert(CGAL_PMA2_SMALL_RATIONAL_TEST_BITS > 0 && CGAL_PMA2_SMALL_RATIONAL_TEST_BITS < 127, "bits in (0, 127)");
    const Int m = Int(1) << CGAL_PMA2_SMALL_RATIONAL_TEST_BITS;
    if(r >= m || r <= -m) throw Small_rational_overflow();
    return r;
  }
#else
  static Int limited(Int r) { return r; }
#endif
  // a / g for g > 0 dividing a
  static Int quotient(Int a, Int g)
  {
    if(g == 1) return a;
    if(fits_64(a) && fits_64(g)) return Int(std::int64_t(a) / std::int64_t(g));
    return a / g;
  }

  static int ctz(Uint x)
  {
    const std::uint64_t lo = std::uint64_t(x);
    return lo != 0 ? __builtin_ctzll(lo) : 64 + __builtin_ctzll(std::uint64_t(x >> 64));
  }

  // binary gcd of u, v > 0
  static std::uint64_t gcd_64(std::uint64_t u, std::uint64_t v)
  {
    const int shift = __builtin_ctzll(u | v);
    u >>= __builtin_ctzll(u);
    do {
      v >>= __builtin_ctzll(v);
      if(u > v) {
        const std::uint64_t t = v;
        v = u;
        u = t;
      }
      v -= u;
    } while(v != 0);
    return u << shift;
  }

  // gcd(|a|, |b|) > 0 for a, b not both zero (binary gcd)
  static Int gcd(Int a, Int b)
  {
    Uint u = a < 0 ? Uint(0) - Uint(a) : Uint(a), v = b < 0 ? Uint(0) - Uint(b) : Uint(b);
    if(u == 0) return Int(v);
    if(v == 0) return Int(u);
    if(u == 1 || v == 1) return 1;
    if(((u | v) >> 64) == 0) return Int(gcd_64(std::uint64_t(u), std::uint64_t(v)));
    const int shift = ctz(u | v);
    u >>= ctz(u);
    do {
      v >>= ctz(v);
      if(u > v) {
        const Uint t = v;
        v = u;
        u = t;
      }
      v -= u;
    } while(v != 0);
    return Int(u << shift);
  }

  static Small_rational sum(const Small_rational& a, const Small_rational& b, bool subtract)
  {
    if(subtract && b.n_ == min_int()) throw Small_rational_overflow();
    const Int bn = subtract ? -b.n_ : b.n_;
    if(a.n_ == 0) return raw(bn, b.d_);
    if(bn == 0) return a;
    if(a.d_ == b.d_) {
      const Int n = add(a.n_, bn);
      if(n == 0) return Small_rational();
      const Int g = gcd(n, a.d_);
      return raw(quotient(n, g), quotient(a.d_, g));
    }
    const Int g = gcd(a.d_, b.d_);
    const Int n = add(mul(a.n_, quotient(b.d_, g)), mul(bn, quotient(a.d_, g)));
    if(n == 0) return Small_rational();
    const Int d = mul(quotient(a.d_, g), b.d_);
    const Int h = gcd(n, d);
    return raw(quotient(n, h), quotient(d, h));
  }

  // the integer square root of x >= 0, if x is a perfect square
  static bool integer_root(Int x, Int& root)
  {
    if(x < 0) return false;
    const Uint u = Uint(x);
    // (in 64-bit halves: the conversions of 128-bit integers are calls into
    // libgcc; r < 2^64 as x < 2^127)
    const double estimate = double(std::int64_t(x >> 64)) * 18446744073709551616.0 + double(std::uint64_t(x));
    Uint r = Uint(std::uint64_t(std::sqrt(estimate)));
    // correct the floating-point estimate (r < 2^64, so r^2 fits)
    while(r > 0 && r * r > u) --r;
    while((r + 1) * (r + 1) <= u) ++r;
    root = Int(r);
    return r * r == u;
  }

  static Interval_nt<false> int_interval(Int x)
  {
    const bool negative = x < 0;
    const Uint u = negative ? Uint(0) - Uint(x) : Uint(x);
    // each 64-bit half may be rounded to double: widen it by one unit
    auto half = [](std::uint64_t x) {
      const double d = double(x);
      const bool exact = d < 18446744073709551616.0 && std::uint64_t(d) == x;
      return exact ? Interval_nt<false>(d) : Interval_nt<false>(next_toward_zero(d), next_up(d));
    };
    Interval_nt<false> r = half(std::uint64_t(u >> 64)) * Interval_nt<false>(18446744073709551616.0) + half(std::uint64_t(u));
    return negative ? -r : r;
  }

  static Int from_mpz(mpz_srcptr z)
  {
    Uint u = 0;
    const std::size_t limbs = mpz_size(z);
    for(std::size_t i = limbs; i-- > 0;) u = (u << (8 * sizeof(mp_limb_t) - 1) << 1) | Uint(mpz_getlimbn(z, i));
    return mpz_sgn(z) < 0 ? -Int(u) : Int(u);
  }

  static Gmpz to_mpz(Int x)
  {
    const bool negative = x < 0;
    const Uint u = negative ? Uint(0) - Uint(x) : Uint(x);
    Gmpz hi(static_cast<unsigned long>(std::uint64_t(u >> 64)));
    Gmpz lo(static_cast<unsigned long>(std::uint64_t(u)));
    Gmpz r = hi * Gmpz(static_cast<unsigned long>(1) << 32) * Gmpz(static_cast<unsigned long>(1) << 32) + lo;
    return negative ? -r : r;
  }

  Int n_, d_;   // d_ > 0, gcd(n_, d_) = 1
};

inline Sign sign(const Small_rational& q) { return q.sign(); }
inline Interval_nt<false> to_interval(const Small_rational& q) { return q.to_interval(); }

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_SMALL_RATIONAL_H
