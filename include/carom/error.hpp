// carom: the one exception type the library throws for bad arguments.
#pragma once

#include <stdexcept>
#include <string>

namespace carom {

// Thrown when an argument is NaN, infinite, or outside its documented range. what() reads
// "carom::FUNCTION: ARGUMENT = VALUE: REQUIREMENT", and each part is available on its own.
class InvalidArgument : public std::invalid_argument {
 public:
  InvalidArgument(std::string function, std::string argument, std::string value,
                  std::string requirement);

  [[nodiscard]] const std::string& function() const noexcept { return function_; }
  [[nodiscard]] const std::string& argument() const noexcept { return argument_; }
  [[nodiscard]] const std::string& value() const noexcept { return value_; }
  [[nodiscard]] const std::string& requirement() const noexcept { return requirement_; }

 private:
  std::string function_;
  std::string argument_;
  std::string value_;
  std::string requirement_;
};

}  // namespace carom
