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
// Exact numbers built from rationals by +, -, *, / and square roots, nested
// to any depth: the last stage of the filtered traits.  It decides the exact
// ties that the one-root numbers (One_root_rational.h) cannot represent:
// several unrelated roots (the lengths of oblique segments), roots of
// numbers that hold roots (the discriminant of a PSS circle next to a
// diagonal, and the chord of that circle), and it never gives up.
//
// Why not a library type.  CGAL's Sqrt_extension nests, but its operands
// must share one root (checked only in debug builds: a release build gives
// sqrt 8 * sqrt 2 = 8), so two independent roots at one level cannot be
// added.  CORE::Expr is exact, but its root bounds count every square root
// node of the expression, and a tie between two event times with ten such
// nodes took seconds; its progressive evaluation is also a process-global
// flag.  Here the roots of one evaluation are shared and the sign is found
// by exact squaring, in rational arithmetic, with no precision bound.
//
// Representation.  A context (Nested_root_context, one per decision) holds
// the roots r_1, r_2, ... created so far; root k is s_k = sqrt(a_k) > 0,
// where the radicand a_k is itself a number in s_1 .. s_k-1.  A number is a
// polynomial with rational coefficients, of degree at most one in each s_k
// (s_k^2 is replaced by a_k), stored as (bit mask of its roots, coefficient)
// terms.  Roots are shared: a rational radicand whose ratio to an existing
// one is a rational square reuses that root (sqrt 8 = 2 sqrt 2), and equal
// radicands give one root.  The roots need not be independent (a nested
// root may denest): nothing below relies on it.
//
// Sign (exact): first a double-interval evaluation; if it cannot decide,
// write the number as P + Q s_k for its highest root s_k, with P and Q free
// of s_k; find the signs of P and Q (recursively); if they differ, the
// sign of P^2 - Q^2 a_k (a number in fewer roots) decides.  This is the
// one-root rule of One_root_rational.h applied root by root.
//
// Division rationalises the denominator, one root at a time, by the
// conjugate; should a conjugate vanish (dependent roots), the denominator
// equals 2P and the division goes on with that.
//
// The rational type.  The coefficients are Small_rational (128 bits, on the
// stack: Small_rational.h) or Gmp_rational (GMP's mpq_t from a pool of the
// thread: Gmp_rational.h): the types Small_nested_root_number and
// Nested_root_number.  A Small_rational operation whose result does not fit
// throws Small_rational_overflow, and the caller evaluates again in
// Gmp_rational (as the one-root stage does).  The terms of a number live in
// a small vector with room for four on the stack: the exact ties of
// degenerate input (the integer circles of font outlines) spent a third of
// their time in malloc and GMP for numbers of a few terms.  Gmp_rational
// rather than CGAL::Gmpq (a reference-counted handle allocated for every
// temporary) took 3% to 7% off shapes with many such ties in one thread
// (RESULTS.md, twenty-first session).

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_NESTED_ROOT_NUMBER_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_NESTED_ROOT_NUMBER_H

#include <CGAL/Progressive_medial_axis_2/internal/One_root_rational.h>
#include <CGAL/Progressive_medial_axis_2/internal/Small_rational.h>

// GCC 12 warns, wrongly, of a read beyond the inline storage when a
// small_vector of trivially copyable elements is moved (GCC bug 108197,
// boostorg/container issue 267; newer Boost versions do not warn).
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#endif
#include <boost/container/small_vector.hpp>
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#pragma GCC diagnostic pop
#endif

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

typedef std::uint64_t Root_mask;

/// A term of a nested-root number: a rational coefficient times the product
/// of the roots whose bits are set in `mask`.
template <class Q>
struct Root_term {
  Root_mask mask;
  Q c;
  friend bool operator==(const Root_term& a, const Root_term& b) { return a.mask == b.mask && a.c == b.c; }
};

inline int highest_root(Root_mask m)
{
  CGAL_precondition(m != 0);
  return 63 - __builtin_clzll(m);
}

/// The roots of one exact evaluation, with coefficients of the rational
/// type Rational (Gmp_rational or Small_rational).  Creating a context makes it the
/// current one of the thread (for its Rational) until it is destroyed; nested-root
/// numbers are valid only while their context lives.
template <class Rational>
class Basic_nested_root_context
{
public:
  typedef Root_term<Rational> Term;
  typedef boost::container::small_vector<Term, 4> Root_polynomial;

