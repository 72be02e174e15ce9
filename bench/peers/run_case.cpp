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
  if (spec.scene == "gas") return make_gas_scene(spec.n, spec.packing, spec.seed);
  if (spec.scene == "bullets") return make_bullets_scene(spec.seed, kStepsPerSecond);
  throw std::invalid_argument("unknown scene '" + spec.scene + "' (gas or bullets)");
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
  const double energy_start = kinetic_energy(velocities, masses);

  const double dt = 1.0 / kStepsPerSecond;
  for (std::uint32_t step = 0; step < spec.steps; ++step) {
    const double cpu_start = thread_cpu_seconds();
    const Clock::time_point start = Clock::now();
    engine->step(dt);
    step_seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    step_cpu_seconds.push_back(thread_cpu_seconds() - cpu_start);
    if (!spec.checks) continue;

    engine->read(after, velocities);
    breaks.clear();
    engine->path_breaks(dt, breaks);
    result.largest_overlap = std::max(
        result.largest_overlap, detectors.largest_overlap(after, radii, scene.lower, scene.upper));
    for (const PassThrough& pair :
         detectors.find_pass_throughs(before, after, radii, breaks, scene.lower, scene.upper)) {
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
  result.energy_drift = (kinetic_energy(velocities, masses) - energy_start) / energy_start;
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
       << " left_box=" << r.left_box << " non_finite=" << r.non_finite
       << " contacts=" << r.contacts;
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
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace carom::peers
