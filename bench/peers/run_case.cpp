#include "run_case.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "detectors.hpp"
#include "engine.hpp"
#include "scene.hpp"

namespace carom::peers {
namespace {

using Clock = std::chrono::steady_clock;

// This thread's CPU time, seconds.
double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

// The process's peak resident memory so far (VmHWM), KiB; 0 where /proc is not there.
std::int64_t peak_resident_kib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stoll(line.substr(6));
  }
  return 0;
}

Scene make_scene(const CaseSpec& spec) {
  Scene scene;
  if (spec.scene == "gas") {
    scene = make_gas_scene(spec.n, spec.packing, spec.seed);
  } else if (spec.scene == "bullets") {
    scene = make_bullets_scene(spec.seed, kStepsPerSecond);
  } else if (spec.scene == "gravity") {
    scene = make_gravity_scene(spec.n, spec.seed);
  } else {
    throw std::invalid_argument("unknown scene '" + spec.scene + "' (gas, bullets or gravity)");
  }
  scene.sleeping = spec.sleeping;
  return scene;
}

// The phase a step ending at `time` belongs to.
Phase phase_at(const Scene& scene, double time) {
  if (time <= scene.impact_start) return kFalling;
  if (time <= scene.rest_start) return kImpact;
  return kRest;
}

