// carom tool: the result of `carom sweep` as text for people and as JSON for programs.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "sweep/sweep_case.hpp"

namespace carom::cli {

// A few plain lines; numbers rounded to 6 significant digits.
[[nodiscard]] std::string sweep_text(const SweepOutcome& outcome);

// One object with the keys hit, overlapping, t, a_at, b_at, normal, point, v3, va_after,
// vb_after and impulse; vectors are [x, y]. Every key is always there: without a hit the
// contact's keys are null. Numbers are written so that they read back to the same double.
[[nodiscard]] nlohmann::ordered_json sweep_json(const SweepOutcome& outcome);

}  // namespace carom::cli
