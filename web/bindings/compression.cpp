#include "compression.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "carom/error.hpp"
#include "carom/science/packing.hpp"

namespace carom::web {
namespace {

constexpr const char* kWhere = "compress_frame";
// A growth this close to the asked speed is kept rather than restarted, as science::compress
// keeps it, so that the frames of one compression make one growth law.
constexpr double kSameRateTolerance = 1e-9;

[[noreturn]] void reject(const std::string& field, double value, const std::string& expected) {
  throw InvalidArgument(kWhere, field, std::to_string(value), expected);
}

// The world's relative growth rate that makes the smallest diameter grow at `rate` thermal
// speeds, as science::compress converts it.
double relative_growth_rate(const World& world, const std::vector<BallId>& ids, double rate,
                            double kT) {
  BallId smallest = ids.front();
  for (const BallId id : ids) {
    if (world.radius(id) < world.radius(smallest)) smallest = id;
  }
  return rate * std::sqrt(kT / world.mass(smallest)) / (2.0 * world.radius(smallest));
}

}  // namespace

DrawnWorld make_packing(const PackingStart& start) {
  if (start.count < 2) {
    throw InvalidArgument("make_packing", "count", std::to_string(start.count), "must be >= 2");
  }
  science::PackingSpec spec;
  spec.n = static_cast<std::uint64_t>(start.count);
  spec.second_diameter = start.second_diameter;
  spec.second_fraction = start.second_fraction;
  spec.boundary = start.boundary;
  spec.aspect = start.aspect;
  spec.start_eta = start.start_eta;
  spec.sized_for_eta = start.sized_for_eta;
  spec.seed = start.seed;
  return DrawnWorld(science::make_packing_world(spec));
}

CompressionFrameResult compress_frame(DrawnWorld& drawn, const CompressionFrame& frame) {
  if (!(std::isfinite(frame.rate) && frame.rate >= 0.0)) {
    reject("rate", frame.rate, "must be a finite number >= 0");
  }
  if (!(std::isfinite(frame.kT) && frame.kT > 0.0)) {
    reject("kT", frame.kT, "must be a finite number > 0");
  }
  if (!std::isfinite(frame.until)) reject("until", frame.until, "must be finite");
  if (frame.collisions < 1) reject("collisions", frame.collisions, "must be >= 1");
  if (!(std::isfinite(frame.pressure_limit) && frame.pressure_limit >= 0.0)) {
    reject("pressure_limit", frame.pressure_limit, "must be a finite number >= 0");
  }
  World& world = drawn.world();
  const std::vector<BallId> ids = world.balls();
  if (ids.size() < 2) {
    throw InvalidArgument(kWhere, "world", std::to_string(ids.size()) + " balls",
                          "must hold at least two");
  }
  const double wanted =
      frame.rate == 0.0 ? 0.0 : relative_growth_rate(world, ids, frame.rate, frame.kT);
  if (!(std::abs(world.growth_rate_from_now() - wanted) <= kSameRateTolerance * wanted)) {
    world.set_growth_rate(wanted);
  }

  std::uint32_t slots = 0;
  for (const BallId id : ids) slots = std::max(slots, id.index + 1);
  // Radii by slot at the start of each window, for σ_ij at a contact's time (the radii grow
  // within a window), as science::compress measures it.
  std::vector<double> window_radius(slots, 0.0);
  double window_start = 0.0;
  double window_rate = 0.0;
  double virial = 0.0;
  world.set_stop_condition([&](const ContactEvent& contact) {
    if (contact.kind == ContactKind::ball_ball) {
      const double grown = 1.0 + window_rate * (contact.time - window_start);
      virial += contact.impulse *
                (window_radius[contact.a.index] + window_radius[contact.b.index]) * grown;
    }
    return false;
  });
  // The contacts are summed above; a frame near jamming resolves too many to keep.
  const bool was_recording = world.contact_recording();
  world.set_contact_recording(false);

  const double n = static_cast<double>(ids.size());
  const std::uint64_t window = ids.size();
  const std::uint64_t budget = static_cast<std::uint64_t>(frame.collisions);
  const double end = frame.until;
  const double start = world.time();
  CompressionFrameResult result;
  std::uint64_t done_in_frame = 0;
  while (done_in_frame < budget && world.time() < end) {
    for (const BallId id : ids) window_radius[id.index] = world.radius(id);
    window_start = world.time();
    window_rate = world.growth_rate_from_now();
    virial = 0.0;
    const double energy_before = world.kinetic_energy();
    const std::uint64_t done = world.run_collisions(window, end);
    done_in_frame += done;
    const double elapsed = world.time() - window_start;
    const double energy_after = world.kinetic_energy();
    if (elapsed > 0.0) {
      const double window_virial = virial / (0.5 * (energy_before + energy_after) / n);
      result.virial += window_virial;
      result.window_pressure = 1.0 + window_virial / (2.0 * elapsed * n);
    }
    result.work += world.set_temperature(frame.kT);
    if (frame.pressure_limit > 0.0 && elapsed > 0.0 &&
        result.window_pressure >= frame.pressure_limit) {
      result.over_pressure_limit = true;
      break;
    }
    if (done == window && !(elapsed > 0.0)) {
      result.stalled = true;
      break;
    }
    if (world.stop_reason() == StopReason::no_more_contacts) {
      // Nothing will meet again (growth off, disks at rest): the frame's time passes freely.
      static_cast<void>(world.run_until(end));
      break;
    }
  }
  world.set_stop_condition({});
  world.set_contact_recording(was_recording);
  result.collisions = static_cast<double>(done_in_frame);
  result.time = world.time() - start;
  if (result.time > 0.0) result.pressure = 1.0 + result.virial / (2.0 * result.time * n);
  return result;
}

}  // namespace carom::web
