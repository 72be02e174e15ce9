#include "bowl_bounce.hpp"

#include <cmath>

#include "carom/bounce.hpp"

namespace carom::detail {

BowlBounce bounce_inside_arc(Vec2 velocity, Vec2 normal, double restitution) {
  const double approach = dot(velocity, normal);
  const double speed = length(velocity);
  // Arriving flatter than the sliding angle: elastic (a frictionless wall does no work on a
  // sliding ball). A graze (approach 0) changes nothing here; the turn below moves it inwards.
  const double e = approach < kBowlSlidingSine * speed ? 1.0 : restitution;
  const Vec2 bounced = approach > 0.0 ? velocity - normal * ((1.0 + e) * approach) : velocity;
  const double out_speed = length(bounced);
  const double leaving = -dot(bounced, normal);  // the speed away from the wall
  if (!(leaving < kBowlLeavingSine * out_speed)) {
    return {bounced, dot(velocity - bounced, normal)};
  }
  // Turned to the leaving angle, the speed kept. bounced has a part along the wall here: with
  // none it would be either zero (out_speed 0, returned above) or straight away from the wall.
  const Vec2 along_wall = bounced + normal * leaving;
  const double leaving_cosine = std::sqrt(1.0 - kBowlLeavingSine * kBowlLeavingSine);
  const Vec2 turned = along_wall * (out_speed * leaving_cosine / length(along_wall)) -
                      normal * (out_speed * kBowlLeavingSine);
  return {turned, dot(velocity - turned, normal)};
}

}  // namespace carom::detail
