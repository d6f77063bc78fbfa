// Unit tests of the exact numbers of the filtered traits: the one-root
// numbers (internal/One_root_rational.h): exact ties, signs against MPFR at
// high precision, and the cases that must be handed on (Not_one_root); and
// the nested-root numbers (internal/Nested_root_number.h) that take them:
// several roots, roots of roots, roots that denest, exact zeros, division;
// and the MPFR intervals' products and quotients by the signs of the bounds
// (internal/Mpfr_interval.h) against the hull of the four products; and
// the certification of double-double results and the double-double
// intervals (internal/Double_double.h), those against MPFR.
#include <CGAL/Progressive_medial_axis_2/internal/Double_double.h>
#include <CGAL/Progressive_medial_axis_2/internal/Mpfr_interval.h>
#include <CGAL/Progressive_medial_axis_2/internal/One_root_rational.h>
#include <CGAL/Progressive_medial_axis_2/internal/Nested_root_number.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_constructions.h>

#include <pma_test/check.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <type_traits>
#include <vector>

using CGAL::Gmpq;
using CGAL::Progressive_medial_axes::internal::Not_one_root;
using CGAL::Progressive_medial_axes::internal::One_root_rational;
using CGAL::Progressive_medial_axes::internal::One_root_sqrt;
using CGAL::Progressive_medial_axes::internal::Small_rational;
using CGAL::Progressive_medial_axes::internal::Small_rational_overflow;
using CGAL::Progressive_medial_axes::internal::Small_one_root;
using CGAL::Progressive_medial_axes::internal::Nested_root_context;
using CGAL::Progressive_medial_axes::internal::Nested_root_number;
using CGAL::Progressive_medial_axes::internal::Small_nested_root_context;
using CGAL::Progressive_medial_axes::internal::Small_nested_root_number;
using CGAL::Progressive_medial_axes::internal::Mpfr_interval;
using CGAL::Progressive_medial_axes::internal::Mpfr_precision_scope;

