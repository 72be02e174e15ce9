// libFuzzer target for carom::World driven by a random sequence of API calls: add and remove
// balls (some with collision filters that let pairs pass through each other), move them
// (refused or to the nearest free place), set velocities, step with random dt,
// run_until, run_collisions with small counts (with and without a time limit), a stop condition,
// contact recording on and off, and a save → load round trip; in an open world, a box and a
// periodic cell, with segments and arcs in the first two (some of them moving: translating,
// turning about a pivot, for a while or for ever), and sensors (segments, arcs and discs, some
// removing the balls that enter); on a billiards table (spins, cue strikes, cushions) too. After
// every call it checks:
// - the only exception is carom::InvalidArgument, thrown exactly when an argument the harness
//   knows to be invalid was passed, or when a placement overlaps (then the world is unchanged);
// - World::audit finds no overlap and no ball outside the box; every number is finite;
// - time never goes back, contacts lie in the call's time range in the documented order;
// - elastic worlds keep their energy (kinetic, plus potential under gravity) and inelastic ones
//   never gain any (to rounding), on a table the spins' energy counted in;
// - a table's changes of motion state lie in the call's time range in time order;
// - a loaded world saves to the same bytes and, given the next call, agrees bit for bit with
//   the world it was saved from;
// - the queries (a ray's every hit, a ball cast, a circle and a box from each of a few balls)
//   find what a scan of every ball and wall finds;
// - sensors' enters and exits lie in the call's time range in time order, alternate for each
//   ball and sensor, agree with balls_in_sensor, and a ball recorded inside a sensor overlaps
//   it (one recorded outside does not, where its filter meets the sensor).
//
// Input bytes, read front to back (missing bytes read as 0, so every input is valid):
//   byte 0: boundary (open, box, periodic), the world's restitution and gravity (none, or, in an
//   open world or a box, down at 9.81 with balls resting and sliding) or, without gravity,
//   growth (radii growing at 0.05 of themselves a time unit; energy is then pumped in, not
//   checked), or a table (carom::Table's defaults; half the velocity calls strike or spin);
//   then up to kMaxWalls walls (non-periodic worlds), then up to kMaxCalls calls, one opcode
//   byte each followed by its arguments. Counts, sizes and speeds are bounded so that one input
//   runs in milliseconds; the call that brings the world's contacts to kMaxContacts is stopped
//   there and ends the input. Seeds: tests/fuzz/corpus/world/ (written by make_world_corpus.py).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "carom/bounce.hpp"
#include "carom/error.hpp"
#include "carom/geometry.hpp"
#include "carom/sweep.hpp"
#include "carom/world.hpp"

