// carom_textbook_gas: a textbook event-driven hard-disk simulator, the yardstick of the world's
// speed goals (a careful textbook implementation: one earliest event per ball, an indexed binary
// heap, cell crossings), run on the same scene as carom_world_gas_probe and timed the same way.
//   carom_textbook_gas N ETA COLLISIONS_PER_BALL [EQUILIBRATE_PER_BALL=2] [SHUFFLED=0]
//   carom_textbook_gas --check
// SHUFFLED=1 numbers the balls in the random order in which carom_world_gas_probe's SHUFFLED=1
// adds them (the same permutation), so that neighbours are far apart in memory; the textbook
// simulator never re-orders its balls.
// The simulator is the one of Rapaport, Allen & Tildesley and Lubachevsky, written plainly:
// - equal disks (diameter 1, mass 1) in a periodic square box, distances by minimum image;
// - a uniform grid with as many cells per axis as fit with cells no smaller than a diameter, each
//   cell a doubly linked list of its balls;
// - each ball keeps its own local time and is advanced lazily (position + velocity·(t − local));
// - each ball has exactly one pending event, the earliest of its contacts with the balls in the
//   3×3 block of cells around it (the quadratic time of impact of an approaching pair) and its
//   leaving its cell, held in an indexed binary min-heap (each ball knows its heap position, so
//   its entry is updated in place in O(log N));
// - a contact event remembers the partner's collision counter and is stale (the ball is
//   re-predicted) when that counter has moved on;
// - a collision exchanges the normal components of the two velocities and re-predicts both balls;
//   a cell crossing moves the ball to the next cell (wrapping through the box's edge) and
//   re-predicts it.
// It uses nothing of carom but the scene: the start (positions and velocities) is read out of the
// World that carom/science/hard_disk_gas.hpp builds, so both programs start from the same state.
// --check (run by ctest) compares its first collisions with carom's World on small gases and
// checks that it keeps the disks apart, in their cells, and conserves energy (see check()).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "carom/science/hard_disk_gas.hpp"
#include "gas_run_support.hpp"

#ifdef __GLIBC__     // defined by the standard headers above
#include <malloc.h>  // malloc_trim
#endif

namespace textbook {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr std::uint32_t kNil = std::numeric_limits<std::uint32_t>::max();

// One collision, for the comparison with carom (ball indices in lattice order, first < second).
struct Collision {
  double time;
  std::uint32_t first;
  std::uint32_t second;
};

class Gas {
 public:
  // Equal disks of diameter 1 in the periodic box [0, side)², positions inside the box.
  Gas(double side, const std::vector<double>& x, const std::vector<double>& y,
      const std::vector<double>& vx, const std::vector<double>& vy)
      : side_(side), half_side_(side / 2.0) {
    cells_per_axis_ = static_cast<std::uint32_t>(std::floor(side / kDiameter));
    while (cells_per_axis_ > 3 && side / static_cast<double>(cells_per_axis_) < kDiameter) {
      --cells_per_axis_;
    }
    cell_size_ = side / static_cast<double>(cells_per_axis_);
    head_.assign(static_cast<std::size_t>(cells_per_axis_) * cells_per_axis_, kNil);
    const std::size_t n = x.size();
    balls_.resize(n);
    events_.resize(n);
    heap_.resize(n);
    heap_position_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      Ball& ball = balls_[i];
      ball.x = x[i];
      ball.y = y[i];
      ball.vx = vx[i];
      ball.vy = vy[i];
      ball.cx = cell_of(ball.x);
      ball.cy = cell_of(ball.y);
      link(static_cast<std::uint32_t>(i));
    }
    for (std::size_t i = 0; i < n; ++i) {
      heap_[i] = {kInfinity, static_cast<std::uint32_t>(i)};
      heap_position_[i] = static_cast<std::uint32_t>(i);
    }
    for (std::size_t i = 0; i < n; ++i) predict(static_cast<std::uint32_t>(i));
  }

