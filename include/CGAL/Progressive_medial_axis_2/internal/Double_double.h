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
// bits): the fast, non-certified stage used by the filtered traits to
// construct branch points whose double intervals are too wide.  Decisions
// never use it.

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

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DOUBLE_DOUBLE_H