namespace {

using carom::BallDef;
using carom::BallId;
using carom::Boundary;
using carom::Segment;
using carom::SensorAction;
using carom::Vec2;
using carom::WallId;
using carom::World;
using carom::WorldDef;

constexpr std::size_t kMaxWalls = 6;
constexpr std::size_t kMaxCalls = 48;
constexpr std::size_t kMaxBalls = 24;
// Contacts an input may resolve: the call that reaches the count is stopped there (through the
// stop condition) and the input ends. A ball of radius 10⁻⁶ rattling between a box's corner and
// an immovable ball set against it makes millions of real contacts a time unit, and light balls
// between heavy ones in a small periodic cell 10⁵ a call
// (10 s an input under the sanitizers): valid physics whose cost is only the
// count, which ended fuzz runs on their time limit. Ordinary inputs resolve a few thousand.
constexpr std::uint64_t kMaxContacts = 50'000;
// The box and the periodic cell: [0, 20]².
constexpr double kSide = 20.0;
constexpr double kSmallestOpenRadius = 0.01;
// The speed past which a ball falling in an open world ends the input (see falling_too_fast): a
// fall of 20 time units under gravity 9.81, twice the fastest launch.
constexpr double kFastestFall = 200.0;
// Elastic worlds keep their energy to rounding: each bounce changes it by a few ulps of the
// pair's energy, itself at most the total. 1e-9 relative leaves room for thousands of bounces
// at 1e-13 each; a real bug (a missed wall, a bad impulse) changes it at the percent level.
constexpr double kEnergyTolerance = 1e-9;

[[noreturn]] void fail(const char* what, const std::string& detail = {}) {
  std::fprintf(stderr, "carom world fuzz: %s %s\n", what, detail.c_str());
  std::abort();
}

void check(bool ok, const char* what, const std::string& detail = {}) {
  if (!ok) fail(what, detail);
}

// CAROM_WORLD_FUZZ_TRACE=1 prints every call, so that a reproducer reads as a program.
const bool kTrace = std::getenv("CAROM_WORLD_FUZZ_TRACE") != nullptr;

// A macro, so that the compiler checks each format against its arguments.
#define CAROM_TRACE(...)                           \
  do {                                             \
    if (kTrace) std::fprintf(stderr, __VA_ARGS__); \
  } while (false)

// Reads the fuzz bytes front to back; past the end every read is 0.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  [[nodiscard]] bool done() const { return at_ >= size_; }
  std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  std::uint16_t word() { return static_cast<std::uint16_t>(byte() | (byte() << 8)); }
  // A fraction in [0, 1].
  double unit() { return word() / 65535.0; }
  // One of a few values, so that the fuzzer reaches the interesting ones (0, tiny, huge).
  template <std::size_t N>
  double pick(const double (&values)[N]) {
    return values[byte() % N];
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

constexpr double kRadii[] = {0.5, 1.0, 0.01, 2.0, 0.25, 1e-6, 3.0, 0.1};
constexpr double kSpeeds[] = {0.0, 1.0, 3.0, 0.5, 10.0, 1e-9, 100.0, 7.0};
constexpr double kSteps[] = {0.1, 0.0, 1.0, 0.01, 2.5, 1e-12, 0.37, 5.0};
constexpr double kMasses[] = {1.0, 2.0, 0.5, 1e-3, 1e3, carom::kImmovable, 1.0, 3.0};
constexpr double kRestitutions[] = {1.0, 1.0, 0.9, 0.5, 0.3, 1.0};

// A position: mostly inside [0, kSide]², sometimes outside it (to be refused by a box, or
// wrapped by a periodic cell).
Vec2 position(Bytes& in) {
  const std::uint8_t mode = in.byte();
  const double spread = (mode & 7) == 0 ? 3.0 * kSide : kSide;
  const double offset = (mode & 7) == 0 ? -kSide : 0.0;
  return {offset + spread * in.unit(), offset + spread * in.unit()};
}

Vec2 velocity(Bytes& in) {
  const double speed = in.pick(kSpeeds);
  const double angle = 2.0 * std::numbers::pi * in.unit();
  // Axis-aligned now and then: the directions that graze walls and stay on grid lines.
  if ((in.byte() & 3) == 0) return {speed, 0.0};
  return {speed * std::cos(angle), speed * std::sin(angle)};
}

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// Everything observable about the world's balls, for "unchanged" and "identical" checks.
struct Snapshot {
  double time = 0.0;
  std::vector<BallId> ids;
  std::vector<double> numbers;
  std::uint64_t collisions = 0;
  friend bool operator==(const Snapshot&, const Snapshot&) = default;
};

Snapshot snapshot(const World& world) {
  Snapshot s;
  s.time = world.time();
  s.ids = world.balls();
  s.collisions = world.collision_count();
  for (const BallId id : s.ids) {
    const Vec2 p = world.position(id);
    const Vec2 v = world.velocity(id);
    s.numbers.insert(s.numbers.end(), {p.x, p.y, v.x, v.y, world.radius(id), world.mass(id)});
    if (world.def().table) {
      const carom::Spin w = world.spin(id);
      s.numbers.insert(s.numbers.end(), {w.x, w.y, w.z});
    }
  }
  return s;
}

bool same_bits(const Snapshot& a, const Snapshot& b) {
  return a.ids == b.ids && a.collisions == b.collisions &&
         std::memcmp(&a.time, &b.time, sizeof a.time) == 0 &&
         a.numbers.size() == b.numbers.size() &&
         (a.numbers.empty() ||
          std::memcmp(a.numbers.data(), b.numbers.data(), a.numbers.size() * sizeof(double)) == 0);
}

std::string save_bytes(const World& world) {
  std::ostringstream out(std::ios::binary);
  world.save(out);
  return out.str();
}

class Harness {
 public:
  explicit Harness(Bytes& in) : in_(in) {
    const std::uint8_t head = in_.byte();
    const int choice = head & 0x7f;  // the top bit chooses the cell size
    def_.boundary = static_cast<Boundary>(choice % 3);
    def_.lower = {0.0, 0.0};
    def_.upper = {kSide, kSide};
    def_.restitution =
        kRestitutions[static_cast<std::size_t>(choice / 3) % std::size(kRestitutions)];
    // Inelastic balls could collapse (infinitely many contacts in finite time) without the TC
    // model, and a run would never end; the world offers collapse_time for exactly that.
    if (def_.restitution < 1.0) def_.collapse_time = 1e-2;
    // Gravity in an open world or a box. (In a periodic cell balls fall for ever, ever faster,
    // and a run of a few calls can take minutes of cell crossings: the reference tests cover it.)
    if ((choice / 18) % 2 == 1 && def_.boundary != Boundary::periodic) def_.gravity = {0.0, -9.81};
    if ((choice / 36) % 2 == 1 && def_.gravity == Vec2{}) def_.growth_rate = 0.05;
    // A billiards table (neither gravity nor growth): balls slide, roll, spin and stop, and every
    // wall is a cushion. Energy, spin's included, then only falls.
    if (choice / 72 == 1 && def_.gravity == Vec2{} && def_.growth_rate == 0.0) {
      def_.table = carom::Table{};
    }
    if ((head & 0x80) != 0) def_.cell_size = 4.0;  // a fixed grid as well as the chosen one
    world_.emplace(def_);
    install_stop_condition(*world_, 0);
    CAROM_TRACE("World(boundary %d, restitution %g, cell_size %g, gravity %g, growth %g)\n",
                static_cast<int>(def_.boundary), def_.restitution, def_.cell_size, def_.gravity.y,
                def_.growth_rate);
    driven_ = def_.growth_rate != 0.0;  // growth pumps energy in
    elastic_ = def_.restitution == 1.0 && !def_.table;
  }

  void run() {
    if (def_.boundary != Boundary::periodic) add_walls();
    for (std::size_t call = 0; call < kMaxCalls && !in_.done() && !jammed_; ++call) {
      one_call();
      if (slowed_) break;  // before the audit (see set_velocity)
      check_invariants();
      if (over_budget_ || falling_too_fast()) break;
    }
  }

  // An open world under gravity with nothing below a ball: it falls for ever, faster and faster,
  // and its grid follows it, so each time unit brings more cell crossings (an input that ran 200
  // time units took 17 s). Valid physics whose cost is only the count: the input ends once a
  // ball is that fast.
  [[nodiscard]] bool falling_too_fast() {
    if (def_.boundary != Boundary::open || def_.gravity == Vec2{}) return false;
    for (const BallId id : world().balls()) {
      if (carom::length(world().velocity(id)) > kFastestFall) return true;
    }
    return false;
  }

 private:
  World& world() { return *world_; }

  void add_walls() {
    const std::size_t count = in_.byte() % (kMaxWalls + 1);
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint8_t kind = in_.byte();
      // Bit 3: a sensor (bit 4: one that removes the balls entering it; bit 5: a disc).
      const bool sensor = (kind & 8) != 0;
      const SensorAction action =
          (kind & 16) != 0 ? SensorAction::remove_ball : SensorAction::report;
      try {
        if (sensor && (kind & 32) != 0) {
          const Vec2 c = position(in_);
          const double radius = 0.05 + 4.0 * in_.unit();
          CAROM_TRACE("add_sensor(disc {%.17g, %.17g}, %.17g, %d)\n", c.x, c.y, radius,
                      static_cast<int>(action));
          world().add_sensor(carom::Ball{c, radius}, action);
        } else if ((kind & 1) == 0) {
          const Vec2 a = position(in_);
          // A zero-length segment (a point) now and then.
          const Vec2 b = (kind & 6) == 0 ? a : position(in_);
          CAROM_TRACE("add_%s({%.17g, %.17g}, {%.17g, %.17g})\n", sensor ? "sensor" : "segment",
                      a.x, a.y, b.x, b.y);
          if (sensor) {
            world().add_sensor(Segment{a, b}, action);
          } else {
            set_motion(world().add_segment({a, b}), kind, a);
          }
        } else {
          const Vec2 c = position(in_);
          const double radius = 0.5 + 8.0 * in_.unit();
          const double start = 2.0 * std::numbers::pi * (in_.unit() - 0.5);
          // Zero span, a full circle, or anything between.
          const double span = (kind & 6) == 0   ? 0.0
                              : (kind & 6) == 2 ? 2.0 * std::numbers::pi
                                                : 2.0 * std::numbers::pi * in_.unit();
          CAROM_TRACE("add_%s({%.17g, %.17g}, %.17g, %.17g, %.17g)\n", sensor ? "sensor" : "arc",
                      c.x, c.y, radius, start, start + span);
          if (sensor) {
            world().add_sensor(carom::Arc{c, radius, start, start + span}, action);
          } else {
            set_motion(world().add_arc({c, radius, start, start + span}), kind, c);
          }
        }
      } catch (const carom::InvalidArgument& error) {
        fail("a valid wall was refused:", error.what());
      }
    }
  }

  // Bit 6 of a solid wall's kind: it moves, turning about a pivot near `near` and translating
  // (bit 7: for a while rather than for ever), its motion read from the input.
  void set_motion(carom::WallId wall, std::uint8_t kind, Vec2 near) {
    if ((kind & 64) == 0) return;
    if (def_.table) {
      carom::WallMotion refused;
      refused.velocity = {1.0, 0.0};
      return expect_refusal([&](World& w) { w.set_wall_motion(wall, refused); });
    }
    carom::WallMotion motion;
    motion.velocity = {2.0 * (in_.unit() - 0.5), 2.0 * (in_.unit() - 0.5)};
    motion.angular_velocity = 8.0 * (in_.unit() - 0.5);
    motion.pivot = near + Vec2{in_.unit() - 0.5, in_.unit() - 0.5};
    if ((kind & 128) != 0) motion.duration = 3.0 * in_.unit();
    CAROM_TRACE("set_wall_motion(%u, {%.17g, %.17g}, %.17g, {%.17g, %.17g}, %.17g)\n", wall,
                motion.velocity.x, motion.velocity.y, motion.angular_velocity, motion.pivot.x,
                motion.pivot.y, motion.duration);
    world().set_wall_motion(wall, motion);
    check(world().wall_motion(wall) ==
              (motion.moves() ? motion : carom::WallMotion{{}, 0.0, {}, 0.0}),
          "wall_motion is not the motion set");
    // A moving wall does work on the balls, and may crush them against another wall.
    driven_ = true;
    walls_move_ = true;
  }

  BallId some_ball() {
    const std::vector<BallId> ids = world().balls();
    if (ids.empty()) return {};
    return ids[in_.byte() % ids.size()];
  }

  void one_call() {
    const std::uint8_t op = in_.byte();
    // The twin of a loaded world follows it through the next call that advances time only; any
    // other call ends the comparison.
    const bool advances = op % 12 >= 5 && op % 12 <= 8;
    if (!advances) twin_.reset();
    switch (op % 12) {
      case 0:
      case 1:
        return add_ball();
      case 2:
        return remove_ball();
      case 3:
        return set_position();
      case 4:
        return set_velocity();
      case 5:
      case 6:
        return advance_by_step();
      case 7:
        return advance_by_collisions();
      case 8:
        return advance_until();
      case 9:
        return save_and_load();
      case 10:
        return set_stop_condition();
      default:
        return bad_call();
    }
  }

  void add_ball() {
    if (world().ball_count() >= kMaxBalls) return;
    BallDef def;
    def.position = position(in_);
    def.velocity = velocity(in_);
    def.radius = in_.pick(kRadii);
    // An open world plans its grid around the balls' extent, which for one ball is a few of its
    // diameters: a lone ball of radius 1e-6 crossing 10 lengths makes ~10⁷ cell crossings
    // (seconds; correct, but too slow for a fuzz input). Tiny balls are fuzzed in the box and
    // the periodic cell, whose grid covers the whole of it.
    if (def_.boundary == Boundary::open) def.radius = std::max(def.radius, kSmallestOpenRadius);
    def.mass = in_.pick(kMasses);
    // A moving immovable ball does work on the balls it meets without limit: crushed balls are
    // refused once their contacts pile up (WorldExtreme.RowOfBallsCrushedByAMovingImmovableBall…),
    // but one driving a periodic gas heats it ever faster, more contacts each time unit (inputs
    // of 26 s when tried).
    // Valid input the fuzzer cannot bound, so immovable balls stay at rest.
    if (def.mass == carom::kImmovable) def.velocity = {};
    const std::uint8_t r = in_.byte();
    if (r % 4 == 1) {
      def.restitution = kRestitutions[r / 4 % std::size(kRestitutions)];
      if (*def.restitution < 1.0 && def_.collapse_time == 0.0) def.restitution = 1.0;
    }
    // r % 4 == 2: a collision filter of one of three kinds (each meeting its own kind, one of
    // them the default's too, one in a group that never meets itself), so that pairs pass
    // through each other and filtered balls are placed overlapping.
    carom::CollisionFilter filter;
    if (r % 4 == 2) {
      const std::uint64_t kind = std::uint64_t{1} << (r / 4 % 3);
      filter = {kind, kind | (r / 16 % 2 == 0 ? 1U : 0U), r / 32 % 2 == 0 ? 0 : -1};
    }
    const Snapshot before = snapshot(world());
    CAROM_TRACE(
        "add_ball(p {%.17g, %.17g}, v {%.17g, %.17g}, r %.17g, m %.17g, e %.17g, filter {%llu, "
        "%llu, %d})\n",
        def.position.x, def.position.y, def.velocity.x, def.velocity.y, def.radius, def.mass,
        def.restitution.value_or(-1.0), static_cast<unsigned long long>(filter.category),
        static_cast<unsigned long long>(filter.mask), static_cast<int>(filter.group));
    try {
      const BallId id = world().add_ball(def, filter);
      check(world().contains(id), "add_ball returned a handle the world does not contain");
      check(world().filter(id) == filter, "add_ball lost the filter");
      check(world().radius(id) == def.radius, "add_ball lost the radius");
      if (def.restitution && *def.restitution < 1.0) elastic_ = false;
      if (def.mass == carom::kImmovable && (def.velocity.x != 0.0 || def.velocity.y != 0.0)) {
        // A moving immovable ball does work on the others: it may add energy or take it.
        driven_ = true;
      }
    } catch (const carom::InvalidArgument&) {
      // An overlapping place, outside the box, or too big for the periodic cell: refused, and
      // nothing changed.
      check(snapshot(world()) == before, "a refused add_ball changed the world");
    }
    reset_energy();
  }

  void remove_ball() {
    const BallId id = some_ball();
    if (id.is_null()) return;
    CAROM_TRACE("remove_ball(%u)\n", id.index);
    world().remove_ball(id);
    forget_sensor_pairs(id);
    check(!world().contains(id), "a removed ball is still there");
    try {
      (void)world().position(id);
      fail("a stale handle was accepted");
    } catch (const carom::InvalidArgument&) {
    }
    reset_energy();
  }

  void set_position() {
    const BallId id = some_ball();
    const Vec2 target = position(in_);
    const bool nearest = (in_.byte() & 1) != 0;
    if (id.is_null()) return;
    const Snapshot before = snapshot(world());
    const Vec2 from = world().position(id);
    CAROM_TRACE("set_position(%u, {%.17g, %.17g}, %s)\n", id.index, target.x, target.y,
                nearest ? "nearest_free" : "refuse");
    try {
      const Vec2 placed = world().set_position(
          id, target, nearest ? carom::Placement::nearest_free : carom::Placement::refuse);
      check(finite(placed), "set_position placed a ball at a non-finite place");
      check(placed == world().position(id), "set_position returned another place than it used");
      if (!nearest && def_.boundary != Boundary::periodic) {
        check(placed == target, "set_position(refuse) moved the ball elsewhere");
      }
      if (nearest && def_.boundary != Boundary::periodic) {
        // On the segment from where it was to where it was asked to go.
        const Vec2 path = target - from;
        const Vec2 moved = placed - from;
        const double scale = std::max({1.0, std::abs(path.x), std::abs(path.y)});
        check(std::abs(carom::cross(path, moved)) <= 1e-9 * scale * scale,
              "nearest_free left the line towards the target");
        check(carom::dot(moved, path) >= -1e-9 * scale * scale,
              "nearest_free moved the ball backwards");
      }
    } catch (const carom::InvalidArgument&) {
      check(snapshot(world()) == before, "a refused set_position changed the world");
    }
    reset_energy();
  }

  void set_velocity() {
    // A growing world is driven anyway; half its velocity calls are a thermostat's step instead.
    if (def_.growth_rate != 0.0 && in_.byte() % 2 == 0) return set_temperature();
    // On a table half of them are a cue's strike or a spin set instead.
    if (def_.table && in_.byte() % 2 == 0) return strike();
    const BallId id = some_ball();
    Vec2 v = velocity(in_);
    if (id.is_null()) return;
    if (world().mass(id) == carom::kImmovable) v = {};  // see add_ball
    CAROM_TRACE("set_velocity(%u, {%.17g, %.17g})\n", id.index, v.x, v.y);
    // The audit allows a ball the rounding of its present speed times the time; a ball slowed
    // after fast motion may carry its old speed's rounding (a tiny ball 16 ulps into an arc after
    // a slowing to 10⁻⁹ was found). The input ends after such a slowing (a limit of the audit's
    // model, not of the engine: an overlapping ball that separates is left alone, one that
    // approaches bounces at once).
    const double old_speed = carom::length(world().velocity(id));
    if (carom::length(v) * 16.0 < old_speed && world().time() > 0.0) slowed_ = true;
    world().set_velocity(id, v);
    check(world().velocity(id) == v, "set_velocity did not set it");
    if (world().mass(id) == carom::kImmovable && (v.x != 0.0 || v.y != 0.0)) driven_ = true;
    reset_energy();
  }

  // World::set_temperature: the movable balls' kinetic energy about their centre of mass becomes
  // kT a ball (when they move relative to it at all), the momentum stays.
  void set_temperature() {
    static constexpr double kTemperatures[] = {0.01, 1.0, 4.0};
    const double kT = in_.pick(kTemperatures);
    CAROM_TRACE("set_temperature(%.17g)\n", kT);
    double mass = 0.0;
    double count = 0.0;
    // Σ m·|v|, before and after: the momentum's rounding is relative to it, not to |P|, which
    // fast balls moving against each other can make small.
    const auto momentum_scale = [this] {
      double scale = 0.0;
      for (const BallId id : world().balls()) {
        if (world().mass(id) == carom::kImmovable) continue;
        scale += world().mass(id) * carom::length(world().velocity(id));
      }
      return scale;
    };
    for (const BallId id : world().balls()) {
      if (world().mass(id) == carom::kImmovable) continue;
      mass += world().mass(id);
      count += 1.0;
    }
    const double scale_before = momentum_scale();
    const Vec2 momentum = world().momentum();
    const double before = world().kinetic_energy();
    const double work = world().set_temperature(kT);
    const double after = world().kinetic_energy();
    check(std::abs(after - before - work) <= 1e-9 * (before + after + 1.0),
          "set_temperature's work is not the change of kinetic energy");
    check(carom::length(world().momentum() - momentum) <=
              1e-9 * (scale_before + momentum_scale() + 1e-300),
          "set_temperature changed the momentum");
    if (count == 0.0) return reset_energy();
    const double internal_before = before - carom::dot(momentum, momentum) / (2.0 * mass);
    if (internal_before > 1e-12 * before) {
      const double internal = after - carom::dot(momentum, momentum) / (2.0 * mass);
      check(std::abs(internal - count * kT) <= 1e-6 * count * kT,
            "set_temperature did not reach kT a ball");
      // A strong cooling leaves balls with the rounding of their old speeds (see set_velocity).
      if (after * 256.0 < before && world().time() > 0.0) slowed_ = true;
    }
    reset_energy();
  }

  // A call that advances time; checks the contacts it reports and, after a load, that the
  // twin saved before it agrees bit for bit.
  template <typename Call>
  void advance(Call call) {
    const double start = world().time();
    try {
      call(world());
    } catch (const carom::InvalidArgument& e) {
      // Jammed balls and a stalled time are refused mid-run (docs/world.md, "Known limits"), and
      // so are balls grown too large for a periodic cell or packed until their contacts pile up:
      // the world must still be valid; the input ends, since its future is undefined.
      const std::string what = e.what();
      const bool growing =
          def_.growth_rate != 0.0 && (what.find("grown too large") != std::string::npos ||
                                      what.find("piling up") != std::string::npos);
      const bool crushed = walls_move_ && what.find("crushed") != std::string::npos;
      check(what.find("jammed") != std::string::npos || what.find("stalled") != std::string::npos ||
                growing || crushed,
            "a run threw for a valid call");
      jammed_ = true;
      return;
    }
    const double end = world().time();
    check(end >= start, "time went back");
    const auto contacts = world().contacts();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const carom::ContactEvent& c = contacts[i];
      check(c.time >= start && c.time <= end, "a contact outside the call's time range");
      check(std::isfinite(c.impulse) && c.impulse >= 0.0, "a bad impulse");
      check(finite(c.point) && finite(c.normal), "a non-finite contact point or normal");
      check(std::abs(carom::length(c.normal) - 1.0) < 1e-9, "a contact normal is not unit");
      if (i > 0) check(contacts[i - 1].time <= c.time, "contacts out of time order");
    }
    check_sensor_events(start, end);
    double motion_before = start;
    for (const carom::MotionEvent& e : world().motion_events()) {
      check(e.time >= motion_before && e.time <= end, "a motion event out of order or range");
      check(e.from != e.to, "a motion event that changes nothing");
      motion_before = e.time;
    }
    // A ball placed into or out of a sensor between runs changes at the next run's start: the
    // states agree with the places once a run has passed that instant.
    sensors_settled_ = end > start;
    over_budget_ = world().stopped_early() && world().collision_count() >= kMaxContacts;
    if (over_budget_) CAROM_TRACE("stopped by the contact budget at t = %.17g\n", world().time());
    if (twin_) {
      call(*twin_);
      check(same_bits(snapshot(*twin_), snapshot(world())),
            "a loaded world diverged from the world it was saved from");
      check(twin_->sensor_events().size() == world().sensor_events().size(),
            "a loaded world recorded other sensor events");
      twin_.reset();
    }
  }

