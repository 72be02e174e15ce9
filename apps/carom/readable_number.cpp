#include "readable_number.hpp"

#include <fmt/format.h>

namespace carom::cli {

std::string readable(double value) {
  return fmt::format("{:.6g}", value + 0.0);  // + 0.0 turns -0 into 0: a sign on zero only puzzles
}

std::string readable(Vec2 v) { return "(" + readable(v.x) + ", " + readable(v.y) + ")"; }

}  // namespace carom::cli
