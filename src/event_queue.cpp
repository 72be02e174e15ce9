#include "event_queue.hpp"

#include <utility>

namespace carom::detail {

void EventQueue::reset(std::uint32_t count) {
  events_.assign(count, Event{});
  heap_.resize(count);
  position_.resize(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    events_[i].owner = i;
    heap_[i] = {events_[i].time, i};
    position_[i] = i;
  }
}

void EventQueue::add_slot() {
  const auto owner = static_cast<std::uint32_t>(events_.size());
  Event nothing;
  nothing.owner = owner;
  events_.push_back(nothing);
  position_.push_back(static_cast<std::uint32_t>(heap_.size()));
  heap_.push_back({nothing.time, owner});
}

void EventQueue::set(std::uint32_t owner, const Event& event) {
  const bool sooner = earlier(event, events_[owner]);
  events_[owner] = event;
  heap_[position_[owner]].time = event.time;
  if (sooner) {
    sift_up(position_[owner]);
  } else {
    sift_down(position_[owner]);
  }
}

void EventQueue::swap_positions(std::uint32_t a, std::uint32_t b) {
  std::swap(heap_[a], heap_[b]);
  position_[heap_[a].owner] = a;
  position_[heap_[b].owner] = b;
}

void EventQueue::sift_up(std::uint32_t position) {
  while (position > 0) {
    const std::uint32_t parent = (position - 1) / 2;
    if (!before(position, parent)) return;
    swap_positions(position, parent);
    position = parent;
  }
}

void EventQueue::sift_down(std::uint32_t position) {
  const auto size = static_cast<std::uint32_t>(heap_.size());
  for (;;) {
    const std::uint32_t left = 2 * position + 1;
    if (left >= size) return;
    const std::uint32_t right = left + 1;
    const std::uint32_t child = right < size && before(right, left) ? right : left;
    if (!before(child, position)) return;
    swap_positions(position, child);
    position = child;
  }
}

}  // namespace carom::detail
