// carom: sensors, walls that report rather than bounce. A sensor is a segment, an arc or a disc
// that takes no part in the response: balls pass through it, and each time a ball starts or stops
// overlapping it the world records an enter or an exit at its exact time, however fast the ball
// crosses (a bullet through a thin line records both). Enters and exits of one ball and sensor
// alternate, starting with an enter. A sensor may also remove the ball that enters it (a pocket).
// Sensors share the walls' ids and filters (a ball its filter lets through a sensor records
// nothing there). The user guide: docs/world.md, "Sensors".
#pragma once

#include <cstddef>
#include <cstdint>

#include "carom/handles.hpp"

namespace carom {

// What a sensor does when a ball enters it.
enum class SensorAction : std::uint8_t {
  report,       // records the enter and, later, the exit
  remove_ball,  // records the enter and removes the ball (a pocket): no exit follows
};

enum class SensorEventKind : std::uint8_t { enter, exit };

// One enter or exit, in the order of the run: by time, and where it falls among contacts()
// (contacts_before of them came first).
struct SensorEvent {
  double time = 0.0;
  SensorEventKind kind = SensorEventKind::enter;
  BallId ball;           // stale from this event on when removed
  WallId sensor = 0;     // the sensor's wall id
  bool removed = false;  // the sensor removed the ball (SensorAction::remove_ball)
  std::size_t contacts_before = 0;
};

}  // namespace carom
