// carom_slot_cells_gas: an experiment beside carom's engine (docs/performance.md, twenty-third
// slice). A lean event-driven simulator of the hard-disk gas of carom_world_gas_probe, built to
// measure one idea on its own: cells that hold their balls' numbers in four fixed slots, so that
// a prediction names its 3 × 3 block's balls with three vector loads and three AVX-512 compress
// instructions (no list walked, no branch on how full a cell is), then solves up to eight pairs a
// step with AVX-512 gathers.
//   carom_slot_cells_gas N ETA COLLISIONS_PER_BALL [CELL] [EQUILIBRATE_PER_BALL=2]
//   carom_slot_cells_gas --check
// CELL is the cell's side in diameters (default 1.25 below η = 0.45, else 1.05, the measured
// best); it must lie in [1, √2). Exits 77 on a CPU without AVX-512 (F, VL, DQ, BW).
//
// What it shares with carom's engine: the scene (read out of apps/carom/hard_disk_setup.hpp's
// World), the event queue (src/event_queue.hpp, carom's calendar queue, one event a ball), local
// times, cell crossings with hysteresis, stale contacts found by the partner's version. What it
// leaves out, being a gas-only experiment: species, walls, immovable balls, the exact-range
// rescaled path for extreme magnitudes, contact records, the lookahead and the re-sorts by cell
// that carom needs for 10⁶ balls, and bit-identity with carom's arithmetic (its pair formula is
// the textbook's, without fused multiply-adds).
//
// Four slots a cell always suffice: a ball stays listed in its cell until its centre is h beyond
// a side, so a cell's balls have their centres in a square of side CELL + 2h; of five points in a
// square of side s two lie in one quarter, at most s/√2 apart, so with CELL + 2h < √2 no five
// disks of diameter 1 fit. The hysteresis h is the largest that both this and the 3 × 3 block's
// reach (CELL − 2h ≥ 1) allow. The grid is stored with a border of copied cells on every side,
// so that a block's three rows are always three runs of twelve slots; a ball seen through a
// border copy is brought to its nearest image by rounding the offset to whole box sides.
#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "world/event_queue.hpp"
#include "gas_run_support.hpp"
#include "hard_disk_setup.hpp"

#define SLOT_CELLS_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw")))

namespace slot_cells {

using carom::detail::Event;
using carom::detail::EventKind;
using carom::detail::EventQueue;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr std::uint32_t kSlots = 4;

// A ball at its local time t (one cache line; the gathers read x, y, vx, vy and t by offset).
struct alignas(64) Ball {
  double x = 0.0;
  double y = 0.0;
  double vx = 0.0;
  double vy = 0.0;
  double t = 0.0;
  std::uint32_t version = 0;  // bumped at each collision: a contact predicted before is stale
  std::int32_t cx = 0;
  std::int32_t cy = 0;
};
static_assert(sizeof(Ball) == 64 && offsetof(Ball, t) == 32);

// The least of eight lanes. (The masked forms, here and in predict, give every lane a defined
// source: GCC 12 warns that the unmasked intrinsics' undefined one may be used uninitialized.)
SLOT_CELLS_AVX512 inline double least_of(__m512d lanes) {
  const __m256d none = _mm256_setzero_pd();
  const __m256d half = _mm256_min_pd(_mm512_mask_extractf64x4_pd(none, 0xF, lanes, 0),
                                     _mm512_mask_extractf64x4_pd(none, 0xF, lanes, 1));
  const __m128d quarter = _mm_min_pd(_mm256_castpd256_pd128(half), _mm256_extractf128_pd(half, 1));
  return _mm_cvtsd_f64(_mm_min_sd(quarter, _mm_unpackhi_pd(quarter, quarter)));
}

class Gas {
 public:
  Gas(double side, const std::vector<double>& x, const std::vector<double>& y,
      const std::vector<double>& vx, const std::vector<double>& vy, double cell)
      : side_(side),
        columns_(static_cast<std::int32_t>(std::floor(side / cell))),
        cell_(side / columns_),
        hysteresis_(std::min(0.5 * (cell_ - 1.0), 0.5 * (std::sqrt(2.0) - cell_) - 1e-9)),
        ghost_(static_cast<std::uint32_t>(x.size())) {
    const auto n = static_cast<std::uint32_t>(x.size());
    const auto padded = static_cast<std::size_t>(columns_ + 2);
    slots_.assign(padded * padded * kSlots, ghost_);
    // Ball n is the ghost every empty slot names: at NaN, so that any pair with it misses.
    balls_.resize(static_cast<std::size_t>(n) + 1);
    balls_[n].x = std::numeric_limits<double>::quiet_NaN();
    balls_[n].y = std::numeric_limits<double>::quiet_NaN();
    handles_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      Ball& ball = balls_[i];
      ball.x = x[i];
      ball.y = y[i];
      ball.vx = vx[i];
      ball.vy = vy[i];
      ball.cx = std::clamp(static_cast<std::int32_t>(std::floor(ball.x / cell_)), 0, columns_ - 1);
      ball.cy = std::clamp(static_cast<std::int32_t>(std::floor(ball.y / cell_)), 0, columns_ - 1);
      link(i);
      handles_[i] = i;
    }
    queue_.reset(n);
    queue_.use_handles(handles_.data());
    for (std::uint32_t i = 0; i < n; ++i) predict(i);
  }

