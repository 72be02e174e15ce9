// carom_bench_goals: the world's speed and memory goals judged on this host. Each gas of the plan
// (goals.hpp) runs as `carom bench ... --json` in a process of its own, with the carom tool built
// beside this program or the one --tool names; the figures they print give the verdicts.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <vector>

#include "child_process.hpp"
#include "goals.hpp"

#ifndef CAROM_GOALS_TOOL
#define CAROM_GOALS_TOOL ""
#endif

namespace carom::goals {
namespace {

constexpr const char* kName = "carom_bench_goals";
// The exit statuses of the carom tool: a wrong command line, and anything else that fails.
constexpr int kExitUsage = 2;
constexpr int kExitFailure = 1;

struct GoalsOptions {
  std::string tool = CAROM_GOALS_TOOL;
  std::string seed = "1";
  std::string equilibrate = "2";
  bool json = false;
};

int usage_error(const std::string& message) {
  std::cerr << kName << ": error: " << message << " (see '" << kName << " --help')\n";
  return kExitUsage;
}

// The values `carom bench --seed` and `--equilibrate` take, checked before any gas runs: CLI11's
// validators, which return what is wrong ("" for nothing).
std::string check_seed(const std::string& text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) {
    return "a whole number from 0 to 2^64 - 1, not \"" + text + "\"";
  }
  return "";
}
std::string check_collisions_per_ball(const std::string& text) {
  double value = 0.0;
  if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || value < 0.0) {
    return "a number of collisions a disk >= 0, not \"" + text + "\"";
  }
  return "";
}

int run_goals(const GoalsOptions& options) {
  // A signal stops the gas that runs, and with it the verdicts.
  const StopSignals stop_signals;
  std::vector<nlohmann::ordered_json> benches;
  std::vector<GasFigures> gases;
  const std::vector<GoalGas> plan = goal_plan();
  for (std::size_t k = 0; k < plan.size(); ++k) {
    std::string out;
    if (StopSignals::received() == 0) {
      if (!options.json) {
        std::cerr << kName << ": gas " << k + 1 << " of " << plan.size() << ", " << plan[k].n
                  << " disks at eta " << plan[k].eta << '\n';
      }
      try {
        out = output_of_program(options.tool,
                                bench_arguments(plan[k], options.seed, options.equilibrate));
      } catch (const std::runtime_error&) {
        if (StopSignals::received() == 0) throw;
      }
    }
    if (StopSignals::received() != 0) {
      std::cerr << kName << ": " << StopSignals::what() << " in gas " << k + 1 << " of "
                << plan.size() << ": no verdicts\n";
      return 128 + StopSignals::received();
    }
    benches.push_back(nlohmann::ordered_json::parse(out));
    gases.push_back(gas_figures(benches.back()));
  }
  const std::vector<GoalVerdict> verdicts = judge_goals(gases);
  if (options.json) {
    std::cout << goals_json(benches, verdicts).dump() << '\n';
  } else {
    std::cout << goals_text(benches, verdicts, tool_text(options.tool, benches.front()));
  }
  std::cout.flush();
  if (!std::cout) {
    std::cerr << kName << ": error: cannot write to standard output\n";
    return kExitFailure;
  }
  return 0;
}

int parse_and_run(int argc, char** argv) {
  CLI::App app{"carom_bench_goals: the world's speed and memory goals judged on this host.", kName};
  app.footer(
      "Runs, for each packing fraction (0.3, then 0.6), 10^4 disks (K 20, R 5), 10^5\n"
      "(K 10, R 5), 10^6 (K 2, R 3) and 10^4 again, each as `carom bench --n N --eta ETA\n"
      "--collisions-per-ball K --repeat R --json` in a process of its own (so that its\n"
      "bytes a ball are its own peak), and judges the world's goals on this host: at\n"
      "least 2.5 M collisions/s at 10^4 and 1.5 M at 10^5 (the median of the timed runs,\n"
      "10^4's two gases pooled), 10^6 at most twice 10^4's median cost a collision, at\n"
      "most 128 bytes a ball at 10^6. About half a minute with a release build of the\n"
      "tool; --seed and --equilibrate apply to every gas. The exit status is 0 whether\n"
      "or not the goals are met (the verdicts are in the output); Ctrl-C or SIGTERM\n"
      "stops the gas that runs and ends with 130 or 143, no verdicts.\n\n"
      "Example:\n"
      "  taskset -c 1 build/release/bench/goals/carom_bench_goals");
  GoalsOptions options;
  const std::string built_tool = options.tool;
  app.add_option("--tool", options.tool,
                 "The carom tool that runs the gases" +
                     (built_tool.empty() ? std::string(" (none was built with this program)")
                                         : " (default: " + built_tool + ")"))
      ->type_name("PATH");
  app.add_option("--seed", options.seed, "Seed of the velocities' generator, for every gas")
      ->type_name("S")
      ->capture_default_str()
      ->check(CLI::Validator(check_seed, "", "seed"));
  app.add_option("--equilibrate", options.equilibrate,
                 "Untimed collisions per disk before each gas's timed runs, >= 0")
      ->type_name("K0")
      ->capture_default_str()
      ->check(CLI::Validator(check_collisions_per_ball, "", "collisions a disk"));
  app.add_flag("--json", options.json, "Print one JSON object, numbers exact, not text");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& done) {  // --help: printed, nothing else to do
    return app.exit(done);
  } catch (const CLI::ParseError& error) {
    // `carom bench`'s options of one gas: the user wants to hear that the plan is fixed.
    for (int k = 1; k < argc; ++k) {
      const std::string word = argv[k];
      for (const char* option : {"--n", "--eta", "--collisions-per-ball", "--repeat"}) {
        if (word == option || word.rfind(std::string(option) + "=", 0) == 0) {
          return usage_error(std::string(option) + ": the goals' gases are fixed; `carom bench " +
                             option + " ...` runs a gas of your choosing");
        }
      }
    }
    return usage_error(error.what());
  }
  if (options.tool.empty()) {
    return usage_error("no carom tool was built with this program: give one with --tool PATH");
  }
  if (!std::filesystem::is_regular_file(options.tool) ||
      ::access(options.tool.c_str(), X_OK) != 0) {
    return usage_error("--tool \"" + options.tool + "\": no program there that can be run");
  }
  try {
    return run_goals(options);
  } catch (const std::exception& error) {
    std::cerr << kName << ": error: " << error.what() << '\n';
  }
  return kExitFailure;
}

}  // namespace
}  // namespace carom::goals

int main(int argc, char** argv) { return carom::goals::parse_and_run(argc, argv); }
