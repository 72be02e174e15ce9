// carom tool: the whole command line, from argv to the exit status (exit_codes.hpp). main() is
// this call alone; every error becomes one message on stderr, and no exception escapes.
#pragma once

namespace carom::cli {

[[nodiscard]] int run_command_line(int argc, char** argv);

}  // namespace carom::cli
