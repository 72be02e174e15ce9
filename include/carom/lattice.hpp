// carom: the triangular lattice that scene generators and the hard-disk gas start balls on —
// columns × rows sites over a rectangle or a periodic cell, odd rows shifted half a spacing — and
// the choice, among lattices with at least n sites, of the one whose sites lie farthest apart.
// Why the nearest distance is what nearest() computes: docs/derivation.md, "The triangular
// lattice".
#pragma once

#include <cstdint>

#include "carom/vec2.hpp"

namespace carom {

// Balls start on sites at least (1 + kLatticeSlack) diameters apart: positions are rounded to
// doubles and gaps are measured through the minimum image, so balls exactly a diameter apart on
// paper could overlap by a rounding.
inline constexpr double kLatticeSlack = 1e-9;

// columns × rows sites over [origin, origin + size), numbered row by row: site i is in column
// i % columns of row i / columns, at origin + ((column + 1/4)·ax, (row + 1/2)·ay), odd rows half
// a spacing further along, with spacings ax = size.x / columns, ay = size.y / rows. Starting a
// quarter spacing in keeps the shifted rows inside. Periodic: [origin, origin + size) is a
// periodic cell and the sites' images count as sites.
struct TriangularLattice {
  Vec2 origin;
  Vec2 size;
  std::uint64_t columns = 1;
  std::uint64_t rows = 1;
  bool periodic = false;

  [[nodiscard]] std::uint64_t sites() const noexcept { return columns * rows; }
  // (ax, ay): along a row, and between rows.
  [[nodiscard]] Vec2 spacing() const noexcept;
  // The position of site `index` (< sites()).
  [[nodiscard]] Vec2 site(std::uint64_t index) const noexcept;
  // The smallest distance between two sites, images included when periodic; +infinity for a
  // single site in a rectangle.
  [[nodiscard]] double nearest() const noexcept;
  // The site of ball `ball` of `balls` (1 <= balls <= sites()) when the balls are spread evenly
  // over the sites: floor(ball·sites / balls), exact while that product is below 2^64 (every
  // lattice best_triangular_lattice returns has at most 2n sites, so any n below 2^31).
  [[nodiscard]] std::uint64_t spread(std::uint64_t ball, std::uint64_t balls) const noexcept;
};

// Which lattices best_triangular_lattice tries, and which of two equally good ones it keeps. Each
// tries every lattice that can be the best of its kind (docs/derivation.md says why).
enum class LatticeSearch {
  // Each column count from 1 to n with the fewest rows that hold n sites, in a periodic cell
  // rounded up to an even number so that the lattice tiles it; ties go to fewer columns. The
  // scene generators' lattice.
  by_columns,
  // Each row count from 1 to n + 1 with the fewest columns that hold n sites, odd row counts in
  // a periodic cell included (nearest() counts their wrap); ties go to fewer rows. The hard-disk
  // gas's lattice.
  by_rows,
};

// Of the triangular lattices with at least n sites over [origin, origin + size) (a periodic cell
// or a rectangle) that `search` tries, the one whose sites lie farthest apart, in O(n) time.
// Throws carom::InvalidArgument unless 1 <= n < 2^31 and both components of size are > 0.
[[nodiscard]] TriangularLattice best_triangular_lattice(std::uint64_t n, Vec2 origin, Vec2 size,
                                                        bool periodic, LatticeSearch search);

}  // namespace carom
