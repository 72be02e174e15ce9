// carom: which balls and walls meet. Each ball and wall has a CollisionFilter; a pair whose
// filters say no passes through each other with no contact at all (no event, no response, no
// overlap complaint). The default filter meets every other default one, so a world that never
// sets a filter behaves, bit for bit, as one without filters. The user guide: docs/world.md,
// "Filters".
#pragma once

#include <cstdint>

namespace carom {

struct CollisionFilter {
  std::uint64_t category = 1;  // what this one is: one bit or several
  std::uint64_t mask = ~0ULL;  // the categories it meets
  // A group other than 0 overrides the bits between members of one group: a positive group's
  // members always meet, a negative group's never (a ragdoll's parts, a chain's links).
  std::int32_t group = 0;

  friend constexpr bool operator==(const CollisionFilter&, const CollisionFilter&) = default;
};

// Whether two filters let their owners meet (Box2D's rule, so that filters carry over).
[[nodiscard]] constexpr bool should_collide(const CollisionFilter& a,
                                            const CollisionFilter& b) noexcept {
  if (a.group == b.group && a.group != 0) return a.group > 0;
  return (a.mask & b.category) != 0 && (a.category & b.mask) != 0;
}

}  // namespace carom
