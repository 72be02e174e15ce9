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

TableBall strike(const CueStrike& cue, double mass, double radius) {
  // The cue's direction d, the player's right s (horizontal) and up u = s × d, all unit and
  // orthogonal.
  const double c = std::cos(cue.elevation);
  const double e = std::sin(cue.elevation);
  const double cf = std::cos(cue.direction);
  const double sf = std::sin(cue.direction);
  const double d[3] = {c * cf, c * sf, -e};
  const double s[3] = {sf, -cf, 0.0};
  const double u[3] = {s[1] * d[2] - s[2] * d[1], s[2] * d[0] - s[0] * d[2],
                       s[0] * d[1] - s[1] * d[0]};
  // The tip meets the ball at r = −depth·d + side·s + height·u from the centre; its lever about
  // the centre is r × d = side·u − height·s, of squared length side² + height².
  const double inertia = 0.4 * mass * radius * radius;
  const double lever = cue.side * cue.side + cue.height * cue.height;
  // The impulse that gives the tip's point and the cue the relative speed −e·V along d.
  const double impulse =
      (1.0 + cue.restitution) * cue.speed / (1.0 / cue.cue_mass + 1.0 / mass + lever / inertia);
  TableBall out;
  out.radius = radius;
  // The table takes the impulse's downward part: the centre moves along d's horizontal part.
  out.velocity = Vec2{d[0], d[1]} * (impulse / mass);
  const double k = impulse / inertia;
  out.spin = Vec2{cue.side * u[0] - cue.height * s[0], cue.side * u[1] - cue.height * s[1]} * k;
  out.twist = (cue.side * u[2] - cue.height * s[2]) * k;
  return out;
}

void collide_on_table(TableBall& a, TableBall& b, Vec2 normal, double restitution,
                      double friction) {
  const double approach = dot(a.velocity - b.velocity, normal);
  if (!(approach > 0.0)) return;
  const double radius = a.radius;
  // Impulses over the mass: the normal one, (1 + e)/2 of the approach for equal balls.
  const double normal_impulse = 0.5 * (1.0 + restitution) * approach;
  // The slip of a's surface past b's at the contact point (3D: the spins give it a vertical part):
  // (va − vb) + R·(ωa + ωb) × n, less its part along n.
  const double n[3] = {normal.x, normal.y, 0.0};
  const double w[3] = {a.spin.x + b.spin.x, a.spin.y + b.spin.y, a.twist + b.twist};
  double slip[3] = {a.velocity.x - b.velocity.x + radius * (w[1] * n[2] - w[2] * n[1]),
                    a.velocity.y - b.velocity.y + radius * (w[2] * n[0] - w[0] * n[2]),
                    radius * (w[0] * n[1] - w[1] * n[0])};
  const double along = slip[0] * n[0] + slip[1] * n[1];
  slip[0] -= along * n[0];
  slip[1] -= along * n[1];
  const double size = std::sqrt(slip[0] * slip[0] + slip[1] * slip[1] + slip[2] * slip[2]);
  // A friction impulse J (over the mass) changes the slip by 7·J (each ball's centre by J, each
  // spin by 5/2·J/R at the lever R): it stops at sticking, |slip|/7, or at friction·normal.
  const double tangential = size > 0.0 ? std::min(friction * normal_impulse, size / 7.0) : 0.0;
  const double t[3] = {size > 0.0 ? slip[0] / size : 0.0, size > 0.0 ? slip[1] / size : 0.0,
                       size > 0.0 ? slip[2] / size : 0.0};
  // On a: −J·t at +R·n; on b: +J·t at −R·n. Both spins turn by −(5/2)·J/R·(n × t).
  const double k = 2.5 * tangential / radius;
  const double turn[3] = {-k * (n[1] * t[2] - n[2] * t[1]), -k * (n[2] * t[0] - n[0] * t[2]),
                          -k * (n[0] * t[1] - n[1] * t[0])};
  a.velocity = a.velocity - normal * normal_impulse - Vec2{t[0], t[1]} * tangential;
  b.velocity = b.velocity + normal * normal_impulse + Vec2{t[0], t[1]} * tangential;
  a.spin = a.spin + Vec2{turn[0], turn[1]};
  b.spin = b.spin + Vec2{turn[0], turn[1]};
  a.twist += turn[2];
  b.twist += turn[2];
}

}  // namespace carom::detail
