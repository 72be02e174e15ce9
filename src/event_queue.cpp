#include "event_queue.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

#include "permute.hpp"

namespace carom::detail {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::int64_t kFarBucket = std::numeric_limits<std::int64_t>::max();
// Bucket numbers stay far below 2^62 so that converting them to integers is exact and safe.
constexpr double kLastBucket = 0x1p62;
// A year has at least this many buckets, and about kBucketsPerEvent per pending event: with the
// width below, most events then fall inside the year and the overflow list stays short.
constexpr std::uint32_t kMinBuckets = 16;
constexpr double kBucketsPerEvent = 2.0;
// Pending events' times ahead of the earliest are spread roughly exponentially with mean m, so
// n events are about n/m per unit time at the front: a width of kEventsPerBucket·m/n puts about
// that many events in each bucket there.
constexpr double kEventsPerBucket = 2.0;
// open_year estimates the spread of pending times from at most about this many of them.
constexpr std::size_t kMedianSample = 4096;

}  // namespace

void EventQueue::reset(std::uint32_t count) {
  events_.resize(count);
  partner_versions_.assign(count, 0);
  for (std::uint32_t i = 0; i < count; ++i) {
    events_[i] = {kInfinity, i | (static_cast<std::uint32_t>(EventKind::cell_crossing) << 30), 0};
  }
  clear_places(count);
}

void EventQueue::clear_places(std::uint32_t count) {
  places_.assign(count, Place::none);
  link_next_.assign(count, kNone);
  link_prev_.assign(count, kNone);
  heap_.clear();
  std::fill(buckets_.begin(), buckets_.end(), kNone);
  overflow_ = kNone;
  outside_heap_ = 0;
  year_open_ = false;
  current_ = 0;
  year_end_ = 0;
}

void EventQueue::reorder(std::span<const std::uint32_t> new_place) {
  const auto count = static_cast<std::uint32_t>(new_place.size());
  move_to(events_, new_place);
  move_to(partner_versions_, new_place);
  for (std::uint32_t k = 0; k < count; ++k) {
    Entry& entry = events_[k];
    if (entry.kind() == EventKind::ball_ball) entry.partner = new_place[entry.partner];
    entry.owner_and_kind = k | (entry.owner_and_kind & ~(kMaxBalls - 1));
  }
  // The structure is rebuilt around the same events: where an event sits in it never changes
  // which one comes first.
  clear_places(count);
  for (std::uint32_t k = 0; k < count; ++k) insert(k);
}

Event EventQueue::unpack(std::uint32_t owner) const {
  const Entry& entry = events_[owner];
  Event event;
  event.time = entry.time;
  event.kind = entry.kind();
  event.owner = owner;
  event.partner = entry.partner;
  event.partner_version = partner_versions_[owner];
  return event;
}

// Rounding is monotonic, so a later time never gets an earlier bucket: every event of a bucket
// comes before every event of a later one, and the heap's first is the queue's first.
std::int64_t EventQueue::bucket_of(double time) const {
  if (inverse_width_ == 0.0) return time <= origin_ ? 0 : kFarBucket;  // a year of one instant
  const double offset = (time - origin_) * inverse_width_;
  if (!(offset < kLastBucket)) return kFarBucket;
  // Truncation is the floor for offsets >= 0; a time before the origin (none is queued, but the
  // function is total) is bucket 0's, like the year's first instant.
  return offset > 0.0 ? static_cast<std::int64_t>(offset) : 0;
}

void EventQueue::set(std::uint32_t owner, const Event& event) {
  remove(owner);
  events_[owner] = {event.time, owner | (static_cast<std::uint32_t>(event.kind) << 30),
                    event.partner};
  partner_versions_[owner] = event.partner_version;
  insert(owner);
}

void EventQueue::insert(std::uint32_t owner) {
  const double time = events_[owner].time;
  if (time == kInfinity) return;  // Place::none
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

void EventQueue::remove(std::uint32_t owner) {
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
  }
}

void EventQueue::list_push(std::uint32_t& head, std::uint32_t owner, Place place) {
  link_prev_[owner] = kNone;
  link_next_[owner] = head;
  if (head != kNone) link_prev_[head] = owner;
  head = owner;
  places_[owner] = place;
  ++outside_heap_;
}

