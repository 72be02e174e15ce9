#include "bench/bench_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "options/readable_number.hpp"

namespace carom::cli {

namespace {

// A byte count as people write cache sizes: in MiB or KiB where it divides evenly.
std::string cache_text(std::uint64_t bytes) {
  if (bytes == 0) return "unknown";
  constexpr std::uint64_t kKiB = 1024;
  if (bytes % (kKiB * kKiB) == 0) return fmt::format("{} MiB", bytes / (kKiB * kKiB));
  if (bytes % kKiB == 0) return fmt::format("{} KiB", bytes / kKiB);
  return fmt::format("{} B", bytes);
}

// The middle value (the mean of the middle two for an even count); NaN for none.
double median_of(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2.0;
}

// The report's last two lines: the build its figures come from, and the machine.
std::string build_and_machine_text(const std::string& build_type, const std::string& compiler,
                                   const MachineInfo& machine) {
  std::string out = fmt::format("  build: {}, {}\n",
                                build_type.empty() ? "(no build type)" : build_type, compiler);
  out += fmt::format("  machine: {}, {} logical CPUs; caches L1d {}, L2 {}, L3 {}\n", machine.cpu,
                     machine.logical_cpus, cache_text(machine.l1d_cache_bytes),
                     cache_text(machine.l2_cache_bytes), cache_text(machine.l3_cache_bytes));
  return out;
}

}  // namespace

std::vector<double> BenchOutcome::repetition_nanoseconds_per_collision() const {
  std::vector<double> out;
  if (repetitions.empty()) return out;
  const double each = static_cast<double>(collisions) / static_cast<double>(repetitions.size());
  out.reserve(repetitions.size());
  for (const double seconds : repetitions) out.push_back(seconds * 1e9 / each);
  return out;
}

double BenchOutcome::median_nanoseconds_per_collision() const {
  const std::vector<double> each = repetition_nanoseconds_per_collision();
  if (each.empty()) return nanoseconds_per_collision();
  return median_of(each);
}

double BenchOutcome::best_nanoseconds_per_collision() const {
  const std::vector<double> each = repetition_nanoseconds_per_collision();
  if (each.empty()) return nanoseconds_per_collision();
  return *std::min_element(each.begin(), each.end());
}

std::string bench_text(const BenchOutcome& o) {
  std::string out;
  out += fmt::format("{} equal disks (diameter 1), packing fraction {}, periodic box {} x {}\n",
                     o.n, readable(o.eta), readable(o.box_side), readable(o.box_side));
  out += fmt::format("  start: triangular lattice of {} x {} sites, velocities from seed {}\n",
                     o.lattice_columns, o.lattice_rows, o.seed);
  out += fmt::format("  setup {} s, equilibration {} collisions in {} s (neither timed)\n",
                     rounded(o.setup_seconds), o.equilibration_collisions,
                     rounded(o.equilibration_seconds));
  out +=
      fmt::format("  timed: {} collisions in {} s = {} collisions/s ({} ns per collision)\n",
                  o.collisions, rounded(o.wall_seconds), readable_count(o.collisions_per_second()),
                  rounded(o.nanoseconds_per_collision()));
  if (o.repetitions.size() > 1) {
    std::string each;
    for (const double ns : o.repetition_nanoseconds_per_collision()) {
      each += (each.empty() ? "" : ", ") + rounded(ns);
    }
    out += fmt::format("  {} timed runs, ns per collision: {} (median {}, least {})\n",
                       o.repetitions.size(), each, rounded(o.median_nanoseconds_per_collision()),
                       rounded(o.best_nanoseconds_per_collision()));
  }
  out +=
      fmt::format("  memory: {} bytes per ball (peak resident set growth, contact recording off)\n",
                  rounded(o.bytes_per_ball()));
  out += fmt::format("  drift over the timed run{}: energy {}, momentum {} (relative)\n",
                     o.repetitions.size() > 1 ? "s" : "", rounded(o.energy_drift),
                     rounded(o.momentum_drift));
  if (o.audit) {
    out += o.audit->empty() ? fmt::format("  audit after the timed runs: clean ({} s)\n",
                                          rounded(o.audit_seconds))
                            : fmt::format("  audit after the timed runs: {}\n", *o.audit);
  }
  out += build_and_machine_text(o.build_type, o.compiler, o.machine);
  return out;
}

nlohmann::ordered_json bench_json(const BenchOutcome& o) {
  nlohmann::ordered_json out;
  out["n"] = o.n;
  out["eta"] = o.eta;
  out["seed"] = o.seed;
  out["box_side"] = o.box_side;
  out["lattice_columns"] = o.lattice_columns;
  out["lattice_rows"] = o.lattice_rows;
  out["setup_seconds"] = o.setup_seconds;
  out["equilibration_collisions"] = o.equilibration_collisions;
  out["equilibration_seconds"] = o.equilibration_seconds;
  out["collisions"] = o.collisions;
  out["wall_seconds"] = o.wall_seconds;
  out["collisions_per_second"] = o.collisions_per_second();
  out["nanoseconds_per_collision"] = o.nanoseconds_per_collision();
  out["repetitions"] = o.repetitions.size();
  out["repetition_nanoseconds_per_collision"] = o.repetition_nanoseconds_per_collision();
  out["median_nanoseconds_per_collision"] = o.median_nanoseconds_per_collision();
  out["best_nanoseconds_per_collision"] = o.best_nanoseconds_per_collision();
  out["bytes_per_ball"] = o.bytes_per_ball();
  out["peak_rss_growth_bytes"] = o.peak_rss_growth_bytes;
  out["stopped"] = o.interrupted ? nlohmann::ordered_json("interrupted") : nlohmann::ordered_json();
  out["energy_drift"] = o.energy_drift;
  out["momentum_drift"] = o.momentum_drift;
  // null when not asked for, "clean", or the first violation World::audit() found.
  out["audit"] = !o.audit           ? nlohmann::ordered_json()
                 : o.audit->empty() ? nlohmann::ordered_json("clean")
                                    : nlohmann::ordered_json(*o.audit);
  out["audit_seconds"] = o.audit_seconds;
  out["build_type"] = o.build_type;
  out["compiler"] = o.compiler;
  out["machine"] = {{"cpu", o.machine.cpu},
                    {"logical_cpus", o.machine.logical_cpus},
                    {"l1d_cache_bytes", o.machine.l1d_cache_bytes},
                    {"l2_cache_bytes", o.machine.l2_cache_bytes},
                    {"l3_cache_bytes", o.machine.l3_cache_bytes}};
  return out;
}

}  // namespace carom::cli