  void advance_by_step() {
    const double dt = in_.pick(kSteps) * (1.0 + in_.unit());
    CAROM_TRACE("step(%.17g)\n", dt);
    advance([dt](World& w) {
      const double advanced = w.step(dt);
      check(advanced >= 0.0 && advanced <= dt, "step advanced outside [0, dt]");
    });
  }

  void advance_by_collisions() {
    const std::uint8_t how = in_.byte();
    const std::uint64_t count = how % 9;
    const double limit = world().time() + in_.pick(kSteps) * 4.0;
    // Without a time limit only where a run is sure to end: a box, whose walls the balls meet. A
    // periodic cell can hold orbits that never meet and cannot be proved not to, and an open
    // world balls that meet only after an astronomically long flight (found by the fuzzer: two
    // balls side by side at speed 7, converging by 1.7·10⁻¹⁵, a run of 10¹⁵ grid re-plans;
    // world.hpp): runs the caller must bound.
    const bool unlimited = (how & 0x80) != 0 && def_.boundary == Boundary::box;
    CAROM_TRACE("run_collisions(%u, %.17g)\n", static_cast<unsigned>(count),
                unlimited ? INFINITY : limit);
    advance([count, limit, unlimited](World& w) {
      const std::uint64_t done =
          unlimited ? w.run_collisions(count) : w.run_collisions(count, limit);
      check(done <= count, "run_collisions resolved more than asked");
      if (!unlimited) check(w.time() <= limit, "run_collisions ran past its time limit");
      if (w.contact_recording() && !w.stopped_early()) {
        check(w.contacts().size() == done, "run_collisions miscounted its contacts");
      }
    });
  }

