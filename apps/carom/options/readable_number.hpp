// carom tool: numbers for people to read. Six significant digits tell the story; --json gives
// every digit.
#pragma once

#include <string>

#include "carom/vec2.hpp"

namespace carom::cli {

// value to 6 significant digits, shortest form ("0.5", "1e-07"); -0 reads as 0.
[[nodiscard]] std::string readable(double value);
// "(x, y)", each as above.
[[nodiscard]] std::string readable(Vec2 v);
// Derived figures (rates, durations, times in messages) to 3 significant digits: "0.00674",
// "1.19", "1120", "1.06e-09"; -0 reads as 0.
[[nodiscard]] std::string rounded(double value);
// A large count or rate in words, 3 significant digits: "723", "7.24 thousand", "1.06 million",
// "2.5 billion".
[[nodiscard]] std::string readable_count(double value);
// A measured value with its standard error, the error to 2 significant digits and the value to
// the same decimal place: "2.070 ± 0.014", "0.5209 ± 0.0056", "1234 ± 56". A zero or non-finite
// error leaves the value as readable() gives it.
[[nodiscard]] std::string with_error(double value, double error);
// The two parts of with_error, for tables with a column each.
struct ValueAndError {
  std::string value;
  std::string error;
};
[[nodiscard]] ValueAndError with_error_parts(double value, double error);
// A size in bytes to 3 significant digits in decimal units: "512 bytes", "3.2 MB", "1.05 GB".
[[nodiscard]] std::string readable_bytes(double bytes);

}  // namespace carom::cli
