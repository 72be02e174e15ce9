#include "science/gas_run.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "carom/science/hard_disk_gas.hpp"

namespace carom::science::test {

GasResults run_gas(const GasRunSpec& spec) {
  const science::HardDiskLayout layout = science::hard_disk_layout(spec.n, spec.eta);
  if (!layout.box_wide_enough() || !layout.disks_fit()) {
    throw std::invalid_argument("run_gas: the lattice cannot hold this gas");
  }
  World world = science::make_hard_disk_world(layout, spec.seed);
  const auto count = static_cast<double>(spec.n);
  const auto equilibration =
      static_cast<std::uint64_t>(std::round(spec.equilibrate_per_disk * count));
  const double rate = equilibrate(world, equilibration);
  GasMonitorSettings settings = spec.settings;
  settings.structure_interval = 2.0 * spec.structure_every / rate;
  return measure_gas(world, 2.0 * spec.collisions_per_disk / rate, settings);
}

bool long_tests_enabled() {
  const char* value = std::getenv("CAROM_LONG_TESTS");
  return value != nullptr && std::string_view(value) == "1";
}

}  // namespace carom::science::test
