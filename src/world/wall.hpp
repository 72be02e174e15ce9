// carom internal: a wall of the world, a segment or an arc, or a sensor (a segment, an arc or a
// disc that reports overlaps rather than bounce), with the few questions the engine asks of it.
// A wall may move rigidly (carom/wall_motion.hpp): it then keeps the path it moves on, and its
// shape is where the path had carried it when last brought up to date.
#pragma once

#include <cstdint>
#include <limits>

#include "carom/sensor.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"
#include "core/arc_frame.hpp"
#include "core/rigid_sweep.hpp"
#include "core/sensor_overlap.hpp"

namespace carom::detail {

// Whether a wall is a sensor, and what it does to a ball that enters it.
enum class SensorRole : std::uint8_t { none, report, remove_ball };

// A moving wall's path: the rigid motion from `start` (its pivot as at start) until `until`, and
// the shape as it was at start.
struct WallPath {
  RigidMotion rigid;
  double start = 0.0;
  double until = std::numeric_limits<double>::infinity();
  double reach = 0.0;  // the farthest point of the wall from the pivot
  double speed = 0.0;  // the pivot's
  Segment segment;
  Arc arc;
  ArcFrame frame;
};

struct Wall {
  bool is_arc = false;
  bool is_disc = false;  // a sensor's disc (never a solid wall)
  // Whether it has a path (set_wall_motion, even one that has ended): such a wall is not listed
  // in the grid's cells, every ball's prediction asks about it.
  bool moving = false;
  bool removed = false;  // (remove_wall) nothing meets it, nothing sees it
  SensorRole sensor = SensorRole::none;
  Segment segment;
  Arc arc;
  ArcFrame frame;            // is_arc only
  Ball disc;                 // is_disc only
  std::uint32_t filter = 0;  // its CollisionFilter's number in the world's FilterTable
  WallPath path;             // moving only

  // Whether balls bounce off it (it is no sensor, and has not been removed).
  [[nodiscard]] bool solid() const { return sensor == SensorRole::none && !removed; }
  // Whether the grid's cells list it.
  [[nodiscard]] bool listed() const { return !moving && !removed; }
  // Whether it is moving at time t (a path that has not ended, with a velocity or a turn).
  [[nodiscard]] bool moves_at(double t) const {
    return moving && t < path.until &&
           (path.rigid.velocity != Vec2{} || path.rigid.angular_velocity != 0.0);
  }
};

// The time a moving wall's path has run for at t (it stops at its end).
[[nodiscard]] double path_time(const Wall& wall, double t);
// The rigid motion of a moving wall from t on (its pivot as at t).
[[nodiscard]] RigidMotion motion_from(const Wall& wall, double t);
// Brings a moving wall's shape to where its path has carried it at t.
void place_at(Wall& wall, double t);
// The farthest point of a moving wall's shape at its path's start from the pivot then.
[[nodiscard]] double path_reach(const Wall& wall);
// A moving wall's path, from t on: the shape as at t, which moves by `rigid` for `duration`.
void set_path(Wall& wall, double t, const RigidMotion& rigid, double duration);

[[nodiscard]] Wall make_segment_wall(const Segment& segment);
[[nodiscard]] Wall make_arc_wall(const char* function, const Arc& arc);
[[nodiscard]] Wall make_disc_sensor(const Ball& disc, SensorRole role);
[[nodiscard]] SensorRole sensor_role(SensorAction action);

// A sensor's shape, as the overlap times take it.
[[nodiscard]] SensorShape sensor_shape(const Wall& wall);

// The point of the wall nearest to p.
[[nodiscard]] Vec2 nearest_point(const Wall& wall, Vec2 p);

// Whether a ball centred at p meets the wall on the inside of an arc (rather than its outside,
// an end point or a segment): p is inside the arc's circle and its nearest point of the whole
// circle, straight out from the centre, lies within the span.
[[nodiscard]] bool inside_arc(const Wall& wall, Vec2 p);

// The first approaching contact of a ball moving with velocity within [0, horizon].
[[nodiscard]] Impact time_of_impact(const Wall& wall, const Ball& ball, Vec2 velocity,
                                    double horizon);

// The same for a ball that accelerates (gravity).
[[nodiscard]] Impact time_of_impact(const Wall& wall, const Ball& ball, const Motion& motion,
                                    double horizon);

// Where the segment from o to o + d first meets the wall (either side, its ends included): the
// fraction s in [0, 1], the point, and the wall's unit normal there turned to face the ray (a
// ray along a segment's line meets it head-on: the normal is −d's direction).
struct RayCrossing {
  bool hit = false;
  double s = 0.0;
  Vec2 point;
  Vec2 normal;
};
[[nodiscard]] RayCrossing ray_crossing(const Wall& wall, Vec2 o, Vec2 d);

// An axis-aligned box holding the whole wall.
void bounds(const Wall& wall, Vec2& lower, Vec2& upper);

}  // namespace carom::detail
