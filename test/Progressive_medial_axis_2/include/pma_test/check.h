// The check of every test program of Progressive_medial_axis_2: never
// compiled out, prints where it failed and what it was told, counts the
// failures; pma_test::report() prints the count and gives the exit status.
//
//   CHECK(condition)
//   CHECK(condition, message)    message: a stream expression, a << " " << b
//   REQUIRE(condition[, message]) the same, then returns 1 from the function

#ifndef PMA_TEST_CHECK_H
#define PMA_TEST_CHECK_H

#include <iostream>

namespace pma_test {

inline int& failures()
{
  static int f = 0;
  return f;
}

inline long& checks()
{
  static long c = 0;
  return c;
}

/// Prints `name: C checks, F failures` and returns the exit status.
inline int report(const char* name)
{
  std::cout << name << ": " << checks() << " checks, " << failures() << " failures\n";
  return failures() == 0 ? 0 : 1;
}

} // namespace pma_test

#define PMA_CHECK_2(cond, msg)                                                                     \
  do {                                                                                             \
    ++pma_test::checks();                                                                          \
    if(!(cond)) {                                                                                  \
      ++pma_test::failures();                                                                      \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond "\n  " << msg << "\n"; \
    }                                                                                              \
  } while(0)

#define PMA_REQUIRE_2(cond, msg)                                                                   \
  do {                                                                                             \
    ++pma_test::checks();                                                                          \
    if(!(cond)) {                                                                                  \
      ++pma_test::failures();                                                                      \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond "\n  " << msg << "\n"; \
      return 1;                                                                                    \
    }                                                                                              \
  } while(0)

#define PMA_CHECK_1(cond) PMA_CHECK_2(cond, "")
#define PMA_REQUIRE_1(cond) PMA_REQUIRE_2(cond, "")
#define PMA_CHECK_PICK(_1, _2, name, ...) name
#define CHECK(...) PMA_CHECK_PICK(__VA_ARGS__, PMA_CHECK_2, PMA_CHECK_1, unused)(__VA_ARGS__)
#define REQUIRE(...) PMA_CHECK_PICK(__VA_ARGS__, PMA_REQUIRE_2, PMA_REQUIRE_1, unused)(__VA_ARGS__)

#endif // PMA_TEST_CHECK_H
