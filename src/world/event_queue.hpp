// carom internal: the world's event queue. One slot per ball holding that ball's earliest
// predicted event (rather than every predicted pair), replaced whenever its ball is
// re-predicted. A calendar queue in the style of Paul (J. Comput. Phys. 221 (2007) 615): time is
// cut into buckets of equal width; the events of the current bucket sit in a small indexed
// binary heap (in the exact event order), later buckets of the current "year" in unsorted
// lists, and events beyond the year in one overflow list that is sorted into buckets when the
// year ends (with the width re-tuned to the events then pending). Replacing a slot and taking
// the earliest are O(1) on average. Design: docs/engine.md, "One event per ball".
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "huge_page_allocator.hpp"
#include "world_event.hpp"

namespace carom::detail {

class EventQueue {
 public:
  // Slots for balls 0 .. count-1, all holding "nothing will happen".
  void reset(std::uint32_t count);
  // Adds slots holding "nothing will happen" up to balls 0 .. count-1, keeping the others.
  void reserve_slots(std::uint32_t count);
  // The handle index of the ball at each place, for the order of simultaneous events
  // (world_event.hpp); the caller keeps the array alive and calls this again after it moves.
  void use_handles(const std::uint32_t* handles) { handles_ = handles; }
  // Moves the slots as the engine re-orders its balls: ball i's slot goes to new_place[i], and
  // every ball named in an event is renamed likewise. The pending events stay exactly as they
  // were.
  void reorder(std::span<const std::uint32_t> new_place);
  void set(std::uint32_t owner, const Event& event);
  [[nodiscard]] Event slot(std::uint32_t owner) const { return unpack(owner); }
  // The earliest event in the order of world_event.hpp's `earlier`, or one at +infinity when no
  // slot holds a finite time. Not const: it may open the next bucket or year.
  [[nodiscard]] Event top();
  // Whether set() defers filing an event that falls in a later bucket until the second top()
  // after it, asking the cache for its bucket's list head now: large worlds' events are filed
  // across the queue's whole year, a miss or two each, which then overlap the engine's work
  // (docs/engine.md, "Memory"). Events at the current bucket are filed at once, and top()
  // files the deferred events of a bucket before it opens it, so the order of events is the same
  // either way.
  void defer_filing(bool on) noexcept {
    flush_deferred();
    defer_ = on;
  }

  // For the engine's lookahead (world_lookahead.cpp), which walks the buckets ahead of the
  // current one: the current bucket's number (it grows while a year lasts; -1 while no year is
  // open), the first event's owner in bucket `bucket` (kNone past the year), the owner after
  // `owner` in its bucket's list (kNone at its end), and a pending event's kind and partner.
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  [[nodiscard]] std::int64_t current_bucket() const { return year_open_ ? current_ : -1; }
  [[nodiscard]] std::uint32_t bucket_first(std::int64_t bucket) const {
    if (!year_open_ || bucket >= year_end_) return kNone;
    return buckets_[static_cast<std::size_t>(bucket) & (buckets_.size() - 1)];
  }
  [[nodiscard]] std::uint32_t list_next(std::uint32_t owner) const { return link_next_[owner]; }
  [[nodiscard]] EventKind kind_of(std::uint32_t owner) const { return events_[owner].kind(); }
  [[nodiscard]] std::uint32_t partner_of(std::uint32_t owner) const {
    return events_[owner].partner();
  }
  // Asks the cache, for writing, for the links that taking the ball's event out of its bucket's
  // list writes (its neighbours' in the list).
  [[gnu::always_inline]] void prefetch_list_neighbours(std::uint32_t owner) const {
    if (places_[owner] != Place::bucket) return;
    const std::uint32_t before_it = link_prev_[owner];
    const std::uint32_t after_it = link_next_[owner];
    __builtin_prefetch(&link_next_[before_it != kNoEvent ? before_it : owner], 1);
    __builtin_prefetch(&link_prev_[after_it != kNoEvent ? after_it : owner], 1);
  }
  // Asks the cache for what replacing the ball's slot reads (inlined by force, as
  // Grid::prefetch_block_heads is, for the same reason).
  [[gnu::always_inline]] void prefetch_slot(std::uint32_t owner) const {
    __builtin_prefetch(&events_[owner]);
    __builtin_prefetch(&places_[owner]);
    __builtin_prefetch(&link_next_[owner]);
    __builtin_prefetch(&link_prev_[owner]);
  }
  // The most balls, and walls, an event can name (two bits of the owner and partner fields hold
  // the kind).
  static constexpr std::uint32_t kMaxBalls = 1u << 30;
  static constexpr std::uint32_t kMaxWalls = 1u << 30;

 private:
  static constexpr std::uint32_t kNoEvent = std::numeric_limits<std::uint32_t>::max();  // links
  static constexpr double kNever = std::numeric_limits<double>::infinity();
  static constexpr std::int64_t kFarBucket = std::numeric_limits<std::int64_t>::max();
  // Bucket numbers stay far below 2^62 so that converting them to integers is exact and safe.
  static constexpr double kLastBucket = 0x1p62;

