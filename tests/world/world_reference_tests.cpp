// The World against the brute-force oracle (reference_simulator.hpp) on random scenes: the same
// contacts (balls, walls, kind), in the same order, at the same times.
//
// Why most comparisons re-synchronise the oracle. A gas of hard balls is chaotic: each contact
// multiplies a difference in the balls' state by up to the free path over the radius (and a
// near-graze by far more). The World and the oracle round differently (the World keeps each ball
// at its own local time; the oracle moves every ball at every contact), so starting from one-ulp
// differences, two correct simulators measured here drift apart by 1e-10 relative within about a
// hundred contacts of the scenes below, and follow different histories soon after. Comparing
// whole runs to 1e-9 is therefore only sound over a few dozen contacts (WholeRunAcrossCalls).
// The long comparisons instead restart the oracle from the World's own state before every
// contact (ContactByContact: world.run_collisions(1)) or every short step (StepByStep), so each
// comparison carries the rounding of one prediction (or a few) only, and any real difference — a
// missed, extra, misordered or mistimed contact, a wrong bounce — shows where it happens.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "carom/error.hpp"
#include "carom/world.hpp"
#include "long_tests.hpp"
#include "world/random_scene.hpp"
#include "world/reference_simulator.hpp"
#include "world/scene_world.hpp"

namespace carom {
namespace {

using testing::BoxAs;
using testing::GasOptions;
using testing::ReferenceScene;
using testing::ReferenceSimulator;
using testing::SceneWorld;
using testing::Tolerances;

constexpr double kReferenceStep = 1.0 / 60.0;
// Speeds up to 100 diameters per step, as docs/guarantees.md promises.
constexpr double kDiametersPerStep = 100.0;

// Times agree to 1e-9 relative (docs/guarantees.md, section 1), measured against max(|t|,
// kReferenceStep). One prediction from identical states carries ~1e-15 relative (a handful of
// roundings, times the conditioning of the contact's quadratic); 1e-9 leaves room for near-grazes.
// Measured on these scenes: at most 2e-15 contact by contact and step by step, 2e-13 over the whole
// run.
constexpr double kTimeTol = 1e-9;
// Velocities, approach speeds and normals: the same 1e-9, relative to the scene's top speed
// (measured: at most 6e-13 step by step, 3e-12 over the whole run).
constexpr double kSpeedTol = 1e-9;
// Positions: 1e-9 of the scene's side (positions are O(side), each rounding ~1e-16 of it).
constexpr double kPositionTol = 1e-9;

// How far ahead the oracle looks for the next contact in a contact-by-contact comparison: every
// scene here has a contact far sooner (its balls cross the box within a few steps).
constexpr double kNextContactHorizonSteps = 1000.0;

using testing::long_tests_enabled;

GasOptions fast_gas(std::size_t ball_count, double side, bool periodic) {
  GasOptions options;
  options.ball_count = ball_count;
  options.side = side;
  options.periodic = periodic;
  options.max_speed = kDiametersPerStep * 2.0 * options.max_radius / kReferenceStep;
  return options;
}

Tolerances tolerances_for(const GasOptions& options) {
  Tolerances tolerances;
  tolerances.time = kTimeTol;
  tolerances.time_scale = kReferenceStep;
  tolerances.speed = kSpeedTol;
  tolerances.speed_scale = options.max_speed;
  tolerances.position = kPositionTol * options.side;
  return tolerances;
}

// Before every World contact, restarts the oracle from the World's state and checks that the
// World's next contact is the oracle's, and that both leave every ball in the same state.
void expect_contact_by_contact(SceneWorld& built, const ReferenceScene& scene,
                               std::size_t contact_count, const Tolerances& tolerances) {
  for (std::size_t k = 0; k < contact_count; ++k) {
    ReferenceSimulator reference(testing::scene_at_world_time(scene, built));
    const std::size_t expected =
        reference.run_collisions(1, built.world.time() + kNextContactHorizonSteps * kReferenceStep);
    ASSERT_EQ(expected, 1u) << "the oracle finds no next contact after " << k;
    ASSERT_EQ(built.world.run_collisions(1), 1u) << "contact " << k;
    ASSERT_TRUE(
        testing::same_contacts(built.world.contacts(), built.ids, reference.contacts(), tolerances))
        << "contact " << k << " of the run";
    ASSERT_TRUE(testing::same_state(built, reference, scene, tolerances))
        << "after contact " << k << " of the run";
  }
}

// Restarts the oracle from the World's state before every step of dt.
void expect_step_by_step(SceneWorld& built, const ReferenceScene& scene, double dt, int steps,
                         const Tolerances& tolerances, std::size_t& contacts_seen) {
  for (int s = 0; s < steps; ++s) {
    ReferenceSimulator reference(testing::scene_at_world_time(scene, built));
    reference.run_until(built.world.time() + dt);
    built.world.step(dt);
    ASSERT_TRUE(
        testing::same_contacts(built.world.contacts(), built.ids, reference.contacts(), tolerances))
        << "step " << s;
    ASSERT_TRUE(testing::same_state(built, reference, scene, tolerances)) << "after step " << s;
    contacts_seen += reference.contacts().size();
  }
}

// ---- contact by contact ----------------------------------------------------------------------

constexpr std::size_t kContactsCompared = 600;

TEST(WorldReference, BoxGasContactByContact) {
  const GasOptions options = fast_gas(120, 60.0, false);
  const ReferenceScene scene = testing::random_gas(options, 101);
  SceneWorld built = testing::build_world(scene);
  expect_contact_by_contact(built, scene, kContactsCompared, tolerances_for(options));
}

TEST(WorldReference, PeriodicGasContactByContact) {
  const GasOptions options = fast_gas(120, 60.0, true);
  const ReferenceScene scene = testing::random_gas(options, 102);
  SceneWorld built = testing::build_world(scene);
  expect_contact_by_contact(built, scene, kContactsCompared, tolerances_for(options));
}

TEST(WorldReference, BoxBoundaryGasContactByContact) {
  const GasOptions options = fast_gas(120, 60.0, false);
  const ReferenceScene scene = testing::random_gas(options, 103);
  SceneWorld built = testing::build_world(scene, BoxAs::boundary);
  expect_contact_by_contact(built, scene, kContactsCompared, tolerances_for(options));
}

// Unequal masses, immovable posts and mixed restitutions: this one depends on the rule that
// combines two balls' restitutions (testing::combined_restitution, the smaller of the two).
TEST(WorldReference, MixedMassesRestitutionsAndPostsContactByContact) {
  GasOptions options = fast_gas(120, 60.0, false);
  options.min_mass = 0.1;
  options.max_mass = 10.0;
  options.restitutions = {1.0, 0.9, 0.6, 0.3};
  options.immovable_fraction = 0.1;
  const ReferenceScene scene = testing::random_gas(options, 104);
  SceneWorld built = testing::build_world(scene);
  expect_contact_by_contact(built, scene, kContactsCompared, tolerances_for(options));
}

// An open world fenced by a rotated hexagon, with arcs (whole circles, bowls and short arcs) and
// short segments at arbitrary angles standing on some of the grid's sites.
ReferenceScene angled_walls_scene(std::uint64_t seed, GasOptions& options) {
  constexpr int kSitesPerRow = 10;
  constexpr double kHexagonTurn = 0.3;  // radians: no wall is axis-aligned
  constexpr int kObstacleEvery = 4;     // every 4th site holds an obstacle instead of a ball
  options = fast_gas(kSitesPerRow * kSitesPerRow, 60.0, false);
  ReferenceScene gas = testing::random_gas(options, seed);
  std::mt19937_64 engine(seed);
  auto uniform = [&engine](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine);
  };

