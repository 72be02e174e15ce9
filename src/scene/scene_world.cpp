// Building a world from a scene, running it with pockets, and reading its state back.
#include <algorithm>
#include <string>
#include <utility>

#include "carom/error.hpp"
#include "carom/scene.hpp"
#include "scene_check.hpp"

namespace carom {
namespace {

// user_data of a pocket's ball: this bit set, the pocket's index below it. A ball's user_data is
// its scene index.
constexpr std::uint64_t kPocketTag = std::uint64_t{1} << 63U;

SceneError world_refused(const std::string& path, const InvalidArgument& error) {
  return SceneError(
      {"", 0, 0, path, error.value(), "the world refuses it: " + error.requirement(), ""});
}

bool is_pocket(const std::vector<BallId>& pockets, BallId id) {
  return std::find(pockets.begin(), pockets.end(), id) != pockets.end();
}

// The world stopped right after a contact with a pocket: remove the ball that fell in.
void pot(SceneWorld& sw, std::vector<PottedBall>* potted) {
  const std::span<const ContactEvent> contacts = sw.world.contacts();
  if (contacts.empty()) return;
  const ContactEvent& last = contacts.back();
  if (last.kind != ContactKind::ball_ball) return;
  const bool a_is_pocket = is_pocket(sw.pockets, last.a);
  const BallId ball = a_is_pocket ? last.b : last.a;
  const BallId pocket = a_is_pocket ? last.a : last.b;
  if (!is_pocket(sw.pockets, pocket) || is_pocket(sw.pockets, ball)) return;
  if (!sw.world.contains(ball)) return;
  const std::uint64_t index = sw.world.user_data(ball);
  sw.world.remove_ball(ball);
  if (index < sw.balls.size()) sw.balls[static_cast<std::size_t>(index)] = BallId{};
  if (potted != nullptr) {
    const auto k = static_cast<std::size_t>(
        std::find(sw.pockets.begin(), sw.pockets.end(), pocket) - sw.pockets.begin());
    potted->push_back({sw.start_time + last.time, static_cast<std::size_t>(index), k});
  }
}

void append(const World& world, std::vector<ContactEvent>* contacts) {
  if (contacts == nullptr) return;
  const std::span<const ContactEvent> now = world.contacts();
  contacts->insert(contacts->end(), now.begin(), now.end());
}

}  // namespace

std::optional<std::size_t> SceneWorld::index_of(BallId id) const {
  if (!world.contains(id)) return std::nullopt;
  const std::uint64_t data = world.user_data(id);
  if ((data & kPocketTag) != 0) return std::nullopt;
  return static_cast<std::size_t>(data);
}

SceneWorld make_world(const Scene& scene) {
  std::vector<SceneBall> balls = scene_detail::check_scene(scene);
  scene_detail::separate_touching(scene, balls);
  const WorldDef& def = scene.world;
  SceneWorld sw{[&] {
                  try {
                    return World(def);
                  } catch (const InvalidArgument& error) {
                    throw world_refused("world", error);
                  }
                }(),
                {},
                {},
                {},
                {},
                0.0};
  sw.scene = scene;
  sw.scene.balls = balls;
  sw.scene.generators.clear();
  sw.start_time = scene.time;

  try {
    for (const Segment& segment : scene.segments) static_cast<void>(sw.world.add_segment(segment));
    for (const ScenePolyline& polyline : scene.polylines) {
      static_cast<void>(sw.world.add_polyline(polyline.points, polyline.closed));
    }
    for (const Arc& arc : scene.arcs) static_cast<void>(sw.world.add_arc(arc));
  } catch (const InvalidArgument& error) {
    throw world_refused("segments", error);
  }
  sw.balls.reserve(balls.size());
  sw.world.reserve(balls.size() + scene.pockets.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const SceneBall& b = balls[i];
    try {
      const BallId id = sw.world.add_ball(
          {b.position, b.velocity, b.radius, b.mass, b.restitution, static_cast<std::uint64_t>(i)});
      sw.balls.push_back(id);
      if (b.name) sw.by_name[*b.name] = id;
    } catch (const InvalidArgument& error) {
      throw world_refused("balls[" + std::to_string(i) + "]", error);
    }
  }
  for (std::size_t k = 0; k < scene.pockets.size(); ++k) {
    const ScenePocket& p = scene.pockets[k];
    try {
      const BallId id =
          sw.world.add_ball({p.position, {}, p.radius, kImmovable, std::nullopt, kPocketTag | k});
      sw.pockets.push_back(id);
      if (p.name) sw.by_name[*p.name] = id;
    } catch (const InvalidArgument& error) {
      throw world_refused("pockets[" + std::to_string(k) + "]", error);
    }
  }
  if (!sw.pockets.empty()) stop_at_pocket_contacts(sw.world, sw.pockets);
  return sw;
}

void stop_at_pocket_contacts(World& world, std::vector<BallId> pockets) {
  world.set_stop_condition([pockets = std::move(pockets)](const ContactEvent& contact) {
    return contact.kind == ContactKind::ball_ball &&
           (is_pocket(pockets, contact.a) || is_pocket(pockets, contact.b));
  });
}

double step_scene(SceneWorld& sw, double dt, std::vector<ContactEvent>* contacts,
                  std::vector<PottedBall>* potted) {
  const double start = sw.world.time();
  if (sw.pockets.empty()) {
    const double advanced = sw.world.step(dt);
    append(sw.world, contacts);
    return advanced;
  }
  return run_scene_until(sw, start + dt, contacts, potted);
}

double run_scene_until(SceneWorld& sw, double time, std::vector<ContactEvent>* contacts,
                       std::vector<PottedBall>* potted) {
  const double start = sw.world.time();
  for (;;) {
    static_cast<void>(sw.world.run_until(time));
    append(sw.world, contacts);
    if (!sw.world.stopped_early()) break;
    pot(sw, potted);
    if (sw.world.time() >= time) break;
  }
  return sw.world.time() - start;
}

std::uint64_t run_scene_collisions(SceneWorld& sw, std::uint64_t count,
                                   std::vector<ContactEvent>* contacts,
                                   std::vector<PottedBall>* potted, double time_limit) {
  std::uint64_t done = 0;
  while (done < count) {
    done += sw.world.run_collisions(count - done, time_limit);
    append(sw.world, contacts);
    if (!sw.world.stopped_early()) break;
    pot(sw, potted);
  }
  return done;
}

Scene capture_scene(const SceneWorld& sw) {
  Scene scene = sw.scene;
  scene.balls.clear();
  scene.generators.clear();
  scene.time = sw.time();
  // set_gravity may have changed it since the world was built.
  scene.world.gravity = sw.world.def().gravity;
  // The world's own settings are what it ran with, whatever the scene it came from said.
  scene.world.rest_height = sw.world.def().rest_height;
  // Growth continues from the radii of now at the rate relative to them, the same law.
  scene.world.growth_rate = sw.world.growth_rate_from_now();
  for (std::size_t i = 0; i < sw.balls.size(); ++i) {
    const BallId id = sw.balls[i];
    if (id.is_null() || !sw.world.contains(id)) continue;
    SceneBall ball = sw.scene.balls[i];
    ball.position = sw.world.position(id);
    ball.velocity = sw.world.velocity(id);
    ball.radius = sw.world.radius(id);
    scene.balls.push_back(ball);
  }
  return scene;
}

}  // namespace carom
