// carom tool: `carom pack`, dense and jammed packings of disks by Lubachevsky–Stillinger
// compression (carom/science/packing.hpp), with their contact network
// (carom/science/contact_network.hpp).
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

[[nodiscard]] Command add_pack_command(CLI::App& app);

}  // namespace carom::cli
