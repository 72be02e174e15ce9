// carom tool: where the example scenes are, for the help to name (the verbs' examples/).
#pragma once

#include <string>

namespace carom::cli {

// The installed examples beside this executable (PREFIX/share/carom/examples for
// PREFIX/bin/carom), else the source tree's examples/ for a tool run from its build folder.
[[nodiscard]] std::string examples_folder();

}  // namespace carom::cli