  // Whether the cell size can hold every ball in four slots with a block of reach 1.
  [[nodiscard]] bool valid() const { return columns_ >= 3 && hysteresis_ >= 0.0; }
  [[nodiscard]] bool overflowed() const { return overflowed_; }

  // Processes events until `count` collisions have happened (fewer only if nothing is pending).
  [[gnu::noinline]] std::uint64_t run_collisions(std::uint64_t count) {
    std::uint64_t done = 0;
    while (done < count && !overflowed_) {
      const Event event = queue_.top();
      if (event.time == kInfinity) break;
      now_ = event.time;
      const std::uint32_t i = event.owner;
      if (event.kind == EventKind::cell_crossing) {
        cross(i, event.partner);
        predict(i);
        ++crossings_;
      } else if (balls_[event.partner].version != event.partner_version) {
        predict(i);
        ++stale_;
      } else {
        collide(i, event.partner);
        predict(i);
        predict(event.partner);
        ++done;
      }
    }
    return done;
  }

  [[nodiscard]] double kinetic_energy() const {
    double sum = 0.0;
    for (std::uint32_t i = 0; i < ghost_; ++i) {
      sum += 0.5 * (balls_[i].vx * balls_[i].vx + balls_[i].vy * balls_[i].vy);
    }
    return sum;
  }
  // The smallest distance between two disks' centres (nearest image), over every pair: O(N²).
  [[nodiscard]] double closest_pair_distance() const {
    double closest = kInfinity;
    for (std::uint32_t i = 0; i < ghost_; ++i) {
      for (std::uint32_t j = i + 1; j < ghost_; ++j) {
        const double dx = nearest_image(position_x(j) - position_x(i));
        const double dy = nearest_image(position_y(j) - position_y(i));
        closest = std::min(closest, std::sqrt(dx * dx + dy * dy));
      }
    }
    return closest;
  }
  [[nodiscard]] std::uint64_t crossings() const { return crossings_; }
  [[nodiscard]] std::uint64_t stale() const { return stale_; }
  [[nodiscard]] std::int32_t columns() const { return columns_; }
  // The balls' and the cells' arrays (not the event queue's).
  [[nodiscard]] std::size_t bytes() const {
    return balls_.capacity() * sizeof(Ball) + slots_.capacity() * sizeof(std::uint32_t) +
           handles_.capacity() * sizeof(std::uint32_t);
  }

