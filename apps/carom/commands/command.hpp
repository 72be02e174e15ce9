// carom tool: what every verb (carom sweep, and later run, render, ...) gives the dispatcher.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace carom::cli {

// A verb registered on the tool's command line. Its options are parsed into state that run
// shares; main() calls run only for the verb the user named. run returns the exit status and
// may throw UsageError for bad values.
struct Command {
  CLI::App* subcommand = nullptr;
  std::function<int()> run;
};

}  // namespace carom::cli