  void advance_until() {
    const double target = world().time() + in_.pick(kSteps);
    CAROM_TRACE("run_until(%.17g)\n", target);
    advance([target](World& w) {
      (void)w.run_until(target);
      if (w.stop_reason() == carom::StopReason::none) {
        check(w.time() == target, "run_until stopped elsewhere");
      } else {
        check(w.time() <= target, "a stopped run_until went past its end");
      }
    });
  }

  void save_and_load() {
    CAROM_TRACE("save and load\n");
    const std::string bytes = save_bytes(world());
    std::istringstream in(bytes, std::ios::binary);
    World loaded = World::load(in);
    check(save_bytes(loaded) == bytes, "a loaded world saves to other bytes");
    check(same_bits(snapshot(loaded), snapshot(world())), "a loaded world differs");
    twin_.emplace(std::move(*world_));
    world_.emplace(std::move(loaded));
    // The stop condition is not saved: set it again, as a caller would; on both, since the
    // condition refers to its world by address and both have moved.
    install_stop_condition(*twin_, stop_after_.value_or(0));
    install_stop_condition(*world_, stop_after_.value_or(0));
    install_interruption(*twin_, interrupt_every_);
    install_interruption(*world_, interrupt_every_);
  }

  // Stops at contacts whose count since creation is a multiple of `every` (none when 0), and
  // at the input's contact budget: functions of the world's history only, so that a twin and its
  // loaded copy stop at the same contact. (The world therefore always has a stop condition, and
  // builds every contact's details; unit tests cover the engine without one.)
  static void install_stop_condition(World& w, std::uint32_t every) {
    w.set_stop_condition([&w, every](const carom::ContactEvent&) {
      const std::uint64_t count = w.collision_count();
      return (every != 0 && count % every == 0) || count >= kMaxContacts;
    });
  }