  ReferenceScene scene;
  // A regular hexagon around the square [0, side]²: its inner radius, R·cos 30°, exceeds the
  // square's half-diagonal, so every ball of the gas starts inside it.
  const Vec2 centre{0.5 * options.side, 0.5 * options.side};
  const double circumradius = 1.05 * options.side / std::sqrt(2.0) / std::cos(std::numbers::pi / 6);
  for (int k = 0; k < 6; ++k) {
    const double a0 = kHexagonTurn + k * std::numbers::pi / 3;
    const double a1 = kHexagonTurn + (k + 1) * std::numbers::pi / 3;
    scene.walls.push_back(
        testing::segment_wall({centre + Vec2{std::cos(a0), std::sin(a0)} * circumradius,
                               centre + Vec2{std::cos(a1), std::sin(a1)} * circumradius}));
  }
  const double spacing = options.side / kSitesPerRow;
  // Obstacles fit in their site with the same clearance random_gas keeps for balls.
  const double obstacle_radius = 0.5 * spacing * 0.9;
  for (std::size_t i = 0; i < gas.balls.size(); ++i) {
    if (i % kObstacleEvery != 1) {
      scene.balls.push_back(gas.balls[i]);
      continue;
    }
    const Vec2 site{(static_cast<double>(i % kSitesPerRow) + 0.5) * spacing,
                    (static_cast<double>(i / kSitesPerRow) + 0.5) * spacing};
    const double start = uniform(-std::numbers::pi, std::numbers::pi);
    switch ((i / kObstacleEvery) % 4) {
      case 0:  // a whole circle: a round bumper. From angle 0, as start + 2π − start can
               // round above 2π, which the span check refuses.
        scene.walls.push_back(
            testing::arc_wall({site, obstacle_radius, 0.0, 2.0 * std::numbers::pi}));
        break;
      case 1:  // a half circle: a bowl balls can enter
        scene.walls.push_back(
            testing::arc_wall({site, obstacle_radius, start, start + std::numbers::pi}));
        break;
      case 2:  // a short arc: mostly its end points are met
        scene.walls.push_back(testing::arc_wall({site, obstacle_radius, start, start + 0.7}));
        break;
      default: {  // a segment at an arbitrary angle through the site
        const Vec2 half = Vec2{std::cos(start), std::sin(start)} * obstacle_radius;
        scene.walls.push_back(testing::segment_wall({site - half, site + half}));
      }
    }
  }
  return scene;
}

TEST(WorldReference, AngledWallsAndArcsContactByContact) {
  GasOptions options;
  const ReferenceScene scene = angled_walls_scene(105, options);
  SceneWorld built = testing::build_world(scene);
  expect_contact_by_contact(built, scene, kContactsCompared, tolerances_for(options));
}

// Inelastic balls in a round bowl: their bounces off the wall flatten until they slide round
// it, where both the World and the oracle bounce them by bounce_inside_arc (sliding: elastic,
// never leaving flatter than kBowlLeavingSine). Most of the contacts compared are sliding ones.
TEST(WorldReference, InelasticBallsSlidingRoundABowlContactByContact) {
  ReferenceScene scene;
  scene.walls.push_back(testing::arc_wall({{0.0, 0.0}, 10.0, 0.0, 2.0 * std::numbers::pi}));
  for (int k = 0; k < 6; ++k) {
    testing::ReferenceBall ball;
    const double angle = k * std::numbers::pi / 3.0;
    ball.position = Vec2{std::cos(angle), std::sin(angle)} * 4.0;
    ball.velocity = Vec2{std::cos(1.7 * k + 0.3), std::sin(1.7 * k + 0.3)} * (3.0 + k);
    ball.radius = 0.5;
    ball.restitution = 0.3;
    scene.balls.push_back(ball);
  }
  SceneWorld built = testing::build_world(scene);
  GasOptions options;
  options.side = 20.0;
  options.max_speed = 8.0;
  expect_contact_by_contact(built, scene, kContactsCompared, tolerances_for(options));
}

// A fast gas of 80 balls in a box, changed between runs: each round `change` alters the World
// and the oracle's scene alike (drawing from `uniform`), then the next 30 contacts are compared
// one by one, then a plain step follows.
struct ChangedGas {
  static constexpr std::size_t kContactsPerRound = 30;
  GasOptions options = fast_gas(80, 60.0, false);
  ReferenceScene scene;
  SceneWorld built;
  std::mt19937_64 engine;

