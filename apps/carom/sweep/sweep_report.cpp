#include "sweep/sweep_report.hpp"

#include <fmt/format.h>

#include "options/readable_number.hpp"

namespace carom::cli {
namespace {

nlohmann::ordered_json pair(Vec2 v) { return nlohmann::ordered_json::array({v.x, v.y}); }

}  // namespace

std::string sweep_text(const SweepOutcome& outcome) {
  const Impact& impact = outcome.impact;
  std::string out;
  if (!impact.hit) {
    if (!impact.overlapping) {
      out += "A and B do not touch during the step\n";
    } else if (outcome.relative_move == Vec2{}) {
      out += "A and B overlap at the start and keep still relative to each other: no contact\n";
    } else {
      out += "A and B overlap at the start and are separating: no contact during the step\n";
    }
    out += fmt::format("  relative movement v3 = va - vb = {}\n", readable(outcome.relative_move));
    return out;
  }
  out += impact.overlapping
             ? "A and B overlap at the start and are approaching: contact at t = 0\n"
             : fmt::format("A and B touch at t = {} of the step\n", readable(impact.t));
  out += fmt::format("  A at {}   B at {}\n", readable(impact.a_at), readable(impact.b_at));
  out += fmt::format("  normal (A to B) {}   contact point {}\n", readable(impact.normal),
                     readable(impact.point));
  out += fmt::format("  relative movement v3 = va - vb = {}\n", readable(outcome.relative_move));
  if (outcome.bounce) {
    out += fmt::format("  velocities after: A {}   B {}   impulse {}\n",
                       readable(outcome.bounce->velocity_a), readable(outcome.bounce->velocity_b),
                       readable(outcome.bounce->impulse));
  }
  return out;
}

nlohmann::ordered_json sweep_json(const SweepOutcome& outcome) {
  const Impact& impact = outcome.impact;
  const bool bounced = impact.hit && outcome.bounce.has_value();
  nlohmann::ordered_json out;
  out["hit"] = impact.hit;
  out["overlapping"] = impact.overlapping;
  out["t"] = impact.hit ? nlohmann::ordered_json(impact.t) : nullptr;
  out["a_at"] = impact.hit ? pair(impact.a_at) : nullptr;
  out["b_at"] = impact.hit ? pair(impact.b_at) : nullptr;
  out["normal"] = impact.hit ? pair(impact.normal) : nullptr;
  out["point"] = impact.hit ? pair(impact.point) : nullptr;
  out["v3"] = pair(outcome.relative_move);
  out["va_after"] = bounced ? pair(outcome.bounce->velocity_a) : nullptr;
  out["vb_after"] = bounced ? pair(outcome.bounce->velocity_b) : nullptr;
  out["impulse"] = bounced ? nlohmann::ordered_json(outcome.bounce->impulse) : nullptr;
  return out;
}

}  // namespace carom::cli