  // Processes events until `count` collisions have happened; returns how many did (fewer only if
  // no event is pending at all). Collisions are appended to `record` when it is not null.
  [[gnu::noinline]] std::uint64_t run_collisions(std::uint64_t count,
                                                 std::vector<Collision>* record = nullptr) {
    std::uint64_t done = 0;
    while (done < count) {
      const std::uint32_t i = heap_[0].ball;
      const double t = heap_[0].time;
      if (t == kInfinity) break;
      now_ = t;
      const Event event = events_[i];
      if (event.kind == Event::kCrossing) {
        cross(i, event.axis, event.direction);
        predict(i);
        ++crossings_;
      } else if (balls_[event.partner].collisions != event.partner_collisions) {
        predict(i);
        ++stale_;
      } else {
        const std::uint32_t j = event.partner;
        collide(i, j);
        predict(i);
        predict(j);
        ++done;
        if (record != nullptr) record->push_back({t, std::min(i, j), std::max(i, j)});
      }
    }
    collisions_ += done;
    return done;
  }

  [[nodiscard]] double time() const { return now_; }
  [[nodiscard]] std::uint64_t collisions() const { return collisions_; }
  [[nodiscard]] std::uint64_t crossings() const { return crossings_; }
  [[nodiscard]] std::uint64_t stale() const { return stale_; }
  [[nodiscard]] std::size_t size() const { return balls_.size(); }
  [[nodiscard]] std::uint32_t cells_per_axis() const { return cells_per_axis_; }

  [[nodiscard]] double kinetic_energy() const {
    double sum = 0.0;
    for (const Ball& ball : balls_) sum += 0.5 * (ball.vx * ball.vx + ball.vy * ball.vy);
    return sum;
  }

  // Where ball i is at the current time (not wrapped into the box: it lies in its cell).
  [[nodiscard]] std::pair<double, double> position(std::uint32_t i) const {
    const Ball& ball = balls_[i];
    const double dt = now_ - ball.t;
    return {ball.x + ball.vx * dt, ball.y + ball.vy * dt};
  }

  // The smallest distance between two disks' centres (minimum image) over every pair: O(N²).
  [[nodiscard]] double closest_pair_distance() const {
    double closest = kInfinity;
    const std::uint32_t n = static_cast<std::uint32_t>(balls_.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      const auto [xi, yi] = position(i);
      for (std::uint32_t j = i + 1; j < n; ++j) {
        const auto [xj, yj] = position(j);
        const double dx = minimum_image(xj - xi);
        const double dy = minimum_image(yj - yi);
        closest = std::min(closest, std::sqrt(dx * dx + dy * dy));
      }
    }
    return closest;
  }

  // How far the farthest ball lies outside the cell it is filed in (0 when all are inside), and
  // whether the cell lists hold every ball exactly once, in the cell it names.
  [[nodiscard]] double farthest_outside_cell() const {
    double farthest = 0.0;
    for (std::uint32_t i = 0; i < balls_.size(); ++i) {
      const auto [x, y] = position(i);
      const Ball& ball = balls_[i];
      const double left = cell_size_ * ball.cx;
      const double bottom = cell_size_ * ball.cy;
      farthest = std::max(
          {farthest, left - x, x - (left + cell_size_), bottom - y, y - (bottom + cell_size_)});
    }
    return farthest;
  }
  [[nodiscard]] bool cell_lists_consistent() const {
    std::size_t listed = 0;
    for (std::uint32_t cell = 0; cell < head_.size(); ++cell) {
      std::uint32_t previous = kNil;
      for (std::uint32_t j = head_[cell]; j != kNil; j = balls_[j].next) {
        if (balls_[j].cy * cells_per_axis_ + balls_[j].cx != cell) return false;
        if (balls_[j].prev != previous) return false;
        previous = j;
        ++listed;
      }
    }
    return listed == balls_.size();
  }

  // Bytes the simulator's arrays hold.
  [[nodiscard]] std::size_t bytes() const {
    return balls_.capacity() * sizeof(Ball) + events_.capacity() * sizeof(Event) +
           heap_.capacity() * sizeof(HeapNode) + heap_position_.capacity() * sizeof(std::uint32_t) +
           head_.capacity() * sizeof(std::uint32_t);
  }

 private:
  static constexpr double kDiameter = 1.0;

  // A ball: its position at its local time t, its velocity, its collision counter, its cell and
  // its links in the cell's list (64 bytes).
  struct Ball {
    double x = 0.0;
    double y = 0.0;
    double vx = 0.0;
    double vy = 0.0;
    double t = 0.0;
    std::uint32_t collisions = 0;
    std::uint32_t cx = 0;
    std::uint32_t cy = 0;
    std::uint32_t next = kNil;
    std::uint32_t prev = kNil;
  };