  explicit ChangedGas(std::uint64_t seed)
      : scene(testing::random_gas(options, seed)),
        built(testing::build_world(scene)),
        engine(seed) {}
  double uniform(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine);
  }
  template <class Change>
  void run_rounds(int rounds, Change change) {
    for (int round = 0; round < rounds; ++round) {
      SCOPED_TRACE("round " + std::to_string(round));
      change(round);
      ASSERT_FALSE(built.world.audit().has_value());
      expect_contact_by_contact(built, scene, kContactsPerRound, tolerances_for(options));
      if (::testing::Test::HasFatalFailure()) return;
      built.world.step(0.5 * kReferenceStep);
    }
  }
};

// Between runs a game moves, pushes, removes and adds balls; the World must forget every
// prediction those changes spoil.
TEST(WorldReference, ChangesBetweenRunsContactByContact) {
  ChangedGas gas(109);
  SceneWorld& built = gas.built;
  auto pick = [&gas]() {
    return std::uniform_int_distribution<std::size_t>(0, gas.built.ids.size() - 1)(gas.engine);
  };
  auto random_velocity = [&gas] {
    const double angle = gas.uniform(0.0, 2.0 * std::numbers::pi);
    return Vec2{std::cos(angle), std::sin(angle)} * gas.uniform(0.0, gas.options.max_speed);
  };
  const double side = gas.options.side;
  gas.run_rounds(20, [&](int) {
    // A push, a drag to wherever it can go, a removal and an addition. (One random draw per
    // statement: the order function arguments are evaluated in is unspecified.)
    const std::size_t pushed = pick();
    const Vec2 push = random_velocity();
    built.world.set_velocity(built.ids[pushed], push);
    const std::size_t dragged = pick();
    const Vec2 target{gas.uniform(1.0, side - 1.0), gas.uniform(1.0, side - 1.0)};
    static_cast<void>(
        built.world.set_position(built.ids[dragged], target, Placement::nearest_free));
    const std::size_t removed = pick();
    built.world.remove_ball(built.ids[removed]);
    built.ids.erase(built.ids.begin() + static_cast<std::ptrdiff_t>(removed));
    gas.scene.balls.erase(gas.scene.balls.begin() + static_cast<std::ptrdiff_t>(removed));
    testing::ReferenceBall added;
    added.radius = gas.options.max_radius;
    added.velocity = random_velocity();
    for (;;) {  // a free place: add_ball refuses an overlapping one
      added.position = {gas.uniform(1.0, side - 1.0), gas.uniform(1.0, side - 1.0)};
      BallDef def;
      def.position = added.position;
      def.velocity = added.velocity;
      def.radius = added.radius;
      def.mass = added.mass;
      def.restitution = added.restitution;
      try {
        const BallId id = built.world.add_ball(def);
        // The slot freed just before is reused: the new ball takes the removed one's place in
        // slot order, which is where the oracle's order must put it too.
        std::size_t at = 0;
        while (at < built.ids.size() && built.ids[at].index < id.index) ++at;
        built.ids.insert(built.ids.begin() + static_cast<std::ptrdiff_t>(at), id);
        gas.scene.balls.insert(gas.scene.balls.begin() + static_cast<std::ptrdiff_t>(at), added);
        break;
      } catch (const InvalidArgument&) {
      }
    }
  });
}

