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

// The disks of the equilibrated box gas (η = 0.3, no gravity) the sensor and moving-wall
// benchmarks run.
inline constexpr std::uint64_t kEquilibratedGasBalls = 10'000;
// A fresh copy (by save and load) of that gas, equilibrated 2 collisions a disk once for the
// process, so that every case starts alike.
[[nodiscard]] std::unique_ptr<World> equilibrated_gas_copy();

}  // namespace carom::bench
