#include "drawing/ball_colours.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace carom::cli {
namespace {

// viridis at eight evenly spaced points (matplotlib's table), interpolated linearly between.
constexpr std::array kViridis{
    rgb_from_hex(0x440154), rgb_from_hex(0x46337e), rgb_from_hex(0x365c8d), rgb_from_hex(0x277f8e),
    rgb_from_hex(0x1fa187), rgb_from_hex(0x4ac16d), rgb_from_hex(0x9fda3a), rgb_from_hex(0xfde725)};

// Tableau 10: ten colours that stay apart from each other and from white.
constexpr std::array kNamePalette{
    rgb_from_hex(0x4e79a7), rgb_from_hex(0xf28e2b), rgb_from_hex(0xe15759), rgb_from_hex(0x76b7b2),
    rgb_from_hex(0x59a14f), rgb_from_hex(0xedc948), rgb_from_hex(0xb07aa1), rgb_from_hex(0xff9da7),
    rgb_from_hex(0x9c755f), rgb_from_hex(0xbab0ac)};
constexpr Rgb kUnnamedColour = rgb_from_hex(0x9a9a9a);

// FNV-1a: a fixed hash, so a name gets the same colour on every run and every build.
std::uint64_t fnv1a(std::string_view text) {
  constexpr std::uint64_t kOffset = 14695981039346656037ULL;
  constexpr std::uint64_t kPrime = 1099511628211ULL;
  std::uint64_t hash = kOffset;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= kPrime;
  }
  return hash;
}

Rgb colour_of_name(std::string_view name) {
  const std::string_view group = name.substr(0, name.find('#'));
  return kNamePalette[fnv1a(group) % kNamePalette.size()];
}

Rgb checked_colour(const std::string& text, std::string_view scene_file, std::string path) {
  if (std::optional<Rgb> colour = parse_css_colour(text)) return *colour;
  SceneError::Details details;
  details.file = std::string(scene_file);
  details.path = std::move(path);
  details.value = "\"" + text + "\"";
  details.problem = "is not a colour carom can draw (use #rgb, #rrggbb or a CSS colour name)";
  throw SceneError(std::move(details));
}

}  // namespace

Rgb speed_colour(double fraction) {
  const double clamped = std::isnan(fraction) ? 0.0 : std::clamp(fraction, 0.0, 1.0);
  const double scaled = clamped * static_cast<double>(kViridis.size() - 1);
  const auto lower = std::min(static_cast<std::size_t>(scaled), kViridis.size() - 2);
  const double w = scaled - static_cast<double>(lower);
  const Rgb& a = kViridis[lower];
  const Rgb& b = kViridis[lower + 1];
  return {a.r + (b.r - a.r) * w, a.g + (b.g - a.g) * w, a.b + (b.b - a.b) * w};
}

bool scene_gives_colours(const Scene& scene) {
  return std::any_of(scene.balls.begin(), scene.balls.end(),
                     [](const SceneBall& b) { return b.color.has_value(); }) ||
         std::any_of(scene.generators.begin(), scene.generators.end(),
                     [](const SceneGenerator& g) { return g.color.has_value(); });
}

std::vector<Rgb> named_ball_colours(const Scene& scene, const std::vector<SceneBall>& balls,
                                    std::string_view scene_file) {
  // Checked where they are written, so the message names the field the user typed.
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    if (scene.balls[i].color) {
      (void)checked_colour(*scene.balls[i].color, scene_file,
                           "balls[" + std::to_string(i) + "].color");
    }
  }
  for (std::size_t g = 0; g < scene.generators.size(); ++g) {
    if (scene.generators[g].color) {
      (void)checked_colour(*scene.generators[g].color, scene_file,
                           "generators[" + std::to_string(g) + "].color");
    }
  }
  std::vector<Rgb> colours;
  colours.reserve(balls.size());
  for (const SceneBall& ball : balls) {
    if (ball.color) {
      colours.push_back(parse_css_colour(*ball.color).value_or(kUnnamedColour));
    } else if (ball.name) {
      colours.push_back(colour_of_name(*ball.name));
    } else {
      colours.push_back(kUnnamedColour);
    }
  }
  return colours;
}

}  // namespace carom::cli
