// A brute-force event-driven simulator of balls, walls and arcs, written only as the oracle for
// the World tests. It shares nothing with the World's engine except the already-tested core
// (time of impact and bounce): no grid, no event queue, no cached predictions. Each iteration it
// asks every pair and every ball–wall for its first approaching contact, takes the earliest,
// moves every ball to that time and bounces. O(N²) per contact: slow and obviously right.
// Under gravity every movable ball follows its parabola and the contact times come from the core's
// accelerated queries (carom::Motion); with zero gravity the straight-line queries and moves
// alone are used, so a scene without gravity runs bit for bit as a straight-line one. A ball may
// grow at a constant speed (its radius r + growth·t, WorldDef::growth_rate's law); its contact
// times then come from the same queries with the growth in the Motion, and a contact reverses
// the closing of the gap (the normal approach plus the growth speeds) times the restitution.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"
#include "carom/world.hpp"

namespace carom::testing {

// How two balls' restitutions combine into the pair's. world.hpp does not state the rule; the
// oracle assumes the smaller of the two (the bouncier ball cannot make a dead ball lively).
// One named function so that the oracle changes in one place once the rule is settled.
[[nodiscard]] double combined_restitution(double restitution_a, double restitution_b);

struct ReferenceBall {
  Vec2 position;
  Vec2 velocity;
  double radius = 1.0;
  double mass = 1.0;  // > 0, or kImmovable (then the velocity must be zero)
  double restitution = 1.0;
  double growth = 0.0;  // radius per time unit (0 for an immovable ball)
};

struct ReferenceWall {
  bool is_arc = false;
  Segment segment;
  Arc arc;
};

[[nodiscard]] ReferenceWall segment_wall(const Segment& segment);
[[nodiscard]] ReferenceWall arc_wall(const Arc& arc);
// The four walls World::add_box makes, in its order: from the lower-left corner to the
// lower-right one, then counter-clockwise.
[[nodiscard]] std::array<ReferenceWall, 4> box_walls(Vec2 lower, Vec2 upper);

struct ReferenceScene {
  std::vector<ReferenceBall> balls;
  std::vector<ReferenceWall> walls;  // not allowed in a periodic scene
  bool periodic = false;             // both axes wrap around [lower, upper)
  Vec2 lower;
  Vec2 upper;
  double start_time = 0.0;  // the world time the balls' state belongs to
  // The acceleration of every movable ball (WorldDef::gravity); immovable balls do not fall.
  // A contact at which gravity merely presses a pair together with no normal speed (a resting
  // contact) has no response the oracle can vouch for: meeting one throws std::runtime_error,
  // so scenes under gravity keep their balls bouncing (elastic ones, say).
  Vec2 gravity;
};

struct ReferenceContact {
  double time = 0.0;
  ContactKind kind = ContactKind::ball_ball;
  std::size_t a = 0;     // ball index; for two balls the lower one
  std::size_t b = 0;     // the other ball (ball_ball only)
  std::size_t wall = 0;  // ball_wall only
  Vec2 normal;           // unit, from a towards b or the wall
  double approach_speed = 0.0;
  double impulse = 0.0;
};

class ReferenceSimulator {
 public:
  explicit ReferenceSimulator(ReferenceScene scene);

  // Advances to end_time (>= time()), resolving every contact on the way in the World's order:
  // time, then ball–ball before ball–wall, then ids ascending.
  void run_until(double end_time);
  // Resolves the next `count` contacts that happen by time_limit and stops right after the last
  // (or at time_limit, if fewer happen); returns how many it resolved.
  std::size_t run_collisions(std::size_t count, double time_limit);

  [[nodiscard]] double time() const noexcept { return time_; }
  [[nodiscard]] const std::vector<ReferenceBall>& balls() const noexcept { return scene_.balls; }
  [[nodiscard]] const std::vector<ReferenceContact>& contacts() const noexcept { return contacts_; }

 private:
  struct Candidate;

  [[nodiscard]] double lookahead() const;
  // The ball's acceleration: gravity, or zero for an immovable ball.
  [[nodiscard]] Vec2 acceleration_of(const ReferenceBall& ball) const;
  [[nodiscard]] Candidate earliest_contact(double horizon) const;
  void consider_pair(std::size_t i, std::size_t j, double horizon,
                     const std::vector<double>& speeds, Candidate& best) const;
  void consider_wall(std::size_t i, std::size_t w, double horizon, Candidate& best) const;
  void advance(double dt);
  void resolve(const Candidate& contact);
  // Throws for a resting contact: its normal speed is zero within rounding of the pair's speed.
  static void refuse_resting(const ReferenceContact& contact, double speed);
  // Moves on to the next contact if it happens by end_time (and resolves it), or to end_time.
  // Returns whether a contact was resolved.
  bool advance_to_next_contact(double end_time);

  ReferenceScene scene_;
  double time_ = 0.0;
  std::vector<ReferenceContact> contacts_;
};

}  // namespace carom::testing
