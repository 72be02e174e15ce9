// The triangular lattice of carom/lattice.hpp: where its sites lie, how far apart (against brute
// force over small lattices, bounded and periodic), which lattice the search keeps, and how balls
// are spread over more sites than there are balls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "carom/error.hpp"
#include "carom/lattice.hpp"

namespace carom {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

TEST(TriangularLattice, SitesLieRowByRowWithOddRowsShiftedHalfASpacing) {
  const TriangularLattice lattice{{1.0, 2.0}, {8.0, 6.0}, 4, 3, false};
  EXPECT_EQ(lattice.sites(), 12u);
  EXPECT_EQ(lattice.spacing(), (Vec2{2.0, 2.0}));
  EXPECT_EQ(lattice.site(0), (Vec2{1.5, 3.0}));  // a quarter spacing in, half a row up
  EXPECT_EQ(lattice.site(3), (Vec2{7.5, 3.0}));  // the end of row 0
  EXPECT_EQ(lattice.site(4), (Vec2{2.5, 5.0}));  // row 1 starts three quarters in
  EXPECT_EQ(lattice.site(7), (Vec2{8.5, 5.0}));
  EXPECT_EQ(lattice.site(8), (Vec2{1.5, 7.0}));  // row 2 lines up with row 0
  EXPECT_EQ(lattice.site(11), (Vec2{7.5, 7.0}));
}

TEST(TriangularLattice, EverySiteLiesInsideItsRectangle) {
  for (std::uint64_t columns = 1; columns <= 7; ++columns) {
    for (std::uint64_t rows = 1; rows <= 7; ++rows) {
      const TriangularLattice lattice{{-3.0, 0.5}, {2.5, 1.25}, columns, rows, false};
      for (std::uint64_t i = 0; i < lattice.sites(); ++i) {
        const Vec2 p = lattice.site(i);
        EXPECT_GE(p.x, -3.0);
        EXPECT_LT(p.x, -0.5);
        EXPECT_GE(p.y, 0.5);
        EXPECT_LT(p.y, 1.75);
      }
    }
  }
}

// The smallest distance between two sites by comparing every pair; periodic: every pair with
// each of the eight neighbouring images of the second (a site with its own images too). Images
// further away are more than a cell apart, never nearer than the first ring.
double brute_force_nearest(const TriangularLattice& lattice) {
  double nearest = kInfinity;
  const int reach = lattice.periodic ? 1 : 0;
  for (std::uint64_t i = 0; i < lattice.sites(); ++i) {
    for (std::uint64_t j = 0; j < lattice.sites(); ++j) {
      for (int ix = -reach; ix <= reach; ++ix) {
        for (int iy = -reach; iy <= reach; ++iy) {
          if (i == j && ix == 0 && iy == 0) continue;
          const Vec2 image = lattice.site(j) + Vec2{ix * lattice.size.x, iy * lattice.size.y};
          nearest = std::min(nearest, length(image - lattice.site(i)));
        }
      }
    }
  }
  return nearest;
}

TEST(TriangularLattice, NearestMatchesBruteForce) {
  const Vec2 sizes[] = {{1.0, 1.0}, {3.0, 1.0}, {1.0, 2.5}, {0.7, 1.9}, {5.0, 0.3}};
  for (const bool periodic : {false, true}) {
    for (const Vec2 size : sizes) {
      for (std::uint64_t columns = 1; columns <= 6; ++columns) {
        for (std::uint64_t rows = 1; rows <= 7; ++rows) {
          const TriangularLattice lattice{{0.25, -1.0}, size, columns, rows, periodic};
          const double expected = brute_force_nearest(lattice);
          const double nearest = lattice.nearest();
          if (std::isinf(expected)) {
            EXPECT_EQ(nearest, kInfinity);
          } else {
            EXPECT_NEAR(nearest, expected, 1e-12 * expected)
                << columns << " x " << rows << " over " << size.x << " x " << size.y
                << (periodic ? " periodic" : "");
          }
        }
      }
    }
  }
}

// An odd number of rows in a periodic cell: the last row and the first's image, both unshifted,
// lie one row spacing apart.
TEST(TriangularLattice, OddPeriodicRowsMeetAcrossTheWrap) {
  const TriangularLattice odd{{0.0, 0.0}, {6.0, 3.0}, 3, 3, true};
  EXPECT_EQ(odd.nearest(), 1.0);
  const TriangularLattice even{{0.0, 0.0}, {6.0, 4.0}, 3, 4, true};
  EXPECT_EQ(even.nearest(), std::hypot(1.0, 1.0));
}

// Every lattice a search may consider: all columns × rows with at least n sites (in a periodic
// cell, with by_columns, an even number of rows or one, so up to n + 1 rows).
std::vector<TriangularLattice> every_lattice(std::uint64_t n, Vec2 size, bool periodic,
                                             LatticeSearch search) {
  std::vector<TriangularLattice> lattices;
  for (std::uint64_t columns = 1; columns <= n; ++columns) {
    for (std::uint64_t rows = 1; rows <= n + 1; ++rows) {
      if (columns * rows < n) continue;
      if (periodic && search == LatticeSearch::by_columns && rows > 1 && rows % 2 == 1) continue;
      lattices.push_back({{0.0, 0.0}, size, columns, rows, periodic});
    }
  }
  return lattices;
}

// The search keeps the lattice whose sites lie farthest apart of all it may consider, and of the
// equally good, the one with the fewest of the walked count, then the fewest of the other.
TEST(BestTriangularLattice, IsTheFarthestApartOfEveryLatticeWithEnoughSites) {
  const Vec2 sizes[] = {{1.0, 1.0}, {3.0, 1.0}, {1.0, 2.5}, {0.7, 1.9}};
  for (const LatticeSearch search : {LatticeSearch::by_columns, LatticeSearch::by_rows}) {
    for (const bool periodic : {false, true}) {
      for (const Vec2 size : sizes) {
        for (std::uint64_t n = 1; n <= 40; ++n) {
          const TriangularLattice best =
              best_triangular_lattice(n, {0.0, 0.0}, size, periodic, search);
          ASSERT_GE(best.sites(), n);
          EXPECT_LE(best.sites(), 2 * n);
          const std::vector<TriangularLattice> all = every_lattice(n, size, periodic, search);
          double farthest = 0.0;
          for (const TriangularLattice& lattice : all) {
            farthest = std::max(farthest, lattice.nearest());
          }
          EXPECT_EQ(best.nearest(), farthest)
              << n << " over " << size.x << " x " << size.y << (periodic ? " periodic" : "");
          for (const TriangularLattice& lattice : all) {
            if (lattice.nearest() != farthest) continue;
            const bool by_columns = search == LatticeSearch::by_columns;
            const std::uint64_t walked = by_columns ? lattice.columns : lattice.rows;
            const std::uint64_t best_walked = by_columns ? best.columns : best.rows;
            const std::uint64_t other = by_columns ? lattice.rows : lattice.columns;
            const std::uint64_t best_other = by_columns ? best.rows : best.columns;
            EXPECT_TRUE(walked > best_walked || (walked == best_walked && other >= best_other))
                << n << ": " << lattice.columns << " x " << lattice.rows << " beats "
                << best.columns << " x " << best.rows;
          }
        }
      }
    }
  }
}

// Four sites in a periodic square: one column of four rows and two of two are equally good; the
// walks keep different ones. Nine: three rows of three beat every even row count.
TEST(BestTriangularLattice, WalksKeepTheirOwnTiesAndOddRows) {
  const TriangularLattice columns =
      best_triangular_lattice(4, {0.0, 0.0}, {1.0, 1.0}, true, LatticeSearch::by_columns);
  EXPECT_EQ(columns.columns, 1u);
  EXPECT_EQ(columns.rows, 4u);
  const TriangularLattice rows =
      best_triangular_lattice(4, {0.0, 0.0}, {1.0, 1.0}, true, LatticeSearch::by_rows);
  EXPECT_EQ(rows.columns, 2u);
  EXPECT_EQ(rows.rows, 2u);
  EXPECT_EQ(columns.nearest(), rows.nearest());

  const TriangularLattice odd =
      best_triangular_lattice(9, {0.0, 0.0}, {3.0, 3.0}, true, LatticeSearch::by_rows);
  EXPECT_EQ(odd.columns, 3u);
  EXPECT_EQ(odd.rows, 3u);
  const TriangularLattice even =
      best_triangular_lattice(9, {0.0, 0.0}, {3.0, 3.0}, true, LatticeSearch::by_columns);
  EXPECT_EQ(even.rows % 2, 0u);
  EXPECT_LT(even.nearest(), odd.nearest());
}

// Many sites in a square come close to the densest packing: n disks of diameter `nearest` cover
// nearly π/(2√3) of the area.
TEST(BestTriangularLattice, LargeLatticeNearlyTriangular) {
  const std::uint64_t n = 100'000;
  for (const LatticeSearch search : {LatticeSearch::by_columns, LatticeSearch::by_rows}) {
    const TriangularLattice best = best_triangular_lattice(n, {0.0, 0.0}, {1.0, 1.0}, true, search);
    const double d = best.nearest();
    const double covered = static_cast<double>(n) * std::numbers::pi * d * d / 4.0;
    EXPECT_GT(covered, 0.9);
    EXPECT_LT(covered, std::numbers::pi / (2.0 * std::sqrt(3.0)) + 1e-12);
    EXPECT_LE(best.sites(), 2 * n);
  }
}

TEST(BestTriangularLattice, RejectsCountsAndSizesOutOfRange) {
  const Vec2 size{1.0, 1.0};
  EXPECT_THROW((void)best_triangular_lattice(0, {}, size, false, LatticeSearch::by_columns),
               InvalidArgument);
  EXPECT_THROW((void)best_triangular_lattice(std::uint64_t{1} << 31U, {}, size, true,
                                             LatticeSearch::by_rows),
               InvalidArgument);
  for (const Vec2 bad : {Vec2{0.0, 1.0}, Vec2{1.0, -1.0}, Vec2{std::nan(""), 1.0}}) {
    EXPECT_THROW((void)best_triangular_lattice(3, {}, bad, false, LatticeSearch::by_columns),
                 InvalidArgument);
  }
}

// n balls over s >= n sites: ball i on site floor(i·s/n), so the sites taken rise by
// floor(s/n) or ceil(s/n), the first is site 0 and the last within the lattice.
TEST(TriangularLattice, SpreadsBallsEvenlyOverMoreSites) {
  for (std::uint64_t columns = 1; columns <= 9; ++columns) {
    for (std::uint64_t rows = 1; rows <= 9; ++rows) {
      const TriangularLattice lattice{{0.0, 0.0}, {1.0, 1.0}, columns, rows, true};
      const std::uint64_t sites = lattice.sites();
      for (std::uint64_t n = 1; n <= sites; ++n) {
        EXPECT_EQ(lattice.spread(0, n), 0u);
        EXPECT_LT(lattice.spread(n - 1, n), sites);
        for (std::uint64_t i = 1; i < n; ++i) {
          const std::uint64_t step = lattice.spread(i, n) - lattice.spread(i - 1, n);
          EXPECT_GE(step, sites / n);
          EXPECT_LE(step, (sites + n - 1) / n);
        }
      }
      for (std::uint64_t i = 0; i < sites; ++i) EXPECT_EQ(lattice.spread(i, sites), i);
    }
  }
}

// The largest counts the search takes: ball·sites stays within 64 bits.
TEST(TriangularLattice, SpreadIsExactAtTheLargestCount) {
  const std::uint64_t n = (std::uint64_t{1} << 31U) - 1;
  const TriangularLattice lattice{{0.0, 0.0}, {1.0, 1.0}, n, 2, true};  // 2n sites, the most
  EXPECT_EQ(lattice.spread(n - 1, n), 2 * n - 2);
  EXPECT_EQ(lattice.spread(n / 2, n), n - 1);
}

}  // namespace
}  // namespace carom