  // A run stopped from outside every `every`-th look at stop requests (every·1024 events): a
  // function of the run's events only, so that a twin and its loaded copy stop alike. 0: never.
  static void install_interruption(World& w, std::uint32_t every) {
    if (every == 0) {
      w.set_progress_callback(nullptr);
      return;
    }
    w.set_progress_callback([every](const carom::RunStatus& status) {
      return status.events > 0 && (status.events / World::kStopCheckEvents) % every == 0;
    });
  }

  void set_stop_condition() {
    const std::uint8_t how = in_.byte();
    CAROM_TRACE("stop condition / recording / interruption: %u\n", static_cast<unsigned>(how % 5));
    if (how % 5 == 0) {
      stop_after_.reset();
      install_stop_condition(world(), 0);
    } else if (how % 5 == 1) {
      stop_after_ = 1 + how % 7;
      install_stop_condition(world(), *stop_after_);
    } else if (how % 5 == 2) {
      world().set_contact_recording(!world().contact_recording());
    } else if (how % 5 == 3) {
      interrupt_every_ = (how / 5) % 4;
      install_interruption(world(), interrupt_every_);
    } else {
      // A request between runs stops the next before its first event, changing nothing.
      const Snapshot before = snapshot(world());
      world().request_stop();
      (void)world().run_until(world().time() + 1.0);
      check(world().stop_reason() == carom::StopReason::interrupted,
            "a requested stop did not stop the next run");
      check(snapshot(world()) == before, "a run stopped before its first event changed the world");
      check(world().contacts().empty(), "a run stopped before its first event had contacts");
    }
  }

