#include "commands/run_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "carom/scene.hpp"
#include "options/exit_codes.hpp"
#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "run/run_checkpoint.hpp"
#include "run/run_outputs.hpp"
#include "run/run_report.hpp"
#include "run/scene_input.hpp"
#include "system/output_file.hpp"
#include "system/progress_bar.hpp"
#include "system/stop_signals.hpp"
#include "system/wall_clock.hpp"

namespace carom::cli {
namespace {

// Without --every, a run to a time is cut into this many chunks (for the progress bar and the
// events file, which are brought up to date after each), and a run of collisions likewise.
constexpr double kChunksPerRun = 200.0;
// Without --every, `--until` writes this many frames after the first.
constexpr double kDefaultFrames = 100.0;
// Contacts a chunk of a run until rest (for the events file, the progress line and checkpoints).
constexpr std::uint64_t kRestChunk = 1000;
// What an output takes, for the check of free space before a run: a frame's line for a ball and
// an event's JSON line, a quarter above what the box of 1000 writes (95 bytes a ball in CSV, 93 in
// extended XYZ; 225 an event), since long names and full-precision numbers take more.
constexpr double kFrameBytesPerBall = 120.0;
constexpr double kEventBytes = 280.0;

struct RunOptions {
  std::string scene;
  std::string until;
  std::string steps;
  std::string dt;
  std::string collisions;
  std::string time_limit;
  std::string frames;
  std::string format;
  std::string every;
  std::string events;
  std::string save;
  std::string checkpoint;
  std::string checkpoint_every;
  std::string resume;
  bool stats = false;
  bool json = false;
  bool quiet = false;
};

// rest: until every ball rests and every shot is struck (a scene on a table, with no other mode).
enum class Mode : std::uint8_t { until, steps, collisions, rest };

struct RunPlan {
  Mode mode = Mode::until;
  double until = 0.0;
  std::uint64_t steps = 0;
  double dt = 0.0;
  std::uint64_t collisions = 0;
  std::optional<double> time_limit;  // --collisions: scene time not to run past
  std::optional<double> every;
  std::optional<double> checkpoint_every;
  std::optional<FrameFormat> frame_format;
};

std::uint64_t parse_count(std::string_view option, std::string_view text) {
  const OptionValue value{option, text, "a whole number >= 1"};
  const std::uint64_t number = parse_whole_number(value);
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
  if (o.scene.empty() == o.resume.empty()) {
    throw UsageError("SCENE/--resume", "",
                     "give a scene file to run, or --resume FILE to continue from a checkpoint");
  }
  const int modes = static_cast<int>(!o.until.empty()) + static_cast<int>(!o.steps.empty()) +
                    static_cast<int>(!o.collisions.empty());
  if (modes > 1) {
    throw UsageError("--until/--steps/--collisions", "",
                     "give exactly one of --until T, --steps K (with --dt DT) or --collisions K");
  }
  if (modes == 0) {
    // Until rest: refused after the scene is read unless it is on a table (require_mode).
    plan.mode = Mode::rest;
  } else if (!o.until.empty()) {
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
  if (!o.time_limit.empty()) {
    if (plan.mode != Mode::collisions) {
      throw UsageError("--time-limit", o.time_limit,
                       "--time-limit goes with --collisions (--until is a time already)");
    }
    plan.time_limit = parse_finite_number(o.time_limit, {"--time-limit", o.time_limit, "a time"});
  }
  if (!o.every.empty()) {
    if (plan.mode == Mode::collisions) {
      throw UsageError("--every", o.every,
                       "frames at times need --until, --steps or a run until rest; with "
                       "--collisions the frames "
                       "are the first and the last");
    }
    if (o.frames.empty()) throw UsageError("--every", o.every, "--every goes with --frames");
    plan.every = parse_positive("--every", o.every);
  }
  if (!o.format.empty()) {
    if (o.frames.empty()) throw UsageError("--format", o.format, "--format goes with --frames");
    plan.frame_format = frame_format_of("." + o.format);
    if (!plan.frame_format) throw UsageError("--format", o.format, "give csv or xyz");
  } else if (!o.frames.empty()) {
    plan.frame_format = frame_format_of(o.frames);
    if (!plan.frame_format) {
      throw UsageError("--frames", o.frames,
                       "the file name must end in .csv (CSV) or .xyz (extended XYZ), or give "
                       "--format csv|xyz (for - and other names without one)");
    }
  }
  if (!o.checkpoint_every.empty()) {
    if (o.checkpoint.empty()) {
      throw UsageError("--checkpoint-every", o.checkpoint_every,
                       "--checkpoint-every goes with --checkpoint FILE");
    }
    plan.checkpoint_every = parse_positive("--checkpoint-every", o.checkpoint_every);
  }
  if (o.resume == kStandardOutput) {
    throw UsageError("--resume", o.resume, "a checkpoint is read from a file, not standard input");
  }
  // Every output is checked before any work, and no two may be the same file.
  const NamedOutput outputs[] = {{"--frames", &o.frames},
                                 {"--events", &o.events},
                                 {"--save", &o.save},
                                 {"--checkpoint", &o.checkpoint}};
  check_distinct_outputs(outputs);
  if (!o.checkpoint.empty() && !replaced_by_rename(o.checkpoint)) {
    throw UsageError("--checkpoint", o.checkpoint,
                     "a checkpoint is a file replaced at every write (the one before kept as "
                     "FILE.prev): give a plain file, not standard output, a device or a FIFO");
  }
  return plan;
}

// Refuses, before the run, an output that would not fit in its folder's free space: the frames
// (their number is known from the plan) and, for --collisions, the events.
void check_room_for_outputs(const RunOptions& o, const RunPlan& plan, std::size_t balls,
                            double start_time) {
  if (!o.frames.empty()) {
    double frames = 2.0;
    if (plan.mode == Mode::until) {
      const double span = plan.until - start_time;
      frames += span / plan.every.value_or(span / kDefaultFrames);
    } else if (plan.mode == Mode::steps) {
      const double span = static_cast<double>(plan.steps) * plan.dt;
      frames += span / plan.every.value_or(plan.dt);
    }
    const double bytes = frames * static_cast<double>(balls) * kFrameBytesPerBall;
    if (const auto problem = check_room(o.frames, bytes)) {
      throw UsageError("--frames", o.frames,
                       "refused before the run: " + readable(frames) + " frames of " +
                           std::to_string(balls) + " balls " + *problem);
    }
  }
  if (!o.events.empty() && plan.mode == Mode::collisions) {
    const double bytes = static_cast<double>(plan.collisions) * kEventBytes;
    if (const auto problem = check_room(o.events, bytes)) {
      throw UsageError(
          "--events", o.events,
          "refused before the run: " + std::to_string(plan.collisions) + " contacts " + *problem);
    }
  }
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

// Whether the total energy should stay as it is: every restitution 1, no pockets, and no
// immovable ball moving (which does work on the balls it meets). Otherwise its changes are
// physics, not numerical drift.
bool keeps_total_energy(const SceneWorld& built) {
  const Scene& scene = built.scene;
  if (!scene.pockets.empty() || scene.world.restitution != 1.0) return false;
  // Growth pumps energy in, a thermostat takes it out.
  if (scene.world.growth_rate != 0.0 || scene.thermostat) return false;
  for (const SceneBall& ball : scene.balls) {
    if (ball.restitution && *ball.restitution != 1.0) return false;
    if (ball.mass == kImmovable && (ball.velocity.x != 0.0 || ball.velocity.y != 0.0)) return false;
  }
  return true;
}

// Why a run stopped short, for the closing line ("" when it did what it was asked).
std::string stop_note(StopReason reason) {
  switch (reason) {
    case StopReason::no_more_contacts:
      return " (stopped: no contact will ever happen again)";
    case StopReason::time_limit:
      return " (stopped at the --time-limit)";
    case StopReason::interrupted:
      return " (stopped by a signal)";
    case StopReason::stop_condition:
    case StopReason::none:
      break;
  }
  return "";
}

// The options that decide a run's course, as a user would write them (for a resume that differs).
std::string plan_text(const RunProgress& p) {
  std::string text;
  switch (static_cast<Mode>(p.mode)) {
    case Mode::until:
      text = "--until " + number_text(p.until);
      break;
    case Mode::steps:
      text = "--steps " + std::to_string(p.steps) + " --dt " + number_text(p.dt);
      break;
    case Mode::collisions:
      text = "--collisions " + std::to_string(p.collisions);
      if (p.has_time_limit) text += " --time-limit " + number_text(p.time_limit);
      break;
    case Mode::rest:
      text = "no --until/--steps/--collisions (until every ball rests)";
      break;
  }
  if (p.every > 0.0) text += " --every " + number_text(p.every);
  if (p.checkpoint_every > 0.0) text += " --checkpoint-every " + number_text(p.checkpoint_every);
  return text;
}

// The plan's part of a run's progress.
RunProgress plan_progress(const RunPlan& plan) {
  RunProgress p;
  p.mode = static_cast<std::uint8_t>(plan.mode);
  p.until = plan.mode == Mode::until ? plan.until : 0.0;
  p.steps = plan.steps;
  p.dt = plan.dt;
  p.collisions = plan.collisions;
  p.has_time_limit = plan.time_limit.has_value();
  p.time_limit = plan.time_limit.value_or(0.0);
  p.every = plan.every.value_or(0.0);
  p.checkpoint_every = plan.checkpoint_every.value_or(0.0);
  return p;
}

// The run itself: advances chunk by chunk, writing frames, events and checkpoints as it goes.
// All its position in the run lives in state_, so that a run resumed from a checkpoint takes
// the same chunks, writes frames at the same times and counts on from the same numbers. A signal
// stops the world within a few thousand events, at an event boundary inside a chunk: the chunk's
// contacts are written, the frame and checkpoint due at its end are not (they belong to a time
// not reached), and the end frame and checkpoint hold the stop.
class Runner {
 public:
  Runner(const RunOptions& options, const RunPlan& plan, SceneWorld& built, RunProgress progress,
         bool resumed)
      : options_(options),
        plan_(plan),
        built_(built),
        directory_(built),
        progress_(!options.quiet),
        wall_offset_(built.scene.world.boundary == Boundary::box ? 4 : 0),
        state_(std::move(progress)),
        resumed_(resumed) {}

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

  // Call while a StopOnSignals lives.
  void run(RunOutcome& outcome) {
    start_ = state_.run_start_time;
    stop_world_on_signals(built_.world, [this](const RunStatus& status) { on_progress(status); });
    // A resumed run's frame at its start was written by the run that made the checkpoint.
    if (!resumed_) write_frame();
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
      case Mode::rest:
        run_to_rest();
        break;
    }
    built_.world.set_progress_callback(nullptr);
    if (frames_ && state_.last_frame_time != built_.time()) write_frame();
    progress_.finish();
    // The end (or the stop) is a checkpoint too, unless the last one already holds it.
    if (dirty_) checkpoint();
    if (StopOnSignals::requested()) stopped_ = StopReason::interrupted;
    outcome.interrupted = stopped_ == StopReason::interrupted;
    outcome.stopped = stopped_;
    outcome.collisions = state_.ball_ball + state_.ball_wall;
    outcome.ball_ball = state_.ball_ball;
    outcome.ball_wall = state_.ball_wall;
    outcome.potted = state_.potted;
    outcome.frames = frames_ ? frames_->frames() : 0;
  }

  // Finishes the files; returns what went wrong, or nothing.
  std::optional<std::string> commit() {
    if (checkpoint_problem_) return checkpoint_problem_;
    if (frames_) {
      if (auto problem = frames_->commit()) return problem;
    }
    if (events_) {
      if (auto problem = events_->commit()) return problem;
    }
    return std::nullopt;
  }

 private:
  [[nodiscard]] bool stop_requested() const {
    return StopOnSignals::requested() || checkpoint_problem_.has_value();
  }

  // Whether the world's last run was cut short by a signal.
  [[nodiscard]] bool interrupted() const {
    return built_.world.stop_reason() == StopReason::interrupted;
  }

  // The run's fraction done, for the progress bar, given the world's status within a chunk.
  [[nodiscard]] double fraction_done(const RunStatus& status) const {
    switch (plan_.mode) {
      case Mode::until: {
        const double span = plan_.until - start_;
        return span > 0.0 ? (built_.start_time + status.time - start_) / span : 1.0;
      }
      case Mode::steps:
        return static_cast<double>(state_.steps_done) / static_cast<double>(plan_.steps);
      case Mode::collisions:
        return static_cast<double>(state_.collisions_done + status.contacts) /
               static_cast<double>(plan_.collisions);
      case Mode::rest:
        break;  // (how long until rest is not known beforehand)
    }
    return 0.0;
  }

  // Inside a chunk: the bar moves on even when no contact happens (balls crossing cells in a
  // periodic world that never meet, or a long flight to the next contact).
  void on_progress(const RunStatus& status) {
    const double seconds = seconds_since(clock_start_);
    const std::uint64_t done =
        state_.ball_ball + state_.ball_wall + status.contacts - counted_before_;
    const std::uint64_t crossings = status.events - status.contacts;
    progress_.update(fraction_done(status),
                     readable(seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0) +
                         " collisions/s  t=" + readable(built_.start_time + status.time) +
                         (crossings > 0 ? "  " + readable(static_cast<double>(crossings)) +
                                              " cell crossings in this chunk"
                                        : ""));
  }

  void after_chunk(double fraction) {
    for (const ContactEvent& c : contacts_) {
      ++(c.kind == ContactKind::ball_ball ? state_.ball_ball : state_.ball_wall);
    }
    // A potting is a pocket's sensor removing the ball (no contact).
    for (const SensorEvent& e : built_.sensor_events) {
      const bool pocket =
          std::find(built_.pockets.begin(), built_.pockets.end(), e.sensor) != built_.pockets.end();
      if (pocket && e.removed) ++state_.potted;
    }
    if (events_) events_->write(contacts_, directory_, built_, wall_offset_);
    contacts_.clear();
    dirty_ = true;
    const double seconds = seconds_since(clock_start_);
    const std::uint64_t done = state_.ball_ball + state_.ball_wall - counted_before_;
    progress_.update(fraction, readable(seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0) +
                                   " collisions/s  t=" + readable(built_.time()));
  }

  void write_frame() {
    if (frames_) frames_->write_frame(built_);
    state_.last_frame_time = built_.time();
  }

  // Writes a checkpoint (with --checkpoint); a failure stops the run and is reported by commit().
  void checkpoint() {
    dirty_ = false;
    if (options_.checkpoint.empty()) return;
    if (auto problem = write_checkpoint(options_.checkpoint, encode_checkpoint(built_, state_))) {
      checkpoint_problem_ = "checkpoint: " + *problem;
    }
  }

  [[nodiscard]] double checkpoint_time() const {
    if (!plan_.checkpoint_every) return std::numeric_limits<double>::infinity();
    return start_ + static_cast<double>(state_.next_checkpoint) * *plan_.checkpoint_every;
  }

  // For the modes that cannot stop at a time: a checkpoint after the chunk that reaches time
  // start + k·every (one, however many such times the chunk passed).
  void checkpoint_if_due() {
    if (!plan_.checkpoint_every || built_.time() < checkpoint_time()) return;
    while (checkpoint_time() <= built_.time()) ++state_.next_checkpoint;
    checkpoint();
  }

  void run_until() {
    const double end = plan_.until;
    const double span = end - start_;
    const double every = plan_.every.value_or(span / kDefaultFrames);
    // Chunks no longer than a frame interval nor 1/200 of the run, for the events file and the
    // progress bar.
    const double chunk = std::min(every, span / kChunksPerRun);
    // Frame k falls at start + k·every; computed from k, never accumulated, so no drift. The same
    // for chunks and checkpoints, so a resumed run cuts its chunks where the first run would have.
    std::uint64_t& next_frame = state_.next_frame;
    std::uint64_t& next_chunk = state_.next_chunk;
    while (built_.time() < end && !stop_requested()) {
      const double frame_time = start_ + static_cast<double>(next_frame) * every;
      const double chunk_time = start_ + static_cast<double>(next_chunk) * chunk;
      const double checkpoint_at = checkpoint_time();
      const double target = std::min({frame_time, chunk_time, checkpoint_at, end});
      // The world's end is computed from the target alone, so that a run stopped inside a chunk
      // and resumed ends the chunk at the same instant. The clock may pass a target by a
      // rounding; a run never goes back.
      const double world_end = std::max(target - built_.start_time, built_.world.time());
      run_scene_until(built_, world_end, &contacts_);
      const bool reached = !interrupted();
      if (reached && target >= frame_time) {
        write_frame();
        ++next_frame;
      }
      if (reached && target >= chunk_time) ++next_chunk;
      after_chunk(span > 0.0 ? (built_.time() - start_) / span : 1.0);
      if (!reached) break;
      if (target >= checkpoint_at) {
        ++state_.next_checkpoint;
        checkpoint();
      }
      if (target >= end) break;
    }
  }

  void run_steps() {
    const double every = plan_.every.value_or(plan_.dt);
    std::uint64_t& next_frame = state_.next_frame;
    while (state_.steps_done < plan_.steps && !stop_requested()) {
      // A step's end is fixed when it starts (world time + dt, as World::step takes it) and kept
      // in the progress, so that a step cut by a signal is finished by the resumed run.
      if (!state_.in_step) {
        state_.in_step = true;
        state_.step_end = built_.world.time() + plan_.dt;
      }
      run_scene_until(built_, state_.step_end, &contacts_);
      if (interrupted()) {
        after_chunk(static_cast<double>(state_.steps_done) / static_cast<double>(plan_.steps));
        break;
      }
      state_.in_step = false;
      ++state_.steps_done;
      // A frame after the step that reaches frame time k·every (to rounding of the steps' sum).
      const double elapsed = built_.time() - start_;
      if (elapsed >= static_cast<double>(next_frame) * every * (1.0 - 1e-12)) {
        write_frame();
        while (static_cast<double>(next_frame) * every * (1.0 - 1e-12) <= elapsed) ++next_frame;
      }
      after_chunk(static_cast<double>(state_.steps_done) / static_cast<double>(plan_.steps));
      checkpoint_if_due();
    }
  }

  void run_collisions() {
    const auto chunk = static_cast<std::uint64_t>(
        std::max(1.0, std::floor(static_cast<double>(plan_.collisions) / kChunksPerRun)));
    const double limit = plan_.time_limit ? *plan_.time_limit - built_.start_time
                                          : std::numeric_limits<double>::infinity();
    std::uint64_t& done = state_.collisions_done;
    while (done < plan_.collisions && !stop_requested()) {
      if (built_.world.time() >= limit) {
        stopped_ = StopReason::time_limit;
        break;
      }
      const std::uint64_t ask = std::min(chunk, plan_.collisions - done);
      const std::uint64_t got = run_scene_collisions(built_, ask, &contacts_, nullptr, limit);
      done += got;
      after_chunk(static_cast<double>(done) / static_cast<double>(plan_.collisions));
      if (got < ask) {  // interrupted, at the time limit, or no contact will ever happen again
        stopped_ = built_.world.stop_reason();
        break;
      }
      checkpoint_if_due();
    }
  }

  // Whether nothing will move again: every ball at rest and every shot struck.
  [[nodiscard]] bool resting() const {
    return built_.world.at_rest() && built_.shots_taken == built_.scene.shots.size();
  }

  // Until rest: chunks of contacts (the world waits through a rest for the next shot), or with
  // --every chunks that end on the frame times.
  void run_to_rest() {
    std::uint64_t& next_frame = state_.next_frame;
    while (!resting() && !stop_requested()) {
      if (plan_.every) {
        const double frame_time = start_ + static_cast<double>(next_frame) * *plan_.every;
        const double world_end = std::max(frame_time - built_.start_time, built_.world.time());
        run_scene_until(built_, world_end, &contacts_);
        if (!interrupted()) {
          write_frame();
          ++next_frame;
        }
      } else {
        static_cast<void>(run_scene_collisions(built_, kRestChunk, &contacts_));
      }
      after_chunk(0.0);
      if (interrupted()) break;
      checkpoint_if_due();
    }
  }

  const RunOptions& options_;
  const RunPlan& plan_;
  SceneWorld& built_;
  BallDirectory directory_;
  ProgressBar progress_;
  std::size_t wall_offset_;
  RunProgress state_;
  bool resumed_;
  // Contacts counted before this process started (for the progress bar's rate).
  std::uint64_t counted_before_ = state_.ball_ball + state_.ball_wall;
  bool dirty_ = false;  // chunks run since the last checkpoint
  StopReason stopped_ = StopReason::none;
  std::optional<std::string> checkpoint_problem_;
  std::optional<FrameWriter> frames_;
  std::optional<EventWriter> events_;
  std::vector<ContactEvent> contacts_;
  double start_ = 0.0;
  std::chrono::steady_clock::time_point clock_start_ = std::chrono::steady_clock::now();
};

// The world and progress to run from: the scene built fresh, or a checkpoint read back (and the
// plan checked against the one it was made with).
Checkpoint starting_point(const RunOptions& options, RunPlan& plan) {
  if (options.resume.empty()) {
    const Scene scene = read_scene_argument(options.scene);
    Checkpoint start{make_world(scene), plan_progress(plan)};
    const SceneWorld& built = start.built;
    RunProgress& p = start.progress;
    p.run_start_time = built.time();
    p.balls_at_start = live_balls(built);
    p.energy_before = built.world.kinetic_energy();
    p.potential_before = built.world.potential_energy();
    p.momentum_before_x = built.world.momentum().x;
    p.momentum_before_y = built.world.momentum().y;
    p.movable_mass = movable_mass(built);
    p.scene_file = scene_source_name(options.scene);
    return start;
  }
  Checkpoint start = read_checkpoint(options.resume);
  // --checkpoint-every cuts the chunks of an --until run, so it carries over unless given.
  if (!plan.checkpoint_every && start.progress.checkpoint_every > 0.0) {
    plan.checkpoint_every = start.progress.checkpoint_every;
  }
  const RunProgress asked = plan_progress(plan);
  if (plan_text(asked) != plan_text(start.progress)) {
    throw UsageError("--resume", options.resume,
                     "the checkpoint was made by a run with " + plan_text(start.progress) +
                         "; give the same options to continue it (this run: " + plan_text(asked) +
                         ")");
  }
  return start;
}

int run(const RunOptions& options) {
  RunPlan plan = parse(options);
  const auto setup_start = std::chrono::steady_clock::now();
  Checkpoint start;
  try {
    start = starting_point(options, plan);
  } catch (const CheckpointError& error) {
    std::cerr << "carom run: error: " << error.what() << '\n';
    return kExitUsage;
  }
  SceneWorld& built = start.built;
  const RunProgress& p = start.progress;
  if (plan.mode == Mode::rest && !built.scene.world.table) {
    throw UsageError(
        "--until/--steps/--collisions", "",
        "give exactly one of --until T, --steps K (with --dt DT) or --collisions K (a scene "
        "on a table, world.table, runs until every ball rests without one)");
  }
  if (plan.mode == Mode::until && plan.until < built.time()) {
    throw UsageError("--until", options.until,
                     "the scene starts at time " + readable(built.time()) +
                         "; --until is the time to run to, not a duration");
  }
  check_room_for_outputs(options, plan, live_balls(built), built.time());
  RunOutcome outcome;
  outcome.scene = p.scene_file;
  outcome.gravity = built.world.def().gravity != Vec2{};
  outcome.total_energy_conserved = keeps_total_energy(built);
  // Gravity changes the kinetic energy and the momentum as it should; only the total is kept.
  outcome.conservative = outcome.total_energy_conserved && !outcome.gravity;
  outcome.setup_seconds = seconds_since(setup_start);
  outcome.balls_at_start = p.balls_at_start;
  outcome.start_time = p.run_start_time;
  outcome.energy_before = p.energy_before;
  outcome.potential_before = p.potential_before;
  outcome.momentum_before = {p.momentum_before_x, p.momentum_before_y};
  outcome.movable_mass = p.movable_mass;

  // Ctrl-C and SIGTERM from here on stop the run cleanly; before, nothing has been written yet.
  const StopOnSignals stop_on_signals;
  Runner runner(options, plan, built, start.progress, !options.resume.empty());
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
    if (const auto problem = write_output(options.save, to_json_text(capture_scene(built)))) {
      std::cerr << "carom run: error: " << *problem << '\n';
      return kExitFailure;
    }
  }
  outcome.wall_seconds = seconds_since(run_start);
  outcome.end_time = built.time();
  outcome.balls_at_end = live_balls(built);
  outcome.energy_after = built.world.kinetic_energy();
  if (built.scene.thermostat) outcome.thermostat_work = built.thermostat_work;
  outcome.potential_after = built.world.potential_energy();
  outcome.momentum_after = built.world.momentum();

  // An output written to standard output keeps it to itself: the summary goes to stderr.
  const bool stdout_taken = options.frames == kStandardOutput ||
                            options.events == kStandardOutput || options.save == kStandardOutput;
  std::ostream& report = stdout_taken ? std::cerr : std::cout;
  if (options.stats) {
    if (options.json) {
      report << run_json(outcome).dump() << '\n';
    } else {
      report << run_text(outcome);
    }
  } else if (!options.quiet) {
    report << "ran " << outcome.scene << " from t=" << readable(outcome.start_time)
           << " to t=" << readable(outcome.end_time) << ": " << outcome.collisions << " collisions"
           << stop_note(outcome.stopped) << "\n";
  }
  if (outcome.interrupted) {
    std::cerr << "carom run: " << StopOnSignals::what() << " at t=" << readable(outcome.end_time)
              << "; the outputs are complete up to there\n";
    return StopOnSignals::exit_code();
  }
  return kExitSuccess;
}

}  // namespace

Command add_run_command(CLI::App& app) {
  CLI::App* verb = app.add_subcommand("run", "Run a scene file and write what it does");
  verb->footer(
      "Advances the scene's world in exact event order (every contact at the time it\n"
      "happens) by one of: --until T (to scene time T), --steps K --dt DT (K steps of DT),\n"
      "or --collisions K (the next K contacts; pocket contacts count); a scene on a table\n"
      "(world.table) runs with none of them until every ball rests and every shot is\n"
      "struck. SCENE - reads the\n"
      "scene from standard input. --collisions returns early when it can prove that no\n"
      "contact will ever happen (balls flying apart, all at rest); some endless runs cannot\n"
      "be told apart from long ones (two balls in a periodic cell on a slanted orbit that\n"
      "never meets): give --time-limit T there, or stop it with Ctrl-C.\n\n"
      "Outputs: a file is written to FILE.tmp beside it (beside a link's target) and renamed\n"
      "onto it when complete; - (standard output), devices and FIFOs are written directly.\n"
      "Ctrl-C or SIGTERM stops the run within a few thousand events with every output\n"
      "complete up to there (exit status 130 or 143); a second one ends it at once.\n"
      "  --frames FILE   positions and velocities at the start, every --every time units,\n"
      "                  and at the end: .csv (time,index,name,x,y,vx,vy,radius) or .xyz\n"
      "                  (extended XYZ, opens in OVITO and ASE); --format csv|xyz for a\n"
      "                  name without either (-, /dev/stdout, a FIFO). Without --every: 100\n"
      "                  frames for --until, one per step for --steps.\n"
      "  --events FILE   every contact as a JSON line: time, kind (ball_ball, ball_wall),\n"
      "                  scene ball indices, wall, point, normal, approach_speed, impulse;\n"
      "                  and in their places the pottings (potted: ball, pocket) and the\n"
      "                  sensors' enters and exits; on a table each ball's change of motion\n"
      "                  state (motion: ball, from, to: sliding, rolling, spinning,\n"
      "                  stationary).\n"
      "  --save FILE     the end state as a scene file to continue from.\n"
      "  --checkpoint FILE  at the end (and on a stop) and, with --checkpoint-every T,\n"
      "                  each time T of scene time has passed: the world and the run's\n"
      "                  progress, written to FILE.tmp, synced and renamed onto FILE; the\n"
      "                  checkpoint before moves to FILE.prev. --until runs are cut at the\n"
      "                  checkpoint times; --steps and --collisions runs check after each\n"
      "                  step or chunk.\n"
      "  --resume FILE   (instead of SCENE) continue from a checkpoint with the same\n"
      "                  --until/--steps/--dt/--collisions/--time-limit/--every options: the\n"
      "                  run ends bit for bit as the run that wrote the checkpoint, even one\n"
      "                  stopped by a signal. --frames and --events are new files that hold\n"
      "                  what happens after the checkpoint; --stats counts and changes cover\n"
      "                  the whole run. A damaged checkpoint is refused (exit 2). Details:\n"
      "                  docs/checkpoints.md.\n"
      "  --stats         collisions, collisions per second, energy and momentum change\n"
      "                  (\"drift\" in a scene that conserves them), with gravity the\n"
      "                  potential and total energy too, wall time, and why a run stopped\n"
      "                  short (--json: one JSON object, \"stopped\": null or one of\n"
      "                  \"no_more_contacts\", \"time_limit\", \"interrupted\").\n"
      "An output whose estimated size exceeds its folder's free space is refused before\n"
      "the run. A progress bar is drawn on stderr when it is a terminal (--quiet: none);\n"
      "the summary goes to stderr when an output is -.\n\n"
      "Examples:\n"
      "  carom run examples/billiards.json --until 10 --stats --frames break.csv\n"
      "  carom run examples/periodic-gas.json --collisions 1000000 --stats --json\n"
      "  carom run examples/box-of-1000.json --steps 100 --dt 0.1 --frames box.xyz --save "
      "end.json\n"
      "  carom run examples/periodic-gas.json --until 1000 --checkpoint gas.ckpt "
      "--checkpoint-every 50\n"
      "  carom run --resume gas.ckpt --until 1000 --checkpoint gas.ckpt\n"
      "  carom run examples/newtons-cradle.json --until 1 --events - --quiet | head");
  auto options = std::make_shared<RunOptions>();
  verb->add_option("SCENE", options->scene, "Scene file (JSON, docs/scenes.md); - stdin");
  verb->add_option("--until", options->until, "Run to this scene time")->type_name("T");
  verb->add_option("--steps", options->steps, "Run this many steps of --dt")->type_name("K");
  verb->add_option("--dt", options->dt, "Length of a step")->type_name("DT");
  verb->add_option("--collisions", options->collisions, "Run this many contacts")->type_name("K");
  verb->add_option("--time-limit", options->time_limit,
                   "With --collisions: never run past this scene time")
      ->type_name("T");
  verb->add_option("--frames", options->frames, "Write frames to FILE (.csv or .xyz; - stdout)")
      ->type_name("FILE");
  verb->add_option("--format", options->format, "Frames' format when FILE has no extension")
      ->type_name("csv|xyz");
  verb->add_option("--every", options->every, "Time between frames")->type_name("DT");
  verb->add_option("--events", options->events, "Write every contact to FILE (JSON lines)")
      ->type_name("FILE");
  verb->add_option("--save", options->save, "Write the end state to FILE as a scene")
      ->type_name("FILE");
  verb->add_option("--checkpoint", options->checkpoint,
                   "Write checkpoints to FILE (the one before: FILE.prev)")
      ->type_name("FILE");
  verb->add_option("--checkpoint-every", options->checkpoint_every,
                   "Scene time between checkpoints")
      ->type_name("T");
  verb->add_option("--resume", options->resume, "Continue the run a checkpoint was made by")
      ->type_name("FILE");
  verb->add_flag("--stats", options->stats, "Print a summary of the run");
  verb->add_flag("--json", options->json, "With --stats: one JSON object");
  verb->add_flag("--quiet", options->quiet, "No progress bar and no closing line");
  return {verb, [options] { return run(*options); }};
}

}  // namespace carom::cli
