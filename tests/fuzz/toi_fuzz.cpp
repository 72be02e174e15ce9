// libFuzzer target for the time-of-impact functions: any doubles at all (NaN, infinities,
// subnormals, 1e±308) must give either carom::InvalidArgument (exactly when an argument is
// outside its documented domain) or a valid answer: a hit with t in [0, horizon] and a unit
// normal, or no hit; never a NaN, never a crash. It also checks the promises that tie the
// queries together: ball–ball is symmetric, the step form is the time form with horizon 1, the
// batch kernel answers bit for bit as the scalar one, a segment whose ends coincide is a point,
// and a zero acceleration and growth give the straight-line answer. Under an acceleration or a
// growth, a hit at ordinary magnitudes is a real touch.
//
// Input: up to 19 doubles, 8 bytes each, little-endian bit patterns (missing bytes read as 0):
//   a.x a.y a.radius va.x va.y  b.x b.y b.radius vb.x vb.y  horizon  arc.start arc.end
//   aa.x aa.y ab.x ab.y  ga gb
// B's centre doubles as the point, the segment's start (vb its end) and the arc's centre; aa and
// ab are the accelerations of A and B, ga and gb their growths (radius per time).
// Seeds: tests/fuzz/corpus/toi/ (written by tests/fuzz/make_toi_corpus.py).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <vector>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "carom/sweep_batch.hpp"

namespace {

using carom::Arc;
using carom::Ball;
using carom::Impact;
using carom::Segment;
using carom::Vec2;

constexpr std::size_t kDoubles = 19;

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "carom toi fuzz: %s\n", what);
  std::abort();
}

void check(bool ok, const char* what) {
  if (!ok) fail(what);
}

struct Input {
  Ball a;
  Vec2 va;
  Ball b;
  Vec2 vb;
  double horizon = 0.0;
  double start_angle = 0.0;
  double end_angle = 0.0;
  Vec2 aa;
  Vec2 ab;
  double ga = 0.0;
  double gb = 0.0;
};

Input decode(const std::uint8_t* data, std::size_t size) {
  double v[kDoubles] = {};
  std::memcpy(v, data, std::min(size, sizeof v));
  return {{{v[0], v[1]}, v[2]},
          {v[3], v[4]},
          {{v[5], v[6]}, v[7]},
          {v[8], v[9]},
          v[10],
          v[11],
          v[12],
          {v[13], v[14]},
          {v[15], v[16]},
          v[17],
          v[18]};
}

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool valid_ball(const Ball& ball) {
  return finite(ball.center) && std::isfinite(ball.radius) && ball.radius > 0.0;
}
bool valid_horizon(double horizon) { return std::isfinite(horizon) && horizon >= 0.0; }
bool has_nan(Vec2 v) { return std::isnan(v.x) || std::isnan(v.y); }

void check_answer(const Impact& impact, double horizon) {
  check(!std::isnan(impact.t), "t is NaN");
  check(!has_nan(impact.a_at) && !has_nan(impact.b_at), "a position is NaN");
  check(!has_nan(impact.normal) && !has_nan(impact.point), "the normal or the point is NaN");
  if (impact.hit) {
    check(impact.t >= 0.0 && impact.t <= horizon, "a hit's t lies outside [0, horizon]");
    check(std::abs(std::hypot(impact.normal.x, impact.normal.y) - 1.0) < 1e-12,
          "a hit's normal is not a unit vector");
  } else {
    check(impact.t == 0.0, "no hit, but t is not 0");
  }
}

bool same(const Impact& x, const Impact& y) {
  return x.hit == y.hit && x.overlapping == y.overlapping && x.t == y.t && x.a_at == y.a_at &&
         x.b_at == y.b_at && x.normal == y.normal && x.point == y.point;
}

// Calls query; returns false if it threw carom::InvalidArgument. Checks that it throws exactly
// when the arguments are invalid.
template <typename Query>
bool call(Query query, bool arguments_valid, Impact& out) {
  try {
    out = query();
  } catch (const carom::InvalidArgument&) {
    check(!arguments_valid, "InvalidArgument thrown for valid arguments");
    return false;
  }
  check(arguments_valid, "invalid arguments accepted");
  return true;
}