  // A ball's one pending event (its time is in the heap).
  struct Event {
    static constexpr std::uint8_t kContact = 0;
    static constexpr std::uint8_t kCrossing = 1;
    std::uint32_t partner = kNil;          // contact: the other ball
    std::uint32_t partner_collisions = 0;  // contact: the other ball's counter when predicted
    std::uint8_t kind = kCrossing;
    std::uint8_t axis = 0;       // crossing: 0 for x, 1 for y
    std::uint8_t direction = 0;  // crossing: 1 towards higher cells, 0 towards lower
  };

  struct HeapNode {
    double time;
    std::uint32_t ball;
  };

  [[nodiscard]] std::uint32_t cell_of(double coordinate) const {
    const auto cell = static_cast<std::int64_t>(std::floor(coordinate / cell_size_));
    return static_cast<std::uint32_t>(std::clamp<std::int64_t>(cell, 0, cells_per_axis_ - 1));
  }

  [[nodiscard]] double minimum_image(double d) const {
    if (d > half_side_) return d - side_;
    if (d < -half_side_) return d + side_;
    return d;
  }

  void link(std::uint32_t i) {
    Ball& ball = balls_[i];
    std::uint32_t& head = head_[ball.cy * cells_per_axis_ + ball.cx];
    ball.prev = kNil;
    ball.next = head;
    if (head != kNil) balls_[head].prev = i;
    head = i;
  }

  void unlink(std::uint32_t i) {
    Ball& ball = balls_[i];
    if (ball.prev != kNil) {
      balls_[ball.prev].next = ball.next;
    } else {
      head_[ball.cy * cells_per_axis_ + ball.cx] = ball.next;
    }
    if (ball.next != kNil) balls_[ball.next].prev = ball.prev;
  }

  // Brings ball i to the current time.
  void advance(Ball& ball) const { carom::bench::advance_to(ball, now_); }

  void cross(std::uint32_t i, std::uint8_t axis, std::uint8_t direction) {
    Ball& ball = balls_[i];
    advance(ball);
    unlink(i);
    carom::bench::step_cell(axis == 0 ? ball.cx : ball.cy, axis == 0 ? ball.x : ball.y,
                            direction == 1, cells_per_axis_, side_);
    link(i);
  }

  // Elastic equal-mass bounce (gas_run_support.hpp).
  void collide(std::uint32_t i, std::uint32_t j) {
    Ball& a = balls_[i];
    Ball& b = balls_[j];
    advance(a);
    advance(b);
    carom::bench::exchange_normal_velocities(a, b, minimum_image(b.x - a.x),
                                             minimum_image(b.y - a.y));
    ++a.collisions;
    ++b.collisions;
  }

  // The time until two disks at relative position (dx, dy) with relative velocity (dvx, dvy)
  // touch, or infinity when they never do (moving apart, or missing each other). The roots of
  // |dr + dv·s|² = d² are s = (−b ∓ √(b² − v²c)) / v² with b = dr·dv, c = |dr|² − d²; the earlier
  // one is computed as c / (−b + √(b² − v²c)), which does not cancel. Disks already touching or
  // overlapping by a rounding (c <= 0) while approaching touch now.
  static double time_of_impact(double dx, double dy, double dvx, double dvy) {
    const double b = dx * dvx + dy * dvy;
    if (b >= 0.0) return kInfinity;
    const double c = dx * dx + dy * dy - kDiameter * kDiameter;
    if (c <= 0.0) return 0.0;
    const double v2 = dvx * dvx + dvy * dvy;
    const double discriminant = b * b - v2 * c;
    if (discriminant <= 0.0) return kInfinity;
    return c / (std::sqrt(discriminant) - b);
  }

