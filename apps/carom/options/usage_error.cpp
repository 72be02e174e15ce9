#include "options/usage_error.hpp"

#include <utility>

namespace carom::cli {

UsageError::UsageError(std::string option, std::string value, std::string problem)
    // An option without a value to quote (one that is missing, or a flag) is named alone.
    : std::runtime_error(value.empty() ? option + ": " + problem
                                       : option + " \"" + value + "\": " + problem),
      option_(std::move(option)),
      value_(std::move(value)),
      problem_(std::move(problem)) {}

}  // namespace carom::cli