  // A call the documentation refuses: it must throw InvalidArgument and change nothing.
  template <typename Call>
  void expect_refusal(Call call) {
    const Snapshot before = snapshot(world());
    bool threw = false;
    try {
      call(world());
    } catch (const carom::InvalidArgument& error) {
      threw = true;
      check(std::string(error.what()).find("carom::") == 0, "a message without carom::");
    }
    check(threw, "an invalid argument was accepted");
    check(snapshot(world()) == before, "a refused call changed the world");
  }

  // Arguments the documentation calls invalid: each must throw InvalidArgument and change
  // nothing.
  void bad_call() {
    const Snapshot before = snapshot(world());
    const std::uint8_t which = in_.byte() % 6;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    bool threw = false;
    try {
      switch (which) {
        case 0:
          (void)world().step(-in_.pick(kSpeeds) - 1e-300);
          break;
        case 1:
          (void)world().step(nan);
          break;
        case 2:
          // Before the time by at least 1, however large the time is.
          (void)world().run_until(-1.0 - world().time());
          break;
        case 3:
          (void)world().run_collisions(1, nan);
          break;
        case 4: {
          BallDef def;
          def.radius = (in_.byte() & 1) != 0 ? 0.0 : nan;
          (void)world().add_ball(def);
          break;
        }
        default: {
          const BallId id = some_ball();
          if (id.is_null()) {
            world().remove_ball(id);
          } else {
            world().set_velocity(id, {std::numeric_limits<double>::infinity(), 0.0});
          }
          break;
        }
      }
    } catch (const carom::InvalidArgument& error) {
      threw = true;
      check(std::string(error.what()).find("carom::") == 0, "a message without carom::");
    }
    check(threw, "an invalid argument was accepted");
    check(snapshot(world()) == before, "a refused call changed the world");
  }

  void reset_energy() { energy_ = total_energy(); }

  // The kinetic energy (on a table with the spins', ½·(2/5)·m·R²·|ω|² a ball) plus gravity's.
  [[nodiscard]] double total_energy() {
    double energy = world().kinetic_energy() + world().potential_energy();
    if (!def_.table) return energy;
    for (const BallId id : world().balls()) {
      if (world().mass(id) == carom::kImmovable) continue;
      const carom::Spin w = world().spin(id);
      const double r = world().radius(id);
      energy += 0.2 * world().mass(id) * r * r * (w.x * w.x + w.y * w.y + w.z * w.z);
    }
    return energy;
  }

  // A cue strikes a ball (the tip anywhere on the ball's face, the cue tilted up to 1.2 rad), or
  // its spin is set; an immovable ball refuses both.
  void strike() {
    const BallId id = some_ball();
    if (id.is_null()) return;
    const double r = world().radius(id);
    carom::CueStrike cue;
    cue.speed = 5.0 * in_.unit();
    cue.direction = 2.0 * std::numbers::pi * in_.unit();
    cue.elevation = 1.2 * in_.unit();
    const double reach = 0.95 * r * in_.unit();
    const double around = 2.0 * std::numbers::pi * in_.unit();
    cue.side = reach * std::cos(around);
    cue.height = reach * std::sin(around);
    const bool spin_only = in_.byte() % 4 == 0;
    const carom::Spin spin{40.0 * (in_.unit() - 0.5) / r, 40.0 * (in_.unit() - 0.5) / r,
                           40.0 * (in_.unit() - 0.5) / r};
    const bool movable = world().mass(id) != carom::kImmovable;
    CAROM_TRACE("%s(%u)\n", spin_only ? "set_spin" : "strike", id.index);
    const auto call = [&](World& w) {
      if (spin_only) {
        w.set_spin(id, spin);
      } else {
        w.strike(id, cue);
      }
    };
    if (!movable) return expect_refusal(call);
    try {
      call(world());
    } catch (const carom::InvalidArgument& error) {
      fail("a valid strike or spin was refused:", error.what());
    }
    if (spin_only) check(world().spin(id) == spin, "set_spin did not set it");
    reset_energy();
  }

  void forget_sensor_pairs(BallId id) {
    for (auto pair = inside_.begin(); pair != inside_.end();) {
      pair = pair->first == id.index ? inside_.erase(pair) : std::next(pair);
    }
  }

  // A call's sensor events, against the states the harness follows.
  void check_sensor_events(double start, double end) {
    double previous = start;
    for (const carom::SensorEvent& e : world().sensor_events()) {
      check(e.time >= previous && e.time <= end, "a sensor event out of order or range");
      previous = e.time;
      check(world().sensor(e.sensor).has_value(), "a sensor event names no sensor");
      const std::pair key{e.ball.index, e.sensor};
      const bool enter = e.kind == carom::SensorEventKind::enter;
      check(enter != inside_.contains(key), "enters and exits do not alternate");
      if (enter) {
        inside_.insert(key);
      } else {
        inside_.erase(key);
      }
      if (e.removed) {
        check(enter && *world().sensor(e.sensor) == SensorAction::remove_ball,
              "a ball removed by a sensor that does not remove");
        check(!world().contains(e.ball), "a ball removed by a sensor is still there");
        forget_sensor_pairs(e.ball);
        removed_ = true;
      }
    }
    for (WallId k = 0; k < world().wall_count(); ++k) {
      if (!world().sensor(k)) continue;
      const auto expected = static_cast<std::size_t>(std::count_if(
          inside_.begin(), inside_.end(), [k](const auto& key) { return key.second == k; }));
      const std::vector<BallId> recorded = world().balls_in_sensor(k);
      for (const BallId id : recorded) {
        check(inside_.contains({id.index, k}), "balls_in_sensor lists a ball never entered");
      }
      check(recorded.size() == expected, "balls_in_sensor misses a ball that entered");
    }
  }

