// carom internal: a predicted event of the world's engine and the total order events are
// processed in (docs/engine.md, "Event order").
#pragma once

#include <cstdint>
#include <limits>

namespace carom::detail {

enum class EventKind : std::uint8_t {
  ball_ball = 0,      // two balls touch
  ball_wall = 1,      // a ball touches a wall
  cell_crossing = 2,  // a ball's centre leaves its grid cell (bookkeeping, no contact)
  // A ball's motion changes by itself: under gravity a sliding ball leaves its support
  // (world_resting.cpp), on a table its motion state ends (world_table.cpp).
  motion_change = 3,
};

// The four sides a ball's centre can leave its cell through (the partner of a crossing).
enum CrossingSide : std::uint32_t { kLeft = 0, kRight = 1, kDown = 2, kUp = 3 };

struct Event {
  double time = std::numeric_limits<double>::infinity();  // +inf: nothing will happen
  EventKind kind = EventKind::cell_crossing;
  std::uint32_t owner = 0;    // the ball whose slot holds the event
  std::uint32_t partner = 0;  // the other ball, the wall, or the CrossingSide
  // The partner ball's contact count when predicted: the event is stale once it has changed. A
  // sensor's event has kSensorEvent. A cell crossing's is kClearBehind where the prediction found
  // no contact with any ball around its owner, else 0 (docs/engine.md, "Crossing a cell").
  std::uint32_t partner_version = 0;
};
inline constexpr std::uint32_t kClearBehind = 1;
// A ball_wall event's partner_version is this where the wall is a sensor: the event is the ball's
// next enter or exit there, not a contact.
inline constexpr std::uint32_t kSensorEvent = 1;
// A ball_wall event's partner_version where the wall moves (world_moving_walls.cpp): a contact,
// or a time to look again (the wall's path ends, or the search for a contact stopped short).
inline constexpr std::uint32_t kMovingWallContact = 2;
inline constexpr std::uint32_t kMovingWallLook = 3;

// Time, then kind, then the balls' handles (for two balls the pair in ascending order, then the
// owner), so that simultaneous events are processed in one documented, deterministic order.
// Events name balls by their place in the engine's arrays, which the engine re-orders for
// locality (World::Impl::sort_by_cell); `handles` maps a place to its ball's handle index, which
// never changes, so the order of events does not depend on where balls are stored.
[[nodiscard]] inline bool tie_before(EventKind kind_a, std::uint32_t owner_a,
                                     std::uint32_t partner_a, EventKind kind_b,
                                     std::uint32_t owner_b, std::uint32_t partner_b,
                                     const std::uint32_t* handles) noexcept {
  if (kind_a != kind_b) return kind_a < kind_b;
  // A wall's or a side's number is its own key; a ball's is its handle.
  const std::uint32_t a_owner = handles[owner_a];
  const std::uint32_t b_owner = handles[owner_b];
  const bool pair_a = kind_a == EventKind::ball_ball;
  const bool pair_b = kind_b == EventKind::ball_ball;
  const std::uint32_t a_partner = pair_a ? handles[partner_a] : partner_a;
  const std::uint32_t b_partner = pair_b ? handles[partner_b] : partner_b;
  const std::uint32_t a_first = pair_a && a_partner < a_owner ? a_partner : a_owner;
  const std::uint32_t a_second = pair_a && a_partner < a_owner ? a_owner : a_partner;
  const std::uint32_t b_first = pair_b && b_partner < b_owner ? b_partner : b_owner;
  const std::uint32_t b_second = pair_b && b_partner < b_owner ? b_owner : b_partner;
  if (a_first != b_first) return a_first < b_first;
  if (a_second != b_second) return a_second < b_second;
  return a_owner < b_owner;
}

[[nodiscard]] inline bool earlier(const Event& a, const Event& b,
                                  const std::uint32_t* handles) noexcept {
  if (a.time != b.time) return a.time < b.time;
  return tie_before(a.kind, a.owner, a.partner, b.kind, b.owner, b.partner, handles);
}

}  // namespace carom::detail
