#include "usage_error.hpp"

#include <utility>

namespace carom::cli {

UsageError::UsageError(std::string option, std::string value, std::string problem)
    : std::runtime_error(option + " \"" + value + "\": " + problem),
      option_(std::move(option)),
      value_(std::move(value)),
      problem_(std::move(problem)) {}

}  // namespace carom::cli