  Basic_nested_root_context() : previous_(current()) { current() = this; }
  ~Basic_nested_root_context() { current() = previous_; }
  Basic_nested_root_context(const Basic_nested_root_context&) = delete;
  Basic_nested_root_context& operator=(const Basic_nested_root_context&) = delete;

  static Basic_nested_root_context*& current()
  {
    static thread_local Basic_nested_root_context* c = nullptr;
    return c;
  }
  static Basic_nested_root_context& get()
  {
    CGAL_precondition(current() != nullptr);
    return *current();
  }

  std::size_t number_of_roots() const { return roots_.size(); }

  // ---- polynomial arithmetic ----

  /// Sorts the terms by mask, adds the coefficients of equal masks and drops zeros.
  static void normalize(Root_polynomial& v)
  {
    if(v.size() < 2) {
      if(v.size() == 1 && q_sign(v[0].c) == ZERO) v.clear();
      return;
    }
    std::sort(v.begin(), v.end(), [](const Term& a, const Term& b) { return a.mask < b.mask; });
    std::size_t out = 0;
    for(std::size_t i = 0; i < v.size();) {
      Term t = v[i];
      std::size_t j = i + 1;
      for(; j < v.size() && v[j].mask == t.mask; ++j) t.c += v[j].c;
      if(q_sign(t.c) != ZERO) v[out++] = t;
      i = j;
    }
    v.resize(out);
  }

  static Root_polynomial add(const Root_polynomial& a, const Root_polynomial& b, bool subtract)
  {
    Root_polynomial r;
    r.reserve(a.size() + b.size());
    std::size_t i = 0, j = 0;
    while(i < a.size() || j < b.size()) {
      if(j == b.size() || (i < a.size() && a[i].mask < b[j].mask)) {
        r.push_back(a[i++]);
      } else if(i == a.size() || b[j].mask < a[i].mask) {
        r.push_back(Term{b[j].mask, subtract ? -b[j].c : b[j].c});
        ++j;
      } else {
        Rational c = subtract ? a[i].c - b[j].c : a[i].c + b[j].c;
        if(q_sign(c) != ZERO) r.push_back(Term{a[i].mask, c});
        ++i;
        ++j;
      }
    }
    return r;
  }

  Root_polynomial multiply(const Root_polynomial& a, const Root_polynomial& b) const
  {
    Root_polynomial r;
    if(a.empty() || b.empty()) return r;
    r.reserve(a.size() * b.size());
    for(const Term& x : a)
      for(const Term& y : b) add_monomial_product(x.mask, y.mask, x.c * y.c, r);
    normalize(r);
    return r;
  }

  static Root_polynomial scale(const Root_polynomial& a, const Rational& q)
  {
    Root_polynomial r;
    if(q_sign(q) == ZERO) return r;
    r.reserve(a.size());
    for(const Term& t : a) r.push_back(Term{t.mask, t.c * q});
    return r;
  }

  static bool is_rational(const Root_polynomial& a) { return a.empty() || (a.size() == 1 && a[0].mask == 0); }
  static Rational rational_value(const Root_polynomial& a) { return a.empty() ? Rational(0) : a[0].c; }
  static Root_polynomial constant(const Rational& q)
  {
    Root_polynomial r;
    if(q_sign(q) != ZERO) r.push_back(Term{0, q});
    return r;
  }

  /// The exact sign.
  Sign sign(const Root_polynomial& a) const
  {
    if(a.empty()) return ZERO;
    // every term of one sign (the roots are positive)
    const Sign s0 = q_sign(a[0].c);
    bool same = true;
    for(const Term& t : a)
      if(q_sign(t.c) != s0) { same = false; break; }
    if(same) return s0;
    {
      const Interval_nt<false> v = interval(a);
      if(v.inf() > 0) return POSITIVE;
      if(v.sup() < 0) return NEGATIVE;
    }
    Root_mask all = 0;
    for(const Term& t : a) all |= t.mask;
    const int k = highest_root(all);
    const Root_mask bit = Root_mask(1) << k;
    Root_polynomial P, Q;
    for(const Term& t : a) {
      if(t.mask & bit) Q.push_back(Term{t.mask & ~bit, t.c});
      else P.push_back(t);
    }
    normalize(Q);   // removing the bit keeps the order, but be safe
    const Sign sq = sign(Q), sp = sign(P);
    if(sq == ZERO) return sp;
    if(sp == ZERO || sp == sq) return sq;
    // P + Q s_k with opposite signs: compare P^2 with Q^2 a_k
    const Sign s = sign(add(multiply(P, P), multiply(multiply(Q, Q), radicand(k)), true));
    return s == ZERO ? ZERO : (s == POSITIVE ? sp : sq);
  }

