#include "commands/shot_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "carom/scene.hpp"
#include "drawing/ball_colours.hpp"
#include "drawing/picture_file.hpp"
#include "drawing/scene_picture.hpp"
#include "drawing/trail_recorder.hpp"
#include "options/exit_codes.hpp"
#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "run/run_outputs.hpp"
#include "run/scene_input.hpp"
#include "system/output_file.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {
namespace {

// The paths are drawn through each ball's centre at every contact and at this step of table
// time as well: a sliding ball's parabola then strays from the chords by at most μs·g·step²/8
// (0.4 mm at the defaults).
constexpr double kPathStep = 1.0 / 64.0;

struct ShotOptions {
  std::string scene;
  std::string ball;
  std::string speed;
  std::string direction;
  std::string elevation;
  std::string side;
  std::string height;
  std::string cue_mass;
  std::string tip_restitution;
  std::string events;
  std::string out;
  std::string save;
  bool json = false;
  bool quiet = false;
};

double parse_number(std::string_view option, const std::string& text, double fallback) {
  if (text.empty()) return fallback;
  return parse_finite_number(text, {option, text, "a number"});
}

// The option a field of the shot came from, for a scene check's complaint about it.
std::string option_of(const std::string& path) {
  const std::string field = path.substr(path.rfind('.') + 1);
  if (field == "restitution") return "--tip-restitution";
  if (field == "cue_mass") return "--cue-mass";
  return "--" + field;
}

// The scene with this shot, struck at its start, in place of the shots it holds; checked as a
// scene file is, so that a mistake in the shot names its option.
Scene scene_with_shot(const ShotOptions& o) {
  Scene scene = read_scene_argument(o.scene);
  if (!scene.world.table) {
    throw UsageError("SCENE", o.scene,
                     "is not on a table: give a scene with world.table (docs/pool.md)");
  }
  SceneShot shot;
  shot.ball = o.ball;
  shot.time = scene.time;
  shot.cue.speed = parse_number("--speed", o.speed, 0.0);
  shot.cue.direction = parse_number("--direction", o.direction, 0.0);
  shot.cue.elevation = parse_number("--elevation", o.elevation, 0.0);
  shot.cue.side = parse_number("--side", o.side, 0.0);
  shot.cue.height = parse_number("--height", o.height, 0.0);
  shot.cue.cue_mass = parse_number("--cue-mass", o.cue_mass, CueStrike{}.cue_mass);
  shot.cue.restitution =
      parse_number("--tip-restitution", o.tip_restitution, CueStrike{}.restitution);
  scene.shots = {shot};
  try {
    return parse_scene(to_json_text(scene), scene_source_name(o.scene));
  } catch (const SceneError& error) {
    const std::string& path = error.details().path;
    if (path.rfind("shots[0]", 0) == 0) {
      std::string value = error.details().value;  // (a name comes quoted)
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
        value = value.substr(1, value.size() - 2);
      }
      throw UsageError(option_of(path), value, error.details().problem);
    }
    throw;
  }
}

void write_picture(const ShotOptions& o, const Scene& scene, const SceneWorld& sw,
                   const TrailRecorder& paths) {
  PictureStyle style;
  style.mode = scene_gives_colours(scene) ? ColourMode::name : ColourMode::speed;
  style.top_speed = 1.0;
  style.name_colours = named_ball_colours(sw.scene, sw.scene.balls, o.scene);
  ViewBox seen = balls_box(sw);
  seen.add(paths.extent(sw.world.time()));
  frame_picture(style, scene, seen, std::nullopt, false);
  style.title = std::filesystem::path(scene_source_name(o.scene)).filename().string();
  style.trails = &paths;
  const ScenePicture picture = draw_scene(sw, style);
  const PictureFile file =
      encode_picture(picture, o.out.ends_with(".svg"), kPictureWidth, std::nullopt);
  if (const auto problem = write_output(o.out, file.bytes)) throw std::runtime_error(*problem);
}

