// carom internal: a predicted event of the world's engine and the total order events are
// processed in (docs/world.md, "Event order").
#pragma once

#include <cstdint>
#include <limits>

namespace carom::detail {

enum class EventKind : std::uint8_t {
  ball_ball = 0,      // two balls touch
  ball_wall = 1,      // a ball touches a wall
  cell_crossing = 2,  // a ball's centre leaves its grid cell (bookkeeping, no contact)
};

// The four sides a ball's centre can leave its cell through (the partner of a crossing).
enum CrossingSide : std::uint32_t { kLeft = 0, kRight = 1, kDown = 2, kUp = 3 };

struct Event {
  double time = std::numeric_limits<double>::infinity();  // +inf: nothing will happen
  EventKind kind = EventKind::cell_crossing;
  std::uint32_t owner = 0;    // the ball whose slot holds the event
  std::uint32_t partner = 0;  // the other ball, the wall, or the CrossingSide
  // The partner ball's contact count when predicted: the event is stale once it has changed.
  std::uint32_t partner_version = 0;
};

// Time, then kind, then the ids (for two balls the pair in ascending order, then the owner), so
// that simultaneous events are processed in one documented, deterministic order.
[[nodiscard]] inline bool earlier(const Event& a, const Event& b) noexcept {
  if (a.time != b.time) return a.time < b.time;
  if (a.kind != b.kind) return a.kind < b.kind;
  const bool pair_a = a.kind == EventKind::ball_ball;
  const std::uint32_t a_first = pair_a && a.partner < a.owner ? a.partner : a.owner;
  const std::uint32_t a_second = pair_a && a.partner < a.owner ? a.owner : a.partner;
  const bool pair_b = b.kind == EventKind::ball_ball;
  const std::uint32_t b_first = pair_b && b.partner < b.owner ? b.partner : b.owner;
  const std::uint32_t b_second = pair_b && b.partner < b.owner ? b.owner : b.partner;
  if (a_first != b_first) return a_first < b_first;
  if (a_second != b_second) return a_second < b_second;
  return a.owner < b.owner;
}

}  // namespace carom::detail
