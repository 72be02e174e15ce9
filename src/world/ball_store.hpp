// carom internal: the world's balls — their slots, which the engine reads and re-orders, and the
// handles users hold, which never move. One place owns the bookkeeping between the two: which
// handle names which slot, each slot's generation (a removed ball's handle goes stale), the
// handles free for reuse, and how many balls live (docs/engine.md, "Memory").
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "ball_slot.hpp"
#include "carom/world.hpp"
#include "huge_page_allocator.hpp"
#include "permute.hpp"

namespace carom::detail {

// The rest of a ball, read only by the API (kept apart so that prediction's scans of
// neighbours touch only the slots).
struct BallInfo {
  std::uint64_t user_data = 0;
  std::uint32_t generation = 1;  // the live (or next) generation; never 0
  std::uint32_t filter = 0;      // its CollisionFilter's number in the world's FilterTable
};
static_assert(sizeof(BallInfo) == 16);

struct BallStore {
  // By slot: the engine's data. Slots are re-ordered by grid cell from time to time (renumber),
  // so that neighbours sit near each other in memory; a BallId names a handle index, which never
  // moves, and the two maps below translate.
  BigVector<BallSlot> balls;
  BigVector<BallInfo> infos;
  BigVector<std::uint32_t> handle_of;       // by slot
  BigVector<std::uint32_t> slot_of_handle;  // by handle index
  std::vector<std::uint32_t> free_handles;  // reused last-freed first
  std::size_t live_count = 0;

  // The slot of the live ball `id` names, or nothing (a null, stale or unknown handle).
  [[nodiscard]] std::optional<std::uint32_t> find(BallId id) const noexcept {
    if (id.is_null() || id.index >= slot_of_handle.size()) return std::nullopt;
    const std::uint32_t slot = slot_of_handle[id.index];
    if (!balls[slot].alive() || infos[slot].generation != id.generation) return std::nullopt;
    return slot;
  }
  [[nodiscard]] BallId id_of(std::uint32_t slot) const {
    return {handle_of[slot], infos[slot].generation};
  }
  // Whether slot a's ball comes before slot b's in handle order (the order of ties and of
  // anything reported per ball).
  [[nodiscard]] bool handle_before(std::uint32_t a, std::uint32_t b) const {
    return handle_of[a] < handle_of[b];
  }

  // A slot for a new ball: the last freed handle's (its generation moved on when it was freed),
  // or a new slot whose handle index is its own. `grew` says a slot was added, so that per-slot
  // arrays kept elsewhere grow with it.
  [[nodiscard]] std::uint32_t acquire(bool& grew) {
    ++live_count;
    if (!free_handles.empty()) {
      const std::uint32_t slot = slot_of_handle[free_handles.back()];
      free_handles.pop_back();
      grew = false;
      return slot;
    }
    const auto slot = static_cast<std::uint32_t>(balls.size());
    balls.emplace_back();
    infos.emplace_back();
    handle_of.push_back(slot);
    slot_of_handle.push_back(slot);
    grew = true;
    return slot;
  }
  // The slot's ball is gone: its handle goes stale (the generation moves on, skipping 0, the
  // null handle's) and is free for reuse.
  void release(std::uint32_t slot) {
    std::uint32_t& generation = infos[slot].generation;
    generation = generation == std::numeric_limits<std::uint32_t>::max() ? 1 : generation + 1;
    free_handles.push_back(handle_of[slot]);
    --live_count;
  }

  void reserve(std::size_t count) {
    balls.reserve(count);
    infos.reserve(count);
    handle_of.reserve(count);
    slot_of_handle.reserve(count);
  }

  // Moves every slot's ball to destination[slot] (a permutation), with its info and handle, and
  // the slots of `others` (further per-slot arrays) alike; handles keep naming their balls.
  template <class... Vectors>
  void renumber(std::span<const std::uint32_t> destination, Vectors&... others) {
    move_all_to(destination, balls, infos, handle_of, others...);
    for (std::uint32_t k = 0; k < handle_of.size(); ++k) slot_of_handle[handle_of[k]] = k;
  }

  // Calls visit(slot) for every live ball, in handle order.
  template <class Visit>
  void for_each_live(Visit visit) const {
    for (const std::uint32_t slot : slot_of_handle) {
      if (balls[slot].alive()) visit(slot);
    }
  }
};

}  // namespace carom::detail
