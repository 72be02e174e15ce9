// Re-ordering the engine's per-ball arrays in place (src/permute.hpp): every array ends as a copy
// moved out of place would, for permutations of every shape (the identity, fixed points among
// cycles, one long cycle, a random one, and a nearly sorted one like a re-sort by cell's).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "world/permute.hpp"

namespace carom::detail {
namespace {

template <class T>
std::vector<T> moved_out_of_place(const std::vector<T>& values,
                                  const std::vector<std::uint32_t>& destination) {
  std::vector<T> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[destination[i]] = values[i];
  return out;
}

void expect_moved_like_a_copy(const std::vector<std::uint32_t>& destination) {
  const auto n = static_cast<std::uint32_t>(destination.size());
  std::vector<std::uint32_t> numbers(n);
  std::iota(numbers.begin(), numbers.end(), 100u);
  std::vector<double> reals(n);
  std::vector<std::string> names(n);  // not trivially copyable: moved, not copied bitwise
  for (std::uint32_t i = 0; i < n; ++i) {
    reals[i] = 0.5 * i;
    names[i] = "ball " + std::to_string(i);
  }
  const auto want_numbers = moved_out_of_place(numbers, destination);
  const auto want_reals = moved_out_of_place(reals, destination);
  const auto want_names = moved_out_of_place(names, destination);
  move_all_to(destination, numbers, reals, names);
  EXPECT_EQ(numbers, want_numbers);
  EXPECT_EQ(reals, want_reals);
  EXPECT_EQ(names, want_names);
  std::vector<double> alone(n);
  std::iota(alone.begin(), alone.end(), 0.0);
  const auto want_alone = moved_out_of_place(alone, destination);
  move_to(alone, destination);
  EXPECT_EQ(alone, want_alone);
}

TEST(Permute, TheIdentityMovesNothing) {
  std::vector<std::uint32_t> identity(50);
  std::iota(identity.begin(), identity.end(), 0u);
  expect_moved_like_a_copy(identity);
}

TEST(Permute, CyclesAmongFixedPoints) {
  // 0 -> 3 -> 5 -> 0, 1 and 4 stay, 2 <-> 6, 7 stays.
  expect_moved_like_a_copy({3, 1, 6, 5, 4, 0, 2, 7});
}

TEST(Permute, OneCycleThroughEveryPlace) {
  std::vector<std::uint32_t> rotate(257);
  for (std::uint32_t i = 0; i < rotate.size(); ++i) rotate[i] = (i + 1) % 257;
  expect_moved_like_a_copy(rotate);
}

TEST(Permute, RandomAndNearlySortedPermutations) {
  std::mt19937_64 random(7);
  for (const std::uint32_t n : {0u, 1u, 2u, 1000u}) {
    std::vector<std::uint32_t> destination(n);
    std::iota(destination.begin(), destination.end(), 0u);
    std::shuffle(destination.begin(), destination.end(), random);
    expect_moved_like_a_copy(destination);
    // A re-sort by cell: most places move by a little.
    std::iota(destination.begin(), destination.end(), 0u);
    for (std::uint32_t i = 0; i + 3 < n; i += 5) std::swap(destination[i], destination[i + 3]);
    expect_moved_like_a_copy(destination);
  }
}

}  // namespace
}  // namespace carom::detail
