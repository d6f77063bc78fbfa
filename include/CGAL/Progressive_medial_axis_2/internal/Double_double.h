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
// Double-double arithmetic (an unevaluated sum of two doubles, about 106
// bits), and intervals of it: the stage of the filtered traits between
// double intervals and MPFR intervals, for decisions and for branch points
// that double intervals leave undecided or cannot round.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DOUBLE_DOUBLE_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DOUBLE_DOUBLE_H

#include <CGAL/Progressive_medial_axis_2/internal/Float_bits.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>

#include <cmath>
#include <utility>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

class Double_double
{
public:
  Double_double() : hi_(0), lo_(0) {}
  Double_double(double d) : hi_(d), lo_(0) {}
  Double_double(int i) : hi_(double(i)), lo_(0) {}

  double to_double() const { return hi_ + lo_; }
  /// The two doubles: the value is hi() + lo(), |lo()| at most half an ulp of hi().
  double hi() const { return hi_; }
  double lo() const { return lo_; }

  friend Double_double operator+(const Double_double& a, const Double_double& b)
  {
    double s, e, t, f;
    two_sum(a.hi_, b.hi_, s, e);
    two_sum(a.lo_, b.lo_, t, f);
    e += t;
    fast_two_sum(s, e, s, e);
    e += f;
    fast_two_sum(s, e, s, e);
    return Double_double(s, e);
  }
  friend Double_double operator-(const Double_double& a) { return Double_double(-a.hi_, -a.lo_); }
  friend Double_double operator-(const Double_double& a, const Double_double& b) { return a + (-b); }
  friend Double_double operator*(const Double_double& a, const Double_double& b)
  {
    double p, e;
    two_product(a.hi_, b.hi_, p, e);
    e += a.hi_ * b.lo_ + a.lo_ * b.hi_;
    fast_two_sum(p, e, p, e);
    return Double_double(p, e);
  }
  friend Double_double operator*(const Double_double& a, double b)
  {
    double p, e;
    two_product(a.hi_, b, p, e);
    e += a.lo_ * b;
    fast_two_sum(p, e, p, e);
    return Double_double(p, e);
  }
  friend Double_double operator/(const Double_double& a, const Double_double& b)
  {
    const double q1 = a.hi_ / b.hi_;
    const Double_double r = a - b * q1;
    const double q2 = r.hi_ / b.hi_;
    double s, e;
    fast_two_sum(q1, q2, s, e);
    return Double_double(s, e);
  }
  Double_double& operator+=(const Double_double& b) { return *this = *this + b; }
  Double_double& operator-=(const Double_double& b) { return *this = *this - b; }
  Double_double& operator*=(const Double_double& b) { return *this = *this * b; }
  Double_double& operator/=(const Double_double& b) { return *this = *this / b; }

  friend Double_double sqrt(const Double_double& a)
  {
    if(a.hi_ <= 0) return Double_double(0);
    double s = std::sqrt(a.hi_);
    // one Newton step: s + (a - s^2) / (2 s)
    Double_double ss = Double_double(s) * Double_double(s);
    Double_double r = (a - ss) / Double_double(2 * s);
    return Double_double(s) + r;
  }
  friend Double_double abs(const Double_double& a) { return a.hi_ < 0 ? -a : a; }

  friend bool operator<(const Double_double& a, const Double_double& b)
  {
    return a.hi_ < b.hi_ || (a.hi_ == b.hi_ && a.lo_ < b.lo_);
  }
  friend bool operator>(const Double_double& a, const Double_double& b) { return b < a; }
  friend bool operator<=(const Double_double& a, const Double_double& b) { return !(b < a); }
  friend bool operator>=(const Double_double& a, const Double_double& b) { return !(a < b); }
  friend bool operator==(const Double_double& a, const Double_double& b) { return a.hi_ == b.hi_ && a.lo_ == b.lo_; }
  friend bool operator!=(const Double_double& a, const Double_double& b) { return !(a == b); }

private:
  Double_double(double h, double l) : hi_(h), lo_(l) {}
  static void two_sum(double a, double b, double& s, double& e)
  {
    s = a + b;
    double bb = s - a;
    e = (a - (s - bb)) + (b - bb);
  }
  // p + e = a b exactly: a fused multiply-add where the compiler has one,
  // else Dekker's product of Veltkamp halves (a call of std::fma through
  // the library costs more than these ten operations)
  static void two_product(double a, double b, double& p, double& e)
  {
    p = a * b;
#ifdef __FMA__
    e = std::fma(a, b, -p);
#else
    const double split = 134217729.0;   // 2^27 + 1
    double t = split * a;
    const double ah = t - (t - a), al = a - ah;
    t = split * b;
    const double bh = t - (t - b), bl = b - bh;
    e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
#endif
  }
  static void fast_two_sum(double a, double b, double& s, double& e)
  {
    s = a + b;
    e = b - (s - a);
  }
  double hi_, lo_;
};