 private:
  // An offset along one axis brought to its nearest image (whole box sides taken off).
  [[nodiscard]] double nearest_image(double d) const {
    return d - side_ * std::nearbyint(d / side_);
  }
  [[nodiscard]] double position_x(std::uint32_t i) const {
    return balls_[i].x + balls_[i].vx * (now_ - balls_[i].t);
  }
  [[nodiscard]] double position_y(std::uint32_t i) const {
    return balls_[i].y + balls_[i].vy * (now_ - balls_[i].t);
  }
  // The first of cell (px, py)'s slots in the padded grid.
  [[nodiscard]] std::size_t padded_cell(std::int32_t px, std::int32_t py) const {
    return (static_cast<std::size_t>(py) * static_cast<std::size_t>(columns_ + 2) +
            static_cast<std::size_t>(px)) *
           kSlots;
  }
  // Writes `value` into slot k of the ball's cell and of that cell's border copies.
  void write_slot(const Ball& ball, std::uint32_t k, std::uint32_t value) {
    const std::int32_t xs[2] = {ball.cx + 1, ball.cx == 0              ? columns_ + 1
                                             : ball.cx == columns_ - 1 ? 0
                                                                       : -1};
    const std::int32_t ys[2] = {ball.cy + 1, ball.cy == 0              ? columns_ + 1
                                             : ball.cy == columns_ - 1 ? 0
                                                                       : -1};
    for (const std::int32_t py : ys) {
      for (const std::int32_t px : xs) {
        if (px >= 0 && py >= 0) slots_[padded_cell(px, py) + k] = value;
      }
    }
  }
  void link(std::uint32_t i) {
    const Ball& ball = balls_[i];
    const std::uint32_t* own = &slots_[padded_cell(ball.cx + 1, ball.cy + 1)];
    std::uint32_t k = 0;
    while (k < kSlots && own[k] != ghost_) ++k;
    if (k == kSlots) {
      overflowed_ = true;  // cannot happen with valid(); reported rather than written past
      return;
    }
    write_slot(ball, k, i);
  }
  void unlink(std::uint32_t i) {
    const Ball& ball = balls_[i];
    const std::uint32_t* own = &slots_[padded_cell(ball.cx + 1, ball.cy + 1)];
    std::uint32_t k = 0;
    while (k < kSlots && own[k] != i) ++k;
    if (k < kSlots) write_slot(ball, k, ghost_);
  }

  void advance(Ball& ball) const { carom::bench::advance_to(ball, now_); }

  // Crossing through `side` (0: −x, 1: +x, 2: −y, 3: +y), wrapping through the box's edge.
  void cross(std::uint32_t i, std::uint32_t side) {
    Ball& ball = balls_[i];
    advance(ball);
    unlink(i);
    carom::bench::step_cell(side < 2 ? ball.cx : ball.cy, side < 2 ? ball.x : ball.y,
                            (side & 1U) != 0, columns_, side_);
    link(i);
  }

  // Elastic equal-mass bounce (gas_run_support.hpp), the offset by its nearest image.
  void collide(std::uint32_t i, std::uint32_t j) {
    Ball& a = balls_[i];
    Ball& b = balls_[j];
    advance(a);
    advance(b);
    carom::bench::exchange_normal_velocities(a, b, nearest_image(b.x - a.x),
                                             nearest_image(b.y - a.y));
    ++a.version;
    ++b.version;
  }

