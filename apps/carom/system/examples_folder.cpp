#include "system/examples_folder.hpp"

#include <filesystem>
#include <system_error>

namespace carom::cli {

std::string examples_folder() {
  namespace fs = std::filesystem;
  std::error_code error;
  // From the executable's own path, not a prefix fixed at configure time: `cmake --install
  // --prefix P` chooses the prefix after the build, and an installed tree may be moved.
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path installed =
        (executable.parent_path() / CAROM_EXAMPLES_FROM_BINDIR).lexically_normal();
    if (fs::is_directory(installed, error)) return installed.string();
  }
  if (fs::is_directory(CAROM_SOURCE_EXAMPLES, error)) return CAROM_SOURCE_EXAMPLES;
  return "examples/ in carom's source tree";
}

}  // namespace carom::cli