  /// An interval that contains the value (double precision).
  Interval_nt<false> interval(const Root_polynomial& a) const
  {
    Protect_FPU_rounding<true> protection;
    Interval_nt<false> s(0);
    for(const Term& t : a) {
      Interval_nt<false> x(q_interval(t.c));
      for(Root_mask m = t.mask; m != 0; m &= m - 1) x *= roots_[__builtin_ctzll(m)].value;
      s += x;
    }
    return s;
  }

  /// a / b, b != 0.
  Root_polynomial divide(const Root_polynomial& a, const Root_polynomial& b) const
  {
    CGAL_precondition(!b.empty());
    if(is_rational(b)) return scale(a, Rational(1) / b[0].c);
    Root_mask all = 0;
    for(const Term& t : b) all |= t.mask;
    const int k = highest_root(all);
    const Root_mask bit = Root_mask(1) << k;
    Root_polynomial P, Q;
    for(const Term& t : b) {
      if(t.mask & bit) Q.push_back(Term{t.mask & ~bit, t.c});
      else P.push_back(t);
    }
    // b (P - Q s_k) = P^2 - Q^2 a_k, free of s_k
    Root_polynomial norm = add(multiply(P, P), multiply(multiply(Q, Q), radicand(k)), true);
    if(sign(norm) == ZERO) {
      // P = Q s_k (b != 0): b = 2P
      if(sign(b) == ZERO) throw std::domain_error("division by zero");
      return divide(a, scale(P, Rational(2)));
    }
    Root_polynomial conj = P;
    for(const Term& t : Q) conj.push_back(Term{t.mask | bit, -t.c});
    normalize(conj);
    return divide(multiply(a, conj), norm);
  }

  /// The non-negative square root of a >= 0.
  Root_polynomial square_root(const Root_polynomial& a)
  {
    const Sign s = sign(a);
    if(s == NEGATIVE) throw std::domain_error("square root of a negative number");
    if(s == ZERO) return Root_polynomial();
    if(is_rational(a)) {
      const Rational q = a[0].c;
      Rational r;
      if(rational_square_root(q, r)) return constant(r);
      // an existing root whose ratio to q is a rational square
      for(std::size_t j = 0; j < roots_.size(); ++j) {
        if(!roots_[j].rational) continue;
        if(rational_square_root(q / roots_[j].q, r)) return Root_polynomial{Term{Root_mask(1) << j, r}};
      }
    } else {
      for(std::size_t j = 0; j < roots_.size(); ++j)
        if(!roots_[j].rational && roots_[j].radicand == a) return Root_polynomial{Term{Root_mask(1) << j, Rational(1)}};
    }
    if(roots_.size() >= 64) throw std::length_error("more than 64 square roots in one exact evaluation");
    Root root;
    root.radicand = a;
    root.rational = is_rational(a);
    if(root.rational) root.q = a[0].c;
    {
      Protect_FPU_rounding<true> protection;
      Interval_nt<false> v = interval(a);
      root.value = CGAL::sqrt(Interval_nt<false>((std::max)(0.0, v.inf()), (std::max)(0.0, v.sup())));
    }
    roots_.push_back(root);
    return Root_polynomial{Term{Root_mask(1) << (roots_.size() - 1), Rational(1)}};
  }

  /// The value as an MPFR number, rounded to nearest, at `precision` bits
  /// of working precision (sqrt and products rounded to nearest: an
  /// approximation, refined by the caller).
  void approximate(const Root_polynomial& a, mpfr_prec_t precision, mpfr_t out) const
  {
    std::vector<mpfr_t> roots(roots_.size());
    for(std::size_t k = 0; k < roots_.size(); ++k) {
      mpfr_init2(roots[k], precision);
      evaluate(roots_[k].radicand, roots, precision, roots[k]);
      if(mpfr_sgn(roots[k]) < 0) mpfr_set_zero(roots[k], 1);
      mpfr_sqrt(roots[k], roots[k], MPFR_RNDN);
    }
    evaluate(a, roots, precision, out);
    for(std::size_t k = 0; k < roots_.size(); ++k) mpfr_clear(roots[k]);
  }

private:
  struct Root {
    Root_polynomial radicand;
    bool rational = false;
    Rational q;                   // the radicand, when rational
    Interval_nt<false> value;     // the root, as a double interval
  };

  const Root_polynomial& radicand(int k) const { return roots_[k].radicand; }

