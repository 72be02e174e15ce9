// carom science: the contact network of a packing of disks — which disks touch, which are
// rattlers, the mean contact number of the rest — and its bond-orientational order ψ₆.
//
// Two disks are in contact when the gap between them is at most `tolerance` times the sum of their
// radii; a disk touches a box's wall when its gap to the wall is at most tolerance times its
// radius. Rattlers are the disks with fewer than three contacts (d + 1 in two dimensions: a disk
// held by fewer is free to move), found again and again as removing one can leave its neighbours
// with too few, until none is left (the usual iterative rule). A jammed packing is isostatic: the
// rest have 2d = 4 contacts each on the mean, walls counted as contacts. docs/science.md,
// "Compression and jamming".
#pragma once

#include <cstdint>
#include <vector>

#include "carom/world.hpp"

namespace carom::science {

// In the jammed packings compress() makes at a reduced pressure of 10¹², contacts have gaps of
// about 10⁻¹² of a diameter and the nearest non-contacts of more than 10⁻⁶.
inline constexpr double kContactTolerance = 1e-9;

// The tolerance for a packing at reduced pressure z: in a packing near jamming a contact's gap is
// about d/z of the sum of the radii (free-volume theory, d = 2), so 10³/z takes every contact and
// leaves the near ones out (kContactTolerance at z = 10¹²); at most 10⁻², as a packing far from
// jamming (z below 10⁵) has no contacts to speak of.
[[nodiscard]] inline double contact_tolerance_at_pressure(double z) {
  constexpr double kMostTolerance = 1e-2;
  constexpr double kContactsWithin = 1e3;
  return z > kContactsWithin / kMostTolerance ? kContactsWithin / z : kMostTolerance;
}
// Neighbours for ψ₆: centres closer than this many times the sum of the two radii.
inline constexpr double kPsi6Cutoff = 1.4;

struct ContactNetwork {
  // Indices into world.balls() (the order of handles).
  struct Pair {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
  };
  std::vector<Pair> pairs;              // disk–disk contacts, a < b
  std::vector<std::uint32_t> contacts;  // each disk's contacts, walls included
  std::vector<std::uint8_t> rattler;    // 1 for a rattler
  std::uint64_t wall_contacts = 0;
  std::uint64_t rattlers = 0;
  // The mean contact number of the disks that are not rattlers, counting only contacts between
  // them and with walls (4 at isostatic jamming); 0 when every disk is a rattler.
  double mean_contacts_of_rest = 0.0;
  // The mean over every disk of `contacts`.
  double mean_contacts = 0.0;
};

// The contact network of the world's balls now (a periodic cell or a box, or an open world of
// balls alone). tolerance finite and >= 0; throws InvalidArgument otherwise.
[[nodiscard]] ContactNetwork find_contact_network(const World& world,
                                                  double tolerance = kContactTolerance);

// The global bond-orientational order |Σ_j ψ₆,j| / N, with ψ₆,j = (1/n_j)·Σ_k exp(6iθ_jk) over
// the n_j neighbours k closer than cutoff·(r_j + r_k) (a disk with none counts 0): 1 for one
// perfect triangular crystal, near 0 for a fluid or a glass of many orientations.
[[nodiscard]] double global_psi6(const World& world, double cutoff = kPsi6Cutoff);

}  // namespace carom::science
