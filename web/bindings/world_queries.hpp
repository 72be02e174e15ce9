// carom web: the World's queries (carom/world.hpp, "queries") and the last step's contacts, in a
// page's own terms: balls by their DrawnWorld index, pockets by their index in pockets(), walls
// by their World id, and plain JavaScript objects out. The "Pool" page aims with cast_ball.
//
// A query's filter is a JavaScript object (or undefined), every key optional:
//   balls   false: the query sees no ball (pockets included: they are balls of the World)
//   walls   false: it sees no wall
//   pockets false: it sees no pocket
//   ignore  a ball's index: the query does not see it (a cast of that ball from where it is);
//           -1 or absent: none
//   accept  a function of a ball's index answering true or false: whether the query may see the
//           ball (it is not asked about pockets). It must not throw: a JavaScript exception would
//           unwind through the query without its C++ clean-up
//
// A hit is {kind, ball, pocket, wall, boundary, fraction, point, normal, center, overlapping}:
// kind "none", "ball", "pocket" or "wall"; ball the ball's index (or -1), pocket the pocket's
// (or -1), wall the World's wall id (or -1) with boundary true for the four walls of a box;
// fraction, point, normal (from what was hit back towards the caster), center and overlapping as
// carom::QueryHit has them.
#pragma once

#include <emscripten/val.h>

#include "carom/vec2.hpp"
#include "drawn_world.hpp"

namespace carom::web {

// World::cast_ball: the first ball, pocket or wall a ball of radius at center touches while
// moved by translation.
[[nodiscard]] emscripten::val cast_ball(const DrawnWorld& w, Vec2 center, double radius,
                                        Vec2 translation, const emscripten::val& filter);
// World::balls_in_circle: the indices of the balls (pockets left out) that touch or overlap the
// circle, in the World's handle order.
[[nodiscard]] emscripten::val balls_in_circle(const DrawnWorld& w, Vec2 center, double radius,
                                              const emscripten::val& filter);
// The contacts of the last step (DrawnWorld::step_contacts), each
// {time, kind, a, b, pocket, wall, point, normal, approach_speed, impulse}: kind "ball" (a and b
// the two balls' indices), "wall" (a the ball, wall the World's wall id) or "pocket" (a the ball
// the pocket took, pocket its index); b, pocket and wall are -1 where they name nothing.
[[nodiscard]] emscripten::val step_contacts(const DrawnWorld& w);

}  // namespace carom::web
