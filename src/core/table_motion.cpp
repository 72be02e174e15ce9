#include "table_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "carom/bounce.hpp"  // kImmovable

namespace carom::detail {

namespace {
namespace table_parts {  // (named: the core compiles as unity files)

constexpr double kForever = std::numeric_limits<double>::infinity();
// A contact point slipping slower than this share of the ball's speeds is rolling: the rounding
// of v − R·ω leaves that much where the two cancel.
constexpr double kSlipRounding = 0x1p-40;

// (By hypot: a speed of 1e-163, which a sum of impulses can leave, squares to nothing.)
double speed_of(Vec2 v) { return length(v); }

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
      return normalized(contact_velocity(ball)) * (-cloth.sliding * cloth.g);
    }
    case TableState::rolling:
      return normalized(ball.velocity) * (-cloth.rolling * cloth.g);
    case TableState::spinning:
    case TableState::stationary:
      return {};
  }
  return {};
}

StateMotion state_motion(const TableBall& ball, const Cloth& cloth) {
  return {table_state(ball), table_acceleration(ball, cloth), time_in_state(ball, cloth)};
}

TableBall advance_in_state(const TableBall& ball, const StateMotion& motion, const Cloth& cloth,
                           double t) {
  TableBall out = ball;
  out.twist = twist_after(ball, cloth, t);
  switch (motion.state) {
    case TableState::sliding:
      out.velocity = ball.velocity + motion.acceleration * t;
      out.spin = ball.spin + Vec2{motion.acceleration.y, -motion.acceleration.x} *
                                 (5.0 / (2.0 * ball.radius) * t);
      return out;
    case TableState::rolling:
      out.velocity = ball.velocity + motion.acceleration * t;
      out.spin = rolling_spin(out.velocity, ball.radius);
      return out;
    case TableState::spinning:
    case TableState::stationary:
      return out;
  }
  return out;
}

TableBall end_of_state(const TableBall& ball, const StateMotion& motion, const Cloth& cloth) {
  TableBall out = advance_in_state(ball, motion, cloth, motion.duration);
  switch (motion.state) {
    case TableState::sliding:
      out.spin = rolling_spin(out.velocity, ball.radius);
      break;
    case TableState::rolling:
      out.velocity = {};
      out.spin = {};
      break;
    case TableState::spinning:
      out.twist = 0.0;
      break;
    case TableState::stationary:
      break;
  }
  return out;
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

double collide_on_table(TableBall& a, TableBall& b, Vec2 normal, double restitution,
                        double friction) {
  const double approach = dot(a.velocity - b.velocity, normal);
  if (!(approach > 0.0)) return 0.0;
  const double inverse_a = 1.0 / a.mass;  // (0 for an immovable ball)
  const double inverse_b = 1.0 / b.mass;
  const double inverse_sum = inverse_a + inverse_b;
  // The normal impulse through the centres.
  const double normal_impulse = (1.0 + restitution) * approach / inverse_sum;
  // The slip of a's surface past b's at the contact point (3D: the spins give it a vertical
  // part): (va − vb) + (Ra·ωa + Rb·ωb) × n, less its part along n.
  const double n[3] = {normal.x, normal.y, 0.0};
  const double w[3] = {a.radius * a.spin.x + b.radius * b.spin.x,
                       a.radius * a.spin.y + b.radius * b.spin.y,
                       a.radius * a.twist + b.radius * b.twist};
  double slip[3] = {a.velocity.x - b.velocity.x + (w[1] * n[2] - w[2] * n[1]),
                    a.velocity.y - b.velocity.y + (w[2] * n[0] - w[0] * n[2]),
                    w[0] * n[1] - w[1] * n[0]};
  const double along = slip[0] * n[0] + slip[1] * n[1];
  slip[0] -= along * n[0];
  slip[1] -= along * n[1];
  const double size = std::sqrt(slip[0] * slip[0] + slip[1] * slip[1] + slip[2] * slip[2]);
  // A friction impulse J against the slip changes it by 7/2·J·(1/ma + 1/mb) (each centre by
  // J/m, each surface by R²/I·J = 5/2·J/m more through the spin): it stops at sticking or at
  // friction times the normal impulse.
  const double tangential =
      size > 0.0 ? std::min(friction * normal_impulse, size / (3.5 * inverse_sum)) : 0.0;
  const double t[3] = {size > 0.0 ? slip[0] / size : 0.0, size > 0.0 ? slip[1] / size : 0.0,
                       size > 0.0 ? slip[2] / size : 0.0};
  // On a: −J·t at +Ra·n; on b: +J·t at −Rb·n. Each spin turns by −(5/2)·J/(m·R)·(n × t).
  const double cross[3] = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2],
                           n[0] * t[1] - n[1] * t[0]};
  const Vec2 push = normal * normal_impulse + Vec2{t[0], t[1]} * tangential;
  a.velocity = a.velocity - push * inverse_a;
  b.velocity = b.velocity + push * inverse_b;
  const double turn_a = inverse_a == 0.0 ? 0.0 : -2.5 * tangential * inverse_a / a.radius;
  const double turn_b = inverse_b == 0.0 ? 0.0 : -2.5 * tangential * inverse_b / b.radius;
  a.spin = a.spin + Vec2{cross[0], cross[1]} * turn_a;
  b.spin = b.spin + Vec2{cross[0], cross[1]} * turn_b;
  a.twist += cross[2] * turn_a;
  b.twist += cross[2] * turn_b;
  return normal_impulse;
}

