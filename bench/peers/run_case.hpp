// carom peers benchmark: one engine on one scene, timed and checked step by step, in this
// process. The report (report.hpp) runs each case in a process of its own, so that the peak
// memory of one engine is not mixed with another's.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace carom::peers {

inline constexpr double kStepsPerSecond = 60.0;
inline constexpr std::uint32_t kDefaultSteps = 600;
inline constexpr std::uint64_t kDefaultSeed = 1;

struct CaseSpec {
  std::string engine = "carom";
  std::string scene = "gas";  // gas or bullets
  std::uint32_t n = 1000;     // disks in the gas (the bullets scene has its own counts)
  double packing = 0.2;       // the gas's packing fraction
  std::uint32_t steps = kDefaultSteps;
  std::uint64_t seed = kDefaultSeed;
  // Run the checks after every step (untimed). Off: only the clock runs between steps, which
  // shows how much the checks' sweeps through memory slow the next step (caches evicted).
  bool checks = true;
};

struct CaseResult {
  CaseSpec spec;
  std::uint32_t balls = 0;
  double setup_seconds = 0.0;  // building the engine's world from the scene
  double median_step_ms = 0.0;
  double worst_step_ms = 0.0;
  double mean_step_ms = 0.0;
  // The same steps on this thread's CPU clock: time the thread was not running (the machine busy
  // with other work) does not count. On a quiet machine it matches the wall clock.
  double median_step_cpu_ms = 0.0;
  // Resident memory, KiB (Linux's VmHWM): the process's peak at the end, and its peak before the
  // engine was built (the scene, the harness's buffers and its checks already run once).
  std::int64_t peak_kib = 0;
  std::int64_t harness_kib = 0;
  double energy_drift = 0.0;          // (E_end − E_start) / E_start
  double largest_overlap = 0.0;       // over every step's end, fraction of the sum of radii
  std::uint64_t pass_throughs = 0;    // pair-steps: a pair that went through each other in a step
  double deepest_pass_through = 0.0;  // PassThrough::depth, the largest
  std::uint32_t bullets_through = 0;  // bullets that went through at least one disk
  std::uint32_t left_box = 0;         // disks whose centre was outside the box at a step's end
  std::uint32_t non_finite = 0;       // disks with a NaN or infinite coordinate at the end
  std::int64_t contacts = -1;         // resolved contacts, where the engine counts them
};

// Throws std::invalid_argument for an unknown engine or scene.
[[nodiscard]] CaseResult run_case(const CaseSpec& spec);

// One line of `key=value` fields, and back; parse returns nothing for a malformed line.
[[nodiscard]] std::string to_line(const CaseResult& result);
[[nodiscard]] std::optional<CaseResult> parse_line(std::string_view line);

}  // namespace carom::peers
