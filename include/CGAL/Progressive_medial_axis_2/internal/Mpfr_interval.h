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
// Interval arithmetic on MPFR numbers of a chosen precision: the second
// stage of the filtered traits, between double intervals and the exact stages.
// Comparisons return CGAL::Uncertain<bool>, whose conversion to bool throws
// CGAL::Uncertain_conversion_exception when the interval cannot decide, as
// with CGAL::Interval_nt.
//
// Boost.Multiprecision's `mpfr_float` has no directed rounding per
// operation and `mpfi` (MPFI) is not a dependency of CGAL, hence this class.
// The bounds of an interval of at most 256 bits (the filtered traits use
// 191) live in the object (MPFR's custom interface), not on the heap:
// malloc and free were a third of the MPFR stage's time on symmetric shapes.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MPFR_INTERVAL_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MPFR_INTERVAL_H

#include <CGAL/Uncertain.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Gmpq.h>

#include <mpfr.h>

#include <algorithm>
#include <utility>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

class Mpfr_interval
{
public:
  /// The default precision, the filtered traits' MPFR stage's: three 64-bit
  /// limbs, where MPFR's additions and products take their fast paths (at
  /// 256 bits, four limbs, they take the general ones).  Near-ties of
  /// decimal and flattened-curve input ran 2% to 9% faster than at 256 bits;
  /// of 841 shapes, 12 passed one or two more decisions to the exact stages
  /// (RESULTS.md, twenty-second session).
  static constexpr mpfr_prec_t default_precision = 191;

  /// The precision, in bits, of the intervals created from now on in this thread.
  static mpfr_prec_t& precision()
  {
    static thread_local mpfr_prec_t p = default_precision;
    return p;
  }

  Mpfr_interval() { init(); mpfr_set_zero(lo_, 1); mpfr_set_zero(hi_, 1); }
  Mpfr_interval(double d) { init(); mpfr_set_d(lo_, d, MPFR_RNDD); mpfr_set_d(hi_, d, MPFR_RNDU); }
  Mpfr_interval(int i) { init(); mpfr_set_si(lo_, i, MPFR_RNDD); mpfr_set_si(hi_, i, MPFR_RNDU); }
  explicit Mpfr_interval(const Gmpq& q) { init(); mpfr_set_q(lo_, q.mpq(), MPFR_RNDD); mpfr_set_q(hi_, q.mpq(), MPFR_RNDU); }
  Mpfr_interval(const Mpfr_interval& o)
  {
    init();
    mpfr_set(lo_, o.lo_, MPFR_RNDD);
    mpfr_set(hi_, o.hi_, MPFR_RNDU);
  }
  // (no move: the bounds may point into the object's own storage)
  Mpfr_interval& operator=(const Mpfr_interval& o)
  {
    if(this != &o) {
      mpfr_set(lo_, o.lo_, MPFR_RNDD);
      mpfr_set(hi_, o.hi_, MPFR_RNDU);
    }
    return *this;
  }
  ~Mpfr_interval()
  {
    if(mpfr_get_prec(lo_) > inline_precision) {
      mpfr_clear(lo_);
      mpfr_clear(hi_);
    }
  }

  /// The bounds.
  mpfr_srcptr lower() const { return lo_; }
  mpfr_srcptr upper() const { return hi_; }
  double inf() const { return mpfr_get_d(lo_, MPFR_RNDD); }
  double sup() const { return mpfr_get_d(hi_, MPFR_RNDU); }
  /// The double nearest to the midpoint.
  double midpoint() const
  {
    mpfr_t m;
    mpfr_init2(m, mpfr_get_prec(lo_) + 1);
    mpfr_add(m, lo_, hi_, MPFR_RNDN);
    mpfr_div_2ui(m, m, 1, MPFR_RNDN);
    double d = mpfr_get_d(m, MPFR_RNDN);
    mpfr_clear(m);
    return d;
  }
  /// Whether the interval's two ends round to the same double.
  bool rounds_to_one_double() const { return mpfr_get_d(lo_, MPFR_RNDN) == mpfr_get_d(hi_, MPFR_RNDN); }
  Interval_nt<false> to_interval() const { return Interval_nt<false>(inf(), sup()); }

