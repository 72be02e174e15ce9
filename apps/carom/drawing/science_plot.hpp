// carom tool: line plots of measured curves (g(r), speed distributions, MSD, Z(η)) as SVG, drawn
// with SvgFigure in a plot frame with ticks at round values.
#pragma once

#include <string>
#include <vector>

namespace carom::cli {

struct PlotSeries {
  std::string label;
  std::string colour = "black";
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> error;  // optional: an error bar of ±error[i] at each point
  bool points = false;        // dots (with error bars) instead of a line
  bool dashed = false;
};

struct PlotSpec {
  std::string title;
  std::string subtitle;
  std::string x_label;
  std::string y_label;
  std::vector<PlotSeries> series;
};

// The plot as a self-contained SVG document. Non-finite values are left out.
[[nodiscard]] std::string render_plot(const PlotSpec& spec);

}  // namespace carom::cli
