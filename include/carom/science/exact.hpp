// carom science: exact results for hard disks that the measurements are checked against.
// Derivations and sources: docs/science.md. Units: diameter σ, mass m, kT.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

namespace carom::science {

// The virial series of hard disks in the packing fraction η, Z = 1 + Σ b_k·η^(k−1), with the
// exact b2, b3, b4 (b3 and b4 from the known closed forms, to the digits printed).
inline constexpr double kVirialB2 = 2.0;
inline constexpr double kVirialB3 = 3.1280178;
inline constexpr double kVirialB4 = 4.2578545;
// The next coefficient (numerical, Clisby & McCoy), used only to bound the truncation error.
inline constexpr double kVirialB5 = 5.3368966;

// Z to third order in η: the part of the series known exactly.
[[nodiscard]] constexpr double virial_z(double eta) {
  return 1.0 + eta * (kVirialB2 + eta * (kVirialB3 + eta * kVirialB4));
}

// Henderson's equation of state for hard disks, Z = (1 + η²/8) / (1 − η)².
[[nodiscard]] constexpr double henderson_z(double eta) {
  return (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
}

// ⟨v⁴⟩/⟨v²⟩² of one disk among n equal disks (n ≥ 2) with fixed kinetic energy and zero total
// momentum: 2(n − 1)/n. It tends to 2, the Maxwell–Boltzmann value, as n grows.
[[nodiscard]] constexpr double moment_ratio_exact(std::uint64_t n) {
  const auto count = static_cast<double>(n);
  return 2.0 * (count - 1.0) / count;
}

// The rate/pressure identity of n equal disks at fixed energy and zero momentum, with kT = K/n:
// (4/√π)(Z − 1) = c_n · ω·σ·√(m/kT), where c_n = √n·Γ(n − ½)/Γ(n) = 1 + 3/(8n) + O(n⁻²).
// For n → ∞ this is the textbook identity (c = 1). n ≥ 2.
[[nodiscard]] inline double rate_pressure_ratio_exact(std::uint64_t n) {
  const auto count = static_cast<double>(n);
  return std::sqrt(count) * std::exp(std::lgamma(count - 0.5) - std::lgamma(count));
}

// The two-dimensional Maxwell–Boltzmann density of the speed v: (m·v/kT)·exp(−m·v²/(2kT)).
[[nodiscard]] inline double maxwell_speed_density(double speed, double kT, double mass = 1.0) {
  return mass * speed / kT * std::exp(-mass * speed * speed / (2.0 * kT));
}

}  // namespace carom::science
