// carom tool: SVG elements in screen coordinates (pixels, y down), the building blocks of
// SvgFigure. Sizes here are the figure's fixed proportions; see svg_elements.cpp.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "carom/vec2.hpp"

namespace carom::cli {

// How a line is drawn. width counts the figure's line widths (1 is a thin line, 2 a bold one).
struct Pen {
  std::string colour = "black";
  double width = 1.0;
  bool dashed = false;
};

// The figure's base sizes in pixels (SVG user units): every size is a fixed part of the
// picture's side, so the figure keeps its proportions whatever the world's scale.
inline constexpr double kPictureSide = 640.0;  // the longer side of the area a picture fills
inline constexpr double kLineWidth = kPictureSide / 320.0;  // thin, yet visible scaled down
inline constexpr double kFontSize = kPictureSide / 40.0;    // readable, small beside the balls
// An arrow head's half width, as a share of its length: a slim head (the PNG pictures too).
inline constexpr double kHeadHalfWidthShare = 0.4;
// An arrow's outline on each side, in line widths (the PNG pictures too): a thin band, enough to
// part the arrow from a ball of its own colour.
inline constexpr double kOutlineWidth = 1.0;

enum class TextAnchor { kStart, kMiddle, kEnd };

// Each appends one element (or two, for an arrow) and a newline to out.
void svg_circle(std::string& out, Vec2 center, double radius, const Pen& pen,
                std::string_view fill);
void svg_line(std::string& out, Vec2 from, Vec2 to, const Pen& pen);
// Lines joining consecutive points, as one <polyline> element.
void svg_polyline(std::string& out, std::span<const Vec2> points, const Pen& pen);
// A line with a head at `to`; nothing for a zero-length arrow. With an outline colour the arrow
// is drawn over a band of that colour, kOutlineWidth wider on each side, so that it shows on a
// fill of its own colour.
void svg_arrow(std::string& out, Vec2 from, Vec2 to, const Pen& pen, std::string_view outline = {});
// A small filled dot: a point, not a ball.
void svg_dot(std::string& out, Vec2 at, std::string_view colour);
// baseline is where the text's baseline meets its anchor.
void svg_text(std::string& out, Vec2 baseline, TextAnchor anchor, double size, bool bold,
              std::string_view text);

// A coordinate with two decimals: hundredths of a pixel are invisible.
[[nodiscard]] std::string svg_number(double value);
// text with &, <, > and " escaped, for element content and attribute values.
[[nodiscard]] std::string escape_xml(std::string_view text);

}  // namespace carom::cli