// Walls added between runs: each round a segment at an arbitrary angle or an arc, standing where
// no ball touches it, goes into the World and the oracle alike. The World re-predicts only the
// balls in the cells the wall is listed in; the next contacts must still be the oracle's (fast
// balls meet the new walls within a few contacts).
TEST(WorldReference, WallsAddedBetweenRunsContactByContact) {
  ChangedGas gas(113);
  SceneWorld& built = gas.built;
  const double side = gas.options.side;
  gas.run_rounds(24, [&](int round) {
    // The wall lies within `reach` of its site: a free site is one no ball comes within reach of.
    const double reach = gas.uniform(0.5, 3.0);
    Vec2 site;
    for (bool free = false; !free;) {
      site = {gas.uniform(reach, side - reach), gas.uniform(reach, side - reach)};
      free = true;
      for (const BallId id : built.ids) {
        free = free && length(built.world.position(id) - site) > reach + built.world.radius(id);
      }
    }
    const double angle = gas.uniform(-std::numbers::pi, std::numbers::pi);
    if (round % 2 == 0) {
      const Vec2 half = Vec2{std::cos(angle), std::sin(angle)} * reach;
      const Segment segment{site - half, site + half};
      built.world.add_segment(segment);
      gas.scene.walls.push_back(testing::segment_wall(segment));
    } else {
      const double span = gas.uniform(0.5, 2.0 * std::numbers::pi - 0.1);
      const Arc arc{site, reach, angle, angle + span};
      built.world.add_arc(arc);
      gas.scene.walls.push_back(testing::arc_wall(arc));
    }
  });
}

// ---- step by step ----------------------------------------------------------------------------

// Steps of a sixteenth of kReferenceStep over a sparse gas: one or two contacts per step, so that
// no chain of contacts inside a step amplifies the two simulators' rounding differences (see the
// top of the file; with whole steps of kReferenceStep, measured differences reach 3e-10 of the time
// within one step). Many step ends, each with balls in flight at up to 100 diameters per
// kReferenceStep.
constexpr int kSubsteps = 16;
constexpr double kSubstep = kReferenceStep / kSubsteps;
constexpr int kStepsCompared = 20 * kSubsteps;

TEST(WorldReference, BoxGasStepByStep) {
  const GasOptions options = fast_gas(50, 200.0, false);
  const ReferenceScene scene = testing::random_gas(options, 106);
  SceneWorld built = testing::build_world(scene);
  std::size_t contacts = 0;
  expect_step_by_step(built, scene, kSubstep, kStepsCompared, tolerances_for(options), contacts);
  EXPECT_GT(contacts, 300u);  // the comparison must have met a fair number of contacts
}

TEST(WorldReference, PeriodicGasStepByStep) {
  const GasOptions options = fast_gas(50, 120.0, true);
  const ReferenceScene scene = testing::random_gas(options, 107);
  SceneWorld built = testing::build_world(scene);
  std::size_t contacts = 0;
  expect_step_by_step(built, scene, kSubstep, kStepsCompared, tolerances_for(options), contacts);
  EXPECT_GT(contacts, 200u);
}

// ---- one whole run, World contacts accumulated over many calls -------------------------------

// Short enough that the chaos described at the top of the file stays far below the tolerance.
TEST(WorldReference, WholeRunAcrossCalls) {
  const GasOptions options = fast_gas(50, 200.0, false);
  const ReferenceScene scene = testing::random_gas(options, 108);
  SceneWorld built = testing::build_world(scene);
  std::vector<ContactEvent> world_contacts;

  // Every way of advancing, one after the other.
  built.world.step(0.5 * kReferenceStep);
  testing::append_contacts(built.world, world_contacts);
  built.world.run_until(built.world.time() + 0.25 * kReferenceStep);
  testing::append_contacts(built.world, world_contacts);
  ASSERT_EQ(built.world.run_collisions(5), 5u);
  testing::append_contacts(built.world, world_contacts);
  for (int i = 0; i < 10; ++i) {
    built.world.step(0.1 * kReferenceStep);
    testing::append_contacts(built.world, world_contacts);
  }
  built.world.run_until(2.0 * kReferenceStep);
  testing::append_contacts(built.world, world_contacts);

  ReferenceSimulator reference(scene);
  reference.run_until(2.0 * kReferenceStep);
  ASSERT_GT(reference.contacts().size(), 20u);
  EXPECT_TRUE(testing::same_contacts(world_contacts, built.ids, reference.contacts(),
                                     tolerances_for(options)));
  EXPECT_TRUE(testing::same_state(built, reference, scene, tolerances_for(options)));
}

