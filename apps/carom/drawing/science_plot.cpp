#include "drawing/science_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "drawing/svg_writer.hpp"
#include "drawing/value_range.hpp"
#include "options/readable_number.hpp"

namespace carom::cli {
namespace {

// The plot area in the figure's own coordinates; SvgFigure scales it to the picture.
constexpr double kAreaWidth = 10.0;
constexpr double kAreaHeight = 6.5;
constexpr double kTick = 0.12;
constexpr int kTargetTicks = 6;

// A round tick spacing (1, 2 or 5 times a power of ten) giving about kTargetTicks ticks.
double tick_step(const ValueRange& range) {
  const double raw = (range.high - range.low) / kTargetTicks;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 5.0}) {
    if (factor * power >= raw) return factor * power;
  }
  return 10.0 * power;
}

// The range widened to whole ticks (and made non-empty).
ValueRange rounded(ValueRange range, double& step) {
  if (range.empty()) range = {0.0, 1.0};
  if (range.high == range.low) {
    range.low -= 0.5;
    range.high += 0.5;
  }
  step = tick_step(range);
  return {std::floor(range.low / step) * step, std::ceil(range.high / step) * step};
}

}  // namespace

std::string render_plot(const PlotSpec& spec) {
  ValueRange xs;
  ValueRange ys;
  for (const PlotSeries& series : spec.series) {
    for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
      if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) continue;
      const double bar =
          i < series.error.size() && std::isfinite(series.error[i]) ? series.error[i] : 0.0;
      xs.add(series.x[i]);
      ys.add(series.y[i] - bar);
      ys.add(series.y[i] + bar);
    }
  }
  double x_step = 1.0;
  double y_step = 1.0;
  const ValueRange x_range = rounded(xs, x_step);
  const ValueRange y_range = rounded(ys, y_step);
  const auto to_plot = [&](double x, double y) {
    return Vec2{(x - x_range.low) / (x_range.high - x_range.low) * kAreaWidth,
                (y - y_range.low) / (y_range.high - y_range.low) * kAreaHeight};
  };

  SvgFigure figure;
  figure.heading(spec.title);
  if (!spec.subtitle.empty()) figure.heading(spec.subtitle);
  const Pen axis{"black", 1.0, false};
  const Pen grid{"#dddddd", 0.5, false};
  figure.line({0.0, 0.0}, {kAreaWidth, 0.0}, axis);
  figure.line({0.0, 0.0}, {0.0, kAreaHeight}, axis);
  figure.line({kAreaWidth, 0.0}, {kAreaWidth, kAreaHeight}, grid);
  figure.line({0.0, kAreaHeight}, {kAreaWidth, kAreaHeight}, grid);
  // Ticks by index, not by adding steps, so rounding neither accumulates nor drops the last.
  const auto ticks = [](const ValueRange& range, double step) {
    return static_cast<int>(std::lround((range.high - range.low) / step));
  };
  for (int tick = 0; tick <= ticks(x_range, x_step); ++tick) {
    const double x = x_range.low + tick * x_step;
    const Vec2 at = to_plot(x, y_range.low);
    figure.line(at, at + Vec2{0.0, -kTick}, axis);
    figure.label(at + Vec2{0.0, -kTick}, {0.0, -1.0},
                 readable(std::abs(x) < 1e-12 * x_step ? 0.0 : x), "black");
  }
  for (int tick = 0; tick <= ticks(y_range, y_step); ++tick) {
    const double y = y_range.low + tick * y_step;
    const Vec2 at = to_plot(x_range.low, y);
    figure.line(at, at + Vec2{-kTick, 0.0}, axis);
    figure.label(at + Vec2{-kTick, 0.0}, {-1.0, 0.0},
                 readable(std::abs(y) < 1e-12 * y_step ? 0.0 : y), "black");
  }
  figure.label({kAreaWidth / 2.0, -0.9}, {0.0, -1.0}, spec.x_label, "black");
  figure.label({0.0, kAreaHeight + 0.3}, {1.0, 1.0}, spec.y_label, "black");

  for (const PlotSeries& series : spec.series) {
    const Pen pen{series.colour, series.points ? 1.0 : 1.5, series.dashed};
    bool have_last = false;
    Vec2 last;
    for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
      if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) {
        have_last = false;
        continue;
      }
      const Vec2 at = to_plot(series.x[i], series.y[i]);
      if (series.points) {
        figure.dot(at, series.colour);
        if (i < series.error.size() && std::isfinite(series.error[i]) && series.error[i] > 0.0) {
          figure.line(to_plot(series.x[i], series.y[i] - series.error[i]),
                      to_plot(series.x[i], series.y[i] + series.error[i]), pen);
        }
      } else if (have_last) {
        figure.line(last, at, pen);
      }
      last = at;
      have_last = true;
    }
    if (!series.label.empty()) {
      figure.legend(series.points ? LegendMark::kDot : LegendMark::kLine, pen, series.label);
    }
  }
  return figure.render();
}

}  // namespace carom::cli
