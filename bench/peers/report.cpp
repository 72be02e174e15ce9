#include "report.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine.hpp"
#include "run_case.hpp"
#include "scene.hpp"

extern char** environ;  // NOLINT: POSIX declares it nowhere else

namespace carom::peers {
namespace {

constexpr std::uint32_t kGasSizes[] = {1'000, 10'000, 100'000};
constexpr std::uint32_t kQuickGasSizes[] = {1'000, 10'000};
constexpr double kPackings[] = {0.2, 0.5};
// A peer at N = 10⁵ runs this many steps rather than 600: there Chipmunk took 0.2 to 0.4 s a step
// and Box2D 0.4 to 1.8 s (wall clock, on a busy 2-core machine), and the whole report should stay
// within several minutes. The table shows the steps.
constexpr std::uint32_t kLargestGas = 100'000;
constexpr std::uint32_t kPeerStepsAtLargestGas = 100;
constexpr std::uint32_t kQuickSteps = 120;
constexpr std::uint32_t kSmokeGasSizes[] = {200};
constexpr std::uint32_t kSmokeSteps = 10;
// The bullets cross the box (about 63 wide) one and a half times a step: ten steps are enough
// for each to meet the field many times.
constexpr std::uint32_t kBulletSteps = 10;
// The gravity scene's size: the largest whose run stays within a few minutes. carom resolves
// every contact of the heap as it forms, and their number grows much faster than N: at 10³
// its worst step holds about 2.6·10⁵ contacts and its whole run takes about 30 s of CPU; at
// 2·10³ single steps held up to 3.7·10⁶; at 10⁴ the first 15 steps of the impact averaged 1.6 s
// of CPU and 5·10⁵ contacts, and grew. The peers run it twice, with sleeping off and on.
constexpr std::uint32_t kGravitySize = 1'000;
constexpr std::uint32_t kQuickGravitySize = 300;
constexpr std::uint32_t kSmokeGravitySize = 200;
// The comparison's goal: carom at least this many times faster per step than the fastest peer, at
// N = 10⁴ and 10⁵.
constexpr double kGoalSpeedUp = 5.0;
constexpr std::uint32_t kGoalSmallestN = 10'000;

struct Outcome {
  CaseSpec spec;
  std::optional<CaseResult> result;
  std::string failure;  // why there is no result
  double wall_seconds = 0.0;
};

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// Runs `self run ...` for one case and reads its one line of results.
Outcome run_in_child(const std::string& self, const CaseSpec& spec) {
  Outcome outcome;
  outcome.spec = spec;
  std::vector<std::string> args = {self,        "run",
                                   "--engine",  spec.engine,
                                   "--scene",   spec.scene,
                                   "--n",       std::to_string(spec.n),
                                   "--packing", format("%.17g", spec.packing),
                                   "--steps",   std::to_string(spec.steps),
                                   "--seed",    std::to_string(spec.seed)};
  if (spec.sleeping) args.emplace_back("--sleeping");
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);

  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) throw std::runtime_error("pipe failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[1]);
  const auto start = std::chrono::steady_clock::now();
  pid_t child = 0;
  const int spawned = posix_spawn(&child, self.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  if (spawned != 0) {
    close(pipe_ends[0]);
    outcome.failure = "could not start " + self;
    return outcome;
  }
  std::string output;
  char buffer[4096];
  for (ssize_t got = 0; (got = read(pipe_ends[0], buffer, sizeof buffer)) > 0;) {
    output.append(buffer, static_cast<std::size_t>(got));
  }
  close(pipe_ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  outcome.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFSIGNALED(status)) {
    outcome.failure = "killed by signal " + std::to_string(WTERMSIG(status));
  } else if (WEXITSTATUS(status) != 0) {
    outcome.failure = "exit status " + std::to_string(WEXITSTATUS(status));
  } else {
    // The result is the line that starts with "engine="; a peer may print a banner of its own
    // (Debian's Chipmunk announces its debug build on standard output).
    const std::size_t line_start = output.rfind("engine=");
    if (line_start != std::string::npos) {
      const std::size_t line_end = output.find('\n', line_start);
      outcome.result = parse_line(std::string_view(output).substr(
          line_start, line_end == std::string::npos ? std::string::npos : line_end - line_start));
    }
    if (!outcome.result) outcome.failure = "unreadable result: " + output;
  }
  return outcome;
}

std::string read_first(const char* path, const std::string& key) {
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    if (line.rfind(key, 0) == 0) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  }
  return "unknown";
}

std::string load_average() {
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  file >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

std::string engine_label(const std::vector<EngineInfo>& engines, const std::string& name) {
  for (const EngineInfo& e : engines) {
    if (e.name == name) return e.version;
  }
  return name;
}

std::string mib(std::int64_t kib) { return format("%.1f", static_cast<double>(kib) / 1024.0); }

std::string count_or_failure(const Outcome& o, std::uint64_t value) {
  return o.result ? std::to_string(value) : "—";
}

void gas_table(std::ostream& out, const std::vector<Outcome>& outcomes,
               const std::vector<EngineInfo>& engines) {
  out << "| N | packing | engine | steps | median ms/step | worst ms/step | median CPU ms/step | "
         "contacts/step | peak MiB (engine's share) | energy drift | largest overlap | missed "
         "(deepest) | "
         "left box |\n"
      << "|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Outcome& o : outcomes) {
    if (o.spec.scene != "gas") continue;
    out << "| " << o.spec.n << " | " << format("%.1f", o.spec.packing) << " | "
        << engine_label(engines, o.spec.engine) << " | " << o.spec.steps << " | ";
    if (!o.result) {
      out << "failed: " << o.failure << " | | | | | | | | |\n";
      continue;
    }
    const CaseResult& r = *o.result;
    out << format("%.3f", r.median_step_ms) << " | " << format("%.3f", r.worst_step_ms) << " | "
        << format("%.3f", r.median_step_cpu_ms) << " | "
        << (r.contacts >= 0 ? format("%.0f", static_cast<double>(r.contacts) / r.spec.steps)
                            : std::string("—"))
        << " | " << mib(r.peak_kib) << " (" << mib(r.peak_kib - r.harness_kib) << ") | "
        << format("%.2e", r.energy_drift) << " | " << format("%.2e", r.largest_overlap) << " | "
        << r.pass_throughs
        << (r.pass_throughs > 0 ? " (" + format("%.1e", r.deepest_pass_through) + ")" : "") << " | "
        << r.left_box << (r.non_finite ? " (non-finite)" : "") << " |\n";
  }
}

void bullets_table(std::ostream& out, const std::vector<Outcome>& outcomes,
                   const std::vector<EngineInfo>& engines) {
  out << "| engine | steps | bullets through a disk (of " << kBulletCount
      << ") | pass-throughs (pair-steps) | left box | energy drift | largest overlap | median "
         "ms/step | median CPU ms/step | contacts/step |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Outcome& o : outcomes) {
    if (o.spec.scene != "bullets") continue;
    out << "| " << engine_label(engines, o.spec.engine) << " | " << o.spec.steps << " | ";
    if (!o.result) {
      out << "failed: " << o.failure << " | | | | | | | |\n";
      continue;
    }
    const CaseResult& r = *o.result;
    out << count_or_failure(o, r.bullets_through) << " | " << r.pass_throughs << " | " << r.left_box
        << " | " << format("%.2e", r.energy_drift) << " | " << format("%.2e", r.largest_overlap)
        << " | " << format("%.3f", r.median_step_ms) << " | "
        << format("%.3f", r.median_step_cpu_ms) << " | "
        << (r.contacts >= 0 ? format("%.0f", static_cast<double>(r.contacts) / r.spec.steps)
                            : std::string("—"))
        << " |\n";
  }
}

std::string sleeping_label(const CaseSpec& spec) {
  if (spec.engine == "carom") return "— (resting contact)";
  return spec.sleeping ? "on" : "off";
}

const char* const kPhaseNames[kPhaseCount] = {"falling", "impact", "rest"};

void gravity_time_table(std::ostream& out, const std::vector<Outcome>& outcomes,
                        const std::vector<EngineInfo>& engines) {
  out << "| engine | sleeping | phase | steps | median ms/step | mean ms/step | median CPU ms/step "
         "| mean CPU ms/step | contacts/step |\n"
      << "|---|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const Outcome& o : outcomes) {
    if (o.spec.scene != "gravity") continue;
    const std::string lead =
        "| " + engine_label(engines, o.spec.engine) + " | " + sleeping_label(o.spec) + " | ";
    if (!o.result) {
      out << lead << "failed: " << o.failure << " | | | | | | |\n";
      continue;
    }
    for (int phase = 0; phase < kPhaseCount; ++phase) {
      const PhaseResult& p = o.result->phases[phase];
      out << lead << kPhaseNames[phase] << " | " << p.steps << " | ";
      if (p.steps == 0) {
        out << "— | — | — | — | — |\n";
        continue;
      }
      out << format("%.3f", p.median_step_ms) << " | " << format("%.3f", p.mean_step_ms) << " | "
          << format("%.3f", p.median_step_cpu_ms) << " | " << format("%.3f", p.mean_step_cpu_ms)
          << " | "
          << (p.contacts >= 0 ? format("%.0f", static_cast<double>(p.contacts) / p.steps)
                              : std::string("—"))
          << " |\n";
    }
  }
}

