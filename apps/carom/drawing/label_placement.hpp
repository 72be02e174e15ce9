// carom tool: where a label's text goes on the screen, and how much of a drawing it would cover,
// so a figure can pick the spot that hides the fewest lines.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "carom/vec2.hpp"
#include "drawing/svg_elements.hpp"

namespace carom::cli {

// Text centred on a point has its baseline this far below it, in font sizes: about half the
// height of a capital letter.
inline constexpr double kBaselineDrop = 0.35;
// The white outline behind label text, in font sizes: wide enough to part text from a line.
inline constexpr double kHaloWidth = 0.25;
// The average width of a character, in font sizes, of plain and of bold text in a sans-serif
// face: enough to size a legend's columns and to wrap a line before the picture's edge.
inline constexpr double kAverageCharWidth = 0.6;
inline constexpr double kBoldCharWidth = 0.65;

// An axis-aligned box on the screen (pixels, y down).
struct TextBox {
  Vec2 min;
  Vec2 max;
};

// A label's text as it will be drawn: its anchor, baseline, and the box it covers.
struct PlacedText {
  Vec2 baseline;
  TextAnchor anchor = TextAnchor::kMiddle;
  TextBox box;
};

// Bold text of kFontSize put next to the screen point at, moved off it in the screen direction
// away (any length; zero centres it on at).
[[nodiscard]] PlacedText place_text(Vec2 at, Vec2 away, std::string_view text);

// Characters, not bytes, of UTF-8 text: labels use a few non-ASCII letters (′, −).
[[nodiscard]] std::size_t count_characters(std::string_view utf8);

// text broken at spaces into lines of at most `most` characters; a word longer than that gets a
// line of its own. Empty text gives no lines.
[[nodiscard]] std::vector<std::string> wrap_words(std::string_view text, std::size_t most);
// How many characters of text of this font size (and weight) fit in width.
[[nodiscard]] std::size_t characters_in(double width, double font_size, bool bold);

// What is already drawn on a panel, in screen coordinates, for labels to keep clear of.
class Obstacles {
 public:
  void add_segment(Vec2 from, Vec2 to);
  // A circle's outline; its inside is free (labels sit on pale fills with a white halo).
  void add_circle(Vec2 center, double radius);
  void add_box(const TextBox& box);

  // How many of the obstacles the box touches.
  [[nodiscard]] int collisions(const TextBox& box) const;

 private:
  struct Segment {
    Vec2 from;
    Vec2 to;
  };
  struct Circle {
    Vec2 center;
    double radius;
  };
  std::vector<Segment> segments_;
  std::vector<Circle> circles_;
  std::vector<TextBox> boxes_;
};

}  // namespace carom::cli
