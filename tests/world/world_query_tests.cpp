// The world's queries (ray casts, ball casts, overlap queries) against a brute-force reference:
// the same closed forms asked of every ball (at every periodic copy in reach) and every wall,
// over random worlds of each boundary, mid-run (balls on their paths, under gravity, growing).
// The grid walk must find exactly what the scan finds, bit for bit; a few cases check the answers
// against geometry worked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "carom/world.hpp"
#include "world/wall.hpp"

namespace carom::query_tests {
namespace {

enum class Kind { open, box, periodic, gravity, growth };

constexpr double kSide = 60.0;

// A random world of ~150 balls of radii 0.3–1.2, run for a while so that balls are mid-path;
// the box ones with slanted segments and arcs inside, the open one with balls spread past where
// its grid began.
World random_world(Kind kind, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  WorldDef def;
  if (kind == Kind::periodic || kind == Kind::growth) {
    def.boundary = Boundary::periodic;
  } else if (kind != Kind::open) {
    def.boundary = Boundary::box;
  }
  def.lower = {0.0, 0.0};
  def.upper = {kSide, kSide};
  if (kind == Kind::gravity) def.gravity = {0.0, -9.81};
  World world(def);
  if (def.boundary == Boundary::box) {
    world.add_segment({{10.0, 40.0}, {25.0, 35.0}});
    world.add_segment({{30.0, 20.0}, {50.0, 22.0}});
    world.add_arc({{15.0, 15.0}, 6.0, 0.3, 2.8});
    world.add_arc({{45.0, 45.0}, 5.0, -1.0, 4.0});
  }
  for (int k = 0; k < 150; ++k) {
    BallDef ball;
    const double spread = kind == Kind::open ? 3.0 : 1.0;
    ball.position = {kSide * (0.5 + spread * (unit(engine) - 0.5)),
                     kSide * (0.5 + spread * (unit(engine) - 0.5))};
    ball.velocity = {4.0 * (unit(engine) - 0.5), 4.0 * (unit(engine) - 0.5)};
    ball.radius = 0.3 + 0.9 * unit(engine);
    try {
      world.add_ball(ball);
    } catch (const InvalidArgument&) {
      // (an overlap: that place is skipped)
    }
  }
  if (kind == Kind::growth) world.set_growth_rate(0.02);
  world.run_until(kind == Kind::gravity ? 0.6 : 2.5);
  return world;
}

// Every place a ball of the world can be met at: its position and, in a periodic world, its
// copies within `reach` of the box [lower, upper].
std::vector<std::pair<BallId, Vec2>> copies_near(const World& world, Vec2 lower, Vec2 upper,
                                                 double reach) {
  std::vector<std::pair<BallId, Vec2>> out;
  const bool periodic = world.def().boundary == Boundary::periodic;
  const Vec2 period = world.def().upper - world.def().lower;
  for (const BallId id : world.balls()) {
    const Vec2 p = world.position(id);
    if (!periodic) {
      out.emplace_back(id, p);
      continue;
    }
    const double r = reach + world.radius(id);
    for (double kx = std::ceil((lower.x - r - p.x) / period.x);
         kx <= std::floor((upper.x + r - p.x) / period.x); ++kx) {
      for (double ky = std::ceil((lower.y - r - p.y) / period.y);
           ky <= std::floor((upper.y + r - p.y) / period.y); ++ky) {
        out.emplace_back(id, p + Vec2{kx * period.x, ky * period.y});
      }
    }
  }
  return out;
}

BallDef ball_at(Vec2 position, double radius) {
  BallDef def;
  def.position = position;
  def.radius = radius;
  return def;
}

detail::Wall wall_of(const World& world, WallId id) {
  const auto shape = world.wall(id);
  if (const auto* segment = std::get_if<Segment>(&shape))
    return detail::make_segment_wall(*segment);
  return detail::make_arc_wall("test", std::get<Arc>(shape));
}

auto order(const QueryHit& hit) {
  return std::make_tuple(hit.fraction, hit.kind == HitKind::ball ? 0 : 1,
                         hit.kind == HitKind::ball ? hit.ball.index : hit.wall);
}

// Every hit of the ray, by brute force: the ball closed form for each copy, the wall crossing.
std::vector<QueryHit> ray_reference(const World& world, Vec2 o, Vec2 d) {
  std::vector<QueryHit> hits;
  const Vec2 lower{std::min(o.x, o.x + d.x), std::min(o.y, o.y + d.y)};
  const Vec2 upper{std::max(o.x, o.x + d.x), std::max(o.y, o.y + d.y)};
  for (const auto& [id, p] : copies_near(world, lower, upper, 0.0)) {
    const double r = world.radius(id);
    const Impact impact = sweep_ball_point({p, r}, -d, o);
    if (!impact.hit || impact.overlapping) continue;
    QueryHit hit;
    hit.kind = HitKind::ball;
    hit.ball = id;
    hit.fraction = impact.t;
    hits.push_back(hit);
  }
  for (WallId w = 0; w < world.wall_count(); ++w) {
    const detail::RayCrossing crossing = detail::ray_crossing(wall_of(world, w), o, d);
    if (!crossing.hit) continue;
    QueryHit hit;
    hit.kind = HitKind::wall;
    hit.wall = w;
    hit.fraction = crossing.s;
    hits.push_back(hit);
  }
  std::sort(hits.begin(), hits.end(),
            [](const QueryHit& a, const QueryHit& b) { return order(a) < order(b); });
  std::vector<QueryHit> once;
  for (const QueryHit& hit : hits) {
    if (std::none_of(once.begin(), once.end(), [&](const QueryHit& kept) {
          return kept.kind == hit.kind && kept.ball == hit.ball && kept.wall == hit.wall;
        })) {
      once.push_back(hit);
    }
  }
  return once;
}

QueryHit ball_cast_reference(const World& world, Vec2 c, double radius, Vec2 d) {
  QueryHit best;
  const auto offer = [&](const QueryHit& hit) {
    if (!best || order(hit) < order(best)) best = hit;
  };
  const Vec2 lower{std::min(c.x, c.x + d.x), std::min(c.y, c.y + d.y)};
  const Vec2 upper{std::max(c.x, c.x + d.x), std::max(c.y, c.y + d.y)};
  for (const auto& [id, p] : copies_near(world, lower, upper, radius)) {
    const Impact impact = sweep_ball_ball({c, radius}, d, {p, world.radius(id)});
    if (!impact.hit && !impact.overlapping) continue;
    QueryHit hit;
    hit.kind = HitKind::ball;
    hit.ball = id;
    hit.fraction = impact.overlapping ? 0.0 : impact.t;
    offer(hit);
  }
  for (WallId w = 0; w < world.wall_count(); ++w) {
    const Impact impact = detail::time_of_impact(wall_of(world, w), {c, radius}, d, 1.0);
    if (!impact.hit && !impact.overlapping) continue;
    QueryHit hit;
    hit.kind = HitKind::wall;
    hit.wall = w;
    hit.fraction = impact.overlapping ? 0.0 : impact.t;
    offer(hit);
  }
  return best;
}

std::vector<std::uint32_t> handles(const std::vector<BallId>& ids) {
  std::vector<std::uint32_t> out;
  for (const BallId id : ids) out.push_back(id.index);
  return out;
}

std::vector<std::uint32_t> circle_reference(const World& world, Vec2 c, double radius) {
  std::vector<std::uint32_t> out;
  for (const auto& [id, p] : copies_near(world, c, c, radius)) {
    const double reach = radius + world.radius(id);
    if (length_squared(p - c) <= reach * reach) out.push_back(id.index);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::uint32_t> box_reference(const World& world, Vec2 lower, Vec2 upper) {
  std::vector<std::uint32_t> out;
  for (const auto& [id, p] : copies_near(world, lower, upper, 0.0)) {
    const Vec2 nearest{std::clamp(p.x, lower.x, upper.x), std::clamp(p.y, lower.y, upper.y)};
    const double r = world.radius(id);
    if (length_squared(nearest - p) <= r * r) out.push_back(id.index);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string kind_name(Kind kind) {
  switch (kind) {
    case Kind::open:
      return "open";
    case Kind::box:
      return "box";
    case Kind::periodic:
      return "periodic";
    case Kind::gravity:
      return "gravity";
    case Kind::growth:
      return "growth";
  }
  return "?";
}

constexpr Kind kKinds[] = {Kind::open, Kind::box, Kind::periodic, Kind::gravity, Kind::growth};
// 5 kinds × 4 worlds × 500 queries: 10⁴ cases of each query.
constexpr int kWorldsPerKind = 4;
constexpr int kQueriesPerWorld = 500;

// A random segment: mostly short (a cell or two), some across the world, a few far longer (a
// periodic world's ray wraps several times; an open world's starts far outside).
struct Segment2 {
  Vec2 start, move;
};
Segment2 random_path(std::mt19937_64& engine) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double angle = 2.0 * std::numbers::pi * unit(engine);
  const double pick = unit(engine);
  const double length = pick < 0.6    ? 10.0 * unit(engine)
                        : pick < 0.95 ? 80.0 * unit(engine)
                                      : 400.0 * unit(engine);
  const double spread = pick > 0.9 ? 4.0 : 1.2;
  return {{kSide * (0.5 + spread * (unit(engine) - 0.5)),
           kSide * (0.5 + spread * (unit(engine) - 0.5))},
          {length * std::cos(angle), length * std::sin(angle)}};
}

TEST(WorldQuery, RayCastsFindWhatEveryBallAndWallScanFinds) {
  int hits = 0;
  for (const Kind kind : kKinds) {
    for (int w = 0; w < kWorldsPerKind; ++w) {
      const World world = random_world(kind, 100 + static_cast<std::uint64_t>(w));
      std::mt19937_64 engine(7 + static_cast<std::uint64_t>(w));
      for (int q = 0; q < kQueriesPerWorld; ++q) {
        const auto [o, d] = random_path(engine);
        const std::vector<QueryHit> expected = ray_reference(world, o, d);
        const QueryHit first = world.cast_ray(o, d);
        const std::vector<QueryHit> all = world.cast_ray_all(o, d);
        SCOPED_TRACE(kind_name(kind) + " world " + std::to_string(w) + " query " +
                     std::to_string(q));
        ASSERT_EQ(all.size(), expected.size());
        for (std::size_t k = 0; k < all.size(); ++k) {
          ASSERT_EQ(order(all[k]), order(expected[k])) << "hit " << k;
        }
        if (expected.empty()) {
          ASSERT_FALSE(first);
          continue;
        }
        ++hits;
        ASSERT_EQ(order(first), order(expected.front()));
        // The point lies on the ray at its fraction, and the normal is a unit vector facing it.
        const Vec2 on_ray = o + d * first.fraction;
        ASSERT_LE(length(first.point - on_ray), 1e-9 * (1.0 + length(o) + length(d)));
        ASSERT_NEAR(length(first.normal), 1.0, 1e-12);
        ASSERT_LE(dot(first.normal, d), 1e-12 * length(d));
      }
    }
  }
  EXPECT_GT(hits, 3000);  // the cases meet something often enough to weigh the walk
}

TEST(WorldQuery, BallCastsFindWhatTheScanFindsAndTouchThere) {
  int hits = 0;
  for (const Kind kind : kKinds) {
    for (int w = 0; w < kWorldsPerKind; ++w) {
      const World world = random_world(kind, 200 + static_cast<std::uint64_t>(w));
      std::mt19937_64 engine(17 + static_cast<std::uint64_t>(w));
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      for (int q = 0; q < kQueriesPerWorld; ++q) {
        const auto [c, d] = random_path(engine);
        const double radius =
            unit(engine) < 0.9 ? 0.1 + 1.5 * unit(engine) : 3.0 + 5.0 * unit(engine);
        const QueryHit expected = ball_cast_reference(world, c, radius, d);
        const QueryHit hit = world.cast_ball(c, radius, d);
        SCOPED_TRACE(kind_name(kind) + " world " + std::to_string(w) + " query " +
                     std::to_string(q));
        ASSERT_EQ(static_cast<bool>(hit), static_cast<bool>(expected));
        if (!expected) continue;
        ++hits;
        ASSERT_EQ(order(hit), order(expected));
        ASSERT_NEAR(length(hit.normal), 1.0, 1e-12);
        if (hit.overlapping) continue;
        // Touching: the centre at contact is the radius (and the ball's) from the contact point.
        ASSERT_NEAR(length(hit.center - hit.point), radius, 1e-9 * (1.0 + radius));
        ASSERT_LE(length(hit.center - (c + d * hit.fraction)),
                  1e-9 * (1.0 + length(c) + length(d)));
      }
    }
  }
  EXPECT_GT(hits, 3000);
}

TEST(WorldQuery, OverlapQueriesFindWhatTheScanFinds) {
  int found = 0;
  for (const Kind kind : kKinds) {
    for (int w = 0; w < kWorldsPerKind; ++w) {
      const World world = random_world(kind, 300 + static_cast<std::uint64_t>(w));
      std::mt19937_64 engine(27 + static_cast<std::uint64_t>(w));
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      for (int q = 0; q < kQueriesPerWorld; ++q) {
        const Vec2 p{kSide * (1.4 * unit(engine) - 0.2), kSide * (1.4 * unit(engine) - 0.2)};
        const double radius = unit(engine) < 0.9 ? 3.0 * unit(engine) : 40.0 * unit(engine);
        const Vec2 size{20.0 * unit(engine), 20.0 * unit(engine)};
        SCOPED_TRACE(kind_name(kind) + " world " + std::to_string(w) + " query " +
                     std::to_string(q));
        ASSERT_EQ(handles(world.balls_at_point(p)), circle_reference(world, p, 0.0));
        const std::vector<std::uint32_t> in_circle = handles(world.balls_in_circle(p, radius));
        ASSERT_EQ(in_circle, circle_reference(world, p, radius));
        ASSERT_EQ(handles(world.balls_in_box(p, p + size)), box_reference(world, p, p + size));
        found += static_cast<int>(in_circle.size());
      }
    }
  }
  EXPECT_GT(found, 10000);
}

TEST(WorldQuery, ARayMeetsTheNearSideOfABallAndBothSidesOfAWall) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {20.0, 20.0}});
  const BallId ball = world.add_ball(ball_at({10.0, 5.0}, 1.0));
  const WallId segment = world.add_segment({{5.0, 12.0}, {15.0, 12.0}});
  const QueryHit up = world.cast_ray({10.0, 0.5}, {0.0, 19.0});
  ASSERT_TRUE(up);
  EXPECT_EQ(up.kind, HitKind::ball);
  EXPECT_EQ(up.ball, ball);
  EXPECT_DOUBLE_EQ(up.fraction, 3.5 / 19.0);
  EXPECT_EQ(up.point, (Vec2{10.0, 4.0}));
  EXPECT_EQ(up.normal, (Vec2{0.0, -1.0}));
  // From inside the ball the ray does not see it; it meets the segment from below, ...
  const QueryHit out = world.cast_ray({10.0, 5.0}, {0.0, 10.0});
  ASSERT_TRUE(out);
  EXPECT_EQ(out.kind, HitKind::wall);
  EXPECT_EQ(out.wall, segment);
  EXPECT_DOUBLE_EQ(out.fraction, 0.7);
  EXPECT_EQ(out.normal, (Vec2{0.0, -1.0}));
  // ... and from above with the normal turned up; then the box's floor (wall 0..3).
  const std::vector<QueryHit> down = world.cast_ray_all({12.0, 19.0}, {0.0, -19.5});
  ASSERT_EQ(down.size(), 2u);
  EXPECT_EQ(down[0].wall, segment);
  EXPECT_EQ(down[0].normal, (Vec2{0.0, 1.0}));
  EXPECT_EQ(down[1].kind, HitKind::wall);
  EXPECT_DOUBLE_EQ(down[1].point.y, 0.0);
  // A filter hides the ball: the ray goes on to the segment.
  QueryFilter no_ball;
  no_ball.ignore = ball;
  EXPECT_EQ(world.cast_ray({10.0, 0.5}, {0.0, 19.0}, no_ball).wall, segment);
  QueryFilter walls_only;
  walls_only.balls = false;
  EXPECT_EQ(world.cast_ray({10.0, 0.5}, {0.0, 19.0}, walls_only).kind, HitKind::wall);
}

TEST(WorldQuery, ARayMeetsAnArcFromInsideAndOutsideAndPassesItsGap) {
  World world;
  world.add_arc({{10.0, 10.0}, 3.0, 0.0, std::numbers::pi});  // the upper half circle
  const QueryHit out = world.cast_ray({10.0, 10.0}, {0.0, 10.0});
  ASSERT_TRUE(out);
  EXPECT_DOUBLE_EQ(out.fraction, 0.3);
  EXPECT_EQ(out.point, (Vec2{10.0, 13.0}));
  EXPECT_EQ(out.normal, (Vec2{0.0, -1.0}));
  const QueryHit in = world.cast_ray({10.0, 20.0}, {0.0, -10.0});
  ASSERT_TRUE(in);
  EXPECT_DOUBLE_EQ(in.fraction, 0.7);
  EXPECT_EQ(in.normal, (Vec2{0.0, 1.0}));
  // Down from the centre is the gap; sideways at y = 11 meets the arc at x = 10 ± √8.
  EXPECT_FALSE(world.cast_ray({10.0, 10.0}, {0.0, -10.0}));
  const std::vector<QueryHit> across = world.cast_ray_all({0.0, 11.0}, {20.0, 0.0});
  ASSERT_EQ(across.size(), 1u);  // a wall is met once, at its first meeting
  EXPECT_NEAR(across[0].point.x, 10.0 - std::sqrt(8.0), 1e-14);
}

TEST(WorldQuery, AnAimLineBallCastStopsWhereTheCueBallTouchesTheObjectBall) {
  // The cue ball (r = 1) aimed along x at an object ball 1 below its line: it touches when the
  // centres are 2 apart, at x = 20 − √3.
  World world;
  const BallId cue = world.add_ball(ball_at({0.0, 0.0}, 1.0));
  const BallId object = world.add_ball(ball_at({20.0, 1.0}, 1.0));
  QueryFilter not_the_cue;
  not_the_cue.ignore = cue;
  const QueryHit hit = world.cast_ball({0.0, 0.0}, 1.0, {40.0, 0.0}, not_the_cue);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit.ball, object);
  EXPECT_FALSE(hit.overlapping);
  EXPECT_NEAR(hit.center.x, 20.0 - std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(hit.center.y, 0.0, 1e-14);
  EXPECT_NEAR(hit.fraction, (20.0 - std::sqrt(3.0)) / 40.0, 1e-15);
  // The object ball leaves along the line of centres: the normal from it back to the cue ball.
  EXPECT_NEAR(hit.normal.x, -std::sqrt(3.0) / 2.0, 1e-14);
  EXPECT_NEAR(hit.normal.y, -0.5, 1e-14);
  // Unfiltered, the cast starts inside the cue ball itself.
  const QueryHit inside = world.cast_ball({0.0, 0.0}, 1.0, {40.0, 0.0});
  EXPECT_EQ(inside.ball, cue);
  EXPECT_TRUE(inside.overlapping);
  EXPECT_EQ(inside.fraction, 0.0);
  // accept sees only the balls the geometry found; rejecting every one finds nothing.
  QueryFilter none;
  none.accept = [](BallId) { return false; };
  EXPECT_FALSE(world.cast_ball({0.0, 0.0}, 1.0, {40.0, 0.0}, none));
}

TEST(WorldQuery, OverlapQueriesCountTouchingAndOrderByHandle) {
  World world;
  const BallId a = world.add_ball(ball_at({0.0, 0.0}, 1.0));
  const BallId b = world.add_ball(ball_at({3.0, 0.0}, 1.0));
  EXPECT_EQ(world.balls_at_point({1.0, 0.0}), std::vector<BallId>{a});
  EXPECT_TRUE(world.balls_at_point({1.5, 0.0}).empty());
  EXPECT_EQ(world.balls_in_circle({1.5, 0.0}, 0.5), (std::vector<BallId>{a, b}));
  EXPECT_EQ(world.balls_in_box({1.0, -5.0}, {2.0, 5.0}), (std::vector<BallId>{a, b}));
  EXPECT_EQ(world.balls_in_box({1.1, -5.0}, {1.9, 5.0}), std::vector<BallId>{});
}

TEST(WorldQuery, BadArgumentsAreRefusedNamingThem) {
  World world;
  world.add_ball(ball_at({0.0, 0.0}, 1.0));
  const double nan = std::nan("");
  EXPECT_THROW(static_cast<void>(world.cast_ray({nan, 0.0}, {1.0, 0.0})), InvalidArgument);
  EXPECT_THROW(static_cast<void>(world.cast_ball({0.0, 0.0}, 0.0, {1.0, 0.0})), InvalidArgument);
  EXPECT_THROW(static_cast<void>(world.balls_in_circle({0.0, 0.0}, -1.0)), InvalidArgument);
  try {
    static_cast<void>(world.balls_in_box({1.0, 1.0}, {0.0, 2.0}));
    FAIL() << "an upside-down box was accepted";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.argument(), "upper");
  }
}

}  // namespace
}  // namespace carom::query_tests
