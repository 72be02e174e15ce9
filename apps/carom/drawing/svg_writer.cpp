#include "drawing/svg_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace carom::cli {
namespace {

constexpr double kTitleFontSize = 1.2 * kFontSize;
constexpr double kLegendFontSize = 0.875 * kFontSize;
constexpr double kLineSpacing = 1.6;          // baseline to baseline, in font sizes
constexpr double kPadding = 1.5 * kFontSize;  // between the canvas edge and any text
constexpr double kMargin = 3.0 * kFontSize;   // around a picture: room for labels sticking out
// Above a panel's caption: a blank line's worth, so each panel reads as its own part.
constexpr double kCaptionSpace = 2.0 * kLineSpacing * kFontSize;
// Legend layout, in legend font sizes: the mark's width, the space before the text and after
// it, and the radius of a disc mark.
constexpr double kLegendMarkWidth = 2.6;
constexpr double kLegendTextGap = 0.6;
constexpr double kLegendColumnGap = 1.0;
constexpr double kLegendDiscRadius = 0.45;
// A short legend reads best as one column; a long one in two keeps the figure from growing tall.
constexpr std::size_t kLegendOneColumnMost = 4;
constexpr std::size_t kLegendColumns = 2;

}  // namespace

struct SvgFigure::Frame {
  // The smallest box around a panel's shapes, in world coordinates.
  struct Bounds {
    double min_x = std::numeric_limits<double>::infinity();
    double min_y = std::numeric_limits<double>::infinity();
    double max_x = -std::numeric_limits<double>::infinity();
    double max_y = -std::numeric_limits<double>::infinity();

    void add(Vec2 p, double reach = 0.0) {
      min_x = std::min(min_x, p.x - reach);
      min_y = std::min(min_y, p.y - reach);
      max_x = std::max(max_x, p.x + reach);
      max_y = std::max(max_y, p.y + reach);
    }
    [[nodiscard]] bool empty() const { return !(min_x <= max_x); }
    // Half the box's sides: halves of finite numbers subtract without overflow, so a box spanning
    // most of the double range still has a size.
    [[nodiscard]] double half_width() const { return max_x * 0.5 - min_x * 0.5; }
    [[nodiscard]] double half_height() const { return max_y * 0.5 - min_y * 0.5; }
  };

  Bounds world;
  double scale = 1.0;
  Vec2 origin;  // where the world box's top-left corner lands

  // World coordinates (y up) to screen coordinates (y down), through halves (see Bounds).
  [[nodiscard]] Vec2 operator()(Vec2 p) const {
    return {origin.x + (p.x * 0.5 - world.min_x * 0.5) * (2.0 * scale),
            origin.y + (world.max_y * 0.5 - p.y * 0.5) * (2.0 * scale)};
  }
  [[nodiscard]] double width() const { return world.half_width() * (2.0 * scale); }
  [[nodiscard]] double height() const { return world.half_height() * (2.0 * scale); }
};

// The spot that covers fewest obstacles; the earliest wins a tie, so spots go best first.
PlacedText SvgFigure::place_label(const Label& label, const Frame& frame,
                                  const Obstacles& obstacles) {
  PlacedText best;
  int fewest = std::numeric_limits<int>::max();
  for (const LabelSpot& spot : label.spots) {
    const PlacedText text = place_text(frame(spot.at), Vec2{spot.away.x, -spot.away.y}, label.text);
    const int covered = obstacles.collisions(text.box);
    if (covered < fewest) {
      best = text;
      fewest = covered;
    }
    if (covered == 0) break;
  }
  return best;
}

SvgFigure::Panel& SvgFigure::current_panel() {
  if (panels_.empty()) panels_.emplace_back();
  return panels_.back();
}

void SvgFigure::panel(std::string caption) {
  panels_.push_back({std::move(caption), {}, {}, std::nullopt});
}

void SvgFigure::view(Vec2 lower, Vec2 upper) {
  if (!is_finite(lower) || !is_finite(upper) || !(lower.x < upper.x && lower.y < upper.y)) return;
  current_panel().shown = Shown{lower, upper};
}

void SvgFigure::circle(Vec2 center, double radius, const Pen& pen, std::string fill) {
  if (!is_finite(center) || !std::isfinite(radius)) return;
  current_panel().shapes.emplace_back(Circle{center, radius, pen, std::move(fill)});
}

void SvgFigure::line(Vec2 from, Vec2 to, const Pen& pen) {
  if (!is_finite(from) || !is_finite(to)) return;
  current_panel().shapes.emplace_back(Line{from, to, pen, false, ""});
}

void SvgFigure::polyline(std::vector<Vec2> points, const Pen& pen) {
  std::erase_if(points, [](Vec2 p) { return !is_finite(p); });
  if (points.size() < 2) return;
  current_panel().shapes.emplace_back(Polyline{std::move(points), pen});
}

