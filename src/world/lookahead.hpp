// carom internal: what the engine's lookahead (world_lookahead.cpp) carries from one call to
// the next (a call each time the queue's current bucket advances). Each call asks the cache for
// one more level of the data the events ahead will read: what it learns from lines that the
// call before asked for is kept here, so that no call waits for memory. Design: docs/engine.md,
// "Memory".
#pragma once

#include <array>
#include <cstdint>

namespace carom::detail {

// A short list of fixed capacity whose pushes past it overwrite the last item: the lookahead
// only prefetches, so dropping a few under a burst costs a few misses, never a result.
template <typename T, std::uint32_t N>
struct DropList {
  static constexpr std::uint32_t kCapacity = N;
  std::array<T, kCapacity> items{};
  std::uint32_t count = 0;

  // Pushes `value` when `keep` (written either way, so that callers need not branch on it).
  void push_if(T value, bool keep) {
    items[count] = value;
    count += static_cast<std::uint32_t>(keep & (count + 1 < kCapacity));
  }
  // A burst of pushes keeps the count in a local instead: after each item of push_if GCC
  // stores `count` and loads it again (an item of the same type may alias it), some 12
  // instructions an item chained through memory. The caller checks the room for the whole
  // burst first (at + n <= kCapacity), takes `at` from count, and stores it back after.
  [[nodiscard]] std::uint32_t push_if_at(std::uint32_t at, T value, bool keep) {
    items[at] = value;
    return at + static_cast<std::uint32_t>(keep);
  }
  void clear() { count = 0; }
  [[nodiscard]] const T* begin() const { return items.data(); }
  [[nodiscard]] const T* end() const { return items.data() + count; }
};

struct Lookahead {
  // The queue's current bucket at the last call (-1: none yet, or the queue was rebuilt since).
  std::int64_t passed_bucket = -1;
  // By the parity of the call that found them, for the next call to use: the cells whose 3×3
  // blocks' list heads were asked for ...
  DropList<std::int32_t, 32> cells[2];
  // ... the balls of pair contacts ahead whose event-list links were asked for ...
  DropList<std::uint32_t, 32> partners[2];
  // ... and the first balls of the blocks before, whose records and list links were asked for.
  DropList<std::uint32_t, 9 * 32> first_balls[2];
  int parity = 0;
  // By bucket number modulo kCursors: the ball in that bucket's list whose stage 0 the last walk
  // made (EventQueue::kNone: the list's end). Read only after a call has set them: passed_bucket
  // at -1 makes the next call start every bucket in reach afresh.
  static constexpr std::int64_t kCursors = 8;
  std::array<std::uint32_t, kCursors> cursors{};
  // Whether calls also ask for the cells' second balls and the pair partners' blocks: worth
  // their instructions only in worlds far larger than the last-level cache.
  bool deep = false;
};

}  // namespace carom::detail