/// Interval arithmetic in double-double: a value v (Double_double) and a
/// radius r, the interval [v - r, v + r].  The decision stage of the
/// filtered traits between double intervals and MPFR intervals: near-ties
/// that double intervals cannot separate (decimal and flattened-curve
/// input) are separated here, far more cheaply than by the MPFR stage
/// (RESULTS.md, twenty-third session).
/// Comparisons return CGAL::Uncertain, as CGAL::Interval_nt's do.
///
/// Why the radius encloses.  Each operation computes v in double-double
/// and adds to the propagated radius a bound of its own rounding error,
/// `rel |v| + tiny`:
/// - A sum is Joldes, Muller and Popescu's AccurateDWPlusDW (Algorithm 6 of
///   "Tight and rigorous error bounds for basic building blocks of
///   double-word arithmetic", ACM TOMS 44(2), 2017), relative error at most
///   3u^2 + 13u^3 (u = 2^-53); a product is their DWTimesDW1 (Algorithm 10,
///   CRlibm's Mul22), below 2^-102.  `rel` = 2^-96 leaves a margin of 2^6
///   over both.
/// - A quotient and a square root are approximated by Double_double, whose
///   error is not relied on: the radius comes from the residual
///   `a - q b` (resp. `a - s s`), computed with sums and products, divided by
///   a lower bound of |b| (resp. of s).
/// - Those bounds hold without underflow; `tiny` = 2^-1000 bounds the
///   absolute error that underflowing parts add (a few 2^-1074 per
///   operation), so values below about 2^-900 are not decided here (the MPFR
///   stage takes them: coordinates of 1e-300).  A value beyond 2^995, where
///   Dekker's splitting could overflow, throws.
/// - The radius itself is summed in rounding to nearest, a few terms, then
///   multiplied by 1 + 2^-48, which covers their rounding errors.
/// The stage therefore needs the rounding mode to nearest, the default
/// outside CGAL's Protect_FPU_rounding.
class Double_double_interval
{
public:
  Double_double_interval() : v_(0), r_(0) {}
  Double_double_interval(double d) : v_(check(d)), r_(0) {}
  Double_double_interval(int i) : v_(double(i)), r_(0) {}
  /// The interval [i.first, i.second] (an inexact input of Epeck).
  explicit Double_double_interval(const std::pair<double, double>& i)
    : v_(Double_double(check(i.first)) + Double_double(check(i.second)))
  {
    v_ = v_ * Double_double(0.5);
    r_ = up(0.5 * (i.second - i.first) + own_error(v_));
  }

  const Double_double& value() const { return v_; }
  double radius() const { return r_; }
  /// An upper bound of the magnitudes in the interval.
  double magnitude() const { return up(mag(v_) + r_); }
  double inf() const { return next_down(v_.hi() - up(std::fabs(v_.lo()) + r_)); }
  double sup() const { return next_up(v_.hi() + up(std::fabs(v_.lo()) + r_)); }
  Interval_nt<false> to_interval() const { return Interval_nt<false>(inf(), sup()); }
  double to_double() const { return v_.to_double(); }
  /// Whether every value of the interval rounds to the same double, then
  /// to_double().  The ends are v - e and v + e, e the radius plus a bound
  /// of the error of computing them; if both round to to_double(), so does
  /// every value between them, by monotony of rounding.  A value exactly
  /// on a rounding boundary (a midpoint of two doubles, a zero) never
  /// passes: the interval of a computed value is never a point.
  bool rounds_to_one_double() const
  {
    const double d = v_.to_double();
    const double e = up(r_ + 2 * own_error(v_));
    if(!std::isfinite(d) || !(e < HUGE_VAL))
      return false;
    return (v_ + Double_double(e)).to_double() == d && (v_ - Double_double(e)).to_double() == d;
  }

