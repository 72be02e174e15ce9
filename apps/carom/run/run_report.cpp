#include "run/run_report.hpp"

#include <cmath>

#include "options/readable_number.hpp"

namespace carom::cli {

double RunOutcome::energy_change() const {
  return energy_before > 0.0 ? (energy_after - energy_before) / energy_before : 0.0;
}

double RunOutcome::total_energy_change() const {
  const double scale = energy_before > 0.0 ? energy_before : energy_after;
  return scale > 0.0 ? (total_energy_after() - total_energy_before()) / scale : 0.0;
}

double RunOutcome::momentum_change() const {
  const double scale = std::sqrt(2.0 * movable_mass * energy_before);
  return scale > 0.0 ? length(momentum_after - momentum_before) / scale : 0.0;
}

double RunOutcome::collisions_per_second() const {
  return wall_seconds > 0.0 ? static_cast<double>(collisions) / wall_seconds : 0.0;
}

std::string stop_reason_name(StopReason reason) {
  switch (reason) {
    case StopReason::no_more_contacts:
      return "no_more_contacts";
    case StopReason::time_limit:
      return "time_limit";
    case StopReason::interrupted:
      return "interrupted";
    case StopReason::stop_condition:
      return "stop_condition";
    case StopReason::none:
      break;
  }
  return "";
}

namespace {

// Why a run stopped short, in words.
std::string stop_text(StopReason reason) {
  switch (reason) {
    case StopReason::no_more_contacts:
      return "no contact will ever happen again";
    case StopReason::time_limit:
      return "reached --time-limit";
    case StopReason::interrupted:
      return "interrupted by a signal";
    case StopReason::stop_condition:
      return "the stop condition";
    case StopReason::none:
      break;
  }
  return "";
}

}  // namespace

std::string run_text(const RunOutcome& o) {
  // Changes of energy and momentum are drift only where the scene conserves them.
  const std::string change = o.conservative ? "drift" : "change";
  std::string text;
  text += "scene           " + o.scene + "\n";
  text += "time            " + readable(o.start_time) + " -> " + readable(o.end_time) + "\n";
  if (o.stopped != StopReason::none) text += "stopped         " + stop_text(o.stopped) + "\n";
  text += "balls           " + std::to_string(o.balls_at_start) + " -> " +
          std::to_string(o.balls_at_end) + "\n";
  text += "collisions      " + std::to_string(o.collisions) + " (ball-ball " +
          std::to_string(o.ball_ball) + ", ball-wall " + std::to_string(o.ball_wall) + ")\n";
  if (o.potted > 0) text += "potted          " + std::to_string(o.potted) + "\n";
  text += "collisions/s    " + readable_count(o.collisions_per_second()) + "\n";
  text += "wall time       " + rounded(o.wall_seconds) + " s (setup " + rounded(o.setup_seconds) +
          " s)\n";
  if (o.gravity) {
    // Gravity trades kinetic for potential energy: their sum is what elastic contacts keep.
    const std::string total_change = o.total_energy_conserved ? "drift" : "change";
    text += "kinetic energy  " + readable(o.energy_before) + " -> " + readable(o.energy_after) +
            " (change " + rounded(o.energy_change()) + ")\n";
    text += "potential       " + readable(o.potential_before) + " -> " +
            readable(o.potential_after) + "\n";
    text += "total energy    " + readable(o.total_energy_before()) + " -> " +
            readable(o.total_energy_after()) + " (" + total_change + " " +
            rounded(o.total_energy_change()) + ")\n";
  } else {
    text += "energy          " + readable(o.energy_before) + " -> " + readable(o.energy_after) +
            " (" + change + " " + rounded(o.energy_change()) + ")\n";
  }
  text += "momentum        " + readable(o.momentum_before) + " -> " + readable(o.momentum_after) +
          " (" + change + " " + rounded(o.momentum_change()) + ")\n";
  if (o.thermostat_work) text += "thermostat work " + readable(*o.thermostat_work) + "\n";
  if (o.frames > 0) text += "frames          " + std::to_string(o.frames) + "\n";
  return text;
}

nlohmann::ordered_json run_json(const RunOutcome& o) {
  nlohmann::ordered_json json;
  json["scene"] = o.scene;
  json["start_time"] = o.start_time;
  json["end_time"] = o.end_time;
  json["interrupted"] = o.interrupted;
  json["stopped"] = o.stopped == StopReason::none
                        ? nlohmann::ordered_json()
                        : nlohmann::ordered_json(stop_reason_name(o.stopped));
  json["balls_at_start"] = o.balls_at_start;
  json["balls_at_end"] = o.balls_at_end;
  json["collisions"] = o.collisions;
  json["ball_ball"] = o.ball_ball;
  json["ball_wall"] = o.ball_wall;
  json["potted"] = o.potted;
  json["collisions_per_second"] = o.collisions_per_second();
  json["wall_seconds"] = o.wall_seconds;
  json["setup_seconds"] = o.setup_seconds;
  json["energy_before"] = o.energy_before;
  json["energy_after"] = o.energy_after;
  json["conservative"] = o.conservative;
  json["energy_change"] = o.energy_change();
  json["potential_energy_before"] = o.potential_before;
  json["potential_energy_after"] = o.potential_after;
  json["total_energy_before"] = o.total_energy_before();
  json["total_energy_after"] = o.total_energy_after();
  json["total_energy_conserved"] = o.total_energy_conserved;
  json["total_energy_change"] = o.total_energy_change();
  json["momentum_before"] = {o.momentum_before.x, o.momentum_before.y};
  json["momentum_after"] = {o.momentum_after.x, o.momentum_after.y};
  json["momentum_change"] = o.momentum_change();
  json["frames"] = o.frames;
  json["thermostat_work"] =
      o.thermostat_work ? nlohmann::ordered_json(*o.thermostat_work) : nlohmann::ordered_json();
  return json;
}

}  // namespace carom::cli
