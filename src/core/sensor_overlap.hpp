// carom internal: when a moving ball starts or stops overlapping a sensor's shape (a segment, an
// arc or a disc), for any motion the gap polynomials describe (straight lines, gravity's
// parabolas, growing radii). The shape's neighbourhood is a union of pieces, each cut out by
// polynomial signs (a disc about each end point; a slab along a segment; a band in a wedge along
// an arc), so the times of overlap within a horizon are unions and intersections of the times
// polynomials are positive, and each sign change is found by gap_polynomial.hpp's certified
// closings: none is skipped, however fast the ball. Derivation: docs/derivation.md, "Sensors".
#pragma once

#include <array>
#include <cstddef>

#include "arc_frame.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"

namespace carom::detail {

// Sorted, disjoint closed intervals of time [start, end], each of positive length.
class TimeSpans {
 public:
  // Enough for any region here: every bound is a sign change of one of the pieces' polynomials
  // (an arc's region has at most 24 of them: two end discs of 3 each, a band of 2×3 plus a
  // linear bound, a wedge of 2×2), and a union or an intersection never adds a bound.
  static constexpr std::size_t kCapacity = 16;

  void add(double start, double end);  // after every span added so far, start >= their ends
  [[nodiscard]] std::size_t size() const { return count_; }
  [[nodiscard]] double start(std::size_t k) const { return bounds_[2 * k]; }
  [[nodiscard]] double end(std::size_t k) const { return bounds_[2 * k + 1]; }

  [[nodiscard]] static TimeSpans unite(const TimeSpans& a, const TimeSpans& b);
  [[nodiscard]] static TimeSpans intersect(const TimeSpans& a, const TimeSpans& b);
  // [0, horizon] less the spans.
  [[nodiscard]] TimeSpans complement(double horizon) const;

 private:
  std::array<double, 2 * kCapacity> bounds_{};
  std::size_t count_ = 0;
};

// A sensor's shape: a segment, an arc (prepared), or a disc.
struct SensorShape {
  enum class Kind : unsigned char { segment, arc, disc };
  Kind kind = Kind::segment;
  Segment segment;
  Arc arc_as_given;  // the arc (with `arc`, its prepared frame)
  ArcFrame arc;
  Ball disc;
};

// The times within [0, horizon] (horizon may be +infinity) at which the ball, moving with
// `motion`, overlaps the shape: its centre closer to the shape than its radius (at that time).
[[nodiscard]] TimeSpans overlap_times(const Ball& ball, const Motion& motion,
                                      const SensorShape& shape, double horizon);

// The next change of a ball's overlap with a sensor: from `inside` (the overlap as last recorded)
// to the other state, at t in [0, horizon]. A recorded state that the motion does not bear out
// at 0 changes at 0 (a ball placed into or out of the sensor), so enters and exits alternate.
// `now` is the clock's time at t = 0: a span that starts or ends at a t the clock cannot tell
// from 0 (now + t == now) counts as starting or ending at 0, so that an enter is never followed
// by an exit at the same instant (the ball, brought to the enter's time, may sit a rounding
// outside the shape) nor an exit by an enter. Computed again from the same ball state and the
// same recorded state, it gives the same answer, so changes at one instant cannot repeat. Within
// a horizon the clock cannot tell from 0 nothing is decided (no change).
struct SensorChange {
  bool found = false;
  double t = 0.0;
};
[[nodiscard]] SensorChange next_sensor_change(const Ball& ball, const Motion& motion,
                                              const SensorShape& shape, bool inside, double horizon,
                                              double now = 0.0);

}  // namespace carom::detail