  // Ball i's earliest event: leaving its cell (grown by the hysteresis), or touching a ball of
  // its block (the textbook's root c / (√(b² − v²c) − b), 0 for an approaching pair that
  // rounding left overlapping).
  SLOT_CELLS_AVX512 void predict(std::uint32_t i) {
    const Ball& ball = balls_[i];
    const double wall_x =
        cell_ * (ball.cx + (ball.vx > 0.0 ? 1 : 0)) + (ball.vx > 0.0 ? hysteresis_ : -hysteresis_);
    const double wall_y =
        cell_ * (ball.cy + (ball.vy > 0.0 ? 1 : 0)) + (ball.vy > 0.0 ? hysteresis_ : -hysteresis_);
    const double exit_x = ball.vx != 0.0 ? ball.t + (wall_x - ball.x) / ball.vx : kInfinity;
    const double exit_y = ball.vy != 0.0 ? ball.t + (wall_y - ball.y) / ball.vy : kInfinity;
    const bool y_first = exit_y < exit_x;
    Event event;
    event.owner = i;
    event.kind = EventKind::cell_crossing;
    event.partner = y_first ? 2U + (ball.vy > 0.0 ? 1U : 0U) : (ball.vx > 0.0 ? 1U : 0U);
    event.time = std::max(y_first ? exit_y : exit_x, now_);

    // Name the block's balls: three runs of twelve slots, the ghost's and the ball's own dropped.
    const __m512i ghost = _mm512_set1_epi32(static_cast<int>(ghost_));
    const __m512i self = _mm512_set1_epi32(static_cast<int>(i));
    std::uint32_t count = 0;
    for (std::int32_t row = 0; row < 3; ++row) {
      const std::uint32_t* run = &slots_[padded_cell(ball.cx, ball.cy + row)];
      const __m512i names = _mm512_maskz_loadu_epi32(0x0FFF, run);
      const __mmask16 keep = _mm512_mask_cmpneq_epi32_mask(
          _mm512_mask_cmpneq_epi32_mask(0x0FFF, names, ghost), names, self);
      _mm512_storeu_si512(&names_[count], _mm512_maskz_compress_epi32(keep, names));
      count += static_cast<std::uint32_t>(__builtin_popcount(keep));
    }

    // Solve them eight at a time.
    const double dt = now_ - ball.t;
    const __m512d p_x = _mm512_set1_pd(ball.x + ball.vx * dt);
    const __m512d p_y = _mm512_set1_pd(ball.y + ball.vy * dt);
    const __m512d v_x = _mm512_set1_pd(ball.vx);
    const __m512d v_y = _mm512_set1_pd(ball.vy);
    const __m512d now = _mm512_set1_pd(now_);
    const __m512d side = _mm512_set1_pd(side_);
    const __m512d inverse_side = _mm512_set1_pd(1.0 / side_);
    const __m512d one = _mm512_set1_pd(1.0);
    const __m512d zero = _mm512_setzero_pd();
    const __m512d never = _mm512_set1_pd(kInfinity);
    const double* base = &balls_[0].x;
    double earliest = kInfinity;
    std::uint32_t partner = 0;
    for (std::uint32_t k = 0; k < count; k += 8) {
      const auto live = static_cast<__mmask8>(count - k >= 8 ? 0xFFU : (1U << (count - k)) - 1U);
      const __m256i name =
          _mm256_mask_loadu_epi32(_mm256_set1_epi32(static_cast<int>(ghost_)), live, &names_[k]);
      const __m256i offset = _mm256_slli_epi32(name, 3);  // eight doubles a ball
      const __m512d o_x = _mm512_mask_i32gather_pd(zero, 0xFF, offset, base + 0, 8);
      const __m512d o_y = _mm512_mask_i32gather_pd(zero, 0xFF, offset, base + 1, 8);
      const __m512d o_vx = _mm512_mask_i32gather_pd(zero, 0xFF, offset, base + 2, 8);
      const __m512d o_vy = _mm512_mask_i32gather_pd(zero, 0xFF, offset, base + 3, 8);
      const __m512d o_t = _mm512_mask_i32gather_pd(zero, 0xFF, offset, base + 4, 8);
      const __m512d elapsed = _mm512_sub_pd(now, o_t);
      __m512d s_x = _mm512_sub_pd(p_x, _mm512_add_pd(o_x, _mm512_mul_pd(o_vx, elapsed)));
      __m512d s_y = _mm512_sub_pd(p_y, _mm512_add_pd(o_y, _mm512_mul_pd(o_vy, elapsed)));
      s_x = _mm512_sub_pd(
          s_x, _mm512_mul_pd(side, _mm512_mask_roundscale_pd(zero, 0xFF,
                                                             _mm512_mul_pd(s_x, inverse_side), 0)));
      s_y = _mm512_sub_pd(
          s_y, _mm512_mul_pd(side, _mm512_mask_roundscale_pd(zero, 0xFF,
                                                             _mm512_mul_pd(s_y, inverse_side), 0)));
      const __m512d u_x = _mm512_sub_pd(v_x, o_vx);
      const __m512d u_y = _mm512_sub_pd(v_y, o_vy);
      const __m512d b = _mm512_add_pd(_mm512_mul_pd(s_x, u_x), _mm512_mul_pd(s_y, u_y));
      const __m512d c =
          _mm512_sub_pd(_mm512_add_pd(_mm512_mul_pd(s_x, s_x), _mm512_mul_pd(s_y, s_y)), one);
      const __m512d v2 = _mm512_add_pd(_mm512_mul_pd(u_x, u_x), _mm512_mul_pd(u_y, u_y));
      const __m512d discriminant = _mm512_sub_pd(_mm512_mul_pd(b, b), _mm512_mul_pd(v2, c));
      const __mmask8 hit = _mm512_cmp_pd_mask(b, zero, _CMP_LT_OQ) &
                           _mm512_cmp_pd_mask(discriminant, zero, _CMP_GT_OQ);
      const __m512d root =
          _mm512_div_pd(c, _mm512_sub_pd(_mm512_mask_sqrt_pd(zero, 0xFF, discriminant), b));
      const __m512d when =
          _mm512_mask_blend_pd(hit, never, _mm512_mask_max_pd(zero, 0xFF, root, zero));
      const double least = least_of(when);
      const __mmask8 at = _mm512_cmp_pd_mask(when, _mm512_set1_pd(least), _CMP_EQ_OQ);
      const auto lane = static_cast<std::uint32_t>(__builtin_ctz(at | 0x100U)) & 7U;
      const bool sooner = least < earliest;
      partner = sooner ? names_[k + lane] : partner;
      earliest = sooner ? least : earliest;
    }
    if (now_ + earliest < event.time) {
      event.time = now_ + earliest;
      event.kind = EventKind::ball_ball;
      event.partner = partner;
      event.partner_version = balls_[partner].version;
    }
    queue_.set(i, event);
  }

