// The world's table of ball kinds (src/species.hpp): equal kinds share a number, a number is
// reused once its last ball is gone, and a kind is stored exactly as given.
#include <gtest/gtest.h>

#include <cmath>

#include "world/species.hpp"

namespace carom::detail {
namespace {

TEST(SpeciesTable, EqualKindsShareOneSpecies) {
  SpeciesTable table;
  const std::uint32_t first = table.acquire(0.5, 1.0, 1.0);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(table.acquire(0.5, 1.0, 1.0), first);
  EXPECT_EQ(table[first].balls, 1001u);
}

TEST(SpeciesTable, KindsDifferingInAnyFieldOrBitAreApart) {
  SpeciesTable table;
  const std::uint32_t base = table.acquire(0.5, 1.0, 1.0);
  const std::uint32_t radius = table.acquire(std::nextafter(0.5, 1.0), 1.0, 1.0);
  const std::uint32_t mass = table.acquire(0.5, kImmovable, 1.0);
  const std::uint32_t restitution = table.acquire(0.5, 1.0, 0.0);
  const std::uint32_t negative_zero = table.acquire(0.5, 1.0, -0.0);
  EXPECT_NE(radius, base);
  EXPECT_NE(mass, base);
  EXPECT_NE(restitution, base);
  EXPECT_NE(negative_zero, restitution);  // bit for bit: a save writes back what was given
  EXPECT_EQ(table[radius].radius, std::nextafter(0.5, 1.0));
  EXPECT_FALSE(table[mass].movable());
  EXPECT_EQ(table[mass].inverse_mass, 0.0);
  EXPECT_EQ(table[table.acquire(0.5, 4.0, 1.0)].inverse_mass, 0.25);
  EXPECT_TRUE(std::signbit(table[negative_zero].restitution));
}

TEST(SpeciesTable, ANumberIsReusedOnlyOnceItsLastBallIsGone) {
  SpeciesTable table;
  const std::uint32_t a = table.acquire(1.0, 1.0, 1.0);
  table.acquire(1.0, 1.0, 1.0);
  const std::uint32_t b = table.acquire(2.0, 1.0, 1.0);
  table.release(a);
  EXPECT_NE(table.acquire(3.0, 1.0, 1.0), a);  // a still has a ball
  table.release(a);
  table.release(a);  // the third and last of a
  const std::uint32_t reused = table.acquire(4.0, 2.0, 0.5);
  EXPECT_EQ(reused, a);
  EXPECT_EQ(table[reused].radius, 4.0);
  EXPECT_EQ(table[reused].mass, 2.0);
  EXPECT_EQ(table[reused].restitution, 0.5);
  EXPECT_EQ(table[b].radius, 2.0);  // untouched
  // The old kind, asked for again, gets a species of its own rather than the reused number.
  const std::uint32_t again = table.acquire(1.0, 1.0, 1.0);
  EXPECT_NE(again, reused);
  EXPECT_EQ(table[again].radius, 1.0);
}

TEST(SpeciesTable, ManyKindsEachKeepTheirFields) {
  SpeciesTable table;
  std::vector<std::uint32_t> ids;
  for (int i = 0; i < 500; ++i) ids.push_back(table.acquire(1.0 + i, 2.0 + i, 1.0 / (1 + i)));
  for (int i = 0; i < 500; ++i) {
    const Species& kind = table[ids[static_cast<std::size_t>(i)]];
    EXPECT_EQ(kind.radius, 1.0 + i);
    EXPECT_EQ(kind.mass, 2.0 + i);
    EXPECT_EQ(kind.restitution, 1.0 / (1 + i));
  }
}

}  // namespace
}  // namespace carom::detail