void gravity_check_table(std::ostream& out, const std::vector<Outcome>& outcomes,
                         const std::vector<EngineInfo>& engines) {
  out << "| engine | sleeping | steps | CPU s, all steps | settled at (s) | rms speed at the end | "
         "energy change | largest energy rise | largest overlap | into a wall | missed (deepest) "
         "| left box | peak MiB (engine's share) |\n"
      << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Outcome& o : outcomes) {
    if (o.spec.scene != "gravity") continue;
    out << "| " << engine_label(engines, o.spec.engine) << " | " << sleeping_label(o.spec) << " | "
        << o.spec.steps << " | ";
    if (!o.result) {
      out << "failed: " << o.failure << " | | | | | | | | | |\n";
      continue;
    }
    const CaseResult& r = *o.result;
    double cpu_seconds = 0.0;
    for (const PhaseResult& p : r.phases) cpu_seconds += p.mean_step_cpu_ms * p.steps / 1e3;
    out << format("%.1f", cpu_seconds) << " | "
        << (r.settled_time >= 0.0 ? format("%.2f", r.settled_time) : std::string("not settled"))
        << " | " << format("%.1e", r.end_rms_speed) << " | " << format("%.3f", r.energy_drift)
        << " | " << format("%.2e", r.energy_rise) << " | " << format("%.2e", r.largest_overlap)
        << " | " << format("%.2e", r.largest_wall_overlap) << " | " << r.pass_throughs
        << (r.pass_throughs > 0 ? " (" + format("%.1e", r.deepest_pass_through) + ")" : "") << " | "
        << r.left_box << (r.non_finite ? " (non-finite)" : "") << " | " << mib(r.peak_kib) << " ("
        << mib(r.peak_kib - r.harness_kib) << ") |\n";
  }
}

