#include "world/reference_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "carom/bounce.hpp"
#include "carom/sweep.hpp"

namespace carom::testing {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The oracle looks ahead only as far as every pair can close this many largest diameters. Any
// window is correct (a window without a contact just moves every ball to its end); a short one
// lets the cheap reach test below skip most pairs.
constexpr double kLookaheadDiameters = 4.0;

// The reach test may only skip pairs that cannot touch within the window. Its inputs carry a few
// roundings (~1e-16 relative), so a margin of 1e-6 of the reach keeps it safely conservative.
constexpr double kReachSlack = 1e-6;

// A scene that keeps colliding without end (inelastic collapse) would hang the test; this many
// contacts in one run_until is far more than any test scene has.
constexpr std::uint64_t kMaxContactsPerRun = 50'000'000;

// Under gravity a pair touching with no normal speed while gravity presses it together is a
// resting contact, which the core reports at once (t = 0) and which a bounce cannot undo: the
// oracle would meet it again and again at the same time. The core counts a normal speed as zero
// within about 2^-48 of the pair's speed (the rounding of its gap's slope); a contact slower
// along the normal than 2^-40 of that speed is read as resting. A real bounce that slow is a
// graze of measure ~1e-12, which no test scene meets.
constexpr double kRestingSpeedRatio = 0x1p-40;

bool is_immovable(const ReferenceBall& ball) { return std::isinf(ball.mass); }

bool has_gravity(const ReferenceScene& scene) { return scene.gravity != Vec2{}; }

bool has_growth(const ReferenceScene& scene) {
  return std::any_of(scene.balls.begin(), scene.balls.end(),
                     [](const ReferenceBall& ball) { return ball.growth != 0.0; });
}

// Gravity or growth: the contact times then come from the Motion queries.
bool has_motion_law(const ReferenceScene& scene) { return has_gravity(scene) || has_growth(scene); }

// The offset (−length, 0 or +length) that brings a separation d in (−length, length) to the
// nearest image, |d − offset| <= length / 2.
double nearest_image_offset(double d, double length) {
  if (d > 0.5 * length) return length;
  if (d < -0.5 * length) return -length;
  return 0.0;
}

// Back into [lower, upper) after a move shorter than the cell.
double wrap(double x, double lower, double upper) {
  const double length = upper - lower;
  if (x >= upper) x -= length;
  if (x < lower) x += length;
  // x a hair below lower plus the length can round up to upper itself.
  if (x >= upper) x = lower;
  return x;
}

}  // namespace

double combined_restitution(double restitution_a, double restitution_b) {
  return std::min(restitution_a, restitution_b);
}

ReferenceWall segment_wall(const Segment& segment) { return {false, segment, {}}; }

ReferenceWall arc_wall(const Arc& arc) { return {true, {}, arc}; }

std::array<ReferenceWall, 4> box_walls(Vec2 lower, Vec2 upper) {
  const Vec2 lower_right{upper.x, lower.y};
  const Vec2 upper_left{lower.x, upper.y};
  return {segment_wall({lower, lower_right}), segment_wall({lower_right, upper}),
          segment_wall({upper, upper_left}), segment_wall({upper_left, lower})};
}

// The earliest contact found so far; t is relative to the simulator's current time.
struct ReferenceSimulator::Candidate {
  bool found = false;
  double t = kInfinity;
  ContactKind kind = ContactKind::ball_ball;
  std::size_t a = 0;
  std::size_t b = 0;  // the other ball, or the wall
  Vec2 normal;
};

namespace {

// The World's documented order: time, then ball–ball before ball–wall, then the ids (the ball
// pair ascending, or the ball then the wall).
template <class C>
bool comes_before(const C& x, const C& y) {
  if (!y.found) return x.found;
  if (!x.found) return false;
  if (x.t != y.t) return x.t < y.t;
  if (x.kind != y.kind) return x.kind == ContactKind::ball_ball;
  if (x.a != y.a) return x.a < y.a;
  return x.b < y.b;
}

}  // namespace

