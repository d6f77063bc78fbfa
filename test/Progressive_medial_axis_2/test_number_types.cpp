// Unit tests of the exact one-root numbers of the filtered traits
// (internal/One_root_rational.h): exact ties, signs against MPFR at high
// precision, and the cases that must be handed on (Not_one_root).
#include <CGAL/Progressive_medial_axis_2/internal/One_root_rational.h>

#include <cstdio>
#include <cstdlib>
#include <random>

using CGAL::Gmpq;
using CGAL::PMA2::internal::Not_one_root;
using CGAL::PMA2::internal::One_root_rational;
using CGAL::PMA2::internal::One_root_sqrt;

namespace {

int failures = 0;

void check(bool ok, const char* what)
{
  if(!ok) {
    ++failures;
    std::printf("FAIL: %s\n", what);
  }
}

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

} // namespace

int main()
{
  // squares of rationals stay rational
  check(root(49).is_rational() && root(49) == One_root_rational(7), "sqrt(49) = 7");
  check(sqrt(One_root_rational(Gmpq(9, 4))) == One_root_rational(Gmpq(3, 2)), "sqrt(9/4) = 3/2");
  // (1 + sqrt 2)^2 = 3 + 2 sqrt 2, and sqrt 8 sqrt 2 = 4 (commensurable roots)
  const One_root_rational s2 = root(2);
  check((One_root_rational(1) + s2) * (One_root_rational(1) + s2) == One_root_rational(3) + One_root_rational(2) * s2,
        "(1 + sqrt 2)^2 = 3 + 2 sqrt 2");
  check(root(8) * s2 == One_root_rational(4), "sqrt 8 * sqrt 2 = 4");
  check(One_root_rational(1) / (s2 - One_root_rational(1)) == s2 + One_root_rational(1), "1 / (sqrt 2 - 1) = sqrt 2 + 1");
  // different roots: comparisons work, arithmetic is handed on
  check(root(2) < root(3) && root(3) > root(2) && root(2) != root(3), "sqrt 2 < sqrt 3");
  bool thrown = false;
  try {
    (void)(root(2) + root(3));
  } catch(Not_one_root&) {
    thrown = true;
  }
  check(thrown, "sqrt 2 + sqrt 3 throws Not_one_root");
  thrown = false;
  try {
    (void)sqrt(One_root_rational(1) + s2);
  } catch(Not_one_root&) {
    thrown = true;
  }
  check(thrown, "sqrt(1 + sqrt 2) throws Not_one_root");

  // alpha + sqrt(rho): sqrt(3 + 2 sqrt 2) = 1 + sqrt 2; sqrt 2 + sqrt 3 = sqrt(5 + 2 sqrt 6)
  One_root_sqrt x{One_root_rational(0), One_root_rational(3) + One_root_rational(2) * s2};
  One_root_sqrt y{One_root_rational(1) + s2, One_root_rational(0)};
  check(sign_of_difference(x, y) == CGAL::ZERO, "sqrt(3 + 2 sqrt 2) = 1 + sqrt 2");
  One_root_sqrt u{s2, One_root_rational(3)};
  One_root_sqrt v{One_root_rational(0), One_root_rational(5) + One_root_rational(2) * root(6)};
  check(sign_of_difference(u, v) == CGAL::ZERO && sign_of_difference(v, u) == CGAL::ZERO,
        "sqrt 2 + sqrt 3 = sqrt(5 + 2 sqrt 6)");
  One_root_sqrt w{s2, One_root_rational(Gmpq(300001, 100000))};
  check(sign_of_difference(w, v) == CGAL::POSITIVE && sign_of_difference(v, w) == CGAL::NEGATIVE,
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
      ++failures;
      std::printf("FAIL: sign(%ld + %ld sqrt %ld - (%ld + %ld sqrt %ld)) = %d, expected %d\n", a1, b1, d1, a2, b2, d2,
                  int(got), int(expected));
    }
    ++compared;
  }
  std::printf("%d random comparisons, %d failures\n", compared, failures);
  return failures == 0 ? 0 : 1;
}
