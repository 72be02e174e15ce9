#include "carom/science/packing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "carom/error.hpp"
#include "carom/geometry.hpp"
#include "carom/number_text.hpp"
#include "neighbour_cells.hpp"

namespace carom::science {
namespace {

constexpr const char* kMakeWhere = "science::make_packing_world";
constexpr const char* kCompressWhere = "science::compress";
// Random placement tries a disk this many times before the start counts as too dense.
constexpr int kPlacementTries = 100000;
// A periodic world wants a cell wider than three of its largest disks (hard_disk_gas.hpp).
constexpr double kMinPeriodicSideInDiameters = 3.0;
// compress keeps a world's own growth when it already grows this close to the asked speed (a
// compression resumed from a save), so that the resumed run repeats the original bit for bit.
constexpr double kSameRateTolerance = 1e-9;

void refuse_unless(bool ok, const char* where, const char* field, double value,
                   const char* expected) {
  if (!ok) throw InvalidArgument(where, field, number_text(value), expected);
}

double cell_area(const World& world) {
  const Vec2 side = world.def().upper - world.def().lower;
  return side.x * side.y;
}

// The first and second species' disk counts.
std::uint64_t second_species_count(const PackingSpec& spec) {
  return static_cast<std::uint64_t>(
      std::llround(spec.second_fraction * static_cast<double>(spec.n)));
}

void check_spec(const PackingSpec& spec) {
  if (spec.n < 2 || spec.n > (std::uint64_t{1} << 30U)) {
    throw InvalidArgument(kMakeWhere, "n", std::to_string(spec.n), "must lie in [2, 2^30]");
  }
  refuse_unless(std::isfinite(spec.second_diameter) && spec.second_diameter > 0.0, kMakeWhere,
                "second_diameter", spec.second_diameter, "must be a finite number > 0");
  refuse_unless(spec.second_fraction >= 0.0 && spec.second_fraction <= 1.0, kMakeWhere,
                "second_fraction", spec.second_fraction, "must lie in [0, 1]");
  refuse_unless(spec.boundary == Boundary::periodic || spec.boundary == Boundary::box, kMakeWhere,
                "boundary", static_cast<double>(spec.boundary), "must be periodic or box");
  refuse_unless(std::isfinite(spec.aspect) && spec.aspect > 0.0, kMakeWhere, "aspect", spec.aspect,
                "must be a finite number > 0");
  refuse_unless(spec.start_eta > 0.0 && spec.start_eta <= 0.5, kMakeWhere, "start_eta",
                spec.start_eta, "must lie in (0, 0.5]");
  refuse_unless(spec.sized_for_eta >= spec.start_eta && spec.sized_for_eta < 1.0, kMakeWhere,
                "sized_for_eta", spec.sized_for_eta, "must lie in [start_eta, 1)");
}

}  // namespace

double packing_fraction(const World& world) {
  double covered = 0.0;
  for (const BallId id : world.balls()) {
    const double r = world.radius(id);
    covered += std::numbers::pi * r * r;
  }
  return covered / cell_area(world);
}

World make_packing_world(const PackingSpec& spec) {
  check_spec(spec);
  const std::uint64_t second = second_species_count(spec);
  const std::uint64_t first = spec.n - second;
  // Cell area from the reference diameter 1 at sized_for_eta.
  const double covered_at_unit =
      std::numbers::pi / 4.0 *
      (static_cast<double>(first) +
       static_cast<double>(second) * spec.second_diameter * spec.second_diameter);
  const double area = covered_at_unit / spec.sized_for_eta;
  const double width = std::sqrt(area / spec.aspect);
  const double height = width * spec.aspect;
  const double start_scale = std::sqrt(spec.start_eta / spec.sized_for_eta);
  const double first_radius = 0.5 * start_scale;
  const double second_radius = 0.5 * start_scale * spec.second_diameter;
  const double largest =
      2.0 * std::max(second > 0 ? second_radius : 0.0, first > 0 ? first_radius : 0.0);
  if (spec.boundary == Boundary::periodic) {
    // The world's rule holds for the largest disk when packed, at diameter sized_for_eta's.
    const double packed_largest = largest / start_scale;
    if (std::min(width, height) <= kMinPeriodicSideInDiameters * packed_largest) {
      throw InvalidArgument(kMakeWhere, "n", std::to_string(spec.n),
                            "is too few for a periodic cell: it must be more than " +
                                number_text(kMinPeriodicSideInDiameters) +
                                " of the largest disks wide at the packing fraction it is sized "
                                "for; take more disks or an aspect nearer 1");
    }
  }

  WorldDef def;
  def.boundary = spec.boundary;
  def.lower = {0.0, 0.0};
  def.upper = {width, height};
  World world(def);
  world.reserve(static_cast<std::size_t>(spec.n));

  std::mt19937_64 random(spec.seed);
  const bool periodic = spec.boundary == Boundary::periodic;
  NeighbourCells cells(def.lower, def.upper, largest, periodic, spec.n);
  std::vector<Vec2> positions;
  std::vector<double> radii;
  positions.reserve(static_cast<std::size_t>(spec.n));
  radii.reserve(static_cast<std::size_t>(spec.n));
  // The larger species first: random placement then fails less often.
  const bool second_first = spec.second_diameter > 1.0;
  for (std::uint64_t i = 0; i < spec.n; ++i) {
    const bool is_second = second_first ? i < second : i >= first;
    const double r = is_second ? second_radius : first_radius;
    const double margin = periodic ? 0.0 : r;
    std::uniform_real_distribution<double> along_x(margin, width - margin);
    std::uniform_real_distribution<double> along_y(margin, height - margin);
    int tries = 0;
    while (true) {
      if (++tries > kPlacementTries) {
        throw InvalidArgument(kMakeWhere, "start_eta", number_text(spec.start_eta),
                              "is too dense for random placement: disk " + std::to_string(i) +
                                  " found no free place in " + std::to_string(kPlacementTries) +
                                  " tries");
      }
      Vec2 p{along_x(random), along_y(random)};
      if (periodic) {
        // [0, side) exactly: a draw of `side` itself wraps to 0.
        if (p.x >= width) p.x = 0.0;
        if (p.y >= height) p.y = 0.0;
      }
      bool free = true;
      cells.for_each_near(p, [&](std::uint32_t j, Vec2 offset_to_j) {
        const double reach = r + radii[j];
        // A hair of room, so that the world's own check (with its rounding) never refuses it.
        if (length_squared(offset_to_j) <= reach * reach * (1.0 + 1e-12)) free = false;
      });
      if (!free) continue;
      cells.insert(static_cast<std::uint32_t>(positions.size()), p);
      positions.push_back(p);
      radii.push_back(r);
      break;
    }
  }

  // Maxwell–Boltzmann velocities at kT = 1, zero momentum, K/N = 1 exactly.
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vec2> velocities(static_cast<std::size_t>(spec.n));
  Vec2 mean;
  for (Vec2& v : velocities) {
    v.x = normal(random);
    v.y = normal(random);
    mean += v;
  }
  mean /= static_cast<double>(spec.n);
  double energy = 0.0;
  for (Vec2& v : velocities) {
    v -= mean;
    energy += 0.5 * length_squared(v);
  }
  const double scale = energy > 0.0 ? std::sqrt(static_cast<double>(spec.n) / energy) : 0.0;
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    BallDef ball;
    ball.position = positions[i];
    ball.velocity = velocities[i] * scale;
    ball.radius = radii[i];
    ball.mass = 1.0;
    world.add_ball(ball);
  }
  return world;
}

