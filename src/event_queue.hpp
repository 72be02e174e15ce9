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
  [[nodiscard]] const Event& top() const { return events_[heap_.front()]; }
  [[nodiscard]] bool empty() const { return heap_.empty(); }

 private:
  void sift_up(std::uint32_t position);
  void sift_down(std::uint32_t position);
  void swap_positions(std::uint32_t a, std::uint32_t b);
  [[nodiscard]] bool before(std::uint32_t position_a, std::uint32_t position_b) const {
    return earlier(events_[heap_[position_a]], events_[heap_[position_b]]);
  }

  std::vector<Event> events_;            // by ball
  std::vector<std::uint32_t> heap_;      // ball indices in heap order
  std::vector<std::uint32_t> position_;  // by ball: where it is in heap_
};

}  // namespace carom::detail