ReferenceSimulator::ReferenceSimulator(ReferenceScene scene)
    : scene_(std::move(scene)), time_(scene_.start_time) {
  for (const ReferenceBall& ball : scene_.balls) {
    if (is_immovable(ball) && ball.velocity != Vec2{}) {
      throw std::invalid_argument("reference: an immovable ball must stand still");
    }
  }
  if (!scene_.periodic) return;
  if (!scene_.walls.empty()) throw std::invalid_argument("reference: walls in a periodic scene");
  double largest_radius = 0.0;
  for (ReferenceBall& ball : scene_.balls) {
    largest_radius = std::max(largest_radius, ball.radius);
    ball.position = {wrap(ball.position.x, scene_.lower.x, scene_.upper.x),
                     wrap(ball.position.y, scene_.lower.y, scene_.upper.y)};
  }
  const Vec2 cell = scene_.upper - scene_.lower;
  // The nearest image is the only one a ball can touch within the window (see lookahead()).
  if (!(std::min(cell.x, cell.y) > 4.0 * largest_radius)) {
    throw std::invalid_argument("reference: the periodic cell must exceed two diameters");
  }
}

Vec2 ReferenceSimulator::acceleration_of(const ReferenceBall& ball) const {
  return is_immovable(ball) ? Vec2{} : scene_.gravity;
}

double ReferenceSimulator::lookahead() const {
  double fastest = 0.0;
  double largest_radius = 0.0;
  for (const ReferenceBall& ball : scene_.balls) {
    // (A growing ball's surface moves at most its speed plus its growth.)
    fastest = std::max(fastest, length(ball.velocity) + ball.growth);
    largest_radius = std::max(largest_radius, ball.radius);
  }
  const double pull = length(scene_.gravity);
  if (fastest == 0.0 && pull == 0.0) return kInfinity;
  double closing = kLookaheadDiameters * 2.0 * largest_radius;
  if (scene_.periodic) {
    // A pair touching through an image at most half a cell away (nearest_image_offset) needs
    // their separation, two radii plus the closing distance, to stay below half a cell; half
    // of the room left keeps it so by a wide margin.
    const Vec2 cell = scene_.upper - scene_.lower;
    const double room = 0.5 * std::min(cell.x, cell.y) - 2.0 * largest_radius;
    closing = std::min(closing, 0.5 * room);
  }
  // Two balls close at most at twice the top speed.
  if (pull == 0.0) return closing / (2.0 * fastest);
  // Under gravity two balls close by at most 2·fastest·h + pull·h² in a window h (each moves
  // fastest·h + ½·pull·h² at most): h is that quadratic's positive root for `closing`, in the
  // form without cancellation.
  return closing / (fastest + std::sqrt(fastest * fastest + pull * closing));
}

void ReferenceSimulator::consider_pair(std::size_t i, std::size_t j, double horizon,
                                       const std::vector<double>& speeds, Candidate& best) const {
  const ReferenceBall& a = scene_.balls[i];
  const ReferenceBall& b = scene_.balls[j];
  if (is_immovable(a) && is_immovable(b)) return;
  Vec2 b_center = b.position;
  if (scene_.periodic) {
    const Vec2 cell = scene_.upper - scene_.lower;
    const Vec2 d = b.position - a.position;
    b_center -= Vec2{nearest_image_offset(d.x, cell.x), nearest_image_offset(d.y, cell.y)};
  }
  const Vec2 acceleration_a = acceleration_of(a);
  const Vec2 acceleration_b = acceleration_of(b);
  // They close at most at the sum of their speeds, plus half the sum of their accelerations'
  // magnitudes times the window squared.
  const double reach = a.radius + b.radius +
                       (speeds[i] + speeds[j] + a.growth + b.growth) * horizon +
                       0.5 * (length(acceleration_a) + length(acceleration_b)) * horizon * horizon;
  if (length_squared(b_center - a.position) > reach * reach * (1.0 + kReachSlack)) return;
  const Impact impact =
      has_motion_law(scene_)
          ? time_of_impact_ball_ball(
                {a.position, a.radius}, Motion{a.velocity, acceleration_a, a.growth},
                {b_center, b.radius}, Motion{b.velocity, acceleration_b, b.growth}, horizon)
          : time_of_impact_ball_ball({a.position, a.radius}, a.velocity, {b_center, b.radius},
                                     b.velocity, horizon);
  if (!impact.hit) return;
  const Candidate candidate{true, impact.t, ContactKind::ball_ball, i, j, impact.normal};
  if (comes_before(candidate, best)) best = candidate;
}

