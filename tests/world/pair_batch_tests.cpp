// The world's batched pair solver (src/pair_batch.hpp) against the scalar time of impact it
// replaces in prediction (circle_crossing.hpp's entry_crossing): the same answer, bit for bit, on
// random pairs of every scale, including the magnitudes that take the rescaled path, zeros, and
// pairs already touching.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "core/circle_crossing.hpp"
#include "world/pair_batch.hpp"

namespace carom {
namespace {

constexpr double kHorizon = std::numeric_limits<double>::max();  // the world's kFarFuture

// A coordinate: mostly ordinary, sometimes zero, tiny or huge (beyond the exact range's window,
// where the batch must hand the pair to the rescaled path).
double coordinate(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  switch (random() % 8) {
    case 0:
      return 0.0;
    case 1:
      return unit(random) * 1e-200;
    case 2:
      return unit(random) * 1e200;
    case 3:
      return unit(random) * 1e-6;
    default:
      return unit(random) * 10.0;
  }
}

double reach(std::mt19937_64& random) {
  std::uniform_real_distribution<double> size(0.1, 10.0);
  switch (random() % 10) {
    case 0:
      return 1e-160;
    case 1:
      return 1e160;
    default:
      return size(random);
  }
}

// solve (four pairs a vector operation where the CPU has AVX2) and solve_one_by_one, on
// batches of every size from 1 to full (a size not a multiple of four pads the last vector).
void check_pair_batch_solver(void (detail::PairBatch::*solver)(double)) {
  std::mt19937_64 random(20261130);
  detail::PairBatch batch;
  int hits = 0;
  int rescaled = 0;
  int touching = 0;
  for (int round = 0; round < 4000; ++round) {
    batch.count = 0;
    const std::size_t size = 1 + random() % detail::PairBatch::kCapacity;
    while (batch.count < size) {
      Vec2 s{coordinate(random), coordinate(random)};
      const Vec2 u{coordinate(random), coordinate(random)};
      const double r = reach(random);
      if (random() % 16 == 0) s = Vec2{r * 0.5, 0.0};  // inside: t = 0 when approaching
      batch.push(s, u, r, static_cast<std::uint32_t>(batch.count));
    }
    (batch.*solver)(kHorizon);
    for (std::size_t k = 0; k < batch.count; ++k) {
      const Vec2 s{batch.sx[k], batch.sy[k]};
      const Vec2 u{batch.ux[k], batch.uy[k]};
      const detail::Crossing expected = detail::entry_crossing(s, u, batch.reach[k], kHorizon);
      // What prediction makes of the batch's answer (prediction_steps.hpp).
      detail::Crossing got;
      if (batch.outcome(k) == detail::PairBatch::kHit) {
        got = {true, batch.t[k]};
      } else if (batch.outcome(k) == detail::PairBatch::kRescale) {
        got = detail::entry_crossing_rescaled({s, u, batch.reach[k]}, kHorizon);
        ++rescaled;
      }
      EXPECT_EQ(batch.outcome(k) == detail::PairBatch::kRescale,
                !detail::in_exact_range(s, u, batch.reach[k]))
          << "pair " << k << " of round " << round;
      ASSERT_EQ(got.found, expected.found) << "round " << round << ", pair " << k;
      if (expected.found) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(got.t), std::bit_cast<std::uint64_t>(expected.t))
            << "round " << round << ", pair " << k << ": " << got.t << " vs " << expected.t;
        ++hits;
        if (expected.t == 0.0) ++touching;
      }
    }
  }
  // The sample reached every branch: hits, pairs already touching, and the rescaled path.
  EXPECT_GT(hits, 500);
  EXPECT_GT(touching, 50);
  EXPECT_GT(rescaled, 500);
}

TEST(PairBatch, SolvesEveryPairAsTheScalarEntryCrossing) {
  check_pair_batch_solver(&detail::PairBatch::solve);
}

TEST(PairBatch, SolvesEveryPairOneByOneAsTheScalarEntryCrossing) {
  check_pair_batch_solver(&detail::PairBatch::solve_one_by_one);
}

