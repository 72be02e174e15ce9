#include "drawing/svg_elements.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace carom::cli {
namespace {

constexpr double kDotRadius = 2.0 * kLineWidth;  // clearly smaller than any arrow head
// Arrow heads grow with the line: a fixed part so thin arrows still show one, and a part per
// line width so a thick line does not swallow its head.
constexpr double kHeadFixedLength = 4.0 * kLineWidth;
constexpr double kHeadLengthPerWidth = 2.5;
// An arrow shorter than this many head lengths gets a smaller head, so some shaft still shows.
constexpr double kShortestArrowInHeads = 1.6;
// Dashes long enough to read as a line, gaps wide enough to see at a glance.
constexpr double kDashLength = 4.0 * kLineWidth;
constexpr double kDashGap = 3.0 * kLineWidth;
constexpr double kFillOpacity = 0.7;

std::string stroke_attributes(const Pen& pen) {
  std::string out = fmt::format(R"(stroke="{}" stroke-width="{}")", pen.colour,
                                svg_number(pen.width * kLineWidth));
  // Round ends look finished on solid lines; on dashed ones they would close up the gaps.
  out += pen.dashed ? fmt::format(R"( stroke-dasharray="{},{}")", svg_number(kDashLength),
                                  svg_number(kDashGap))
                    : R"( stroke-linecap="round")";
  return out;
}

std::string_view anchor_name(TextAnchor anchor) {
  switch (anchor) {
    case TextAnchor::kStart:
      return "start";
    case TextAnchor::kMiddle:
      return "middle";
    case TextAnchor::kEnd:
      return "end";
  }
  return "start";
}

}  // namespace

std::string svg_number(double value) { return fmt::format("{:.2f}", value); }

std::string escape_xml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void svg_circle(std::string& out, Vec2 center, double radius, const Pen& pen,
                std::string_view fill) {
  // Fills let what lies below show through, so overlapping balls show their overlap.
  const std::string opacity =
      fill == "none" ? "" : fmt::format(R"( fill-opacity="{}")", kFillOpacity);
  out +=
      fmt::format(R"(<circle cx="{}" cy="{}" r="{}" fill="{}"{} {}/>)", svg_number(center.x),
                  svg_number(center.y), svg_number(radius), fill, opacity, stroke_attributes(pen));
  out += '\n';
}

void svg_line(std::string& out, Vec2 from, Vec2 to, const Pen& pen) {
  out +=
      fmt::format(R"(<line x1="{}" y1="{}" x2="{}" y2="{}" {}/>)", svg_number(from.x),
                  svg_number(from.y), svg_number(to.x), svg_number(to.y), stroke_attributes(pen));
  out += '\n';
}

void svg_polyline(std::string& out, std::span<const Vec2> points, const Pen& pen) {
  std::string coordinates;
  for (const Vec2 p : points) {
    if (!coordinates.empty()) coordinates += ' ';
    coordinates += svg_number(p.x) + "," + svg_number(p.y);
  }
  out += fmt::format(R"(<polyline points="{}" fill="none" stroke-linejoin="round" {}/>)",
                     coordinates, stroke_attributes(pen));
  out += '\n';
}

// The head is a filled triangle drawn here rather than an SVG marker: a marker cannot take the
// line's colour in SVG 1.1, and the line's end would poke out beside the marker's tip.
void svg_arrow(std::string& out, Vec2 from, Vec2 to, const Pen& pen, std::string_view outline) {
  const double len = distance(from, to);
  if (!(len > 0.0)) return;
  const Vec2 direction = (to - from) / len;
  const double head_length = std::min(
      kHeadFixedLength + kHeadLengthPerWidth * pen.width * kLineWidth, len / kShortestArrowInHeads);
  const Vec2 base = to - direction * head_length;
  const Vec2 side = left_normal(direction) * (kHeadHalfWidthShare * head_length);
  // The shaft stops inside the head, so neither a gap nor a blunt line end shows at the tip.
  const Vec2 shaft_end = base + direction * (0.5 * head_length);
  const std::string head = fmt::format("M{},{} L{},{} L{},{} Z", svg_number(to.x), svg_number(to.y),
                                       svg_number(base.x + side.x), svg_number(base.y + side.y),
                                       svg_number(base.x - side.x), svg_number(base.y - side.y));
  if (!outline.empty()) {
    // The same shaft and head, wider by the outline on each side, underneath.
    svg_line(out, from, shaft_end,
             Pen{std::string(outline), pen.width + 2.0 * kOutlineWidth, false});
    out += fmt::format(
        R"(<path d="{}" fill="{}" stroke="{}" stroke-width="{}" stroke-linejoin="round"/>)", head,
        outline, outline, svg_number(2.0 * kOutlineWidth * kLineWidth));
    out += '\n';
  }
  svg_line(out, from, shaft_end, pen);
  out += fmt::format(R"(<path d="{}" fill="{}"/>)", head, pen.colour);
  out += '\n';
}

void svg_dot(std::string& out, Vec2 at, std::string_view colour) {
  out += fmt::format(R"(<circle cx="{}" cy="{}" r="{}" fill="{}"/>)", svg_number(at.x),
                     svg_number(at.y), svg_number(kDotRadius), colour);
  out += '\n';
}

void svg_text(std::string& out, Vec2 baseline, TextAnchor anchor, double size, bool bold,
              std::string_view text) {
  out += fmt::format(R"(<text x="{}" y="{}" font-size="{}"{} text-anchor="{}">{}</text>)",
                     svg_number(baseline.x), svg_number(baseline.y), svg_number(size),
                     bold ? R"( font-weight="bold")" : "", anchor_name(anchor), escape_xml(text));
  out += '\n';
}

}  // namespace carom::cli