  friend Double_double_interval operator+(const Double_double_interval& a, const Double_double_interval& b)
  {
    const Double_double v = a.v_ + b.v_;
    return Double_double_interval(v, up(a.r_ + b.r_ + own_error(v)));
  }
  friend Double_double_interval operator-(const Double_double_interval& a)
  {
    return Double_double_interval(-a.v_, a.r_);
  }
  friend Double_double_interval operator-(const Double_double_interval& a, const Double_double_interval& b)
  {
    const Double_double v = a.v_ - b.v_;
    return Double_double_interval(v, up(a.r_ + b.r_ + own_error(v)));
  }
  friend Double_double_interval operator*(const Double_double_interval& a, const Double_double_interval& b)
  {
    const Double_double v = a.v_ * b.v_;
    double r = own_error(v);
    if(a.r_ != 0 || b.r_ != 0)
      r += mag(a.v_) * b.r_ + mag(b.v_) * a.r_ + a.r_ * b.r_;
    return Double_double_interval(v, up(r));
  }
  friend Double_double_interval operator/(const Double_double_interval& a, const Double_double_interval& b)
  {
    const double lower = lower_magnitude(b);   // |b| on the interval is at least this
    if(!(lower > 0))
      throw Uncertain_conversion_exception("Double_double_interval: division by an interval containing 0");
    const Double_double q = a.v_ / b.v_;
    check(q.hi());
    // |a - q b| on the intervals, through the residual of the values
    const Double_double t = q * b.v_;
    const Double_double d = a.v_ - t;
    const double residual = mag(d) + own_error(t) + own_error(d) + a.r_ + mag(q) * b.r_;
    return Double_double_interval(q, up(up(residual) / lower));
  }
  Double_double_interval& operator+=(const Double_double_interval& b) { return *this = *this + b; }
  Double_double_interval& operator-=(const Double_double_interval& b) { return *this = *this - b; }
  Double_double_interval& operator*=(const Double_double_interval& b) { return *this = *this * b; }
  Double_double_interval& operator/=(const Double_double_interval& b) { return *this = *this / b; }

  friend Double_double_interval sqrt(const Double_double_interval& a)
  {
    const double upper = a.v_.hi() + up(std::fabs(a.v_.lo()) + a.r_);
    if(upper < 0)
      throw Uncertain_conversion_exception("Double_double_interval: square root of a negative interval");
    const double lower = a.v_.hi() - up(std::fabs(a.v_.lo()) + a.r_);
    if(!(lower > 0x1p-900)) {
      // [0, sqrt(upper)], as centre and radius
      const double h = 0.5 * up(std::sqrt(up(upper)));
      return Double_double_interval(Double_double(h), up(h));
    }
    const Double_double s = sqrt(a.v_);
    // |sqrt(x) - s| = |x - s^2| / (sqrt(x) + s) <= (|v - s^2| + r) / s
    const double s_lower = lower_magnitude(Double_double_interval(s, 0));
    if(!(s_lower > 0))
      throw Uncertain_conversion_exception("Double_double_interval: square root not certified");
    const Double_double t = s * s;
    const Double_double d = a.v_ - t;
    const double residual = mag(d) + own_error(t) + own_error(d) + a.r_;
    return Double_double_interval(s, up(up(residual) / s_lower));
  }
  friend Double_double_interval abs(const Double_double_interval& a)
  {
    const int sign = a.certain_sign();
    if(sign > 0) return a;
    if(sign < 0) return -a;
    const double h = 0.5 * a.magnitude();
    return Double_double_interval(Double_double(h), up(h));
  }

  friend Uncertain<Comparison_result> compare(const Double_double_interval& a, const Double_double_interval& b)
  {
    if(a.r_ == 0 && b.r_ == 0 && a.v_.hi() == b.v_.hi() && a.v_.lo() == b.v_.lo())
      return EQUAL;
    const int sign = (a - b).certain_sign();
    if(sign == 0)
      return Uncertain<Comparison_result>::indeterminate();
    return sign < 0 ? SMALLER : LARGER;
  }
  friend Uncertain<bool> operator<(const Double_double_interval& a, const Double_double_interval& b)
  {
    const Uncertain<Comparison_result> c = compare(a, b);
    if(!is_certain(c)) return Uncertain<bool>::indeterminate();
    return get_certain(c) == SMALLER;
  }
  friend Uncertain<bool> operator>(const Double_double_interval& a, const Double_double_interval& b) { return b < a; }
  friend Uncertain<bool> operator<=(const Double_double_interval& a, const Double_double_interval& b) { return !(b < a); }
  friend Uncertain<bool> operator>=(const Double_double_interval& a, const Double_double_interval& b) { return !(a < b); }
  friend Uncertain<bool> operator==(const Double_double_interval& a, const Double_double_interval& b)
  {
    const Uncertain<Comparison_result> c = compare(a, b);
    if(!is_certain(c)) return Uncertain<bool>::indeterminate();
    return get_certain(c) == EQUAL;
  }
  friend Uncertain<bool> operator!=(const Double_double_interval& a, const Double_double_interval& b) { return !(a == b); }

