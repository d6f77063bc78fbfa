// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Exact numbers a + b sqrt(D), with a, b, D rational (GMP) and D > 0: the
// third stage of the filtered traits, between the MPFR intervals and the
// nested-root numbers (Nested_root_number.h).  The decisions that reach it are exact ties (two equal event
// times, a zero discriminant).  With axis-parallel input edges (mazes, CAD
// parts) the tangent circles are rational and an event time adds at most one
// square root, so such ties are decided here, in rational arithmetic, faster
// than by the general nested-root numbers.
//
// An operation that would leave the form (two different square roots, a
// root of a number that is not rational, a division by zero) throws
// Not_one_root, and the caller goes on to the nested-root numbers.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_ONE_ROOT_RATIONAL_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_ONE_ROOT_RATIONAL_H

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <exception>

namespace CGAL {
namespace PMA2 {
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

/// sign(u + v sqrt(m)), m > 0.
inline Sign sign_one_root(const Gmpq& u, const Gmpq& v, const Gmpq& m)
{
  const Sign su = CGAL::sign(u), sv = CGAL::sign(v);
  if(sv == ZERO)
    return su;
  if(su == ZERO || su == sv)
    return sv;
  // opposite signs: compare u^2 with v^2 m
  const Sign s = CGAL::sign(u * u - v * v * m);
  return s == ZERO ? ZERO : (s == POSITIVE ? su : sv);
}

class One_root_rational
{
public:
  One_root_rational() {}
  One_root_rational(int i) : a_(i) {}
  One_root_rational(double d) : a_(d) {}
  explicit One_root_rational(const Gmpq& a) : a_(a) {}
  One_root_rational(const Gmpq& a, const Gmpq& b, const Gmpq& d) : a_(a), b_(b), d_(d)
  {
    if(CGAL::sign(b_) == ZERO)
      d_ = Gmpq(0);
  }

  const Gmpq& a() const { return a_; }
  const Gmpq& b() const { return b_; }
  const Gmpq& d() const { return d_; } ///< 0 for a rational number
  bool is_rational() const { return CGAL::sign(b_) == ZERO; }
  Sign sign() const { return sign_one_root(a_, b_, d_); }

  /// An interval that contains the value.
  Interval_nt<false> to_interval() const
  {
    Protect_FPU_rounding<true> protection;
    Interval_nt<false> r(CGAL::to_interval(a_));
    if(!is_rational())
      r += Interval_nt<false>(CGAL::to_interval(b_)) * CGAL::sqrt(Interval_nt<false>(CGAL::to_interval(d_)));
    return r;
  }

  /// The value correctly rounded to double (rational values), or to within
  /// one unit in the last place.
  double to_double() const
  {
    mpfr_t x;
    if(is_rational()) {
      mpfr_init2(x, 53);
      mpfr_set_q(x, a_.mpq(), MPFR_RNDN);
    } else {
      // a + b sqrt(d) at 256 bits
      mpfr_t y;
      mpfr_init2(x, 256);
      mpfr_init2(y, 256);
      mpfr_set_q(x, d_.mpq(), MPFR_RNDN);
      mpfr_sqrt(x, x, MPFR_RNDN);
      mpfr_set_q(y, b_.mpq(), MPFR_RNDN);
      mpfr_mul(x, x, y, MPFR_RNDN);
      mpfr_set_q(y, a_.mpq(), MPFR_RNDN);
      mpfr_add(x, x, y, MPFR_RNDN);
      mpfr_clear(y);
    }
    const double r = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clear(x);
    return r;
  }

  One_root_rational operator-() const { return One_root_rational(-a_, -b_, d_); }

  friend One_root_rational operator+(const One_root_rational& x, const One_root_rational& y)
  {
    Gmpq yb, d;
    align(x, y, yb, d);
    return One_root_rational(x.a_ + y.a_, x.b_ + yb, d);
  }
  friend One_root_rational operator-(const One_root_rational& x, const One_root_rational& y) { return x + (-y); }
  friend One_root_rational operator*(const One_root_rational& x, const One_root_rational& y)
  {
    Gmpq yb, d;
    align(x, y, yb, d);
    return One_root_rational(x.a_ * y.a_ + x.b_ * yb * d, x.a_ * yb + x.b_ * y.a_, d);
  }
  friend One_root_rational operator/(const One_root_rational& x, const One_root_rational& y)
  {
    // multiply by the conjugate of y
    const Gmpq n = y.a_ * y.a_ - y.b_ * y.b_ * y.d_;
    if(CGAL::sign(n) == ZERO)
      throw Not_one_root();
    const One_root_rational conj(y.a_ / n, -y.b_ / n, y.d_);
    return x * conj;
  }
  One_root_rational& operator+=(const One_root_rational& y) { return *this = *this + y; }
  One_root_rational& operator-=(const One_root_rational& y) { return *this = *this - y; }
  One_root_rational& operator*=(const One_root_rational& y) { return *this = *this * y; }
  One_root_rational& operator/=(const One_root_rational& y) { return *this = *this / y; }

