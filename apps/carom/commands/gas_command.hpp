// carom tool: `carom gas`, a hard-disk gas in a periodic box with the measurements of
// carom/science/gas_monitor.hpp: pressure (Z), collision rate, mean free path, speed
// distribution, g(r), ψ₆ and diffusion, each with a block-average error.
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

struct GasOptionText;

[[nodiscard]] Command add_gas_command(CLI::App& app);
// The gas options both `carom gas` and `carom eos` take (all but --eta) added to verb.
void add_gas_options(CLI::App& verb, GasOptionText& gas);

}  // namespace carom::cli