namespace {


One_root_rational root(int d) { return sqrt(One_root_rational(d)); }

// a + b sqrt(d) in MPFR at 1024 bits
double sign_mpfr(long a1, long b1, long d1, long a2, long b2, long d2)
{
  mpfr_t x, y;
  mpfr_init2(x, 1024);
  mpfr_init2(y, 1024);
  mpfr_set_si(x, d1, MPFR_RNDN);
  mpfr_sqrt(x, x, MPFR_RNDN);
  mpfr_mul_si(x, x, b1, MPFR_RNDN);
  mpfr_add_si(x, x, a1, MPFR_RNDN);
  mpfr_set_si(y, d2, MPFR_RNDN);
  mpfr_sqrt(y, y, MPFR_RNDN);
  mpfr_mul_si(y, y, b2, MPFR_RNDN);
  mpfr_add_si(y, y, a2, MPFR_RNDN);
  mpfr_sub(x, x, y, MPFR_RNDN);
  const double r = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  mpfr_clear(y);
  return r;
}

template <class N>
N nroot(const N& x) { return sqrt(x); }

// sign of (expression evaluated by f in MPFR at 4096 bits), 0 if below 1e-1000
template <class F>
CGAL::Sign mpfr_sign(const F& f)
{
  mpfr_t x;
  mpfr_init2(x, 4096);
  f(x);
  CGAL::Sign s = CGAL::ZERO;
  if(mpfr_cmpabs_ui(x, 0) != 0 && mpfr_get_exp(x) > -3300) s = mpfr_sgn(x) > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
  mpfr_clear(x);
  return s;
}

// The same tests for both rational types of the coefficients (the small
// one fits every number here).
template <class N, class Context>
void nested_root_tests()
{
  Context context;
  const N two(2), three(3);
  const N s2 = nroot(two), s3 = nroot(three), s6 = nroot(N(6)), s8 = nroot(N(8));
  CHECK(s8 * s2 == N(4), "nested: sqrt 8 * sqrt 2 = 4");
  CHECK(s8 == N(2) * s2, "nested: sqrt 8 = 2 sqrt 2 (shared root)");
  CHECK(s2 * s3 == s6, "nested: sqrt 2 sqrt 3 = sqrt 6");
  CHECK((s2 + s3) * (s2 + s3) == N(5) + N(2) * s6, "nested: (sqrt 2 + sqrt 3)^2 = 5 + 2 sqrt 6");
  CHECK(nroot(N(5) + N(2) * s6) == s2 + s3, "nested: sqrt(5 + 2 sqrt 6) = sqrt 2 + sqrt 3 (denests)");
  const N d = nroot(N(3) + N(2) * s2);   // = 1 + sqrt 2, a root dependent on sqrt 2
  CHECK(d == N(1) + s2 && d - s2 == N(1), "nested: sqrt(3 + 2 sqrt 2) = 1 + sqrt 2");
  CHECK(N(1) / (d - s2) == N(1), "nested: division by a denominator with dependent roots");
  CHECK(N(7) / (d + s2 - N(1)) == N(7) / (N(2) * s2), "nested: division, dependent conjugate");
  const N q = N(1) + s2 + s3;
  CHECK((N(1) / q) * q == N(1), "nested: 1 / (1 + sqrt 2 + sqrt 3) * (1 + sqrt 2 + sqrt 3) = 1");
  // sqrt(a + sqrt b) sqrt(a - sqrt b) = sqrt(a^2 - b)
  const N sb = nroot(N(7));
  CHECK(nroot(N(4) + sb) * nroot(N(4) - sb) == N(3), "nested: sqrt(4 + sqrt 7) sqrt(4 - sqrt 7) = 3");
  CHECK(nroot(N(4) + sb) > nroot(N(4) - sb) && !(nroot(N(4) + sb) < nroot(N(4) - sb)), "nested: ordering");
  CHECK(s2.to_double() == std::sqrt(2.0) && (N(1) / N(3)).to_double() == 1.0 / 3.0, "nested: to_double");
  CHECK(d.to_interval().inf() <= 1 + std::sqrt(2.0) && d.to_interval().sup() >= 1 + std::sqrt(2.0), "nested: to_interval");
  // to_double of rational values written with roots that cancel only in value
  // (d - sqrt 2 = 1): a midpoint of two doubles rounds to even, on both sides
  // of zero, and a zero is 0 (the ties of symmetric input)
  for(int k = 1; k <= 7; k += 2) {
    const N midpoint = (d - s2) * (N(1) + N(k) * N(std::ldexp(1.0, -53)));   // 1 + k 2^-53
    const int j = ((k + 1) / 2) % 2 == 0 ? (k + 1) / 2 : (k - 1) / 2;           // the even neighbour
    const double expected = 1 + std::ldexp(double(j), -52);
    CHECK(midpoint.to_double() == expected && (-midpoint).to_double() == -expected,
          "nested: 1 + " << k << " 2^-53 rounds to even");
  }
  CHECK((d - s2 - N(1)).to_double() == 0 && ((d - s2) * N(3) - N(3)).to_double() == 0, "nested: zero");

  // random a + b sqrt(c + e sqrt f) + g sqrt h against the same built another
  // way, and against a perturbed value, signs checked against MPFR
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> small(-9, 9), pos(1, 30);
  int compared = 0;
  for(int i = 0; i < 300; ++i) {
    Context local;
    const int a = small(rng), b = small(rng), c = pos(rng) + 50, e = small(rng), f = pos(rng), g = small(rng), h = pos(rng);
    const N x = N(a) + N(b) * nroot(N(c) + N(e) * nroot(N(f))) + N(g) * nroot(N(h));
    // the same value: b sqrt(c + e sqrt f) = sqrt(b^2 c + b^2 e sqrt f) sign(b)
    const N inner = nroot(N(b * b * c) + N(b * b * e) * nroot(N(f)));
    const N y = N(a) + (b < 0 ? -inner : inner) + N(g) * nroot(N(4 * h)) / N(2);
    if(!(x == y)) { ++pma_test::failures(); std::printf("FAIL: nested identity %d\n", i); }
    const int k = small(rng);
    const N z = y + N(k) * nroot(N(2)) - N(k) * nroot(N(3));
    const CGAL::Sign expected = mpfr_sign([&](mpfr_t r) {
      mpfr_t t;
      mpfr_init2(t, 4096);
      mpfr_set_si(t, 2, MPFR_RNDN); mpfr_sqrt(t, t, MPFR_RNDN); mpfr_mul_si(r, t, k, MPFR_RNDN);
      mpfr_set_si(t, 3, MPFR_RNDN); mpfr_sqrt(t, t, MPFR_RNDN); mpfr_mul_si(t, t, k, MPFR_RNDN); mpfr_sub(r, r, t, MPFR_RNDN);
      mpfr_clear(t);
    });
    if((z - x).sign() != expected) { ++pma_test::failures(); std::printf("FAIL: nested sign %d\n", i); }
    ++compared;
  }
  std::printf("%d nested-root identities and signs\n", compared);
}

// Small_rational coefficients: a product that does not fit in 128 bits
// throws, never gives a wrong value; the same in Gmpq is exact.
void small_nested_root_overflow_tests()
{
  bool thrown = false;
  try {
    Small_nested_root_context context;
    Small_nested_root_number x = sqrt(Small_nested_root_number(std::ldexp(1.0, 60))) + sqrt(Small_nested_root_number(3));
    for(int i = 0; i < 4; ++i) x = x * x;
  } catch(Small_rational_overflow&) {
    thrown = true;
  }
  CHECK(thrown, "small nested: a product beyond 128 bits throws");
  Nested_root_context context;
  Nested_root_number y = sqrt(Nested_root_number(std::ldexp(1.0, 60))) + sqrt(Nested_root_number(3));
  for(int i = 0; i < 4; ++i) y = y * y;
  CHECK(y.sign() == CGAL::POSITIVE && y.to_double() > std::ldexp(1.0, 479), "nested: the same in Gmpq");
}

// Small_rational and the one-root numbers over it agree with Gmpq, and
// overflow is reported, never wrong.
void small_rational_tests()
{
  CHECK(Small_rational(0.75) * Small_rational(4) == Small_rational(3), "small: 0.75 * 4 = 3");
  CHECK((Small_rational(1) / Small_rational(3)).to_gmpq() == Gmpq(1, 3), "small: 1 / 3");
  CHECK((Small_rational(std::ldexp(1.0, -100)) + Small_rational(1)).to_gmpq() == Gmpq(std::ldexp(1.0, -100)) + Gmpq(1), "small: 2^-100 + 1");
  Small_rational r;
  CHECK(rational_square_root(Small_rational(9) / Small_rational(16), r) && r == Small_rational(0.75), "small: sqrt(9/16)");
  CHECK(!rational_square_root(Small_rational(2), r), "small: 2 is not a square");
  bool thrown = false;
  try {
    Small_rational x(1e18);
    for(int i = 0; i < 4; ++i) x = x * x;
  } catch(Small_rational_overflow&) {
    thrown = true;
  }
  CHECK(thrown, "small: overflow is reported");
  // random expressions in both types
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> small(-1000, 1000);
  int compared = 0, overflows = 0;
  for(int i = 0; i < 20000; ++i) {
    Small_rational x(small(rng)), y(small(rng) + 0.5), z(small(rng) / 8.0);
    Gmpq gx = x.to_gmpq(), gy = y.to_gmpq(), gz = z.to_gmpq();
    try {
      for(int k = 0; k < 6; ++k) {
        const int op = small(rng) & 3;
        if(op == 0) { x = x + y * z; gx = gx + gy * gz; }
        else if(op == 1) { x = x - y / z; gx = gx - gy / gz; }
        else if(op == 2) { y = x * z - y; gy = gx * gz - gy; }
        else { z = (x + y) / (z * z + Small_rational(1)); gz = (gx + gy) / (gz * gz + Gmpq(1)); }
        if(x.to_gmpq() != gx || y.to_gmpq() != gy || z.to_gmpq() != gz || x.sign() != CGAL::sign(gx)) {
          ++pma_test::failures();
          std::printf("FAIL: small rational differs from Gmpq (%d)\n", i);
          break;
        }
        if(CGAL::to_interval(gx).first < x.to_interval().inf() || CGAL::to_interval(gx).second > x.to_interval().sup()) {
          ++pma_test::failures();
          std::printf("FAIL: small rational interval (%d)\n", i);
          break;
        }
      }
    } catch(Small_rational_overflow&) {
      ++overflows;
    }
    ++compared;
  }
  // integers and fractions around the 64-bit boundary, where the arithmetic
  // switches between 64-bit and 128-bit operations
  std::uniform_int_distribution<int> bits(1, 70);
  std::uniform_int_distribution<std::int64_t> word(INT64_MIN, INT64_MAX);
  for(int i = 0; i < 20000; ++i) {
    auto value = [&]() {
      const int b = bits(rng);
      const double m = std::ldexp(double(word(rng) >> 11), -52);   // |m| < 1, 52 bits
      return std::ldexp(m, b) + (i % 3 == 0 ? 0.0 : std::ldexp(1.0, -bits(rng) % 40));
    };
    try {
      const Small_rational x(value()), y(value());
      const Gmpq gx = x.to_gmpq(), gy = y.to_gmpq();
      Gmpq quotient;
      if(CGAL::sign(gy) != CGAL::ZERO) quotient = gx / gy;
      if(Gmpq(CGAL::to_double(gx)) != gx || (x * y).to_gmpq() != gx * gy || (x + y).to_gmpq() != gx + gy ||
         (x - y).to_gmpq() != gx - gy || (CGAL::sign(gy) != CGAL::ZERO && (x / y).to_gmpq() != quotient)) {
        ++pma_test::failures();
        std::printf("FAIL: small rational near 2^64 differs from Gmpq (%d)\n", i);
      }
    } catch(Small_rational_overflow&) {
      ++overflows;
    }
  }
  // pooled GMP rationals against Gmpq: values that grow, copies, moves and
  // storage reused from the pool
  {
    using CGAL::Progressive_medial_axes::internal::Gmp_rational;
    std::uniform_real_distribution<double> real(-1e3, 1e3);
    for(int i = 0; i < 2000; ++i) {
      Gmp_rational x(real(rng)), y(real(rng)), z(small(rng));
      Gmpq gx = x.to_gmpq(), gy = y.to_gmpq(), gz = z.to_gmpq();
      for(int k = 0; k < 8; ++k) {
        const int op = small(rng) & 3;
        if(op == 0) { x = x + y * z; gx = gx + gy * gz; }
        else if(op == 1 && CGAL::sign(gz) != CGAL::ZERO) { x = x - y / z; gx = gx - gy / gz; }
        else if(op == 2) { Gmp_rational t = -x; y = std::move(t); y *= z; gy = -gx * gz; }
        else { Gmp_rational t(y); t -= x; z = t; gz = gy - gx; }
        Gmp_rational r;
        const bool square = rational_square_root(z * z, r);
        if(x.to_gmpq() != gx || y.to_gmpq() != gy || z.to_gmpq() != gz || x.sign() != CGAL::sign(gx) ||
           !square || r.to_gmpq() != CGAL::abs(gz) || (x == y) != (gx == gy) ||
           CGAL::to_interval(gx) != std::make_pair(x.to_interval().inf(), x.to_interval().sup())) {
          ++pma_test::failures();
          std::printf("FAIL: pooled GMP rational differs from Gmpq (%d)\n", i);
          break;
        }
      }
    }
  }
  // one-root numbers over small rationals against Gmpq
  for(int i = 0; i < 5000; ++i) {
    const int a1 = small(rng), b1 = small(rng), d1 = 1 + (small(rng) & 15), a2 = small(rng), b2 = small(rng);
    const int d2 = (i % 2) ? d1 : 1 + (small(rng) & 15);
    const Small_one_root p = Small_one_root(a1) + Small_one_root(b1) * sqrt(Small_one_root(d1));
    const Small_one_root q = Small_one_root(a2) + Small_one_root(b2) * sqrt(Small_one_root(d2));
    const One_root_rational gp = One_root_rational(a1) + One_root_rational(b1) * sqrt(One_root_rational(d1));
    const One_root_rational gq = One_root_rational(a2) + One_root_rational(b2) * sqrt(One_root_rational(d2));
    const bool same_root = d1 == d2 || b1 == 0 || b2 == 0;
    if(sign_of_difference(p, q) != sign_of_difference(gp, gq) ||
       (same_root && (p * q).to_big() != gp * gq)) {
      ++pma_test::failures();
      std::printf("FAIL: small one-root differs from Gmpq (%d)\n", i);
    }
  }
  std::printf("%d small-rational expressions (%d overflowed), 5000 one-root comparisons\n", compared, overflows);
}

// The product or quotient of a and b as the hull of the four products or
// quotients of their bounds, each rounded outwards: a and b's bounds in x
// and y, the result's in lo and hi.
void hull_of_four(mpfr_srcptr x0, mpfr_srcptr x1, mpfr_srcptr y0, mpfr_srcptr y1, bool divide, mpfr_ptr lo, mpfr_ptr hi)
{
  mpfr_t t;
  mpfr_init2(t, mpfr_get_prec(lo));
  const mpfr_srcptr x[2] = {x0, x1}, y[2] = {y0, y1};
  for(int i = 0; i < 4; ++i) {
    auto op = divide ? mpfr_div : mpfr_mul;
    op(t, x[i / 2], y[i % 2], MPFR_RNDD);
    if(i == 0 || mpfr_less_p(t, lo)) mpfr_set(lo, t, MPFR_RNDD);
    op(t, x[i / 2], y[i % 2], MPFR_RNDU);
    if(i == 0 || mpfr_greater_p(t, hi)) mpfr_set(hi, t, MPFR_RNDU);
  }
  mpfr_clear(t);
}

// Products and quotients of intervals of every sign pattern (positive,
// negative, containing 0, zero, points), at the filtered traits' precision
// (191 bits), at the largest inline one (256 bits) and at a precision whose
// bounds are on the heap (1024 bits).
void mpfr_interval_tests()
{
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(-3, 3);
  int compared = 0;
  for(mpfr_prec_t precision : {191, 256, 1024}) {
    Mpfr_precision_scope scope(precision);
    auto make = [&](int kind) {
      const double a = u(random), b = u(random);
      switch(kind) {
      case 0: return Mpfr_interval(a);                                             // a point
      case 1: return Mpfr_interval(a) / Mpfr_interval(3);                          // narrow, the sign of a
      case 2: return Mpfr_interval(a) / Mpfr_interval(3) * Mpfr_interval(3) - Mpfr_interval(a);   // around 0
      case 3: return Mpfr_interval(a) / Mpfr_interval(3) + Mpfr_interval(b) / Mpfr_interval(7);
      default: return Mpfr_interval(0);
      }
    };
    mpfr_t lo, hi;
    mpfr_init2(lo, precision);
    mpfr_init2(hi, precision);
    for(int i = 0; i < 20000; ++i) {
      const Mpfr_interval a = make(int(random() % 5)), b = make(int(random() % 5));
      for(bool divide : {false, true}) {
        if(divide && mpfr_sgn(b.lower()) <= 0 && mpfr_sgn(b.upper()) >= 0) {
          bool thrown = false;
          try {
            (void)(a / b);
          } catch(CGAL::Uncertain_conversion_exception&) {
            thrown = true;
          }
          CHECK(thrown, "an MPFR interval divided by one containing 0 throws");
          continue;
        }
        const Mpfr_interval r = divide ? a / b : a * b;
        hull_of_four(a.lower(), a.upper(), b.lower(), b.upper(), divide, lo, hi);
        ++compared;
        if(!mpfr_equal_p(r.lower(), lo) || !mpfr_equal_p(r.upper(), hi)) {
          ++pma_test::failures();
          std::printf("FAIL: MPFR interval %s differs from the hull of four (%d bits, case %d)\n",
                      divide ? "quotient" : "product", int(precision), i);
        }
      }
    }
    mpfr_clear(lo);
    mpfr_clear(hi);
  }
  std::printf("%d MPFR interval products and quotients\n", compared);
}

} // namespace