// ---- under gravity -----------------------------------------------------------------------------
//
// The same comparisons with WorldDef::gravity set: movable balls on parabolas, the oracle asking
// the core's accelerated queries (carom::Motion) for every candidate contact. The balls are
// elastic throughout, so none ever comes to rest: the oracle refuses resting contacts (see
// ReferenceScene::gravity), and the scenes keep every contact a bounce.
//
// Tolerances are those above. The accelerated queries find a closing time to the rounding of the
// gap polynomial (bisection with Newton steps, docs/derivation.md), so one prediction from
// identical states again carries only a few roundings; 1e-9 leaves room for near-grazes as
// before. Speeds grow as balls fall, so speeds and normals are measured against the top speed of
// the balls at the time (never below the scene's starting one). Measured on these scenes and on
// 300 more drawn like them (other seeds, gravity in every direction): times within 5e-14
// relative, normals, approach speeds and velocities within 1e-12, positions within 7e-13 of the
// side.

// build_world makes a World without gravity; gravity set at time 0 gives it the scene's, every
// ball keeping its start place and velocity.
SceneWorld build_world_under_gravity(const ReferenceScene& scene) {
  SceneWorld built = testing::build_world(scene);
  built.world.set_gravity(scene.gravity);
  return built;
}

double top_speed(const SceneWorld& built) {
  double top = 0.0;
  for (const BallId id : built.ids) top = std::max(top, length(built.world.velocity(id)));
  return top;
}

