// A ball on a cloth (src/core/table_motion.hpp): the textbook closed forms (a stun shot rolls at
// 5/7 of its speed after 2v/(7·μs·g), a rolling ball stops after v²/(2·μr·g), a spin stops after
// 2R|ωz|/(5·μsp·g)), and over random shots with side, top and back spin: the angular momentum
// about the contact point is kept through the slide, the rolling velocity is v − 2/7·u, the
// energy never rises, and each state leads to the next. Cushions (Han's model) and held contacts:
// the closed forms without friction, and over random cases energy that never rises.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/table_motion.hpp"

namespace carom::detail {
namespace table_motion_tests {

constexpr double kRadius = 0.028575;  // a pool ball, 57.15 mm across
const Cloth kCloth{9.81, 0.2, 0.01, 0.044};

TableBall ball(Vec2 velocity, Vec2 spin = {}, double twist = 0.0) {
  return {velocity, spin, twist, kRadius};
}

// Energy over the mass: ½v² + ½·(2/5)R²|ω|².
double energy(const TableBall& b) {
  return 0.5 * length_squared(b.velocity) +
         0.2 * b.radius * b.radius * (length_squared(b.spin) + b.twist * b.twist);
}

// Angular momentum about the contact point over the mass, in the plane: (2/5)R²·ω + R·(−vy, vx).
Vec2 contact_momentum(const TableBall& b) {
  return b.spin * (0.4 * b.radius * b.radius) + Vec2{-b.velocity.y, b.velocity.x} * b.radius;
}

TEST(TableMotion, AStunShotRollsAtFiveSeventhsOfItsSpeedAfterTheTextbookTime) {
  const TableBall stun = ball({2.0, 0.0});
  ASSERT_EQ(table_state(stun), TableState::sliding);
  const double t = time_in_state(stun, kCloth);
  EXPECT_DOUBLE_EQ(t, 2.0 * 2.0 / (7.0 * 0.2 * 9.81));
  const TableStep end = evolve(stun, kCloth, t);
  EXPECT_NEAR(end.ball.velocity.x, 2.0 * 5.0 / 7.0, 1e-15);
  EXPECT_EQ(end.ball.velocity.y, 0.0);
  EXPECT_EQ(table_state(end.ball), TableState::rolling);
  // Displacement under constant deceleration μs·g: v·t − ½μs·g·t².
  EXPECT_NEAR(end.displacement.x, 2.0 * t - 0.5 * 0.2 * 9.81 * t * t, 1e-15);
}

TEST(TableMotion, ARollingBallStopsAfterTheTextbookDistance) {
  const Vec2 v{0.6, -0.8};  // speed 1
  const TableBall rolling = ball(v, {0.8 / kRadius, 0.6 / kRadius});
  ASSERT_EQ(table_state(rolling), TableState::rolling);
  const double t = time_in_state(rolling, kCloth);
  EXPECT_DOUBLE_EQ(t, 1.0 / (0.01 * 9.81));
  const TableStep end = evolve(rolling, kCloth, t);
  EXPECT_EQ(end.ball.velocity, (Vec2{}));
  EXPECT_EQ(table_state(end.ball), TableState::stationary);
  EXPECT_NEAR(length(end.displacement), 1.0 / (2.0 * 0.01 * 9.81), 1e-12);
  // Halfway through, still rolling without slipping.
  EXPECT_EQ(table_state(evolve(rolling, kCloth, 0.5 * t).ball), TableState::rolling);
}

TEST(TableMotion, ASpinInPlaceStopsAtTheClosedFormTime) {
  const TableBall spinning = ball({}, {}, 30.0);
  ASSERT_EQ(table_state(spinning), TableState::spinning);
  const double t = time_in_state(spinning, kCloth);
  EXPECT_DOUBLE_EQ(t, 2.0 * kRadius * 30.0 / (5.0 * 0.044 * 9.81));
  EXPECT_EQ(evolve(spinning, kCloth, t).ball.twist, 0.0);
  EXPECT_NEAR(evolve(spinning, kCloth, 0.5 * t).ball.twist, 15.0, 1e-12);
  EXPECT_EQ(table_state(evolve(spinning, kCloth, t).ball), TableState::stationary);
}

TEST(TableMotion, ACentreStrikeGivesTheMomentumOfAnElasticImpactAndNoSpin) {
  // A level cue of mass M at V through the centre: J = (1 + e)·V / (1/M + 1/m).
  const double m = 0.17;
  const TableBall b = strike({2.0, 0.3, 0.0, 0.0, 0.0, 0.54, 0.8}, m, kRadius);
  const double j = 1.8 * 2.0 / (1.0 / 0.54 + 1.0 / m);
  EXPECT_NEAR(b.velocity.x, j / m * std::cos(0.3), 1e-14);
  EXPECT_NEAR(b.velocity.y, j / m * std::sin(0.3), 1e-14);
  EXPECT_EQ(b.twist, 0.0);
  EXPECT_NEAR(length(b.spin), 0.0, 1e-12);
  EXPECT_EQ(table_state(b), TableState::sliding);  // a stun shot
}

TEST(TableMotion, AStrikeTwoFifthsOfTheRadiusAboveTheCentreRollsAtOnce) {
  // The natural roll: R·ω = v when height = I/(m·R) = 2R/5.
  const TableBall b = strike({3.0, 1.1, 0.0, 0.0, 0.4 * kRadius}, 0.17, kRadius);
  EXPECT_NEAR(length(contact_velocity(b)), 0.0, 1e-12 * length(b.velocity));
  // Higher: follow (the contact point slips backwards); lower: draw.
  const TableBall follow = strike({3.0, 0.0, 0.0, 0.0, 0.6 * kRadius}, 0.17, kRadius);
  const TableBall draw = strike({3.0, 0.0, 0.0, 0.0, -0.5 * kRadius}, 0.17, kRadius);
  EXPECT_LT(contact_velocity(follow).x, 0.0);
  EXPECT_GT(contact_velocity(draw).x, draw.velocity.x);
  // Right of centre turns the ball counter-clockwise seen from above; left, clockwise.
  EXPECT_GT(strike({3.0, 0.0, 0.0, 0.5 * kRadius, 0.0}, 0.17, kRadius).twist, 0.0);
  EXPECT_LT(strike({3.0, 0.0, 0.0, -0.5 * kRadius, 0.0}, 0.17, kRadius).twist, 0.0);
}

TEST(TableMotion, RandomStrikesNeverMakeEnergyAndKeepTheImpulsesLever) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double m = 0.17;
  const double inertia = 0.4 * m * kRadius * kRadius;
  for (int k = 0; k < 2000; ++k) {
    CueStrike cue;
    cue.speed = 4.0 * (1.0 + unit(random));
    cue.direction = 3.2 * unit(random);
    cue.elevation = 0.7 * (1.0 + unit(random));
    cue.side = 0.6 * kRadius * unit(random);
    cue.height = 0.6 * kRadius * unit(random);
    cue.restitution = k % 2 == 0 ? 1.0 : 0.5 + 0.5 * unit(random);
    const TableBall b = strike(cue, m, kRadius);
    // The impulse J, from the speed: |v| = J·cos(elevation)/m.
    const double j = length(b.velocity) * m / std::cos(cue.elevation);
    // Energy: the ball's and the cue's after the strike are at most the cue's before.
    const double cue_after = cue.speed - j / cue.cue_mass;
    const double after = 0.5 * m * length_squared(b.velocity) +
                         0.5 * inertia * (length_squared(b.spin) + b.twist * b.twist) +
                         0.5 * cue.cue_mass * cue_after * cue_after;
    EXPECT_LE(after, 0.5 * cue.cue_mass * cue.speed * cue.speed * (1.0 + 1e-12)) << "strike " << k;
    // The spin is the impulse's moment about the centre over I: |ω| = J·√(side² + height²)/I.
    const double lever = std::sqrt(cue.side * cue.side + cue.height * cue.height);
    EXPECT_NEAR(std::sqrt(length_squared(b.spin) + b.twist * b.twist), j * lever / inertia,
                1e-9 * (1.0 + j * lever / inertia))
        << "strike " << k;
  }
}

// The angle of the struck ball's velocity from the line of centres.
double throw_angle(Vec2 velocity, Vec2 normal) {
  return std::atan2(cross(normal, velocity), dot(normal, velocity));
}

TEST(TableMotion, AStunShotThrowsTheObjectBallByTheFrictionsClosedForm) {
  // A cue ball sliding without spin at v meets a ball at rest at cut angle φ (the line of
  // centres φ from its path), e = 1, ball friction μ. The slip at the contact is v·sin φ across the
  // line and the normal impulse v·cos φ: the friction slides throughout when sin φ / 7 > μ·cos φ,
  // throwing the object ball atan(μ) off the line; below that it sticks, at atan(tan φ / 7).
  const double mu = 0.06;
  for (const double cut : {0.5236, 0.0873}) {
    TableBall cue = ball({1.0, 0.0});
    TableBall object = ball({});
    const Vec2 normal{std::cos(cut), -std::sin(cut)};  // the object ball lies right of the path
    collide_on_table(cue, object, normal, 1.0, mu);
    const double sliding = std::atan(mu);
    const double sticking = std::atan(std::tan(cut) / 7.0);
    // Thrown towards the cue ball's path (anticlockwise from a normal that points right of it).
    EXPECT_NEAR(throw_angle(object.velocity, normal), std::min(sliding, sticking), 1e-12)
        << "cut " << cut;
    // Both balls turn the same way (friction on each surface), and momentum is kept.
    EXPECT_NEAR(cue.velocity.x + object.velocity.x, 1.0, 1e-15);
    EXPECT_NEAR(cue.velocity.y + object.velocity.y, 0.0, 1e-15);
    EXPECT_EQ(cue.twist, object.twist);
  }
}

TEST(TableMotion, AHeadOnHitWithoutSpinExchangesVelocitiesAndSpinsNothing) {
  TableBall cue = ball({2.0, 0.0});
  TableBall object = ball({});
  collide_on_table(cue, object, {1.0, 0.0}, 1.0, 0.06);
  EXPECT_EQ(cue.velocity, (Vec2{}));
  EXPECT_EQ(object.velocity, (Vec2{2.0, 0.0}));
  EXPECT_EQ(object.spin, (Vec2{}));
  EXPECT_EQ(object.twist, 0.0);
}

TEST(TableMotion, RandomBallCollisionsKeepMomentumAndNeverMakeEnergy) {
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    TableBall a = ball({3.0 * unit(random), 3.0 * unit(random)},
                       {100.0 * unit(random), 100.0 * unit(random)}, 50.0 * unit(random));
    TableBall b = ball({unit(random), unit(random)}, {20.0 * unit(random), 20.0 * unit(random)},
                       10.0 * unit(random));
    const double angle = 3.2 * unit(random);
    const Vec2 normal{std::cos(angle), std::sin(angle)};
    const Vec2 momentum = a.velocity + b.velocity;
    const double before = energy(a) + energy(b);
    const double e = 0.9 + 0.1 * unit(random);
    const bool approaching = dot(a.velocity - b.velocity, normal) > 0.0;
    collide_on_table(a, b, normal, e, 0.06);
    EXPECT_NEAR((a.velocity + b.velocity).x, momentum.x, 1e-12) << "pair " << k;
    EXPECT_NEAR((a.velocity + b.velocity).y, momentum.y, 1e-12) << "pair " << k;
    EXPECT_LE(energy(a) + energy(b), before * (1.0 + 1e-12)) << "pair " << k;
    // After an approach they part (or move together) along the normal.
    if (approaching) {
      EXPECT_LE(dot(a.velocity - b.velocity, normal), 1e-12) << "pair " << k;
    }
  }
}