// The interval square root of the interval stage (nt_sqrt(), which does not
// leave the upward rounding) against MPFR's square roots rounded down and
// up: the same doubles, on perfect squares, random doubles of every
// exponent, subnormals, zero, intervals with a negative lower end and
// infinity.
void interval_sqrt_tests()
{
  typedef CGAL::Interval_nt<false> I;
  std::mt19937_64 rng(11);
  std::vector<double> xs = {0.0, -0.0, 1.0, 2.0, 4.0, 0.25, 1e-320, 4.9406564584124654e-324, 2.2250738585072014e-308,
                            1.7976931348623157e308, 9007199254740993.0, 3.0, 1e300, 1e-300, HUGE_VAL};
  for(int i = 1; i < 2000; ++i) xs.push_back(double(i) * double(i));
  std::uniform_int_distribution<std::uint64_t> bits(0, 0x7FEFFFFFFFFFFFFFull);
  for(int i = 0; i < 200000; ++i) {
    std::uint64_t b = bits(rng);
    double x;
    std::memcpy(&x, &b, sizeof x);
    xs.push_back(x);
    xs.push_back(std::nextafter(x, 0.0) * std::nextafter(x, 0.0));
  }
  mpfr_t m;
  mpfr_init2(m, 53);
  int failures = 0;
  CGAL::Protect_FPU_rounding<true> protection;
  for(std::size_t k = 0; k < xs.size(); ++k) {
    const double lo = xs[k], hi = xs[(k * 7919) % xs.size()];
    const I x((std::min)(lo, hi), (std::max)(lo, hi));
    const I r = CGAL::Progressive_medial_axes::internal::nt_sqrt(x);
    double down = 0, up;
    if(x.inf() > 0) {
      mpfr_set_d(m, x.inf(), MPFR_RNDN);
      mpfr_sqrt(m, m, MPFR_RNDD);
      down = mpfr_get_d(m, MPFR_RNDD);
    }
    mpfr_set_d(m, x.sup(), MPFR_RNDN);
    mpfr_sqrt(m, m, MPFR_RNDU);
    up = mpfr_get_d(m, MPFR_RNDU);
    if(!(r.inf() == down && r.sup() == up) && failures++ < 5)
      std::printf("FAIL: sqrt([%.17g, %.17g]) = [%.17g, %.17g], expected [%.17g, %.17g]\n", x.inf(), x.sup(), r.inf(),
                  r.sup(), down, up);
  }
  const I negative(-1.0, 4.0);
  const I r = CGAL::Progressive_medial_axes::internal::nt_sqrt(negative);
  if(!(r.inf() == 0 && r.sup() == 2)) ++failures;
  mpfr_clear(m);
  CHECK(failures == 0, "interval square roots are MPFR's, rounded down and up");
}