  // Where the harness's own distance says each ball is, against the recorded states.
  void check_sensor_geometry() {
    const World& w = world();
    for (WallId k = 0; k < w.wall_count(); ++k) {
      if (!w.sensor(k)) continue;
      const auto shape = w.wall(k);
      for (const BallId id : w.balls()) {
        const Vec2 p = w.position(id);
        double distance = 0.0;
        if (const auto* s = std::get_if<Segment>(&shape)) {
          distance = carom::length(carom::nearest_point(*s, p) - p);
        } else if (const auto* disc = std::get_if<carom::Ball>(&shape)) {
          distance = std::max(0.0, carom::length(p - disc->center) - disc->radius);
        } else {
          const auto& arc = std::get<carom::Arc>(shape);
          const auto at = [&](double angle) {
            return arc.center + Vec2{std::cos(angle), std::sin(angle)} * arc.radius;
          };
          distance = std::min(carom::length(p - at(arc.start_angle)),
                              carom::length(p - at(arc.end_angle)));
          const Vec2 offset = p - arc.center;
          const double turn = 2.0 * std::numbers::pi;
          const double from_start = std::fmod(
              std::fmod(std::atan2(offset.y, offset.x) - arc.start_angle, turn) + turn, turn);
          if (from_start <= arc.end_angle - arc.start_angle ||
              arc.end_angle - arc.start_angle >= turn) {
            distance = std::min(distance, std::abs(carom::length(offset) - arc.radius));
          }
        }
        const double r = w.radius(id);
        // The positions' rounding and the sensors' margin (2^-40 of the coordinates), far
        // below this.
        const double slack = 1e-7 * (std::abs(p.x) + std::abs(p.y) + r + kSide);
        if (inside_.contains({id.index, k})) {
          check(distance <= r + slack, "a ball recorded inside a sensor is clear of it");
        } else if (carom::should_collide(w.filter(id), w.wall_filter(k))) {
          check(distance >= r - slack, "a ball recorded outside a sensor overlaps it");
        }
      }
    }
  }

  void check_invariants() {
    World& w = world();
    if (const auto problem = w.audit()) fail("audit:", *problem);
    check(std::isfinite(w.time()), "the time is not finite");
    for (const BallId id : w.balls()) {
      check(finite(w.position(id)) && finite(w.velocity(id)), "a non-finite ball");
      if (def_.boundary == Boundary::periodic) {
        const Vec2 p = w.position(id);
        // Inside the cell, to the rounding of the last re-wrap.
        constexpr double kSlack = 1e-9 * kSide;
        check(p.x >= -kSlack && p.x < kSide + kSlack && p.y >= -kSlack && p.y < kSide + kSlack,
              "a ball outside the periodic cell");
      }
    }
    // Under gravity the total, whose rounding is that of its larger parts.
    const double energy = total_energy();
    check(std::isfinite(energy), "the energy is not finite");
    const double scale = w.kinetic_energy() + std::abs(w.potential_energy());
    const double allowed = kEnergyTolerance * std::max({scale, std::abs(energy_), 1e-300});
    if (driven_ || removed_) {
      // Nothing to check: the immovable ball's motion is a source of energy, or a sensor
      // removed a ball and its energy with it.
      removed_ = false;
    } else if (elastic_) {
      check(std::abs(energy - energy_) <= allowed, "an elastic world changed its energy");
    } else {
      check(energy <= energy_ + allowed, "an inelastic world gained energy");
    }
    energy_ = energy;
    check_queries();
  }