TEST(TableMotion, RandomShotsKeepTheContactMomentumLoseEnergyAndPassThroughEachState) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    // Speeds to 5 m/s, spins (top, back, side) to what a cue tip gives, English to 50 rad/s.
    TableBall b = ball({5.0 * unit(random), 5.0 * unit(random)},
                       {150.0 * unit(random), 150.0 * unit(random)}, 50.0 * unit(random));
    if (table_state(b) != TableState::sliding) continue;
    // Through the slide: the angular momentum about the contact point is kept (friction acts
    // there), and the ball rolls at v − 2/7·u.
    const Vec2 u0 = contact_velocity(b);
    const Vec2 momentum = contact_momentum(b);
    const double slide = time_in_state(b, kCloth);
    const TableStep rolled = evolve(b, kCloth, slide);
    const Vec2 after = contact_momentum(rolled.ball);
    const double scale = length(momentum) + kRadius * 5.0;
    EXPECT_NEAR(after.x, momentum.x, 1e-12 * scale) << "shot " << k;
    EXPECT_NEAR(after.y, momentum.y, 1e-12 * scale) << "shot " << k;
    const Vec2 expected = b.velocity - u0 * (2.0 / 7.0);
    EXPECT_NEAR(rolled.ball.velocity.x, expected.x, 1e-12) << "shot " << k;
    EXPECT_NEAR(rolled.ball.velocity.y, expected.y, 1e-12) << "shot " << k;
    // Then each state to the next, the energy falling at every sample on the way.
    double last = energy(b);
    int states = 0;
    for (TableBall now = b; table_state(now) != TableState::stationary && states < 5; ++states) {
      const double span = time_in_state(now, kCloth);
      ASSERT_TRUE(std::isfinite(span) && span >= 0.0) << "shot " << k;
      for (int s = 1; s <= 8; ++s) {
        const double e = energy(evolve(now, kCloth, span * s / 8.0).ball);
        EXPECT_LE(e, last * (1.0 + 1e-12) + 1e-15) << "shot " << k;
        last = e;
      }
      const TableState before = table_state(now);
      now = evolve(now, kCloth, span).ball;
      EXPECT_NE(table_state(now), before) << "shot " << k;
    }
    EXPECT_LE(states, 3) << "shot " << k;  // sliding, rolling, spinning at most
  }
}

