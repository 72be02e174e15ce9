// When a moving ball overlaps a sensor's shape (src/core/sensor_overlap.hpp): closed-form cases,
// and random segments, arcs and discs against a brute-force reference (the distance sampled
// densely along straight, falling and growing motions, each sign change bisected).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/arc_frame.hpp"
#include "core/sensor_overlap.hpp"
#include "random_cases.hpp"
#include "reference_distance.hpp"

namespace carom::detail {
namespace sensor_overlap_tests {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

SensorShape segment_shape(const Segment& s) {
  SensorShape shape;
  shape.kind = SensorShape::Kind::segment;
  shape.segment = s;
  return shape;
}

SensorShape arc_shape(const Arc& arc) {
  SensorShape shape;
  shape.kind = SensorShape::Kind::arc;
  shape.arc_as_given = arc;
  shape.arc = make_arc_frame("test", arc);
  return shape;
}

SensorShape disc_shape(const Ball& disc) {
  SensorShape shape;
  shape.kind = SensorShape::Kind::disc;
  shape.disc = disc;
  return shape;
}

struct Span {
  double start;
  double end;
};

std::vector<Span> spans_of(const TimeSpans& spans) {
  std::vector<Span> out;
  for (std::size_t k = 0; k < spans.size(); ++k) out.push_back({spans.start(k), spans.end(k)});
  return out;
}

TEST(SensorOverlap, ABulletThroughAThinLineEntersAndLeavesAtTheClosedFormTimes) {
  // A ball of radius 0.01 at 10^6 diameters a time unit crosses the line x = 0 (a segment from
  // y = −1 to 1) head on: it overlaps it while its centre is within 0.01 of x = 0.
  const Ball bullet{{-5000.0, 0.25}, 0.01};
  const Vec2 velocity{2e4, 0.0};
  const SensorShape line = segment_shape({{0.0, -1.0}, {0.0, 1.0}});
  const auto spans = spans_of(overlap_times(bullet, Motion{velocity, {}}, line, 1.0));
  ASSERT_EQ(spans.size(), 1U);
  EXPECT_NEAR(spans[0].start, (5000.0 - 0.01) / 2e4, 1e-15);
  EXPECT_NEAR(spans[0].end, (5000.0 + 0.01) / 2e4, 1e-15);
  // The recorded state decides which change comes next.
  const SensorChange enter = next_sensor_change(bullet, Motion{velocity, {}}, line, false, 1.0);
  ASSERT_TRUE(enter.found);
  EXPECT_EQ(enter.t, spans[0].start);
  // Recorded inside but not overlapping now: the change is at once.
  const SensorChange at_once = next_sensor_change(bullet, Motion{velocity, {}}, line, true, 1.0);
  ASSERT_TRUE(at_once.found);
  EXPECT_EQ(at_once.t, 0.0);
  // Past the horizon: nothing.
  EXPECT_FALSE(next_sensor_change(bullet, Motion{velocity, {}}, line, false, 0.2).found);
  // A horizon the clock cannot tell from now decides nothing, either way (rather than "no span
  // holds now", which would read as leaving at once).
  EXPECT_FALSE(next_sensor_change(bullet, Motion{velocity, {}}, line, true, 0.0).found);
  EXPECT_FALSE(next_sensor_change(bullet, Motion{velocity, {}}, line, true, 1e-20, 1.0).found);
}

TEST(SensorOverlap, AFallingBallThroughARingIsInsideTwiceOnTheWayUpAndDown) {
  // Thrown straight up into a full ring of radius 2 about the origin, its peak at y = 1: the
  // ball (radius 0.5) overlaps the ring while |y| is within 0.5 of 2, near y = −2 on the way up
  // and again on the way down.
  const Ball ball{{0.0, -4.0}, 0.5};
  const Motion motion{{0.0, std::sqrt(2.0 * 9.81 * 5.0)}, {0.0, -9.81}};  // peak at y = 1
  const SensorShape ring = arc_shape({{0.0, 0.0}, 2.0, 0.0, 2.0 * std::numbers::pi});
  const auto spans = spans_of(overlap_times(ball, motion, ring, kInfinity));
  ASSERT_EQ(spans.size(), 2U);
  const double v0 = motion.velocity.y;
  const auto time_at = [&](double y, bool rising) {
    const double root = std::sqrt(v0 * v0 - 2.0 * 9.81 * (y + 4.0));
    return (v0 + (rising ? -root : root)) / 9.81;
  };
  EXPECT_NEAR(spans[0].start, time_at(-2.5, true), 1e-12);
  EXPECT_NEAR(spans[0].end, time_at(-1.5, true), 1e-12);
  EXPECT_NEAR(spans[1].start, time_at(-1.5, false), 1e-12);
  EXPECT_NEAR(spans[1].end, time_at(-2.5, false), 1e-12);
}

TEST(SensorOverlap, AGrowingBallAtRestEntersWhenItsRadiusReachesTheDisc) {
  const Ball ball{{3.0, 0.0}, 1.0};
  const SensorShape disc = disc_shape({{0.0, 0.0}, 1.5});
  // Radius 1 + 0.25·t reaches 3 − 1.5 = 1.5 at t = 2, and never shrinks.
  const auto spans = spans_of(overlap_times(ball, Motion{{}, {}, 0.25}, disc, 10.0));
  ASSERT_EQ(spans.size(), 1U);
  EXPECT_NEAR(spans[0].start, 2.0, 1e-12);
  EXPECT_EQ(spans[0].end, 10.0);
  // Inside with the span running to the horizon: no exit within it.
  const Ball grown{{3.0, 0.0}, 2.0};
  EXPECT_FALSE(next_sensor_change(grown, Motion{{}, {}, 0.25}, disc, true, 10.0).found);
}

// The reference: spans where the sampled gap (distance − radius) is negative, each bound
// bisected; `clear` is false where some sample comes so near zero that a brief overlap or a
// graze between samples could be missed (the case is then not compared).
struct Reference {
  std::vector<Span> spans;
  bool clear = true;
};

template <typename Gap>
Reference reference_spans(const Gap& gap, double horizon, int samples, double margin) {
  Reference out;
  const auto bisect = [&](double low, double high) {
    const bool low_inside = gap(low) < 0.0;
    for (int k = 0; k < 80 && high - low > 1e-14; ++k) {
      const double mid = 0.5 * (low + high);
      ((gap(mid) < 0.0) == low_inside ? low : high) = mid;
    }
    return 0.5 * (low + high);
  };
  double previous = 0.0;
  bool inside = gap(0.0) < 0.0;
  double since = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double t = horizon * i / samples;
    const double g = gap(t);
    if (std::abs(g) < margin) out.clear = false;
    const bool now_inside = g < 0.0;
    if (now_inside != inside) {
      const double at = bisect(previous, t);
      if (inside) {
        out.spans.push_back({since, at});
      } else {
        since = at;
      }
      inside = now_inside;
    }
    previous = t;
  }
  if (inside) out.spans.push_back({since, horizon});
  return out;
}

Vec2 at(const Ball& ball, const Motion& m, double t) {
  return ball.center + m.velocity * t + m.acceleration * (0.5 * t * t);
}

// Random motions of three kinds (straight, falling, growing) against random shapes: every span
// of overlap matches the reference's to 1e-9, and none is missing or extra.
template <typename MakeShape, typename Distance>
void compare_with_reference(std::uint64_t seed, MakeShape make_shape, Distance distance) {
  testing::RandomCases random(seed);
  constexpr double kHorizon = 2.0;
  constexpr int kSamples = 4000;
  int compared = 0;
  for (int n = 0; n < 3000; ++n) {
    const auto shape = make_shape(random);
    const Ball ball{random.point(6.0), random.log_uniform(0.05, 1.5)};
    Motion motion{random.point(4.0), {}};
    if (n % 3 == 1) motion.acceleration = {random.uniform(-3.0, 3.0), random.uniform(-12.0, 0.0)};
    if (n % 3 == 2) motion.growth = random.uniform(0.0, 0.5);
    // Each sample step moves the centre (and the radius) by at most this much.
    const double step =
        (length(motion.velocity) + length(motion.acceleration) * kHorizon + motion.growth) *
        kHorizon / kSamples;
    const auto gap = [&](double t) {
      return distance(at(ball, motion, t), shape.first) - (ball.radius + motion.growth * t);
    };
    const Reference reference = reference_spans(gap, kHorizon, kSamples, 2.0 * step);
    if (!reference.clear) continue;
    ++compared;
    const auto spans = spans_of(overlap_times(ball, motion, shape.second, kHorizon));
    ASSERT_EQ(spans.size(), reference.spans.size()) << "case " << n;
    for (std::size_t k = 0; k < spans.size(); ++k) {
      EXPECT_NEAR(spans[k].start, reference.spans[k].start, 1e-9) << "case " << n << " span " << k;
      EXPECT_NEAR(spans[k].end, reference.spans[k].end, 1e-9) << "case " << n << " span " << k;
    }
  }
  // Most cases are clear of grazes: the comparison covers them.
  EXPECT_GT(compared, 2000);
}

TEST(SensorOverlap, SegmentsMatchABruteForceReference) {
  compare_with_reference(
      11,
      [](testing::RandomCases& random) {
        const Segment s = random.segment(5.0);
        return std::pair{s, segment_shape(s)};
      },
      [](Vec2 p, const Segment& s) { return testing::distance_to_segment(p, s); });
}

TEST(SensorOverlap, ArcsMatchABruteForceReference) {
  compare_with_reference(
      12,
      [](testing::RandomCases& random) {
        const Arc arc = random.arc(4.0);
        return std::pair{arc, arc_shape(arc)};
      },
      [](Vec2 p, const Arc& arc) { return testing::distance_to_arc(p, arc); });
}

TEST(SensorOverlap, DiscsMatchABruteForceReference) {
  compare_with_reference(
      13,
      [](testing::RandomCases& random) {
        const Ball disc{random.point(4.0), random.log_uniform(0.1, 4.0)};
        return std::pair{disc, disc_shape(disc)};
      },
      [](Vec2 p, const Ball& disc) {
        return std::max(0.0, length(p - disc.center) - disc.radius);
      });
}

TEST(SensorOverlap, SpansUniteIntersectAndComplement) {
  TimeSpans a;
  a.add(0.0, 1.0);
  a.add(2.0, 3.0);
  TimeSpans b;
  b.add(0.5, 2.5);
  const auto both = spans_of(TimeSpans::intersect(a, b));
  ASSERT_EQ(both.size(), 2U);
  EXPECT_EQ(both[0].start, 0.5);
  EXPECT_EQ(both[0].end, 1.0);
  EXPECT_EQ(both[1].start, 2.0);
  EXPECT_EQ(both[1].end, 2.5);
  const auto either = spans_of(TimeSpans::unite(a, b));
  ASSERT_EQ(either.size(), 1U);
  EXPECT_EQ(either[0].end, 3.0);
  const auto rest = spans_of(a.complement(4.0));
  ASSERT_EQ(rest.size(), 2U);
  EXPECT_EQ(rest[0].start, 1.0);
  EXPECT_EQ(rest[1].end, 4.0);
  // A single instant is no span.
  TimeSpans instant;
  instant.add(1.0, 1.0);
  EXPECT_EQ(instant.size(), 0U);
}

}  // namespace sensor_overlap_tests
}  // namespace carom::detail
