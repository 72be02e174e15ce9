// carom tool: the error for a bad value on the command line.
#pragma once

#include <stdexcept>
#include <string>

namespace carom::cli {

// Thrown when an option's value is malformed or out of range. what() reads
// `OPTION "VALUE": PROBLEM`, so the user sees which option, what they typed and why it is wrong
// (`OPTION: PROBLEM` when there is no value to quote).
class UsageError : public std::runtime_error {
 public:
  UsageError(std::string option, std::string value, std::string problem);

  [[nodiscard]] const std::string& option() const noexcept { return option_; }
  [[nodiscard]] const std::string& value() const noexcept { return value_; }
  [[nodiscard]] const std::string& problem() const noexcept { return problem_; }

 private:
  std::string option_;
  std::string value_;
  std::string problem_;
};

}  // namespace carom::cli
