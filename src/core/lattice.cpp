#include "carom/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "carom/error.hpp"
#include "validate.hpp"

namespace carom {
namespace {

// ball·sites stays below 2^64 in spread() for the lattices the search tries (at most 2n sites).
constexpr std::uint64_t kMaxLatticeBalls = std::uint64_t{1} << 31U;

}  // namespace

Vec2 TriangularLattice::spacing() const noexcept {
  return {size.x / static_cast<double>(columns), size.y / static_cast<double>(rows)};
}

Vec2 TriangularLattice::site(std::uint64_t index) const noexcept {
  const std::uint64_t row = index / columns;
  const std::uint64_t column = index % columns;
  const Vec2 a = spacing();
  const double shift = row % 2 == 1 ? 0.75 : 0.25;
  return origin +
         Vec2{(static_cast<double>(column) + shift) * a.x, (static_cast<double>(row) + 0.5) * a.y};
}

double TriangularLattice::nearest() const noexcept {
  const Vec2 a = spacing();
  double nearest = std::numeric_limits<double>::infinity();
  // Along a row (in a periodic cell a lone column's image is one spacing along).
  if (periodic || columns > 1) nearest = std::min(nearest, a.x);
  // To the next row, half a spacing to either side.
  if (rows > 1) nearest = std::min(nearest, std::hypot(a.x / 2.0, a.y));
  // Two rows up, straight above (in a periodic cell of two rows, the first row's image).
  if (rows > 2 || (periodic && rows == 2)) nearest = std::min(nearest, 2.0 * a.y);
  // An odd number of rows in a periodic cell: the last row and the image of the first, both
  // unshifted, lie one row spacing apart (one row: a site and its own image above).
  if (periodic && rows % 2 == 1) nearest = std::min(nearest, a.y);
  return nearest;
}

std::uint64_t TriangularLattice::spread(std::uint64_t ball, std::uint64_t balls) const noexcept {
  return ball * sites() / balls;
}

TriangularLattice best_triangular_lattice(std::uint64_t n, Vec2 origin, Vec2 size, bool periodic,
                                          LatticeSearch search) {
  constexpr const char* kFunction = "best_triangular_lattice";
  if (n < 1 || n >= kMaxLatticeBalls) {
    throw InvalidArgument(kFunction, "n", std::to_string(n), "must lie in [1, 2^31)");
  }
  if (!(size.x > 0.0 && size.y > 0.0)) {
    throw InvalidArgument(kFunction, "size", detail::vector_text(size),
                          "must have both components > 0");
  }
  TriangularLattice best{origin, size, 1, 1, periodic};
  double best_nearest = 0.0;
  // Walking rows, n + 1 rows of one column can beat n: in a periodic cell, when n is odd.
  const std::uint64_t last = search == LatticeSearch::by_rows ? n + 1 : n;
  for (std::uint64_t count = 1; count <= last; ++count) {
    const std::uint64_t fewest =
        (n + count - 1) / count;  // of the other dimension, to hold n sites
    TriangularLattice lattice{origin, size, count, fewest, periodic};
    if (search == LatticeSearch::by_columns) {
      if (periodic && lattice.rows > 1 && lattice.rows % 2 == 1) ++lattice.rows;
    } else {
      lattice.columns = fewest;
      lattice.rows = count;
    }
    const double nearest = lattice.nearest();
    if (count == 1 || nearest > best_nearest) {
      best = lattice;
      best_nearest = nearest;
    }
  }
  return best;
}

}  // namespace carom
