// carom tool: a line plot as an SVG document — quantities over time for `carom render --plot`.
#pragma once

#include <string>
#include <vector>

#include "carom/vec2.hpp"

namespace carom::cli {

struct TimePlotSeries {
  std::string name;          // in the legend
  std::string colour;        // any SVG colour
  std::vector<Vec2> points;  // (x, y), x increasing
  // Drawn as steps (each y held until the next point's x), for counts per bin.
  bool steps = false;
};

struct TimePlotSpec {
  std::string title;
  std::string subtitle;
  std::string x_label;
  std::string y_label;
  std::vector<TimePlotSeries> series;
  bool y_from_zero = false;  // the y axis starts at 0 (or below, for negative values)
  // A y range narrower than this share of the largest |y| is widened to it around its middle,
  // so a conserved quantity shows as a flat line rather than as its rounding noise magnified.
  double smallest_relative_range = 1e-3;
};

// The plot with axes, ticks at round numbers, a grid and a legend.
[[nodiscard]] std::string plot_svg(const TimePlotSpec& spec);

// Tick positions at round numbers (1, 2 or 5 times a power of ten) covering [low, high], about
// `count` of them.
[[nodiscard]] std::vector<double> round_ticks(double low, double high, int count);

}  // namespace carom::cli
