// carom web: a carom::World together with what a page needs to draw and handle it: its balls in
// the order they were added, and a flat buffer of their positions that JavaScript reads without a
// call per ball.
//
// Pages build one shape by shape (add_ball, add_segment, add_arc) and fill it with generated
// balls (lattice_filling.hpp), or load a scene file (scene_loading.hpp): then the world is the
// scene library's SceneWorld, stepped with carom::step_scene so that pockets swallow balls. A
// ball keeps its index when it falls into a pocket or the page removes it (remove_ball); it is
// then no longer in the world.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "carom/scene.hpp"
#include "carom/shapes.hpp"
#include "carom/vec2.hpp"
#include "carom/world.hpp"

namespace carom::web {

class DrawnWorld {
 public:
  explicit DrawnWorld(const WorldDef& def);
  // The world of a loaded scene: its balls (in scene order), walls, pockets and colours.
  explicit DrawnWorld(SceneWorld scene_world);
  // A world built elsewhere (a packing's start, compression.hpp): its balls indexed in the order
  // of World::balls(), the order carom::science's contact network uses.
  explicit DrawnWorld(World world);

  // A world that goes on exactly as this one would (World::save and World::load: the same calls
  // give bit-identical results), its balls, pockets and colours indexed as here: a page tries a
  // shot on the copy first (the "Pool" page's prediction).
  [[nodiscard]] DrawnWorld copy() const;

  // ---- building ----
  // Returns the ball's index (0, 1, ... in the order added).
  int add_ball(Vec2 position, Vec2 velocity, double radius, double mass);
  // Its wall id (for set_wall_motion).
  int add_segment(const Segment& segment);
  // A segment sensor (World::add_sensor): balls pass it, each enter and exit recorded
  // (step_sensor_events); `removes`: the ball that enters is removed (a drain). Its wall id.
  int add_sensor(const Segment& segment, bool removes);
  void add_arc(const Arc& arc);
  // Takes the ball out of the world (a pinball's drain); its index stays taken, so the indices of
  // the others do not change.
  void remove_ball(int index);

  // ---- running ----
  // carom::step_scene (carom::World::step when there are no pockets); returns the time advanced.
  double step(double dt);
  // Multiplies every velocity by factor (> 0): the gas runs hotter or colder.
  void scale_speeds(double factor);
  // carom::World::set_velocity (a launched ball); a held ball keeps it for its release.
  void set_velocity(int index, Vec2 velocity);
  // carom::World::set_gravity: from the world's time on.
  void set_gravity(Vec2 gravity);

  // ---- dragging ----
  // The ball whose disc contains point (the last added among several), or -1.
  [[nodiscard]] int ball_at(Vec2 point) const;
  // Holds the ball still (velocity zero) until release; its velocity is kept for release.
  void hold(int index);
  // Moves the held ball towards point with carom::Placement::nearest_free: it stops where it
  // would first touch another ball or a wall. Returns where it is.
  Vec2 drag_to(int index, Vec2 point);
  // Gives the ball back the velocity it had when it was taken hold of.
  void release(int index);

  // ---- reading ----
  // x, y, radius and speed of each ball, four floats per ball in the order added (radius 0 for a
  // ball a pocket took). The view is valid until the next call into the module (memory may grow).
  [[nodiscard]] std::span<const float> snapshot();
  // Balls in the world now (potted balls not counted); not noexcept: embind 3.1.6 cannot bind
  // those.
  [[nodiscard]] int ball_count() const;
  // Each ball's colour as the scene gives it (CSS colour text), "" when unset; by index.
  [[nodiscard]] const std::vector<std::string>& colors() const noexcept { return colors_; }
  [[nodiscard]] const std::vector<ScenePocket>& pockets() const noexcept { return pockets_; }
  [[nodiscard]] Vec2 position(int index) const;
  // As the world has it: zero while the ball is held.
  [[nodiscard]] Vec2 velocity(int index) const;
  // The walls added (the segments, then polylines' segments, and arcs of a scene), a box's
  // boundary left out.
  [[nodiscard]] std::vector<Segment> segments() const;
  [[nodiscard]] std::vector<Arc> arcs() const;
  [[nodiscard]] const WorldDef& def() const noexcept { return scene_world_.world.def(); }
  [[nodiscard]] const World& world() const noexcept { return scene_world_.world; }
  // For what a page runs through the library beyond step (a compression's frame).
  [[nodiscard]] World& world() noexcept { return scene_world_.world; }
  // Contacts resolved by the last step.
  [[nodiscard]] int last_step_contacts() const;
  // Every contact of the last step, in the order they happened, pockets' included: a world with
  // pockets (or a thermostat) is stepped in pieces, and World::contacts() holds only the last
  // piece's, so step keeps them all for such a world (and for any other reads the World's own).
  [[nodiscard]] std::span<const ContactEvent> step_contacts() const noexcept;
  // The sensors' enters and exits during the last step, in order.
  [[nodiscard]] std::span<const SensorEvent> step_sensor_events() const noexcept {
    return scene_world_.sensor_events;
  }

  // ---- naming balls (for the queries and contacts, world_queries.hpp) ----
  // The World's handle of the ball at index; throws InvalidArgument as every call by index does.
  [[nodiscard]] BallId handle(int index) const { return id(index); }
  // The index of a ball of the world, or of one a pocket or a sensor took during the last step
  // (so that step_contacts and step_sensor_events can name it); -1 for a pocket or a ball this
  // DrawnWorld does not list.
  [[nodiscard]] int index_of(BallId ball) const;
  // The index of a pocket (in pockets()) whose sensor is wall `wall`, or -1 for any other wall.
  [[nodiscard]] int pocket_of(WallId wall) const;

 private:
  DrawnWorld(const DrawnWorld& original, World world);
  [[nodiscard]] BallId id(int index) const;
  [[nodiscard]] WallId first_own_wall() const;
  [[nodiscard]] bool present(BallId ball) const;

  // The world and its balls by index (scene_world_.balls; null once potted or removed), pockets
  // included.
  SceneWorld scene_world_;
  std::vector<std::string> colors_;
  std::vector<ScenePocket> pockets_;
  std::vector<std::optional<Vec2>> held_velocity_;  // set while a ball is held
  std::vector<float> snapshot_;
  std::vector<ContactEvent> step_contacts_;  // the last step's, when it went in pieces
  // The balls by index as the last step began, when it went in pieces or the world has sensors
  // (a pocket or a sensor may take a ball that step_contacts or step_sensor_events name).
  std::vector<BallId> step_balls_;
  bool has_sensors_ = false;
  bool step_in_pieces_ = false;
};

}  // namespace carom::web
