// Masses and restitution, called directly.
#include <gtest/gtest.h>

#include "carom/bounce.hpp"
#include "options/scalar_args.hpp"
#include "options/usage_error.hpp"

namespace carom::cli {
namespace {

TEST(ScalarArgs, MassIsPositiveOrImmovable) {
  EXPECT_EQ(parse_mass("--ma", "2.5"), 2.5);
  EXPECT_EQ(parse_mass("--ma", "1e-300"), 1e-300);
  EXPECT_EQ(parse_mass("--ma", "inf"), kImmovable);
  EXPECT_EQ(parse_mass("--ma", "immovable"), kImmovable);
  for (const char* bad : {"0", "-0", "-1", "nan", "-inf", "infinity", "Immovable", "", "1kg"}) {
    EXPECT_THROW((void)parse_mass("--ma", bad), UsageError) << bad;
  }
}

TEST(ScalarArgs, RestitutionLiesInZeroToOne) {
  EXPECT_EQ(parse_restitution("--e", "0"), 0.0);
  EXPECT_EQ(parse_restitution("--e", "0.5"), 0.5);
  EXPECT_EQ(parse_restitution("--e", "1"), 1.0);
  for (const char* bad : {"-0.1", "1.0000001", "nan", "inf", "", "half"}) {
    EXPECT_THROW((void)parse_restitution("--e", bad), UsageError) << bad;
  }
}

TEST(ScalarArgs, ErrorNamesTheOptionAndValue) {
  try {
    (void)parse_restitution("--e", "2");
    FAIL() << "no error";
  } catch (const UsageError& error) {
    EXPECT_EQ(error.option(), "--e");
    EXPECT_EQ(error.value(), "2");
  }
}

}  // namespace
}  // namespace carom::cli
