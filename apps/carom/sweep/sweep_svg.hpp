// carom tool: the picture of a `carom sweep` case, drawn the way the tutorial draws two moving
// balls: where they start and how they move, the relative movement v3, where they touch, each
// movement split along the line of centres and across it, and how they leave.
#pragma once

#include <string>

#include "sweep/sweep_case.hpp"

namespace carom::cli {

// A self-contained SVG document with a title, the picture and a legend.
[[nodiscard]] std::string sweep_svg(const SweepCase& sweep_case, const SweepOutcome& outcome);

}  // namespace carom::cli
