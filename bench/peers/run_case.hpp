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
// A heap counts as settled once its root-mean-square speed stays below this, length units per
// second: Box2D's sleep tolerance (b2_linearSleepTolerance), about a ten-thousandth of the speed
// the highest disks land at.
inline constexpr double kSettledRmsSpeed = 0.01;

struct CaseSpec {
  std::string engine = "carom";
  std::string scene = "gas";  // gas, bullets or gravity
  std::uint32_t n = 1000;     // disks in the gas or the gravity scene (the bullets have their own)
  double packing = 0.2;       // the gas's packing fraction
  std::uint32_t steps = kDefaultSteps;
  std::uint64_t seed = kDefaultSeed;
  // Run the checks after every step (untimed). Off: only the clock runs between steps, which
  // shows how much the checks' sweeps through memory slow the next step (caches evicted).
  bool checks = true;
  // Let a time-stepped engine put still bodies to sleep (Scene::sleeping).
  bool sleeping = false;
};

// Steps of 1/60 s, the time each took, and the contacts the engine resolved in them, over one
// phase of a scene that has phases (Scene::impact_start).
struct PhaseResult {
  std::uint32_t steps = 0;
  double median_step_ms = 0.0;
  double mean_step_ms = 0.0;  // what the phase cost in all, per step: a few heavy steps show here
  double median_step_cpu_ms = 0.0;
  double mean_step_cpu_ms = 0.0;
  std::int64_t contacts = -1;  // where the engine counts them
};

// The phases of the gravity scene, in order.
enum Phase : std::uint8_t { kFalling, kImpact, kRest, kPhaseCount };

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
  // (E_end − E_start) / E_start, E the kinetic energy plus gravity's potential energy measured from
  // a disk resting on the floor (so that E is what there is to lose; without gravity it is the
  // kinetic energy alone).
  double energy_drift = 0.0;
  // The largest rise of E above its lowest value so far, over every step's end, over E_start: 0
  // for an engine whose energy never rises.
  double energy_rise = 0.0;
  double end_rms_speed = 0.0;  // √(2·kinetic energy / total mass) at the last step's end
  // The time from which the root-mean-square speed stayed below kSettledRmsSpeed to the end; -1
  // when it was above at the end.
  double settled_time = -1.0;
  double largest_wall_overlap = 0.0;  // over every step's end, fraction of the radius
  PhaseResult phases[kPhaseCount];    // for a scene with phases
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
