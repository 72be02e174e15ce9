#include "validate.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <version>

#include "carom/error.hpp"
#include "carom/number_text.hpp"

namespace carom::detail {
namespace {

// Shortest text that reads back to the same double, so a message shows the exact value.
std::string to_text(double value) { return carom::number_text(value); }

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