  // Ball i's earliest event from the current time: leaving its cell, or touching a ball of the
  // 3×3 block of cells around it; it replaces the ball's entry in the heap.
  void predict(std::uint32_t i) {
    const Ball& ball = balls_[i];
    Event event;
    // Leaving the cell, from the ball's stored state (its local time may be earlier than now).
    double when = kInfinity;
    if (ball.vx != 0.0) {
      const double wall = cell_size_ * (ball.vx > 0.0 ? ball.cx + 1 : ball.cx);
      when = ball.t + (wall - ball.x) / ball.vx;
      event.axis = 0;
      event.direction = ball.vx > 0.0 ? 1 : 0;
    }
    if (ball.vy != 0.0) {
      const double wall = cell_size_ * (ball.vy > 0.0 ? ball.cy + 1 : ball.cy);
      const double when_y = ball.t + (wall - ball.y) / ball.vy;
      if (when_y < when) {
        when = when_y;
        event.axis = 1;
        event.direction = ball.vy > 0.0 ? 1 : 0;
      }
    }
    // A ball that rounding left a hair outside its cell leaves it now.
    when = std::max(when, now_);
    // Contacts with the balls of the 3×3 block, all brought to the current time.
    const double ti = now_ - ball.t;
    const double xi = ball.x + ball.vx * ti;
    const double yi = ball.y + ball.vy * ti;
    const std::uint32_t m = cells_per_axis_;
    const std::uint32_t columns[3] = {(ball.cx + m - 1) % m, ball.cx, (ball.cx + 1) % m};
    const std::uint32_t rows[3] = {(ball.cy + m - 1) % m, ball.cy, (ball.cy + 1) % m};
    for (const std::uint32_t row : rows) {
      for (const std::uint32_t column : columns) {
        for (std::uint32_t j = head_[row * m + column]; j != kNil; j = balls_[j].next) {
          if (j == i) continue;
          const Ball& other = balls_[j];
          const double tj = now_ - other.t;
          const double dx = minimum_image(other.x + other.vx * tj - xi);
          const double dy = minimum_image(other.y + other.vy * tj - yi);
          const double dt = time_of_impact(dx, dy, other.vx - ball.vx, other.vy - ball.vy);
          if (now_ + dt < when) {
            when = now_ + dt;
            event.kind = Event::kContact;
            event.partner = j;
            event.partner_collisions = other.collisions;
          }
        }
      }
    }
    events_[i] = event;
    update(i, when);
  }

  // ---- the indexed binary min-heap ----
  void update(std::uint32_t i, double time) {
    const std::uint32_t k = heap_position_[i];
    const double old = heap_[k].time;
    heap_[k].time = time;
    if (time < old) {
      sift_up(k);
    } else {
      sift_down(k);
    }
  }

  void place(std::uint32_t k, HeapNode node) {
    heap_[k] = node;
    heap_position_[node.ball] = k;
  }

  void sift_up(std::uint32_t k) {
    const HeapNode node = heap_[k];
    while (k > 0) {
      const std::uint32_t parent = (k - 1) / 2;
      if (heap_[parent].time <= node.time) break;
      place(k, heap_[parent]);
      k = parent;
    }
    place(k, node);
  }

  void sift_down(std::uint32_t k) {
    const HeapNode node = heap_[k];
    const auto n = static_cast<std::uint32_t>(heap_.size());
    while (true) {
      std::uint32_t child = 2 * k + 1;
      if (child >= n) break;
      if (child + 1 < n && heap_[child + 1].time < heap_[child].time) ++child;
      if (node.time <= heap_[child].time) break;
      place(k, heap_[child]);
      k = child;
    }
    place(k, node);
  }

  double side_;
  double half_side_;
  double cell_size_ = 0.0;
  std::uint32_t cells_per_axis_ = 0;
  double now_ = 0.0;
  std::vector<Ball> balls_;
  std::vector<Event> events_;
  std::vector<HeapNode> heap_;
  std::vector<std::uint32_t> heap_position_;
  std::vector<std::uint32_t> head_;  // first ball of each cell's list, kNil when empty
  std::uint64_t collisions_ = 0;
  std::uint64_t crossings_ = 0;
  std::uint64_t stale_ = 0;
};

}  // namespace textbook