// A round of the slot solvers' checks: kinds of random sizes, and balls of every scale stored at
// earlier local times (their own or the world's time).
constexpr std::uint32_t kSlots = 64;
constexpr std::uint32_t kKinds = 5;
constexpr double kNow = 5.0;
void fill_round(std::mt19937_64& random, std::vector<detail::BallSlot>& slots,
                std::vector<detail::Species>& kinds, bool one_kind) {
  std::uniform_real_distribution<double> earlier(0.0, 3.0);
  for (detail::Species& kind : kinds) kind.radius = reach(random) * 0.5;
  for (detail::BallSlot& slot : slots) {
    slot.position = {coordinate(random), coordinate(random)};
    slot.velocity = {coordinate(random), coordinate(random)};
    slot.local_time = kNow - (random() % 4 == 0 ? 0.0 : earlier(random));
    slot.species = one_kind ? 0 : static_cast<std::uint32_t>(random() % kKinds);
  }
}

// The query of ball `self` as the world's prediction makes it (the ball at the world's time).
detail::SlotQuery query_of(std::vector<detail::BallSlot>& slots,
                           const std::vector<detail::Species>& kinds, std::uint32_t self,
                           bool one_kind) {
  slots[self].local_time = kNow;
  detail::SlotQuery query;
  query.self = self;
  query.p = slots[self].position;
  query.v = slots[self].velocity;
  query.now = kNow;
  query.radius = kinds[slots[self].species].radius;
  query.species = one_kind ? nullptr : kinds.data();
  query.horizon = kHorizon;
  return query;
}

// The answers of a named batch's first `size` pairs against a pushed batch's, bit for bit; counts
// the hits (by the lane's ball: bit k of second_lanes) and the pairs left to the rescaled path.
void expect_pushed_answers(const detail::PairBatch& named, const detail::PairBatch& pushed,
                           std::size_t size, int round, std::uint32_t second_lanes, int hits[2],
                           int& rescaled) {
  for (std::size_t k = 0; k < size; ++k) {
    const auto expected = pushed.outcome(k);
    ASSERT_EQ(named.outcome(k), expected) << "round " << round << ", pair " << k;
    if (expected == detail::PairBatch::kHit) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(named.t[k]), std::bit_cast<std::uint64_t>(pushed.t[k]))
          << "round " << round << ", pair " << k;
      ++hits[(second_lanes >> k) & 1U];
    }
    if (expected == detail::PairBatch::kRescale) ++rescaled;
  }
}

// solve_slots (the neighbours read from their slots inside the kernel) against what the world's
// general path does with the same slots: slot_pair's values pushed with the sum of the two radii,
// then solve. Every outcome and every time the same, bit for bit, on batches of every size (a
// neighbour may be named twice), neighbours stored at earlier local times, magnitudes of every
// scale, in a world of one kind and in one of several (each neighbour's radius its species').
void check_slot_solver(void (detail::PairBatch::*solver)(const detail::BallSlot*,
                                                         const detail::SlotQuery&),
                       bool one_kind) {
  std::mt19937_64 random(one_kind ? 20261201 : 20261202);
  std::vector<detail::BallSlot> slots(kSlots);
  std::vector<detail::Species> kinds(kKinds);
  detail::PairBatch named;
  detail::PairBatch pushed;
  int hits[2] = {0, 0};
  int rescaled = 0;
  for (int round = 0; round < 4000; ++round) {
    fill_round(random, slots, kinds, one_kind);
    const detail::SlotQuery query =
        query_of(slots, kinds, static_cast<std::uint32_t>(random() % kSlots), one_kind);
    if (random() % 16 == 0) {  // touching already
      slots[(query.self + 1) % kSlots].position = query.p + Vec2{query.radius * 0.5, 0.0};
    }
    named.count = 0;
    pushed.count = 0;
    const std::size_t size = 1 + random() % detail::PairBatch::kCapacity;
    while (named.count < size) {
      const auto other = static_cast<std::uint32_t>(random() % kSlots);
      if (other == query.self) continue;
      named.other[named.count++] = other;
      const detail::SlotPair pair = detail::slot_pair(slots[other], query.p, query.v, kNow);
      const double other_radius = one_kind ? query.radius : kinds[slots[other].species].radius;
      pushed.push(pair.s, pair.u, query.radius + other_radius, other);
    }
    (named.*solver)(slots.data(), query);
    pushed.solve(kHorizon);
    expect_pushed_answers(named, pushed, size, round, 0, hits, rescaled);
    for (std::size_t k = 0; k < size; ++k) {
      EXPECT_EQ(detail::slot_reach(slots[named.other[k]], query), pushed.reach[k]);
    }
  }
  EXPECT_GT(hits[0], 500);
  EXPECT_GT(rescaled, 500);
}

