#include "options/readable_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace carom::cli {

std::string readable(double value) {
  return fmt::format("{:.6g}", value + 0.0);  // + 0.0 turns -0 into 0: a sign on zero only puzzles
}

std::string readable(Vec2 v) { return "(" + readable(v.x) + ", " + readable(v.y) + ")"; }

std::string rounded(double value) {
  // Whole numbers up to 10¹⁵ in digits (1120, not 1.12e+03), rounded to 3 significant digits.
  const double magnitude = std::abs(value);
  if (magnitude >= 999.5 && magnitude < 1e15) {
    const double unit = std::pow(10.0, std::floor(std::log10(magnitude)) - 2.0);
    return fmt::format("{:.0f}", std::round(value / unit) * unit);
  }
  return fmt::format("{:.3g}", value + 0.0);
}

std::string readable_count(double value) {
  constexpr struct {
    double scale;
    const char* word;
  } kScales[] = {{1e9, "billion"}, {1e6, "million"}, {1e3, "thousand"}};
  for (const auto& [scale, word] : kScales) {
    // 999.5 thousand reads as 1 million: the rounding to 3 digits decides the word.
    if (std::abs(value) >= scale * 0.9995) return fmt::format("{:.3g} {}", value / scale, word);
  }
  return fmt::format("{:.3g}", value + 0.0);
}

ValueAndError with_error_parts(double value, double error) {
  if (!std::isfinite(value) || !std::isfinite(error) || !(error > 0.0)) {
    return {readable(value), readable(error)};
  }
  // The decimal place of the error's second significant digit.
  const int place = static_cast<int>(std::floor(std::log10(error))) - 1;
  if (place > 0) {
    const double unit = std::pow(10.0, place);
    return {fmt::format("{:.0f}", std::round(value / unit) * unit + 0.0),
            fmt::format("{:.0f}", std::round(error / unit) * unit)};
  }
  const int decimals = -place;
  return {fmt::format("{:.{}f}", value + 0.0, decimals), fmt::format("{:.{}f}", error, decimals)};
}

std::string with_error(double value, double error) {
  const ValueAndError parts = with_error_parts(value, error);
  return parts.value + " ± " + parts.error;
}

std::string readable_bytes(double bytes) {
  if (!(bytes >= 1000.0)) return fmt::format("{:.0f} bytes", bytes);
  constexpr const char* kUnits[] = {"kB", "MB", "GB", "TB", "PB"};
  std::size_t unit = 0;
  bytes /= 1000.0;
  while (bytes >= 999.5 && unit + 1 < std::size(kUnits)) {
    bytes /= 1000.0;
    ++unit;
  }
  return fmt::format("{:.3g} {}", bytes, kUnits[unit]);
}

}  // namespace carom::cli
