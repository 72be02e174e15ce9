#include "run_command.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "atomic_file.hpp"
#include "carom/scene.hpp"
#include "exit_codes.hpp"
#include "interrupt.hpp"
#include "option_value.hpp"
#include "progress_bar.hpp"
#include "readable_number.hpp"
#include "run_outputs.hpp"
#include "run_report.hpp"
#include "usage_error.hpp"

namespace carom::cli {
namespace {

// Without --every, a run to a time is cut into this many chunks (for the progress bar and for
// Ctrl-C, which is honoured between chunks), and a run of collisions likewise.
constexpr double kChunksPerRun = 200.0;
// Without --every, `--until` writes this many frames after the first.
constexpr double kDefaultFrames = 100.0;

struct RunOptions {
  std::string scene;
  std::string until;
  std::string steps;
  std::string dt;
  std::string collisions;
  std::string frames;
  std::string every;
  std::string events;
  std::string save;
  bool stats = false;
  bool json = false;
  bool quiet = false;
};

enum class Mode : std::uint8_t { until, steps, collisions };

struct RunPlan {
  Mode mode = Mode::until;
  double until = 0.0;
  std::uint64_t steps = 0;
  double dt = 0.0;
  std::uint64_t collisions = 0;
  std::optional<double> every;
  std::optional<FrameFormat> frame_format;
};

std::uint64_t parse_count(std::string_view option, std::string_view text) {
  const OptionValue value{option, text, "a whole number >= 1"};
  if (text.empty()) reject(value, "a number is missing");
  std::uint64_t number = 0;
  const char* const end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, number);
  if (error == std::errc::result_out_of_range) reject(value, "the number is too large");
  if (error != std::errc{} || stop != end) reject(value, "not a whole number");
  if (number == 0) reject(value, "must be at least 1");
  return number;
}

double parse_positive(std::string_view option, std::string_view text) {
  const OptionValue value{option, text, "a number > 0"};
  const double number = parse_finite_number(text, value);
  if (!(number > 0.0)) reject(value, "must be > 0");
  return number;
}

RunPlan parse(const RunOptions& o) {
  RunPlan plan;
  const int modes = static_cast<int>(!o.until.empty()) + static_cast<int>(!o.steps.empty()) +
                    static_cast<int>(!o.collisions.empty());
  if (modes != 1) {
    throw UsageError("--until/--steps/--collisions", "",
                     "give exactly one of --until T, --steps K (with --dt DT) or --collisions K");
  }
  if (!o.until.empty()) {
    plan.mode = Mode::until;
    plan.until = parse_finite_number(o.until, {"--until", o.until, "a time"});
  } else if (!o.steps.empty()) {
    plan.mode = Mode::steps;
    plan.steps = parse_count("--steps", o.steps);
    if (o.dt.empty()) throw UsageError("--dt", "", "--steps needs --dt, the length of a step");
    plan.dt = parse_positive("--dt", o.dt);
  } else {
    plan.mode = Mode::collisions;
    plan.collisions = parse_count("--collisions", o.collisions);
  }
  if (o.json && !o.stats) throw UsageError("--json", "", "--json goes with --stats");
  if (!o.dt.empty() && plan.mode != Mode::steps) {
    throw UsageError("--dt", o.dt, "--dt goes with --steps");
  }
  if (!o.every.empty()) {
    if (plan.mode == Mode::collisions) {
      throw UsageError("--every", o.every,
                       "frames at times need --until or --steps; with --collisions the frames "
                       "are the first and the last");
    }
    if (o.frames.empty()) throw UsageError("--every", o.every, "--every goes with --frames");
    plan.every = parse_positive("--every", o.every);
  }
  if (!o.frames.empty()) {
    plan.frame_format = frame_format_of(o.frames);
    if (!plan.frame_format) {
      throw UsageError("--frames", o.frames,
                       "the file name must end in .csv (CSV) or .xyz (extended XYZ)");
    }
  }
  // Every output is checked before any work, and no two may be the same file.
  const std::vector<std::pair<const char*, const std::string*>> outputs{
      {"--frames", &o.frames}, {"--events", &o.events}, {"--save", &o.save}};
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string& path = *outputs[i].second;
    if (path.empty()) continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (*outputs[j].second == path) {
        throw UsageError(outputs[i].first, path,
                         std::string("the same file as ") + outputs[j].first);
      }
    }
    if (const auto problem = check_writable(path)) {
      throw UsageError(outputs[i].first, path, "cannot be written: " + *problem);
    }
  }
  return plan;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double movable_mass(const SceneWorld& built) {
  double mass = 0.0;
  for (const BallId id : built.balls) {
    if (!id.is_null() && built.world.mass(id) != kImmovable) mass += built.world.mass(id);
  }
  return mass;
}