// Without friction the cushion's impulse runs through the centre: the spin is untouched and the
// normal speed becomes vn·(1 − (1 + e)·cos²θ) (−e·vn where the nose is at the equator), or 0
// where that would still go into the cushion.
TEST(TableMotion, AFrictionlessCushionBouncesByTheNosesAngleAndTurnsNoSpin) {
  for (const double height : {0.5, 0.635, 0.9}) {
    TableBall b = ball({2.0, 0.5}, {3.0, -4.0}, 7.0);
    const Cushion cushion{height, 0.8, 0.0};
    const double sine = 2.0 * height - 1.0;
    const double cosine_squared = 1.0 - sine * sine;
    const double change = cushion_bounce(b, {1.0, 0.0}, cushion);
    // (At 0.9 the nose pushes mostly down: the cushion's face stops the rest of the approach.)
    const double after = std::min(2.0 * (1.0 - 1.8 * cosine_squared), 0.0);
    EXPECT_NEAR(b.velocity.x, after, 1e-14) << height;
    EXPECT_NEAR(change, 2.0 - after, 1e-14) << height;
    EXPECT_EQ(b.velocity.y, 0.5) << height;
    EXPECT_EQ(b.spin, (Vec2{3.0, -4.0})) << height;
    EXPECT_EQ(b.twist, 7.0) << height;
  }
}