void EventQueue::list_remove(std::uint32_t& head, std::uint32_t owner) {
  const std::uint32_t before_it = link_prev_[owner];
  const std::uint32_t after_it = link_next_[owner];
  if (before_it != kNone) {
    link_next_[before_it] = after_it;
  } else {
    head = after_it;
  }
  if (after_it != kNone) link_prev_[after_it] = before_it;
  places_[owner] = Place::none;
  --outside_heap_;
}

Event EventQueue::top() {
  while (heap_.empty()) {
    if (!year_open_ || current_ + 1 >= year_end_) {
      if (!open_year()) return Event{};  // nothing finite left
      continue;
    }
    ++current_;
    auto& head = buckets_[static_cast<std::size_t>(current_) & (buckets_.size() - 1)];
    while (head != kNone) {
      const std::uint32_t owner = head;
      list_remove(head, owner);
      heap_push(owner);
    }
  }
  return unpack(heap_.front().owner());
}

bool EventQueue::open_year() {
  // Every finite event is in the overflow list now (the year's buckets and the heap are empty).
  if (overflow_ == kNone) {
    year_open_ = false;
    return false;
  }
  // The earliest time, and the median of an evenly spaced sample of the times (every one in a
  // small queue): the sample keeps the year's planning from needing a copy of every time.
  const auto count = static_cast<std::size_t>(outside_heap_);
  const std::size_t stride = count / kMedianSample + 1;
  double earliest = kInfinity;
  scratch_.clear();
  std::size_t position = 0;
  for (std::uint32_t i = overflow_; i != kNone; i = link_next_[i], ++position) {
    earliest = std::min(earliest, events_[i].time);
    if (position % stride == 0) scratch_.push_back(events_[i].time);
  }
  // The median time ahead of the earliest, robust against a few events far away (which would
  // make a mean, and so the width, huge); for exponentially spread times it is m·ln 2.
  const auto middle = scratch_.begin() + static_cast<std::ptrdiff_t>(scratch_.size() / 2);
  std::nth_element(scratch_.begin(), middle, scratch_.end());
  const double mean_ahead = (*middle - earliest) / std::numbers::ln2;
  const double width = kEventsPerBucket * mean_ahead / static_cast<double>(count);
  const auto wanted = static_cast<std::uint64_t>(kBucketsPerEvent * static_cast<double>(count));
  // The cast is for 32-bit targets (the wasm build); a bucket per event or so always fits.
  const auto size =
      static_cast<std::size_t>(std::bit_ceil(std::max<std::uint64_t>(kMinBuckets, wanted)));
  buckets_.assign(size, kNone);
  origin_ = earliest;
  // Half the events or more at the earliest time (width 0): the year is that one instant, so
  // that later events wait in the overflow list and the next year is tuned to their spread
  // (rather than every event going to the heap).
  inverse_width_ = width > 0.0 && std::isfinite(1.0 / width) ? 1.0 / width : 0.0;
  current_ = 0;
  year_end_ = inverse_width_ == 0.0 ? 1 : static_cast<std::int64_t>(size);
  year_open_ = true;
  std::uint32_t pending = overflow_;
  overflow_ = kNone;
  outside_heap_ = 0;
  while (pending != kNone) {
    const std::uint32_t owner = pending;
    pending = link_next_[owner];
    places_[owner] = Place::none;
    insert(owner);
  }
  return true;
}

void EventQueue::heap_push(std::uint32_t owner) {
  places_[owner] = Place::heap;
  heap_.push_back(events_[owner]);
  heap_sift_up(static_cast<std::uint32_t>(heap_.size() - 1));
}

void EventQueue::heap_remove(std::uint32_t owner) {
  const std::uint32_t position = link_next_[owner];
  const Entry last = heap_.back();
  heap_.pop_back();
  places_[owner] = Place::none;
  link_next_[owner] = kNone;
  if (last.owner() == owner) return;
  heap_[position] = last;
  // The moved entry goes up or down, never both: up only when it is before its new parent.
  if (position > 0 && before(last, heap_[(position - 1) / 2])) {
    heap_sift_up(position);
  } else {
    heap_sift_down(position);
  }
}

void EventQueue::heap_sift_up(std::uint32_t position) {
  const Entry entry = heap_[position];
  while (position > 0) {
    const std::uint32_t parent = (position - 1) / 2;
    if (!before(entry, heap_[parent])) break;
    heap_place(position, heap_[parent]);
    position = parent;
  }
  heap_place(position, entry);
}

void EventQueue::heap_sift_down(std::uint32_t position) {
  const Entry entry = heap_[position];
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