void SvgFigure::arrow(Vec2 from, Vec2 to, const Pen& pen, std::string outline) {
  if (from == to || !is_finite(from) || !is_finite(to)) return;
  current_panel().shapes.emplace_back(Line{from, to, pen, true, std::move(outline)});
}

void SvgFigure::dot(Vec2 at, std::string colour) {
  if (!is_finite(at)) return;
  current_panel().shapes.emplace_back(Dot{at, std::move(colour)});
}

void SvgFigure::label(std::vector<LabelSpot> spots, std::string text, std::string colour) {
  std::erase_if(spots, [](const LabelSpot& s) { return !is_finite(s.at) || !is_finite(s.away); });
  if (!spots.empty()) {
    current_panel().labels.push_back({std::move(spots), std::move(text), std::move(colour)});
  }
}

void SvgFigure::label(Vec2 at, Vec2 away, std::string text, std::string colour) {
  label(std::vector<LabelSpot>{{at, away}}, std::move(text), std::move(colour));
}

void SvgFigure::heading(std::string text) { headings_.push_back(std::move(text)); }

void SvgFigure::legend(LegendMark mark, const Pen& pen, std::string text, std::string fill) {
  legend_.push_back({mark, pen, std::move(text), std::move(fill)});
}

void SvgFigure::render_panel(std::string& out, const Panel& panel, const Frame& frame,
                             std::size_t number) {
  Obstacles obstacles;
  if (panel.shown) {
    const Vec2 top_left = frame({panel.shown->lower.x, panel.shown->upper.y});
    out += fmt::format(
        R"(<clipPath id="panel{}"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>)", number,
        svg_number(top_left.x), svg_number(top_left.y), svg_number(frame.width()),
        svg_number(frame.height()));
    out += '\n';
    out += fmt::format(R"svg(<g class="panel" clip-path="url(#panel{})">)svg", number);
    out += '\n';
  } else {
    out += "<g class=\"panel\">\n";
  }
  for (const Shape& shape : panel.shapes) {
    if (const auto* c = std::get_if<Circle>(&shape)) {
      svg_circle(out, frame(c->center), c->radius * frame.scale, c->pen, c->fill);
      obstacles.add_circle(frame(c->center), c->radius * frame.scale);
    } else if (const auto* l = std::get_if<Line>(&shape)) {
      if (l->arrow_head) {
        svg_arrow(out, frame(l->from), frame(l->to), l->pen, l->outline);
      } else {
        svg_line(out, frame(l->from), frame(l->to), l->pen);
      }
      obstacles.add_segment(frame(l->from), frame(l->to));
    } else if (const auto* d = std::get_if<Dot>(&shape)) {
      svg_dot(out, frame(d->at), d->colour);
      obstacles.add_segment(frame(d->at), frame(d->at));
    } else if (const auto* p = std::get_if<Polyline>(&shape)) {
      std::vector<Vec2> on_screen;
      on_screen.reserve(p->points.size());
      for (const Vec2 point : p->points) on_screen.push_back(frame(point));
      svg_polyline(out, on_screen, p->pen);
      for (std::size_t k = 1; k < on_screen.size(); ++k) {
        obstacles.add_segment(on_screen[k - 1], on_screen[k]);
      }
    }
  }
  out += fmt::format(
      R"(<g stroke="white" stroke-width="{}" stroke-linejoin="round" paint-order="stroke">)",
      svg_number(kHaloWidth * kFontSize));
  out += '\n';
  for (const Label& l : panel.labels) {
    const PlacedText text = place_label(l, frame, obstacles);
    obstacles.add_box(text.box);
    out += fmt::format(R"(<g fill="{}">)", l.colour);
    svg_text(out, text.baseline, text.anchor, kFontSize, true, l.text);
    out += "</g>\n";
  }
  out += "</g>\n</g>\n";
}

std::size_t SvgFigure::legend_columns() const {
  return legend_.size() > kLegendOneColumnMost ? kLegendColumns : 1;
}

double SvgFigure::legend_width() const {
  std::size_t longest = 0;
  for (const LegendEntry& e : legend_) longest = std::max(longest, count_characters(e.text));
  const double column = (kLegendMarkWidth + kLegendTextGap + kLegendColumnGap +
                         kAverageCharWidth * static_cast<double>(longest)) *
                        kLegendFontSize;
  return column * static_cast<double>(legend_columns());
}

double SvgFigure::legend_height() const {
  const std::size_t rows = (legend_.size() + legend_columns() - 1) / legend_columns();
  return static_cast<double>(rows) * kLineSpacing * kLegendFontSize;
}

void SvgFigure::render_legend(std::string& out, Vec2 origin, double width) const {
  const double row_height = kLineSpacing * kLegendFontSize;
  const std::size_t columns = legend_columns();
  const std::size_t rows = (legend_.size() + columns - 1) / columns;
  const double column_width = width / static_cast<double>(columns);
  const double mark_width = kLegendMarkWidth * kLegendFontSize;
  out += "<g class=\"legend\">\n";
  for (std::size_t i = 0; i < legend_.size(); ++i) {
    const LegendEntry& e = legend_[i];
    // Column by column, so the entries read top to bottom as they were added.
    const std::size_t column = i / rows;
    const std::size_t row = i % rows;
    const Vec2 mark_left{origin.x + static_cast<double>(column) * column_width,
                         origin.y + (static_cast<double>(row) + 0.5) * row_height};
    const Vec2 mark_right = mark_left + Vec2{mark_width, 0.0};
    const Vec2 mark_middle = (mark_left + mark_right) / 2.0;
    switch (e.mark) {
      case LegendMark::kDisc:
      case LegendMark::kRing:
        svg_circle(out, mark_middle, kLegendDiscRadius * kLegendFontSize, e.pen, e.fill);
        break;
      case LegendMark::kLine:
        svg_line(out, mark_left, mark_right, e.pen);
        break;
      case LegendMark::kArrow:
        svg_arrow(out, mark_left, mark_right, e.pen);
        break;
      case LegendMark::kDot:
        svg_dot(out, mark_middle, e.pen.colour);
        break;
    }
    const Vec2 text_at =
        mark_right + Vec2{kLegendTextGap * kLegendFontSize, kBaselineDrop * kLegendFontSize};
    svg_text(out, text_at, TextAnchor::kStart, kLegendFontSize, false, e.text);
  }
  out += "</g>\n";
}

std::vector<SvgFigure::Frame> SvgFigure::fit_panels() const {
  std::vector<Frame> frames(panels_.size());
  double largest_half = 0.0;
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    Frame::Bounds& world = frames[i].world;
    if (const std::optional<Shown>& shown = panels_[i].shown) {
      world.add(shown->lower);
      world.add(shown->upper);
      largest_half = std::max({largest_half, world.half_width(), world.half_height()});
      continue;
    }
    for (const Shape& shape : panels_[i].shapes) {
      if (const auto* c = std::get_if<Circle>(&shape)) world.add(c->center, c->radius);
      if (const auto* l = std::get_if<Line>(&shape)) {
        world.add(l->from);
        world.add(l->to);
      }
      if (const auto* d = std::get_if<Dot>(&shape)) world.add(d->at);
      if (const auto* p = std::get_if<Polyline>(&shape)) {
        for (const Vec2 point : p->points) world.add(point);
      }
    }
    for (const Label& l : panels_[i].labels) world.add(l.spots.front().at);
    if (world.empty()) world.add(Vec2{});
    largest_half = std::max({largest_half, world.half_width(), world.half_height()});
  }
  // A picture of one point, or of sizes too small to divide by, still renders (as a point).
  const double fitted = kPictureSide * 0.5 / largest_half;
  const double scale = std::isfinite(fitted) && fitted > 0.0 ? fitted : 1.0;
  for (Frame& frame : frames) frame.scale = scale;
  return frames;
}

std::string SvgFigure::render() const {
  std::vector<Frame> frames = fit_panels();
  double widest = kPictureSide;
  for (const Frame& frame : frames) widest = std::max(widest, frame.width());
  const double canvas_width = std::max(widest + 2.0 * kMargin, legend_width() + 2.0 * kPadding);

  // Top to bottom: headings, panels (each under its caption), legend; y is the pen's height.
  std::string body;
  double y = kPadding;
  // Headings wrap at spaces so that none runs past the canvas's right edge.
  for (std::size_t i = 0; i < headings_.size(); ++i) {
    const bool title = i == 0;
    const double size = title ? kTitleFontSize : kFontSize;
    const std::vector<std::string> lines =
        wrap_words(headings_[i], characters_in(canvas_width - 2.0 * kPadding, size, title));
    for (std::size_t k = 0; k < lines.size(); ++k) {
      y += title && k == 0 ? kTitleFontSize : kLineSpacing * size;
      svg_text(body, {kPadding, y}, TextAnchor::kStart, size, title, lines[k]);
    }
  }
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    if (!panels_[i].caption.empty()) {
      y += kCaptionSpace;
      svg_text(body, {kPadding, y}, TextAnchor::kStart, kFontSize, true, panels_[i].caption);
    }
    Frame& frame = frames[i];
    frame.origin = {(canvas_width - frame.width()) / 2.0, y + kMargin};
    render_panel(body, panels_[i], frame, i);
    y += kMargin + frame.height() + kMargin;
  }
  render_legend(body, {kPadding, y}, canvas_width - 2.0 * kPadding);
  const double canvas_height = y + legend_height() + kPadding;

  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" )"
      R"(font-family="DejaVu Sans, Helvetica, Arial, sans-serif">)",
      svg_number(canvas_width), svg_number(canvas_height));
  out += '\n';
  if (!headings_.empty()) out += "<title>" + escape_xml(headings_.front()) + "</title>\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out += body;
  out += "</svg>\n";
  return out;
}

}  // namespace carom::cli
