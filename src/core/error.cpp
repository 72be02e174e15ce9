#include "carom/error.hpp"

#include <utility>

namespace carom {

InvalidArgument::InvalidArgument(std::string function, std::string argument, std::string value,
                                 std::string requirement)
    : std::invalid_argument("carom::" + function + ": " + argument + " = " + value + ": " +
                            requirement),
      function_(std::move(function)),
      argument_(std::move(argument)),
      value_(std::move(value)),
      requirement_(std::move(requirement)) {}

}  // namespace carom
