#include "commands/sweep_command.hpp"

#include <CLI/CLI.hpp>
#include <array>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>

#include "carom/error.hpp"
#include "options/exit_codes.hpp"
#include "options/scalar_args.hpp"
#include "options/usage_error.hpp"
#include "options/vector_args.hpp"
#include "sweep/sweep_case.hpp"
#include "sweep/sweep_report.hpp"
#include "sweep/sweep_svg.hpp"
#include "system/output_file.hpp"

namespace carom::cli {
namespace {

// The options as typed. CLI11 only collects the text; every value is parsed here, so that one
// set of rules and messages covers them all.
struct SweepOptions {
  std::string a;
  std::string va;
  std::string b;
  std::string vb = "0,0";  // a standing ball unless said otherwise
  std::string ma = "1";
  std::string mb = "1";
  std::string e = "1";
  std::string svg;
  bool json = false;
  const CLI::Option* svg_option = nullptr;  // counts whether --svg was given, even as ""
};

// Which option supplied each argument the library may complain about, and what that argument
// is in the option's value.
struct ArgumentSource {
  std::string_view argument;  // carom::InvalidArgument::argument()
  std::string_view option;
  std::string SweepOptions::*text;
  std::string_view part;
};

constexpr std::array kArgumentSources{
    ArgumentSource{"a.center", "--a", &SweepOptions::a, "the centre"},
    ArgumentSource{"a.radius", "--a", &SweepOptions::a, "the radius"},
    ArgumentSource{"move_a", "--va", &SweepOptions::va, "the movement"},
    ArgumentSource{"velocity_a", "--va", &SweepOptions::va, "the movement"},
    ArgumentSource{"b.center", "--b", &SweepOptions::b, "the centre"},
    ArgumentSource{"b.radius", "--b", &SweepOptions::b, "the radius"},
    ArgumentSource{"move_b", "--vb", &SweepOptions::vb, "the movement"},
    ArgumentSource{"velocity_b", "--vb", &SweepOptions::vb, "the movement"},
    ArgumentSource{"mass_a", "--ma", &SweepOptions::ma, "the mass"},
    ArgumentSource{"mass_b", "--mb", &SweepOptions::mb, "the mass"},
    ArgumentSource{"restitution", "--e", &SweepOptions::e, "the restitution"},
};

// The library's complaint in the command line's words: `--a "0,0,-1": the radius -1 must be a
// finite number > 0`. An argument no option supplies is passed on unchanged.
[[noreturn]] void rethrow_as_usage_error(const InvalidArgument& error,
                                         const SweepOptions& options) {
  for (const ArgumentSource& source : kArgumentSources) {
    if (error.argument() == source.argument) {
      throw UsageError(std::string(source.option), options.*source.text,
                       std::string(source.part) + " " + error.value() + " " + error.requirement());
    }
  }
  throw error;
}

SweepCase parse(const SweepOptions& options) {
  SweepCase c;
  c.a = parse_ball("--a", options.a);
  c.move_a = parse_vector("--va", options.va);
  c.b = parse_ball("--b", options.b);
  c.move_b = parse_vector("--vb", options.vb);
  c.mass_a = parse_mass("--ma", options.ma);
  c.mass_b = parse_mass("--mb", options.mb);
  c.restitution = parse_restitution("--e", options.e);
  if (c.mass_a == kImmovable && c.mass_b == kImmovable) {
    throw UsageError("--mb", options.mb, "A and B cannot both be immovable (--ma is too)");
  }
  return c;
}

int run(const SweepOptions& options) {
  const SweepCase sweep_case = parse(options);
  SweepOutcome outcome;
  try {
    outcome = solve(sweep_case);
  } catch (const InvalidArgument& error) {
    rethrow_as_usage_error(error, options);
  }

  // The picture comes first: if it cannot be written, nothing is printed and the status says so.
  const bool draw = options.svg_option->count() > 0;
  if (draw) {
    if (options.svg.empty()) throw UsageError("--svg", options.svg, "the file name is empty");
    if (auto error = write_output(options.svg, sweep_svg(sweep_case, outcome))) {
      throw UsageError("--svg", options.svg, *error);
    }
  }

  if (options.json) {
    std::cout << sweep_json(outcome).dump() << '\n';
  } else {
    std::cout << sweep_text(outcome);
    if (draw) std::cout << "  picture: " << options.svg << '\n';
  }
  return kExitSuccess;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  CLI::App* sweep = app.add_subcommand(
      "sweep", "When two moving balls touch during one step, and how they bounce");
  sweep->footer(
      "Each ball moves from its start by its movement vector during the step; t is\n"
      "the fraction of the step at which A and B first touch, and the normal points\n"
      "from A's centre to B's.\n\n"
      "Examples:\n"
      "  carom sweep --a 0,0,1 --va 6,2 --b 8,3,1.5 --vb -4,-1 --svg two-balls.svg\n"
      "  carom sweep --a 0,0,1 --va 4,1 --b 3,0,1 --vb 0,0 --mb inf --e 0.5 --json");

  auto options = std::make_shared<SweepOptions>();
  sweep->add_option("--a", options->a, "Ball A at the start: centre X,Y and radius R > 0")
      ->type_name("X,Y,R")
      ->required();
  sweep->add_option("--va", options->va, "A's movement during the step")
      ->type_name("DX,DY")
      ->required();
  sweep->add_option("--b", options->b, "Ball B at the start: centre X,Y and radius R > 0")
      ->type_name("X,Y,R")
      ->required();
  sweep->add_option("--vb", options->vb, "B's movement during the step (0,0: standing)")
      ->type_name("DX,DY")
      ->capture_default_str();
  sweep->add_option("--ma", options->ma, "A's mass: a number > 0, or inf or immovable")
      ->type_name("M")
      ->capture_default_str();
  sweep->add_option("--mb", options->mb, "B's mass: a number > 0, or inf or immovable")
      ->type_name("M")
      ->capture_default_str();
  sweep->add_option("--e", options->e, "Restitution in [0, 1]: 1 elastic, 0 no rebound")
      ->type_name("E")
      ->capture_default_str();
  sweep->add_flag("--json", options->json, "Print one JSON object, numbers exact, not text");
  options->svg_option =
      sweep->add_option("--svg", options->svg, "Also draw the case as an SVG picture in FILE")
          ->type_name("FILE");

  return {sweep, [options] { return run(*options); }};
}

}  // namespace carom::cli