std::string_view compression_end_name(CompressionEnd end) noexcept {
  switch (end) {
    case CompressionEnd::target:
      return "target";
    case CompressionEnd::pressure:
      return "pressure";
    case CompressionEnd::stalled:
      return "stalled";
    case CompressionEnd::collision_limit:
      return "collision_limit";
    case CompressionEnd::interrupted:
      return "interrupted";
  }
  return "unknown";
}

CompressionResult compress(World& world, const CompressionSettings& settings,
                           const std::function<bool(const CompressionProgress&)>& progress) {
  refuse_unless(std::isfinite(settings.rate) && settings.rate > 0.0, kCompressWhere, "rate",
                settings.rate, "must be a finite number > 0");
  refuse_unless(std::isfinite(settings.kT) && settings.kT > 0.0, kCompressWhere, "kT", settings.kT,
                "must be a finite number > 0");
  refuse_unless(settings.pressure_limit > 1.0, kCompressWhere, "pressure_limit",
                settings.pressure_limit, "must be > 1");
  refuse_unless(
      settings.target_eta == 0.0 || (settings.target_eta > 0.0 && settings.target_eta < 1.0),
      kCompressWhere, "target_eta", settings.target_eta, "must be 0 or lie in (0, 1)");
  const WorldDef& def = world.def();
  if (def.boundary != Boundary::periodic && def.boundary != Boundary::box) {
    throw InvalidArgument(kCompressWhere, "world.boundary", "open",
                          "must be periodic or box: an open world has no packing fraction");
  }
  if (def.gravity != Vec2{}) {
    throw InvalidArgument(kCompressWhere, "world.gravity", "non-zero", "must be zero");
  }
  const std::vector<BallId> ids = world.balls();
  if (ids.size() < 2) {
    throw InvalidArgument(kCompressWhere, "world", std::to_string(ids.size()) + " balls",
                          "must hold at least two");
  }
  double smallest_radius = std::numeric_limits<double>::infinity();
  std::uint32_t slots = 0;
  for (const BallId id : ids) {
    if (world.mass(id) == kImmovable) {
      throw InvalidArgument(kCompressWhere, "world", "an immovable ball",
                            "must hold movable balls only");
    }
    smallest_radius = std::min(smallest_radius, world.radius(id));
    slots = std::max(slots, id.index + 1);
  }
  const double n = static_cast<double>(ids.size());
  const double eta_now = packing_fraction(world);
  if (settings.target_eta != 0.0 && !(settings.target_eta > eta_now)) {
    throw InvalidArgument(
        kCompressWhere, "target_eta", number_text(settings.target_eta),
        "must be above the world's packing fraction now, " + number_text(eta_now));
  }

  // The world's growth rate is relative to its radii: the smallest diameter grows at
  // rate·√(kT/m), m = 1 for every disk make_packing_world makes (the mass of the smallest
  // disk otherwise).
  BallId smallest;
  for (const BallId id : ids) {
    if (world.radius(id) == smallest_radius) {
      smallest = id;
      break;
    }
  }
  const double thermal_speed = std::sqrt(settings.kT / world.mass(smallest));
  const double wanted_rate = settings.rate * thermal_speed / (2.0 * smallest_radius);
  const double current_rate = world.growth_rate_from_now();
  if (!(std::abs(current_rate - wanted_rate) <= kSameRateTolerance * wanted_rate)) {
    world.set_growth_rate(wanted_rate);
  }
  const double rate = world.growth_rate_from_now();
  // η(t) = η_now·(1 + rate·(t − now))².
  const double target_time =
      settings.target_eta == 0.0
          ? std::numeric_limits<double>::infinity()
          : world.time() + (std::sqrt(settings.target_eta / eta_now) - 1.0) / rate;

  const std::uint64_t window =
      settings.window_collisions != 0 ? settings.window_collisions : ids.size();

  // Radii by slot at the start of each window, for σ_ij at a contact's time.
  std::vector<double> window_radius(slots, 0.0);
  double window_start = 0.0;
  double window_rate = 0.0;
  double virial = 0.0;  // Σ σ_ij·J_ij over the window's ball–ball contacts
  world.set_stop_condition([&](const ContactEvent& contact) {
    if (contact.kind == ContactKind::ball_ball) {
      const double grown = 1.0 + window_rate * (contact.time - window_start);
      virial += contact.impulse *
                (window_radius[contact.a.index] + window_radius[contact.b.index]) * grown;
    }
    return false;
  });
  const bool was_recording = world.contact_recording();
  world.set_contact_recording(false);

  CompressionResult result;
  CompressionProgress status;
  while (true) {
    status.eta = packing_fraction(world);
    status.collisions = result.collisions;
    status.time = world.time();
    if (progress && progress(status)) {
      result.end = CompressionEnd::interrupted;
      break;
    }
    if (settings.collision_limit != 0 && result.collisions >= settings.collision_limit) {
      result.end = CompressionEnd::collision_limit;
      break;
    }
    for (const BallId id : ids) window_radius[id.index] = world.radius(id);
    window_start = world.time();
    window_rate = world.growth_rate_from_now();
    virial = 0.0;
    const double energy_before = world.kinetic_energy();
    const std::uint64_t done = std::isfinite(target_time)
                                   ? world.run_collisions(window, target_time)
                                   : world.run_collisions(window);
    result.collisions += done;
    if (world.stop_reason() == StopReason::interrupted) {
      result.end = CompressionEnd::interrupted;
      break;
    }
    const double elapsed = world.time() - window_start;
    const double energy_after = world.kinetic_energy();
    ++result.windows;
    if (elapsed > 0.0) {
      const double kT = 0.5 * (energy_before + energy_after) / n;
      result.pressure = 1.0 + virial / (2.0 * elapsed * n * kT);
      status.pressure = result.pressure;
    }
    result.thermostat_work += world.set_temperature(settings.kT);
    if (world.time() >= target_time) {
      result.end = CompressionEnd::target;
      break;
    }
    if (result.pressure >= settings.pressure_limit) {
      result.end = CompressionEnd::pressure;
      break;
    }
    if (done == window && elapsed <= 0.0) {
      result.end = CompressionEnd::stalled;
      break;
    }
  }
  world.set_stop_condition({});
  world.set_contact_recording(was_recording);
  if (result.end != CompressionEnd::interrupted) world.set_growth_rate(0.0);
  result.jammed = result.end == CompressionEnd::pressure || result.end == CompressionEnd::stalled;
  result.eta = packing_fraction(world);
  result.time = world.time();
  return result;
}

}  // namespace carom::science
