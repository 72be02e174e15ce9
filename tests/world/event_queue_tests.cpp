// The world's event queue (src/event_queue.hpp) against a scan of every slot: the event it
// gives as the earliest is the earliest by the total order of world_event.hpp, whether or not
// it defers filing events in later buckets (the large worlds' mode), through the years it opens
// (finding the pending events by a scan of the slots, or by walking their list where few slots
// hold one), the events replaced while their filing is deferred, and re-orderings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "world/event_queue.hpp"

namespace carom::detail {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

Event earliest_by_scan(const EventQueue& queue, std::uint32_t slots, const std::uint32_t* handles) {
  Event best;
  for (std::uint32_t k = 0; k < slots; ++k) {
    const Event candidate = queue.slot(k);
    if (candidate.time == kNever) continue;
    if (best.time == kNever || earlier(candidate, best, handles)) best = candidate;
  }
  return best;
}

// An event for `owner` some time after `now`: spread like a gas's (mostly within a few mean
// times, sometimes far), with ties (times on a coarse grid) and each kind.
Event random_event(std::mt19937_64& random, std::uint32_t owner, std::uint32_t slots, double now) {
  std::exponential_distribution<double> ahead(1.0);
  std::uniform_int_distribution<std::uint32_t> pick(0, slots - 1);
  Event event;
  event.owner = owner;
  const std::uint32_t shape = pick(random) % 8;
  double delay = ahead(random);
  if (shape == 0) delay = std::floor(delay * 4.0) / 4.0;  // ties, and events at `now`
  if (shape == 1) delay *= 50.0;                          // beyond the year
  event.time = now + delay;
  event.kind = static_cast<EventKind>(pick(random) % 3);
  event.partner = event.kind == EventKind::cell_crossing ? pick(random) % 4 : pick(random);
  event.partner_version = static_cast<std::uint32_t>(random());
  return event;
}

// Processes `steps` events the way the engine does: take the earliest, re-predict its owner
// and a few others (some twice, some to "nothing"); checks each earliest against the scan. Only
// every `every`-th slot ever holds an event (the rest: balls at rest).
void check_against_scan(bool deferring, std::uint64_t seed, std::uint32_t every = 1) {
  constexpr std::uint32_t kSlots = 2000;
  constexpr int kSteps = 20000;
  std::mt19937_64 random(seed);
  std::vector<std::uint32_t> handles(kSlots);
  std::iota(handles.begin(), handles.end(), 0u);
  const std::vector<std::uint32_t> identity = handles;
  std::shuffle(handles.begin(), handles.end(), random);  // ties are broken by handle
  EventQueue queue;
  queue.reset(kSlots);
  queue.use_handles(handles.data());
  for (std::uint32_t k = 0; k < kSlots; k += every) {
    queue.set(k, random_event(random, k, kSlots, 0.0));
  }
  queue.defer_filing(deferring);
  std::uniform_int_distribution<std::uint32_t> pick(0, kSlots - 1);
  const auto pick_active = [&] { return pick(random) / every * every; };
  for (int step = 0; step < kSteps; ++step) {
    const Event top = queue.top();
    const Event expected = earliest_by_scan(queue, kSlots, handles.data());
    ASSERT_EQ(top.time, expected.time) << "step " << step;
    ASSERT_EQ(top.owner, expected.owner) << "step " << step;
    ASSERT_EQ(top.kind, expected.kind) << "step " << step;
    ASSERT_EQ(top.partner, expected.partner) << "step " << step;
    ASSERT_EQ(top.partner_version, expected.partner_version) << "step " << step;
    if (top.time == kNever) break;
    // The engine re-orders its balls from time to time, with filings deferred: the queue is
    // rebuilt around the same events (a permutation that keeps each ball in place suffices).
    if (step % 5000 == 4999) queue.reorder(identity);
    const double now = top.time;
    queue.set(top.owner, random_event(random, top.owner, kSlots, now));
    const std::uint32_t others = pick(random) % 4;
    for (std::uint32_t k = 0; k < others; ++k) {
      const std::uint32_t owner = pick_active();
      const bool removed = pick(random) % 50 == 0;  // a ball removed: "nothing will happen"
      queue.set(owner, removed ? Event{} : random_event(random, owner, kSlots, now));
      // Replaced again before the next top(): its deferred filing is taken back.
      if (pick(random) % 8 == 0) queue.set(owner, random_event(random, owner, kSlots, now));
    }
  }
}

TEST(EventQueue, EarliestAgreesWithAScanOfEverySlot) { check_against_scan(false, 1); }

TEST(EventQueue, EarliestAgreesWithAScanWhileDeferringFiling) {
  check_against_scan(true, 1);
  check_against_scan(true, 2);
}

// 100 of 2000 slots hold events, fewer than the share at which a new year scans the slots: it
// walks the overflow list instead. 300, about the share, for years of either kind.
TEST(EventQueue, EarliestAgreesWithAScanWhenFewSlotsHoldEvents) {
  check_against_scan(false, 3, 20);
  check_against_scan(true, 4, 20);
  check_against_scan(true, 5, 7);
}

}  // namespace
}  // namespace carom::detail
