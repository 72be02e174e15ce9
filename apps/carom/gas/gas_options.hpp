// carom tool: the options `carom gas` and `carom eos` share — the gas (N, packing fraction, an
// optional second size), the run's length and the seed — parsed and checked into a GasSpec.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "carom/science/hard_disk_gas.hpp"

namespace carom::cli {

// The options as typed.
struct GasOptionText {
  std::string n = "400";
  std::string eta = "0.3";
  std::string mix;  // "D:F": a second species of diameter D making up a fraction F of the disks
  std::string equilibrate = "50";
  std::string collisions = "500";
  std::string seed = "1";
  std::string blocks = "16";
  std::string start = "lattice";  // or "compress"
};

// A gas ready to build and run.
struct GasSpec {
  std::uint64_t n = 0;
  double eta = 0.0;
  std::vector<double> diameters;   // one per disk; all 1 without --mix
  science::HardDiskLayout layout;  // the box of eta for these diameters
  std::uint64_t equilibration_collisions = 0;
  double collisions_per_disk = 0.0;
  std::uint64_t seed = 0;
  std::uint64_t blocks = 0;
  // Where the disks start: a triangular lattice at eta (melted by the equilibration), or a
  // random dilute start compressed to eta (science::compress at kCompressStartRate, then the
  // equilibration at fixed radius).
  bool compress_start = false;
  double second_diameter = 1.0;  // --mix's D and F (1 and 0 without it)
  double second_fraction = 0.0;
};

// The growth speed of a compressed start's diameter, in thermal speeds: slow enough that the gas
// stays near equilibrium on the way (its pressure follows the equation of state within 1 % at
// η ≤ 0.5: tests/science/packing_tests.cpp), and equal disks crystallise above η ≈ 0.72.
inline constexpr double kCompressStartRate = 1e-3;
// A compressed start is placed at random at this packing fraction (or half the target, if less).
inline constexpr double kCompressStartEta = 0.3;

// Parses and checks every option, eta included; throws UsageError for the first bad one.
[[nodiscard]] GasSpec parse_gas_spec(const GasOptionText& text);
// The same with a packing fraction given as a number (for each point of `carom eos`).
[[nodiscard]] GasSpec parse_gas_spec(const GasOptionText& text, double eta,
                                     const std::string& eta_text);

}  // namespace carom::cli