double mean(const std::vector<double>& values) {
  double total = 0.0;
  for (const double v : values) total += v;
  return values.empty() ? 0.0 : total / static_cast<double>(values.size());
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

CaseResult run_case(const CaseSpec& spec) {
  CaseResult result;
  result.spec = spec;
  const Scene scene = make_scene(spec);
  const std::size_t n = scene.balls.size();
  result.balls = static_cast<std::uint32_t>(n);
  std::vector<double> radii(n);
  std::vector<double> masses(n);
  std::vector<Vec2> before(n);
  std::vector<Vec2> after(n);
  std::vector<Vec2> velocities(n);
  std::vector<char> left(n, 0);
  std::vector<char> bullet_through(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    radii[i] = scene.balls[i].radius;
    masses[i] = scene.balls[i].mass;
    before[i] = scene.balls[i].position;
    velocities[i] = scene.balls[i].velocity;
  }
  std::vector<double> step_seconds;
  std::vector<double> step_cpu_seconds;
  step_seconds.reserve(spec.steps);
  step_cpu_seconds.reserve(spec.steps);
  Detectors detectors;
  // Run the checks once on the scene, so that their buffers count in the harness's share of the
  // memory rather than in the engine's.
  result.largest_overlap = detectors.largest_overlap(before, radii, scene.lower, scene.upper);
  std::vector<PathBreak> breaks;
  static_cast<void>(
      detectors.find_pass_throughs(before, before, radii, breaks, scene.lower, scene.upper));
  result.harness_kib = peak_resident_kib();

  const Clock::time_point setup_start = Clock::now();
  std::unique_ptr<Engine> engine = make_engine(spec.engine, scene);
  result.setup_seconds = std::chrono::duration<double>(Clock::now() - setup_start).count();
  // The start as the engine holds it (Box2D has rounded it to single precision).
  engine->read(before, velocities);
  // Potential energy counts from a disk resting on the floor, the lowest it can go.
  double floor_radius = 0.0;
  for (const double r : radii) floor_radius = std::max(floor_radius, r);
  const Vec2 floor{0.0, scene.lower.y + floor_radius};
  const auto energy = [&](std::span<const Vec2> positions) {
    return kinetic_energy(velocities, masses) +
           potential_energy(positions, masses, scene.gravity, floor);
  };
  const double energy_start = energy(before);
  double energy_lowest = energy_start;
  double total_mass = 0.0;
  for (const double m : masses) total_mass += m;
  const auto rms_speed = [&] {
    return std::sqrt(2.0 * kinetic_energy(velocities, masses) / total_mass);
  };
  // Under gravity the path between two bends is a parabola; the pass-through check follows its
  // chord, which sags from it by up to |g|·dt²/8 over a step, so two disks' chords may come
  // |g|·dt²/4 closer than their paths did. Passes shallower than that, as a fraction of the sum of
  // radii, are not counted (for every engine alike).
  const double dt = 1.0 / kStepsPerSecond;
  const double sag = length(scene.gravity) * dt * dt / 4.0;
  double smallest_radius_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0 || 2.0 * radii[i] < smallest_radius_sum) smallest_radius_sum = 2.0 * radii[i];
  }
  const double min_depth = smallest_radius_sum > 0.0 ? sag / smallest_radius_sum : 0.0;
  const bool phased = scene.impact_start > 0.0;
  std::vector<double> phase_seconds[kPhaseCount];
  std::vector<double> phase_cpu_seconds[kPhaseCount];
  std::int64_t contacts_before = engine->contact_count();
  std::int64_t phase_contacts[kPhaseCount] = {0, 0, 0};

  for (std::uint32_t step = 0; step < spec.steps; ++step) {
    const double cpu_start = thread_cpu_seconds();
    const Clock::time_point start = Clock::now();
    engine->step(dt);
    step_seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    step_cpu_seconds.push_back(thread_cpu_seconds() - cpu_start);
    if (phased) {
      const Phase phase = phase_at(scene, (step + 1) * dt);
      phase_seconds[phase].push_back(step_seconds.back());
      phase_cpu_seconds[phase].push_back(step_cpu_seconds.back());
      const std::int64_t contacts = engine->contact_count();
      phase_contacts[phase] += contacts - contacts_before;
      contacts_before = contacts;
    }
    if (!spec.checks) continue;

    engine->read(after, velocities);
    breaks.clear();
    engine->path_breaks(dt, breaks);
    result.largest_overlap = std::max(
        result.largest_overlap, detectors.largest_overlap(after, radii, scene.lower, scene.upper));
    result.largest_wall_overlap = std::max(
        result.largest_wall_overlap, largest_wall_overlap(after, radii, scene.lower, scene.upper));
    const double energy_now = energy(after);
    result.energy_rise = std::max(result.energy_rise, (energy_now - energy_lowest) / energy_start);
    energy_lowest = std::min(energy_lowest, energy_now);
    if (rms_speed() >= kSettledRmsSpeed) {
      result.settled_time = -1.0;
    } else if (result.settled_time < 0.0) {
      result.settled_time = (step + 1) * dt;
    }
    for (const PassThrough& pair : detectors.find_pass_throughs(
             before, after, radii, breaks, scene.lower, scene.upper, min_depth)) {
      ++result.pass_throughs;
      result.deepest_pass_through = std::max(result.deepest_pass_through, pair.depth);
      if (scene.balls[pair.a].bullet != scene.balls[pair.b].bullet) {
        bullet_through[scene.balls[pair.a].bullet ? pair.a : pair.b] = 1;
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (outside_box(after[i], scene.lower, scene.upper)) left[i] = 1;
    }
    std::swap(before, after);
  }

  result.peak_kib = peak_resident_kib();
  if (!spec.checks) engine->read(before, velocities);
  result.energy_drift = (energy(before) - energy_start) / energy_start;
  result.end_rms_speed = rms_speed();
  for (int phase = 0; phase < kPhaseCount; ++phase) {
    PhaseResult& out = result.phases[phase];
    out.steps = static_cast<std::uint32_t>(phase_seconds[phase].size());
    out.median_step_ms = median(phase_seconds[phase]) * 1e3;
    out.median_step_cpu_ms = median(phase_cpu_seconds[phase]) * 1e3;
    out.mean_step_ms = mean(phase_seconds[phase]) * 1e3;
    out.mean_step_cpu_ms = mean(phase_cpu_seconds[phase]) * 1e3;
    out.contacts = contacts_before >= 0 ? phase_contacts[phase] : -1;
  }
  result.bullets_through =
      static_cast<std::uint32_t>(std::count(bullet_through.begin(), bullet_through.end(), 1));
  result.left_box = static_cast<std::uint32_t>(std::count(left.begin(), left.end(), 1));
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = before[i];  // the last step's end, after the swap
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(velocities[i].x) ||
        !std::isfinite(velocities[i].y)) {
      ++result.non_finite;
    }
  }
  result.contacts = engine->contact_count();
  double total = 0.0;
  for (const double s : step_seconds) {
    result.worst_step_ms = std::max(result.worst_step_ms, s * 1e3);
    total += s;
  }
  result.mean_step_ms =
      step_seconds.empty() ? 0.0 : total / static_cast<double>(step_seconds.size()) * 1e3;
  result.median_step_ms = median(step_seconds) * 1e3;
  result.median_step_cpu_ms = median(step_cpu_seconds) * 1e3;
  return result;
}

