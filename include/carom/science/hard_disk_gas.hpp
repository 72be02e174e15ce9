// carom science: the hard-disk gas that `carom bench`, `carom gas`, the benchmarks and the
// science tests share. N equal disks (diameter 1, mass 1, elastic; or disks of given diameters)
// in a periodic square box sized for a given packing fraction, started on a triangular lattice
// with Maxwell–Boltzmann velocities from a seeded generator and no total momentum.
#pragma once

#include <cstdint>
#include <span>

#include "carom/lattice.hpp"
#include "carom/world.hpp"

namespace carom::science {

inline constexpr double kDiskDiameter = 1.0;
inline constexpr double kDiskRadius = kDiskDiameter / 2.0;
inline constexpr double kDiskMass = 1.0;
// The densest packing of equal disks, the triangular one: π / (2√3).
inline constexpr double kTriangularPackingLimit = 0.906899682117108925;
// The World wants a periodic cell more than three diameters wide on each axis, so that the 3×3
// block of grid cells around a ball never holds the same cell twice.
inline constexpr double kMinPeriodicSideInDiameters = 3.0;
// Lattice sites are at least (1 + kLatticeSlack) diameters apart (carom/lattice.hpp says why).
using carom::kLatticeSlack;
// hard_disk_layout takes fewer disks than this.
inline constexpr std::uint64_t kMaxHardDisks = std::uint64_t{1} << 31U;

// Where the disks start: a triangular lattice of `rows` rows of `columns` sites over the periodic
// box (carom/lattice.hpp; an odd number of rows is allowed). When there are more sites than
// disks, the disks are spread evenly over the sites (TriangularLattice::spread).
struct HardDiskLayout {
  std::uint64_t n = 0;
  double eta = 0.0;   // packing fraction n·π·d²/(4·side²)
  double side = 0.0;  // the periodic box is [0, side) × [0, side)
  std::uint64_t columns = 0;
  std::uint64_t rows = 0;
  double nearest = 0.0;  // the smallest distance between two sites, images included
  // The largest packing fraction at which this lattice still holds n disks: the lattice scales
  // with the box, so that is eta·nearest²/d².
  double densest_eta = 0.0;

  [[nodiscard]] bool box_wide_enough() const {
    return side > kMinPeriodicSideInDiameters * kDiskDiameter;
  }
  [[nodiscard]] bool disks_fit() const { return nearest >= kDiskDiameter * (1.0 + kLatticeSlack); }
  // The lattice itself: disk i sits on its site lattice().spread(i, n).
  [[nodiscard]] TriangularLattice lattice() const noexcept;
};

// The box for n disks at packing fraction eta, and of the triangular lattices with at least n
// sites over it, the one whose sites lie farthest apart (best_triangular_lattice walking the row
// counts, odd ones included). Whether the disks fit is for the caller to check (box_wide_enough,
// disks_fit). Throws carom::InvalidArgument unless 1 <= n < kMaxHardDisks and eta is finite, > 0.
[[nodiscard]] HardDiskLayout hard_disk_layout(std::uint64_t n, double eta);

// The world of the scene: the layout must fit (both checks above true). Velocity components are
// drawn from a normal distribution with standard deviation 1 by std::mt19937_64(seed) (x then y,
// ball by ball in lattice order; the values depend on the standard library's
// normal_distribution), then the mean velocity is subtracted from every ball, so the total
// momentum is zero up to rounding. The mean comes from a first pass over the same random
// sequence: nothing but the world is allocated, so a caller can measure the world's memory
// around this call.
[[nodiscard]] World make_hard_disk_world(const HardDiskLayout& layout, std::uint64_t seed);

// The same world with disk i of diameter diameters[i] (one per disk, each > 0), on the same sites
// and with the same velocities scaled by one factor so that K/N = 1 exactly (kT = 1; mass 1
// whatever the size). The caller checks that the largest
// diameter is at most layout.nearest (less the lattice slack); a layout from
// hard_disk_layout(n, eta_of_unit_disks) with eta_of_unit_disks = η·n/Σd² has the box of η.
[[nodiscard]] World make_hard_disk_world(const HardDiskLayout& layout, std::uint64_t seed,
                                         std::span<const double> diameters);

}  // namespace carom::science
