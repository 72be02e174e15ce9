// carom: nearest points and distances to the static shapes, and the arithmetic of a periodic cell
// — the very functions the World uses, so that a caller's checks (a scene's overlaps, a drag, a
// measurement's minimum image) agree with the engine's to the bit.
#pragma once

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"

namespace carom {

// The point of the segment nearest to p (a for a segment whose ends coincide).
[[nodiscard]] Vec2 nearest_point(const Segment& segment, Vec2 p);
// The point of the arc nearest to p: straight out from the centre when that direction lies in the
// arc's span, otherwise the nearer end point. Throws carom::InvalidArgument for an arc that
// breaks the rules of shapes.hpp.
[[nodiscard]] Vec2 nearest_point(const Arc& arc, Vec2 p);
[[nodiscard]] double distance(const Segment& segment, Vec2 p);
[[nodiscard]] double distance(const Arc& arc, Vec2 p);

// A periodic cell [lower, upper) whose opposite edges are the same: what a periodic World's
// boundary is (WorldDef::lower, upper).
class PeriodicCell {
 public:
  constexpr PeriodicCell() = default;
  constexpr PeriodicCell(Vec2 lower, Vec2 upper)
      : lower_(lower), upper_(upper), period_(upper - lower), half_period_(period_ * 0.5) {}

  [[nodiscard]] constexpr Vec2 lower() const noexcept { return lower_; }
  [[nodiscard]] constexpr Vec2 upper() const noexcept { return upper_; }
  [[nodiscard]] constexpr Vec2 period() const noexcept { return period_; }

  // The shortest of the periodic images of an offset d (ties to either). An offset between two
  // points of the cell is less than a period long and needs one correction at most: that path
  // is the engine's, a compare and a subtraction an axis; longer offsets are reduced by whole
  // periods.
  [[nodiscard]] constexpr Vec2 minimum_image(Vec2 d) const noexcept {
    return {image(d.x, period_.x, half_period_.x), image(d.y, period_.y, half_period_.y)};
  }

  // p moved by whole periods into [lower, upper).
  [[nodiscard]] Vec2 wrap(Vec2 p) const noexcept;

 private:
  [[nodiscard]] static constexpr double image(double d, double period, double half) noexcept {
    if (d > half) {
      d -= period;
      if (d > half) d = far_image(d, period);
    } else if (d < -half) {
      d += period;
      if (d < -half) d = far_image(d, period);
    }
    return d;
  }
  [[nodiscard]] static double far_image(double d, double period) noexcept;

  Vec2 lower_;
  Vec2 upper_;
  Vec2 period_;
  Vec2 half_period_;
};

}  // namespace carom