// A rolling ball sent square into a cushion above its equator: friction at the nose takes topspin
// off it, and it leaves moving away.
TEST(TableMotion, ACushionAboveTheEquatorCutsARollingBallsTopspin) {
  TableBall b = ball({1.0, 0.0}, {0.0, 1.0 / kRadius});
  cushion_bounce(b, {1.0, 0.0}, Cushion{});
  EXPECT_LT(b.velocity.x, 0.0);
  EXPECT_LT(b.spin.y, 1.0 / kRadius);
  EXPECT_NEAR(b.velocity.y, 0.0, 1e-15);
}

TEST(TableMotion, RandomCushionBouncesNeverMakeEnergy) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    TableBall b = ball({3.0 * unit(random), 3.0 * unit(random)},
                       {150.0 * unit(random), 150.0 * unit(random)}, 80.0 * unit(random));
    const double angle = 3.2 * unit(random);
    const Vec2 normal{std::cos(angle), std::sin(angle)};
    const Cushion cushion{0.75 + 0.24 * unit(random), 0.5 + 0.5 * std::abs(unit(random)),
                          0.4 * std::abs(unit(random))};
    const double before = energy(b);
    const double approach = dot(b.velocity, normal);
    const double change = cushion_bounce(b, normal, cushion);
    EXPECT_LE(energy(b), before * (1.0 + 1e-12)) << "bounce " << k;
    if (approach > 0.0) {
      EXPECT_NEAR(dot(b.velocity, normal), approach - change, 1e-12) << "bounce " << k;
      EXPECT_LE(dot(b.velocity, normal), 1e-12) << "bounce " << k;
    } else {
      EXPECT_EQ(change, 0.0) << "bounce " << k;
    }
  }
}

// Held: both roll on at their momentum-weighted common velocity, momentum kept, energy lost.
TEST(TableMotion, APairHeldTogetherRollsOnAtItsCommonVelocity) {
  std::mt19937_64 random(19);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    TableBall a = ball({unit(random), unit(random)}, {50.0 * unit(random), 50.0 * unit(random)});
    TableBall b = ball({unit(random), unit(random)}, {50.0 * unit(random), 50.0 * unit(random)});
    a.mass = 1.0 + std::abs(unit(random));
    b.mass = 1.0 + std::abs(unit(random));
    // The slides' ends first (v − 2/7·u), then the common velocity.
    const Vec2 momentum = (a.velocity - contact_velocity(a) * (2.0 / 7.0)) * a.mass +
                          (b.velocity - contact_velocity(b) * (2.0 / 7.0)) * b.mass;
    const double before = a.mass * energy(a) + b.mass * energy(b);
    roll_together(a, b);
    EXPECT_EQ(a.velocity, b.velocity) << k;
    const Vec2 after = a.velocity * a.mass + b.velocity * b.mass;
    EXPECT_NEAR(after.x, momentum.x, 1e-12) << k;
    EXPECT_NEAR(after.y, momentum.y, 1e-12) << k;
    EXPECT_LE(a.mass * energy(a) + b.mass * energy(b), before * (1.0 + 1e-12)) << k;
    EXPECT_EQ(table_state(a), TableState::rolling) << k;
  }
}

}  // namespace table_motion_tests
}  // namespace carom::detail
