#include "js_error.hpp"

#include <emscripten/val.h>

namespace carom::web {

void throw_js_error(const std::string& message) {
  emscripten::val::global("Error").new_(message).throw_();
}

}  // namespace carom::web
