// The world tests' shorthand for a ball's definition: where, how fast, how large.
#pragma once

#include "carom/world.hpp"

namespace carom::testing {

inline BallDef ball_def(Vec2 position, Vec2 velocity, double radius = 0.5) {
  BallDef def;
  def.position = position;
  def.velocity = velocity;
  def.radius = radius;
  return def;
}

}  // namespace carom::testing