void roll_together(TableBall& a, TableBall& b) {
  const auto stick = [](TableBall& ball) {
    if (ball.mass == kImmovable) return;
    ball.velocity = ball.velocity - contact_velocity(ball) * (2.0 / 7.0);
  };
  stick(a);
  stick(b);
  Vec2 common;
  if (a.mass == kImmovable) {
    common = a.velocity;
  } else if (b.mass == kImmovable) {
    common = b.velocity;
  } else {
    common = (a.velocity * a.mass + b.velocity * b.mass) / (a.mass + b.mass);
  }
  for (TableBall* ball : {&a, &b}) {
    if (ball->mass == kImmovable) continue;
    ball->velocity = common;
    ball->spin = rolling_spin(common, ball->radius);
  }
}

void roll_along(TableBall& ball, Vec2 normal) {
  ball.velocity = ball.velocity - contact_velocity(ball) * (2.0 / 7.0);
  const double into = dot(ball.velocity, normal);
  if (into > 0.0) ball.velocity = ball.velocity - normal * into;
  ball.spin = rolling_spin(ball.velocity, ball.radius);
}

double cushion_bounce(TableBall& ball, Vec2 normal, const Cushion& cushion) {
  // In the frame (n, s, z): n towards the cushion, s = z × n along it, z up. The contact point
  // sits at r = R·(cos θ, 0, sin θ), sin θ = h/R − 1 (h the nose's height above the cloth), and
  // m = r/R is the contact's normal.
  const double sine = 2.0 * cushion.height - 1.0;
  const double cosine = std::sqrt(std::max(0.0, 1.0 - sine * sine));
  const Vec2 along = left_normal(normal);
  const double vn = dot(ball.velocity, normal);
  const double vs = dot(ball.velocity, along);
  // The spin in the frame: its (n, s) parts from (ωx, ωy), z as it is.
  const double wn = dot(ball.spin, normal);
  const double ws = dot(ball.spin, along);
  const double wz = ball.twist;
  const double radius = ball.radius;
  const double m[3] = {cosine, 0.0, sine};
  // The approach along m: the spin moves the contact point across m only.
  const double approach = vn * cosine;
  if (!(approach > 0.0)) return 0.0;
  // The contact point's velocity v + ω × r, and its slip (less its part along m).
  double slip[3] = {vn + radius * (ws * m[2] - wz * m[1]), vs + radius * (wz * m[0] - wn * m[2]),
                    radius * (wn * m[1] - ws * m[0])};
  const double normal_part = slip[0] * m[0] + slip[1] * m[1] + slip[2] * m[2];
  for (int k = 0; k < 3; ++k) slip[k] -= normal_part * m[k];
  const double size = std::sqrt(slip[0] * slip[0] + slip[1] * slip[1] + slip[2] * slip[2]);
  // Impulses over the mass: the normal one, and the friction, which changes the slip by 7/2 of
  // itself; it stops at sticking or at friction times the normal impulse.
  const double normal_impulse = (1.0 + cushion.restitution) * approach;
  const double friction =
      size > 0.0 ? std::min(cushion.friction * normal_impulse, size / 3.5) : 0.0;
  double impulse[3];
  for (int k = 0; k < 3; ++k) {
    impulse[k] = -normal_impulse * m[k] - (size > 0.0 ? friction * slip[k] / size : 0.0);
  }
  // The centre takes the impulse's part in the table's plane (the cloth bears the vertical
  // part); the spin turns by r × P / I = 5/(2R)·(m × P).
  ball.velocity = ball.velocity + normal * impulse[0] + along * impulse[1];
  const double k = 2.5 / radius;
  const double turn_n = k * (m[1] * impulse[2] - m[2] * impulse[1]);
  const double turn_s = k * (m[2] * impulse[0] - m[0] * impulse[2]);
  const double turn_z = k * (m[0] * impulse[1] - m[1] * impulse[0]);
  ball.spin = ball.spin + normal * turn_n + along * turn_s;
  ball.twist += turn_z;
  // A nose far above the equator pushes mostly down, and friction can push along: what is left of
  // the approach in the plane is stopped by the cushion's face (the ball leaves along it).
  const double left = dot(ball.velocity, normal);
  if (left > 0.0) ball.velocity = ball.velocity - normal * left;
  return vn - dot(ball.velocity, normal);
}

}  // namespace carom::detail