void goal_table(std::ostream& out, const std::vector<Outcome>& outcomes,
                const std::vector<EngineInfo>& engines) {
  out << "| N | packing | carom median ms/step (CPU) | fastest peer | its median ms/step (CPU) | "
         "speed-up, wall clock | speed-up, CPU clock | goal (≥ "
      << format("%.0f", kGoalSpeedUp) << "×, CPU clock) |\n"
      << "|---:|---:|---:|---|---:|---:|---:|---|\n";
  for (const Outcome& mine : outcomes) {
    if (mine.spec.scene != "gas" || mine.spec.engine != "carom" || !mine.result) continue;
    if (mine.spec.n < kGoalSmallestN) continue;
    const Outcome* fastest = nullptr;
    for (const Outcome& o : outcomes) {
      if (o.spec.scene != "gas" || o.spec.engine == "carom" || !o.result) continue;
      if (o.spec.n != mine.spec.n || o.spec.packing != mine.spec.packing) continue;
      if (!fastest || o.result->median_step_cpu_ms < fastest->result->median_step_cpu_ms) {
        fastest = &o;
      }
    }
    const CaseResult& m = *mine.result;
    out << "| " << mine.spec.n << " | " << format("%.1f", mine.spec.packing) << " | "
        << format("%.3f", m.median_step_ms) << " (" << format("%.3f", m.median_step_cpu_ms)
        << ") | ";
    if (!fastest) {
      out << "no peer measured | | | | |\n";
      continue;
    }
    const CaseResult& f = *fastest->result;
    const double wall = f.median_step_ms / m.median_step_ms;
    const double cpu = f.median_step_cpu_ms / m.median_step_cpu_ms;
    out << engine_label(engines, fastest->spec.engine) << " | " << format("%.3f", f.median_step_ms)
        << " (" << format("%.3f", f.median_step_cpu_ms) << ") | " << format("%.1f×", wall) << " | "
        << format("%.1f×", cpu) << " | " << (cpu >= kGoalSpeedUp ? "met" : "**not met**") << " |\n";
  }
}

