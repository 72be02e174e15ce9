// The "X,Y,R" / "DX,DY" parser, called directly.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "options/usage_error.hpp"
#include "options/vector_args.hpp"

namespace carom::cli {
namespace {

using ::testing::HasSubstr;

// The UsageError a bad value throws (fails the test if it throws none).
UsageError error_for(std::string_view option, std::string_view text) {
  try {
    (void)parse_number_list(option, text, "X,Y,R");
  } catch (const UsageError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for " << text;
  return UsageError("", "", "");
}

TEST(VectorArgs, ReadsBallsAndVectors) {
  const Ball ball = parse_ball("--a", "1.5,-2,0.25");
  EXPECT_EQ(ball.center, (Vec2{1.5, -2}));
  EXPECT_EQ(ball.radius, 0.25);
  EXPECT_EQ(parse_vector("--va", "-4,1e-3"), (Vec2{-4, 1e-3}));
}

TEST(VectorArgs, ReadsEveryDigitExactly) {
  // The shortest text of a double reads back to the same double.
  EXPECT_EQ(parse_vector("--va", "0.1,0.30000000000000004"), (Vec2{0.1, 0.30000000000000004}));
  EXPECT_EQ(parse_vector("--va", "5e-324,1.7976931348623157e308"),
            (Vec2{5e-324, 1.7976931348623157e308}));
}

TEST(VectorArgs, AcceptsTheUsualDecimalForms) {
  EXPECT_EQ(parse_vector("--va", ".5,5."), (Vec2{0.5, 5.0}));
  EXPECT_EQ(parse_vector("--va", "-0,2E2"), (Vec2{-0.0, 200.0}));
}

TEST(VectorArgs, ErrorsNameTheOptionTheValueAndTheForm) {
  const UsageError error = error_for("--b", "1,2");
  EXPECT_EQ(error.option(), "--b");
  EXPECT_EQ(error.value(), "1,2");
  EXPECT_THAT(error.problem(), HasSubstr("2 comma-separated parts where 3 are needed"));
  EXPECT_THAT(error.what(), HasSubstr("--b \"1,2\""));
  EXPECT_THAT(error.what(), HasSubstr("X,Y,R"));
}

TEST(VectorArgs, RejectsWhatIsNotExactlyThreeFiniteNumbers) {
  EXPECT_THAT(error_for("--a", "").problem(), HasSubstr("empty"));
  EXPECT_THAT(error_for("--a", "1,2,3,4").problem(), HasSubstr("4 comma-separated parts"));
  EXPECT_THAT(error_for("--a", "1,,2").problem(), HasSubstr("part 2 is empty"));
  EXPECT_THAT(error_for("--a", ",1,2").problem(), HasSubstr("part 1 is empty"));
  EXPECT_THAT(error_for("--a", "1,2,x").problem(), HasSubstr("\"x\" is not a number"));
  EXPECT_THAT(error_for("--a", "1,2,3x").problem(), HasSubstr("\"3x\" is not a number"));
  EXPECT_THAT(error_for("--a", "1, 2,3").problem(), HasSubstr("\" 2\" is not a number"));
  EXPECT_THAT(error_for("--a", "+1,2,3").problem(), HasSubstr("\"+1\" is not a number"));
  EXPECT_THAT(error_for("--a", "0x1p3,2,3").problem(), HasSubstr("is not a number"));
  EXPECT_THAT(error_for("--a", "nan,2,3").problem(), HasSubstr("\"nan\" is not a finite"));
  EXPECT_THAT(error_for("--a", "1,inf,3").problem(), HasSubstr("\"inf\" is not a finite"));
  EXPECT_THAT(error_for("--a", "1,2,-infinity").problem(), HasSubstr("not a finite"));
  EXPECT_THAT(error_for("--a", "1e400,2,3").problem(), HasSubstr("beyond the range"));
}

TEST(VectorArgs, LeavesTheRadiusRangeToTheLibrary) {
  // Syntax only: a radius <= 0 is carom::sweep_*'s to reject, with its own message.
  EXPECT_EQ(parse_ball("--a", "0,0,-1").radius, -1.0);
}

}  // namespace
}  // namespace carom::cli
