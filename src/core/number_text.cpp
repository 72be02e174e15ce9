#include "carom/number_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace carom {

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
#if defined(__cpp_lib_to_chars)
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return {buffer, result.ptr};
#else
  // The libc++ of Debian's emscripten 3.1.6 (the wasm preset) cannot print doubles with
  // to_chars; 17 significant digits also read back exactly, if not always the shortest way.
  const int length = std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return {buffer, static_cast<std::size_t>(length)};
#endif
}

}  // namespace carom
