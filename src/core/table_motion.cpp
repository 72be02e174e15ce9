#include "table_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom::detail {

namespace {
namespace table_parts {  // (named: the core compiles as unity files)

constexpr double kForever = std::numeric_limits<double>::infinity();
// A contact point slipping slower than this share of the ball's speeds is rolling: the rounding
// of v − R·ω leaves that much where the two cancel.
constexpr double kSlipRounding = 0x1p-40;

double speed_of(Vec2 v) { return std::sqrt(length_squared(v)); }

// How fast the twist decays: the spinning friction's torque over the moment of inertia.
double twist_decay(const TableBall& ball, const Cloth& cloth) {
  return 5.0 * cloth.spinning * cloth.g / (2.0 * ball.radius);
}

double twist_after(const TableBall& ball, const Cloth& cloth, double t) {
  const double left = std::max(std::abs(ball.twist) - twist_decay(ball, cloth) * t, 0.0);
  return std::copysign(left, ball.twist);
}

// The spin of a ball rolling without slipping at velocity v: v − R·(ωy, −ωx) = 0.
Vec2 rolling_spin(Vec2 v, double radius) { return {-v.y / radius, v.x / radius}; }

}  // namespace table_parts
}  // namespace

using namespace table_parts;  // NOLINT(google-build-using-namespace): this file's own helpers

Vec2 contact_velocity(const TableBall& ball) {
  return {ball.velocity.x - ball.radius * ball.spin.y, ball.velocity.y + ball.radius * ball.spin.x};
}

TableState table_state(const TableBall& ball) {
  const double slip = speed_of(contact_velocity(ball));
  const double scale = speed_of(ball.velocity) + ball.radius * speed_of(ball.spin);
  if (slip > kSlipRounding * scale) return TableState::sliding;
  if (ball.velocity != Vec2{}) return TableState::rolling;
  if (ball.twist != 0.0) return TableState::spinning;
  return TableState::stationary;
}

double time_in_state(const TableBall& ball, const Cloth& cloth) {
  switch (table_state(ball)) {
    case TableState::sliding:
      // The slip falls at 7/2·μs·g (docs/derivation.md).
      return 2.0 * speed_of(contact_velocity(ball)) / (7.0 * cloth.sliding * cloth.g);
    case TableState::rolling:
      return speed_of(ball.velocity) / (cloth.rolling * cloth.g);
    case TableState::spinning:
      return std::abs(ball.twist) / twist_decay(ball, cloth);
    case TableState::stationary:
      return kForever;
  }
  return kForever;
}

Vec2 table_acceleration(const TableBall& ball, const Cloth& cloth) {
  switch (table_state(ball)) {
    case TableState::sliding: {
      const Vec2 slip = contact_velocity(ball);
      return slip * (-cloth.sliding * cloth.g / speed_of(slip));
    }
    case TableState::rolling:
      return ball.velocity * (-cloth.rolling * cloth.g / speed_of(ball.velocity));
    case TableState::spinning:
    case TableState::stationary:
      return {};
  }
  return {};
}

TableStep evolve(const TableBall& ball, const Cloth& cloth, double t) {
  const TableState state = table_state(ball);
  const double ends = time_in_state(ball, cloth);
  TableStep out;
  out.ball = ball;
  out.ball.twist = twist_after(ball, cloth, t);
  const Vec2 a = table_acceleration(ball, cloth);
  switch (state) {
    case TableState::sliding: {
      const double s = std::min(t, ends);
      out.ball.velocity = ball.velocity + a * s;
      // The friction F = m·a acts at the contact point, (0, 0, −R) from the centre: its torque
      // over the moment of inertia 2/5·m·R² turns the spin at (dωx, dωy) = 5/(2R)·(ay, −ax).
      const double k = 5.0 / (2.0 * ball.radius);
      out.ball.spin = ball.spin + Vec2{a.y, -a.x} * (k * s);
      // At the end of the slide the contact point stops: the spin is the rolling one exactly.
      if (t >= ends) out.ball.spin = rolling_spin(out.ball.velocity, ball.radius);
      out.displacement = ball.velocity * s + a * (0.5 * s * s);
      return out;
    }
    case TableState::rolling: {
      const double s = std::min(t, ends);
      out.ball.velocity = t >= ends ? Vec2{} : ball.velocity + a * s;
      out.ball.spin = rolling_spin(out.ball.velocity, ball.radius);
      out.displacement = ball.velocity * s + a * (0.5 * s * s);
      return out;
    }
    case TableState::spinning:
    case TableState::stationary:
      out.ball.velocity = {};
      out.ball.spin = {};
      return out;
  }
  return out;
}

}  // namespace carom::detail
