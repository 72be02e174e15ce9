#include "world/scene_world.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace carom::testing {
namespace {

constexpr std::size_t kBoxWallCount = 4;
// How many contacts around the first difference a failure message shows.
constexpr std::size_t kContextContacts = 2;

std::string describe(Vec2 v) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << v.x << ", " << v.y << ")";
  return out.str();
}

std::string describe(const ContactEvent& c,
                     const std::unordered_map<std::uint32_t, std::size_t>& slot_to_ball) {
  std::ostringstream out;
  out.precision(17);
  auto ball = [&](BallId id) {
    const auto found = slot_to_ball.find(id.index);
    return found == slot_to_ball.end() ? std::string("?") : std::to_string(found->second);
  };
  out << "t=" << c.time << (c.kind == ContactKind::ball_ball ? " ball-ball " : " ball-wall ")
      << ball(c.a) << " " << (c.kind == ContactKind::ball_ball ? ball(c.b) : "wall ")
      << (c.kind == ContactKind::ball_wall ? std::to_string(c.wall) : "")
      << " normal=" << describe(c.normal) << " approach=" << c.approach_speed;
  return out.str();
}

std::string describe(const ReferenceContact& c) {
  std::ostringstream out;
  out.precision(17);
  out << "t=" << c.time << (c.kind == ContactKind::ball_ball ? " ball-ball " : " ball-wall ") << c.a
      << " " << (c.kind == ContactKind::ball_ball ? std::to_string(c.b) : "wall ")
      << (c.kind == ContactKind::ball_wall ? std::to_string(c.wall) : "")
      << " normal=" << describe(c.normal) << " approach=" << c.approach_speed;
  return out.str();
}

bool within(double got, double expected, double tolerance) {
  return std::abs(got - expected) <= tolerance;
}

// Why the two contacts differ, or an empty string.
std::string difference(const ContactEvent& w, const ReferenceContact& r,
                       const std::unordered_map<std::uint32_t, std::size_t>& slot_to_ball,
                       std::span<const BallId> ids, const Tolerances& tol) {
  if (w.kind != r.kind) return "kind";
  const auto a = slot_to_ball.find(w.a.index);
  if (a == slot_to_ball.end() || ids[a->second] != w.a) return "ball a is no ball of the scene";
  if (a->second != r.a) return "ball a";
  if (w.kind == ContactKind::ball_ball) {
    const auto b = slot_to_ball.find(w.b.index);
    if (b == slot_to_ball.end() || ids[b->second] != w.b) return "ball b is no ball of the scene";
    if (b->second != r.b) return "ball b";
  } else if (w.wall != r.wall) {
    return "wall";
  }
  if (!within(w.time, r.time, tol.time * std::max(std::abs(r.time), tol.time_scale))) {
    return "time";
  }
  if (!within(w.normal.x, r.normal.x, tol.speed) || !within(w.normal.y, r.normal.y, tol.speed)) {
    return "normal";
  }
  if (!within(w.approach_speed, r.approach_speed, tol.speed * tol.speed_scale)) {
    return "approach speed";
  }
  return {};
}

double nearest_image_difference(double d, double length) {
  if (length <= 0.0) return d;
  return d - length * std::round(d / length);
}

}  // namespace

SceneWorld build_world(const ReferenceScene& scene, BoxAs box_as, double collapse_time) {
  WorldDef def;
  def.collapse_time = collapse_time;
  std::size_t first_wall = 0;
  if (scene.periodic) {
    def.boundary = Boundary::periodic;
    def.lower = scene.lower;
    def.upper = scene.upper;
  } else if (box_as == BoxAs::boundary) {
    if (scene.walls.size() != kBoxWallCount) {
      throw std::invalid_argument("build_world: a box boundary scene has only the box's walls");
    }
    def.boundary = Boundary::box;
    def.lower = scene.lower;
    def.upper = scene.upper;
    first_wall = kBoxWallCount;
  }
  SceneWorld built{World(def), {}};
  for (std::size_t w = first_wall; w < scene.walls.size(); ++w) {
    const ReferenceWall& wall = scene.walls[w];
    const WallId id =
        wall.is_arc ? built.world.add_arc(wall.arc) : built.world.add_segment(wall.segment);
    if (id != w) throw std::runtime_error("build_world: wall ids are not in the order added");
  }
  for (const ReferenceBall& ball : scene.balls) {
    BallDef def_ball;
    def_ball.position = ball.position;
    def_ball.velocity = ball.velocity;
    def_ball.radius = ball.radius;
    def_ball.mass = ball.mass;
    def_ball.restitution = ball.restitution;
    built.ids.push_back(built.world.add_ball(def_ball));
  }
  return built;
}

