// Contact response along the normal. Derivation: docs/derivation.md, "The bounce".
#include "carom/bounce.hpp"

#include "bowl_bounce.hpp"
#include "impulse.hpp"
#include "validate.hpp"

namespace carom {
namespace {

// 1/m, with kImmovable giving exactly 0.
double inverse_mass(double mass) { return mass == kImmovable ? 0.0 : 1.0 / mass; }

// The arguments of a bounce off a static wall, named after `function` when one is bad.
void validate_wall_bounce(const char* function, Vec2 velocity, double mass, Vec2 normal,
                          double restitution) {
  detail::require_finite(function, "velocity", velocity);
  detail::require_positive(function, "mass", mass);
  detail::require_nonzero(function, "normal", normal);
  detail::require_restitution(function, "restitution", restitution);
}

}  // namespace

BounceResult bounce(Vec2 velocity_a, double mass_a, Vec2 velocity_b, double mass_b, Vec2 normal,
                    double restitution) {
  constexpr const char* kFunction = "bounce";
  detail::require_finite(kFunction, "velocity_a", velocity_a);
  detail::require_finite(kFunction, "velocity_b", velocity_b);
  detail::require_mass(kFunction, "mass_a", mass_a);
  detail::require_mass(kFunction, "mass_b", mass_b);
  detail::require_nonzero(kFunction, "normal", normal);
  detail::require_restitution(kFunction, "restitution", restitution);
  if (mass_a == kImmovable && mass_b == kImmovable) {
    detail::require_in_range(kFunction, "mass_b", mass_b, 0.0, 0.0,
                             "cannot be kImmovable when mass_a is too");
  }

  const Vec2 n = normalized(normal);
  const double approach_speed = dot(velocity_a - velocity_b, n);
  if (!(approach_speed > 0.0)) return {velocity_a, velocity_b, 0.0};

  const double inverse_a = inverse_mass(mass_a);
  const double inverse_b = inverse_mass(mass_b);
  const double impulse = detail::normal_impulse(approach_speed, inverse_a, inverse_b, restitution);
  detail::apply_impulse(velocity_a, velocity_b, n, impulse, inverse_a, inverse_b);
  return {velocity_a, velocity_b, impulse};
}

BounceResult bounce_equal_mass(Vec2 velocity_a, Vec2 velocity_b, Vec2 line_of_centres) {
  constexpr const char* kFunction = "bounce_equal_mass";
  detail::require_finite(kFunction, "velocity_a", velocity_a);
  detail::require_finite(kFunction, "velocity_b", velocity_b);
  detail::require_nonzero(kFunction, "line_of_centres", line_of_centres);

  const Components a = decompose(velocity_a, line_of_centres);  // the tutorial's v1a, v1b
  const Components b = decompose(velocity_b, line_of_centres);  // v2a, v2b
  // For unit masses the impulse equals the change of A's velocity along the line of centres.
  const double impulse = dot(a.along - b.along, normalized(line_of_centres));
  return {b.along + a.across, a.along + b.across, impulse};
}

WallBounceResult bounce_off_static(Vec2 velocity, double mass, Vec2 normal, double restitution) {
  validate_wall_bounce("bounce_off_static", velocity, mass, normal, restitution);

  const Vec2 n = normalized(normal);
  const double approach_speed = dot(velocity, n);
  if (!(approach_speed > 0.0)) return {velocity, 0.0};
  const double speed_change = detail::wall_speed_change(approach_speed, restitution);
  return {velocity - n * speed_change, speed_change * mass};
}

WallBounceResult bounce_inside_arc(Vec2 velocity, double mass, Vec2 normal, double restitution) {
  validate_wall_bounce("bounce_inside_arc", velocity, mass, normal, restitution);
  const detail::BowlBounce out =
      detail::bounce_inside_arc(velocity, normalized(normal), restitution);
  return {out.velocity, out.normal_speed_change * mass};
}

}  // namespace carom
