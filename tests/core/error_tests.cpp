// Bad input gets carom::InvalidArgument naming the function, the argument and the value.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "carom/bounce.hpp"
#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "carom/sweep_batch.hpp"

namespace carom {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// Runs call, expects InvalidArgument, and checks each part of the message.
void expect_invalid(const std::function<void()>& call, const std::string& function,
                    const std::string& argument, const std::string& value) {
  try {
    call();
    ADD_FAILURE() << "no exception for " << argument << " = " << value;
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.function(), function);
    EXPECT_EQ(error.argument(), argument);
    EXPECT_EQ(error.value(), value);
    const std::string what = error.what();
    EXPECT_NE(what.find("carom::" + function), std::string::npos) << what;
    EXPECT_NE(what.find(argument + " = " + value), std::string::npos) << what;
  }
}

const Ball kBall{{0.0, 0.0}, 1.0};

TEST(InvalidArgument, IsAStdInvalidArgument) {
  EXPECT_THROW((void)sweep_ball_ball({{0.0, 0.0}, -1.0}, {}, kBall), std::invalid_argument);
}

TEST(InvalidArgument, BallBallArguments) {
  expect_invalid(
      [] {
        (void)sweep_ball_ball({{kNaN, 0.0}, 1.0}, {}, kBall);
      },
      "sweep_ball_ball", "a.center", "(nan, 0)");
  expect_invalid(
      [] {
        (void)sweep_ball_ball({{0.0, 0.0}, 0.0}, {}, kBall);
      },
      "sweep_ball_ball", "a.radius", "0");
  expect_invalid(
      [] {
        (void)sweep_ball_ball({{0.0, 0.0}, -2.5}, {}, kBall);
      },
      "sweep_ball_ball", "a.radius", "-2.5");
  expect_invalid(
      [] {
        (void)sweep_ball_ball(kBall, {kInf, 0.0}, kBall);
      },
      "sweep_ball_ball", "move_a", "(inf, 0)");
  expect_invalid(
      [] {
        (void)sweep_ball_ball(kBall, {}, {{0.0, -kInf}, 1.0});
      },
      "sweep_ball_ball", "b.center", "(0, -inf)");
  expect_invalid(
      [] {
        (void)sweep_ball_ball(kBall, {}, {{3.0, 0.0}, kNaN});
      },
      "sweep_ball_ball", "b.radius", "nan");
  expect_invalid(
      [] {
        (void)sweep_ball_ball(kBall, {}, {{3.0, 0.0}, 1.0}, {0.0, kNaN});
      },
      "sweep_ball_ball", "move_b", "(0, nan)");
  expect_invalid(
      [] {
        (void)time_of_impact_ball_ball(kBall, {}, {{3.0, 0.0}, 1.0}, {}, -1.0);
      },
      "time_of_impact_ball_ball", "horizon", "-1");
  expect_invalid(
      [] {
        (void)time_of_impact_ball_ball(kBall, {}, {{3.0, 0.0}, 1.0}, {1.0, 0.0}, kInf);
      },
      "time_of_impact_ball_ball", "horizon", "inf");
  expect_invalid(
      [] {
        (void)time_of_impact_ball_ball(kBall, {0.0, kNaN}, {{3.0, 0.0}, 1.0}, {}, 1.0);
      },
      "time_of_impact_ball_ball", "velocity_a", "(0, nan)");
}

TEST(InvalidArgument, StaticShapeArguments) {
  expect_invalid(
      [] {
        (void)sweep_ball_point(kBall, {}, {kNaN, 1.0});
      },
      "sweep_ball_point", "point", "(nan, 1)");
  expect_invalid(
      [] {
        (void)sweep_ball_segment(kBall, {}, {{0.0, 0.0}, {kInf, 1.0}});
      },
      "sweep_ball_segment", "segment.b", "(inf, 1)");
  expect_invalid(
      [] {
        (void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, -1.0, 0.0, 1.0});
      },
      "sweep_ball_arc", "arc.radius", "-1");
  expect_invalid(
      [] {
        (void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, 1.0, 1.0, 0.5});
      },
      "sweep_ball_arc", "arc.end_angle - arc.start_angle", "-0.5");
  expect_invalid(
      [] {
        (void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, 1.0, 0.0, 7.0});
      },
      "sweep_ball_arc", "arc.end_angle - arc.start_angle", "7");
  expect_invalid(
      [] {
        (void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, 1.0, kNaN, 1.0});
      },
      "sweep_ball_arc", "arc.start_angle", "nan");
}

