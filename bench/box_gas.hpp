// A gas in a closed box for the benchmarks: N disks of diameter 1 and mass 1 on a square lattice
// in a square box of packing fraction η, velocity components normal with standard deviation 1
// (kT = 1), elastic, contact recording off; with gravity g down of a scale height kT/(m·g) of half
// the side, so that the gas stays a gas, denser below. Not equilibrated.
#pragma once

#include <cstdint>
#include <memory>

#include "carom/world.hpp"

namespace carom::bench {

inline constexpr std::uint64_t kBoxGasSeed = 1;

// Nothing where the lattice cannot hold the disks (spacing at most a diameter).
[[nodiscard]] std::unique_ptr<World> make_box_gas(std::uint64_t n, double eta, bool gravity);

}  // namespace carom::bench
