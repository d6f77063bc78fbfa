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
// Exact numbers a + b sqrt(D), with a, b, D rational and D > 0: the stage of
// the filtered traits after the double intervals (and after the MPFR
// intervals, where the coordinates are not short), before the nested-root
// numbers (Nested_root_number.h).  The decisions that
// reach it are almost always exact ties (two equal event times, a zero
// discriminant).  With axis-parallel input edges (mazes, CAD
// parts) the tangent circles are rational and an event time adds at most one
// square root, so such ties are decided here, in rational arithmetic, faster
// than by the general nested-root numbers.
//
// An operation that would leave the form (two different square roots, a
// root of a number that is not rational, a division by zero) throws
// Not_one_root, and the caller goes on to the nested-root numbers.
//
// The numbers are written once for two rational types: Small_rational (no
// heap, tried first) and Gmpq (when a Small_rational result overflows).

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_ONE_ROOT_RATIONAL_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_ONE_ROOT_RATIONAL_H

#include <CGAL/Progressive_medial_axis_2/internal/Gmp_rational.h>
#include <CGAL/Progressive_medial_axis_2/internal/Small_rational.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <exception>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// Thrown when a value leaves the form a + b sqrt(D).
struct Not_one_root : std::exception {
  const char* what() const noexcept override { return "not a one-root number"; }
};

/// Whether q is the square of a rational; its root in `root` if so.
inline bool rational_square_root(const Gmpq& q, Gmpq& root)
{
  if(CGAL::sign(q) == NEGATIVE)
    return false;
  // a Gmpq is canonical (coprime numerator and denominator): q is a square
  // iff both are
  const mpz_srcptr num = mpq_numref(q.mpq()), den = mpq_denref(q.mpq());
  if(!mpz_perfect_square_p(num) || !mpz_perfect_square_p(den))
    return false;
  Gmpq r;
  mpz_sqrt(mpq_numref(r.mpq()), num);
  mpz_sqrt(mpq_denref(r.mpq()), den);
  root = r;
  return true;
}

/// The double nearest to q (ties to even).
inline double nearest_double(const Gmpq& q)
{
  mpfr_t x;
  mpfr_init2(x, 53);
  mpfr_set_q(x, q.mpq(), MPFR_RNDN);
  const double r = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return r;
}

/// The value of a rational type as a Gmpq, its sign and an interval.
inline const Gmpq& to_gmpq(const Gmpq& q) { return q; }
inline Gmpq to_gmpq(const Small_rational& q) { return q.to_gmpq(); }
inline Gmpq to_gmpq(const Gmp_rational& q) { return q.to_gmpq(); }
inline Gmp_rational to_big(const Small_rational& q) { return Gmp_rational(q.to_gmpq()); }
inline const Gmp_rational& to_big(const Gmp_rational& q) { return q; }
inline Sign q_sign(const Gmpq& q) { return CGAL::sign(q); }
inline Sign q_sign(const Small_rational& q) { return q.sign(); }
inline Sign q_sign(const Gmp_rational& q) { return q.sign(); }
inline Interval_nt<false> q_interval(const Gmpq& q) { return CGAL::to_interval(q); }
inline Interval_nt<false> q_interval(const Small_rational& q) { return q.to_interval(); }
inline Interval_nt<false> q_interval(const Gmp_rational& q) { return q.to_interval(); }

/// sign(u + v sqrt(m)), m > 0.
template <class Q>
Sign sign_one_root(const Q& u, const Q& v, const Q& m)
{
  const Sign su = q_sign(u), sv = q_sign(v);
  if(sv == ZERO)
    return su;
  if(su == ZERO || su == sv)
    return sv;
  // opposite signs: compare u^2 with v^2 m
  const Sign s = q_sign(u * u - v * v * m);
  return s == ZERO ? ZERO : (s == POSITIVE ? su : sv);
}

/// a + b sqrt(d) over the rational type Q: Gmpq, or Small_rational (which
/// throws Small_rational_overflow when a result does not fit).
template <class Q>
class One_root_number
{
public:
  One_root_number() {}
  One_root_number(int i) : a_(i) {}
  One_root_number(double d) : a_(d) {}
  explicit One_root_number(const Q& a) : a_(a) {}
  One_root_number(const Q& a, const Q& b, const Q& d) : a_(a), b_(b), d_(d)
  {
    if(q_sign(b_) == ZERO)
      d_ = Q(0);
  }

  const Q& a() const { return a_; }
  const Q& b() const { return b_; }
  const Q& d() const { return d_; } ///< 0 for a rational number
  bool is_rational() const { return q_sign(b_) == ZERO; }
  Sign sign() const { return sign_one_root(a_, b_, d_); }