int run(const ShotOptions& o) {
  if (o.ball.empty()) throw UsageError("--ball", "", "name the ball the cue strikes");
  if (o.speed.empty()) throw UsageError("--speed", "", "give the cue's speed");
  if (!o.out.empty() && !o.out.ends_with(".png") && !o.out.ends_with(".svg")) {
    throw UsageError("--out", o.out, "the picture's name must end in .png or .svg");
  }
  const NamedOutput outputs[] = {{"--events", &o.events}, {"--out", &o.out}, {"--save", &o.save}};
  check_distinct_outputs(outputs);
  const Scene scene = scene_with_shot(o);
  SceneWorld sw = make_world(scene);
  const StopOnSignals stop_on_signals;
  stop_world_on_signals(sw.world);
  const BallDirectory directory(sw);
  const std::size_t wall_offset = scene.world.boundary == Boundary::box ? 4 : 0;
  std::optional<EventWriter> events;
  if (!o.events.empty()) {
    events.emplace();
    if (auto problem = events->open(o.events)) throw std::runtime_error(*problem);
  }
  TrailRecorder paths(sw, std::numeric_limits<double>::infinity());
  paths.record(sw, {});
  std::vector<ContactEvent> contacts;
  std::uint64_t ball_ball = 0;
  std::uint64_t cushions = 0;
  std::uint64_t potted = 0;
  std::uint64_t changes = 0;
  double last_event = 0.0;  // world time of the last contact, potting or change of state
  const auto resting = [&] {
    return sw.world.at_rest() && sw.shots_taken == sw.scene.shots.size();
  };
  // Until rest, in steps of kPathStep for the picture's paths (the run is the same however it
  // is cut: docs/engine.md).
  do {
    contacts.clear();
    static_cast<void>(run_scene_until(sw, sw.world.time() + kPathStep, &contacts));
    paths.record(sw, contacts);
    for (const ContactEvent& c : contacts) {
      ++(c.kind == ContactKind::ball_ball ? ball_ball : cushions);
      last_event = std::max(last_event, c.time);
    }
    for (const SensorEvent& e : sw.sensor_events) {
      potted += e.removed ? 1U : 0U;
      last_event = std::max(last_event, e.time);
    }
    for (const MotionEvent& e : sw.motion_events) last_event = std::max(last_event, e.time);
    changes += sw.motion_events.size();
    if (events) events->write(contacts, directory, sw, wall_offset);
  } while (!resting() && sw.world.stop_reason() != StopReason::interrupted);
  if (events) {
    if (auto problem = events->commit()) throw std::runtime_error(*problem);
  }
  if (!o.out.empty()) write_picture(o, scene, sw, paths);
  if (!o.save.empty()) {
    if (auto problem = write_output(o.save, to_json_text(capture_scene(sw)))) {
      throw std::runtime_error(*problem);
    }
  }
  const bool interrupted = sw.world.stop_reason() == StopReason::interrupted;
  // At rest since the last event (the run itself ends at the step after it).
  const double rest_time = interrupted ? sw.time() : sw.start_time + last_event;
  std::size_t on_table = 0;
  for (const BallId id : sw.balls) on_table += id.is_null() ? 0U : 1U;
  if (o.json) {
    nlohmann::ordered_json out;
    out["scene"] = scene_source_name(o.scene);
    out["start_time"] = scene.time;
    out["rest_time"] = rest_time;
    out["at_rest"] = !interrupted;
    out["ball_ball"] = ball_ball;
    out["ball_cushion"] = cushions;
    out["potted"] = potted;
    out["state_changes"] = changes;
    out["balls_on_table"] = on_table;
    (o.events == "-" || o.save == "-" ? std::cerr : std::cout) << out.dump() << '\n';
  } else if (!o.quiet) {
    // An output written to standard output keeps it to itself.
    std::ostream& report = o.events == "-" || o.save == "-" ? std::cerr : std::cout;
    report << "shot " << o.ball << " at " << readable(scene.time) << " " << scene.units.time
           << (interrupted ? ": stopped" : ": every ball rests")
           << " at t = " << readable(rest_time) << " after " << ball_ball << " ball contacts, "
           << cushions << " cushions, " << potted << " potted, " << changes
           << " changes of state\n";
  }
  if (interrupted) {
    std::cerr << "carom shot: " << StopOnSignals::what() << " at t = " << readable(sw.time())
              << "; the outputs are complete up to there\n";
    return StopOnSignals::exit_code();
  }
  return kExitSuccess;
}

int run_reporting_errors(const ShotOptions& o) {
  try {
    return run(o);
  } catch (const SceneError& error) {
    std::cerr << "carom shot: error: " << error.what() << '\n';
    return kExitUsage;
  } catch (const UsageError&) {
    throw;
  } catch (const std::runtime_error& error) {
    std::cerr << "carom shot: error: " << error.what() << '\n';
    return kExitFailure;
  }
}

}  // namespace

Command add_shot_command(CLI::App& app) {
  auto options = std::make_shared<ShotOptions>();
  CLI::App* shot = app.add_subcommand(
      "shot", "Strike a ball of a pool scene with the cue and run until every ball rests");
  shot->footer(
      "The scene must be on a table (world.table, docs/pool.md). The cue strikes --ball at the\n"
      "scene's time, in place of the shots the scene holds, and the run goes on until every\n"
      "ball rests. Lengths and times are the scene's; angles in radians.\n"
      "  --events FILE   every contact, potting and change of motion state as JSON lines\n"
      "                  (as carom run --events writes them).\n"
      "  --out FILE      the table at rest with every ball's path (.png or .svg).\n"
      "  --save FILE     the end state as a scene.\n\n"
      "Examples:\n"
      "  carom shot examples/billiards.json --ball cue --speed 5 --height 0.01 --out break.png\n"
      "  carom shot examples/billiards.json --ball cue --speed 2 --direction 0.3 --side 0.012 "
      "--events - --quiet");
  shot->add_option("SCENE", options->scene, "Scene file on a table; - stdin")->required();
  shot->add_option("--ball", options->ball, "The ball the cue strikes, by name")->type_name("NAME");
  shot->add_option("--speed", options->speed, "The cue's speed (>= 0)")->type_name("V");
  shot->add_option("--direction", options->direction, "The cue's heading, radians")
      ->type_name("RAD");
  shot->add_option("--elevation", options->elevation, "The cue's tilt, radians in [0, pi/2)")
      ->type_name("RAD");
  shot->add_option("--side", options->side, "The tip's offset right of the centre")->type_name("D");
  shot->add_option("--height", options->height, "The tip's offset above the centre")
      ->type_name("D");
  shot->add_option("--cue-mass", options->cue_mass, "The cue's mass (0.54)")->type_name("M");
  shot->add_option("--tip-restitution", options->tip_restitution, "Tip against ball (1)")
      ->type_name("E");
  shot->add_option("--events", options->events, "Write the events to FILE (JSON lines)")
      ->type_name("FILE");
  shot->add_option("--out", options->out, "Draw the table and the paths to FILE")
      ->type_name("FILE");
  shot->add_option("--save", options->save, "Write the end state to FILE as a scene")
      ->type_name("FILE");
  shot->add_flag("--json", options->json, "A summary as one JSON object");
  shot->add_flag("--quiet", options->quiet, "No closing line");
  return {shot, [options] { return run_reporting_errors(*options); }};
}

}  // namespace carom::cli
