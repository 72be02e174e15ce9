// carom CLI tests: scene files written into a scratch folder, and the shared example scenes.
#pragma once

#include <filesystem>
#include <string>

#include "run_tool.hpp"

namespace carom::cli::test {

// Writes text to dir/name and returns the path.
std::string write_scene(const ScratchDir& dir, const std::string& name, const std::string& text);

// The path of examples/NAME.
std::string example(const std::string& name);

}  // namespace carom::cli::test