// The gravity scene for every engine, the peers with sleeping off and on, each for the scene's
// whole length (all three phases) but in the smoke test.
std::vector<CaseSpec> gravity_cases(const ReportOptions& options,
                                    const std::vector<std::string>& engines) {
  CaseSpec base;
  base.scene = "gravity";
  base.n = options.quick ? kQuickGravitySize : kGravitySize;
  if (options.smoke) base.n = kSmokeGravitySize;
  base.steps = static_cast<std::uint32_t>(
      std::ceil(make_gravity_scene(base.n, base.seed).end_time * kStepsPerSecond));
  if (options.smoke) base.steps = kSmokeSteps;
  std::vector<CaseSpec> specs;
  for (const std::string& engine : engines) {
    for (const bool sleeping : {false, true}) {
      if (sleeping && engine == "carom") continue;  // carom has no sleeping: its balls rest
      CaseSpec spec = base;
      spec.engine = engine;
      spec.sleeping = sleeping;
      specs.push_back(spec);
    }
  }
  return specs;
}

std::vector<CaseSpec> cases(const ReportOptions& options, const std::vector<EngineInfo>& all) {
  std::vector<std::string> engines = options.engines;
  if (engines.empty()) {
    for (const EngineInfo& e : all) engines.push_back(e.name);
  }
  std::vector<CaseSpec> specs;
  std::vector<std::uint32_t> sizes(std::begin(kGasSizes), std::end(kGasSizes));
  std::uint32_t steps = kDefaultSteps;
  std::uint32_t bullet_steps = kBulletSteps;
  if (options.quick) {
    sizes.assign(std::begin(kQuickGasSizes), std::end(kQuickGasSizes));
    steps = kQuickSteps;
  }
  if (options.smoke) {
    sizes.assign(std::begin(kSmokeGasSizes), std::end(kSmokeGasSizes));
    steps = kSmokeSteps;
    bullet_steps = 2;
  }
  for (const std::uint32_t n : sizes) {
    for (const double packing : kPackings) {
      for (const std::string& engine : engines) {
        CaseSpec spec;
        spec.engine = engine;
        spec.scene = "gas";
        spec.n = n;
        spec.packing = packing;
        spec.steps = steps;
        if (n >= kLargestGas && engine != "carom")
          spec.steps = std::min(steps, kPeerStepsAtLargestGas);
        specs.push_back(spec);
      }
    }
  }
  for (const std::string& engine : engines) {
    CaseSpec spec;
    spec.engine = engine;
    spec.scene = "bullets";
    spec.steps = bullet_steps;
    specs.push_back(spec);
  }
  for (const CaseSpec& spec : gravity_cases(options, engines)) specs.push_back(spec);
  return specs;
}

