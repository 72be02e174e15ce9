// carom internal: a static wall of the world, a segment or an arc, or a sensor (a segment, an
// arc or a disc that reports overlaps rather than bounce), with the few questions the engine asks
// of it.
#pragma once

#include <cstdint>

#include "carom/sensor.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"
#include "core/arc_frame.hpp"
#include "core/sensor_overlap.hpp"

namespace carom::detail {

// Whether a wall is a sensor, and what it does to a ball that enters it.
enum class SensorRole : std::uint8_t { none, report, remove_ball };

struct Wall {
  bool is_arc = false;
  bool is_disc = false;  // a sensor's disc (never a solid wall)
  SensorRole sensor = SensorRole::none;
  Segment segment;
  Arc arc;
  ArcFrame frame;            // is_arc only
  Ball disc;                 // is_disc only
  std::uint32_t filter = 0;  // its CollisionFilter's number in the world's FilterTable

  // Whether balls bounce off it (it is no sensor).
  [[nodiscard]] bool solid() const { return sensor == SensorRole::none; }
};

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
