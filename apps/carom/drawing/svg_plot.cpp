#include "drawing/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "drawing/label_placement.hpp"
#include "drawing/svg_elements.hpp"
#include "drawing/value_range.hpp"
#include "options/readable_number.hpp"

namespace carom::cli {
namespace {

constexpr double kWidth = 760.0;
constexpr double kHeight = 460.0;
constexpr double kLeft = 96.0;  // room for the y ticks' labels and the axis name
constexpr double kRight = 24.0;
constexpr double kTop = 78.0;  // a title and a subtitle of one line each
constexpr double kPlotTitleSize = 1.2 * kFontSize;
constexpr double kPlotSubtitleSize = 0.875 * kFontSize;
constexpr double kPlotTitleLine = 1.25 * kPlotTitleSize;  // baseline to baseline
constexpr double kPlotSubtitleLine = 1.3 * kPlotSubtitleSize;
constexpr double kBottom = 64.0;
constexpr int kTicks = 6;
constexpr double kPad = 1.5 * kFontSize;
constexpr double kTickLength = 5.0;
constexpr double kLegendRow = 1.5 * kFontSize;
constexpr double kLegendLine = 28.0;
const Pen kAxisPen{"#000000", 0.5, false};
const Pen kGridPen{"#dddddd", 0.5, false};

ValueRange y_range(const TimePlotSpec& spec) {
  ValueRange r;
  for (const TimePlotSeries& s : spec.series) {
    for (const Vec2 p : s.points) r.add(p.y);
  }
  if (r.empty()) return {0.0, 1.0};
  if (spec.y_from_zero) r.add(0.0);
  const double largest = std::max(std::abs(r.low), std::abs(r.high));
  const double smallest = largest > 0.0 ? spec.smallest_relative_range * largest : 1.0;
  if (r.high - r.low < smallest) {
    const double middle = r.low * 0.5 + r.high * 0.5;
    r = {middle - smallest * 0.5, middle + smallest * 0.5};
    if (spec.y_from_zero && r.low < 0.0 && middle >= 0.0) r = {0.0, smallest};
  }
  return r;
}

}  // namespace

std::vector<double> round_ticks(double low, double high, int count) {
  if (!(high > low) || count < 1) return {low};
  const double raw = (high - low) / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power * 10.0;
  for (const double m : {1.0, 2.0, 5.0}) {
    if (power * m >= raw) {
      step = power * m;
      break;
    }
  }
  // A hair of slack at both ends, so that rounding in low / step does not drop an end tick.
  constexpr double kSlack = 1e-9;
  std::vector<double> ticks;
  const auto first = static_cast<long long>(std::ceil(low / step - kSlack));
  const auto last = static_cast<long long>(std::floor(high / step + kSlack));
  for (long long k = first; k <= last; ++k) {
    ticks.push_back(k == 0 ? 0.0 : static_cast<double>(k) * step);
  }
  return ticks;
}

std::string plot_svg(const TimePlotSpec& spec) {
  ValueRange xr;
  for (const TimePlotSeries& s : spec.series) {
    for (const Vec2 p : s.points) xr.add(p.x);
  }
  if (xr.empty() || !(xr.high > xr.low))
    xr = {xr.empty() ? 0.0 : xr.low, (xr.empty() ? 0.0 : xr.low) + 1.0};
  const ValueRange yr = y_range(spec);
  // The title and subtitle wrap at spaces to stay inside the picture; each line beyond the first
  // moves the plot down, and the picture grows as much.
  const std::vector<std::string> title =
      wrap_words(spec.title, characters_in(kWidth - 2.0 * kPad, kPlotTitleSize, true));
  const std::vector<std::string> subtitle =
      wrap_words(spec.subtitle, characters_in(kWidth - 2.0 * kPad, kPlotSubtitleSize, false));
  const auto extra_lines = [](const std::vector<std::string>& lines) {
    return lines.size() > 1 ? static_cast<double>(lines.size() - 1) : 0.0;
  };
  const double title_extra = extra_lines(title) * kPlotTitleLine;
  const double extra = title_extra + extra_lines(subtitle) * kPlotSubtitleLine;
  const double top = kTop + extra;
  const double height = kHeight + extra;
  const double plot_w = kWidth - kLeft - kRight;
  const double plot_h = kHeight - kTop - kBottom;
  const auto at = [&](Vec2 p) {
    return Vec2{kLeft + (p.x - xr.low) / (xr.high - xr.low) * plot_w,
                top + plot_h - (p.y - yr.low) / (yr.high - yr.low) * plot_h};
  };

  std::string body;
  for (std::size_t k = 0; k < title.size(); ++k) {
    svg_text(body, {kPad, 1.6 * kFontSize + static_cast<double>(k) * kPlotTitleLine},
             TextAnchor::kStart, kPlotTitleSize, true, title[k]);
  }
  for (std::size_t k = 0; k < subtitle.size(); ++k) {
    svg_text(body,
             {kPad, 3.0 * kFontSize + title_extra + static_cast<double>(k) * kPlotSubtitleLine},
             TextAnchor::kStart, kPlotSubtitleSize, false, subtitle[k]);
  }

  for (const double t : round_ticks(xr.low, xr.high, kTicks)) {
    const Vec2 bottom = at({t, yr.low});
    svg_line(body, {bottom.x, top}, {bottom.x, top + plot_h}, kGridPen);
    svg_line(body, bottom, bottom + Vec2{0.0, kTickLength}, kAxisPen);
    svg_text(body, bottom + Vec2{0.0, kTickLength + kFontSize}, TextAnchor::kMiddle,
             0.875 * kFontSize, false, readable(t));
  }
  for (const double t : round_ticks(yr.low, yr.high, kTicks)) {
    const Vec2 left = at({xr.low, t});
    svg_line(body, {kLeft, left.y}, {kLeft + plot_w, left.y}, kGridPen);
    svg_line(body, left, left - Vec2{kTickLength, 0.0}, kAxisPen);
    svg_text(body, left + Vec2{-kTickLength - 3.0, 0.35 * kFontSize}, TextAnchor::kEnd,
             0.875 * kFontSize, false, readable(t));
  }
  svg_line(body, {kLeft, top + plot_h}, {kLeft + plot_w, top + plot_h}, kAxisPen);
  svg_line(body, {kLeft, top}, {kLeft, top + plot_h}, kAxisPen);
  svg_text(body, {kLeft + plot_w / 2.0, height - 0.8 * kFontSize}, TextAnchor::kMiddle, kFontSize,
           false, spec.x_label);
  body += fmt::format(R"svg(<g transform="translate({},{}) rotate(-90)">)svg",
                      svg_number(kFontSize * 1.2), svg_number(top + plot_h / 2.0));
  svg_text(body, {0.0, 0.0}, TextAnchor::kMiddle, kFontSize, false, spec.y_label);
  body += "</g>\n";

  for (const TimePlotSeries& s : spec.series) {
    std::vector<Vec2> screen;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      if (s.steps && i > 0) screen.push_back(at({s.points[i].x, s.points[i - 1].y}));
      screen.push_back(at(s.points[i]));
    }
    if (screen.size() >= 2) svg_polyline(body, screen, Pen{s.colour, 1.0, false});
  }
  // The legend, top right inside the plot.
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const TimePlotSeries& s = spec.series[i];
    const double y = top + kLegendRow * (static_cast<double>(i) + 1.0);
    const double x = kLeft + plot_w - 12.0 * kFontSize;
    svg_line(body, {x, y - 0.3 * kFontSize}, {x + kLegendLine, y - 0.3 * kFontSize},
             Pen{s.colour, 1.0, false});
    svg_text(body, {x + kLegendLine + 6.0, y}, TextAnchor::kStart, 0.875 * kFontSize, false,
             s.name);
  }

  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" )"
      R"(font-family="DejaVu Sans, Helvetica, Arial, sans-serif">)",
      svg_number(kWidth), svg_number(height));
  out += "\n<title>" + escape_xml(spec.title) + "</title>\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out += body;
  out += "</svg>\n";
  return out;
}

}  // namespace carom::cli
