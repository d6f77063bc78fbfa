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
// GMP rationals for the one-root stage of the filtered traits when the
// coordinates are too long for Small_rational (53-bit mantissas, as in
// coordinates written with 6 decimals).  GMP does the arithmetic; this type
// only manages the storage.  A profile of such input (a Koch snowflake with
// decimal coordinates, thousands of exact ties) spent about 30% of its time
// in malloc and free: CGAL::Gmpq allocates a reference-counted handle for
// every temporary, and GMP then allocates the limbs of its numerator and
// denominator.  Here a temporary takes an mpq_t from a thread-local pool and
// gives it back, limbs included, when it dies, so that after a few
// computations the stage no longer allocates.  (gmpxx's mpq_class and
// Boost.Multiprecision's mpq_rational still allocate for every temporary.)

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_GMP_RATIONAL_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_GMP_RATIONAL_H

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>

#include <gmp.h>
#include <mpfr.h>

#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

class Gmp_rational
{
  // The mpq_t of the objects that died in this thread, ready for reuse.
  struct Pool {
    std::vector<mpq_ptr> free;
    ~Pool()
    {
      for(mpq_ptr q : free) {
        mpq_clear(q);
        delete q;
      }
    }
  };
  static Pool& pool()
  {
    static thread_local Pool p;
    return p;
  }
  // keeps the pool small: a computation of the stage has a few dozen
  // temporaries alive at once
  static constexpr std::size_t max_pooled = 256;

  static mpq_ptr acquire()
  {
    Pool& p = pool();
    if(p.free.empty()) {
      mpq_ptr q = new __mpq_struct;
      mpq_init(q);
      return q;
    }
    mpq_ptr q = p.free.back();
    p.free.pop_back();
    return q;
  }
  static void release(mpq_ptr q)
  {
    Pool& p = pool();
    if(p.free.size() < max_pooled) {
      p.free.push_back(q);
    } else {
      mpq_clear(q);
      delete q;
    }
  }

  struct Uninitialized {};
  explicit Gmp_rational(Uninitialized) : q_(acquire()) {}

public:
  Gmp_rational() : q_(acquire()) { mpq_set_ui(q_, 0, 1); }
  Gmp_rational(int i) : q_(acquire()) { mpq_set_si(q_, i, 1); }
  /// The exact value of a finite double.
  Gmp_rational(double d) : q_(acquire()) { mpq_set_d(q_, d); }
  Gmp_rational(const Gmpq& g) : q_(acquire()) { mpq_set(q_, g.mpq()); }
  Gmp_rational(const Gmp_rational& o) : q_(acquire()) { mpq_set(q_, o.q_); }
  Gmp_rational(Gmp_rational&& o) noexcept : q_(o.q_) { o.q_ = nullptr; }
  Gmp_rational& operator=(const Gmp_rational& o)
  {
    if(q_ == nullptr) q_ = acquire();
    if(this != &o) mpq_set(q_, o.q_);
    return *this;
  }
  Gmp_rational& operator=(Gmp_rational&& o) noexcept
  {
    std::swap(q_, o.q_);
    return *this;
  }
  ~Gmp_rational()
  {
    if(q_ != nullptr) release(q_);
  }

  mpq_srcptr mpq() const { return q_; }
  Sign sign() const { return Sign(mpq_sgn(q_)); }
  Gmpq to_gmpq() const { return Gmpq(q_); }

  Gmp_rational operator-() const
  {
    Gmp_rational r{Uninitialized()};
    mpq_neg(r.q_, q_);
    return r;
  }
  friend Gmp_rational operator+(const Gmp_rational& a, const Gmp_rational& b) { return apply(mpq_add, a, b); }
  friend Gmp_rational operator-(const Gmp_rational& a, const Gmp_rational& b) { return apply(mpq_sub, a, b); }
  friend Gmp_rational operator*(const Gmp_rational& a, const Gmp_rational& b) { return apply(mpq_mul, a, b); }
  /// b != 0 (the callers check)
  friend Gmp_rational operator/(const Gmp_rational& a, const Gmp_rational& b) { return apply(mpq_div, a, b); }
  Gmp_rational& operator+=(const Gmp_rational& b) { mpq_add(q_, q_, b.q_); return *this; }
  Gmp_rational& operator-=(const Gmp_rational& b) { mpq_sub(q_, q_, b.q_); return *this; }
  Gmp_rational& operator*=(const Gmp_rational& b) { mpq_mul(q_, q_, b.q_); return *this; }
  Gmp_rational& operator/=(const Gmp_rational& b) { mpq_div(q_, q_, b.q_); return *this; }

  friend bool operator==(const Gmp_rational& a, const Gmp_rational& b) { return mpq_equal(a.q_, b.q_) != 0; }
  friend bool operator!=(const Gmp_rational& a, const Gmp_rational& b) { return !(a == b); }

  /// Whether the value is the square of a rational, with its root.
  friend bool rational_square_root(const Gmp_rational& q, Gmp_rational& root)
  {
    if(mpq_sgn(q.q_) < 0)
      return false;
    // canonical: q is a square iff its numerator and denominator are
    if(!mpz_perfect_square_p(mpq_numref(q.q_)) || !mpz_perfect_square_p(mpq_denref(q.q_)))
      return false;
    Gmp_rational r{Uninitialized()};
    mpz_sqrt(mpq_numref(r.q_), mpq_numref(q.q_));
    mpz_sqrt(mpq_denref(r.q_), mpq_denref(q.q_));
    root = std::move(r);
    return true;
  }

  /// The smallest interval of doubles that contains the value (as
  /// CGAL::Gmpq's To_interval).
  Interval_nt<false> to_interval() const
  {
    const mpfr_exp_t emin = mpfr_get_emin();
    mpfr_set_emin(-1073);
    MPFR_DECL_INIT(y, 53);
    int r = mpfr_set_q(y, q_, MPFR_RNDA);
    r = mpfr_subnormalize(y, r, MPFR_RNDA);
    const double i = mpfr_get_d(y, MPFR_RNDA);
    mpfr_set_emin(emin);
    if(r == 0 && std::isfinite(i))
      return Interval_nt<false>(i);
    const double s = std::nextafter(i, 0.0);
    return i < 0 ? Interval_nt<false>(i, s) : Interval_nt<false>(s, i);
  }

private:
  template <class Operation>
  static Gmp_rational apply(Operation op, const Gmp_rational& a, const Gmp_rational& b)
  {
    Gmp_rational r{Uninitialized()};
    op(r.q_, a.q_, b.q_);
    return r;
  }

  mpq_ptr q_;   // null only in a moved-from object
};

inline Sign sign(const Gmp_rational& q) { return q.sign(); }

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_GMP_RATIONAL_H
