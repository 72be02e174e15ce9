// The C++ side of bench/python/module_bench.py: the same work as the Python module's calls, done
// from C++, so that the script can say what going through Python costs.
//
//   carom_step_from_cpp make N ETA SEED EQUILIBRATE OUT
//       The hard-disk gas of `carom bench` (science::make_hard_disk_world), run EQUILIBRATE
//       collisions a disk and then N more, whose duration gives the time of one collision a disk;
//       saved to OUT, which both sides then load, so that they start from the same bits.
//   carom_step_from_cpp step|until WORLD DT CALLS REPEATS [OUT]
//       REPEATS times loads WORLD and times CALLS calls of step(DT), or of run_until(t0 + k·DT);
//       saves the last world to OUT, so that the script can check that Python ended in the same
//       state.
//   carom_step_from_cpp add N COLLISIONS READS
//       Times adding N balls on a square lattice (as the script builds them for add_balls) and
//       reading every position back into an array READS times, as world.positions does; then
//       READS times a run of COLLISIONS contacts followed by a read.
//
// Each prints one JSON object on stdout. Only the loop is timed, not loading or saving.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "carom/science/hard_disk_gas.hpp"
#include "carom/world.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::uint64_t count_of(const char* text) { return std::strtoull(text, nullptr, 10); }
double number_of(const char* text) { return std::strtod(text, nullptr); }

int make(std::uint64_t n, double eta, std::uint64_t seed, std::uint64_t equilibrate,
         const std::filesystem::path& out) {
  const carom::science::HardDiskLayout layout = carom::science::hard_disk_layout(n, eta);
  if (!layout.box_wide_enough() || !layout.disks_fit()) {
    std::fprintf(stderr, "no room for %llu disks at eta %g\n", static_cast<unsigned long long>(n),
                 eta);
    return 2;
  }
  carom::World world = carom::science::make_hard_disk_world(layout, seed);
  world.run_collisions(equilibrate * n);
  const double t0 = world.time();
  world.run_collisions(n);
  const double time_per_collision_per_disk = world.time() - t0;
  world.save(out);
  std::printf(
      "{\"n\": %llu, \"eta\": %.17g, \"side\": %.17g, \"time\": %.17g, \"collisions\": %llu, "
      "\"time_per_collision_per_disk\": %.17g}\n",
      static_cast<unsigned long long>(n), eta, layout.side, world.time(),
      static_cast<unsigned long long>(world.collision_count()), time_per_collision_per_disk);
  return 0;
}

void print_list(const char* name, const std::vector<double>& values) {
  std::printf("\"%s\": [", name);
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::printf("%s%.9g", i == 0 ? "" : ", ", values[i]);
  }
  std::printf("]");
}

// Loads the world `repeats` times and times the loop on each; the last one is saved.
int advance(bool until, const std::filesystem::path& in, double dt, std::uint64_t calls,
            std::uint64_t repeats, const char* out) {
  std::vector<double> seconds;
  std::uint64_t collisions = 0;
  double end_time = 0.0;
  for (std::uint64_t r = 0; r < repeats; ++r) {
    carom::World world = carom::World::load(in);
    const double t0 = world.time();
    const std::uint64_t c0 = world.collision_count();
    const Clock::time_point start = Clock::now();
    if (until) {
      for (std::uint64_t k = 1; k <= calls; ++k) {
        world.run_until(t0 + static_cast<double>(k) * dt);
      }
    } else {
      for (std::uint64_t k = 0; k < calls; ++k) world.step(dt);
    }
    seconds.push_back(seconds_since(start));
    collisions = world.collision_count() - c0;
    end_time = world.time();
    if (r + 1 == repeats && out != nullptr) world.save(std::filesystem::path(out));
  }
  std::printf("{");
  print_list("seconds", seconds);
  std::printf(", \"collisions\": %llu, \"time\": %.17g}\n",
              static_cast<unsigned long long>(collisions), end_time);
  return 0;
}

