// carom tool: reading numbers out of an option's text, with messages that point at the bad part.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace carom::cli {

// An option's value as the user typed it, and what a good one looks like, so every message about
// it can name the option, quote the value and show the expected form.
struct OptionValue {
  std::string_view option;    // "--a"
  std::string_view text;      // "1,2,x"
  std::string_view expected;  // "X,Y,R"
};

// Throws UsageError: `OPTION "TEXT": PROBLEM (expected EXPECTED)`.
[[noreturn]] void reject(const OptionValue& value, std::string_view problem);

// item (all of the value, or one comma-separated part of it) read as a decimal number that uses
// every character and is finite. Rejects empty text, spaces, trailing characters ("1.5x"),
// "nan" and "inf", and numbers beyond the range of a double, by calling reject().
[[nodiscard]] double parse_finite_number(std::string_view item, const OptionValue& value);

// value.text read as a whole non-negative decimal integer: digits only, no sign, no spaces.
// Rejects empty text, any other character and numbers beyond 2^64 - 1, by calling reject().
[[nodiscard]] std::uint64_t parse_whole_number(const OptionValue& value);

}  // namespace carom::cli