  // Adds c x^a x^b to out (unnormalised), replacing s_k^2 by a_k.
  void add_monomial_product(Root_mask a, Root_mask b, const Rational& c, Root_polynomial& out) const
  {
    const Root_mask common = a & b;
    if(common == 0) {
      out.push_back(Term{a | b, c});
      return;
    }
    const int k = highest_root(common);
    const Root_mask bit = Root_mask(1) << k;
    a &= ~bit;
    b &= ~bit;
    const Root& r = roots_[k];
    if(r.rational) {
      add_monomial_product(a, b, c * r.q, out);
      return;
    }
    // x^a x^b a_k: the radicand has only roots below k, so the common
    // roots of each product below are below k and the recursion ends
    Root_polynomial ab;
    add_monomial_product(a, b, c, ab);
    for(const Term& s : ab)
      for(const Term& t : r.radicand) add_monomial_product(s.mask, t.mask, s.c * t.c, out);
  }

  static void evaluate(const Root_polynomial& a, const std::vector<mpfr_t>& roots, mpfr_prec_t precision, mpfr_t out)
  {
    mpfr_t term;
    mpfr_init2(term, precision);
    mpfr_set_zero(out, 1);
    for(const Term& t : a) {
      mpfr_set_q(term, internal::to_gmpq(t.c).mpq(), MPFR_RNDN);
      for(Root_mask m = t.mask; m != 0; m &= m - 1) mpfr_mul(term, term, roots[__builtin_ctzll(m)], MPFR_RNDN);
      mpfr_add(out, out, term, MPFR_RNDN);
    }
    mpfr_clear(term);
  }

  Basic_nested_root_context* previous_;
  std::vector<Root> roots_;
};

/// A number in the current Basic_nested_root_context<Q>.
template <class Q>
class Basic_nested_root_number
{
  typedef Basic_nested_root_context<Q> Nested_root_context;
  typedef typename Nested_root_context::Root_polynomial Root_polynomial;
  typedef Basic_nested_root_number Nested_root_number;

public:
  typedef Q Rational;

  Basic_nested_root_number() {}
  Basic_nested_root_number(int i) : p_(Nested_root_context::constant(Q(i))) {}
  Basic_nested_root_number(double d) : p_(Nested_root_context::constant(Q(d))) {}
  explicit Basic_nested_root_number(const Q& q) : p_(Nested_root_context::constant(q)) {}

  const Root_polynomial& polynomial() const { return p_; }
  bool is_rational() const { return Nested_root_context::is_rational(p_); }
  Sign sign() const { return Nested_root_context::get().sign(p_); }

  /// An interval of doubles that contains the value.
  Interval_nt<false> to_interval() const
  {
    if(is_rational()) return q_interval(Nested_root_context::rational_value(p_));
    const Interval_nt<false> coarse = Nested_root_context::get().interval(p_);
    if(coarse.sup() - coarse.inf() <= 4 * std::numeric_limits<double>::epsilon() * (std::max)(std::fabs(coarse.inf()), std::fabs(coarse.sup())))
      return coarse;
    // cancellation: an MPFR approximation, widened by one unit in the last place
    const double d = to_double();
    return Interval_nt<false>(std::nextafter(std::nextafter(d, -HUGE_VAL), -HUGE_VAL),
                              std::nextafter(std::nextafter(d, HUGE_VAL), HUGE_VAL));
  }

  /// The value rounded to the nearest double, ties to even.  A number in
  /// roots can be rational without being a rational polynomial (its roots
  /// cancel), and then lie exactly halfway between two doubles: the ties of
  /// symmetric input, whose branch points are midpoints of input points.
  /// So an approximation near such a midpoint is settled by the exact sign
  /// of the difference, and a zero by the exact sign of the value.
  double to_double() const
  {
    if(is_rational()) return nearest_double(internal::to_gmpq(Nested_root_context::rational_value(p_)));
    // (a zero in roots: its approximations are tiny numbers of either sign;
    // the sign starts with a double-interval evaluation, which settles all
    // but values near zero)
    if(sign() == ZERO) return 0;
    double previous = 0;
    bool first = true;
    for(mpfr_prec_t precision = 192;; precision *= 2) {
      mpfr_t x;
      mpfr_init2(x, precision);
      Nested_root_context::get().approximate(p_, precision, x);
      const double d = mpfr_get_d(x, MPFR_RNDN);
      // two approximations at precisions far beyond 53 bits that round
      // to the same double: the rounding is settled, but for a tie
      if((!first && d == previous) || precision >= 4096) {
        const double result = settle_tie(x, d, precision);
        mpfr_clear(x);
        return result;
      }
      mpfr_clear(x);
      previous = d;
      first = false;
    }
  }