// At 1e45 rad the full-circle allowance (4 ulps of the larger angle) would take a span of ~1e29
// for a full circle: angles beyond ±2^40 are refused, the bound itself is accepted.
TEST(InvalidArgument, ArcAnglesBeyondTwoToTheFortyAreRefused) {
  expect_invalid(
      [] {
        (void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, 5.0, 1e45, 1e45 + 1.5e29});
      },
      "sweep_ball_arc", "arc.start_angle", "1e+45");
  expect_invalid(
      [] {
        (void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, 5.0, 0.0, -0x1p41});
      },
      "sweep_ball_arc", "arc.end_angle", "-2199023255552");
  const double bound = kLargestArcAngle;
  EXPECT_NO_THROW((void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, 5.0, bound, bound}));
  EXPECT_NO_THROW((void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, 5.0, -bound, -bound + 6.0}));
  try {
    (void)sweep_ball_arc(kBall, {}, {{0.0, 0.0}, 5.0, 0x1p40 * 1.5, 0x1p40 * 1.5});
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.requirement(), "must lie in [-2^40, 2^40] radians (1.0995e12)");
  }
}

TEST(InvalidArgument, TinyButPositiveRadiusIsAccepted) {
  EXPECT_NO_THROW((void)sweep_ball_ball({{0.0, 0.0}, 1e-300}, {1.0, 0.0}, kBall));
  EXPECT_NO_THROW((void)sweep_ball_ball({{0.0, 0.0}, 4.9e-324}, {1.0, 0.0}, kBall));
}

TEST(InvalidArgument, BounceArguments) {
  expect_invalid([] { (void)bounce({}, 0.0, {}, 1.0, {1.0, 0.0}); }, "bounce", "mass_a", "0");
  expect_invalid([] { (void)bounce({}, 1.0, {}, -3.0, {1.0, 0.0}); }, "bounce", "mass_b", "-3");
  expect_invalid([] { (void)bounce({}, kNaN, {}, 1.0, {1.0, 0.0}); }, "bounce", "mass_a", "nan");
  expect_invalid([] { (void)bounce({}, -kInf, {}, 1.0, {1.0, 0.0}); }, "bounce", "mass_a", "-inf");
  expect_invalid(
      [] {
        (void)bounce({}, 1.0, {}, 1.0, {1.0, 0.0}, 1.5);
      },
      "bounce", "restitution", "1.5");
  expect_invalid(
      [] {
        (void)bounce({}, 1.0, {}, 1.0, {1.0, 0.0}, -0.1);
      },
      "bounce", "restitution", "-0.1");
  expect_invalid(
      [] {
        (void)bounce({}, 1.0, {}, 1.0, {1.0, 0.0}, kNaN);
      },
      "bounce", "restitution", "nan");
  expect_invalid([] { (void)bounce({}, 1.0, {}, 1.0, {0.0, 0.0}); }, "bounce", "normal", "(0, 0)");
  expect_invalid(
      [] {
        (void)bounce({kNaN, 0.0}, 1.0, {}, 1.0, {1.0, 0.0});
      },
      "bounce", "velocity_a", "(nan, 0)");
  expect_invalid(
      [] {
        (void)bounce({}, kImmovable, {}, kImmovable, {1.0, 0.0});
      },
      "bounce", "mass_b", "inf");
  expect_invalid(
      [] {
        (void)bounce_off_static({}, kImmovable, {1.0, 0.0});
      },
      "bounce_off_static", "mass", "inf");
  expect_invalid(
      [] {
        (void)bounce_off_static({}, 1.0, {1.0, 0.0}, 2.0);
      },
      "bounce_off_static", "restitution", "2");
  expect_invalid([] { (void)bounce_equal_mass({}, {}, {}); }, "bounce_equal_mass",
                 "line_of_centres", "(0, 0)");
}

TEST(InvalidArgument, BatchNamesTheArrayAndIndex) {
  std::vector<double> ones(3, 1.0);
  std::vector<double> zeros(3, 0.0);
  std::vector<double> far{5.0, 5.0, 5.0};
  std::vector<double> bad_radius{1.0, 1.0, -1.0};
  std::vector<double> t(3);
  BallPairArrays pairs{zeros, zeros, ones, ones, zeros, far, zeros, bad_radius, zeros, zeros};
  expect_invalid([&] { (void)sweep_ball_ball_batch(pairs, t); }, "sweep_ball_ball_batch",
                 "pairs.b_radius[2]", "-1");
  std::vector<double> bad_move{0.0, kNaN, 0.0};
  pairs.b_radius = ones;
  pairs.a_move_y = bad_move;
  expect_invalid([&] { (void)sweep_ball_ball_batch(pairs, t); }, "sweep_ball_ball_batch",
                 "pairs.a_move_y[1]", "nan");
  std::vector<double> short_t(2);
  pairs.a_move_y = zeros;
  EXPECT_THROW((void)sweep_ball_ball_batch(pairs, short_t), InvalidArgument);
  std::vector<double> short_array(2, 0.0);
  pairs.b_y = short_array;
  EXPECT_THROW((void)sweep_ball_ball_batch(pairs, t), InvalidArgument);
}

}  // namespace
}  // namespace carom