void fuzz_ball_ball(const Input& in) {
  const bool valid = valid_ball(in.a) && valid_ball(in.b) && finite(in.va) && finite(in.vb) &&
                     valid_horizon(in.horizon);
  Impact ab;
  if (!call([&] { return carom::time_of_impact_ball_ball(in.a, in.va, in.b, in.vb, in.horizon); },
            valid, ab)) {
    return;
  }
  check_answer(ab, in.horizon);
  // Symmetric: swapping A and B gives the same contact and the opposite normal.
  const Impact ba = carom::time_of_impact_ball_ball(in.b, in.vb, in.a, in.va, in.horizon);
  check(ab.hit == ba.hit && ab.t == ba.t && ab.overlapping == ba.overlapping,
        "ball-ball is not symmetric in A and B");
  // The step form is the time form with horizon 1.
  const Impact step = carom::sweep_ball_ball(in.a, in.va, in.b, in.vb);
  check(same(step, carom::time_of_impact_ball_ball(in.a, in.va, in.b, in.vb, 1.0)),
        "the step form differs from the time form with horizon 1");
  check_answer(step, 1.0);
  // The batch kernel: the pair and its swap, bit for bit.
  const double ax[] = {in.a.center.x, in.b.center.x}, ay[] = {in.a.center.y, in.b.center.y};
  const double ar[] = {in.a.radius, in.b.radius};
  const double amx[] = {in.va.x, in.vb.x}, amy[] = {in.va.y, in.vb.y};
  const double bx[] = {in.b.center.x, in.a.center.x}, by[] = {in.b.center.y, in.a.center.y};
  const double br[] = {in.b.radius, in.a.radius};
  const double bmx[] = {in.vb.x, in.va.x}, bmy[] = {in.vb.y, in.va.y};
  double t[2] = {};
  const std::size_t hits =
      carom::sweep_ball_ball_batch({ax, ay, ar, amx, amy, bx, by, br, bmx, bmy}, t);
  const double expected = step.hit ? step.t : carom::kNoHit;
  check(t[0] == expected && t[1] == expected, "the batch differs from sweep_ball_ball");
  check(hits == (step.hit ? 2u : 0u), "the batch's hit count is wrong");
}

void fuzz_static_shapes(const Input& in) {
  const bool moving_valid = valid_ball(in.a) && finite(in.va) && valid_horizon(in.horizon);
  const Vec2 point = in.b.center;
  Impact at_point;
  const bool point_valid = moving_valid && finite(point);
  if (call([&] { return carom::time_of_impact_ball_point(in.a, in.va, point, in.horizon); },
           point_valid, at_point)) {
    check_answer(at_point, in.horizon);
    // A segment whose ends coincide is that point.
    const Impact degenerate =
        carom::time_of_impact_ball_segment(in.a, in.va, {point, point}, in.horizon);
    check(same(at_point, degenerate), "a zero-length segment differs from its point");
  }

  const Segment segment{in.b.center, in.vb};
  Impact at_segment;
  if (call([&] { return carom::time_of_impact_ball_segment(in.a, in.va, segment, in.horizon); },
           moving_valid && finite(segment.a) && finite(segment.b), at_segment)) {
    check_answer(at_segment, in.horizon);
  }

  // The arc may also be refused for an angle beyond ±2^40, a span outside [0, 2π] (with a
  // rounding allowance for a full circle) or a circle reaching beyond the double range.
  const Arc arc{in.b.center, in.b.radius, in.start_angle, in.end_angle};
  const double span = arc.end_angle - arc.start_angle;
  const double reach = std::max(std::abs(arc.center.x), std::abs(arc.center.y)) + arc.radius;
  const bool angles_in_range = std::abs(arc.start_angle) <= carom::kLargestArcAngle &&
                               std::abs(arc.end_angle) <= carom::kLargestArcAngle;
  const bool arc_surely_valid = moving_valid && valid_ball({arc.center, arc.radius}) &&
                                angles_in_range && span >= 0.0 && span <= 2.0 * std::numbers::pi &&
                                std::isfinite(reach);
  // The library takes a span up to 4 ulp of the larger angle beyond 2π for the full circle.
  const double allowance = 8.0 * std::numeric_limits<double>::epsilon() *
                           std::max({std::abs(arc.start_angle), std::abs(arc.end_angle), 7.0});
  const bool arc_surely_invalid = !moving_valid || !valid_ball({arc.center, arc.radius}) ||
                                  !angles_in_range || !std::isfinite(span) || span < 0.0 ||
                                  span > 2.0 * std::numbers::pi + allowance ||
                                  !std::isfinite(reach);
  try {
    const Impact at_arc = carom::time_of_impact_ball_arc(in.a, in.va, arc, in.horizon);
    check(!arc_surely_invalid, "an invalid arc accepted");
    check_answer(at_arc, in.horizon);
  } catch (const carom::InvalidArgument&) {
    check(!arc_surely_valid, "InvalidArgument thrown for a valid arc");
  }
}

