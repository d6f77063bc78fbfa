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
// bits): the stage the filtered traits use to construct branch points whose
// double intervals are too wide.  A result is kept only where an error bound
// taken from the double intervals shows that it rounds to the exact value's
// double (rounds_within()).  Decisions never use it.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DOUBLE_DOUBLE_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DOUBLE_DOUBLE_H

#include <cmath>

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
