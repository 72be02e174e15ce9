// Division by a fixed number as a multiplication and a shift (src/fixed_divisor.hpp), against
// the division instruction: at the ends of the range, around every multiple of the divisor
// that can go wrong first, and at random.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "world/fixed_divisor.hpp"

namespace carom::detail {
namespace {

constexpr std::uint32_t kLargestNumber = 0x7FFFFFFFu;  // the range is [0, 2^31)

std::vector<std::uint32_t> divisors_to_try() {
  std::vector<std::uint32_t> divisors;
  for (std::uint32_t d = 1; d <= 1000; ++d) divisors.push_back(d);
  for (int k = 10; k < 31; ++k) {
    const std::uint32_t power = std::uint32_t{1} << k;
    for (const std::uint32_t d : {power - 1, power, power + 1, power + power / 2 + 1}) {
      divisors.push_back(d);
    }
  }
  divisors.push_back(kLargestNumber);
  divisors.push_back(kLargestNumber - 1);
  return divisors;
}

TEST(FixedDivisor, AgreesWithDivisionAtTheEndsAndAroundMultiples) {
  for (const std::uint32_t d : divisors_to_try()) {
    const FixedDivisor divisor(d);
    for (const std::uint32_t n : {0u, 1u, d - 1, d, d + 1, kLargestNumber, kLargestNumber - 1}) {
      if (n > kLargestNumber) continue;
      ASSERT_EQ(divisor.divide(n), n / d) << n << " / " << d;
    }
    // The rounding error grows with n, so the last multiples below 2^31 are where it would
    // show first: one short of a multiple must not round up to it.
    const std::uint32_t last = kLargestNumber / d * d;
    for (std::uint32_t k = 0; k < 64 && last >= k * d + 1; ++k) {
      const std::uint32_t multiple = last - k * d;
      ASSERT_EQ(divisor.divide(multiple), multiple / d) << multiple << " / " << d;
      ASSERT_EQ(divisor.divide(multiple - 1), (multiple - 1) / d) << multiple - 1 << " / " << d;
    }
  }
}

TEST(FixedDivisor, AgreesWithDivisionAtRandom) {
  std::mt19937 random(20261201);
  std::uniform_int_distribution<std::uint32_t> number(0, kLargestNumber);
  for (int trial = 0; trial < 100'000; ++trial) {
    const std::uint32_t d = std::max<std::uint32_t>(1, number(random) >> (trial % 31));
    const std::uint32_t n = number(random);
    ASSERT_EQ(FixedDivisor(d).divide(n), n / d) << n << " / " << d;
  }
}

}  // namespace
}  // namespace carom::detail
