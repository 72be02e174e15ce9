// carom internal: the world's event queue. One slot per ball holding that ball's earliest
// predicted event, kept in an indexed binary min-heap so that a slot can be replaced in
// O(log n) when its ball is re-predicted (rather than queueing every predicted pair).
#pragma once

#include <cstdint>
#include <vector>

#include "world_event.hpp"

namespace carom::detail {

class EventQueue {
 public:
  // Slots for balls 0 .. count-1, all holding "nothing will happen".
  void reset(std::uint32_t count);
  // Adds a slot for ball `owner` (== current count) holding "nothing will happen".
  void add_slot();
  void set(std::uint32_t owner, const Event& event);
  [[nodiscard]] const Event& slot(std::uint32_t owner) const { return events_[owner]; }
  [[nodiscard]] const Event& top() const { return events_[heap_.front().owner]; }
  [[nodiscard]] bool empty() const { return heap_.empty(); }

 private:
  void sift_up(std::uint32_t position);
  void sift_down(std::uint32_t position);
  void swap_positions(std::uint32_t a, std::uint32_t b);
  // The heap keeps each event's time beside its owner, so that sifting compares times without
  // reaching into events_; only equal times need the full order.
  struct Entry {
    double time;
    std::uint32_t owner;
  };
  [[nodiscard]] bool before(std::uint32_t position_a, std::uint32_t position_b) const {
    const Entry& a = heap_[position_a];
    const Entry& b = heap_[position_b];
    if (a.time != b.time) return a.time < b.time;
    return earlier(events_[a.owner], events_[b.owner]);
  }

  std::vector<Event> events_;            // by ball
  std::vector<Entry> heap_;              // in heap order
  std::vector<std::uint32_t> position_;  // by ball: where it is in heap_
};

}  // namespace carom::detail