// A double-double result is kept only if everything within its error bound
// (from the width of the double interval) rounds to one double.
void double_double_tests()
{
  using CGAL::Progressive_medial_axes::internal::Double_double;
  using CGAL::Progressive_medial_axes::internal::rounds_within;
  const double u = std::ldexp(1.0, -52);
  const Double_double near_one = Double_double(1) + Double_double(std::ldexp(1.0, -60));
  CHECK(rounds_within(near_one, 1, 1 + u, false), "double-double: 1 + 2^-60 rounds to 1");
  CHECK(near_one.to_double() == 1, "double-double: to_double");
  const Double_double midpoint = Double_double(1) + Double_double(std::ldexp(1.0, -53));
  CHECK(!rounds_within(midpoint, 1, 1 + u, false), "double-double: a midpoint is left to exact arithmetic");
  CHECK(!rounds_within(Double_double(0), -1e-16, 1e-16, false), "double-double: so is a zero");
  CHECK(!rounds_within(near_one, 1 + u, 1 + 2 * u, false), "double-double: outside its interval");
  // a cancelling square root widens the bound from 2^-40 to 2^-16 of the width
  CHECK(rounds_within(near_one, 1 - std::ldexp(1.0, -30), 1 + std::ldexp(1.0, -30), false) &&
          !rounds_within(near_one, 1 - std::ldexp(1.0, -30), 1 + std::ldexp(1.0, -30), true) &&
          rounds_within(near_one, 1 - std::ldexp(1.0, -40), 1 + std::ldexp(1.0, -40), true),
        "double-double: the bound of a cancelling square root");
}

