// carom_world_gas_probe: the hard-disk gas of `carom bench` (carom/science/hard_disk_gas.hpp),
// timed by CPU time as well as wall time, with the tool's other figures (setup time, bytes per
// ball). It needs the library alone, so it builds where the tool's dependencies (CLI11, fmt,
// nlohmann-json) are missing, and its CPU-time rate stays meaningful on a loaded machine.
//   carom_world_gas_probe N ETA COLLISIONS_PER_BALL [RECORD_CONTACTS=1] [EQUILIBRATE_PER_BALL=2]
//                         [SHUFFLED=0]
// SHUFFLED=1 adds the same disks in a random order (as a scene file may list them), so that
// neighbours are far apart in memory until the engine re-orders its slots.
// Figures: docs/performance.md; how to use it: tools/perf/README.md.
#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "carom/science/hard_disk_gas.hpp"
#include "gas_run_support.hpp"

namespace {

long peak_resident_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// The same balls (positions, velocities, sizes, masses) added to a fresh world in a random order.
carom::World added_in_random_order(const carom::World& source, double side) {
  const std::vector<carom::BallId> ids = source.balls();
  carom::WorldDef def;
  def.boundary = carom::Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {side, side};
  carom::World world(def);
  for (const std::size_t k : carom::bench::shuffled_order(ids.size())) {
    const carom::BallId id = ids[k];
    carom::BallDef ball;
    ball.position = source.position(id);
    ball.velocity = source.velocity(id);
    ball.radius = source.radius(id);
    ball.mass = source.mass(id);
    world.add_ball(ball);
  }
  return world;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr,
                 "usage: %s N ETA COLLISIONS_PER_BALL [RECORD_CONTACTS=1] "
                 "[EQUILIBRATE_PER_BALL=2] [SHUFFLED=0]\n",
                 argv[0]);
    return 2;
  }
  const std::uint64_t n = std::strtoull(argv[1], nullptr, 10);
  const double eta = std::atof(argv[2]);
  const double per_ball = std::atof(argv[3]);
  const bool record = argc <= 4 || std::atoi(argv[4]) != 0;
  const double equilibrate = argc > 5 ? std::atof(argv[5]) : 2.0;
  const bool shuffled = argc > 6 && std::atoi(argv[6]) != 0;
  const carom::science::HardDiskLayout layout = carom::science::hard_disk_layout(n, eta);
  if (n == 0 || !layout.box_wide_enough() || !layout.disks_fit()) {
    std::fprintf(stderr, "the triangular lattice cannot hold %llu disks at packing %g\n",
                 static_cast<unsigned long long>(n), eta);
    return 2;
  }
  const long resident_before = peak_resident_kib();
  const auto start = std::chrono::steady_clock::now();
  carom::World world = carom::science::make_hard_disk_world(layout, 1);
  if (shuffled) world = added_in_random_order(world, layout.side);
  world.set_contact_recording(record);
  const auto set_up = std::chrono::steady_clock::now();
  world.run_collisions(static_cast<std::uint64_t>(equilibrate * static_cast<double>(n)));
  const long resident_after = peak_resident_kib();
  const double energy_before = world.kinetic_energy();
  const auto wanted = static_cast<std::uint64_t>(per_ball * static_cast<double>(n));
  const auto timed_start = std::chrono::steady_clock::now();
  const double cpu_start = carom::bench::cpu_seconds();
  const std::uint64_t collisions = world.run_collisions(wanted);
  const double cpu = carom::bench::cpu_seconds() - cpu_start;
  const double wall = seconds_between(timed_start, std::chrono::steady_clock::now());
  const auto count = static_cast<double>(collisions);
  std::printf(
      "n=%llu eta=%.2f record=%d setup_s=%.3f equilibrate_s=%.3f collisions=%llu wall_s=%.3f "
      "wall_rate=%.0fk/s cpu_rate=%.0fk/s cpu_ns_per_collision=%.0f bytes_per_ball=%.0f "
      "energy_drift=%.2e\n",
      static_cast<unsigned long long>(n), eta, record ? 1 : 0, seconds_between(start, set_up),
      seconds_between(set_up, timed_start), static_cast<unsigned long long>(collisions), wall,
      count / wall / 1e3, count / cpu / 1e3, cpu / count * 1e9,
      static_cast<double>(resident_after - resident_before) * 1024.0 / static_cast<double>(n),
      (world.kinetic_energy() - energy_before) / energy_before);
  return collisions == wanted ? 0 : 1;
}