  /// The same number with unbounded (GMP) coefficients.
  One_root_number<Gmp_rational> to_big() const
  {
    return One_root_number<Gmp_rational>(internal::to_big(a_), internal::to_big(b_), internal::to_big(d_));
  }

  /// An interval that contains the value.
  Interval_nt<false> to_interval() const
  {
    Protect_FPU_rounding<true> protection;
    Interval_nt<false> r(q_interval(a_));
    if(!is_rational())
      r += Interval_nt<false>(q_interval(b_)) * CGAL::sqrt(Interval_nt<false>(q_interval(d_)));
    return r;
  }

  /// The value correctly rounded to double (rational values), or to within
  /// one unit in the last place.
  double to_double() const
  {
    const Gmpq a = internal::to_gmpq(a_);
    if(is_rational())
      return nearest_double(a);
    // a + b sqrt(d) at 256 bits (an irrational number is never a tie
    // between two doubles)
    mpfr_t x;
    const Gmpq b = internal::to_gmpq(b_), d = internal::to_gmpq(d_);
    mpfr_t y;
    mpfr_init2(x, 256);
    mpfr_init2(y, 256);
    mpfr_set_q(x, d.mpq(), MPFR_RNDN);
    mpfr_sqrt(x, x, MPFR_RNDN);
    mpfr_set_q(y, b.mpq(), MPFR_RNDN);
    mpfr_mul(x, x, y, MPFR_RNDN);
    mpfr_set_q(y, a.mpq(), MPFR_RNDN);
    mpfr_add(x, x, y, MPFR_RNDN);
    mpfr_clear(y);
    const double r = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clear(x);
    return r;
  }

  One_root_number operator-() const { return is_rational() ? One_root_number(-a_) : One_root_number(-a_, -b_, d_); }

  friend One_root_number operator+(const One_root_number& x, const One_root_number& y)
  {
    if(x.is_rational() && y.is_rational())
      return One_root_number(x.a_ + y.a_);
    Q yb, d;
    align(x, y, yb, d);
    return One_root_number(x.a_ + y.a_, x.b_ + yb, d);
  }
  friend One_root_number operator-(const One_root_number& x, const One_root_number& y) { return x + (-y); }
  friend One_root_number operator*(const One_root_number& x, const One_root_number& y)
  {
    if(x.is_rational() && y.is_rational())
      return One_root_number(x.a_ * y.a_);
    Q yb, d;
    align(x, y, yb, d);
    return One_root_number(x.a_ * y.a_ + x.b_ * yb * d, x.a_ * yb + x.b_ * y.a_, d);
  }
  friend One_root_number operator/(const One_root_number& x, const One_root_number& y)
  {
    if(y.is_rational()) {
      if(q_sign(y.a_) == ZERO)
        throw Not_one_root();
      return One_root_number(x.a_ / y.a_, x.b_ / y.a_, x.d_);
    }
    // multiply by the conjugate of y
    const Q n = y.a_ * y.a_ - y.b_ * y.b_ * y.d_;
    if(q_sign(n) == ZERO)
      throw Not_one_root();
    const One_root_number conj(y.a_ / n, -y.b_ / n, y.d_);
    return x * conj;
  }
  One_root_number& operator+=(const One_root_number& y) { return *this = *this + y; }
  One_root_number& operator-=(const One_root_number& y) { return *this = *this - y; }
  One_root_number& operator*=(const One_root_number& y) { return *this = *this * y; }
  One_root_number& operator/=(const One_root_number& y) { return *this = *this / y; }

  /// The sign of x - y; x and y may have different roots.
  friend Sign sign_of_difference(const One_root_number& x, const One_root_number& y)
  {
    if(x.is_rational() || y.is_rational() || x.d_ == y.d_ || roots_commensurable(x, y)) {
      const One_root_number z = x - y;
      return sign_one_root(z.a_, z.b_, z.d_);
    }
    // L = (x.a - y.a) + x.b sqrt(x.d), R = y.b sqrt(y.d): sign(L - R)
    const Q A = x.a_ - y.a_;
    const Sign sl = sign_one_root(A, x.b_, x.d_), sr = q_sign(y.b_);
    if(sl != sr || sl == ZERO)
      return sl > sr ? POSITIVE : (sl < sr ? NEGATIVE : ZERO);
    // same sign s: sign(L - R) = s sign(L^2 - R^2)
    const Sign s2 = sign_one_root(A * A + x.b_ * x.b_ * x.d_ - y.b_ * y.b_ * y.d_, Q(2) * A * x.b_, x.d_);
    return sl == POSITIVE ? s2 : Sign(-int(s2));
  }

