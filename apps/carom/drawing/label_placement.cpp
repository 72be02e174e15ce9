#include "drawing/label_placement.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace carom::cli {
namespace {

// Text sits this far from the point it labels: clear of a thick line's arrow head.
constexpr double kLabelGap = 0.9 * kFontSize;
// A direction within this share of horizontal puts text beside its point, not above or below.
constexpr double kSidewaysShare = 0.4;
// A label's extent, in font sizes: the heights of capitals above the baseline and of descenders
// below it.
constexpr double kCapHeight = 0.73;
constexpr double kDescent = 0.24;

TextAnchor anchor_towards(Vec2 direction) {
  if (direction.x > kSidewaysShare) return TextAnchor::kStart;
  if (direction.x < -kSidewaysShare) return TextAnchor::kEnd;
  return TextAnchor::kMiddle;
}

// Liang–Barsky clipping: the segment from `from` to `to` meets the box (or lies in it) when some
// parameter in [0, 1] survives clipping by all four sides.
bool segment_meets_box(Vec2 from, Vec2 to, const TextBox& box) {
  const Vec2 d = to - from;
  double enter = 0.0;
  double leave = 1.0;
  const std::pair<double, double> sides[] = {{-d.x, from.x - box.min.x},
                                             {d.x, box.max.x - from.x},
                                             {-d.y, from.y - box.min.y},
                                             {d.y, box.max.y - from.y}};
  for (const auto& [p, q] : sides) {
    if (p == 0.0) {
      if (q < 0.0) return false;  // parallel to this side and outside it
      continue;
    }
    const double r = q / p;
    if (p < 0.0) {
      enter = std::max(enter, r);
    } else {
      leave = std::min(leave, r);
    }
    if (enter > leave) return false;
  }
  return true;
}

// The outline meets the box when the box's nearest point is within the radius and its
// farthest corner outside it.
bool circle_meets_box(Vec2 center, double radius, const TextBox& box) {
  const Vec2 nearest{std::clamp(center.x, box.min.x, box.max.x),
                     std::clamp(center.y, box.min.y, box.max.y)};
  const double far_x = std::max(std::abs(center.x - box.min.x), std::abs(center.x - box.max.x));
  const double far_y = std::max(std::abs(center.y - box.min.y), std::abs(center.y - box.max.y));
  return distance(center, nearest) <= radius && length(Vec2{far_x, far_y}) >= radius;
}

bool boxes_meet(const TextBox& a, const TextBox& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

}  // namespace

std::size_t count_characters(std::string_view utf8) {
  constexpr unsigned char kContinuationMask = 0xC0;  // UTF-8 continuation bytes are 10xxxxxx
  constexpr unsigned char kContinuationBits = 0x80;
  return static_cast<std::size_t>(std::count_if(utf8.begin(), utf8.end(), [](char c) {
    return (static_cast<unsigned char>(c) & kContinuationMask) != kContinuationBits;
  }));
}

std::vector<std::string> wrap_words(std::string_view text, std::size_t most) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t space = std::min(text.find(' ', start), text.size());
    const std::string_view word = text.substr(start, space - start);
    start = space + 1;
    if (word.empty()) continue;
    if (!line.empty() && count_characters(line) + 1 + count_characters(word) > most) {
      lines.push_back(std::move(line));
      line.clear();
    }
    if (!line.empty()) line += ' ';
    line += word;
  }
  if (!line.empty()) lines.push_back(std::move(line));
  return lines;
}

std::size_t characters_in(double width, double font_size, bool bold) {
  const double fit = width / ((bold ? kBoldCharWidth : kAverageCharWidth) * font_size);
  return fit >= 1.0 ? static_cast<std::size_t>(fit) : 1;
}

PlacedText place_text(Vec2 at, Vec2 away, std::string_view text) {
  const Vec2 direction = normalized(away);
  const Vec2 spot = at + direction * kLabelGap;
  const TextAnchor anchor = anchor_towards(direction);
  const double width = kBoldCharWidth * kFontSize * static_cast<double>(count_characters(text));
  const double left = anchor == TextAnchor::kStart    ? spot.x
                      : anchor == TextAnchor::kMiddle ? spot.x - width / 2.0
                                                      : spot.x - width;
  const Vec2 baseline{spot.x, spot.y + kBaselineDrop * kFontSize};
  const double halo = kHaloWidth * kFontSize / 2.0;
  return {baseline, anchor,
          TextBox{{left - halo, baseline.y - kCapHeight * kFontSize - halo},
                  {left + width + halo, baseline.y + kDescent * kFontSize + halo}}};
}

void Obstacles::add_segment(Vec2 from, Vec2 to) { segments_.push_back({from, to}); }

void Obstacles::add_circle(Vec2 center, double radius) { circles_.push_back({center, radius}); }

void Obstacles::add_box(const TextBox& box) { boxes_.push_back(box); }

int Obstacles::collisions(const TextBox& box) const {
  int count = 0;
  for (const Segment& s : segments_) {
    count += segment_meets_box(s.from, s.to, box) ? 1 : 0;
  }
  for (const Circle& c : circles_) count += circle_meets_box(c.center, c.radius, box) ? 1 : 0;
  for (const TextBox& b : boxes_) count += boxes_meet(box, b) ? 1 : 0;
  return count;
}

}  // namespace carom::cli
