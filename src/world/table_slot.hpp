// carom internal: a ball's state on a table beside its slot (by slot, only in a world with a
// table): its spin at the slot's local time and the motion state it is in, fixed from the state's
// start to its end (docs/engine.md, "The table").
#pragma once

#include <limits>

#include "carom/vec2.hpp"
#include "core/table_motion.hpp"

namespace carom::detail {

struct TableSlot {
  Vec2 spin;           // ωx, ωy at the slot's local time
  double twist = 0.0;  // ωz at the slot's local time
  Vec2 acceleration;   // the centre's, constant through the state
  double ends = std::numeric_limits<double>::infinity();  // when the state ends (world time)
  TableState state = TableState::stationary;
};

}  // namespace carom::detail