TEST(PairBatch, SolvesNamedSlotsAsThePushedPairs) {
  check_slot_solver(&detail::PairBatch::solve_slots, true);
}

TEST(PairBatch, SolvesNamedSlotsOfSeveralKindsAsThePushedPairs) {
  check_slot_solver(&detail::PairBatch::solve_slots, false);
}

TEST(PairBatch, SolvesNamedSlotsOneByOneAsThePushedPairs) {
  check_slot_solver(&detail::PairBatch::solve_slots_one_by_one, true);
  check_slot_solver(&detail::PairBatch::solve_slots_one_by_one, false);
}

// solve_slots_of_two (a contact's two balls in one batch) against push + solve with each lane's
// own ball: lanes of either ball in any order (a random mask), so that groups of four mix the
// two, on batches of every size, with one kind and with several, bit for bit.
void check_two_ball_slot_solver(void (detail::PairBatch::*solver)(const detail::BallSlot*,
                                                                  const detail::SlotQuery&,
                                                                  const detail::SlotQuery&,
                                                                  std::uint32_t),
                                bool one_kind) {
  std::mt19937_64 random(one_kind ? 20261203 : 20261204);
  std::vector<detail::BallSlot> slots(kSlots);
  std::vector<detail::Species> kinds(kKinds);
  detail::PairBatch named;
  detail::PairBatch pushed;
  int hits[2] = {0, 0};
  int rescaled = 0;
  for (int round = 0; round < 4000; ++round) {
    fill_round(random, slots, kinds, one_kind);
    const auto first = static_cast<std::uint32_t>(random() % kSlots);
    const auto second = static_cast<std::uint32_t>((first + 1 + random() % (kSlots - 1)) % kSlots);
    const detail::SlotQuery queries[2] = {query_of(slots, kinds, first, one_kind),
                                          query_of(slots, kinds, second, one_kind)};
    named.count = 0;
    pushed.count = 0;
    std::uint32_t second_lanes = 0;
    const std::size_t size = 1 + random() % detail::PairBatch::kCapacity;
    while (named.count < size) {
      const auto owner = static_cast<std::size_t>(random() % 2);
      const detail::SlotQuery& query = queries[owner];
      const auto other = static_cast<std::uint32_t>(random() % kSlots);
      if (other == query.self) continue;
      second_lanes |= static_cast<std::uint32_t>(owner) << named.count;
      named.other[named.count++] = other;
      const detail::SlotPair pair = detail::slot_pair(slots[other], query.p, query.v, kNow);
      pushed.push(pair.s, pair.u, detail::slot_reach(slots[other], query), other);
    }
    (named.*solver)(slots.data(), queries[0], queries[1], second_lanes);
    pushed.solve(kHorizon);
    expect_pushed_answers(named, pushed, size, round, second_lanes, hits, rescaled);
  }
  // Both balls' lanes hit often, and the rescaled path was reached.
  EXPECT_GT(hits[0], 250);
  EXPECT_GT(hits[1], 250);
  EXPECT_GT(rescaled, 500);
}

TEST(PairBatch, SolvesTwoBallsNamedSlotsAsEachBallsPushedPairs) {
  check_two_ball_slot_solver(&detail::PairBatch::solve_slots_of_two, true);
}

TEST(PairBatch, SolvesTwoBallsNamedSlotsOfSeveralKindsAsEachBallsPushedPairs) {
  check_two_ball_slot_solver(&detail::PairBatch::solve_slots_of_two, false);
}

TEST(PairBatch, SolvesTwoBallsNamedSlotsOneByOneAsEachBallsPushedPairs) {
  check_two_ball_slot_solver(&detail::PairBatch::solve_slots_of_two_one_by_one, true);
  check_two_ball_slot_solver(&detail::PairBatch::solve_slots_of_two_one_by_one, false);
}

}  // namespace
}  // namespace carom
