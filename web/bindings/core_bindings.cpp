// carom web: the core library (vec2, sweep, bounce) as seen from JavaScript. Plain value types
// become plain objects ({x, y}, {center, radius}, ...); every function is the library's own.
#include <emscripten/bind.h>

#include "carom/bounce.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"
#include "carom/vec2.hpp"
#include "carom/wall_motion.hpp"
#include "js_error.hpp"

namespace carom::web {
namespace {

Impact sweep_two_balls(const Ball& a, Vec2 move_a, const Ball& b, Vec2 move_b) {
  return sweep_ball_ball(a, move_a, b, move_b);
}

Vec2 add(Vec2 a, Vec2 b) { return a + b; }
Vec2 subtract(Vec2 a, Vec2 b) { return a - b; }
Vec2 scale(Vec2 a, double s) { return a * s; }
double vector_length(Vec2 a) { return length(a); }
// decompose is noexcept, and embind 3.1.6 binds only functions whose type has no noexcept.
Components split(Vec2 v, Vec2 axis) { return decompose(v, axis); }

}  // namespace

EMSCRIPTEN_BINDINGS(carom_core) {
  using emscripten::function;
  using emscripten::value_object;

  value_object<Vec2>("Vec2").field("x", &Vec2::x).field("y", &Vec2::y);
  value_object<Ball>("Ball").field("center", &Ball::center).field("radius", &Ball::radius);
  value_object<Segment>("Segment").field("a", &Segment::a).field("b", &Segment::b);
  value_object<WallMotion>("WallMotion")
      .field("velocity", &WallMotion::velocity)
      .field("angular_velocity", &WallMotion::angular_velocity)
      .field("pivot", &WallMotion::pivot)
      .field("duration", &WallMotion::duration);
  value_object<Arc>("Arc")
      .field("center", &Arc::center)
      .field("radius", &Arc::radius)
      .field("start_angle", &Arc::start_angle)
      .field("end_angle", &Arc::end_angle);
  value_object<Impact>("Impact")
      .field("hit", &Impact::hit)
      .field("overlapping", &Impact::overlapping)
      .field("t", &Impact::t)
      .field("a_at", &Impact::a_at)
      .field("b_at", &Impact::b_at)
      .field("normal", &Impact::normal)
      .field("point", &Impact::point);
  value_object<BounceResult>("BounceResult")
      .field("velocity_a", &BounceResult::velocity_a)
      .field("velocity_b", &BounceResult::velocity_b)
      .field("impulse", &BounceResult::impulse);
  value_object<WallBounceResult>("WallBounceResult")
      .field("velocity", &WallBounceResult::velocity)
      .field("impulse", &WallBounceResult::impulse);
  value_object<Components>("Components")
      .field("along", &Components::along)
      .field("across", &Components::across);

  function("sweep_ball_ball", &guarded<&sweep_two_balls>::call);
  function("sweep_ball_point", &guarded<&sweep_ball_point>::call);
  function("sweep_ball_segment", &guarded<&sweep_ball_segment>::call);
  function("sweep_ball_arc", &guarded<&sweep_ball_arc>::call);
  function("bounce", &guarded<&bounce>::call);
  function("bounce_equal_mass", &guarded<&bounce_equal_mass>::call);
  function("bounce_off_static", &guarded<&bounce_off_static>::call);
  function("decompose", &split);
  function("add", &add);
  function("subtract", &subtract);
  function("scale", &scale);
  function("length", &vector_length);
}

}  // namespace carom::web