ReferenceScene scene_at_world_time(const ReferenceScene& scene, const SceneWorld& built) {
  ReferenceScene now = scene;
  now.start_time = built.world.time();
  for (std::size_t i = 0; i < now.balls.size(); ++i) {
    now.balls[i].position = built.world.position(built.ids[i]);
    now.balls[i].velocity = built.world.velocity(built.ids[i]);
    now.balls[i].radius = built.world.radius(built.ids[i]);  // (a growing ball's of now)
  }
  return now;
}

void append_contacts(const World& world, std::vector<ContactEvent>& all) {
  const std::span<const ContactEvent> latest = world.contacts();
  all.insert(all.end(), latest.begin(), latest.end());
}

::testing::AssertionResult same_contacts(std::span<const ContactEvent> world,
                                         std::span<const BallId> ids,
                                         std::span<const ReferenceContact> reference,
                                         const Tolerances& tolerances) {
  std::unordered_map<std::uint32_t, std::size_t> slot_to_ball;
  for (std::size_t i = 0; i < ids.size(); ++i) slot_to_ball[ids[i].index] = i;

  const std::size_t common = std::min(world.size(), reference.size());
  for (std::size_t k = 0; k < common; ++k) {
    const std::string why = difference(world[k], reference[k], slot_to_ball, ids, tolerances);
    if (why.empty()) continue;
    auto failure = ::testing::AssertionFailure();
    failure << "contact " << k << " of " << world.size() << " (world) / " << reference.size()
            << " (reference) differs in " << why << "\n";
    const std::size_t from = k >= kContextContacts ? k - kContextContacts : 0;
    const std::size_t to = std::min(common, k + kContextContacts + 1);
    for (std::size_t j = from; j < to; ++j) {
      failure << "  [" << j << "] world:     " << describe(world[j], slot_to_ball) << "\n"
              << "  [" << j << "] reference: " << describe(reference[j]) << "\n";
    }
    return failure;
  }
  if (world.size() != reference.size()) {
    auto failure = ::testing::AssertionFailure();
    failure << "the world resolved " << world.size() << " contacts, the reference "
            << reference.size() << "; the first " << common << " agree\n";
    if (world.size() > common) failure << "  next world: " << describe(world[common], slot_to_ball);
    if (reference.size() > common) failure << "  next reference: " << describe(reference[common]);
    return failure;
  }
  return ::testing::AssertionSuccess() << common << " contacts agree";
}

::testing::AssertionResult same_state(const SceneWorld& built, const ReferenceSimulator& reference,
                                      const ReferenceScene& scene, const Tolerances& tolerances) {
  const double time_tolerance =
      tolerances.time * std::max(std::abs(reference.time()), tolerances.time_scale);
  if (!within(built.world.time(), reference.time(), time_tolerance)) {
    return ::testing::AssertionFailure()
           << "world time " << built.world.time() << " != reference time " << reference.time();
  }
  const Vec2 cell = scene.periodic ? scene.upper - scene.lower : Vec2{};
  for (std::size_t i = 0; i < built.ids.size(); ++i) {
    const ReferenceBall& expected = reference.balls()[i];
    const Vec2 position = built.world.position(built.ids[i]);
    const Vec2 velocity = built.world.velocity(built.ids[i]);
    const Vec2 offset{nearest_image_difference(position.x - expected.position.x, cell.x),
                      nearest_image_difference(position.y - expected.position.y, cell.y)};
    const double speed_tolerance = tolerances.speed * tolerances.speed_scale;
    if (length(offset) > tolerances.position ||
        length(velocity - expected.velocity) > speed_tolerance) {
      return ::testing::AssertionFailure()
             << "ball " << i << ": world at " << describe(position) << " moving "
             << describe(velocity) << ", reference at " << describe(expected.position) << " moving "
             << describe(expected.velocity);
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace carom::testing