std::size_t live_balls(const SceneWorld& built) {
  std::size_t count = 0;
  for (const BallId id : built.balls) count += id.is_null() ? 0U : 1U;
  return count;
}

// The run itself: advances chunk by chunk, writing frames and events as it goes.
class Runner {
 public:
  Runner(const RunOptions& options, const RunPlan& plan, SceneWorld& built)
      : options_(options),
        plan_(plan),
        built_(built),
        directory_(built),
        progress_(!options.quiet),
        wall_offset_(built.scene.world.boundary == Boundary::box ? 4 : 0) {}

  // Returns what went wrong opening the outputs, or nothing.
  std::optional<std::string> open() {
    if (plan_.frame_format) {
      frames_.emplace(*plan_.frame_format, built_.scene);
      if (auto problem = frames_->open(options_.frames)) return problem;
    }
    if (!options_.events.empty()) {
      events_.emplace();
      if (auto problem = events_->open(options_.events)) return problem;
    }
    return std::nullopt;
  }

  // Call while a StopOnInterrupt lives.
  void run(RunOutcome& outcome) {
    start_ = built_.time();
    write_frame();
    switch (plan_.mode) {
      case Mode::until:
        run_until();
        break;
      case Mode::steps:
        run_steps();
        break;
      case Mode::collisions:
        run_collisions();
        break;
    }
    if (frames_ && last_frame_time_ != built_.time()) write_frame();
    progress_.finish();
    outcome.interrupted = StopOnInterrupt::requested();
    outcome.collisions = ball_ball_ + ball_wall_ + potted_;
    outcome.ball_ball = ball_ball_;
    outcome.ball_wall = ball_wall_;
    outcome.potted = potted_;
    outcome.frames = frames_ ? frames_->frames() : 0;
  }

  // Finishes the files; returns what went wrong, or nothing.
  std::optional<std::string> commit() {
    if (frames_) {
      if (auto problem = frames_->commit()) return problem;
    }
    if (events_) {
      if (auto problem = events_->commit()) return problem;
    }
    return std::nullopt;
  }

 private:
  static bool stop_requested() { return StopOnInterrupt::requested(); }

  void after_chunk(double fraction) {
    for (const ContactEvent& c : contacts_) {
      const bool pocket = c.kind == ContactKind::ball_ball &&
                          (directory_.pocket_index(c.a) || directory_.pocket_index(c.b));
      if (pocket) {
        ++potted_;
      } else if (c.kind == ContactKind::ball_ball) {
        ++ball_ball_;
      } else {
        ++ball_wall_;
      }
    }
    if (events_) events_->write(contacts_, directory_, built_, wall_offset_);
    contacts_.clear();
    const double seconds = seconds_since(clock_start_);
    const std::uint64_t done = ball_ball_ + ball_wall_ + potted_;
    progress_.update(fraction, readable(seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0) +
                                   " collisions/s  t=" + readable(built_.time()));
  }

  void write_frame() {
    if (!frames_) return;
    frames_->write_frame(built_);
    last_frame_time_ = built_.time();
  }