  double side_;
  std::int32_t columns_;
  double cell_;
  double hysteresis_;
  std::uint32_t ghost_;
  double now_ = 0.0;
  std::vector<Ball> balls_;
  std::vector<std::uint32_t> slots_;    // (columns + 2)² cells of kSlots ball numbers
  std::vector<std::uint32_t> handles_;  // the queue's tie order: the ball's own number
  EventQueue queue_;
  // A block's names: up to 36, and room for the last compress's full 16-lane store.
  alignas(64) std::uint32_t names_[64] = {};
  bool overflowed_ = false;
  std::uint64_t crossings_ = 0;
  std::uint64_t stale_ = 0;
};

carom::bench::GasStart start_of(std::uint64_t n, double eta) {
  const carom::cli::HardDiskLayout layout = carom::cli::hard_disk_layout(n, eta);
  return carom::bench::start_of(carom::cli::make_hard_disk_world(layout, 1), layout.side);
}

double default_cell(double eta) { return eta < 0.45 ? 1.25 : 1.05; }

// The self-check (ctest runs it): N = 500 at η = 0.3 and 0.6, 20 collisions a disk after 2 of
// equilibration, then no two disks closer than a diameter less 1e-9 (a missed contact lets a
// pair pass through each other, by far more) and the kinetic energy unchanged to 1e-12
// relative (each bounce conserves it to a few roundings).
int check() {
  bool ok = true;
  for (const double eta : {0.3, 0.6}) {
    const carom::bench::GasStart start = start_of(500, eta);
    Gas gas(start.side, start.x, start.y, start.vx, start.vy, default_cell(eta));
    gas.run_collisions(1000);
    const double energy = gas.kinetic_energy();
    const std::uint64_t done = gas.run_collisions(10000);
    const double closest = gas.closest_pair_distance();
    const double drift = std::abs(gas.kinetic_energy() - energy) / energy;
    const bool sound = gas.valid() && !gas.overflowed() && done == 10000 && closest >= 1.0 - 1e-9 &&
                       drift <= 1e-12;
    std::printf(
        "n=500 eta=%.1f cells=%d^2 collisions=%llu closest pair %.15f, energy drift %.1e: %s\n",
        eta, gas.columns(), static_cast<unsigned long long>(done), closest, drift,
        sound ? "ok" : "FAILED");
    ok = ok && sound;
  }
  return ok ? 0 : 1;
}

