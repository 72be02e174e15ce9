// carom peers benchmark: the checks the harness makes on every engine's state at each step's end,
// the same for all engines and independent of them.
// - largest_overlap: the deepest overlap of two disks, as a fraction of the sum of their radii;
// - find_pass_throughs: pairs that went through each other during a step: carom's swept test
//   (carom::sweep_ball_ball) on each pair's straight motion finds an approaching contact, yet the
//   two are apart at the end of it and moving apart. A time-stepped engine moves each disk in one
//   straight line per step (then corrects positions), so the motion checked is the line from the
//   step's start to its end. An event-driven engine bends a disk's path at each of its contacts
//   within the step; it reports them (PathBreak), and the check follows each straight piece;
// - outside_box: disks whose centre lies outside the box (they went through a wall);
// - largest_wall_overlap: the deepest a disk reaches into the box's walls.
// The pair checks use a PairGrid, so a check costs O(N) for a gas (and O(N + pieces of path) for
// the pass-through check).
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
  // business; a pair that meets exactly at the stretch's end is still approaching there. Passes
  // shallower than `min_depth` (PassThrough::depth) are not listed: under gravity a path between
  // two bends is a parabola, not the straight line the check follows, and a graze within the
  // two lines' sag of each other cannot be told from a near miss.
  [[nodiscard]] std::vector<PassThrough> find_pass_throughs(
      std::span<const Vec2> start, std::span<const Vec2> end, std::span<const double> radii,
      std::span<const PathBreak> breaks, Vec2 lower, Vec2 upper, double min_depth = 0.0);

  // Disks left out of the last check because a coordinate was NaN or infinite (for the
  // pass-through check: anywhere on their path).
  [[nodiscard]] std::uint32_t non_finite() const noexcept { return grid_.skipped(); }

 private:
  struct Piece {
    std::uint32_t ball;
    double t0, t1;  // fractions of the step
    Vec2 p0, p1;    // the centre at t0 and at t1
  };
  static double pass_depth(const Piece& p, const Piece& q, double rp, double rq);

  std::vector<Box> boxes_;
  std::vector<Piece> pieces_;
  std::vector<std::uint32_t> first_piece_;  // by disk, into pieces_; one past the last at the end
  std::vector<PathBreak> sorted_breaks_;
  PairGrid grid_;
};

// Whether a centre lies outside [lower, upper]² (a NaN one counts as outside).
[[nodiscard]] bool outside_box(Vec2 position, Vec2 lower, Vec2 upper) noexcept;

// The largest (r − distance to a wall) / r over all disks and the box's four walls, or 0 when
// none reaches into a wall; a centre past the wall counts from the wall (more than 1).
[[nodiscard]] double largest_wall_overlap(std::span<const Vec2> positions,
                                          std::span<const double> radii, Vec2 lower,
                                          Vec2 upper) noexcept;

// Σ m·|v|²/2, in double precision whatever the engine's own precision.
[[nodiscard]] double kinetic_energy(std::span<const Vec2> velocities,
                                    std::span<const double> masses) noexcept;

// −Σ m·gravity·(p − origin), in double precision: gravity's potential energy, zero at `origin`.
[[nodiscard]] double potential_energy(std::span<const Vec2> positions,
                                      std::span<const double> masses, Vec2 gravity,
                                      Vec2 origin) noexcept;

}  // namespace carom::peers