  void run_until() {
    const double end = plan_.until;
    const double span = end - start_;
    const double every = plan_.every.value_or(span / kDefaultFrames);
    // Chunks no longer than a frame interval nor 1/200 of the run, so Ctrl-C is honoured soon.
    const double chunk = std::min(every, span / kChunksPerRun);
    // Frame k falls at start + k·every; computed from k, never accumulated, so no drift.
    std::uint64_t next_frame = 1;
    std::uint64_t next_chunk = 1;
    while (built_.time() < end && !stop_requested()) {
      const double frame_time = start_ + static_cast<double>(next_frame) * every;
      const double chunk_time = start_ + static_cast<double>(next_chunk) * chunk;
      const double target = std::min({frame_time, chunk_time, end});
      // The clock may pass a target by a rounding; a step is never negative.
      step_scene(built_, std::max(0.0, target - built_.time()), &contacts_);
      if (target >= frame_time) {
        if (frames_) write_frame();
        ++next_frame;
      }
      if (target >= chunk_time) ++next_chunk;
      after_chunk(span > 0.0 ? (built_.time() - start_) / span : 1.0);
      if (target >= end) break;
    }
  }

  void run_steps() {
    const double every = plan_.every.value_or(plan_.dt);
    std::uint64_t next_frame = 1;
    for (std::uint64_t step = 0; step < plan_.steps && !stop_requested(); ++step) {
      step_scene(built_, plan_.dt, &contacts_);
      // A frame after the step that reaches frame time k·every (to rounding of the steps' sum).
      const double elapsed = built_.time() - start_;
      if (elapsed >= static_cast<double>(next_frame) * every * (1.0 - 1e-12)) {
        write_frame();
        while (static_cast<double>(next_frame) * every * (1.0 - 1e-12) <= elapsed) ++next_frame;
      }
      after_chunk(static_cast<double>(step + 1) / static_cast<double>(plan_.steps));
    }
  }

  void run_collisions() {
    const auto chunk = static_cast<std::uint64_t>(
        std::max(1.0, std::floor(static_cast<double>(plan_.collisions) / kChunksPerRun)));
    std::uint64_t done = 0;
    while (done < plan_.collisions && !stop_requested()) {
      const std::uint64_t ask = std::min(chunk, plan_.collisions - done);
      const std::uint64_t got = run_scene_collisions(built_, ask, &contacts_);
      done += got;
      after_chunk(static_cast<double>(done) / static_cast<double>(plan_.collisions));
      if (got < ask) break;  // no contact will ever happen again
    }
  }

  const RunOptions& options_;
  const RunPlan& plan_;
  SceneWorld& built_;
  BallDirectory directory_;
  ProgressBar progress_;
  std::size_t wall_offset_;
  std::optional<FrameWriter> frames_;
  std::optional<EventWriter> events_;
  std::vector<ContactEvent> contacts_;
  std::uint64_t ball_ball_ = 0;
  std::uint64_t ball_wall_ = 0;
  std::uint64_t potted_ = 0;
  double start_ = 0.0;
  double last_frame_time_ = 0.0;
  std::chrono::steady_clock::time_point clock_start_ = std::chrono::steady_clock::now();
};

int run(const RunOptions& options) {
  const RunPlan plan = parse(options);
  const auto setup_start = std::chrono::steady_clock::now();
  const Scene scene = load_scene(options.scene);
  SceneWorld built = make_world(scene);
  if (plan.mode == Mode::until && plan.until < built.time()) {
    throw UsageError("--until", options.until,
                     "the scene starts at time " + readable(built.time()) +
                         "; --until is the time to run to, not a duration");
  }
  RunOutcome outcome;
  outcome.scene = options.scene;
  outcome.setup_seconds = seconds_since(setup_start);
  outcome.balls_at_start = live_balls(built);
  outcome.start_time = built.time();
  outcome.energy_before = built.world.kinetic_energy();
  outcome.momentum_before = built.world.momentum();
  outcome.movable_mass = movable_mass(built);

  // Ctrl-C from here on stops the run cleanly; before, nothing has been written yet.
  const StopOnInterrupt interrupt;
  Runner runner(options, plan, built);
  if (const auto problem = runner.open()) {
    std::cerr << "carom run: error: " << *problem << '\n';
    return kExitUsage;
  }
  const auto run_start = std::chrono::steady_clock::now();
  runner.run(outcome);
  if (const auto problem = runner.commit()) {
    std::cerr << "carom run: error: " << *problem << '\n';
    return kExitFailure;
  }
  if (!options.save.empty()) {
    if (const auto problem =
            write_file_atomically(options.save, to_json_text(capture_scene(built)))) {
      std::cerr << "carom run: error: " << *problem << '\n';
      return kExitFailure;
    }
  }
  outcome.wall_seconds = seconds_since(run_start);
  outcome.end_time = built.time();
  outcome.balls_at_end = live_balls(built);
  outcome.energy_after = built.world.kinetic_energy();
  outcome.momentum_after = built.world.momentum();

  if (options.stats) {
    if (options.json) {
      std::cout << run_json(outcome).dump() << '\n';
    } else {
      std::cout << run_text(outcome);
    }
  } else if (!options.quiet) {
    std::cout << "ran " << options.scene << " from t=" << readable(outcome.start_time)
              << " to t=" << readable(outcome.end_time) << ": " << outcome.collisions
              << " collisions\n";
  }
  if (outcome.interrupted) {
    std::cerr << "carom run: interrupted at t=" << readable(outcome.end_time)
              << "; the outputs are complete up to there\n";
    return kExitInterrupted;
  }
  return kExitSuccess;
}

}  // namespace

