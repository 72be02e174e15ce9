// Whether the long variants of the tests run: CAROM_LONG_TESTS=1 (make test-long) un-skips them.
#pragma once

#include <cstdlib>
#include <string_view>

namespace carom::testing {

[[nodiscard]] inline bool long_tests_enabled() {
  const char* value = std::getenv("CAROM_LONG_TESTS");
  return value != nullptr && std::string_view(value) == "1";
}

}  // namespace carom::testing