void ReferenceSimulator::consider_wall(std::size_t i, std::size_t w, double horizon,
                                       Candidate& best) const {
  const ReferenceBall& ball = scene_.balls[i];
  if (is_immovable(ball)) return;
  const ReferenceWall& wall = scene_.walls[w];
  const Ball disc{ball.position, ball.radius};
  Impact impact;
  if (has_motion_law(scene_)) {
    const Motion motion{ball.velocity, scene_.gravity, ball.growth};
    impact = wall.is_arc ? time_of_impact_ball_arc(disc, motion, wall.arc, horizon)
                         : time_of_impact_ball_segment(disc, motion, wall.segment, horizon);
  } else {
    impact = wall.is_arc ? time_of_impact_ball_arc(disc, ball.velocity, wall.arc, horizon)
                         : time_of_impact_ball_segment(disc, ball.velocity, wall.segment, horizon);
  }
  if (!impact.hit) return;
  const Candidate candidate{true, impact.t, ContactKind::ball_wall, i, w, impact.normal};
  if (comes_before(candidate, best)) best = candidate;
}

ReferenceSimulator::Candidate ReferenceSimulator::earliest_contact(double horizon) const {
  Candidate best;
  const std::size_t count = scene_.balls.size();
  std::vector<double> speeds(count);
  for (std::size_t i = 0; i < count; ++i) speeds[i] = length(scene_.balls[i].velocity);
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = i + 1; j < count; ++j) consider_pair(i, j, horizon, speeds, best);
  }
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t w = 0; w < scene_.walls.size(); ++w) consider_wall(i, w, horizon, best);
  }
  return best;
}

void ReferenceSimulator::advance(double dt) {
  const bool gravity = has_gravity(scene_);
  for (ReferenceBall& ball : scene_.balls) {
    if (gravity && !is_immovable(ball)) {
      // Along the parabola, with the velocity it has at the end of the move.
      ball.position += ball.velocity * dt + scene_.gravity * (0.5 * dt * dt);
      ball.velocity += scene_.gravity * dt;
    } else {
      ball.position += ball.velocity * dt;
    }
    ball.radius += ball.growth * dt;
    if (scene_.periodic) {
      ball.position = {wrap(ball.position.x, scene_.lower.x, scene_.upper.x),
                       wrap(ball.position.y, scene_.lower.y, scene_.upper.y)};
    }
  }
  time_ += dt;
}

