// carom peers benchmark: the checks the harness makes on every engine's state at each step's end,
// the same for all engines and independent of them.
// - largest_overlap: the deepest overlap of two disks, as a fraction of the sum of their radii;
// - find_pass_throughs: pairs that went through each other during a step: carom's swept test
//   (carom::sweep_ball_ball) on each pair's straight motion finds an approaching contact, yet the
//   two are apart at the end of it and moving apart. A time-stepped engine moves each disk in one
//   straight line per step (then corrects positions), so the motion checked is the line from the
//   step's start to its end. An event-driven engine bends a disk's path at each of its contacts
//   within the step; it reports them (PathBreak), and the check follows each straight piece;
// - outside_box: disks whose centre lies outside the box (they went through a wall).
// The pair checks use a PairGrid, so a check costs O(N) for a gas.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "carom/vec2.hpp"
#include "pair_grid.hpp"

namespace carom::peers {

// A point where a disk's path bends within a step: at `fraction` of the step (in [0, 1]) its
// centre was at `position`.
struct PathBreak {
  std::uint32_t ball = 0;
  double fraction = 0.0;
  Vec2 position;
};

struct PassThrough {
  std::uint32_t a = 0;  // a < b
  std::uint32_t b = 0;
  // How deep the straight motions went into each other: 1 − (closest distance) / (r_a + r_b);
  // near 0 for a graze, 1 for a pass through the centre.
  double depth = 0.0;
};

class Detectors {
 public:
  // The largest (r_a + r_b − distance) / (r_a + r_b) over all pairs, or 0 when none overlap.
  [[nodiscard]] double largest_overlap(std::span<const Vec2> positions,
                                       std::span<const double> radii, Vec2 lower, Vec2 upper);

  // Pairs (each listed once) that went through each other: on some stretch of time where both
  // move in a straight line (from `start`, through their `breaks` in time order, to `end`), the
  // swept test finds them meeting while approaching, and at the stretch's end they neither
  // overlap nor approach. A pair overlapping at a stretch's start is the overlap check's
  // business; a pair that meets exactly at the stretch's end is still approaching there.
  [[nodiscard]] std::vector<PassThrough> find_pass_throughs(std::span<const Vec2> start,
                                                            std::span<const Vec2> end,
                                                            std::span<const double> radii,
                                                            std::span<const PathBreak> breaks,
                                                            Vec2 lower, Vec2 upper);

  // Disks left out of the last check because a coordinate was NaN or infinite.
  [[nodiscard]] std::uint32_t non_finite() const noexcept { return grid_.skipped(); }

 private:
  struct Piece {
    std::uint32_t ball;
    double t0, t1;  // fractions of the step
    Vec2 p0, p1;    // the centre at t0 and at t1
  };
  std::vector<Box> boxes_;
  std::vector<Piece> pieces_;
  std::vector<PathBreak> sorted_breaks_;
  PairGrid grid_;
};

// Whether a centre lies outside [lower, upper]² (a NaN one counts as outside).
[[nodiscard]] bool outside_box(Vec2 position, Vec2 lower, Vec2 upper) noexcept;

// Σ m·|v|²/2, in double precision whatever the engine's own precision.
[[nodiscard]] double kinetic_energy(std::span<const Vec2> velocities,
                                    std::span<const double> masses) noexcept;

}  // namespace carom::peers
