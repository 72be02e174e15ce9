#include <string>
#include <utility>

#include "carom/scene.hpp"

namespace carom {
namespace {

std::string message(const SceneError::Details& d) {
  std::string text;
  if (!d.file.empty()) text += d.file;
  if (d.line > 0) {
    text +=
        (text.empty() ? "line " : ":") + std::to_string(d.line) + ":" + std::to_string(d.column);
  }
  if (!text.empty()) text += ": ";
  if (!d.path.empty()) {
    text += d.path;
    if (!d.value.empty()) text += " = " + d.value;
    text += ": ";
  } else if (!d.value.empty()) {
    text += d.value + ": ";
  }
  text += d.problem;
  if (!d.suggestion.empty()) text += " (did you mean \"" + d.suggestion + "\"?)";
  return text;
}

}  // namespace

SceneError::SceneError(Details details)
    : std::runtime_error(message(details)), details_(std::move(details)) {}

}  // namespace carom
