// Box2D 2.4 in the peers benchmark. Set as the scene asks: the scene's gravity, no damping (the
// default), friction 0 and the scene's restitution on every fixture (Box2D mixes two fixtures'
// restitutions by their maximum, so all equal gives the scene's). The restitution threshold:
// Box2D 2.4.1 makes every contact slower than it perfectly inelastic (default 1 m/s). For the
// elastic scenes it is 0, since in the gas (speeds about 1) that would be most contacts. Under
// gravity it is carom's own: a contact there ends in contact when its bounce would lift the disk
// less than the rest height (a thousandth of the radius), that is when it meets the floor slower
// than sqrt(2·g·h)/e, about 0.2 here. Without friction a disk never turns, so Box2D's rotation
// plays no part. Sleeping is off unless the scene allows it (Box2D's default is on: bodies below
// its sleep tolerances for half a second sleep, by islands of touching bodies), so that in the
// gas no slow ball freezes. The scene's bullets get the `bullet` flag (continuous collision
// against other moving bodies). Left at Box2D's defaults: 8 velocity and 3 position iterations
// (the manual's recommendation), continuous collision against static bodies, and its compiled-in
// limits, among them b2_maxTranslation (2 length units per step, so 120 per second at 60 steps
// per second: faster bodies are slowed) and b2_linearSlop (0.005). Box2D works in single
// precision. The walls are static boxes one length unit thick outside the box.
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "carom/world.hpp"
#include "engine.hpp"

namespace carom::peers {
namespace {

constexpr double kWallThickness = 1.0;
constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;
// carom's rest height, as a fraction of the radius: its default, which carom's adapter keeps.
const double kCaromRestHeight = WorldDef{}.rest_height;

b2Vec2 single(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

class Box2DEngine final : public Engine {
 public:
  explicit Box2DEngine(const Scene& scene) : world_(single(scene.gravity)) {
    world_.SetAllowSleeping(scene.sleeping);
    restitution_ = static_cast<float>(scene.restitution);
    restitution_threshold_ = static_cast<float>(restitution_threshold(scene));
    add_walls(scene);
    bodies_.reserve(scene.balls.size());
    for (const SceneBall& ball : scene.balls) {
      b2BodyDef body;
      body.type = b2_dynamicBody;
      body.position = single(ball.position);
      body.linearVelocity = single(ball.velocity);
      body.bullet = ball.bullet;
      b2Body* created = world_.CreateBody(&body);
      b2CircleShape circle;
      circle.m_radius = static_cast<float>(ball.radius);
      b2FixtureDef fixture = fixture_of(&circle);
      fixture.density =
          static_cast<float>(ball.mass / (std::numbers::pi * ball.radius * ball.radius));
      created->CreateFixture(&fixture);
      bodies_.push_back(created);
    }
  }

  void step(double dt) override {
    world_.Step(static_cast<float>(dt), kVelocityIterations, kPositionIterations);
  }

  void read(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const b2Vec2 p = bodies_[i]->GetPosition();
      const b2Vec2 v = bodies_[i]->GetLinearVelocity();
      positions[i] = {p.x, p.y};
      velocities[i] = {v.x, v.y};
    }
  }

 private:
  // The approach speed below which carom ends a bounce off a still floor in contact: the bounce,
  // e·v, would lift the largest disk less than the rest height. 0 without gravity, and for
  // restitution 0 (nothing bounces) or 1 (carom bounces elastic contacts however slow).
  static double restitution_threshold(const Scene& scene) {
    const double g = std::hypot(scene.gravity.x, scene.gravity.y);
    if (g == 0.0 || scene.restitution <= 0.0 || scene.restitution >= 1.0) return 0.0;
    double radius = 0.0;
    for (const SceneBall& ball : scene.balls) radius = std::max(radius, ball.radius);
    return std::sqrt(2.0 * g * kCaromRestHeight * radius) / scene.restitution;
  }

  b2FixtureDef fixture_of(const b2Shape* shape) const {
    b2FixtureDef fixture;
    fixture.shape = shape;
    fixture.friction = 0.0f;
    fixture.restitution = restitution_;
    fixture.restitutionThreshold = restitution_threshold_;
    return fixture;
  }

  void add_walls(const Scene& scene) {
    b2BodyDef ground_def;  // static
    b2Body* ground = world_.CreateBody(&ground_def);
    const Vec2 middle = (scene.lower + scene.upper) / 2.0;
    const Vec2 half = (scene.upper - scene.lower) / 2.0;
    const double w = kWallThickness;
    struct Slab {
      Vec2 half_size;
      Vec2 centre;
    };
    const Slab slabs[] = {
        {{half.x + w, w / 2.0}, {middle.x, scene.lower.y - w / 2.0}},  // bottom
        {{half.x + w, w / 2.0}, {middle.x, scene.upper.y + w / 2.0}},  // top
        {{w / 2.0, half.y}, {scene.lower.x - w / 2.0, middle.y}},      // left
        {{w / 2.0, half.y}, {scene.upper.x + w / 2.0, middle.y}},      // right
    };
    for (const Slab& slab : slabs) {
      b2PolygonShape box;
      box.SetAsBox(static_cast<float>(slab.half_size.x), static_cast<float>(slab.half_size.y),
                   single(slab.centre), 0.0f);
      const b2FixtureDef fixture = fixture_of(&box);
      ground->CreateFixture(&fixture);
    }
  }

  b2World world_;
  float restitution_ = 1.0f;
  float restitution_threshold_ = 0.0f;
  std::vector<b2Body*> bodies_;
};

}  // namespace

std::unique_ptr<Engine> make_box2d_engine(const Scene& scene) {
  return std::make_unique<Box2DEngine>(scene);
}

std::string box2d_version() { return std::string("Box2D ") + CAROM_PEERS_BOX2D_VERSION; }

}  // namespace carom::peers
