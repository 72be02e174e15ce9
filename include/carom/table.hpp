// carom: a billiards table. A world given a Table (WorldDef::table) is a cloth seen from above:
// every ball has a spin as well as a velocity, and moves in the states of the standard friction
// model of pool physics — sliding (its contact point slips on the cloth), rolling, spinning in
// place, at rest — each a parabola of its centre that ends at a closed-form time. Contacts stay
// exact: a ball–ball gap is a quartic in time and a cushion's a quadratic or quartic, each first
// root found by certified isolation. Balls meet with friction between their surfaces (throw) and
// walls are cushions whose nose stands at a height, so that a bounce changes the spin as a real
// cushion does. The user guide: docs/pool.md; the physics: docs/derivation.md, "A ball on a
// cloth".
#pragma once

#include <cstdint>

#include "carom/handles.hpp"

namespace carom {

// The cloth, the balls' surfaces and the cushions. Units are the world's: with metres and
// seconds, g = 9.81.
struct Table {
  double g = 9.81;                   // gravity normal to the table, > 0
  double sliding_friction = 0.2;     // μs: the cloth against a slipping contact point, >= 0
  double rolling_friction = 0.01;    // μr: rolling resistance, >= 0
  double spinning_friction = 0.044;  // μsp: against the spin about the vertical, >= 0
  double ball_friction = 0.06;       // between two balls' surfaces (throw), >= 0
  // The cushion's nose above the cloth, as a share of the ball's diameter (the WPA's 62.5 % to
  // 64.5 %), in [0.5, 1): the contact sits that far up the ball, so that a cushion pushes it
  // down and back and turns its spin (Han's model).
  double cushion_height = 0.635;
  double cushion_restitution = 0.85;  // in [0, 1]
  double cushion_friction = 0.2;      // between ball and cushion, >= 0
  // How long a contact lasts (about 0.2 ms between pool balls): a ball that met something less
  // than this long ago bounces elastically, so that a rack of balls pressed together cannot
  // collide inelastically without end. It is the world's collapse_time unless
  // WorldDef::collapse_time is set (> 0). >= 0; 0 turns it off.
  double contact_time = 2e-4;

  friend bool operator==(const Table&, const Table&) = default;
};

// A ball's angular velocity, radians per unit of time: x and y about the table's axes (topspin of
// a ball rolling along +x is +y), z about the vertical, counter-clockwise seen from above
// ("English").
struct Spin {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  friend bool operator==(const Spin&, const Spin&) = default;
};

// A ball's state on the table.
enum class MotionState : std::uint8_t {
  sliding,    // its contact point slips: friction μs·g against the slip
  rolling,    // it rolls without slipping: μr·g against its velocity
  spinning,   // in place, about the vertical: μsp turns the spin down
  stationary  // at rest
};

// The state's name as text and files write it: "sliding", "rolling", "spinning", "stationary".
[[nodiscard]] constexpr const char* motion_state_name(MotionState state) noexcept {
  switch (state) {
    case MotionState::sliding:
      return "sliding";
    case MotionState::rolling:
      return "rolling";
    case MotionState::spinning:
      return "spinning";
    case MotionState::stationary:
      break;
  }
  return "stationary";
}

// A cue's strike: the cue moving at `speed` along `direction` (radians, in the table's plane)
// tilted `elevation` above the table (radians, [0, π/2)), its tip meeting the ball `side` to the
// right of its centre and `height` above it, both measured across the cue as the player sees the
// ball (side² + height² < radius²; 2/5 of the radius above the centre rolls at once), bouncing
// off it with `restitution`. The cue's mass is in the ball's units (0.54 kg against a 0.17 kg
// ball). No tip friction, no squirt, no jump.
struct CueStrike {
  double speed = 0.0;
  double direction = 0.0;
  double elevation = 0.0;
  double side = 0.0;
  double height = 0.0;
  double cue_mass = 0.54;
  double restitution = 1.0;
};

// A ball's change of state during a run (World::motion_events).
struct MotionEvent {
  double time = 0.0;
  BallId ball;
  MotionState from = MotionState::sliding;
  MotionState to = MotionState::stationary;
};

}  // namespace carom