void gravity_section(std::ostream& out, const ReportOptions& options,
                     const std::vector<Outcome>& outcomes, const std::vector<EngineInfo>& engines) {
  const std::vector<CaseSpec> specs = gravity_cases(options, {"carom"});
  const Scene scene = make_gravity_scene(specs.front().n, specs.front().seed);
  const double dt = 1.0 / kStepsPerSecond;
  out << "\n## Gravity: disks poured into a box\n\n"
      << specs.front().n << " disks of radius " << format("%.1f", kGasRadius) << " and mass "
      << format("%.0f", kGasMass)
      << " on a square lattice, 1.5 diameters apart, filling the upper "
         "two thirds of a tall box ("
      << format("%.0f", scene.upper.x - scene.lower.x) << " wide, "
      << format("%.0f", scene.upper.y - scene.lower.y)
      << " high) with velocity components normal with standard deviation "
      << format("%.1f", kPourVelocitySd) << " (seed " << specs.front().seed << "); gravity "
      << format("%.2f", kGravity) << " down, restitution " << format("%.1f", kPourRestitution)
      << " for every contact (ball on ball and ball on wall), no friction, no damping; steps of "
         "1/60 s, "
      << specs.front().steps
      << " of them. The phases, by time and the same for every engine: *falling* until the "
         "lowest disk, falling freely, would touch the floor ("
      << format("%.2f", scene.impact_start)
      << " s); *impact* until the highest would reach the top of the heap (its height from the "
         "disks at packing "
      << format("%.2f", kPourHeapPacking) << " across the box) plus "
      << format("%.0f", kPourSettleSeconds) << " s (" << format("%.2f", scene.rest_start)
      << " s); *rest* after that, to " << format("%.2f", scene.end_time)
      << " s. Set to match: carom gets the gravity, the restitution and its default rest height "
         "(a thousandth of a radius); Box2D restitution 0.5, friction 0 and, as its restitution "
         "threshold, carom's: carom ends a bounce off a still floor in contact when it would lift "
         "the disk less than the rest height, that is below an approach speed of √(2·g·h)/e, "
         "about 0.2; Chipmunk elasticity √0.5 on every shape (it multiplies two shapes') and "
         "friction 0, and it has no threshold (every contact bounces). Without friction neither "
         "peer turns a disk. The peers run twice: sleeping off, and on (Box2D's default; Chipmunk "
         "after half a second idle, as Box2D); carom's balls rest instead, at no cost. Time per "
         "step as in the gas, with the mean beside the median, since the impact's cost lies in a "
         "few heavy steps. Contacts/step: carom's contacts in the phase over its steps. Settled "
         "at: the time from which the root-mean-square speed stayed below "
      << format("%.2f", kSettledRmsSpeed)
      << " (Box2D's sleep tolerance) to the end. Energy: kinetic plus gravity's potential, "
         "counted from a disk resting on the floor (so it is what there is to lose); energy "
         "change: (E_end − E_start)/E_start; largest energy rise: the largest rise of E above its "
         "lowest value so far, at any step's end, over E_start. Largest overlap as in the gas; "
         "into a wall: the deepest a disk reached into a wall, as a fraction of its radius. "
         "Missed: as in the gas, but passes shallower than |g|·dt²/4 ("
      << format("%.1e", length(scene.gravity) * dt * dt / 4.0 / (2.0 * kGasRadius))
      << " of the sum of radii) do not count: under gravity a path between two bends is a "
         "parabola, the check follows its chord, and two chords can come that much closer than "
         "the paths did.\n\n";
  gravity_time_table(out, outcomes, engines);
  out << "\n";
  gravity_check_table(out, outcomes, engines);
}

