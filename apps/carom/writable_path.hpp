// carom tool: checking that an output file can be written before any work starts, so a long
// run never ends in "cannot write".
#pragma once

#include <optional>
#include <string>

namespace carom::cli {

// Nothing if path can be written the way write_file_atomically writes it (a temporary file
// beside it, renamed onto it); otherwise why not, in the operating system's words. Leaves no
// file behind and does not touch an existing file at path.
[[nodiscard]] std::optional<std::string> check_output_path(const std::string& path);

}  // namespace carom::cli
