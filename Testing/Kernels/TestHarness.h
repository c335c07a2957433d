// Minimal assertion helpers for the kernel tests: each check prints where it failed and the test
// executable exits non-zero when any check failed.
#ifndef cgmesh_TestHarness_h
#define cgmesh_TestHarness_h

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace cgmesh_test
{
inline int& failureCount()
{
  static int failures = 0;
  return failures;
}

inline int finish(const char* suite)
{
  if (failureCount() == 0)
  {
    std::cout << suite << ": all checks passed\n";
    return EXIT_SUCCESS;
  }
  std::cout << suite << ": " << failureCount() << " checks failed\n";
  return EXIT_FAILURE;
}
} // namespace cgmesh_test

#define CHECK(condition)                                                                           \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      ++cgmesh_test::failureCount();                                                               \
      std::cerr << __FILE__ << ':' << __LINE__ << ": check failed: " #condition "\n";              \
    }                                                                                              \
  } while (false)

#define CHECK_EQUAL(actual, expected)                                                              \
  do                                                                                               \
  {                                                                                                \
    const auto actualValue = (actual);                                                             \
    const auto expectedValue = (expected);                                                         \
    if (!(actualValue == expectedValue))                                                           \
    {                                                                                              \
      ++cgmesh_test::failureCount();                                                               \
      std::cerr << __FILE__ << ':' << __LINE__ << ": " #actual " = " << actualValue                \
                << ", expected " << expectedValue << "\n";                                         \
    }                                                                                              \
  } while (false)

#define CHECK_CLOSE(actual, expected, relativeTolerance)                                           \
  do                                                                                               \
  {                                                                                                \
    const double actualValue = (actual);                                                           \
    const double expectedValue = (expected);                                                       \
    if (!(std::abs(actualValue - expectedValue) <=                                                 \
          (relativeTolerance)*std::max(1.0, std::abs(expectedValue))))                             \
    {                                                                                              \
      ++cgmesh_test::failureCount();                                                               \
      std::cerr << __FILE__ << ':' << __LINE__ << ": " #actual " = " << actualValue                \
                << ", expected " << expectedValue << "\n";                                         \
    }                                                                                              \
  } while (false)

#endif