  friend Mpfr_interval operator+(const Mpfr_interval& a, const Mpfr_interval& b)
  {
    Mpfr_interval r;
    mpfr_add(r.lo_, a.lo_, b.lo_, MPFR_RNDD);
    mpfr_add(r.hi_, a.hi_, b.hi_, MPFR_RNDU);
    return r;
  }
  friend Mpfr_interval operator-(const Mpfr_interval& a, const Mpfr_interval& b)
  {
    Mpfr_interval r;
    mpfr_sub(r.lo_, a.lo_, b.hi_, MPFR_RNDD);
    mpfr_sub(r.hi_, a.hi_, b.lo_, MPFR_RNDU);
    return r;
  }
  friend Mpfr_interval operator-(const Mpfr_interval& a)
  {
    Mpfr_interval r;
    mpfr_neg(r.lo_, a.hi_, MPFR_RNDD);
    mpfr_neg(r.hi_, a.lo_, MPFR_RNDU);
    return r;
  }
  // Products and quotients by the signs of the bounds, as CGAL::Interval_nt:
  // two operations, four only for a product of two intervals containing 0.
  friend Mpfr_interval operator*(const Mpfr_interval& a, const Mpfr_interval& b)
  {
    Mpfr_interval r;
    auto set = [&](mpfr_srcptr l1, mpfr_srcptr l2, mpfr_srcptr h1, mpfr_srcptr h2) {
      mpfr_mul(r.lo_, l1, l2, MPFR_RNDD);
      mpfr_mul(r.hi_, h1, h2, MPFR_RNDU);
    };
    if(mpfr_sgn(a.lo_) >= 0) {
      if(mpfr_sgn(b.lo_) >= 0) set(a.lo_, b.lo_, a.hi_, b.hi_);
      else if(mpfr_sgn(b.hi_) <= 0) set(a.hi_, b.lo_, a.lo_, b.hi_);
      else set(a.hi_, b.lo_, a.hi_, b.hi_);
    } else if(mpfr_sgn(a.hi_) <= 0) {
      if(mpfr_sgn(b.lo_) >= 0) set(a.lo_, b.hi_, a.hi_, b.lo_);
      else if(mpfr_sgn(b.hi_) <= 0) set(a.hi_, b.hi_, a.lo_, b.lo_);
      else set(a.lo_, b.hi_, a.lo_, b.lo_);
    } else if(mpfr_sgn(b.lo_) >= 0) {
      set(a.lo_, b.hi_, a.hi_, b.hi_);
    } else if(mpfr_sgn(b.hi_) <= 0) {
      set(a.hi_, b.lo_, a.lo_, b.lo_);
    } else {   // both contain 0 in their interiors
      Mpfr_interval t;
      mpfr_mul(r.lo_, a.lo_, b.hi_, MPFR_RNDD);
      mpfr_mul(t.lo_, a.hi_, b.lo_, MPFR_RNDD);
      mpfr_min(r.lo_, r.lo_, t.lo_, MPFR_RNDD);
      mpfr_mul(r.hi_, a.lo_, b.lo_, MPFR_RNDU);
      mpfr_mul(t.hi_, a.hi_, b.hi_, MPFR_RNDU);
      mpfr_max(r.hi_, r.hi_, t.hi_, MPFR_RNDU);
    }
    return r;
  }
  friend Mpfr_interval operator/(const Mpfr_interval& a, const Mpfr_interval& b)
  {
    // a divisor that may be zero cannot be decided here
    if(mpfr_sgn(b.lo_) <= 0 && mpfr_sgn(b.hi_) >= 0)
      throw Uncertain_conversion_exception("Mpfr_interval: division by an interval containing 0");
    Mpfr_interval r;
    auto set = [&](mpfr_srcptr l1, mpfr_srcptr l2, mpfr_srcptr h1, mpfr_srcptr h2) {
      mpfr_div(r.lo_, l1, l2, MPFR_RNDD);
      mpfr_div(r.hi_, h1, h2, MPFR_RNDU);
    };
    if(mpfr_sgn(b.lo_) > 0) {
      if(mpfr_sgn(a.lo_) >= 0) set(a.lo_, b.hi_, a.hi_, b.lo_);
      else if(mpfr_sgn(a.hi_) <= 0) set(a.lo_, b.lo_, a.hi_, b.hi_);
      else set(a.lo_, b.lo_, a.hi_, b.lo_);
    } else {
      if(mpfr_sgn(a.lo_) >= 0) set(a.hi_, b.hi_, a.lo_, b.lo_);
      else if(mpfr_sgn(a.hi_) <= 0) set(a.hi_, b.lo_, a.lo_, b.hi_);
      else set(a.hi_, b.hi_, a.lo_, b.hi_);
    }
    return r;
  }
  Mpfr_interval& operator+=(const Mpfr_interval& b) { return *this = *this + b; }
  Mpfr_interval& operator-=(const Mpfr_interval& b) { return *this = *this - b; }
  Mpfr_interval& operator*=(const Mpfr_interval& b) { return *this = *this * b; }
  Mpfr_interval& operator/=(const Mpfr_interval& b) { return *this = *this / b; }