// The hand-written part of the report: what the figures mean. Kept in a Markdown file beside the
// sources so that it can be edited without rebuilding.
std::string notes() {
  std::ifstream file(CAROM_PEERS_NOTES_FILE);
  if (!file) return std::string("(missing: ") + CAROM_PEERS_NOTES_FILE + ")\n";
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

int write_report(const ReportOptions& options, const std::string& self) {
  const std::vector<EngineInfo> engines = available_engines();
  const std::vector<CaseSpec> specs = cases(options, engines);
  const std::string load_before = load_average();
  const auto start = std::chrono::steady_clock::now();
  std::vector<Outcome> outcomes;
  bool all_ran = true;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const CaseSpec& spec = specs[i];
    std::cerr << "[" << i + 1 << "/" << specs.size() << "] " << spec.engine << " " << spec.scene;
    if (spec.scene == "gas") std::cerr << " n=" << spec.n << " packing=" << spec.packing;
    if (spec.scene == "gravity") std::cerr << " n=" << spec.n << (spec.sleeping ? " sleeping" : "");
    std::cerr << " steps=" << spec.steps << " ... " << std::flush;
    outcomes.push_back(run_in_child(self, spec));
    const Outcome& o = outcomes.back();
    if (o.result) {
      std::cerr << format("%.1f s", o.wall_seconds) << ", median "
                << format("%.3f ms/step", o.result->median_step_ms) << "\n";
    } else {
      std::cerr << "FAILED: " << o.failure << "\n";
      all_ran = false;
    }
  }
  const double total_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::ofstream file;
  if (!options.out.empty()) {
    file.open(options.out);
    if (!file) {
      std::cerr << "carom_peers: cannot write " << options.out << "\n";
      return 2;
    }
  }
  std::ostream& out = options.out.empty() ? std::cout : file;
  out << "# carom beside Box2D and Chipmunk: the same scenes, one run, one machine\n\n"
      << "<!-- Generated by bench/peers; rerun `make bench-peers` rather than editing "
         "the tables by hand. -->\n\n"
      << "- Command: `" << options.command << "`"
      << (options.quick ? " (quick: N ≤ 10⁴, " + std::to_string(kQuickSteps) + " steps)" : "")
      << (options.smoke ? " (smoke test: tiny cases, a few steps; not a measurement)" : "") << "\n"
      << "- Measured: " << utc_now() << ", " << format("%.0f", total_seconds)
      << " s for the whole run; load average (1, 5, 15 min) " << load_before << " before, "
      << load_average() << " after\n"
      << "- Machine: " << read_first("/proc/cpuinfo", "model name") << ", "
      << sysconf(_SC_NPROCESSORS_ONLN) << " CPUs online (as `lscpu` shows); one thread per engine\n"
      << "- Build: " << CAROM_PEERS_BUILD << "\n"
      << "- Engines:";
  for (const EngineInfo& e : engines) out << " " << e.version << ";";
  out << " each case in a process of its own\n";
  std::string missing;
  for (const char* peer : {"box2d", "chipmunk"}) {
    bool found = false;
    for (const EngineInfo& e : engines) found |= e.name == peer;
    if (!found) missing += std::string(missing.empty() ? "" : ", ") + peer;
  }
  if (!missing.empty()) {
    out << "- **Not in this build: " << missing
        << "** (not installed when it was configured; Debian: libbox2d-dev, libchipmunk-dev; "
           "`make deps` installs them), so the tables below leave it out\n";
  }
  out << "\n"
      << "## The gas: equal disks in a closed box\n\n"
      << "Disks of radius 0.5 and mass 1, elastic, frictionless, no gravity or damping, in a "
         "square box of four static walls; jittered square grid; velocity components normal with "
         "standard deviation 1 (seed "
      << kDefaultSeed
      << "); steps of 1/60 s, 600 of them (the first 100 only for the peers at N = 10⁵, where a "
         "step takes them a good fraction of a second, to keep the run short). "
         "Time per step: the engine's step call alone, on a steady clock (wall), and on the "
         "thread's CPU clock, which leaves out the time the thread waited for a busy machine; "
         "on a quiet machine the two agree. Contacts/step: the contacts carom resolved (the "
         "peers do not count theirs the same way). "
         "Peak MiB: the process's peak resident memory (VmHWM), and in brackets what it grew by "
         "after the harness had set up the scene and its checks (the engine's share, roughly). "
         "Energy drift: (E_end − E_start)/E_start. Largest overlap: the deepest overlap of two "
         "disks at any step's end, as a fraction of the sum of radii. Missed: pair-steps in which "
         "two disks went through each other: carom's swept test (`carom::sweep_ball_ball`) on a "
         "stretch of the step where both move in a straight line meets an approaching contact, "
         "yet at the stretch's end the two neither overlap nor approach; in brackets, how deep the "
         "deepest went: 1 − (closest distance)/(sum of radii), near 0 for a graze. A time-stepped "
         "engine "
         "moves each disk in one straight line per step, from its start to its end; carom bends "
         "a disk's path at each contact, reports the contacts with their times and points, and "
         "the check follows each straight piece. Left box: disks whose centre was outside the box "
         "at a step's end.\n\n";
  gas_table(out, outcomes, engines);
  out << "\n## The bullets\n\n"
      << kBulletCount << " disks of radius " << format("%.2f", kBulletRadius) << " (mass "
      << format("%.2f", kGasMass * (kBulletRadius / kGasRadius) * (kBulletRadius / kGasRadius))
      << ") fly at " << format("%.0f", kBulletDiametersPerStep)
      << " of their diameters per step (100 length units, 6000 per second) from a strip along "
         "the left wall into a resting field of "
      << kBulletFieldCount
      << " gas disks (packing 0.2, box about 63 wide). A bullet that went through at least one "
         "disk in any step (the missed-collision test) counts as through.\n\n";
  bullets_table(out, outcomes, engines);
  gravity_section(out, options, outcomes, engines);
  out << "\n## The goal: carom at least " << format("%.0f", kGoalSpeedUp)
      << "× faster per step than the fastest peer (N ≥ 10⁴)\n\n";
  goal_table(out, outcomes, engines);
  out << "\n" << notes();
  if (!options.out.empty()) std::cerr << "carom_peers: wrote " << options.out << "\n";
  return all_ran ? 0 : 1;
}

}  // namespace carom::peers
