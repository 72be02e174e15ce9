// carom science tests: a measured run of the hard-disk gas of `carom gas` and `carom bench`
// (carom/science/hard_disk_gas.hpp), in one call.
#pragma once

#include <cstdint>

#include "carom/science/gas_monitor.hpp"

namespace carom::science::test {

struct GasRunSpec {
  std::uint64_t n = 400;
  double eta = 0.3;
  double equilibrate_per_disk = 20.0;
  double collisions_per_disk = 200.0;
  std::uint64_t seed = 1;
  double structure_every = 4.0;
  GasMonitorSettings settings;
};

// Builds the gas on its lattice, melts it with the equilibration collisions (at least one per
// disk), then measures for the time that the collisions per disk take at the rate seen while
// equilibrating, with structure samples every structure_every collisions per disk.
[[nodiscard]] GasResults run_gas(const GasRunSpec& spec);

// Whether the long variants should run (the environment variable CAROM_LONG_TESTS is set to 1).
[[nodiscard]] bool long_tests_enabled();

}  // namespace carom::science::test