  friend Mpfr_interval sqrt(const Mpfr_interval& a)
  {
    if(mpfr_sgn(a.hi_) < 0)
      throw Uncertain_conversion_exception("Mpfr_interval: square root of a negative interval");
    Mpfr_interval r;
    if(mpfr_sgn(a.lo_) <= 0)
      mpfr_set_zero(r.lo_, 1);
    else
      mpfr_sqrt(r.lo_, a.lo_, MPFR_RNDD);
    mpfr_sqrt(r.hi_, a.hi_, MPFR_RNDU);
    return r;
  }
  friend Mpfr_interval abs(const Mpfr_interval& a)
  {
    if(mpfr_sgn(a.lo_) >= 0) return a;
    if(mpfr_sgn(a.hi_) <= 0) return -a;
    Mpfr_interval r;
    mpfr_set_zero(r.lo_, 1);
    mpfr_neg(r.hi_, a.lo_, MPFR_RNDU);
    mpfr_max(r.hi_, r.hi_, a.hi_, MPFR_RNDU);
    return r;
  }

  friend Uncertain<bool> operator<(const Mpfr_interval& a, const Mpfr_interval& b)
  {
    if(mpfr_less_p(a.hi_, b.lo_)) return true;
    if(mpfr_greaterequal_p(a.lo_, b.hi_)) return false;
    return Uncertain<bool>::indeterminate();
  }
  friend Uncertain<bool> operator>(const Mpfr_interval& a, const Mpfr_interval& b) { return b < a; }
  friend Uncertain<bool> operator<=(const Mpfr_interval& a, const Mpfr_interval& b) { return !(b < a); }
  friend Uncertain<bool> operator>=(const Mpfr_interval& a, const Mpfr_interval& b) { return !(a < b); }
  friend Uncertain<bool> operator==(const Mpfr_interval& a, const Mpfr_interval& b)
  {
    if(mpfr_less_p(a.hi_, b.lo_) || mpfr_less_p(b.hi_, a.lo_)) return false;
    if(mpfr_equal_p(a.lo_, a.hi_) && mpfr_equal_p(b.lo_, b.hi_) && mpfr_equal_p(a.lo_, b.lo_)) return true;
    return Uncertain<bool>::indeterminate();
  }
  friend Uncertain<bool> operator!=(const Mpfr_interval& a, const Mpfr_interval& b) { return !(a == b); }

  friend Uncertain<bool> operator<(const Mpfr_interval& a, int b) { return a < Mpfr_interval(b); }
  friend Uncertain<bool> operator>(const Mpfr_interval& a, int b) { return a > Mpfr_interval(b); }
  friend Uncertain<bool> operator<=(const Mpfr_interval& a, int b) { return a <= Mpfr_interval(b); }
  friend Uncertain<bool> operator>=(const Mpfr_interval& a, int b) { return a >= Mpfr_interval(b); }
  friend Uncertain<bool> operator==(const Mpfr_interval& a, int b) { return a == Mpfr_interval(b); }

  /// Sign comparison of two intervals.
  friend Uncertain<Comparison_result> compare(const Mpfr_interval& a, const Mpfr_interval& b)
  {
    if(mpfr_less_p(a.hi_, b.lo_)) return SMALLER;
    if(mpfr_less_p(b.hi_, a.lo_)) return LARGER;
    if(mpfr_equal_p(a.lo_, a.hi_) && mpfr_equal_p(b.lo_, b.hi_) && mpfr_equal_p(a.lo_, b.lo_)) return EQUAL;
    return Uncertain<Comparison_result>::indeterminate();
  }

private:
  static constexpr mpfr_prec_t inline_precision = 256;
  static constexpr int inline_limbs = int((inline_precision + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS);

  void init()
  {
    const mpfr_prec_t p = precision();
    if(p <= inline_precision) {
      mpfr_custom_init(lo_limbs_, p);
      mpfr_custom_init_set(lo_, MPFR_ZERO_KIND, 0, p, lo_limbs_);
      mpfr_custom_init(hi_limbs_, p);
      mpfr_custom_init_set(hi_, MPFR_ZERO_KIND, 0, p, hi_limbs_);
    } else {
      mpfr_init2(lo_, p);
      mpfr_init2(hi_, p);
    }
  }
  mpfr_t lo_, hi_;
  mp_limb_t lo_limbs_[inline_limbs], hi_limbs_[inline_limbs];
};

/// Sets the precision of the MPFR intervals in a scope.
class Mpfr_precision_scope
{
public:
  explicit Mpfr_precision_scope(mpfr_prec_t p) : old_(Mpfr_interval::precision()) { Mpfr_interval::precision() = p; }
  ~Mpfr_precision_scope() { Mpfr_interval::precision() = old_; }

private:
  mpfr_prec_t old_;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MPFR_INTERVAL_H
