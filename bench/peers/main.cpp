// carom_peers: carom beside Box2D 2.4 and Chipmunk 7 on the same scenes.
//   carom_peers run --engine E [--scene gas|bullets|gravity] [--n N] [--packing P] [--steps S]
//       [--seed K] [--no-checks] [--sleeping]
//       one engine on one scene in this process; prints one line of key=value results
//   carom_peers report [--out FILE] [--quick | --smoke] [--engines a,b] [--command TEXT]
//       every case, each in a process of its own; writes the Markdown report
//   carom_peers engines
//       the engines this build has
// Exit status: 0 success, 1 a case failed, 2 a usage error (as the carom tool's).
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine.hpp"
#include "report.hpp"
#include "run_case.hpp"

namespace {

constexpr int kExitUsage = 2;

constexpr const char* kUsage =
    "usage: carom_peers run --engine E [--scene gas|bullets|gravity] [--n N] [--packing P] "
    "[--steps S] [--seed K] [--no-checks] [--sleeping]\n"
    "       carom_peers report [--out FILE] [--quick | --smoke] [--engines a,b] [--command TEXT]\n"
    "       carom_peers engines\n";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The value after option `name` at args[i], advancing i.
std::string value_of(const std::vector<std::string>& args, std::size_t& i) {
  if (i + 1 >= args.size()) throw UsageError(args[i] + " needs a value");
  return args[++i];
}

template <typename Number>
Number number_of(const std::vector<std::string>& args, std::size_t& i, Number low, Number high) {
  const std::string& name = args[i];
  const std::string text = value_of(args, i);
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value >= static_cast<double>(low)) ||
      !(value <= static_cast<double>(high))) {
    throw UsageError(name + " " + text + ": expected a number in [" + std::to_string(low) + ", " +
                     std::to_string(high) + "]");
  }
  return static_cast<Number>(value);
}

int run(const std::vector<std::string>& args) {
  carom::peers::CaseSpec spec;
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--engine") {
      spec.engine = value_of(args, i);
    } else if (args[i] == "--scene") {
      spec.scene = value_of(args, i);
    } else if (args[i] == "--n") {
      spec.n = number_of<std::uint32_t>(args, i, 1, 10'000'000);
    } else if (args[i] == "--packing") {
      spec.packing = number_of<double>(args, i, 1e-6, 0.7);
    } else if (args[i] == "--steps") {
      spec.steps = number_of<std::uint32_t>(args, i, 1, 1'000'000);
    } else if (args[i] == "--no-checks") {
      spec.checks = false;
    } else if (args[i] == "--sleeping") {
      spec.sleeping = true;
    } else if (args[i] == "--seed") {
      spec.seed = number_of<std::uint64_t>(args, i, 0, std::uint64_t{1} << 53U);
    } else {
      throw UsageError("unknown option " + args[i]);
    }
  }
  if (spec.scene != "gas" && spec.scene != "bullets" && spec.scene != "gravity") {
    throw UsageError("--scene " + spec.scene + ": expected gas, bullets or gravity");
  }
  bool known = false;
  for (const auto& engine : carom::peers::available_engines()) known |= engine.name == spec.engine;
  if (!known) throw UsageError("--engine " + spec.engine + ": not in this build (see engines)");
  std::cout << carom::peers::to_line(carom::peers::run_case(spec)) << "\n";
  return 0;
}

int report(const std::vector<std::string>& args, const std::string& self) {
  carom::peers::ReportOptions options;
  options.command = "carom_peers report";
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--out") {
      options.out = value_of(args, i);
    } else if (args[i] == "--quick") {
      options.quick = true;
    } else if (args[i] == "--smoke") {
      options.smoke = true;
    } else if (args[i] == "--command") {
      options.command = value_of(args, i);
    } else if (args[i] == "--engines") {
      std::string list = value_of(args, i) + ",";
      for (std::size_t comma = 0; (comma = list.find(',')) != std::string::npos;) {
        if (comma > 0) options.engines.push_back(list.substr(0, comma));
        list.erase(0, comma + 1);
      }
    } else {
      throw UsageError("unknown option " + args[i]);
    }
  }
  return carom::peers::write_report(options, self);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty()) throw UsageError("no command");
    if (args[0] == "run") return run(args);
    // The children are this same program: /proc/self/exe names it whatever the current
    // directory, and its target is the name `ps` then shows.
    if (args[0] == "report") {
      std::error_code error;
      const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
      return report(args, error ? std::string("/proc/self/exe") : self.string());
    }
    if (args[0] == "engines") {
      for (const auto& engine : carom::peers::available_engines()) {
        std::cout << engine.name << "\t" << engine.version << "\n";
      }
      return 0;
    }
    throw UsageError("unknown command " + args[0]);
  } catch (const UsageError& error) {
    std::cerr << "carom_peers: " << error.what() << "\n" << kUsage;
    return kExitUsage;
  } catch (const std::exception& error) {
    std::cerr << "carom_peers: " << error.what() << "\n";
    return 1;
  }
}
