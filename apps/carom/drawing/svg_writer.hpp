// carom tool: a small SVG builder for figures in world coordinates.
//
// Shapes are given in the library's coordinates, y pointing up as in maths. render() draws
// headings, then each panel (stacked top to bottom, all at one scale so sizes compare, the
// largest fitted to a fixed size, y flipped for the screen, with a margin for labels), then a
// legend, on a white background. A shape or label with a coordinate that is not finite (an
// overflowed sum, say) is left out: there is nowhere to draw it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "carom/vec2.hpp"
#include "drawing/label_placement.hpp"
#include "drawing/svg_elements.hpp"

namespace carom::cli {

// A place for a label: next to the point at, moved off it in the direction away (any length);
// a zero direction centres the text on at.
struct LabelSpot {
  Vec2 at;
  Vec2 away;
};

// What a legend entry shows in front of its text.
enum class LegendMark { kDisc, kRing, kLine, kArrow, kDot };

class SvgFigure {
 public:
  // Starts a new panel under the previous ones, with a caption above it ("" for none). Shapes
  // and labels go to the panel started last; a figure without panel() calls has one panel.
  void panel(std::string caption);
  // The panel started last shows exactly this box of the plane (lower-left and upper-right
  // corners, a positive area), its shapes cut at the box's edge. Without it a panel shows the
  // smallest box around its shapes.
  void view(Vec2 lower, Vec2 upper);

  // A circle filled with fill ("none" for an outline only), its outline drawn with pen.
  void circle(Vec2 center, double radius, const Pen& pen, std::string fill = "none");
  void line(Vec2 from, Vec2 to, const Pen& pen);
  // Lines joining consecutive points (an arc drawn as chords, a trail); drawn as one element.
  // Fewer than two finite points draw nothing.
  void polyline(std::vector<Vec2> points, const Pen& pen);
  // A line with an arrow head at `to`, over a band of the outline colour ("" for none) so that
  // it shows on any fill. A zero-length arrow draws nothing.
  void arrow(Vec2 from, Vec2 to, const Pen& pen, std::string outline = "");
  // A small dot of fixed size: a point, not a ball.
  void dot(Vec2 at, std::string colour);
  // text at the first of spots that covers no line, circle or earlier label; where each covers
  // something, at the one that covers least (the earliest of equals). Labels are drawn above
  // every shape of their panel, with a white halo so that lines under them do not hide them.
  void label(std::vector<LabelSpot> spots, std::string text, std::string colour);
  void label(Vec2 at, Vec2 away, std::string text, std::string colour);

  // A line of text above the panels; the first is the title.
  void heading(std::string text);
  // An entry of the legend below the panels: mark drawn with pen (and fill for a disc).
  void legend(LegendMark mark, const Pen& pen, std::string text, std::string fill = "none");

  // The whole figure as a self-contained SVG document.
  [[nodiscard]] std::string render() const;

 private:
  struct Circle {
    Vec2 center;
    double radius;
    Pen pen;
    std::string fill;
  };
  struct Line {
    Vec2 from;
    Vec2 to;
    Pen pen;
    bool arrow_head;
    std::string outline;  // an arrow's
  };
  struct Dot {
    Vec2 at;
    std::string colour;
  };
  struct Polyline {
    std::vector<Vec2> points;
    Pen pen;
  };
  using Shape = std::variant<Circle, Line, Dot, Polyline>;
  struct Label {
    std::vector<LabelSpot> spots;
    std::string text;
    std::string colour;
  };
  struct Shown {
    Vec2 lower;
    Vec2 upper;
  };
  struct Panel {
    std::string caption;
    std::vector<Shape> shapes;
    std::vector<Label> labels;
    std::optional<Shown> shown;  // from view()
  };
  struct LegendEntry {
    LegendMark mark;
    Pen pen;
    std::string text;
    std::string fill;
  };

  // Where a panel lands on the screen: world coordinates to pixels (defined in the .cpp).
  struct Frame;

  Panel& current_panel();
  // Each panel's world box, all at the one scale that fits the largest into kPictureSide.
  [[nodiscard]] std::vector<Frame> fit_panels() const;
  static PlacedText place_label(const Label& label, const Frame& frame, const Obstacles& obstacles);
  // number names the panel's clip path, unique in the document.
  static void render_panel(std::string& out, const Panel& panel, const Frame& frame,
                           std::size_t number);
  // The legend with its top-left corner at origin, its columns spread over width.
  void render_legend(std::string& out, Vec2 origin, double width) const;
  [[nodiscard]] std::size_t legend_columns() const;
  [[nodiscard]] double legend_width() const;  // the least width its texts need
  [[nodiscard]] double legend_height() const;

  std::vector<Panel> panels_;
  std::vector<std::string> headings_;
  std::vector<LegendEntry> legend_;
};

}  // namespace carom::cli