// Whether every value is of ordinary magnitude (|x| <= 1e6, and radii and the horizon at least
// 1e-3), where a hit can be checked against the distance it claims.
bool ordinary(std::initializer_list<double> values) {
  for (const double x : values) {
    if (!(std::abs(x) <= 1e6)) return false;
  }
  return true;
}

// The same queries under accelerations: valid answers, symmetry, the straight-line answer for
// zero accelerations, and real touches at ordinary magnitudes.
void fuzz_accelerated(const Input& in) {
  const carom::Motion ma{in.va, in.aa, in.ga};
  const carom::Motion mb{in.vb, in.ab, in.gb};
  const auto valid_growth = [](double g) { return std::isfinite(g) && g >= 0.0; };
  const bool moving_valid = valid_ball(in.a) && finite(in.va) && finite(in.aa) &&
                            valid_growth(in.ga) && valid_horizon(in.horizon);
  Impact ab;
  if (call(
          [&] { return carom::time_of_impact_ball_ball(in.a, ma, in.b, mb, in.horizon); },
          moving_valid && valid_ball(in.b) && finite(in.vb) && finite(in.ab) && valid_growth(in.gb),
          ab)) {
    check_answer(ab, in.horizon);
    const Impact ba = carom::time_of_impact_ball_ball(in.b, mb, in.a, ma, in.horizon);
    check(ab.hit == ba.hit && ab.t == ba.t, "accelerated ball-ball is not symmetric in A and B");
    if (in.aa == Vec2{} && in.ab == Vec2{} && in.ga == 0.0 && in.gb == 0.0) {
      check(same(ab, carom::time_of_impact_ball_ball(in.a, in.va, in.b, in.vb, in.horizon)),
            "zero accelerations differ from the straight-line answer");
    }
    const bool checkable =
        ordinary({in.a.center.x, in.a.center.y, in.a.radius, in.va.x, in.va.y, in.aa.x, in.aa.y,
                  in.b.center.x, in.b.center.y, in.b.radius, in.vb.x, in.vb.y, in.ab.x, in.ab.y,
                  in.horizon, in.ga, in.gb}) &&
        in.a.radius >= 1e-3 && in.b.radius >= 1e-3;
    if (ab.hit && ab.t > 0.0 && checkable) {
      // At a hit after the start, the centres are the sum of the radii apart, to the rounding
      // of the positions and the time.
      const double apart = std::hypot(ab.b_at.x - ab.a_at.x, ab.b_at.y - ab.a_at.y);
      const double reach = in.a.radius + in.b.radius + (in.ga + in.gb) * ab.t;
      check(std::abs(apart - reach) <= 1e-6 * (1.0 + in.horizon) * 1e3,
            "an accelerated ball-ball hit is no touch");
    }
  }
  Impact at_point;
  if (call([&] { return carom::time_of_impact_ball_point(in.a, ma, in.b.center, in.horizon); },
           moving_valid && finite(in.b.center), at_point)) {
    check_answer(at_point, in.horizon);
  }
  Impact at_segment;
  const Segment segment{in.b.center, in.vb};
  if (call([&] { return carom::time_of_impact_ball_segment(in.a, ma, segment, in.horizon); },
           moving_valid && finite(segment.a) && finite(segment.b), at_segment)) {
    check_answer(at_segment, in.horizon);
  }
  const Arc arc{in.b.center, in.b.radius, in.start_angle, in.end_angle};
  try {
    check_answer(carom::time_of_impact_ball_arc(in.a, ma, arc, in.horizon), in.horizon);
  } catch (const carom::InvalidArgument&) {
    // The straight-line arc query above checks which arcs are refused; this one only answers.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Input input = decode(data, size);
  fuzz_ball_ball(input);
  fuzz_static_shapes(input);
  fuzz_accelerated(input);
  return 0;
}