void ReferenceSimulator::resolve(const Candidate& contact) {
  ReferenceContact record;
  record.time = time_;
  record.kind = contact.kind;
  record.a = contact.a;
  record.normal = contact.normal;
  ReferenceBall& a = scene_.balls[contact.a];
  if (contact.kind == ContactKind::ball_ball) {
    ReferenceBall& b = scene_.balls[contact.b];
    record.b = contact.b;
    record.approach_speed = dot(a.velocity - b.velocity, contact.normal);
    if (has_growth(scene_)) {
      // The gap closes by the approach and both growths; the impulse reverses that, times e.
      const double closing = record.approach_speed + a.growth + b.growth;
      const double inverse_a = is_immovable(a) ? 0.0 : 1.0 / a.mass;
      const double inverse_b = is_immovable(b) ? 0.0 : 1.0 / b.mass;
      const double e = combined_restitution(a.restitution, b.restitution);
      const double impulse = (1.0 + e) * closing / (inverse_a + inverse_b);
      a.velocity -= contact.normal * (impulse * inverse_a);
      b.velocity += contact.normal * (impulse * inverse_b);
      record.approach_speed = closing;
      record.impulse = impulse;
      contacts_.push_back(record);
      return;
    }
    if (has_gravity(scene_)) refuse_resting(record, length(a.velocity - b.velocity));
    const BounceResult result = bounce(a.velocity, a.mass, b.velocity, b.mass, contact.normal,
                                       combined_restitution(a.restitution, b.restitution));
    a.velocity = result.velocity_a;
    b.velocity = result.velocity_b;
    record.impulse = result.impulse;
  } else {
    record.wall = contact.b;
    record.approach_speed = dot(a.velocity, contact.normal);
    if (has_growth(scene_)) {
      const double closing = record.approach_speed + a.growth;
      const double change = (1.0 + a.restitution) * closing;
      a.velocity -= contact.normal * change;
      record.approach_speed = closing;
      record.impulse = is_immovable(a) ? 0.0 : change * a.mass;
      contacts_.push_back(record);
      return;
    }
    const ReferenceWall& wall = scene_.walls[contact.b];
    // The inside of an arc (a ball in a bowl) has its own bounce: the contact's normal points
    // straight out from the arc's centre there, and elsewhere (its outside, an end point) not.
    const Vec2 out = a.position - (wall.is_arc ? wall.arc.center : Vec2{});
    const bool in_bowl = wall.is_arc && length(out) < wall.arc.radius &&
                         dot(out, contact.normal) > 0.0 &&
                         std::abs(cross(out, contact.normal)) <= 1e-9 * length(out);
    if (has_gravity(scene_) && !in_bowl) refuse_resting(record, length(a.velocity));
    const WallBounceResult result =
        in_bowl ? bounce_inside_arc(a.velocity, a.mass, contact.normal, a.restitution)
                : bounce_off_static(a.velocity, a.mass, contact.normal, a.restitution);
    a.velocity = result.velocity;
    record.impulse = result.impulse;
  }
  contacts_.push_back(record);
}

void ReferenceSimulator::refuse_resting(const ReferenceContact& contact, double speed) {
  if (contact.approach_speed > kRestingSpeedRatio * speed) return;
  std::ostringstream out;
  out.precision(17);
  out << "reference: a resting contact at t=" << contact.time << " (ball " << contact.a;
  if (contact.kind == ContactKind::ball_ball) {
    out << " and ball " << contact.b;
  } else {
    out << " and wall " << contact.wall;
  }
  out << ", normal speed " << contact.approach_speed << " of " << speed
      << "), which the oracle does not model";
  throw std::runtime_error(out.str());
}

bool ReferenceSimulator::advance_to_next_contact(double end_time) {
  while (time_ < end_time) {
    const double remaining = end_time - time_;
    const double window = std::min(remaining, lookahead());
    const Candidate next = earliest_contact(window);
    if (next.found) {
      advance(next.t);
      resolve(next);
      return true;
    }
    advance(window);
    if (window == remaining) time_ = end_time;
  }
  return false;
}

void ReferenceSimulator::run_until(double end_time) {
  if (!(end_time >= time_)) throw std::invalid_argument("reference: end_time before time()");
  std::uint64_t resolved = 0;
  while (advance_to_next_contact(end_time)) {
    if (++resolved > kMaxContactsPerRun) {
      throw std::runtime_error("reference: too many contacts (inelastic collapse?)");
    }
  }
  time_ = end_time;
}

std::size_t ReferenceSimulator::run_collisions(std::size_t count, double time_limit) {
  if (!(time_limit >= time_)) throw std::invalid_argument("reference: time_limit before time()");
  std::size_t resolved = 0;
  while (resolved < count && advance_to_next_contact(time_limit)) ++resolved;
  return resolved;
}

}  // namespace carom::testing
