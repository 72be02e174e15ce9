// Chipmunk 7 in the peers benchmark. Set as the scene asks: the scene's gravity, damping 1
// (none; the default), friction 0 on every shape, and elasticity the square root of the scene's
// restitution on every shape (Chipmunk multiplies two shapes' elasticities, so every pair, walls
// included, gets the scene's; it has no restitution threshold: every contact bounces), circles
// whose moment is a uniform disk's (without friction nothing turns them). Left at Chipmunk's
// defaults: 10 solver iterations, the collision slop (0.1 length units of overlap allowed), the
// collision bias, the bounding-box-tree broad phase, and no sleeping, unless the scene allows it:
// then bodies sleep after half a second (Box2D's b2_timeToSleep) below Chipmunk's idle speed,
// which it derives from gravity (|g|·dt, 0.16 here), by components of touching bodies. With the
// environment variable CAROM_PEERS_CHIPMUNK_HASH set, Chipmunk's spatial hash (cells one diameter
// wide, ten per disk) replaces the tree; on the gas it was slower (7.2 against 2.7 ms per step at
// N = 10⁴, packing 0.2; about the same at 10⁵), so the report keeps the default. Chipmunk has no
// continuous collision: a `bullet` ball is an ordinary ball. The walls are static boxes one
// length unit thick outside the box.
#include <chipmunk/chipmunk.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "engine.hpp"

namespace carom::peers {
namespace {

constexpr double kWallThickness = 1.0;
// How long a body must stay idle before it sleeps, when the scene allows sleeping: Box2D's
// b2_timeToSleep, so that the two peers sleep alike.
constexpr double kTimeToSleep = 0.5;

class ChipmunkEngine final : public Engine {
 public:
  explicit ChipmunkEngine(const Scene& scene)
      : space_(cpSpaceNew()), elasticity_(std::sqrt(scene.restitution)) {
    cpSpaceSetGravity(space_, cpv(scene.gravity.x, scene.gravity.y));
    if (scene.sleeping) cpSpaceSetSleepTimeThreshold(space_, kTimeToSleep);
    if (std::getenv("CAROM_PEERS_CHIPMUNK_HASH") != nullptr) {
      cpSpaceUseSpatialHash(space_, 1.0, static_cast<int>(10 * scene.balls.size()));
    }
    add_walls(scene);
    bodies_.reserve(scene.balls.size());
    for (const SceneBall& ball : scene.balls) {
      cpBody* body = cpBodyNew(ball.mass, cpMomentForCircle(ball.mass, 0.0, ball.radius, cpvzero));
      cpBodySetPosition(body, cpv(ball.position.x, ball.position.y));
      cpBodySetVelocity(body, cpv(ball.velocity.x, ball.velocity.y));
      cpSpaceAddBody(space_, body);
      bodies_.push_back(body);
      add_shape(cpCircleShapeNew(body, ball.radius, cpvzero));
    }
  }

  ~ChipmunkEngine() override {
    for (cpShape* shape : shapes_) {
      cpSpaceRemoveShape(space_, shape);
      cpShapeFree(shape);
    }
    for (cpBody* body : bodies_) {
      cpSpaceRemoveBody(space_, body);
      cpBodyFree(body);
    }
    cpSpaceFree(space_);
  }
  ChipmunkEngine(const ChipmunkEngine&) = delete;
  ChipmunkEngine& operator=(const ChipmunkEngine&) = delete;
  ChipmunkEngine(ChipmunkEngine&&) = delete;
  ChipmunkEngine& operator=(ChipmunkEngine&&) = delete;

  void step(double dt) override { cpSpaceStep(space_, dt); }

  void read(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const cpVect p = cpBodyGetPosition(bodies_[i]);
      const cpVect v = cpBodyGetVelocity(bodies_[i]);
      positions[i] = {p.x, p.y};
      velocities[i] = {v.x, v.y};
    }
  }

 private:
  void add_shape(cpShape* shape) {
    cpShapeSetElasticity(shape, elasticity_);
    cpShapeSetFriction(shape, 0.0);
    cpSpaceAddShape(space_, shape);
    shapes_.push_back(shape);
  }

  void add_walls(const Scene& scene) {
    cpBody* ground = cpSpaceGetStaticBody(space_);
    const double l = scene.lower.x;
    const double b = scene.lower.y;
    const double r = scene.upper.x;
    const double t = scene.upper.y;
    const double w = kWallThickness;
    add_shape(cpBoxShapeNew2(ground, cpBBNew(l - w, b - w, r + w, b), 0.0));  // bottom
    add_shape(cpBoxShapeNew2(ground, cpBBNew(l - w, t, r + w, t + w), 0.0));  // top
    add_shape(cpBoxShapeNew2(ground, cpBBNew(l - w, b, l, t), 0.0));          // left
    add_shape(cpBoxShapeNew2(ground, cpBBNew(r, b, r + w, t), 0.0));          // right
  }

  cpSpace* space_;
  double elasticity_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
};

}  // namespace

std::unique_ptr<Engine> make_chipmunk_engine(const Scene& scene) {
  return std::make_unique<ChipmunkEngine>(scene);
}

std::string chipmunk_version() { return std::string("Chipmunk ") + cpVersionString; }

}  // namespace carom::peers