std::string to_line(const CaseResult& r) {
  std::ostringstream line;
  line.precision(17);
  line << "engine=" << r.spec.engine << " scene=" << r.spec.scene << " n=" << r.spec.n
       << " packing=" << r.spec.packing << " steps=" << r.spec.steps << " seed=" << r.spec.seed
       << " checks=" << (r.spec.checks ? 1 : 0) << " balls=" << r.balls
       << " setup_s=" << r.setup_seconds << " median_ms=" << r.median_step_ms
       << " worst_ms=" << r.worst_step_ms << " mean_ms=" << r.mean_step_ms
       << " median_cpu_ms=" << r.median_step_cpu_ms << " peak_kib=" << r.peak_kib
       << " harness_kib=" << r.harness_kib << " energy_drift=" << r.energy_drift
       << " overlap=" << r.largest_overlap << " pass_throughs=" << r.pass_throughs
       << " deepest=" << r.deepest_pass_through << " bullets_through=" << r.bullets_through
       << " left_box=" << r.left_box << " non_finite=" << r.non_finite << " contacts=" << r.contacts
       << " sleeping=" << (r.spec.sleeping ? 1 : 0) << " energy_rise=" << r.energy_rise
       << " end_rms_speed=" << r.end_rms_speed << " settled_time=" << r.settled_time
       << " wall_overlap=" << r.largest_wall_overlap;
  for (int phase = 0; phase < kPhaseCount; ++phase) {
    const PhaseResult& p = r.phases[phase];
    line << " phase" << phase << "=" << p.steps << "," << p.median_step_ms << "," << p.mean_step_ms
         << "," << p.median_step_cpu_ms << "," << p.mean_step_cpu_ms << "," << p.contacts;
  }
  return line.str();
}

std::optional<CaseResult> parse_line(std::string_view line) {
  std::map<std::string, std::string, std::less<>> fields;
  std::istringstream words{std::string(line)};
  std::string word;
  while (words >> word) {
    const std::size_t equals = word.find('=');
    if (equals == std::string::npos) return std::nullopt;
    fields[word.substr(0, equals)] = word.substr(equals + 1);
  }
  try {
    CaseResult r;
    r.spec.engine = fields.at("engine");
    r.spec.scene = fields.at("scene");
    r.spec.n = static_cast<std::uint32_t>(std::stoul(fields.at("n")));
    r.spec.packing = std::stod(fields.at("packing"));
    r.spec.steps = static_cast<std::uint32_t>(std::stoul(fields.at("steps")));
    r.spec.seed = std::stoull(fields.at("seed"));
    r.spec.checks = fields.at("checks") == "1";
    r.balls = static_cast<std::uint32_t>(std::stoul(fields.at("balls")));
    r.setup_seconds = std::stod(fields.at("setup_s"));
    r.median_step_ms = std::stod(fields.at("median_ms"));
    r.worst_step_ms = std::stod(fields.at("worst_ms"));
    r.mean_step_ms = std::stod(fields.at("mean_ms"));
    r.median_step_cpu_ms = std::stod(fields.at("median_cpu_ms"));
    r.peak_kib = std::stoll(fields.at("peak_kib"));
    r.harness_kib = std::stoll(fields.at("harness_kib"));
    r.energy_drift = std::stod(fields.at("energy_drift"));
    r.largest_overlap = std::stod(fields.at("overlap"));
    r.pass_throughs = std::stoull(fields.at("pass_throughs"));
    r.deepest_pass_through = std::stod(fields.at("deepest"));
    r.bullets_through = static_cast<std::uint32_t>(std::stoul(fields.at("bullets_through")));
    r.left_box = static_cast<std::uint32_t>(std::stoul(fields.at("left_box")));
    r.non_finite = static_cast<std::uint32_t>(std::stoul(fields.at("non_finite")));
    r.contacts = std::stoll(fields.at("contacts"));
    r.spec.sleeping = fields.at("sleeping") == "1";
    r.energy_rise = std::stod(fields.at("energy_rise"));
    r.end_rms_speed = std::stod(fields.at("end_rms_speed"));
    r.settled_time = std::stod(fields.at("settled_time"));
    r.largest_wall_overlap = std::stod(fields.at("wall_overlap"));
    for (int phase = 0; phase < kPhaseCount; ++phase) {
      std::istringstream parts(fields.at("phase" + std::to_string(phase)));
      PhaseResult& p = r.phases[phase];
      char commas[5] = {};
      parts >> p.steps >> commas[0] >> p.median_step_ms >> commas[1] >> p.mean_step_ms >>
          commas[2] >> p.median_step_cpu_ms >> commas[3] >> p.mean_step_cpu_ms >> commas[4] >>
          p.contacts;
      if (!parts || std::string_view(commas, 5) != ",,,,,") return std::nullopt;
    }
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace carom::peers
