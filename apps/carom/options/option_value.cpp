#include "options/option_value.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <system_error>

#include "options/usage_error.hpp"

namespace carom::cli {

void reject(const OptionValue& value, std::string_view problem) {
  std::string message(problem);
  message += " (expected ";
  message += value.expected;
  message += ")";
  throw UsageError(std::string(value.option), std::string(value.text), std::move(message));
}

double parse_finite_number(std::string_view item, const OptionValue& value) {
  const std::string quoted = "\"" + std::string(item) + "\"";
  if (item.empty()) reject(value, "a number is missing");
  double number = 0.0;
  const char* const end = item.data() + item.size();
  const auto [stop, error] = std::from_chars(item.data(), end, number);
  if (error == std::errc::result_out_of_range) {
    reject(value, quoted + " is beyond the range of a double");
  }
  if (error != std::errc{} || stop != end) reject(value, quoted + " is not a number");
  if (!std::isfinite(number)) reject(value, quoted + " is not a finite number");
  return number;
}

std::uint64_t parse_whole_number(const OptionValue& value) {
  const std::string_view text = value.text;
  if (text.empty()) reject(value, "a number is missing");
  std::uint64_t number = 0;
  const char* const end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, number);
  if (error == std::errc::result_out_of_range) reject(value, "the number is too large");
  if (error != std::errc{} || stop != end) {
    // Say what is wrong with a number that is one, only not written as whole digits.
    double as_number = 0.0;
    const auto [number_stop, number_error] = std::from_chars(text.data(), end, as_number);
    if (number_error == std::errc{} && number_stop == end) {
      if (as_number < 0.0) reject(value, "must not be negative");
      if (std::floor(as_number) == as_number && as_number < 1e19) {
        reject(value, "write it in digits: " + fmt::format("{:.0f}", as_number));
      }
      reject(value, "not a whole number");
    }
    reject(value, "not a whole number");
  }
  return number;
}

}  // namespace carom::cli