  Nested_root_number operator-() const { return from(Nested_root_context::scale(p_, Q(-1))); }

  friend Nested_root_number operator+(const Nested_root_number& a, const Nested_root_number& b)
  {
    return from(Nested_root_context::add(a.p_, b.p_, false));
  }
  friend Nested_root_number operator-(const Nested_root_number& a, const Nested_root_number& b)
  {
    return from(Nested_root_context::add(a.p_, b.p_, true));
  }
  friend Nested_root_number operator*(const Nested_root_number& a, const Nested_root_number& b)
  {
    return from(Nested_root_context::get().multiply(a.p_, b.p_));
  }
  friend Nested_root_number operator/(const Nested_root_number& a, const Nested_root_number& b)
  {
    return from(Nested_root_context::get().divide(a.p_, b.p_));
  }
  Nested_root_number& operator+=(const Nested_root_number& b) { return *this = *this + b; }
  Nested_root_number& operator-=(const Nested_root_number& b) { return *this = *this - b; }
  Nested_root_number& operator*=(const Nested_root_number& b) { return *this = *this * b; }
  Nested_root_number& operator/=(const Nested_root_number& b) { return *this = *this / b; }

  friend Sign sign_of_difference(const Nested_root_number& a, const Nested_root_number& b) { return (a - b).sign(); }
  friend bool operator<(const Nested_root_number& a, const Nested_root_number& b) { return sign_of_difference(a, b) == NEGATIVE; }
  friend bool operator>(const Nested_root_number& a, const Nested_root_number& b) { return sign_of_difference(a, b) == POSITIVE; }
  friend bool operator<=(const Nested_root_number& a, const Nested_root_number& b) { return sign_of_difference(a, b) != POSITIVE; }
  friend bool operator>=(const Nested_root_number& a, const Nested_root_number& b) { return sign_of_difference(a, b) != NEGATIVE; }
  friend bool operator==(const Nested_root_number& a, const Nested_root_number& b) { return sign_of_difference(a, b) == ZERO; }
  friend bool operator!=(const Nested_root_number& a, const Nested_root_number& b) { return sign_of_difference(a, b) != ZERO; }

  friend Nested_root_number abs(const Nested_root_number& a) { return a.sign() == NEGATIVE ? -a : a; }
  friend Nested_root_number sqrt(const Nested_root_number& a) { return from(Nested_root_context::get().square_root(a.p_)); }

private:
  struct From {};
  Basic_nested_root_number(From, Root_polynomial&& p) : p_(std::move(p)) {}
  // d is x rounded to nearest.  If x is within 2^-(precision - 64) of
  // its size of the midpoint between d and the neighbour on its side, the
  // exact sign of the value minus that midpoint decides (ties to even).
  double settle_tie(const mpfr_t x, double d, mpfr_prec_t precision) const
  {
    const int side = mpfr_cmp_d(x, d);
    if(side == 0 || !std::isfinite(d))
      return d;
    const double neighbour = std::nextafter(d, side > 0 ? HUGE_VAL : -HUGE_VAL);
    mpfr_t m;
    mpfr_init2(m, precision);
    mpfr_set_d(m, d, MPFR_RNDN);
    mpfr_add_d(m, m, neighbour, MPFR_RNDN);   // exact: 54 bits
    mpfr_div_2ui(m, m, 1, MPFR_RNDN);
    mpfr_sub(m, x, m, MPFR_RNDN);
    const bool near = mpfr_zero_p(m) || mpfr_get_exp(m) < mpfr_get_exp(x) - (precision - 64);
    mpfr_clear(m);
    if(!near)
      return d;
    const Nested_root_number midpoint = (Nested_root_number(d) + Nested_root_number(neighbour)) * Nested_root_number(0.5);
    const Sign s = sign_of_difference(*this, midpoint);
    if(s == ZERO) {
      std::int64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      return (bits & 1) == 0 ? d : neighbour;
    }
    return (s == POSITIVE) == (side > 0) ? neighbour : d;
  }

  static Nested_root_number from(Root_polynomial&& p) { return Nested_root_number(From(), std::move(p)); }

  Root_polynomial p_;
};

typedef Basic_nested_root_context<Gmp_rational> Nested_root_context;
typedef Basic_nested_root_number<Gmp_rational> Nested_root_number;
typedef Basic_nested_root_context<Small_rational> Small_nested_root_context;
typedef Basic_nested_root_number<Small_rational> Small_nested_root_number;

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_NESTED_ROOT_NUMBER_H
