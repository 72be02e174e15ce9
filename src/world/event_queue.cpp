#include "event_queue.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

#include "permute.hpp"

namespace carom::detail {

namespace {

// A year has at least this many buckets, and kBucketsPerEvent per pending event rounded up to a
// power of two (so 1 to 2): with the width below, most events then fall inside the year and the
// overflow list stays short. 2 to 4 measured no faster, at 4 to 8 bytes a ball more.
constexpr std::uint32_t kMinBuckets = 16;
constexpr double kBucketsPerEvent = 1.0;
// Pending events' times ahead of the earliest are spread roughly exponentially with mean m, so
// n events are about n/m per unit time at the front: a width of kEventsPerBucket·m/n puts about
// that many events in each bucket there.
constexpr double kEventsPerBucket = 2.0;
// open_year estimates the spread of pending times from at most about this many of them.
constexpr std::size_t kMedianSample = 4096;
// A new year finds the events of the overflow list by a scan of every slot in order, rather than
// by walking the list, once the list holds at least 1 slot in kScanShare: walking chases a link
// an event, a cache miss each once the queue outgrows the cache (10⁶ events: about 170 ns an
// event, a seventh of the run's time), while the scan's reads stream. Below the share, a scan would
// read mostly slots with no pending event (a large world with few balls moving).
constexpr std::uint64_t kScanShare = 8;

}  // namespace

void EventQueue::reset(std::uint32_t count) {
  events_.assign(count, kNothing);
  clear_places(count);
}

void EventQueue::reserve_slots(std::uint32_t count) {
  while (events_.size() < count) {
    events_.push_back(kNothing);
    places_.push_back(Place::none);
    link_next_.push_back(kNoEvent);
    link_prev_.push_back(kNoEvent);
  }
}

void EventQueue::clear_places(std::uint32_t count) {
  places_.assign(count, Place::none);
  link_next_.assign(count, kNoEvent);
  link_prev_.assign(count, kNoEvent);
  heap_.clear();
  deferred_count_ = 0;
  ripe_ = 0;
  std::fill(buckets_.begin(), buckets_.end(), kNoEvent);
  overflow_ = kNoEvent;
  outside_heap_ = 0;
  year_open_ = false;
  current_ = 0;
  year_end_ = 0;
}

void EventQueue::reorder(std::span<const std::uint32_t> new_place) {
  const auto count = static_cast<std::uint32_t>(new_place.size());
  move_to(events_, new_place);
  for (std::uint32_t k = 0; k < count; ++k) {
    Pending& pending = events_[k];
    if (pending.kind() == EventKind::ball_ball) {
      pending.partner_and_kind =
          new_place[pending.partner()] | (pending.partner_and_kind & ~(kMaxBalls - 1));
    }
  }
  // The structure is rebuilt around the same events: where an event sits in it never changes
  // which one comes first.
  clear_places(count);
  for (std::uint32_t k = 0; k < count; ++k) insert(k);
}

bool EventQueue::open_year() {
  // Every finite event is in the overflow list now (the year's buckets and the heap are empty).
  if (overflow_ == kNoEvent) {
    year_open_ = false;
    return false;
  }
  const auto count = static_cast<std::size_t>(outside_heap_);
  const auto slots = static_cast<std::uint32_t>(places_.size());
  const bool scan = outside_heap_ * kScanShare >= slots;
  const std::uint32_t old_list = overflow_;
  // Calls visit(owner) for each event of the overflow list, in the list's order or the slots'
  // (kScanShare); visit may file its event elsewhere, even in a new overflow list (which the
  // scan has passed, and the walk does not follow). Which order only changes how the events sit
  // in the buckets' lists, never which one comes first (the heap orders each bucket).
  const auto for_each_overflowing = [&](auto&& visit) {
    if (scan) {
      for (std::uint32_t k = 0; k < slots; ++k) {
        if (places_[k] == Place::overflow) visit(k);
      }
      return;
    }
    for (std::uint32_t i = old_list; i != kNoEvent;) {
      const std::uint32_t owner = i;
      i = link_next_[owner];  // (before visit refiles it)
      visit(owner);
    }
  };
  // The earliest time, and the median of an evenly spaced sample of the times (every one in a
  // small queue): the sample keeps the year's planning from needing a copy of every time.
  const std::size_t stride = count / kMedianSample + 1;
  double earliest = kNever;
  scratch_.clear();
  std::size_t position = 0;
  for_each_overflowing([&](std::uint32_t owner) {
    earliest = std::min(earliest, events_[owner].time);
    if (position++ % stride == 0) scratch_.push_back(events_[owner].time);
  });
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
  buckets_.assign(size, kNoEvent);
  origin_ = earliest;
  // Half the events or more at the earliest time (width 0): the year is that one instant, so
  // that later events wait in the overflow list and the next year is tuned to their spread
  // (rather than every event going to the heap).
  inverse_width_ = width > 0.0 && std::isfinite(1.0 / width) ? 1.0 / width : 0.0;
  current_ = 0;
  year_end_ = inverse_width_ == 0.0 ? 1 : static_cast<std::int64_t>(size);
  year_open_ = true;
  overflow_ = kNoEvent;
  outside_heap_ = 0;
  for_each_overflowing([&](std::uint32_t owner) {
    places_[owner] = Place::none;
    insert(owner);
  });
  return true;
}

}  // namespace carom::detail
