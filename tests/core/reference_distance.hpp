// A brute-force reference for time of impact, written independently of the library: the
// distance from a ball's centre to each shape (the arc by atan2 angles, not by cross products),
// sampled densely along the motion, with bisection to refine the first contact.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"

namespace carom::testing {

inline double distance_to_segment(Vec2 p, const Segment& s) {
  const Vec2 d = s.b - s.a;
  const double len_sq = length_squared(d);
  const double f = len_sq > 0.0 ? std::clamp(dot(p - s.a, d) / len_sq, 0.0, 1.0) : 0.0;
  return length(p - (s.a + d * f));
}

inline double distance_to_arc(Vec2 p, const Arc& arc) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const Vec2 start =
      arc.center + Vec2{std::cos(arc.start_angle), std::sin(arc.start_angle)} * arc.radius;
  const Vec2 end = arc.center + Vec2{std::cos(arc.end_angle), std::sin(arc.end_angle)} * arc.radius;
  double best = std::min(length(p - start), length(p - end));
  const Vec2 offset = p - arc.center;
  const double angle = std::atan2(offset.y, offset.x);
  const double from_start = std::fmod(std::fmod(angle - arc.start_angle, kTwoPi) + kTwoPi, kTwoPi);
  if (from_start <= arc.end_angle - arc.start_angle) {
    best = std::min(best, std::abs(length(offset) - arc.radius));
  }
  return best;
}

// gap(t): distance between the surfaces at time t (negative when overlapping).
using GapFunction = std::function<double(double)>;

struct ReferenceContact {
  double t;            // first time the gap reaches zero, bisected to `tolerance`
  double deepest_gap;  // the most negative sampled gap after t (how clearly it hits)
};

// Samples gap at `samples` + 1 evenly spaced times in [0, horizon]; returns the first sign
// change from positive to non-positive, refined by bisection. Contacts that begin and end
// between two samples are missed, so callers only compare clear hits.
inline std::optional<ReferenceContact> first_contact(const GapFunction& gap, double horizon,
                                                     int samples, double tolerance) {
  double previous_t = 0.0;
  for (int i = 1; i <= samples; ++i) {
    const double t = horizon * i / samples;
    if (gap(t) <= 0.0) {
      double low = previous_t;
      double high = t;
      while (high - low > tolerance) {
        const double mid = 0.5 * (low + high);
        (gap(mid) <= 0.0 ? high : low) = mid;
      }
      return ReferenceContact{high, gap(t)};
    }
    previous_t = t;
  }
  return std::nullopt;
}

}  // namespace carom::testing
