#include "commands/info_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "carom/scene.hpp"
#include "options/exit_codes.hpp"
#include "options/readable_number.hpp"
#include "run/scene_input.hpp"

namespace carom::cli {
namespace {

struct InfoOptions {
  std::string scene;
  bool json = false;
};

std::string boundary_text(const WorldDef& w) {
  if (w.boundary == Boundary::open) return "open";
  const std::string range = "[" + readable(w.lower.x) + ", " + readable(w.upper.x) + "] x [" +
                            readable(w.lower.y) + ", " + readable(w.upper.y) + "]";
  return (w.boundary == Boundary::box ? "box " : "periodic ") + range;
}

std::string ball_label(const std::vector<SceneBall>& balls, std::size_t i) {
  return "ball " + std::to_string(i) + (balls[i].name ? " \"" + *balls[i].name + "\"" : "");
}

int run(const InfoOptions& options) {
  // An invalid scene throws SceneError: main() prints it as the one message, status 2.
  const Scene scene = read_scene_argument(options.scene);
  const std::vector<SceneBall> balls = expand_balls(scene);
  const SceneSummary s = summarize(scene, balls);
  const std::size_t generated = balls.size() - scene.balls.size();

  if (options.json) {
    nlohmann::ordered_json json;
    json["scene"] = options.scene;
    json["valid"] = true;
    json["time"] = scene.time;
    json["balls"] = s.balls;
    json["generated_balls"] = generated;
    json["immovable_balls"] = s.immovable;
    json["walls"] = s.walls;
    json["pockets"] = s.pockets;
    json["sensors"] = s.sensors;
    json["moving_walls"] = s.moving_walls;
    json["packing_fraction"] =
        s.packing_fraction ? nlohmann::ordered_json(*s.packing_fraction) : nullptr;
    json["kinetic_energy"] = s.kinetic_energy;
    json["potential_energy"] = s.potential_energy;
    json["total_energy"] = s.kinetic_energy + s.potential_energy;
    json["gravity"] = {scene.world.gravity.x, scene.world.gravity.y};
    json["rest_height"] = scene.world.rest_height;
    json["growth_rate"] = scene.world.growth_rate;
    if (scene.thermostat) {
      const SceneThermostat& t = *scene.thermostat;
      json["thermostat"] = {
          {"temperature", t.temperature},
          {"interval", t.interval ? nlohmann::ordered_json(*t.interval) : nullptr},
          {"collisions", t.collisions ? nlohmann::ordered_json(*t.collisions) : nullptr}};
    } else {
      json["thermostat"] = nullptr;
    }
    json["momentum"] = {s.momentum.x, s.momentum.y};
    if (s.smallest_gap) {
      json["smallest_gap"] = {
          {"gap", *s.smallest_gap}, {"a", s.smallest_gap_a}, {"b", s.smallest_gap_b}};
    } else {
      json["smallest_gap"] = nullptr;
    }
    std::cout << json.dump() << '\n';
    return kExitSuccess;
  }
  std::string text;
  text += "scene             " + options.scene + "\n";
  if (!scene.description.empty()) text += "description       " + scene.description + "\n";
  text += "units             length " + scene.units.length + ", time " + scene.units.time +
          ", mass " + scene.units.mass + "\n";
  // Gravity is named only when set: most scenes have none, and their line stays short.
  const bool gravity = scene.world.gravity != Vec2{};
  text += "world             " + boundary_text(scene.world) + ", restitution " +
          readable(scene.world.restitution) +
          (gravity ? ", gravity " + readable(scene.world.gravity) : "") +
          (gravity && scene.world.rest_height != WorldDef{}.rest_height
               ? ", rest height " + readable(scene.world.rest_height) + " radii"
               : "") +
          (scene.world.growth_rate != 0.0
               ? ", growth rate " + readable(scene.world.growth_rate) + " a time unit"
               : "") +
          "\n";
  if (scene.thermostat) {
    const SceneThermostat& t = *scene.thermostat;
    text += "thermostat        kT " + readable(t.temperature) + " every " +
            (t.interval ? readable(*t.interval) + " " + scene.units.time
                        : std::to_string(*t.collisions) + " collisions") +
            "\n";
  }
  text += "time              " + readable(scene.time) + "\n";
  text += "balls             " + std::to_string(s.balls) + " (" + std::to_string(generated) +
          " generated, " + std::to_string(s.immovable) + " immovable)\n";
  text += "walls             " + std::to_string(s.walls) + "\n";
  text += "pockets           " + std::to_string(s.pockets) + "\n";
  if (s.sensors > 0) text += "sensors           " + std::to_string(s.sensors) + "\n";
  if (s.moving_walls > 0) text += "moving walls      " + std::to_string(s.moving_walls) + "\n";
  if (s.packing_fraction) text += "packing fraction  " + readable(*s.packing_fraction) + "\n";
  text += "kinetic energy    " + readable(s.kinetic_energy) + "\n";
  if (gravity) {
    text += "potential energy  " + readable(s.potential_energy) + "\n";
    text += "total energy      " + readable(s.kinetic_energy + s.potential_energy) + "\n";
  }
  text += "momentum          " + readable(s.momentum) + "\n";
  if (s.smallest_gap) {
    text += "smallest gap      " + readable(*s.smallest_gap) + " (" +
            ball_label(balls, s.smallest_gap_a) + " and " + ball_label(balls, s.smallest_gap_b) +
            ")\n";
  } else {
    text += "smallest gap      none (fewer than two balls, or none within two diameters)\n";
  }
  text += "valid             yes\n";
  std::cout << text;
  return kExitSuccess;
}

}  // namespace

Command add_info_command(CLI::App& app) {
  CLI::App* verb = app.add_subcommand("info", "What a scene file holds, and whether it is valid");
  verb->footer(
      "Loads and checks the scene (docs/scenes.md), places its generators' balls, and\n"
      "prints the counts, the packing fraction (in a box or periodic cell), the kinetic\n"
      "energy (with gravity, the potential and total energy too) and momentum of the\n"
      "movable balls, and the smallest gap between two balls (found with a grid: beyond\n"
      "2000 balls only pairs within two of the largest diameters are compared). An\n"
      "invalid scene gets one message naming the file, line, column, field and value,\n"
      "and exit status 2.\n\n"
      "Example:\n"
      "  carom info examples/periodic-gas.json");
  auto options = std::make_shared<InfoOptions>();
  verb->add_option("SCENE", options->scene, "Scene file (JSON)")->required();
  verb->add_flag("--json", options->json, "Print one JSON object");
  return {verb, [options] { return run(*options); }};
}

}  // namespace carom::cli
