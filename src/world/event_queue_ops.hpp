// carom internal: the event queue's operations on the engine's hot path (set, top, and what they
// call), defined inline so that the engine's prediction loop can inline them. The rest of the
// queue (resetting, re-ordering, opening a year) is in event_queue.cpp. Included by
// event_queue.hpp only.
#pragma once

#include <algorithm>
#include <cmath>

namespace carom::detail {

inline Event EventQueue::unpack(std::uint32_t owner) const {
  const Pending& pending = events_[owner];
  Event event;
  event.time = pending.time;
  event.kind = pending.kind();
  event.owner = owner;
  event.partner = pending.partner();
  event.partner_version = pending.partner_version;
  return event;
}

// Rounding is monotonic, so a later time never gets an earlier bucket: every event of a bucket
// comes before every event of a later one, and the heap's first is the queue's first.
inline std::int64_t EventQueue::bucket_of(double time) const {
  if (inverse_width_ == 0.0) return time <= origin_ ? 0 : kFarBucket;  // a year of one instant
  const double offset = (time - origin_) * inverse_width_;
  if (!(offset < kLastBucket)) return kFarBucket;
  // Truncation is the floor for offsets >= 0; a time before the origin (none is queued, but the
  // function is total) is bucket 0's, like the year's first instant.
  return offset > 0.0 ? static_cast<std::int64_t>(offset) : 0;
}

inline void EventQueue::set(std::uint32_t owner, const Event& event) {
  remove(owner);
  events_[owner] = {event.time, event.partner | (static_cast<std::uint32_t>(event.kind) << 30),
                    event.partner_version};
  if (defer_ && year_open_) {
    const std::int64_t bucket = bucket_of(event.time);
    if (bucket > current_ && bucket < year_end_) {
      __builtin_prefetch(&buckets_[static_cast<std::size_t>(bucket) & (buckets_.size() - 1)]);
      if (deferred_count_ == kMostDeferred) flush_deferred();
      deferred_[deferred_count_++] = owner;
      places_[owner] = Place::deferred;
      return;
    }
  }
  insert(owner);
}

// A deferred event falls in a bucket after the current one: set() defers no other, and the
// current bucket moves only in top(), which files every deferred event first (a new year, or a
// reset, likewise). So it goes to a bucket's list, never to the heap, and filing it allocates
// nothing.
inline void EventQueue::file_deferred(std::uint32_t owner) noexcept {
  const auto index =
      static_cast<std::size_t>(bucket_of(events_[owner].time)) & (buckets_.size() - 1);
  places_[owner] = Place::none;
  list_push(buckets_[index], owner, Place::bucket);
}

inline void EventQueue::file_deferred_in(std::int64_t bucket) noexcept {
  for (std::uint32_t k = 0; k < deferred_count_;) {
    const std::uint32_t owner = deferred_[k];
    if (bucket_of(events_[owner].time) != bucket) {
      ++k;
      continue;
    }
    file_deferred(owner);
    // (As in remove: the last one moved here may be filed a little early.)
    deferred_[k] = deferred_[--deferred_count_];
  }
}

inline void EventQueue::flush_deferred() noexcept {
  for (std::uint32_t k = 0; k < deferred_count_; ++k) file_deferred(deferred_[k]);
  deferred_count_ = 0;
  ripe_ = 0;
}

inline void EventQueue::age_deferred() noexcept {
  // (A removal may have moved a later one among the first ripe_: it is filed a little early.)
  const std::uint32_t ripe = std::min(ripe_, deferred_count_);
  for (std::uint32_t k = 0; k < ripe; ++k) file_deferred(deferred_[k]);
  for (std::uint32_t k = ripe; k < deferred_count_; ++k) deferred_[k - ripe] = deferred_[k];
  deferred_count_ -= ripe;
  ripe_ = deferred_count_;
}

inline void EventQueue::insert(std::uint32_t owner) {
  const double time = events_[owner].time;
  if (time == kNever) return;  // Place::none
  if (!year_open_) {
    list_push(overflow_, owner, Place::overflow);
    return;
  }
  const std::int64_t bucket = bucket_of(time);
  if (bucket <= current_) {
    heap_push(owner);
  } else if (bucket < year_end_) {
    const auto index = static_cast<std::size_t>(bucket) & (buckets_.size() - 1);
    list_push(buckets_[index], owner, Place::bucket);
  } else {
    list_push(overflow_, owner, Place::overflow);
  }
}

inline void EventQueue::remove(std::uint32_t owner) {
  switch (places_[owner]) {
    case Place::none:
      return;
    case Place::heap:
      heap_remove(owner);
      return;
    case Place::bucket: {
      // The bucket is found again from the stored time, by the same computation.
      const std::int64_t bucket = bucket_of(events_[owner].time);
      const auto index = static_cast<std::size_t>(bucket) & (buckets_.size() - 1);
      list_remove(buckets_[index], owner);
      return;
    }
    case Place::overflow:
      list_remove(overflow_, owner);
      return;
    case Place::deferred:
      for (std::uint32_t k = 0; k < deferred_count_; ++k) {
        if (deferred_[k] != owner) continue;
        deferred_[k] = deferred_[--deferred_count_];
        places_[owner] = Place::none;
        return;
      }
      return;
  }
}

// The links are written through selected addresses rather than under branches: whether a list
// is empty, or a ball last in it, is random, and such branches mispredicted often (a write whose
// target does not matter goes to the moving ball's own link, which is set right after).
inline void EventQueue::list_push(std::uint32_t& head, std::uint32_t owner, Place place) noexcept {
  link_prev_[head != kNoEvent ? head : owner] = owner;
  link_prev_[owner] = kNoEvent;
  link_next_[owner] = head;
  head = owner;
  places_[owner] = place;
  ++outside_heap_;
}

inline void EventQueue::list_remove(std::uint32_t& head, std::uint32_t owner) {
  const std::uint32_t before_it = link_prev_[owner];
  const std::uint32_t after_it = link_next_[owner];
  *(before_it != kNoEvent ? &link_next_[before_it] : &head) = after_it;
  // (See list_push; by a mask, since GCC keeps a branch for the ?: form here.)
  const std::uint32_t last = 0U - static_cast<std::uint32_t>(after_it == kNoEvent);
  link_prev_[(owner & last) | (after_it & ~last)] = before_it;
  places_[owner] = Place::none;
  --outside_heap_;
}

inline Event EventQueue::top() {
  age_deferred();
  while (heap_.empty()) {
    if (!year_open_ || current_ + 1 >= year_end_) {
      flush_deferred();  // (none is left by now: each falls in a bucket of the year)
      if (!open_year()) return Event{};  // nothing finite left
      continue;
    }
    ++current_;
    // A deferred event falls in a bucket after the one current when it was set: those of the
    // bucket opening now are filed first, the rest keep waiting (most often all of them; filing
    // every one here, when this was the common path, read their lists' heads a few instructions
    // after asking the cache for them, a stall each at 10⁶ balls).
    file_deferred_in(current_);
    // The whole list goes to the heap: walked by its links (each read before heap_push reuses
    // it as the heap position) rather than unlinked ball by ball, whose back links the walk
    // would read and write for nothing.
    auto& head = buckets_[static_cast<std::size_t>(current_) & (buckets_.size() - 1)];
    std::uint32_t owner = head;
    head = kNoEvent;
    while (owner != kNoEvent) {
      const std::uint32_t next = link_next_[owner];
      heap_push(owner);
      --outside_heap_;
      owner = next;
    }
  }
  return unpack(heap_.front().owner());
}

inline void EventQueue::heap_push(std::uint32_t owner) {
  places_[owner] = Place::heap;
  const Entry entry = entry_of(owner);
  heap_.emplace_back();
  write_entry(heap_.back(), entry);
  heap_sift_up(static_cast<std::uint32_t>(heap_.size() - 1), entry);
}

inline void EventQueue::heap_remove(std::uint32_t owner) {
  const std::uint32_t position = link_next_[owner];
  const Entry last = heap_.back();
  heap_.pop_back();
  places_[owner] = Place::none;
  link_next_[owner] = kNoEvent;
  if (last.owner() == owner) return;
  // The moved entry goes up or down, never both: up only when it is before its new parent.
  if (position > 0 && before(last, heap_[(position - 1) / 2])) {
    heap_sift_up(position, last);
  } else {
    heap_sift_down(position, last);
  }
}

// `entry` is the one at `position`, or to go there: passed in registers rather than read back
// from heap_, where it has just been written (an entry written in parts is read back only once
// the parts reach the cache; docs/decisions/0004-calendar-event-queue.md).
inline void EventQueue::heap_sift_up(std::uint32_t position, const Entry& entry) {
  while (position > 0) {
    const std::uint32_t parent = (position - 1) / 2;
    if (!before(entry, heap_[parent])) break;
    heap_place(position, heap_[parent]);
    position = parent;
  }
  heap_place(position, entry);
}

inline void EventQueue::heap_sift_down(std::uint32_t position, const Entry& entry) {
  const auto size = static_cast<std::uint32_t>(heap_.size());
  for (;;) {
    const std::uint32_t left = 2 * position + 1;
    if (left >= size) break;
    const std::uint32_t right = left + 1;
    const std::uint32_t child = right < size && before(heap_[right], heap_[left]) ? right : left;
    if (!before(heap_[child], entry)) break;
    heap_place(position, heap_[child]);
    position = child;
  }
  heap_place(position, entry);
}

}  // namespace carom::detail
