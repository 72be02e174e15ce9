// carom's World in the peers benchmark: a closed box (Boundary::box), the scene's gravity and
// restitution, and everything else at its defaults (the world chooses its own grid; under gravity
// the rest height is the default thousandth of a radius). Nothing is tuned.
#include <algorithm>
#include <memory>
#include <vector>

#include "carom/world.hpp"
#include "engine.hpp"

namespace carom::peers {
namespace {

class CaromEngine final : public Engine {
 public:
  explicit CaromEngine(const Scene& scene) : world_(world_def(scene)) {
    ids_.reserve(scene.balls.size());
    radii_.reserve(scene.balls.size());
    for (const SceneBall& ball : scene.balls) {
      BallDef def;
      def.position = ball.position;
      def.velocity = ball.velocity;
      def.radius = ball.radius;
      def.mass = ball.mass;
      ids_.push_back(world_.add_ball(def));
      radii_.push_back(ball.radius);
      if (scene_index_.size() <= ids_.back().index) scene_index_.resize(ids_.back().index + 1);
      scene_index_[ids_.back().index] = static_cast<std::uint32_t>(ids_.size() - 1);
    }
  }

  void step(double dt) override { world_.step(dt); }

  void read(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    for (std::size_t i = 0; i < ids_.size(); ++i) {
      positions[i] = world_.position(ids_[i]);
      velocities[i] = world_.velocity(ids_[i]);
    }
  }

  // Each contact of the last step bends the path of its disks there: the centre of a disk at a
  // contact is the contact point less its radius along the normal (which points from a to b).
  void path_breaks(double dt, std::vector<PathBreak>& breaks) const override {
    const double step_start = world_.time() - dt;
    for (const ContactEvent& contact : world_.contacts()) {
      const double fraction = std::clamp((contact.time - step_start) / dt, 0.0, 1.0);
      const std::uint32_t a = scene_index_[contact.a.index];
      breaks.push_back({a, fraction, contact.point - contact.normal * radii_[a]});
      if (contact.kind == ContactKind::ball_ball) {
        const std::uint32_t b = scene_index_[contact.b.index];
        breaks.push_back({b, fraction, contact.point + contact.normal * radii_[b]});
      }
    }
  }

  [[nodiscard]] std::int64_t contact_count() const override {
    return static_cast<std::int64_t>(world_.collision_count());
  }

 private:
  static WorldDef world_def(const Scene& scene) {
    WorldDef def;
    def.boundary = Boundary::box;
    def.lower = scene.lower;
    def.upper = scene.upper;
    def.restitution = scene.restitution;
    def.gravity = scene.gravity;
    return def;
  }

  World world_;
  std::vector<BallId> ids_;
  std::vector<double> radii_;
  std::vector<std::uint32_t> scene_index_;  // by the ball's slot
};

}  // namespace

std::unique_ptr<Engine> make_carom_engine(const Scene& scene) {
  return std::make_unique<CaromEngine>(scene);
}

}  // namespace carom::peers