// The double-double intervals (internal/Double_double.h) against MPFR
// intervals at 1024 bits, on random expressions of sums, differences,
// products, quotients and square roots, with cancellations, at scales from
// 2^-1000 to 2^980: every double-double interval must enclose the MPFR one
// (compared exactly), or the operation must throw; a certain comparison
// must be MPFR's; a value said to round to one double must.
void double_double_interval_tests()
{
  using CGAL::Progressive_medial_axes::internal::Double_double_interval;
  typedef Double_double_interval Dd;
  Mpfr_precision_scope scope(1024);
  mpfr_t c, lo, hi;
  mpfr_init2(c, 4400);
  mpfr_init2(lo, 4400);
  mpfr_init2(hi, 4400);
  auto encloses = [&](const Dd& d, const Mpfr_interval& m) {
    mpfr_set_d(c, d.value().hi(), MPFR_RNDN);
    mpfr_add_d(c, c, d.value().lo(), MPFR_RNDN);   // exact at 4400 bits
    mpfr_sub_d(lo, c, d.radius(), MPFR_RNDN);
    mpfr_add_d(hi, c, d.radius(), MPFR_RNDN);
    return mpfr_lessequal_p(lo, m.lower()) && mpfr_greaterequal_p(hi, m.upper()) && d.inf() <= m.inf() &&
           d.sup() >= m.sup();
  };
  struct Both {
    Dd d;
    Mpfr_interval m;
  };
  std::mt19937_64 random(11);
  int checked = 0, narrow = 0, rounded = 0, comparisons = 0;
  for(int scale : {0, -1000, -600, 500, 980}) {
    const double factor = std::ldexp(1.0, scale);
    for(int round = 0; round < 400; ++round) {
      std::vector<Both> v;
      for(int i = 0; i < 6; ++i) {
        // small integers, and doubles with random bits (repeated below, so
        // that differences cancel)
        const double x = (random() % 2 ? double(int(random() % 41) - 20)
                                       : std::ldexp(double(random() >> 11), -53 + int(random() % 9) - 4)) *
                         factor;
        v.push_back(Both{Dd(x), Mpfr_interval(x)});
      }
      for(int step = 0; step < 40; ++step) {
        const Both& a = v[random() % v.size()];
        const Both& b = v[random() % v.size()];
        const int op = int(random() % 6);
        Both r;
        // the operation in one number type: false if it throws (undecided)
        auto apply = [op](const auto& x, const auto& y, auto& result) {
          typedef std::decay_t<decltype(x)> N;
          try {
            switch(op) {
            case 0: result = x + y; break;
            case 1: result = x - y; break;
            case 2: result = x * y; break;
            case 3: result = x / y; break;
            case 4: result = sqrt(abs(x)); break;
            default: result = x / N(3) * N(3) - x + y; break;
            }
          } catch(CGAL::Uncertain_conversion_exception&) {
            return false;
          }
          return true;
        };
        const bool mpfr_threw = !apply(a.m, b.m, r.m);
        const bool dd_threw = !apply(a.d, b.d, r.d);
        if(mpfr_threw || dd_threw || mpfr_inf_p(r.m.upper()) || mpfr_inf_p(r.m.lower()))
          continue;
        ++checked;
        if(!encloses(r.d, r.m)) {
          ++pma_test::failures();
          std::printf("FAIL: a double-double interval misses the value (scale 2^%d, operation %d)\n", scale, op);
          mpfr_printf("  MPFR [%.30Re, %.30Re]\n  dd   %.17g + %.17g +- %.17g\n", r.m.lower(), r.m.upper(),
                      r.d.value().hi(), r.d.value().lo(), r.d.radius());
        }
        const double mid = std::fabs(r.d.value().hi());
        if(mid > 0 && r.d.radius() < mid * std::ldexp(1.0, -90))
          ++narrow;
        if(r.d.rounds_to_one_double()) {
          ++rounded;
          CHECK(mpfr_get_d(r.m.lower(), MPFR_RNDN) == r.d.to_double() &&
                  mpfr_get_d(r.m.upper(), MPFR_RNDN) == r.d.to_double(),
                "double-double interval: rounds to the value's double");
        }
        for(const Both& o : v) {
          CGAL::Uncertain<CGAL::Comparison_result> cd;
          try {
            cd = compare(r.d, o.d);
          } catch(CGAL::Uncertain_conversion_exception&) {   // the difference is out of range
            continue;
          }
          if(!CGAL::is_certain(cd))
            continue;
          ++comparisons;
          const CGAL::Uncertain<CGAL::Comparison_result> cm = compare(r.m, o.m);
          // (1024-bit MPFR intervals decide whatever double-double ones can)
          CHECK(CGAL::is_certain(cm) && CGAL::get_certain(cm) == CGAL::get_certain(cd),
                "double-double interval: a certain comparison is the exact one");
        }
        v.push_back(r);
      }
    }
  }
  mpfr_clear(c);
  mpfr_clear(lo);
  mpfr_clear(hi);
  std::printf("%d double-double interval results, %d narrower than 2^-90, %d rounded, %d comparisons\n", checked,
              narrow, rounded, comparisons);
  CHECK(checked > 20000 && narrow > checked / 4 && rounded > checked / 4, "double-double intervals: enough cases");
  // the typical widths
  const Dd third = Dd(1) / Dd(3), root2 = sqrt(Dd(2));
  CHECK(third.radius() < std::ldexp(1.0, -95) && root2.radius() < std::ldexp(1.0, -94),
        "double-double interval: 1/3 and sqrt 2 to about 95 bits");
  CHECK(third.rounds_to_one_double() && third.to_double() == 1.0 / 3, "double-double interval: 1/3 rounds");
  // exact ties are never decided: a midpoint of two doubles, a zero
  const Dd midpoint = (Dd(1) + Dd(std::ldexp(1.0, -53))) * Dd(3) / Dd(3);
  CHECK(!midpoint.rounds_to_one_double(), "double-double interval: a midpoint is left to exact arithmetic");
  CHECK(!CGAL::is_certain(compare(third * Dd(3), Dd(1))), "double-double interval: 3 (1/3) = 1 is undecided");
}

