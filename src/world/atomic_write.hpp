// carom internal: writing a file so that readers never see half of it.
#pragma once

#include <filesystem>
#include <string_view>

namespace carom::detail {

// Writes content to a fresh temporary file in path's folder, flushes it to the disk (fsync),
// renames it onto path and syncs the folder, so that path holds either its old content or all of
// the new one, even across a crash. Throws carom::InvalidArgument naming `function`, the path and
// the operating system's reason; no temporary file is left behind.
void write_file_atomically(const char* function, const std::filesystem::path& path,
                           std::string_view content);

}  // namespace carom::detail
