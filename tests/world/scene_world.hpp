// The bridge between an oracle scene and a carom::World: build a World holding the same balls and
// walls, read its state back as a scene, and compare its contacts and state with the oracle's.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <vector>

#include "carom/world.hpp"
#include "world/reference_simulator.hpp"

namespace carom::testing {

// How a box scene's first four walls (box_walls(lower, upper)) reach the World.
enum class BoxAs : std::uint8_t {
  walls,     // as segments 0..3 of an open world, so that wall ids match the scene's
  boundary,  // as Boundary::box, whose walls are 0..3 in add_box's order (docs/world.md); the
             // scene may then have no other walls
};

struct SceneWorld {
  World world;
  std::vector<BallId> ids;  // ids[i] is the scene's ball i
};

// Balls get their restitution set explicitly, so the World's default never matters.
[[nodiscard]] SceneWorld build_world(const ReferenceScene& scene, BoxAs box_as = BoxAs::walls,
                                     double collapse_time = 0.0);

// The scene with each ball's position and velocity, and the start time, taken from the world now.
[[nodiscard]] ReferenceScene scene_at_world_time(const ReferenceScene& scene,
                                                 const SceneWorld& built);

// Every World contact in a run, over however many calls it took.
void append_contacts(const World& world, std::vector<ContactEvent>& all);

struct Tolerances {
  double time = 0.0;        // relative to max(|t|, time_scale)
  double time_scale = 1.0;  // the natural time unit of the scene (one step)
  double speed = 0.0;  // relative: approach speeds and velocities (to speed_scale), unit normals
  double speed_scale = 1.0;
  double position = 0.0;  // absolute, length units
};

// The same contacts in the same order: kind, balls, walls exactly; time, normal and approach
// speed within the tolerances. Reports the first difference with its neighbours.
[[nodiscard]] ::testing::AssertionResult same_contacts(std::span<const ContactEvent> world,
                                                       std::span<const BallId> ids,
                                                       std::span<const ReferenceContact> reference,
                                                       const Tolerances& tolerances);

// The same time (within the time tolerance), and every ball at the same place (the nearest image,
// when periodic) with the same velocity.
[[nodiscard]] ::testing::AssertionResult same_state(const SceneWorld& built,
                                                    const ReferenceSimulator& reference,
                                                    const ReferenceScene& scene,
                                                    const Tolerances& tolerances);

}  // namespace carom::testing
