// carom tool: the command line. Each verb lives in its own *_command file; this file builds the
// command line, dispatches to the verb the user named, and turns every error into one message on
// stderr and an exit status (exit_codes.hpp), so no exception ever escapes.
#include "commands/command_line.hpp"

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "carom/error.hpp"
#include "carom/scene.hpp"
#include "commands/bench_command.hpp"
#include "commands/command.hpp"
#include "commands/eos_command.hpp"
#include "commands/gas_command.hpp"
#include "commands/info_command.hpp"
#include "commands/pack_command.hpp"
#include "commands/query_command.hpp"
#include "commands/render_command.hpp"
#include "commands/run_command.hpp"
#include "commands/shot_command.hpp"
#include "commands/sweep_command.hpp"
#include "commands/table_command.hpp"
#include "options/exit_codes.hpp"
#include "options/usage_error.hpp"
#include "system/examples_folder.hpp"

namespace {

using carom::cli::kExitFailure;
using carom::cli::kExitUsage;

// "carom" or "carom sweep": who speaks in a message, and whose --help to suggest.
std::string speaker(const CLI::App& app) {
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  return chosen.empty() ? app.get_name() : app.get_name() + " " + chosen.front()->get_name();
}

int fail(const CLI::App& app, int status, const std::string& message) {
  std::cerr << speaker(app) << ": error: " << message << '\n';
  return status;
}

std::string verb_list(const CLI::App& app) {
  std::string verbs;
  for (const CLI::App* verb : app.get_subcommands([](const CLI::App*) { return true; })) {
    verbs += (verbs.empty() ? "" : ", ") + verb->get_name();
  }
  return verbs;
}

// An option given before the verb that carom itself does not have ("-V", "--verbose"), or
// nothing; CLI11 would report it as a missing verb, or blame the verb that follows.
std::optional<std::string> misplaced_option(int argc, char** argv) {
  for (int k = 1; k < argc; ++k) {
    const std::string_view word = argv[k];
    if (word.empty() || word.front() != '-') return std::nullopt;  // the verb comes first
    if (word == "-h" || word == "--help" || word == "--version") continue;
    std::string message = "\"" + std::string(word) + "\" is not an option of carom itself";
    if (word == "-V" || word == "-v") return message + "; did you mean --version?";
    const bool verb_follows = k + 1 < argc && argv[k + 1][0] != '-';
    if (verb_follows) {
      return message + "; a verb's options come after the verb: carom " + std::string(argv[k + 1]) +
             " " + std::string(word) + " ...";
    }
    return message + " (its options are --help and --version; then a verb)";
  }
  return std::nullopt;
}

// CLI11 reports a misspelt verb as a missing one; the user wants to hear about what they typed.
std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error, int argc,
                                char** argv) {
  const bool no_verb = app.get_subcommands().empty();
  if (no_verb && argc > 1 && argv[1][0] != '-') {
    return "\"" + std::string(argv[1]) + "\" is not a verb; the verbs are: " + verb_list(app);
  }
  if (no_verb) return "give a verb: " + verb_list(app);
  return error.what();
}

int run(const CLI::App& app, const carom::cli::Command& command) {
  try {
    const int status = command.run();
    std::cout.flush();
    if (!std::cout) return fail(app, kExitFailure, "cannot write to standard output");
    return status;
  } catch (const carom::cli::UsageError& error) {
    return fail(app, kExitUsage, error.what());
  } catch (const carom::InvalidArgument& error) {
    return fail(app, kExitUsage, error.what());
  } catch (const carom::SceneError& error) {
    return fail(app, kExitUsage, error.what());
  }
}

int parse_and_run(int argc, char** argv) {
  CLI::App app{"carom: exact continuous collision of moving balls in 2D.", "carom"};
  app.set_version_flag("--version", std::string("carom ") + CAROM_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Run 'carom VERB --help' for the options of a verb.\n"
      "Example scenes (examples/ in the verbs' help): " +
      carom::cli::examples_folder());
  const std::vector<carom::cli::Command> commands{
      carom::cli::add_sweep_command(app), carom::cli::add_bench_command(app),
      carom::cli::add_gas_command(app),   carom::cli::add_eos_command(app),
      carom::cli::add_run_command(app),   carom::cli::add_info_command(app),
      carom::cli::add_query_command(app), carom::cli::add_render_command(app),
      carom::cli::add_pack_command(app),  carom::cli::add_shot_command(app),
      carom::cli::add_table_command(app)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& done) {  // --help or --version: printed, nothing else to do
    return app.exit(done);
  } catch (const CLI::ParseError& error) {
    // An option misplaced before the verb is carom's own error, whatever verb follows it.
    if (auto misplaced = misplaced_option(argc, argv)) {
      std::cerr << app.get_name() << ": error: " << *misplaced << " (see '" << app.get_name()
                << " --help')\n";
      return kExitUsage;
    }
    return fail(
        app, kExitUsage,
        parse_error_message(app, error, argc, argv) + " (see '" + speaker(app) + " --help')");
  }

  for (const carom::cli::Command& command : commands) {
    if (command.subcommand->parsed()) return run(app, command);
  }
  return fail(app, kExitFailure, "no verb to run");  // require_subcommand(1) makes this unreachable
}

}  // namespace

namespace carom::cli {

int run_command_line(int argc, char** argv) {
  try {
    return parse_and_run(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "carom: internal error: " << error.what() << '\n';
  } catch (...) {
    std::cerr << "carom: internal error\n";
  }
  return kExitFailure;
}

}  // namespace carom::cli
