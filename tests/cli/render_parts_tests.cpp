// The parts of `carom render` that stand alone: CSS colours, the speed scale and trails.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "carom/scene.hpp"
#include "drawing/ball_colours.hpp"
#include "drawing/css_colour.hpp"
#include "drawing/trail_recorder.hpp"

namespace carom::cli::test {
namespace {

TEST(CssColour, HexShortAndLongAndNamesInAnyCase) {
  EXPECT_EQ(parse_css_colour("#2060c0"), rgb_from_hex(0x2060c0));
  EXPECT_EQ(parse_css_colour("#2060C0"), rgb_from_hex(0x2060c0));
  EXPECT_EQ(parse_css_colour("#0a0"), rgb_from_hex(0x00aa00));
  EXPECT_EQ(parse_css_colour("red"), rgb_from_hex(0xff0000));
  EXPECT_EQ(parse_css_colour("RebeccaPurple"), rgb_from_hex(0x663399));
  EXPECT_EQ(parse_css_colour("aliceblue"), rgb_from_hex(0xf0f8ff));    // first in the table
  EXPECT_EQ(parse_css_colour("yellowgreen"), rgb_from_hex(0x9acd32));  // last
}

TEST(CssColour, RefusesWhatItCannotDraw) {
  for (const char* text :
       {"", "#", "#12", "#12345", "#1234567", "#ggg", "blurple", "rgb(1,2,3)", " red", "red "}) {
    EXPECT_FALSE(parse_css_colour(text).has_value()) << text;
  }
}

TEST(CssColour, HexRoundTrips) {
  EXPECT_EQ(hex_colour(rgb_from_hex(0x2060c0)), "#2060c0");
  EXPECT_EQ(hex_colour({2.0, -1.0, 0.5}), "#ff0080");  // clamped, rounded to nearest
}

TEST(SpeedColour, ViridisEndsAndClamping) {
  EXPECT_EQ(hex_colour(speed_colour(0.0)), "#440154");
  EXPECT_EQ(hex_colour(speed_colour(1.0)), "#fde725");
  EXPECT_EQ(speed_colour(-3.0), speed_colour(0.0));
  EXPECT_EQ(speed_colour(7.0), speed_colour(1.0));
}

// A ball moving right at speed 1 from x = 2 meets the box's right wall (x = 10) with its surface
// at t = 7.5, its centre at x = 9.5, and comes back: at t = 9 it is at x = 8. The trail over the
// last 5 time units is exactly (6, 5) → (9.5, 5) → (8, 5).
TEST(TrailRecorder, PathBendsExactlyWhereTheBallBounced) {
  const Scene scene = parse_scene(R"({
    "carom_scene": 1,
    "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10]},
    "balls": [{"position": [2, 5], "velocity": [1, 0], "radius": 0.5}]
  })");
  SceneWorld scene_world = make_world(scene);
  TrailRecorder trails(scene_world, 5.0);
  trails.record(scene_world, {});
  std::vector<ContactEvent> contacts;
  for (int frame = 1; frame <= 9; ++frame) {
    contacts.clear();
    step_scene(scene_world, 1.0, &contacts);
    trails.record(scene_world, contacts);
  }
  const std::vector<std::vector<Vec2>> runs = trails.paths(0, scene_world.world.time());
  ASSERT_EQ(runs.size(), 1U);
  // Points at each whole time unit from 4 on (6, 7, 8, 9 on the way out), the bounce, then
  // 9 and 8 on the way back. Exact arithmetic here up to one rounding per step.
  std::vector<double> xs;
  for (const Vec2 p : runs[0]) {
    xs.push_back(p.x);
    EXPECT_DOUBLE_EQ(p.y, 5.0);
  }
  EXPECT_THAT(
      xs, ::testing::Pointwise(::testing::DoubleNear(1e-12), {6.0, 7.0, 8.0, 9.0, 9.5, 9.0, 8.0}));
}

TEST(TrailRecorder, PeriodicWrapSplitsThePathAtTheCellEdge) {
  const Scene scene = parse_scene(R"({
    "carom_scene": 1,
    "world": {"boundary": "periodic", "lower": [0, 0], "upper": [10, 10]},
    "balls": [{"position": [8, 5], "velocity": [1, 0], "radius": 0.5}]
  })");
  SceneWorld scene_world = make_world(scene);
  TrailRecorder trails(scene_world, 10.0);
  trails.record(scene_world, {});
  for (int frame = 1; frame <= 4; ++frame) {
    step_scene(scene_world, 1.0);
    trails.record(scene_world, {});
  }
  // 8 → 9 → 10 ≡ 0 → 1 → 2: two runs, each continued past the edge by the wrapped step.
  const std::vector<std::vector<Vec2>> runs = trails.paths(0, scene_world.world.time());
  ASSERT_GE(runs.size(), 2U);
  EXPECT_NEAR(runs.front().front().x, 8.0, 1e-12);
  EXPECT_GT(runs.front().back().x, 9.99);
  EXPECT_LT(runs.back().front().x, 0.01);
  EXPECT_NEAR(runs.back().back().x, 2.0, 1e-12);
}

}  // namespace
}  // namespace carom::cli::test