bool cpu_has_avx512() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512vl") != 0 &&
         __builtin_cpu_supports("avx512dq") != 0 && __builtin_cpu_supports("avx512bw") != 0;
}

}  // namespace slot_cells

int main(int argc, char** argv) {
  if (!slot_cells::cpu_has_avx512()) {
    std::fprintf(stderr, "%s: this CPU lacks AVX-512 (F, VL, DQ, BW): skipped\n", argv[0]);
    return 77;
  }
  if (argc == 2 && std::strcmp(argv[1], "--check") == 0) return slot_cells::check();
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s N ETA COLLISIONS_PER_BALL [CELL] [EQUILIBRATE_PER_BALL=2]\n",
                 argv[0]);
    std::fprintf(stderr, "       %s --check\n", argv[0]);
    return 2;
  }
  const std::uint64_t n = std::strtoull(argv[1], nullptr, 10);
  const double eta = std::atof(argv[2]);
  const double per_ball = std::atof(argv[3]);
  const double cell = argc > 4 ? std::atof(argv[4]) : slot_cells::default_cell(eta);
  const double equilibrate = argc > 5 ? std::atof(argv[5]) : 2.0;
  const carom::cli::HardDiskLayout layout = carom::cli::hard_disk_layout(n, eta);
  if (n == 0 || !layout.box_wide_enough() || !layout.disks_fit()) {
    std::fprintf(stderr, "the triangular lattice cannot hold %llu disks at packing %g\n",
                 static_cast<unsigned long long>(n), eta);
    return 2;
  }
  if (!(cell >= 1.0 && cell < std::sqrt(2.0)) || std::floor(layout.side / cell) < 3.0) {
    std::fprintf(stderr,
                 "CELL %g: the cell must be at least 1 and under sqrt(2) diameters, "
                 "and the box at least three cells wide\n",
                 cell);
    return 2;
  }
  const carom::bench::GasStart start = slot_cells::start_of(n, eta);
  slot_cells::Gas gas(start.side, start.x, start.y, start.vx, start.vy, cell);
  if (!gas.valid()) {
    std::fprintf(stderr,
                 "CELL %g: the box's whole cells come out at %g diameters, not under sqrt(2)\n",
                 cell, start.side / gas.columns());
    return 2;
  }
  gas.run_collisions(static_cast<std::uint64_t>(equilibrate * static_cast<double>(n)));
  const auto wanted = static_cast<std::uint64_t>(per_ball * static_cast<double>(n));
  const carom::bench::TimedCollisions timed = carom::bench::timed_collisions(gas, wanted);
  const auto count = static_cast<double>(timed.collisions);
  std::printf(
      "n=%llu eta=%.2f cell=%.3f cells=%d^2 collisions=%llu cpu_s=%.3f cpu_rate=%.0fk/s "
      "cpu_ns_per_collision=%.0f crossings_per_collision=%.3f stale_per_collision=%.3f "
      "balls_and_cells_bytes_per_ball=%.0f energy_drift=%.2e\n",
      static_cast<unsigned long long>(n), eta, start.side / gas.columns(), gas.columns(),
      static_cast<unsigned long long>(timed.collisions), timed.cpu_seconds,
      count / timed.cpu_seconds / 1e3, timed.cpu_seconds / count * 1e9,
      timed.crossings_per_collision, timed.stale_per_collision,
      static_cast<double>(gas.bytes()) / static_cast<double>(n), timed.energy_drift);
  if (gas.overflowed()) {
    std::fprintf(stderr, "a cell would have held more than four balls\n");
    return 1;
  }
  return timed.collisions == wanted ? 0 : 1;
}
