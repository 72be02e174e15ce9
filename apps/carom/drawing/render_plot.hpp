// carom tool: `carom render --plot`: energy, momentum or the collision rate of a run, as SVG.
#pragma once

#include <string>

#include "carom/scene.hpp"

namespace carom::cli {

enum class PlotKind { energy, momentum, rate };

// Runs the scene from its start for `until` time units and plots what was asked: the kinetic
// energy (with gravity the potential and total energy too) or the momentum (x, y and its length) at
// kPlotSamples evenly spaced times, or the contacts per time unit (ball–ball, ball–wall, potted) in
// kRateBins bins. title names the scene.
[[nodiscard]] std::string render_plot(const Scene& scene, PlotKind kind, double until,
                                      const std::string& title);

inline constexpr int kPlotSamples = 400;
inline constexpr int kRateBins = 50;

}  // namespace carom::cli