  friend bool operator<(const One_root_number& x, const One_root_number& y) { return sign_of_difference(x, y) == NEGATIVE; }
  friend bool operator>(const One_root_number& x, const One_root_number& y) { return sign_of_difference(x, y) == POSITIVE; }
  friend bool operator<=(const One_root_number& x, const One_root_number& y) { return sign_of_difference(x, y) != POSITIVE; }
  friend bool operator>=(const One_root_number& x, const One_root_number& y) { return sign_of_difference(x, y) != NEGATIVE; }
  friend bool operator==(const One_root_number& x, const One_root_number& y) { return sign_of_difference(x, y) == ZERO; }
  friend bool operator!=(const One_root_number& x, const One_root_number& y) { return sign_of_difference(x, y) != ZERO; }

  friend One_root_number abs(const One_root_number& x) { return x < One_root_number(0) ? -x : x; }

  /// The square root of a rational number; throws Not_one_root otherwise.
  friend One_root_number sqrt(const One_root_number& x)
  {
    if(!x.is_rational() || q_sign(x.a_) == NEGATIVE)
      throw Not_one_root();
    Q r;
    if(rational_square_root(x.a_, r))
      return One_root_number(r);
    return One_root_number(Q(0), Q(1), x.a_);
  }

private:
  // sqrt(x.d) / sqrt(y.d) is rational
  static bool roots_commensurable(const One_root_number& x, const One_root_number& y)
  {
    Q r;
    return rational_square_root(x.d_ / y.d_, r);
  }

  // y's root coefficient over x's root (yb), and the common root d
  static void align(const One_root_number& x, const One_root_number& y, Q& yb, Q& d)
  {
    if(y.is_rational()) {
      yb = Q(0);
      d = x.d_;
    } else if(x.is_rational() || x.d_ == y.d_) {
      yb = y.b_;
      d = y.d_;
    } else {
      // sqrt(y.d) = k sqrt(x.d) with k = sqrt(y.d / x.d) rational, or give up
      Q k;
      if(!rational_square_root(y.d_ / x.d_, k))
        throw Not_one_root();
      yb = y.b_ * k;
      d = x.d_;
    }
  }

  Q a_, b_, d_;
};

typedef One_root_number<Gmp_rational> One_root_rational;
typedef One_root_number<Small_rational> Small_one_root;

/// sign(B + C sqrt(rho)), rho >= 0.
template <class N>
Sign sign_plus_root(const N& B, const N& C, const N& rho)
{
  const Sign sb = B.sign(), sc = C.sign();
  if(sc == ZERO || rho.sign() == ZERO)
    return sb;
  if(sb == ZERO || sb == sc)
    return sc;
  const Sign s = (B * B - C * C * rho).sign();
  return s == ZERO ? ZERO : (s == POSITIVE ? sb : sc);
}

/// An event time alpha + sqrt(rho) with alpha and rho one-root numbers and
/// rho >= 0: a vanishing time (the far end of a chord of a circle whose
/// centre and radius are one-root numbers) or, with rho = 0, any other time.
template <class N>
struct One_root_sqrt_t {
  N alpha, rho;

  Interval_nt<false> to_interval() const
  {
    Protect_FPU_rounding<true> protection;
    Interval_nt<false> r = rho.to_interval();
    if(r.inf() < 0)
      r = Interval_nt<false>(0, (std::max)(0.0, r.sup()));
    return alpha.to_interval() + CGAL::sqrt(r);
  }

  /// The sign of x - y.  Throws Not_one_root when the numbers of x and y
  /// do not share a root.
  friend Sign sign_of_difference(const One_root_sqrt_t& x, const One_root_sqrt_t& y)
  {
    const N A = x.alpha - y.alpha;
    const N one(1), minus_one(-1), two(2);
    if(y.rho.sign() == ZERO)
      return sign_plus_root(A, one, x.rho);
    if(x.rho.sign() == ZERO)
      return sign_plus_root(A, minus_one, y.rho);
    const Sign sa = A.sign(), sr = (x.rho - y.rho).sign();
    if(sa == ZERO)
      return sr;
    if(sr == ZERO || sa == sr)
      return sa;
    if(sa == POSITIVE) // A > 0, sqrt(x.rho) < sqrt(y.rho): sign((A + sqrt(x.rho))^2 - y.rho)
      return sign_plus_root(A * A + x.rho - y.rho, two * A, x.rho);
    // A < 0, sqrt(x.rho) > sqrt(y.rho): -sign((-A + sqrt(y.rho))^2 - x.rho)
    return Sign(-int(sign_plus_root(A * A + y.rho - x.rho, minus_one * two * A, y.rho)));
  }
};

typedef One_root_sqrt_t<One_root_rational> One_root_sqrt;
typedef One_root_sqrt_t<Small_one_root> Small_one_root_sqrt;

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_ONE_ROOT_RATIONAL_H