// expect_contact_by_contact, with the speed scale following the balls as gravity speeds them up.
void expect_contact_by_contact_under_gravity(SceneWorld& built, const ReferenceScene& scene,
                                             std::size_t contact_count, Tolerances tolerances) {
  const double starting_scale = tolerances.speed_scale;
  for (std::size_t k = 0; k < contact_count; ++k) {
    SCOPED_TRACE("contact " + std::to_string(k) + " under gravity");
    tolerances.speed_scale = std::max(starting_scale, top_speed(built));
    expect_contact_by_contact(built, scene, 1, tolerances);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

// expect_step_by_step, with the speed scale following the balls likewise.
void expect_step_by_step_under_gravity(SceneWorld& built, const ReferenceScene& scene, double dt,
                                       int steps, Tolerances tolerances,
                                       std::size_t& contacts_seen) {
  const double starting_scale = tolerances.speed_scale;
  for (int s = 0; s < steps; ++s) {
    SCOPED_TRACE("step " + std::to_string(s) + " under gravity");
    tolerances.speed_scale = std::max(starting_scale, top_speed(built));
    expect_step_by_step(built, scene, dt, 1, tolerances, contacts_seen);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

Tolerances gravity_tolerances(double side, double speed_scale) {
  Tolerances tolerances;
  tolerances.time = kTimeTol;
  tolerances.time_scale = kReferenceStep;
  tolerances.speed = kSpeedTol;
  tolerances.speed_scale = speed_scale;
  tolerances.position = kPositionTol * side;
  return tolerances;
}

constexpr Vec2 kEarthGravity{0.0, -9.81};
constexpr std::size_t kGravityContactsCompared = 3000;

// The oracle on its own first, against closed forms: a ball dropped from rest meets the floor at
// √(2h/g) with speed √(2gh), and bounces back up to the height it fell from.
TEST(WorldReference, GravityOracleDropsABallAtTheClosedFormTime) {
  ReferenceScene scene;
  for (const testing::ReferenceWall& wall : testing::box_walls({0.0, 0.0}, {10.0, 20.0})) {
    scene.walls.push_back(wall);
  }
  testing::ReferenceBall ball;
  ball.position = {5.0, 11.0};
  scene.balls.push_back(ball);  // radius 1: its centre falls 10 to the floor's contact
  scene.gravity = {0.0, -5.0};
  ReferenceSimulator reference(scene);
  reference.run_until(3.0);
  ASSERT_EQ(reference.contacts().size(), 1u);
  const testing::ReferenceContact& floor = reference.contacts()[0];
  EXPECT_EQ(floor.kind, ContactKind::ball_wall);
  EXPECT_EQ(floor.wall, 0u);
  EXPECT_NEAR(floor.time, 2.0, 1e-14);
  EXPECT_NEAR(floor.approach_speed, 10.0, 1e-13);
  // At t = 3 it has risen for 1 from the floor at speed 10: up 10 − 2.5.
  EXPECT_NEAR(reference.balls()[0].position.y, 1.0 + 7.5, 1e-12);
  EXPECT_NEAR(reference.balls()[0].velocity.y, 5.0, 1e-12);
}

// An elastic gas in a tall box: balls fly on parabolas, bounce off the floor and walls and off
// each other (whose relative motion stays linear).
TEST(WorldReference, GravityBoxGasContactByContact) {
  GasOptions options;
  options.ball_count = 36;
  options.side = 20.0;
  options.max_speed = 8.0;
  ReferenceScene scene = testing::random_gas(options, 201);
  scene.gravity = kEarthGravity;
  SceneWorld built = build_world_under_gravity(scene);
  expect_contact_by_contact_under_gravity(built, scene, kGravityContactsCompared,
                                          gravity_tolerances(options.side, options.max_speed));
}

// The same gas restarted from the World before each short step: step ends fall between contacts,
// where both must have moved every ball along the same parabola.
TEST(WorldReference, GravityBoxGasStepByStep) {
  GasOptions options;
  options.ball_count = 36;
  options.side = 20.0;
  options.max_speed = 8.0;
  ReferenceScene scene = testing::random_gas(options, 202);
  scene.gravity = kEarthGravity;
  SceneWorld built = build_world_under_gravity(scene);
  std::size_t contacts = 0;
  // Half steps over 4 time units: a contact or two a step, each step end in mid-flight.
  expect_step_by_step_under_gravity(built, scene, 0.5 * kReferenceStep, 480,
                                    gravity_tolerances(options.side, options.max_speed), contacts);
  EXPECT_GT(contacts, 150u);
}

// A small Galton board: elastic balls fall from the top of a box through rows of immovable pegs
// (against which a falling ball's gap is a quartic in time) onto the floor, and bounce back up.
ReferenceScene galton_board(Vec2 gravity) {
  constexpr double kWidth = 20.0;
  constexpr double kHeight = 30.0;
  constexpr double kPegRadius = 0.3;
  constexpr double kBallRadius = 0.4;
  ReferenceScene scene;
  scene.lower = {0.0, 0.0};
  scene.upper = {kWidth, kHeight};
  for (const testing::ReferenceWall& wall : testing::box_walls(scene.lower, scene.upper)) {
    scene.walls.push_back(wall);
  }
  scene.gravity = gravity;
  // Rows 2 apart, staggered by half the spacing: 1.4 between neighbouring pegs lets a ball of
  // diameter 0.8 through.
  for (int row = 0; row < 7; ++row) {
    for (int k = 0; k < 9; ++k) {
      testing::ReferenceBall peg;
      peg.position = {1.5 + 2.0 * k + (row % 2 == 1 ? 1.0 : 0.0), 8.0 + 2.0 * row};
      peg.radius = kPegRadius;
      peg.mass = kImmovable;
      scene.balls.push_back(peg);
    }
  }
  std::mt19937_64 engine(203);
  auto uniform = [&engine](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine);
  };
  for (int row = 0; row < 3; ++row) {
    for (int k = 0; k < 9; ++k) {
      testing::ReferenceBall ball;
      // Sites 2 apart with ±0.5 of jitter: at least 1 between centres, clear of the pegs' rows
      // (the top one at 20) and of the walls.
      ball.position = {1.5 + 2.0 * k + uniform(-0.5, 0.5), 23.0 + 2.0 * row + uniform(-0.5, 0.5)};
      ball.velocity = {uniform(-3.0, 3.0), uniform(-3.0, 3.0)};
      ball.radius = kBallRadius;
      ball.mass = uniform(0.5, 2.0);
      scene.balls.push_back(ball);
    }
  }
  return scene;
}

TEST(WorldReference, GravityGaltonBoardContactByContact) {
  const ReferenceScene scene = galton_board(kEarthGravity);
  SceneWorld built = build_world_under_gravity(scene);
  expect_contact_by_contact_under_gravity(built, scene, kGravityContactsCompared,
                                          gravity_tolerances(30.0, 3.0 * std::sqrt(2.0)));
}

// Columns of elastic balls of unequal masses dropped onto each other, two standing on immovable
// pegs and two on the floor, every centre on its column's vertical line: head-on contacts in
// quick succession (a ball squeezed between its neighbours meets them within a hop), exactly
// vertical normals, and against the pegs the quartic gap of a falling ball and a fixed one.
TEST(WorldReference, GravityColumnsOnPegsAndFloorContactByContact) {
  ReferenceScene scene;
  for (const testing::ReferenceWall& wall : testing::box_walls({0.0, 0.0}, {16.0, 30.0})) {
    scene.walls.push_back(wall);
  }
  scene.gravity = kEarthGravity;
  for (int column = 0; column < 4; ++column) {
    const double x = 2.0 + 4.0 * column;
    double top = 0.0;  // the highest point of what the column stands on
    if (column % 2 == 0) {
      testing::ReferenceBall peg;
      peg.position = {x, 3.0};
      peg.radius = 0.4;
      peg.mass = kImmovable;
      scene.balls.push_back(peg);
      top = 3.4;
    }
    double y = top + 0.5;
    for (int k = 0; k < 4; ++k) {
      testing::ReferenceBall ball;
      ball.radius = 0.5;
      ball.mass = 1.0 + 0.25 * k;
      // Gaps that differ from ball to ball and column to column, so no two contacts coincide.
      y += 1.0 + 0.3 * (k + 1) + 0.07 * column;
      ball.position = {x, y};
      scene.balls.push_back(ball);
    }
  }
  SceneWorld built = build_world_under_gravity(scene);
  expect_contact_by_contact_under_gravity(built, scene, kGravityContactsCompared,
                                          gravity_tolerances(30.0, 10.0));
}

// A round bowl (the lower half of a circle: its inside, its outside and its two end points) in a
// box, with tilted segments and a round bumper above it, and elastic balls dropped in.
ReferenceScene bowl_scene(Vec2 gravity, std::uint64_t seed) {
  ReferenceScene scene;
  scene.lower = {-12.0, -12.0};
  scene.upper = {12.0, 14.0};
  for (const testing::ReferenceWall& wall : testing::box_walls(scene.lower, scene.upper)) {
    scene.walls.push_back(wall);
  }
  scene.gravity = gravity;
  scene.walls.push_back(
      testing::arc_wall({{0.0, 0.0}, 10.0, std::numbers::pi, 2.0 * std::numbers::pi}));
  scene.walls.push_back(testing::segment_wall({{-7.0, 6.0}, {-2.5, 3.5}}));
  scene.walls.push_back(testing::segment_wall({{2.0, 8.5}, {7.5, 5.0}}));
  scene.walls.push_back(testing::segment_wall({{-9.0, 11.0}, {-5.0, 12.5}}));
  // A whole circle: a round bumper (from angle 0, as start + 2π − start can round above 2π).
  scene.walls.push_back(testing::arc_wall({{1.0, 2.0}, 1.2, 0.0, 2.0 * std::numbers::pi}));
  // An upside-down short arc: a cap balls meet from above and from below.
  scene.walls.push_back(testing::arc_wall({{-4.0, -3.0}, 1.5, 0.3, 2.6}));
  std::mt19937_64 engine(seed);
  auto uniform = [&engine](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine);
  };
  // Balls of radius 0.35 on sites 1.5 apart (±0.25 of jitter: at least 1 between centres) in the
  // bowl's lower middle, where nothing else stands: the farthest site reaches 9.7 from the
  // bowl's centre, inside its radius of 10, and the highest ball's top stays below −4, under the
  // cap (all of which lies above y = −3).
  for (int row = 0; row < 3; ++row) {
    for (int k = 0; k < 7; ++k) {
      testing::ReferenceBall ball;
      ball.position = {-4.5 + 1.5 * k + uniform(-0.25, 0.25),
                       -4.8 - 1.5 * row + uniform(-0.25, 0.25)};
      const double angle = uniform(0.0, 2.0 * std::numbers::pi);
      ball.velocity = Vec2{std::cos(angle), std::sin(angle)} * uniform(2.0, 12.0);
      ball.radius = 0.35;
      ball.mass = uniform(0.5, 2.0);
      scene.balls.push_back(ball);
    }
  }
  return scene;
}

TEST(WorldReference, GravityBowlAndAngledWallsContactByContact) {
  const ReferenceScene scene = bowl_scene(kEarthGravity, 204);
  SceneWorld built = build_world_under_gravity(scene);
  expect_contact_by_contact_under_gravity(built, scene, kGravityContactsCompared,
                                          gravity_tolerances(26.0, 12.0));
}

// The same with gravity pulling sideways and a little down: balls are flung over the bowl's right
// rim and its end point, onto the arc's outside and against the box's right wall.
TEST(WorldReference, SidewaysGravityBowlAndAngledWallsContactByContact) {
  const ReferenceScene scene = bowl_scene({9.0, -3.0}, 205);
  SceneWorld built = build_world_under_gravity(scene);
  expect_contact_by_contact_under_gravity(built, scene, kGravityContactsCompared,
                                          gravity_tolerances(26.0, 12.0));
}

// The hexagon of angled walls and arcs above, with its fast gas and a slanted gravity strong
// enough to bend every path: over the time a ball takes to cross the scene at its starting top
// speed, gravity alone would move it the scene's side.
TEST(WorldReference, SlantedGravityAngledWallsAndArcsContactByContact) {
  GasOptions options;
  ReferenceScene scene = angled_walls_scene(206, options);
  const double pull = 2.0 * options.max_speed * options.max_speed / options.side;
  scene.gravity = Vec2{0.6, -0.8} * pull;
  SceneWorld built = build_world_under_gravity(scene);
  expect_contact_by_contact_under_gravity(built, scene, kContactsCompared, tolerances_for(options));
}

// A periodic gas under gravity: no walls, balls fall through the cell's bottom into its top. Two
// movable balls still meet along a straight relative path, but every ball's motion through the
// grid (and its images) is a parabola.
TEST(WorldReference, GravityPeriodicGasContactByContact) {
  GasOptions options;
  options.ball_count = 100;
  options.side = 24.0;
  options.periodic = true;
  options.max_speed = 16.0;
  ReferenceScene scene = testing::random_gas(options, 207);
  scene.gravity = kEarthGravity;
  SceneWorld built = build_world_under_gravity(scene);
  expect_contact_by_contact_under_gravity(built, scene, kGravityContactsCompared,
                                          gravity_tolerances(options.side, options.max_speed));
}

// The same with immovable posts, which do not fall: against them a falling ball's gap is a
// quartic, met through the cell's images as the balls wrap round and speed up.
TEST(WorldReference, GravityPeriodicGasWithPostsContactByContact) {
  GasOptions options;
  options.ball_count = 64;
  options.side = 24.0;
  options.periodic = true;
  options.max_speed = 8.0;
  options.immovable_fraction = 0.2;
  ReferenceScene scene = testing::random_gas(options, 208);
  scene.gravity = {-2.0, -9.81};
  SceneWorld built = build_world_under_gravity(scene);
  expect_contact_by_contact_under_gravity(built, scene, kGravityContactsCompared,
                                          gravity_tolerances(options.side, options.max_speed));
}

// ---- 2000 balls (CAROM_LONG_TESTS=1) -------------------------------------------------------

constexpr std::size_t kLongBallCount = 2000;
constexpr std::size_t kLongContactsCompared = 1000;

TEST(WorldReference, BoxGasContactByContactLong) {
  if (!long_tests_enabled()) GTEST_SKIP() << "set CAROM_LONG_TESTS=1";
  const GasOptions options = fast_gas(kLongBallCount, 250.0, false);
  const ReferenceScene scene = testing::random_gas(options, 111);
  SceneWorld built = testing::build_world(scene);
  expect_contact_by_contact(built, scene, kLongContactsCompared, tolerances_for(options));
}

TEST(WorldReference, PeriodicGasContactByContactLong) {
  if (!long_tests_enabled()) GTEST_SKIP() << "set CAROM_LONG_TESTS=1";
  const GasOptions options = fast_gas(kLongBallCount, 250.0, true);
  const ReferenceScene scene = testing::random_gas(options, 112);
  SceneWorld built = testing::build_world(scene);
  expect_contact_by_contact(built, scene, kLongContactsCompared, tolerances_for(options));
}

TEST(WorldReference, BoxGasStepByStepLong) {
  if (!long_tests_enabled()) GTEST_SKIP() << "set CAROM_LONG_TESTS=1";
  const GasOptions options = fast_gas(kLongBallCount, 2000.0, false);
  const ReferenceScene scene = testing::random_gas(options, 113);
  SceneWorld built = testing::build_world(scene);
  std::size_t contacts = 0;
  expect_step_by_step(built, scene, kSubstep, kStepsCompared, tolerances_for(options), contacts);
  EXPECT_GT(contacts, 1000u);
}

// ---- growth ----------------------------------------------------------------------------------

// The scene with every movable ball growing as WorldDef::growth_rate `rate` makes it grow from
// time 0: at the speed radius·rate.
ReferenceScene growing(ReferenceScene scene, double rate) {
  for (testing::ReferenceBall& ball : scene.balls) {
    if (!std::isinf(ball.mass)) ball.growth = ball.radius * rate;
  }
  return scene;
}

SceneWorld build_growing_world(const ReferenceScene& scene, double rate) {
  SceneWorld built = testing::build_world(scene);
  built.world.set_growth_rate(rate);
  return built;
}

constexpr double kGrowthRate = 0.05;
constexpr std::size_t kGrowthContactsCompared = 1500;

// Growing disks in a periodic cell: each contact at the closed-form time of the growing gap, each
// bounce adding the growth speeds to the parting; the speed scale follows the balls as growth
// speeds them up.
TEST(WorldReference, GrowthPeriodicGasContactByContact) {
  const GasOptions options = fast_gas(120, 60.0, true);
  const ReferenceScene scene = growing(testing::random_gas(options, 301), kGrowthRate);
  SceneWorld built = build_growing_world(scene, kGrowthRate);
  expect_contact_by_contact_under_gravity(built, scene, kGrowthContactsCompared,
                                          tolerances_for(options));
}

// Growing fast, so that the balls outgrow the grid's cells and it is re-planned on the way
// (radii × 2.3 over the contacts compared).
TEST(WorldReference, FastGrowthPeriodicGasContactByContactAcrossReplannedGrids) {
  const GasOptions options = fast_gas(120, 60.0, true);
  const double rate = 40.0;
  const ReferenceScene scene = growing(testing::random_gas(options, 304), rate);
  SceneWorld built = build_growing_world(scene, rate);
  expect_contact_by_contact_under_gravity(built, scene, kGrowthContactsCompared,
                                          tolerances_for(options));
  const BallId first = built.ids[0];
  EXPECT_GT(built.world.radius(first), 2.0 * scene.balls[0].radius) << built.world.time();
}

// The same in a box: growing balls against its walls.
TEST(WorldReference, GrowthBoxGasContactByContact) {
  const GasOptions options = fast_gas(120, 60.0, false);
  const ReferenceScene scene = growing(testing::random_gas(options, 302), kGrowthRate);
  SceneWorld built = build_growing_world(scene, kGrowthRate);
  expect_contact_by_contact_under_gravity(built, scene, kGrowthContactsCompared,
                                          tolerances_for(options));
}

// Step by step: between contacts both move every ball and grow every radius alike (half steps
// over 4 time units, radii × 1.2, each step end in mid-flight).
TEST(WorldReference, GrowthBoxGasStepByStep) {
  GasOptions options;
  options.ball_count = 36;
  options.side = 20.0;
  options.max_speed = 8.0;
  const ReferenceScene scene = growing(testing::random_gas(options, 303), kGrowthRate);
  SceneWorld built = build_growing_world(scene, kGrowthRate);
  std::size_t contacts = 0;
  expect_step_by_step_under_gravity(built, scene, 0.5 * kReferenceStep, 480,
                                    gravity_tolerances(options.side, options.max_speed), contacts);
  EXPECT_GT(contacts, 100u);
}

}  // namespace
}  // namespace carom
