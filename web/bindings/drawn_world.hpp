// carom web: a carom::World together with what a page needs to draw and handle it: the walls it
// was given (the World keeps no list of their shapes), its balls in the order they were added,
// and a flat buffer of their positions that JavaScript reads without a call per ball.
//
// Pages build one shape by shape (add_ball, add_segment, add_arc) and fill it with generated
// balls (lattice_filling.hpp); a scene file's contents can be handed over the same way.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"
#include "carom/world.hpp"

namespace carom::web {

class DrawnWorld {
 public:
  explicit DrawnWorld(const WorldDef& def);

  // ---- building ----
  // Returns the ball's index (0, 1, ... in the order added).
  int add_ball(Vec2 position, Vec2 velocity, double radius, double mass);
  void add_segment(const Segment& segment);
  void add_arc(const Arc& arc);

  // ---- running ----
  // carom::World::step; returns the time advanced.
  double step(double dt);
  // Multiplies every velocity by factor (> 0): the gas runs hotter or colder.
  void scale_speeds(double factor);

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
  // x, y, radius and speed of each ball, four floats per ball in the order added. The view is
  // valid until the next call into the module (memory may grow).
  [[nodiscard]] std::span<const float> snapshot();
  [[nodiscard]] int ball_count() const;  // not noexcept: embind 3.1.6 cannot bind those
  [[nodiscard]] Vec2 position(int index) const;
  [[nodiscard]] const std::vector<Segment>& segments() const noexcept { return segments_; }
  [[nodiscard]] const std::vector<Arc>& arcs() const noexcept { return arcs_; }
  [[nodiscard]] const WorldDef& def() const noexcept { return def_; }
  [[nodiscard]] const World& world() const noexcept { return world_; }
  // Contacts resolved by the last step.
  [[nodiscard]] int last_step_contacts() const;

 private:
  [[nodiscard]] BallId id(int index) const;

  WorldDef def_;
  World world_;
  std::vector<BallId> ids_;
  std::vector<Segment> segments_;
  std::vector<Arc> arcs_;
  std::vector<std::optional<Vec2>> held_velocity_;  // set while a ball is held
  std::vector<float> snapshot_;
};

}  // namespace carom::web
