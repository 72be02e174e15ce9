#include "commands/table_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>

#include "carom/pool_table.hpp"
#include "carom/scene.hpp"
#include "options/exit_codes.hpp"
#include "options/usage_error.hpp"
#include "system/output_file.hpp"

namespace carom::cli {
namespace {

struct TableOptions {
  std::string size = "9ft";
  std::string rack = "eight";
  std::string out = "-";
};

int run(const TableOptions& o) {
  PoolTableSpec spec;
  if (o.size == "7ft") {
    spec.size = PoolTableSize::seven_foot;
  } else if (o.size == "8ft") {
    spec.size = PoolTableSize::eight_foot;
  } else if (o.size != "9ft") {
    throw UsageError("--size", o.size, "give 7ft, 8ft or 9ft");
  }
  if (o.rack == "nine") {
    spec.rack = PoolRack::nine_ball;
  } else if (o.rack == "none") {
    spec.rack = PoolRack::none;
  } else if (o.rack != "eight") {
    throw UsageError("--rack", o.rack, "give eight, nine or none");
  }
  if (const auto problem = check_output(o.out)) {
    throw UsageError("--out", o.out, "cannot be written: " + *problem);
  }
  if (const auto problem = write_output(o.out, to_json_text(pool_table_scene(spec)))) {
    std::cerr << "carom table: error: " << *problem << '\n';
    return kExitFailure;
  }
  return kExitSuccess;
}

}  // namespace

Command add_table_command(CLI::App& app) {
  auto options = std::make_shared<TableOptions>();
  CLI::App* table = app.add_subcommand(
      "table", "Write a standard pool table with a rack as a scene (docs/pool.md)");
  table->footer(
      "The WPA's playing surfaces (7ft: 78 x 39 in, 8ft: 88 x 44 in, 9ft: 100 x 50 in), cushions\n"
      "with jaws at six pockets, the rack's apex on the foot spot and the cue ball (\"cue\") on "
      "the\n"
      "head spot, on a cloth with the standard friction; metres, seconds, kilograms.\n\n"
      "Examples:\n"
      "  carom table --size 8ft --rack nine --out nine-ball.json\n"
      "  carom table | carom shot - --ball cue --speed 5 --height 0.01 --out break.png");
  table->add_option("--size", options->size, "7ft, 8ft or 9ft (default 9ft)")->type_name("SIZE");
  table->add_option("--rack", options->rack, "eight, nine or none (default eight)")
      ->type_name("RACK");
  table->add_option("--out", options->out, "The scene file (default -: standard output)")
      ->type_name("FILE");
  return {table, [options] { return run(*options); }};
}

}  // namespace carom::cli