Command add_run_command(CLI::App& app) {
  CLI::App* verb = app.add_subcommand("run", "Run a scene file and write what it does");
  verb->footer(
      "Advances the scene's world in exact event order (every contact at the time it\n"
      "happens) by one of: --until T (to scene time T), --steps K --dt DT (K steps of DT),\n"
      "or --collisions K (the next K contacts; pocket contacts count). In an open world\n"
      "whose balls fly apart for good, --collisions waits for contacts that never come\n"
      "(World::run_collisions keeps going); use --until there.\n\n"
      "Outputs, each written to FILE.tmp and renamed when complete (also on Ctrl-C, which\n"
      "stops the run after the current chunk; exit status 130):\n"
      "  --frames FILE   positions and velocities at the start, every --every time units,\n"
      "                  and at the end: .csv (time,index,name,x,y,vx,vy,radius) or .xyz\n"
      "                  (extended XYZ, opens in OVITO and ASE). Without --every: 100\n"
      "                  frames for --until, one per step for --steps.\n"
      "  --events FILE   every contact as a JSON line: time, kind (ball_ball, ball_wall,\n"
      "                  potted), scene ball indices, wall, point, normal, approach_speed,\n"
      "                  impulse.\n"
      "  --save FILE     the end state as a scene file to continue from.\n"
      "  --stats         collisions, collisions per second, energy and momentum drift,\n"
      "                  wall time (--json: one JSON object).\n"
      "A progress bar is drawn on stderr when it is a terminal (--quiet: none).\n\n"
      "Examples:\n"
      "  carom run examples/billiards.json --until 10 --stats --frames break.csv\n"
      "  carom run examples/periodic-gas.json --collisions 1000000 --stats --json\n"
      "  carom run examples/box-of-1000.json --steps 100 --dt 0.1 --frames box.xyz --save "
      "end.json");
  auto options = std::make_shared<RunOptions>();
  verb->add_option("SCENE", options->scene, "Scene file (JSON, docs/scenes.md)")->required();
  verb->add_option("--until", options->until, "Run to this scene time")->type_name("T");
  verb->add_option("--steps", options->steps, "Run this many steps of --dt")->type_name("K");
  verb->add_option("--dt", options->dt, "Length of a step")->type_name("DT");
  verb->add_option("--collisions", options->collisions, "Run this many contacts")->type_name("K");
  verb->add_option("--frames", options->frames, "Write frames to FILE (.csv or .xyz)")
      ->type_name("FILE");
  verb->add_option("--every", options->every, "Time between frames")->type_name("DT");
  verb->add_option("--events", options->events, "Write every contact to FILE (JSON lines)")
      ->type_name("FILE");
  verb->add_option("--save", options->save, "Write the end state to FILE as a scene")
      ->type_name("FILE");
  verb->add_flag("--stats", options->stats, "Print a summary of the run");
  verb->add_flag("--json", options->json, "With --stats: one JSON object");
  verb->add_flag("--quiet", options->quiet, "No progress bar and no closing line");
  return {verb, [options] { return run(*options); }};
}

}  // namespace carom::cli