// The lattice of module_bench.py's add_balls case: balls of radius 0.5 at spacing 1.5 in a
// periodic square, velocities (cos i, sin i).
std::vector<carom::BallDef> lattice_balls(std::uint64_t n, double spacing, std::uint64_t side) {
  std::vector<carom::BallDef> defs(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    defs[i].position = {(static_cast<double>(i % side) + 0.5) * spacing,
                        (static_cast<double>(i / side) + 0.5) * spacing};
    defs[i].velocity = {std::cos(static_cast<double>(i)), std::sin(static_cast<double>(i))};
    defs[i].radius = 0.5;
  }
  return defs;
}

// Every position in handle order into a new array, as world.positions fills a new NumPy array
// (uninitialised, as NumPy's is); returns the seconds taken and adds the values to `sum`.
double read_positions(const carom::World& world, double& sum) {
  const Clock::time_point start = Clock::now();
  const std::vector<carom::BallId> ids = world.balls();
  const std::unique_ptr<double[]> positions(new double[2 * ids.size()]);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const carom::Vec2 p = world.position(ids[i]);
    positions[2 * i] = p.x;
    positions[2 * i + 1] = p.y;
  }
  const double seconds = seconds_since(start);
  // Keeps the reads from being optimised away.
  for (std::size_t i = 0; i < 2 * ids.size(); ++i) sum += positions[i];
  return seconds;
}

// Adds n balls and reads their positions `reads` times; then `reads` times runs `collisions`
// contacts and reads them (after a run the balls sit at different times of their own, and
// reading a position moves it to the world's time).
int add(std::uint64_t n, std::uint64_t collisions, std::uint64_t reads) {
  const auto side = static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  constexpr double kSpacing = 1.5;
  carom::WorldDef def;
  def.boundary = carom::Boundary::periodic;
  def.upper = {static_cast<double>(side) * kSpacing, static_cast<double>(side) * kSpacing};
  // Built outside the timed part, as the script builds its arrays before add_balls.
  const std::vector<carom::BallDef> defs = lattice_balls(n, kSpacing, side);
  carom::World world(def);
  const Clock::time_point start = Clock::now();
  world.reserve(n);
  for (const carom::BallDef& d : defs) static_cast<void>(world.add_ball(d));
  const double add_seconds = seconds_since(start);

  double sum = 0.0;
  std::vector<double> fresh;
  std::vector<double> after_run;
  for (std::uint64_t k = 0; k < reads; ++k) fresh.push_back(read_positions(world, sum));
  for (std::uint64_t k = 0; k < reads; ++k) {
    world.run_collisions(collisions);
    after_run.push_back(read_positions(world, sum));
  }
  std::printf("{\"n\": %llu, \"add_seconds\": %.9g, ", static_cast<unsigned long long>(n),
              add_seconds);
  print_list("read_seconds", fresh);
  std::printf(", ");
  print_list("read_seconds_after_run", after_run);
  std::printf(", \"checksum\": %.17g}\n", sum);
  return 0;
}

int usage() {
  std::fprintf(stderr,
               "usage: carom_step_from_cpp make N ETA SEED EQUILIBRATE OUT\n"
               "       carom_step_from_cpp step|until WORLD DT CALLS REPEATS [OUT]\n"
               "       carom_step_from_cpp add N COLLISIONS READS\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "make" && argc == 7) {
      return make(count_of(argv[2]), number_of(argv[3]), count_of(argv[4]), count_of(argv[5]),
                  argv[6]);
    }
    if ((mode == "step" || mode == "until") && (argc == 6 || argc == 7)) {
      return advance(mode == "until", argv[2], number_of(argv[3]), count_of(argv[4]),
                     count_of(argv[5]), argc == 7 ? argv[6] : nullptr);
    }
    if (mode == "add" && argc == 5) {
      return add(count_of(argv[2]), count_of(argv[3]), count_of(argv[4]));
    }
    return usage();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "carom_step_from_cpp: %s\n", error.what());
    return 1;
  }
}