namespace {

// The resident set now, in KiB (/proc/self/statm), or -1 where it cannot be read.
long resident_kib() {
  std::FILE* file = std::fopen("/proc/self/statm", "r");
  if (file == nullptr) return -1;
  long size = 0;
  long resident = 0;
  const int read = std::fscanf(file, "%ld %ld", &size, &resident);
  std::fclose(file);
  return read == 2 ? resident * 4 : -1;
}

using Start = carom::bench::GasStart;
using carom::bench::start_of;

// The same balls numbered in the random order of carom_world_gas_probe's SHUFFLED=1.
Start shuffled(const Start& start) {
  Start result;
  result.side = start.side;
  for (const std::size_t i : carom::bench::shuffled_order(start.x.size())) {
    result.x.push_back(start.x[i]);
    result.y.push_back(start.y[i]);
    result.vx.push_back(start.vx[i]);
    result.vy.push_back(start.vy[i]);
  }
  return result;
}

textbook::Gas gas_of(const Start& start) {
  return textbook::Gas(start.side, start.x, start.y, start.vx, start.vy);
}

// The self-check (ctest runs it). For N = 200 and 500 at η = 0.3 and 0.6, from the same start:
// 1. the first kCompared collisions of the textbook simulator and of carom's World, one by one:
//    the same pair (lattice order), in the same order, at times within kTimeTolerance relative.
//    The two compute times of impact and bounces with different formulas, so their states differ
//    by roundings, which the gas's chaos multiplies by a roughly constant factor for each
//    collision a ball takes part in: the largest relative time difference is ~1e-14 over the
//    first N collisions, ~1e-13 over 2N and ~1e-11 over 4N at η = 0.3, and the sequences part
//    (a difference over 1e-9, then another pair) after 6 to 13 collisions per ball. The check
//    demands the first kMustAgree = 1000 (2 to 5 per ball, where the differences are still below
//    1e-12, so a real disagreement, not chaos, would fail it) and prints where they part.
// 2. the textbook simulator alone for 20 more collisions per ball: every N collisions, no two
//    disks closer than a diameter less 1e-9, every ball inside the cell it is filed in (to 1e-9,
//    the invariant that makes the 3×3 block hold every ball it can touch) and the cell lists
//    consistent; at the end, the kinetic energy unchanged to 1e-12 relative.
int check() {
  constexpr std::size_t kCompared = 5000;
  constexpr std::size_t kMustAgree = 1000;
  constexpr double kTimeTolerance = 1e-9;
  bool ok = true;
  for (const std::uint64_t n : {std::uint64_t{200}, std::uint64_t{500}}) {
    for (const double eta : {0.3, 0.6}) {
      const carom::science::HardDiskLayout layout = carom::science::hard_disk_layout(n, eta);
      carom::World world = carom::science::make_hard_disk_world(layout, 1);
      const Start start = start_of(world, layout.side);
      std::vector<std::uint32_t> lattice_index;  // BallId::index → position in balls()
      const std::vector<carom::BallId> ids = world.balls();
      for (std::uint32_t k = 0; k < ids.size(); ++k) {
        if (ids[k].index >= lattice_index.size()) lattice_index.resize(ids[k].index + 1, 0);
        lattice_index[ids[k].index] = k;
      }
      world.set_contact_recording(true);
      world.run_collisions(kCompared);
      const std::span<const carom::ContactEvent> contacts = world.contacts();

      textbook::Gas gas = gas_of(start);
      std::vector<textbook::Collision> collisions;
      gas.run_collisions(kCompared, &collisions);

      std::size_t agree = 0;
      double worst = 0.0;  // the largest relative time difference over the agreeing prefix
      const std::size_t both = std::min(contacts.size(), collisions.size());
      for (; agree < both; ++agree) {
        const carom::ContactEvent& c = contacts[agree];
        const textbook::Collision& t = collisions[agree];
        const std::uint32_t a = lattice_index[c.a.index];
        const std::uint32_t b = lattice_index[c.b.index];
        const double relative = std::abs(t.time - c.time) / std::max(1.0, std::abs(c.time));
        if (c.kind != carom::ContactKind::ball_ball || std::min(a, b) != t.first ||
            std::max(a, b) != t.second || !(relative <= kTimeTolerance)) {
          break;
        }
        worst = std::max(worst, relative);
      }
      // The largest relative time difference within the first N, 2N, 4N collisions (1, 2 and 4
      // collisions per ball), to show how roundings grow.
      double within[3] = {0.0, 0.0, 0.0};
      for (std::size_t k = 0; k < agree; ++k) {
        const double relative = std::abs(collisions[k].time - contacts[k].time) /
                                std::max(1.0, std::abs(contacts[k].time));
        for (std::size_t m = 0; m < 3; ++m) {
          if (k < (std::size_t{1} << m) * n) within[m] = std::max(within[m], relative);
        }
      }
      const bool agreed = agree >= kMustAgree;
      std::printf(
          "n=%llu eta=%.1f cells=%u^2: the first %zu of %zu collisions agree with carom (pair, "
          "order, time to %.0e relative; %zu wanted), %.1f per ball; largest relative time "
          "difference in the first N: %.1e, 2N: %.1e, 4N: %.1e, agreeing prefix: %.1e\n",
          static_cast<unsigned long long>(n), eta, gas.cells_per_axis(), agree, both,
          kTimeTolerance, kMustAgree, static_cast<double>(agree) / static_cast<double>(n),
          within[0], within[1], within[2], worst);
      ok = ok && agreed && both == kCompared;

      // The textbook simulator alone, further on.
      const double energy = gas.kinetic_energy();
      double closest = textbook::kInfinity;
      double outside = 0.0;
      bool lists = true;
      for (int round = 0; round < 20; ++round) {
        gas.run_collisions(n);
        closest = std::min(closest, gas.closest_pair_distance());
        outside = std::max(outside, gas.farthest_outside_cell());
        lists = lists && gas.cell_lists_consistent();
      }
      const double drift = std::abs(gas.kinetic_energy() - energy) / energy;
      const bool sound = closest >= 1.0 - 1e-9 && outside <= 1e-9 && lists && drift <= 1e-12;
      std::printf(
          "  then %llu collisions (%llu crossings, %llu stale): closest pair %.15f, farthest "
          "outside its cell %.1e, cell lists %s, energy drift %.1e: %s\n",
          static_cast<unsigned long long>(gas.collisions()),
          static_cast<unsigned long long>(gas.crossings()),
          static_cast<unsigned long long>(gas.stale()), closest, outside,
          lists ? "consistent" : "INCONSISTENT", drift, sound && agreed ? "ok" : "FAILED");
      ok = ok && sound;
    }
  }
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--check") == 0) return check();
  if (argc < 4) {
    std::fprintf(stderr,
                 "usage: %s N ETA COLLISIONS_PER_BALL [EQUILIBRATE_PER_BALL=2] [SHUFFLED=0]\n",
                 argv[0]);
    std::fprintf(stderr, "       %s --check\n", argv[0]);
    return 2;
  }
  const std::uint64_t n = std::strtoull(argv[1], nullptr, 10);
  const double eta = std::atof(argv[2]);
  const double per_ball = std::atof(argv[3]);
  const double equilibrate = argc > 4 ? std::atof(argv[4]) : 2.0;
  const bool shuffle = argc > 5 && std::atoi(argv[5]) != 0;
  const carom::science::HardDiskLayout layout = carom::science::hard_disk_layout(n, eta);
  if (n == 0 || !layout.box_wide_enough() || !layout.disks_fit()) {
    std::fprintf(stderr, "the triangular lattice cannot hold %llu disks at packing %g\n",
                 static_cast<unsigned long long>(n), eta);
    return 2;
  }
  // The start, read out of carom's world, which is then freed and its memory handed back to the
  // system (malloc_trim), so that the growth of the resident set from here counts the textbook
  // simulator's memory alone, pages reused from the world included.
  Start start;
  {
    const carom::World world = carom::science::make_hard_disk_world(layout, 1);
    start = start_of(world, layout.side);
  }
  if (shuffle) start = shuffled(start);
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  const long resident_before = resident_kib();
  textbook::Gas gas = gas_of(start);
  gas.run_collisions(static_cast<std::uint64_t>(equilibrate * static_cast<double>(n)));
  const long resident_after = resident_kib();
  const auto wanted = static_cast<std::uint64_t>(per_ball * static_cast<double>(n));
  const carom::bench::TimedCollisions timed = carom::bench::timed_collisions(gas, wanted);
  const auto count = static_cast<double>(timed.collisions);
  std::printf(
      "n=%llu eta=%.2f shuffled=%d cells=%u^2 collisions=%llu cpu_s=%.3f cpu_rate=%.0fk/s "
      "cpu_ns_per_collision=%.0f crossings_per_collision=%.3f stale_per_collision=%.3f "
      "bytes_per_ball=%.0f array_bytes_per_ball=%.0f energy_drift=%.2e\n",
      static_cast<unsigned long long>(n), eta, shuffle ? 1 : 0, gas.cells_per_axis(),
      static_cast<unsigned long long>(timed.collisions), timed.cpu_seconds,
      count / timed.cpu_seconds / 1e3, timed.cpu_seconds / count * 1e9,
      timed.crossings_per_collision, timed.stale_per_collision,
      static_cast<double>(resident_after - resident_before) * 1024.0 / static_cast<double>(n),
      static_cast<double>(gas.bytes()) / static_cast<double>(n), timed.energy_drift);
  return timed.collisions == wanted ? 0 : 1;
}
