#include "wall.hpp"

#include <algorithm>
#include <cmath>

#include "carom/geometry.hpp"
#include "core/accelerated_sweep.hpp"

namespace carom::detail {

Wall make_segment_wall(const Segment& segment) {
  Wall wall;
  wall.segment = segment;
  return wall;
}

Wall make_arc_wall(const char* function, const Arc& arc) {
  Wall wall;
  wall.is_arc = true;
  wall.arc = arc;
  wall.frame = make_arc_frame(function, arc);
  return wall;
}

Wall make_disc_sensor(const Ball& disc, SensorRole role) {
  Wall wall;
  wall.is_disc = true;
  wall.disc = disc;
  wall.sensor = role;
  return wall;
}

double path_time(const Wall& wall, double t) {
  return std::max(0.0, std::min(t, wall.path.until) - wall.path.start);
}

RigidMotion motion_from(const Wall& wall, double t) {
  RigidMotion rigid = wall.path.rigid;
  rigid.pivot = rigid.pivot + rigid.velocity * path_time(wall, t);
  if (!wall.moves_at(t)) {
    rigid.velocity = Vec2{};
    rigid.angular_velocity = 0.0;
  }
  return rigid;
}

void place_at(Wall& wall, double t) {
  if (!wall.moving) return;
  const double elapsed = path_time(wall, t);
  if (wall.is_arc) {
    wall.arc = wall.path.arc;
    wall.frame = wall.path.frame;
    carry_arc(wall.arc, wall.frame, wall.path.rigid, elapsed);
  } else {
    wall.segment = carried_segment(wall.path.segment, wall.path.rigid, elapsed);
  }
}

void set_path(Wall& wall, double t, const RigidMotion& rigid, double duration) {
  place_at(wall, t);
  wall.moving = true;
  wall.path.rigid = rigid;
  wall.path.start = t;
  wall.path.until = t + duration;
  wall.path.segment = wall.segment;
  wall.path.arc = wall.arc;
  wall.path.frame = wall.frame;
  wall.path.reach = path_reach(wall);
  wall.path.speed = length(rigid.velocity);
}

double path_reach(const Wall& wall) {
  const WallPath& path = wall.path;
  const Vec2 pivot = path.rigid.pivot;
  return wall.is_arc ? length(path.frame.center - pivot) + path.frame.radius
                     : std::max(length(path.segment.a - pivot), length(path.segment.b - pivot));
}

SensorRole sensor_role(SensorAction action) {
  return action == SensorAction::remove_ball ? SensorRole::remove_ball : SensorRole::report;
}

SensorShape sensor_shape(const Wall& wall) {
  SensorShape shape;
  if (wall.is_disc) {
    shape.kind = SensorShape::Kind::disc;
    shape.disc = wall.disc;
  } else if (wall.is_arc) {
    shape.kind = SensorShape::Kind::arc;
    shape.arc_as_given = wall.arc;
    shape.arc = wall.frame;
  } else {
    shape.kind = SensorShape::Kind::segment;
    shape.segment = wall.segment;
  }
  return shape;
}

Vec2 nearest_point(const Wall& wall, Vec2 p) {
  if (wall.is_disc) {
    // The disc's nearest point (p itself inside it).
    const Vec2 out = p - wall.disc.center;
    const double distance = length(out);
    return distance <= wall.disc.radius ? p
                                        : wall.disc.center + out * (wall.disc.radius / distance);
  }
  return wall.is_arc ? wall.frame.nearest(p) : carom::nearest_point(wall.segment, p);
}

bool inside_arc(const Wall& wall, Vec2 p) {
  if (!wall.is_arc) return false;
  const Vec2 out = p - wall.frame.center;
  const double distance = length(out);
  return distance > 0.0 && distance < wall.frame.radius && wall.frame.contains(out / distance);
}

Impact time_of_impact(const Wall& wall, const Ball& ball, Vec2 velocity, double horizon) {
  return wall.is_arc ? time_of_impact_ball_arc(ball, velocity, wall.arc, horizon)
                     : time_of_impact_ball_segment(ball, velocity, wall.segment, horizon);
}

Impact time_of_impact(const Wall& wall, const Ball& ball, const Motion& motion, double horizon) {
  if (motion.acceleration == Vec2{} && motion.growth == 0.0) {
    return time_of_impact(wall, ball, motion.velocity, horizon);
  }
  return wall.is_arc ? accelerated_ball_arc(ball, motion, wall.frame, horizon)
                     : accelerated_ball_segment(ball, motion, wall.segment, horizon);
}

namespace {

// The ray's unit direction, reversed: the normal of a wall met head-on.
Vec2 facing(Vec2 d) { return d == Vec2{} ? Vec2{} : normalized(-d); }

RayCrossing ray_crossing_segment(const Segment& segment, Vec2 o, Vec2 d) {
  const Vec2 e = segment.b - segment.a;
  const Vec2 ao = segment.a - o;
  const double denominator = cross(d, e);
  if (denominator != 0.0) {
    // o + s·d = a + u·e, both in [0, 1].
    const double s = cross(ao, e) / denominator;
    const double u = cross(ao, d) / denominator;
    if (!(s >= 0.0 && s <= 1.0 && u >= 0.0 && u <= 1.0)) return {};
    Vec2 normal = normalized(left_normal(e));
    if (dot(normal, d) > 0.0) normal = -normal;
    return {true, s, segment.a + e * u, normal};
  }
  // Parallel, or a segment that is a point, or a ray that does not move: only on one line can
  // they meet, where the ray enters the segment's extent along it.
  if (cross(ao, d) != 0.0 || cross(ao, e) != 0.0) return {};
  const double dd = dot(d, d);
  if (dd == 0.0) {
    const bool on = dot(o - segment.a, e) >= 0.0 && dot(o - segment.b, e) <= 0.0;
    return on && carom::nearest_point(segment, o) == o ? RayCrossing{true, 0.0, o, Vec2{}}
                                                       : RayCrossing{};
  }
  const double sa = dot(segment.a - o, d) / dd;
  const double sb = dot(segment.b - o, d) / dd;
  if (std::min(sa, sb) <= 0.0 && std::max(sa, sb) >= 0.0) return {true, 0.0, o, facing(d)};
  const double s = std::min(sa, sb);
  if (!(s > 0.0 && s <= 1.0)) return {};
  return {true, s, sa < sb ? segment.a : segment.b, facing(d)};
}

RayCrossing ray_crossing_arc(const ArcFrame& arc, Vec2 o, Vec2 d) {
  // |o + s·d − c|² = R²: A·s² + 2·B·s + C = 0, solved with the cancellation-free pair of roots.
  const Vec2 f = o - arc.center;
  const double a = dot(d, d);
  const double b = dot(f, d);
  const double c = dot(f, f) - arc.radius * arc.radius;
  const auto meets_at = [&](double s) -> RayCrossing {
    if (!(s >= 0.0 && s <= 1.0)) return {};
    const Vec2 point = o + d * s;
    const Vec2 out = point - arc.center;
    const double distance = length(out);
    if (!(distance > 0.0) || !arc.contains(out / distance)) return {};
    Vec2 normal = out / distance;
    if (dot(normal, d) > 0.0) normal = -normal;
    return {true, s, point, normal};
  };
  if (a == 0.0) return c == 0.0 ? meets_at(0.0) : RayCrossing{};
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return {};
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  double first = q / a;
  double second = q != 0.0 ? c / q : first;
  if (second < first) std::swap(first, second);
  const RayCrossing near = meets_at(first);
  return near.hit ? near : meets_at(second);
}

}  // namespace

RayCrossing ray_crossing(const Wall& wall, Vec2 o, Vec2 d) {
  return wall.is_arc ? ray_crossing_arc(wall.frame, o, d)
                     : ray_crossing_segment(wall.segment, o, d);
}

void bounds(const Wall& wall, Vec2& lower, Vec2& upper) {
  if (wall.is_disc) {
    lower = wall.disc.center - Vec2{wall.disc.radius, wall.disc.radius};
    upper = wall.disc.center + Vec2{wall.disc.radius, wall.disc.radius};
    return;
  }
  if (wall.is_arc) {
    lower = wall.arc.center - Vec2{wall.arc.radius, wall.arc.radius};
    upper = wall.arc.center + Vec2{wall.arc.radius, wall.arc.radius};
    return;
  }
  lower = {std::min(wall.segment.a.x, wall.segment.b.x),
           std::min(wall.segment.a.y, wall.segment.b.y)};
  upper = {std::max(wall.segment.a.x, wall.segment.b.x),
           std::max(wall.segment.a.y, wall.segment.b.y)};
}

}  // namespace carom::detail