  // A ball's pending event, 16 bytes: its owner is its place in events_.
  struct Pending {
    double time;
    std::uint32_t partner_and_kind;  // the partner in the low 30 bits, the EventKind above
    std::uint32_t partner_version;
    [[nodiscard]] std::uint32_t partner() const { return partner_and_kind & (kMaxBalls - 1); }
    [[nodiscard]] EventKind kind() const { return static_cast<EventKind>(partner_and_kind >> 30); }
  };
  // An empty slot's entry: "nothing will happen" (at +infinity, never in a list or the heap).
  static constexpr Pending kNothing{kNever,
                                    static_cast<std::uint32_t>(EventKind::cell_crossing) << 30, 0};
  // A heap member: the event without its partner's version but with its owner, 16 bytes, so
  // that sifting compares without reaching into events_.
  struct Entry {
    double time;
    std::uint32_t owner_and_kind;  // owner in the low 30 bits, the EventKind above
    std::uint32_t partner;
    [[nodiscard]] std::uint32_t owner() const { return owner_and_kind & (kMaxBalls - 1); }
    [[nodiscard]] EventKind kind() const { return static_cast<EventKind>(owner_and_kind >> 30); }
  };
  // (write_entry stores an entry's fields as two 64-bit halves.)
  static_assert(sizeof(Entry) == 16 && offsetof(Entry, owner_and_kind) == 8 &&
                offsetof(Entry, partner) == 12);
  enum class Place : std::uint8_t { none, heap, bucket, overflow, deferred };

  [[nodiscard]] Event unpack(std::uint32_t owner) const;
  [[nodiscard]] Entry entry_of(std::uint32_t owner) const {
    const Pending& pending = events_[owner];
    return {pending.time, owner | (pending.partner_and_kind & ~(kMaxBalls - 1)), pending.partner()};
  }
  // The order of world_event.hpp's `earlier`, on entries: the time settles it but for ties.
  [[nodiscard]] bool before(const Entry& a, const Entry& b) const {
    if (a.time != b.time) return a.time < b.time;
    return tie_before(a.kind(), a.owner(), a.partner, b.kind(), b.owner(), b.partner, handles_);
  }
  // The bucket a time falls in, counted from origin_; kFarBucket for times beyond any year.
  [[nodiscard]] std::int64_t bucket_of(double time) const;

  void insert(std::uint32_t owner);
  void remove(std::uint32_t owner);
  void list_push(std::uint32_t& head, std::uint32_t owner, Place place) noexcept;
  void list_remove(std::uint32_t& head, std::uint32_t owner);
  void heap_push(std::uint32_t owner);
  void heap_remove(std::uint32_t owner);
  void heap_sift_up(std::uint32_t position, const Entry& entry);
  void heap_sift_down(std::uint32_t position, const Entry& entry);
  void heap_place(std::uint32_t position, const Entry& entry) {
    write_entry(heap_[position], entry);
    link_next_[entry.owner()] = position;  // a heap member's "next" is its heap position
  }
  // Writes an entry with one 16-byte store where the CPU has SSE2: the heap reads entries just
  // written all the time (a push's parent is often the last push), and a read of a whole entry
  // is served from the store buffer only when one store wrote all of it; written in parts, it
  // waits for them to reach the cache (docs/decisions/0004-calendar-event-queue.md).
  static void write_entry(Entry& to, const Entry& entry) noexcept {
#if defined(__SSE2__)
    const auto ids = static_cast<std::uint64_t>(entry.partner) << 32 | entry.owner_and_kind;
    const __m128i bits =
        _mm_set_epi64x(static_cast<long long>(ids), std::bit_cast<long long>(entry.time));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(&to), bits);
#else
    to = entry;
#endif
  }
  // Files every deferred event (defer_filing).
  void flush_deferred() noexcept;
  // Files the deferred events that fall in `bucket`, which top() is about to open.
  void file_deferred_in(std::int64_t bucket) noexcept;
  // Files the deferred events set before the last top() (their list heads, asked for by set(),
  // have had an event's time to come; the back link filing writes into the old head is a store,
  // which does not hold the engine up). Reading the heads one top() earlier, to ask for those
  // links, stalls on each (the head asked for a few instructions before; measured in
  // docs/decisions/0004-calendar-event-queue.md).
  void age_deferred() noexcept;
  void file_deferred(std::uint32_t owner) noexcept;
  // Starts a new year from the overflow list; false when no finite event is left.
  bool open_year();
  // Empties the heap, the buckets and the lists, keeping events_.
  void clear_places(std::uint32_t count);

  // By ball.
  BigVector<Pending> events_;
  BigVector<Place> places_;
  BigVector<std::uint32_t> link_next_;  // list successor, or heap position
  BigVector<std::uint32_t> link_prev_;  // list predecessor (kNone at a list's head)

  // The current bucket's events, a binary heap of copies (so that sifting compares without
  // reaching into events_).
  BigVector<Entry> heap_;
  BigVector<std::uint32_t> buckets_;  // list heads of the year's buckets, by bucket % size
  std::uint32_t overflow_ = 0;        // list head of events beyond the year (kNone: empty)
  std::uint64_t outside_heap_ = 0;    // finite events in buckets or the overflow list
  bool year_open_ = false;
  std::int64_t current_ = 0;   // the bucket whose events are in heap_
  std::int64_t year_end_ = 0;  // the first bucket past the year
  double origin_ = 0.0;        // the time where bucket 0 starts
  double inverse_width_ = 0.0;
  // Events whose filing is deferred (Place::deferred): a contact's two re-predictions, or a
  // few more; a set() that finds the list full files them all first.
  static constexpr std::uint32_t kMostDeferred = 8;
  std::uint32_t deferred_[kMostDeferred] = {};
  std::uint32_t deferred_count_ = 0;
  std::uint32_t ripe_ = 0;  // the first ripe_ of them were deferred before the last top()
  bool defer_ = false;
  std::vector<double> scratch_;  // open_year's sample of times (kept: at most a few thousand)
  const std::uint32_t* handles_ = nullptr;
};

}  // namespace carom::detail

#include "event_queue_ops.hpp"  // IWYU pragma: export
