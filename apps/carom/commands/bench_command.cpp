#include "commands/bench_command.hpp"

#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/machine_info.hpp"
#include "carom/science/hard_disk_gas.hpp"
#include "options/exit_codes.hpp"
#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "system/stop_signals.hpp"
#include "system/wall_clock.hpp"

#ifndef CAROM_CLI_BUILD_TYPE
#define CAROM_CLI_BUILD_TYPE ""
#endif
#ifndef CAROM_CLI_COMPILER
#define CAROM_CLI_COMPILER ""
#endif

namespace carom::cli {
namespace {

// A typo with extra zeros should be refused at once, not after allocating tens of gigabytes
// (a ball takes a few hundred bytes); the lattice code is also exact only below 2^31 disks.
constexpr std::uint64_t kMaxBalls = 100'000'000;
// Collision counts are computed as K·N in doubles; beyond 2^53 they would no longer be exact.
constexpr double kMaxCollisions = 9007199254740992.0;
// Timed runs (--repeat): enough for any median, few enough to list.
constexpr std::uint64_t kMaxRepeats = 1000;

// The options as typed; every value is parsed here, as for `carom sweep`.
struct BenchOptions {
  std::string n = "10000";
  std::string eta = "0.3";
  std::string collisions_per_ball = "10";
  std::string equilibrate = "2";
  std::string seed = "1";
  std::string repeat = "1";
  bool json = false;
  bool audit = false;
};

struct BenchSettings {
  science::HardDiskLayout layout;
  std::uint64_t seed = 0;
  std::uint64_t equilibration_collisions = 0;
  std::uint64_t collisions = 0;  // in each timed run
  std::uint64_t repeats = 1;     // timed runs
  bool audit = false;
};

// round(per_ball · n) collisions; per_ball must be a finite number >= minimum.
std::uint64_t parse_collisions(std::string_view option, std::string_view text, std::uint64_t n,
                               bool zero_allowed) {
  const OptionValue value{option, text, zero_allowed ? "a number >= 0" : "a number > 0"};
  const double per_ball = parse_finite_number(text, value);
  if (zero_allowed ? !(per_ball >= 0.0) : !(per_ball > 0.0)) {
    reject(value,
           zero_allowed ? "collisions per ball must be >= 0" : "collisions per ball must be > 0");
  }
  const double total = std::round(per_ball * static_cast<double>(n));
  if (total > kMaxCollisions) {
    reject(value, "that makes " + readable(total) + " collisions, more than 2^53");
  }
  if (!zero_allowed && total < 1.0) {
    reject(value, "that makes " + readable(per_ball * static_cast<double>(n)) + " collisions for " +
                      std::to_string(n) + " disks, which rounds to 0");
  }
  return static_cast<std::uint64_t>(total);
}

BenchSettings parse(const BenchOptions& options) {
  BenchSettings settings;
  const std::uint64_t n = parse_whole_number({"--n", options.n, "a whole number >= 2"});
  if (n < 2) {
    throw UsageError("--n", options.n, "at least 2 disks are needed for a collision");
  }
  if (n > kMaxBalls) {
    throw UsageError("--n", options.n, "at most " + std::to_string(kMaxBalls) + " disks");
  }
  const OptionValue eta_value{"--eta", options.eta, "a number in (0, 0.9069)"};
  const double eta = parse_finite_number(options.eta, eta_value);
  if (!(eta > 0.0 && eta < science::kTriangularPackingLimit)) {
    reject(eta_value,
           "the packing fraction must lie above 0 and below that of the densest packing of "
           "equal disks, pi/(2*sqrt(3)) = 0.9069");
  }
  settings.layout = science::hard_disk_layout(n, eta);
  const science::HardDiskLayout& layout = settings.layout;
  if (!layout.box_wide_enough()) {
    throw UsageError("--n", options.n,
                     "at packing fraction " + readable(eta) + " the periodic box is only " +
                         readable(layout.side) +
                         " wide, and it must be more than 3 disk diameters wide: raise --n or "
                         "lower --eta");
  }
  if (!layout.disks_fit()) {
    throw UsageError("--eta", options.eta,
                     "the best triangular lattice for " + std::to_string(n) +
                         " disks in this box has sites only " + readable(layout.nearest) +
                         " apart, less than a diameter (1): this --n can start at packing "
                         "fraction " +
                         readable(layout.densest_eta) + " at most");
  }
  settings.collisions =
      parse_collisions("--collisions-per-ball", options.collisions_per_ball, n, false);
  settings.equilibration_collisions =
      parse_collisions("--equilibrate", options.equilibrate, n, true);
  settings.seed = parse_whole_number({"--seed", options.seed, "a whole number >= 0"});
  settings.audit = options.audit;
  const OptionValue repeat_value{"--repeat", options.repeat, "a whole number from 1 to 1000"};
  settings.repeats = parse_whole_number(repeat_value);
  if (settings.repeats < 1 || settings.repeats > kMaxRepeats) {
    reject(repeat_value, "at least 1 and at most " + std::to_string(kMaxRepeats) + " timed runs");
  }
  const double total =
      static_cast<double>(settings.collisions) * static_cast<double>(settings.repeats);
  if (total > kMaxCollisions) {
    reject(repeat_value, "that makes " + readable(total) + " collisions, more than 2^53");
  }
  return settings;
}

// The process's peak resident set so far, in bytes (Linux reports ru_maxrss in KiB).
std::uint64_t peak_resident_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  constexpr std::uint64_t kBytesPerKiB = 1024;
  return static_cast<std::uint64_t>(usage.ru_maxrss) * kBytesPerKiB;
}

// Runs the gas of `settings` in this process: its figures, exactly as `carom bench` reports them.
BenchOutcome measure(const BenchSettings& settings) {
  BenchOutcome outcome;
  outcome.n = settings.layout.n;
  outcome.eta = settings.layout.eta;
  outcome.seed = settings.seed;
  outcome.box_side = settings.layout.side;
  outcome.lattice_columns = settings.layout.columns;
  outcome.lattice_rows = settings.layout.rows;
  outcome.build_type = CAROM_CLI_BUILD_TYPE;
  outcome.compiler = CAROM_CLI_COMPILER;
  outcome.machine = describe_machine();

  const std::uint64_t peak_before = peak_resident_bytes();
  auto start = std::chrono::steady_clock::now();
  World world = science::make_hard_disk_world(settings.layout, settings.seed);
  outcome.setup_seconds = seconds_since(start);
  // Nothing reads the contacts here, and recording them would grow the process by 80 bytes per
  // collision, so bytes_per_ball would measure the contact list rather than the world.
  world.set_contact_recording(false);
  stop_world_on_signals(world);

  // The first run also builds the final grid and predicts every ball once; equilibration keeps
  // that one-off cost out of the timed run.
  start = std::chrono::steady_clock::now();
  outcome.equilibration_collisions = world.run_collisions(settings.equilibration_collisions);
  outcome.equilibration_seconds = seconds_since(start);
  if (world.stop_reason() == StopReason::interrupted) {
    outcome.interrupted = true;
    return outcome;
  }
  const std::uint64_t peak_after = peak_resident_bytes();
  outcome.peak_rss_growth_bytes = peak_after > peak_before ? peak_after - peak_before : 0;

  const double energy_before = world.kinetic_energy();
  const Vec2 momentum_before = world.momentum();
  for (std::uint64_t k = 0; k < settings.repeats; ++k) {
    start = std::chrono::steady_clock::now();
    const std::uint64_t resolved = world.run_collisions(settings.collisions);
    const double seconds = seconds_since(start);
    outcome.collisions += resolved;
    outcome.wall_seconds += seconds;
    outcome.repetitions.push_back(seconds);
    outcome.interrupted = world.stop_reason() == StopReason::interrupted;
    if (resolved != settings.collisions) break;  // (reported below)
  }
  const double energy_after = world.kinetic_energy();
  const Vec2 momentum_after = world.momentum();

  outcome.energy_drift = (energy_after - energy_before) / energy_before;
  const double total_mass = static_cast<double>(outcome.n) * science::kDiskMass;
  outcome.momentum_drift =
      length(momentum_after - momentum_before) / std::sqrt(2.0 * total_mass * energy_before);
  if (settings.audit) {
    start = std::chrono::steady_clock::now();
    outcome.audit = world.audit().value_or("");
    outcome.audit_seconds = seconds_since(start);
  }
  return outcome;
}

int run(const BenchOptions& options) {
  // A signal stops the gas; the figures of what ran are reported.
  const StopOnSignals stop_on_signals;
  const BenchSettings settings = parse(options);
  const BenchOutcome outcome = measure(settings);
  if (outcome.interrupted && outcome.collisions == 0) {
    std::cerr << "carom bench: " << StopOnSignals::what() << " before a timed collision\n";
    return StopOnSignals::exit_code();
  }
  if (!outcome.interrupted && outcome.collisions != settings.collisions * settings.repeats) {
    std::cerr << "carom bench: error: the world resolved " << outcome.collisions << " of the "
              << settings.collisions * settings.repeats << " collisions asked for\n";
    return kExitFailure;
  }
  if (options.json) {
    std::cout << bench_json(outcome).dump() << '\n';
  } else {
    std::cout << bench_text(outcome);
  }
  if (outcome.interrupted) {
    std::cerr << "carom bench: " << StopOnSignals::what() << " after " << outcome.collisions
              << " timed collisions; the figures cover those\n";
    return StopOnSignals::exit_code();
  }
  if (outcome.audit && !outcome.audit->empty()) {
    std::cerr << "carom bench: error: the audit after the timed runs found: " << *outcome.audit
              << '\n';
    return kExitFailure;
  }
  return kExitSuccess;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  CLI::App* bench = app.add_subcommand(
      "bench", "Collisions per second of the world on a gas of equal hard disks");
  bench->footer(
      "N disks of diameter 1 and mass 1, elastic, in a periodic square box whose side\n"
      "gives the packing fraction ETA = N*pi/(4*side^2). They start on the triangular\n"
      "lattice with the most room that fits the box, with velocity components drawn\n"
      "from a normal distribution (sd 1, std::mt19937_64 seeded with S) and the total\n"
      "momentum removed. The world first resolves K0*N collisions, not timed (this also\n"
      "absorbs building the grid and the first prediction of every ball), then K*N\n"
      "collisions timed with std::chrono::steady_clock; with --repeat R, R such timed\n"
      "runs one after another on the same gas, each one's time reported with their\n"
      "median and the least (a host shared with other work slows some runs), and the\n"
      "totals over all R. The machine (processor, cache sizes) is reported too.\n\n"
      "bytes_per_ball: the growth of the process's peak resident set size (getrusage,\n"
      "ru_maxrss) from before the world is created to after equilibration, divided by\n"
      "N; it includes the transient copies of growing arrays, and it is meaningful only\n"
      "for large N (say 10^4 and up; small worlds fit in memory the process already has).\n"
      "Contact recording is off (World::set_contact_recording(false)): the figure is the\n"
      "world's state, not a list of contacts that nothing reads.\n"
      "energy_drift: (E_after - E_before) / E_before over the timed run. momentum_drift:\n"
      "|P_after - P_before| / sqrt(2*M*E_before), M the total mass.\n"
      "audit (--audit): World::audit() after the timed runs, not timed with them: no two\n"
      "disks overlapping, every disk in the grid cell the engine filed it in; \"clean\",\n"
      "or the first violation (and exit status 1).\n\n"
      "Examples:\n"
      "  carom bench --n 10000 --eta 0.3 --collisions-per-ball 10\n"
      "  carom bench --n 100000 --eta 0.6 --collisions-per-ball 5 --seed 7 --json\n"
      "  carom bench --n 1000000 --collisions-per-ball 2 --repeat 5\n"
      "  carom bench --n 10000000 --collisions-per-ball 10 --audit --json\n\n"
      "The world's speed and memory goals are judged with this verb by the benchmark\n"
      "program carom_bench_goals (docs/performance.md).");

  auto options = std::make_shared<BenchOptions>();
  bench->add_option("--n", options->n, "Number of disks, at least 2")
      ->type_name("N")
      ->capture_default_str();
  bench->add_option("--eta", options->eta, "Packing fraction, in (0, 0.9069)")
      ->type_name("ETA")
      ->capture_default_str();
  bench
      ->add_option("--collisions-per-ball", options->collisions_per_ball,
                   "Timed collisions per disk (K*N in all, rounded), > 0")
      ->type_name("K")
      ->capture_default_str();
  bench
      ->add_option("--equilibrate", options->equilibrate,
                   "Untimed collisions per disk before the timed run, >= 0")
      ->type_name("K0")
      ->capture_default_str();
  bench->add_option("--seed", options->seed, "Seed of the velocities' generator")
      ->type_name("S")
      ->capture_default_str();
  bench
      ->add_option("--repeat", options->repeat,
                   "Timed runs of K*N collisions each, one after another, >= 1")
      ->type_name("R")
      ->capture_default_str();
  bench->add_flag("--json", options->json, "Print one JSON object, numbers exact, not text");
  bench->add_flag("--audit", options->audit,
                  "Audit the world after the timed runs (no overlap, every ball in its cell); "
                  "exit 1 if it finds anything");

  return {bench, [options] { return run(*options); }};
}

}  // namespace carom::cli
