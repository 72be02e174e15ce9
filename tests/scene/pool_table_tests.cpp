// Standard pool tables (carom/pool_table.hpp): every size and rack is a valid scene that reads
// back bit for bit; a ball sent into a corner pocket's mouth falls in; one that meets a side
// pocket's jaw bounces back onto the table; a break leaves every ball potted or on the cloth.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "carom/error.hpp"
#include "carom/pool_table.hpp"
#include "carom/scene.hpp"

namespace carom::pool_table_tests {
namespace {

constexpr double kInch = 0.0254;

TEST(PoolTable, EverySizeAndRackIsAValidScene) {
  for (const PoolTableSize size :
       {PoolTableSize::seven_foot, PoolTableSize::eight_foot, PoolTableSize::nine_foot}) {
    for (const PoolRack rack : {PoolRack::none, PoolRack::eight_ball, PoolRack::nine_ball}) {
      const Scene scene = pool_table_scene({size, rack});
      const std::string text = to_json_text(scene);
      EXPECT_EQ(to_json_text(parse_scene(text)), text);
      const std::size_t balls = rack == PoolRack::eight_ball  ? 16U
                                : rack == PoolRack::nine_ball ? 10U
                                                              : 1U;
      EXPECT_EQ(scene.balls.size(), balls);
      EXPECT_EQ(scene.pockets.size(), 6U);
      EXPECT_EQ(scene.segments.size(), 6U + 12U);  // six cushions, two jaws a pocket
      EXPECT_TRUE(scene.world.table.has_value());
      EXPECT_EQ(scene.balls[0].name, "cue");
    }
  }
  // The playing surface: the cushions' noses span 100 x 50 inches on a 9-foot table.
  const Scene nine = pool_table_scene();
  double right = 0.0;
  double top = 0.0;
  for (const Segment& s : nine.segments) {
    if (s.a.x == s.b.x) right = std::max(right, s.a.x);
    if (s.a.y == s.b.y) top = std::max(top, s.a.y);
  }
  EXPECT_NEAR(right, 100.0 * kInch, 1e-12);
  EXPECT_NEAR(top, 50.0 * kInch, 1e-12);
}

// The cue ball alone, struck at `direction` from `from` hard enough to reach the rail.
SceneWorld one_shot(Vec2 from, double direction) {
  Scene scene = pool_table_scene({PoolTableSize::nine_foot, PoolRack::none});
  scene.balls[0].position = from;
  scene.shots.push_back({"cue", 0.0, CueStrike{}});
  scene.shots[0].cue.speed = 1.5;
  scene.shots[0].cue.direction = direction;
  SceneWorld sw = make_world(scene);
  std::vector<PottedBall> potted;
  run_scene_collisions(sw, 10'000, nullptr, &potted);
  return sw;
}

TEST(PoolTable, ABallIntoACornerMouthFallsIn) {
  // Along the diagonal into the bottom-left corner.
  const SceneWorld sw = one_shot({0.4, 0.4}, std::atan2(-1.0, -1.0));
  EXPECT_TRUE(sw.balls[0].is_null()) << "the ball is still on the table";
}

TEST(PoolTable, ABallOntoASidePocketsJawBouncesBack) {
  // Straight down onto the bottom side pocket's left jaw: its centre over the cushion's end.
  const double middle = 0.5 * 100.0 * kInch;
  const double edge = middle - 0.5 * 5.1 * kInch;
  const SceneWorld sw = one_shot({edge + 0.002, 0.3}, -0.5 * 3.141592653589793);
  ASSERT_FALSE(sw.balls[0].is_null()) << "the ball fell in";
  // (Through the middle of the mouth it falls in.)
  EXPECT_TRUE(one_shot({middle, 0.3}, -0.5 * 3.141592653589793).balls[0].is_null());
  const Vec2 at = sw.world.position(sw.balls[0]);
  EXPECT_GT(at.y, 0.0);  // back on the cloth
  EXPECT_TRUE(sw.world.at_rest());
}

TEST(PoolTable, ABreakLeavesEveryBallPottedOrOnTheCloth) {
  Scene scene = pool_table_scene();
  scene.shots.push_back({"cue", 0.0, CueStrike{}});
  scene.shots[0].cue.speed = 6.0;
  scene.shots[0].cue.height = 0.01;
  scene.shots[0].cue.direction = 0.003;
  SceneWorld sw = make_world(scene);
  run_scene_collisions(sw, 1'000'000);
  ASSERT_TRUE(sw.world.at_rest());
  EXPECT_EQ(sw.world.audit(), std::nullopt);
  for (const BallId id : sw.balls) {
    if (id.is_null()) continue;
    const Vec2 at = sw.world.position(id);
    EXPECT_TRUE(at.x > 0.0 && at.x < 100.0 * kInch && at.y > 0.0 && at.y < 50.0 * kInch)
        << at.x << ", " << at.y;
  }
}

TEST(PoolTable, ABadSpecIsRefused) {
  PoolTableSpec spec;
  spec.ball_radius = -1.0;
  EXPECT_THROW(static_cast<void>(pool_table_scene(spec)), InvalidArgument);
  spec = {};
  spec.rack_gap = std::nan("");
  EXPECT_THROW(static_cast<void>(pool_table_scene(spec)), InvalidArgument);
  spec = {};
  spec.ball_radius = 0.2;  // no room for a rack
  EXPECT_THROW(static_cast<void>(pool_table_scene(spec)), InvalidArgument);
}

}  // namespace
}  // namespace carom::pool_table_tests
