// carom tool: the colours a scene names ("#f2c500", "crimson"), read into numbers Cairo can draw
// and written back as the hex text SVG takes, so a picture looks the same in both formats.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace carom::cli {

// A colour with each channel in [0, 1].
struct Rgb {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
  friend constexpr bool operator==(Rgb, Rgb) noexcept = default;
};

// The colours carom reads: "#rgb", "#rrggbb" (hex digits in either case) and the 148 named
// colours of CSS Color Level 4 ("red", "rebeccapurple"; any case). Nothing for anything else
// (rgb(...), hsl(...), transparency): a picture cannot draw a colour it does not know.
[[nodiscard]] std::optional<Rgb> parse_css_colour(std::string_view text);

// "#rrggbb", each channel rounded to the nearest of 0..255.
[[nodiscard]] std::string hex_colour(Rgb colour);

// The colour from a 0xRRGGBB number.
[[nodiscard]] constexpr Rgb rgb_from_hex(unsigned hex) noexcept {
  constexpr double kChannelMax = 255.0;
  return {static_cast<double>((hex >> 16U) & 0xffU) / kChannelMax,
          static_cast<double>((hex >> 8U) & 0xffU) / kChannelMax,
          static_cast<double>(hex & 0xffU) / kChannelMax};
}

}  // namespace carom::cli