int main()
{
  interval_sqrt_tests();
  double_double_tests();
  double_double_interval_tests();
  mpfr_interval_tests();
  small_rational_tests();
  nested_root_tests<Nested_root_number, Nested_root_context>();
  nested_root_tests<Small_nested_root_number, Small_nested_root_context>();
  small_nested_root_overflow_tests();
  // squares of rationals stay rational
  CHECK(root(49).is_rational() && root(49) == One_root_rational(7), "sqrt(49) = 7");
  CHECK(sqrt(One_root_rational(Gmpq(9, 4))) == One_root_rational(Gmpq(3, 2)), "sqrt(9/4) = 3/2");
  // (1 + sqrt 2)^2 = 3 + 2 sqrt 2, and sqrt 8 sqrt 2 = 4 (commensurable roots)
  const One_root_rational s2 = root(2);
  CHECK((One_root_rational(1) + s2) * (One_root_rational(1) + s2) == One_root_rational(3) + One_root_rational(2) * s2,
        "(1 + sqrt 2)^2 = 3 + 2 sqrt 2");
  CHECK(root(8) * s2 == One_root_rational(4), "sqrt 8 * sqrt 2 = 4");
  CHECK(One_root_rational(1) / (s2 - One_root_rational(1)) == s2 + One_root_rational(1), "1 / (sqrt 2 - 1) = sqrt 2 + 1");
  // different roots: comparisons work, arithmetic is handed on
  CHECK(root(2) < root(3) && root(3) > root(2) && root(2) != root(3), "sqrt 2 < sqrt 3");
  bool thrown = false;
  try {
    (void)(root(2) + root(3));
  } catch(Not_one_root&) {
    thrown = true;
  }
  CHECK(thrown, "sqrt 2 + sqrt 3 throws Not_one_root");
  thrown = false;
  try {
    (void)sqrt(One_root_rational(1) + s2);
  } catch(Not_one_root&) {
    thrown = true;
  }
  CHECK(thrown, "sqrt(1 + sqrt 2) throws Not_one_root");

  // alpha + sqrt(rho): sqrt(3 + 2 sqrt 2) = 1 + sqrt 2; sqrt 2 + sqrt 3 = sqrt(5 + 2 sqrt 6)
  One_root_sqrt x{One_root_rational(0), One_root_rational(3) + One_root_rational(2) * s2};
  One_root_sqrt y{One_root_rational(1) + s2, One_root_rational(0)};
  CHECK(sign_of_difference(x, y) == CGAL::ZERO, "sqrt(3 + 2 sqrt 2) = 1 + sqrt 2");
  One_root_sqrt u{s2, One_root_rational(3)};
  One_root_sqrt v{One_root_rational(0), One_root_rational(5) + One_root_rational(2) * root(6)};
  CHECK(sign_of_difference(u, v) == CGAL::ZERO && sign_of_difference(v, u) == CGAL::ZERO,
        "sqrt 2 + sqrt 3 = sqrt(5 + 2 sqrt 6)");
  One_root_sqrt w{s2, One_root_rational(Gmpq(300001, 100000))};
  CHECK(sign_of_difference(w, v) == CGAL::POSITIVE && sign_of_difference(v, w) == CGAL::NEGATIVE,
        "sqrt 2 + sqrt 3.00001 > sqrt(5 + 2 sqrt 6)");

  // random a1 + b1 sqrt d1 against a2 + b2 sqrt d2 (same or different roots)
  std::mt19937 rng(7);
  std::uniform_int_distribution<long> small(-20, 20), radicand(1, 12);
  int compared = 0;
  for(int i = 0; i < 20000; ++i) {
    const long a1 = small(rng), b1 = small(rng), d1 = radicand(rng), a2 = small(rng), b2 = small(rng);
    const long d2 = (i % 2) ? d1 : radicand(rng);
    const One_root_rational p = One_root_rational(int(a1)) + One_root_rational(int(b1)) * root(int(d1));
    const One_root_rational q = One_root_rational(int(a2)) + One_root_rational(int(b2)) * root(int(d2));
    const double m = sign_mpfr(a1, b1, d1, a2, b2, d2);
    const CGAL::Sign expected = std::abs(m) < 1e-200 ? CGAL::ZERO : (m > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE);
    const CGAL::Sign got = sign_of_difference(p, q);
    if(got != expected) {
      ++pma_test::failures();
      std::printf("FAIL: sign(%ld + %ld sqrt %ld - (%ld + %ld sqrt %ld)) = %d, expected %d\n", a1, b1, d1, a2, b2, d2,
                  int(got), int(expected));
    }
    ++compared;
  }
  std::printf("%d random comparisons\n", compared);
  return pma_test::report("test_number_types");
}