  /// The sign of x - y; x and y may have different roots.
  friend Sign sign_of_difference(const One_root_rational& x, const One_root_rational& y)
  {
    if(x.is_rational() || y.is_rational() || x.d_ == y.d_ || roots_commensurable(x, y)) {
      const One_root_rational z = x - y;
      return sign_one_root(z.a_, z.b_, z.d_);
    }
    // L = (x.a - y.a) + x.b sqrt(x.d), R = y.b sqrt(y.d): sign(L - R)
    const Gmpq A = x.a_ - y.a_;
    const Sign sl = sign_one_root(A, x.b_, x.d_), sr = CGAL::sign(y.b_);
    if(sl != sr || sl == ZERO)
      return sl > sr ? POSITIVE : (sl < sr ? NEGATIVE : ZERO);
    // same sign s: sign(L - R) = s sign(L^2 - R^2)
    const Sign s2 = sign_one_root(A * A + x.b_ * x.b_ * x.d_ - y.b_ * y.b_ * y.d_, Gmpq(2) * A * x.b_, x.d_);
    return sl == POSITIVE ? s2 : Sign(-int(s2));
  }

  friend bool operator<(const One_root_rational& x, const One_root_rational& y) { return sign_of_difference(x, y) == NEGATIVE; }
  friend bool operator>(const One_root_rational& x, const One_root_rational& y) { return sign_of_difference(x, y) == POSITIVE; }
  friend bool operator<=(const One_root_rational& x, const One_root_rational& y) { return sign_of_difference(x, y) != POSITIVE; }
  friend bool operator>=(const One_root_rational& x, const One_root_rational& y) { return sign_of_difference(x, y) != NEGATIVE; }
  friend bool operator==(const One_root_rational& x, const One_root_rational& y) { return sign_of_difference(x, y) == ZERO; }
  friend bool operator!=(const One_root_rational& x, const One_root_rational& y) { return sign_of_difference(x, y) != ZERO; }

  friend One_root_rational abs(const One_root_rational& x) { return x < One_root_rational(0) ? -x : x; }

  /// The square root of a rational number; throws Not_one_root otherwise.
  friend One_root_rational sqrt(const One_root_rational& x)
  {
    if(!x.is_rational() || CGAL::sign(x.a_) == NEGATIVE)
      throw Not_one_root();
    Gmpq r;
    if(rational_square_root(x.a_, r))
      return One_root_rational(r);
    return One_root_rational(Gmpq(0), Gmpq(1), x.a_);
  }

private:
  // sqrt(x.d) / sqrt(y.d) is rational
  static bool roots_commensurable(const One_root_rational& x, const One_root_rational& y)
  {
    Gmpq r;
    return rational_square_root(x.d_ / y.d_, r);
  }

  // y's root coefficient over x's root (yb), and the common root d
  static void align(const One_root_rational& x, const One_root_rational& y, Gmpq& yb, Gmpq& d)
  {
    if(y.is_rational()) {
      yb = Gmpq(0);
      d = x.d_;
    } else if(x.is_rational() || x.d_ == y.d_) {
      yb = y.b_;
      d = y.d_;
    } else {
      // sqrt(y.d) = k sqrt(x.d) with k = sqrt(y.d / x.d) rational, or give up
      Gmpq k;
      if(!rational_square_root(y.d_ / x.d_, k))
        throw Not_one_root();
      yb = y.b_ * k;
      d = x.d_;
    }
  }

  Gmpq a_, b_, d_;
};

/// sign(B + C sqrt(rho)), rho >= 0.
inline Sign sign_plus_root(const One_root_rational& B, const One_root_rational& C, const One_root_rational& rho)
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
struct One_root_sqrt {
  One_root_rational alpha, rho;

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
  friend Sign sign_of_difference(const One_root_sqrt& x, const One_root_sqrt& y)
  {
    const One_root_rational A = x.alpha - y.alpha;
    const One_root_rational one(1), minus_one(-1), two(2);
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

} // namespace internal
} // namespace PMA2
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_ONE_ROOT_RATIONAL_H