  friend Uncertain<bool> operator<(const Double_double_interval& a, int b) { return a < Double_double_interval(b); }
  friend Uncertain<bool> operator>(const Double_double_interval& a, int b) { return a > Double_double_interval(b); }
  friend Uncertain<bool> operator<=(const Double_double_interval& a, int b) { return a <= Double_double_interval(b); }
  friend Uncertain<bool> operator>=(const Double_double_interval& a, int b) { return a >= Double_double_interval(b); }
  friend Uncertain<bool> operator==(const Double_double_interval& a, int b) { return a == Double_double_interval(b); }

private:
  static constexpr double rel = 0x1p-96;
  static constexpr double tiny = 0x1p-1000;

  // (+ tiny: what an underflow in the radius's own computation may lose)
  Double_double_interval(const Double_double& v, double r) : v_(v), r_(r + tiny)
  {
    check(v.hi());
    if(!(r < HUGE_VAL))
      throw Uncertain_conversion_exception("Double_double_interval: radius overflow");
  }
  static double check(double d)
  {
    if(!(std::fabs(d) <= 0x1p995))
      throw Uncertain_conversion_exception("Double_double_interval: out of range");
    return d;
  }
  // rounding to nearest errs by at most 2^-53 per operation: a few terms
  // summed, then this factor, bound the exact sum from above
  static double up(double x) { return x * (1 + 0x1p-48); }
  // an upper bound of |v|
  static double mag(const Double_double& v) { return up(std::fabs(v.hi()) + std::fabs(v.lo())); }
  // the rounding error of the operation that gave v
  static double own_error(const Double_double& v) { return rel * mag(v) + tiny; }
  // a lower bound of the magnitudes in the interval (<= 0: it may hold 0)
  static double lower_magnitude(const Double_double_interval& a)
  {
    // |hi| minus an upper bound of |lo| + r: one rounding, relative to the
    // result (none if it is subnormal)
    return (std::fabs(a.v_.hi()) - up(std::fabs(a.v_.lo()) + a.r_)) * (1 - 0x1p-48);
  }
  // -1 or 1 if every value of the interval has that sign, else 0
  int certain_sign() const
  {
    if(lower_magnitude(*this) > 0)
      return v_.hi() < 0 ? -1 : 1;
    return 0;
  }

  Double_double v_;
  double r_;
};

/// Whether `v`, the double-double result of a computation whose double
/// interval evaluation (same operations, same branches) encloses the exact
/// value in `[inf, sup]`, certainly rounds to the same double as the exact
/// value: every value within an error bound of `v` rounds to the double
/// `v` rounds to, and that double lies in `[inf, sup]`.  The bound is
/// `(sup - inf) * 2^-40`, or `(sup - inf) * 2^-16` if the computation took
/// the square root of a radicand whose interval reaches below half its
/// upper bound (`root_cancels`).
///
/// Why these bounds.  The inputs are doubles, exact in both evaluations.
/// A double-double operation errs by at most about 2^-100 of its result; an
/// interval operation that is not exact widens by at least one unit in the
/// last place, 2^-53 of its result, and one that is exact in doubles is
/// exact in double-double too.  Both errors then propagate through the
/// same derivatives, the interval's with absolute values, so the
/// double-double error stays below the width times about 2^-47: 2^-40
/// leaves a margin of 2^7.  The one operation that does not propagate
/// errors linearly is a square root near zero.  A radicand whose interval
/// stays above half its upper bound is at least its interval's width away
/// from zero, and the root stays linear to a factor 1.5.  Otherwise the
/// double-double radicand errs by e at most 2^-47 of the width w, its root
/// by at most sqrt(e), while the root's interval is wider than
/// 0.29 sqrt(w): the ratio is at most about 2^-22, and 2^-16 leaves a
/// margin of 2^6.  A disk construction takes at most one such root (its
/// other roots are of sums of squares: segment lengths, the radius of a
/// circle through three points).  Exact values on a rounding boundary (a
/// zero, the midpoint of two doubles) always fail the test: they are for
/// exact arithmetic to round.
inline bool rounds_within(const Double_double& v, double inf, double sup, bool root_cancels)
{
  const double d = v.to_double();
  const double e = (sup - inf) * (root_cancels ? 0x1p-16 : 0x1p-40);
  if(!std::isfinite(d) || !std::isfinite(e) || !(inf <= d && d <= sup))
    return false;
  return (v + Double_double(e)).to_double() == d && (v - Double_double(e)).to_double() == d;
}

/// Thrown when a coordinate given to a double-double computation is not a
/// double (an exact number of `Epeck`): its result could not be certified.
struct Inexact_double_double_input {};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DOUBLE_DOUBLE_H
