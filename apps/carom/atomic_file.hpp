// carom tool: writing an output file so that readers never see half of it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace carom::cli {

// Writes content to path + ".tmp" and renames that onto path, so path holds either its old
// content or all of the new. Returns nothing on success, otherwise what went wrong in the
// operating system's words; no .tmp file is left behind either way.
[[nodiscard]] std::optional<std::string> write_file_atomically(const std::string& path,
                                                               std::string_view content);

}  // namespace carom::cli