  // The queries against a scan of every ball (at each periodic copy in reach) and wall, from
  // places the world itself gives (no input is read, so the inputs' meaning is unchanged): from
  // each ball's centre a ray and a cast ball across the world, a circle and a box around it.
  void check_queries() {
    const World& w = world();
    const std::vector<BallId> ids = w.balls();
    // The grid (the engine's and so the queries') files a ball by where it is; once the time's
    // rounding moves a ball further than that in one step of the clock (ulp(time) × speed, an
    // input that runs to 10¹⁷), a ball may sit cells away from where it is filed, and the
    // queries, like prediction, no longer see it. Such worlds are not checked.
    double fastest = 0.0;
    for (const BallId id : ids) fastest = std::max(fastest, carom::length(w.velocity(id)));
    if (std::abs(w.time()) * std::numeric_limits<double>::epsilon() * fastest > 1e-8) return;
    if (sensors_settled_) check_sensor_geometry();
    sensors_settled_ = false;
    const bool periodic = def_.boundary == Boundary::periodic;
    // Every place ball `id` may be met at within `reach` of the box [lo, hi].
    const auto copies = [&](BallId id, Vec2 lo, Vec2 hi, double reach) {
      std::vector<Vec2> out;
      const Vec2 p = w.position(id);
      if (!periodic) return std::vector<Vec2>{p};
      const double r = reach + w.radius(id);
      for (double kx = std::ceil((lo.x - r - p.x) / kSide);
           kx <= std::floor((hi.x + r - p.x) / kSide); ++kx) {
        for (double ky = std::ceil((lo.y - r - p.y) / kSide);
             ky <= std::floor((hi.y + r - p.y) / kSide); ++ky) {
          out.push_back(p + Vec2{kx * kSide, ky * kSide});
        }
      }
      return out;
    };
    std::size_t k = 0;
    for (const BallId from : ids) {
      if (++k > 4) break;
      const Vec2 c = w.position(from);
      const double angle = 2.0 * std::numbers::pi * static_cast<double>(k) / 7.0 + 0.3;
      const Vec2 d = Vec2{std::cos(angle), std::sin(angle)} * (1.5 * kSide);
      const Vec2 lo{std::min(c.x, c.x + d.x), std::min(c.y, c.y + d.y)};
      const Vec2 hi{std::max(c.x, c.x + d.x), std::max(c.y, c.y + d.y)};
      // The ray, balls only (every hit, in order), against sweep_ball_point of each copy.
      carom::QueryFilter balls_only;
      balls_only.walls = false;
      std::vector<std::pair<double, std::uint32_t>> expected;
      for (const BallId id : ids) {
        double first = std::numeric_limits<double>::infinity();
        for (const Vec2 p : copies(id, lo, hi, 0.0)) {
          const carom::Impact hit = carom::sweep_ball_point({p, w.radius(id)}, -d, c);
          if (hit.hit && !hit.overlapping) first = std::min(first, hit.t);
        }
        if (first <= 1.0) expected.emplace_back(first, id.index);
      }
      std::sort(expected.begin(), expected.end());
      const std::vector<carom::QueryHit> hits = w.cast_ray_all(c, d, balls_only);
      check(hits.size() == expected.size(), "cast_ray_all found another number of balls");
      for (std::size_t h = 0; h < hits.size(); ++h) {
        check(hits[h].fraction == expected[h].first && hits[h].ball.index == expected[h].second,
              "cast_ray_all differs from the scan");
      }
      // A ball cast of half the ball's radius, everything seen but the ball itself.
      const double radius = 0.5 * w.radius(from);
      double best = std::numeric_limits<double>::infinity();
      for (const BallId id : ids) {
        if (id == from) continue;
        for (const Vec2 p : copies(id, lo, hi, radius)) {
          const carom::Impact hit = carom::sweep_ball_ball({c, radius}, d, {p, w.radius(id)});
          if (hit.hit || hit.overlapping) best = std::min(best, hit.overlapping ? 0.0 : hit.t);
        }
      }
      for (carom::WallId wall = 0; wall < w.wall_count(); ++wall) {
        if (w.sensor(wall)) continue;  // queries do not see sensors
        const auto shape = w.wall(wall);
        const carom::Impact hit =
            std::holds_alternative<carom::Segment>(shape)
                ? carom::sweep_ball_segment({c, radius}, d, std::get<carom::Segment>(shape))
                : carom::sweep_ball_arc({c, radius}, d, std::get<carom::Arc>(shape));
        if (hit.hit || hit.overlapping) best = std::min(best, hit.overlapping ? 0.0 : hit.t);
      }
      carom::QueryFilter not_itself;
      not_itself.ignore = from;
      const carom::QueryHit cast = w.cast_ball(c, radius, d, not_itself);
      check(cast ? cast.fraction == best : !(best <= 1.0), "cast_ball differs from the scan");
      // The balls within a circle of the ball's diameter around it, and in a box of that size.
      const double around = 2.0 * w.radius(from);
      std::vector<std::uint32_t> in_circle;
      std::vector<std::uint32_t> in_box;
      const Vec2 box_lo = c - Vec2{around, around};
      const Vec2 box_hi = c + Vec2{around, around};
      for (const BallId id : ids) {
        for (const Vec2 p : copies(id, box_lo, box_hi, 0.0)) {
          const double reach = around + w.radius(id);
          if (carom::length_squared(p - c) <= reach * reach) in_circle.push_back(id.index);
          const Vec2 nearest{std::clamp(p.x, box_lo.x, box_hi.x),
                             std::clamp(p.y, box_lo.y, box_hi.y)};
          if (carom::length_squared(nearest - p) <= w.radius(id) * w.radius(id))
            in_box.push_back(id.index);
        }
      }
      const auto indices = [](std::vector<BallId> found) {
        std::vector<std::uint32_t> out;
        for (const BallId id : found) out.push_back(id.index);
        return out;
      };
      for (auto* list : {&in_circle, &in_box}) {
        std::sort(list->begin(), list->end());
        list->erase(std::unique(list->begin(), list->end()), list->end());
      }
      const auto listed = [](const std::vector<std::uint32_t>& list) {
        std::string text;
        for (const std::uint32_t k : list) text += " " + std::to_string(k);
        return text;
      };
      const std::vector<std::uint32_t> circle = indices(w.balls_in_circle(c, around));
      if (circle != in_circle && kTrace) {
        std::fprintf(stderr, "time %.17g centre {%.17g, %.17g} around %.17g\n", w.time(), c.x, c.y,
                     around);
        for (const BallId id : ids) {
          std::fprintf(stderr, "  ball %u at {%.17g, %.17g} v {%.17g, %.17g} r %.17g\n", id.index,
                       w.position(id).x, w.position(id).y, w.velocity(id).x, w.velocity(id).y,
                       w.radius(id));
        }
      }
      check(circle == in_circle,
            "balls_in_circle differs:", listed(circle) + " against the scan's" + listed(in_circle));
      const std::vector<std::uint32_t> box = indices(w.balls_in_box(box_lo, box_hi));
      check(box == in_box,
            "balls_in_box differs:", listed(box) + " against the scan's" + listed(in_box));
    }
  }

  Bytes& in_;
  WorldDef def_;
  std::optional<World> world_;
  std::optional<World> twin_;  // the world a loaded one came from, until the next call
  std::optional<std::uint32_t> stop_after_;
  std::uint32_t interrupt_every_ = 0;
  bool over_budget_ = false;  // the world has resolved kMaxContacts contacts: the input ends
  bool elastic_ = true;
  bool driven_ = false;           // an immovable ball has moved: energy is not a conserved quantity
  bool walls_move_ = false;       // some wall was given a motion
  bool jammed_ = false;           // a run refused jammed balls or a stalled time: the input ends
  bool slowed_ = false;           // set_velocity slowed a ball more than 16 times: the input ends
  bool removed_ = false;          // a sensor removed a ball in the last call
  bool sensors_settled_ = false;  // the last call ran past its start
  double energy_ = 0.0;
  // The (ball index, sensor) pairs inside, as the sensor events told.
  std::set<std::pair<std::uint32_t, WallId>> inside_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  try {
    Harness harness(in);
    harness.run();
  } catch (const carom::InvalidArgument& error) {
    fail("an unexpected carom::InvalidArgument:", error.what());
  } catch (const std::exception& error) {
    fail("an exception that is not carom::InvalidArgument:", error.what());
  }
  return 0;
}
