#include "validate.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <version>

#include "carom/error.hpp"

namespace carom::detail {
namespace {

// Shortest text that reads back to the same double, so a message shows the exact value.
std::string to_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
#if defined(__cpp_lib_to_chars)
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return {buffer, result.ptr};
#else
  // The libc++ of Debian's emscripten 3.1.6 (the wasm preset) cannot print doubles with
  // to_chars; 17 significant digits also read back exactly, if not always the shortest way.
  const int length = std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return {buffer, static_cast<std::size_t>(length)};
#endif
}

std::string to_text(Vec2 value) {
  // Appended piece by piece: g++ 12 at -O3 warns falsely (-Wrestrict) on "(" + std::string.
  std::string text = "(";
  text += to_text(value.x);
  text += ", ";
  text += to_text(value.y);
  text += ")";
  return text;
}

[[noreturn]] void fail(const char* function, const char* argument, std::string value,
                       const char* requirement) {
  throw InvalidArgument(function, argument, std::move(value), requirement);
}

}  // namespace

std::string number_text(double value) { return to_text(value); }
std::string vector_text(Vec2 value) { return to_text(value); }

void require_finite(const char* function, const char* argument, double value) {
  if (!std::isfinite(value)) fail(function, argument, to_text(value), "must be a finite number");
}

void require_finite(const char* function, const char* argument, Vec2 value) {
  if (!is_finite(value)) fail(function, argument, to_text(value), "must have finite components");
}

void require_positive(const char* function, const char* argument, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    fail(function, argument, to_text(value), "must be a finite number > 0");
  }
}

void require_non_negative(const char* function, const char* argument, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    fail(function, argument, to_text(value), "must be a finite number >= 0");
  }
}

void require_in_range(const char* function, const char* argument, double value, double low,
                      double high, const char* requirement) {
  if (!(value >= low && value <= high)) fail(function, argument, to_text(value), requirement);
}

void require_restitution(const char* function, const char* argument, double value) {
  require_in_range(function, argument, value, 0.0, 1.0, "must lie in [0, 1]");
}

void require_mass(const char* function, const char* argument, double value) {
  if (!(value > 0.0)) {
    fail(function, argument, to_text(value), "must be > 0 (or carom::kImmovable)");
  }
}

void require_that(bool condition, const char* function, const char* argument, double value,
                  const char* requirement) {
  if (!condition) fail(function, argument, to_text(value), requirement);
}

void require_nonzero(const char* function, const char* argument, Vec2 value) {
  require_finite(function, argument, value);
  if (value.x == 0.0 && value.y == 0.0) {
    fail(function, argument, to_text(value), "must not be the zero vector");
  }
}

}  // namespace carom::detail
