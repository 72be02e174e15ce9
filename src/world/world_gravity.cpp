// Prediction under gravity: a ball's one pending event when balls move on parabolas
// (docs/engine.md, "Gravity"); and the events of a world with gravity or growth. The same events
// as without gravity (contacts with the balls and walls around, and leaving the cell), each time
// exact: two balls with the same acceleration keep a linear relative motion (the quadratic of the
// straight-line case), every other gap is a polynomial in time closed by the core's certified
// isolation (core/accelerated_sweep.hpp), and a cell's side is reached at the root of a
// quadratic. Apart from the straight-line parts, so that a world without gravity runs exactly as
// it did. (Growing balls are predicted by world_growth_prediction.cpp.)
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "core/accelerated_sweep.hpp"
#include "core/circle_crossing.hpp"
#include "engine_tuning.hpp"
#include "pair_batch.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using detail::Event;
using detail::EventKind;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

namespace {

// √(v² + k), k ≥ −v², without overflow for large |v|.
double root_of(double v, double k) {
  const double magnitude = std::abs(v);
  if (magnitude > 0x1p+500) return magnitude * std::sqrt(std::max(0.0, 1.0 + (k / v) / v));
  return std::sqrt(std::max(0.0, v * v + k));
}

// The first time t ≥ 0 at which a coordinate moving as v·t + ½·a·t² has risen by d (d ≥ 0: the
// distance to a side above it; d < 0: it is a rounding past the side already). Each root in its
// cancellation-free form: 2d / (v + √(v² + 2ad)) while rising, (√(v² + 2ad) − v) / a when it
// must first turn back.
double first_rise(double d, double v, double a) {
  if (!(d > 0.0)) {
    if (v > 0.0 || (v == 0.0 && a > 0.0)) return 0.0;
    d = 0.0;
  }
  if (v > 0.0) {
    const double k = 2.0 * a * d;
    if (k < -v * v) return kInfinity;  // it turns back short of the side
    return 2.0 * d / (v + root_of(v, k));
  }
  if (!(a > 0.0)) return kInfinity;
  return (root_of(v, 2.0 * a * d) - v) / a;
}

// When a coordinate at x, moving as v·t + ½·a·t², first reaches `lower` or `upper` (either
// ±infinity: a side never left); `low` and `high` name the two sides.
struct AxisExit {
  double t = kInfinity;
  std::uint32_t side = detail::kLeft;
};
AxisExit axis_exit(double x, double v, double a, double lower, double upper, std::uint32_t low,
                   std::uint32_t high) {
  AxisExit exit;
  if (std::abs(upper) != kInfinity) exit = {first_rise(upper - x, v, a), high};
  if (std::abs(lower) != kInfinity) {
    const double t = first_rise(x - lower, -v, -a);
    if (t < exit.t) exit = {t, low};
  }
  return exit;
}

}  // namespace

void World::Impl::advance_under_gravity(std::uint32_t ball, double t) {
  BallSlot& b = balls[ball];
  const Vec2 velocity = velocity_at(ball, t);
  b.position = position_at(ball, t);
  b.velocity = velocity;
  b.local_time = t;
}

void World::Impl::predict_under_gravity(std::uint32_t ball) {
  // A ball whose support no longer holds it falls (a safety net: whatever changes a carrier
  // frees what it carried, disturb).
  if (gravity_on && movable(ball) && carriages[ball].state != detail::Carried::free &&
      !supports_hold(ball)) {
    disturb(ball);
    ++balls[ball].version;
  }
  const BallSlot& b = balls[ball];
  const Vec2 p = b.position;  // at the world's time
  const Motion motion = motion_of(ball);
  const Vec2 v = motion.velocity;
  const Vec2 a = motion.acceleration;
  Event best;
  best.owner = ball;

  // Leaving the cell: the first side either coordinate reaches (x first on a tie).
  const std::int32_t cell = grid.cell_of_ball(ball);
  const std::int32_t cx = grid.column(cell);
  const std::int32_t cy = grid.row(cell);
  const AxisExit along_x = axis_exit(p.x, v.x, a.x, grid.exit_x(cx, false), grid.exit_x(cx, true),
                                     detail::kLeft, detail::kRight);
  const AxisExit along_y = axis_exit(p.y, v.y, a.y, grid.exit_y(cy, false), grid.exit_y(cy, true),
                                     detail::kDown, detail::kUp);
  const AxisExit exit = along_y.t < along_x.t ? along_y : along_x;
  best.time = time + exit.t;
  best.kind = EventKind::cell_crossing;
  best.partner = exit.side;
  // A ball carried by gravity on supports: they are touched, not met (docs/engine.md, "Resting
  // and sliding"); a sliding ball leaves its support where its coordinate along the line passes
  // an end.
  const detail::Carriage* carried = nullptr;
  if (gravity_on && movable(ball) && carriages[ball].state != detail::Carried::free) {
    carried = &carriages[ball];
  }
  // Whether ball `other` rests or slides on the support `key`.
  const auto carries = [&](std::uint32_t other, std::uint32_t key) {
    if (!gravity_on || !movable(other)) return false;
    const detail::Carriage& c = carriages[other];
    const auto end = c.support.begin() + c.supports;
    return std::find(c.support.begin(), end, key) != end;
  };
  const auto supported_by = [&](std::uint32_t key) {
    if (carried == nullptr) return false;
    const auto end = carried->support.begin() + carried->supports;
    return std::find(carried->support.begin(), end, key) != end;
  };
  if (carried != nullptr && carried->state == detail::Carried::sliding) {
    // On a ball, in that ball's frame.
    Vec2 offset = p - carried->origin;
    Vec2 relative = v;
    Vec2 relative_acceleration = a;
    const std::uint32_t key = carried->support[0];
    if ((key & detail::kBallSupport) != 0) {
      const std::uint32_t carrier = slot_of_handle[key & ~detail::kBallSupport];
      offset = minimum_image(p - position_at(carrier, time)) - carried->origin;
      relative = v - velocity_at(carrier, time);
      relative_acceleration = a - acceleration_of(carrier);
    }
    const Vec2 tangent = left_normal(carried->normal);
    const AxisExit off =
        axis_exit(dot(offset, tangent), dot(relative, tangent), dot(relative_acceleration, tangent),
                  carried->lower, carried->upper, 0, 0);
    if (off.t < exit.t) {
      best.time = time + off.t;
      best.kind = EventKind::motion_change;
      best.partner = 0;
    }
  }
  // On a table, the end of the ball's motion state (when it comes before the cell's exit).
  if (table_on && table_slots[ball].ends < best.time) {
    best.time = table_slots[ball].ends;
    best.kind = EventKind::motion_change;
    best.partner = 0;
  }
  // Contacts after the ball leaves its cell are found again from the next one.
  const auto horizon = [&] { return best.time < kInfinity ? best.time - time : kFarFuture; };
  const auto consider = [&](double t, EventKind kind, std::uint32_t partner,
                            std::uint32_t partner_version) {
    consider_event(best, ball, t, kind, partner, partner_version);
  };

  const detail::Species& kind = species[b.species];
  const double radius = radius_at(ball, time);
  const Ball shape{p, radius};
  for (const std::uint32_t w : grid.walls(cell)) {
    if (!walls[w].solid()) {
      consider_sensor(best, ball, w, shape, motion, horizon());
      continue;
    }
    if (supported_by(w)) continue;
    const Impact impact = detail::time_of_impact(walls[w], shape, motion, horizon());
    if (impact.hit) consider(impact.t, EventKind::ball_wall, w, 0);
  }
  if (!sensor_inside.empty()) consider_inside_sensors(best, ball, shape, motion, horizon());
  if (!moving_walls.empty()) consider_moving_walls(best, ball, shape, motion, horizon());

  // The balls of the 3×3 block: by their offsets as they are, as the minimum image, or, in a
  // periodic grid with few cells, at all nine images (as prediction_steps.hpp takes them).
  const bool movable_ball = kind.movable();
  const bool periodic = def.boundary == Boundary::periodic;
  const bool few_cells =
      periodic && (grid.nx() < kSingleImageMinCells || grid.ny() < kSingleImageMinCells);
  // A contact at the world's time itself counts only where the response will act on it: the two
  // approach, gravity presses them together along the normal the response takes, or they grow
  // (else the pair, left alone, would be predicted again at once, for ever).
  const double growth = motion.growth;
  const auto acts_now = [&](double t, Vec2 offset, Vec2 other_velocity, Vec2 other_acceleration,
                            double other_growth) {
    if (time + t != time || offset == Vec2{}) return true;
    const Vec2 normal = normalized(-offset);
    // On a table a pair acts now only where it approaches, or touches at rest relative to each
    // other (to rounding) with friction pressing it together: one that separates, however the
    // cloth slows it, has no contact now.
    if (table_on)
      return detail::held_or_approaching(v, other_velocity, a - other_acceleration, normal);
    return detail::approaching(v, other_velocity, normal) ||
           dot(a - other_acceleration, normal) > 0.0 || growth + other_growth > 0.0;
  };
  detail::PairBatch& batch = pair_batch;
  batch.count = 0;
  // The batch's answers: hits (times from now), and pairs outside the exact range, solved again
  // by the scalar rescaled path.
  const auto take = [&](std::size_t k, double t) {
    const std::uint32_t other = batch.other[k];
    const Vec2 offset{batch.sx[k], batch.sy[k]};
    if (acts_now(t, offset, velocity_at(other, time), a, 0.0)) {
      consider(t, EventKind::ball_ball, other, balls[other].version);
    }
  };
  const auto solve_batch = [&] {
    batch.solve(kFarFuture);
    for (std::uint32_t hits = batch.hits; hits != 0; hits &= hits - 1) {
      const auto k = static_cast<std::size_t>(std::countr_zero(hits));
      take(k, batch.t[k]);
    }
    for (std::uint32_t rescales = batch.rescales; rescales != 0; rescales &= rescales - 1) {
      const auto k = static_cast<std::size_t>(std::countr_zero(rescales));
      const detail::Crossing crossing = detail::entry_crossing_rescaled(
          {{batch.sx[k], batch.sy[k]}, {batch.ux[k], batch.uy[k]}, batch.reach[k]}, kFarFuture);
      if (crossing.found) take(k, crossing.t);
    }
    batch.count = 0;
  };
  const auto pair = [&](std::uint32_t other, Vec2 offset) {
    // offset: from the other ball's centre to this one's, at the world's time.
    const BallSlot& o = balls[other];
    const Vec2 other_velocity = velocity_at(other, time);
    const Vec2 other_acceleration = acceleration_of(other);
    const double other_growth = growth_of(other);
    const double other_radius = radius_at(other, time);
    const double reach = radius + other_radius;
    const double limit = horizon();
    if (other_acceleration == a && growth == 0.0 && other_growth == 0.0) {
      // A shared acceleration cancels in the difference: the straight-line quadratic, solved in
      // batches by the pair kernel (the same arithmetic as entry_crossing).
      batch.push(offset, v - other_velocity, reach, other);
      if (batch.full()) solve_batch();
      return;
    }
    // Out of reach within the horizon (the gap can close by at most |u|·h + ½|a|·h² and the
    // growths' share): no quartic to isolate. Most pairs of a ball among pegs are so.
    const double travel =
        limit * (length(v - other_velocity) + 0.5 * length(a - other_acceleration) * limit +
                 growth + other_growth);
    if (length(offset) - reach > 1.0000001 * travel) return;
    const Impact impact = detail::accelerated_ball_ball(
        Ball{offset, radius}, motion, Ball{{}, other_radius},
        Motion{other_velocity, other_acceleration, other_growth}, limit);
    if (impact.hit &&
        acts_now(impact.t, offset, other_velocity, other_acceleration, other_growth)) {
      consider(impact.t, EventKind::ball_ball, other, o.version);
    }
  };
  grid.for_each_neighbour(cell, [&](std::int32_t neighbour) {
    for (std::int32_t j = grid.first_ball(neighbour); j != detail::kNoBall;
         j = grid.next_ball(static_cast<std::uint32_t>(j))) {
      const auto other = static_cast<std::uint32_t>(j);
      if (other == ball) continue;
      if (!movable_ball && !movable(other)) continue;  // nothing can respond
      if (supported_by(handle_of[other] | detail::kBallSupport)) continue;
      if (carries(other, handle_of[ball] | detail::kBallSupport)) continue;  // and the other way
      const Vec2 offset = p - position_at(other, time);
      if (!periodic) {
        pair(other, offset);
      } else if (!few_cells) {
        pair(other, minimum_image(offset));
      } else {
        const Vec2 nearest = minimum_image(offset);
        const Vec2 period = periodic_cell.period();
        for (int kx = -1; kx <= 1; ++kx) {
          for (int ky = -1; ky <= 1; ++ky)
            pair(other, nearest + Vec2{kx * period.x, ky * period.y});
        }
      }
    }
  });
  solve_batch();
  // (A crossing is never marked clear behind: cross_cell predicts a ball under gravity whole.)
  queue.set(ball, best);
}

bool World::Impl::process_general(const Event& event) {
  const std::uint32_t i = event.owner;
  switch (event.kind) {
    case EventKind::ball_ball: {
      const std::uint32_t j = event.partner;
      if (!balls[j].alive() || balls[j].version != event.partner_version) {
        advance(i, event.time);
        predict(i);
        return false;
      }
      if (table_on) return resolve_pair_on_table(i, j, event.time);
      return gravity_on ? resolve_pair_under_gravity(i, j, event.time)
                        : resolve_pair_under_growth(i, j, event.time);
    }
    case EventKind::ball_wall:
      if (event.partner_version == detail::kSensorEvent)
        return process_sensor(i, event.partner, event.time);
      if (event.partner_version != 0) return process_moving_wall(event);
      if (table_on) return resolve_wall_on_table(i, event.partner, event.time);
      return gravity_on ? resolve_wall_under_gravity(i, event.partner, event.time)
                        : resolve_wall_under_growth(i, event.partner, event.time);
    case EventKind::cell_crossing:
      cross_cell(i, event.partner, event.time, event.partner_version == detail::kClearBehind);
      return false;
    case EventKind::motion_change:
      if (table_on) {
        process_motion_change(event);
        return false;
      }
      // Under gravity, a sliding ball past its support's end (or off a curved support's
      // tangent): it falls.
      advance(i, event.time);
      disturb(i);
      ++balls[i].version;
      predict(i);
      return false;
  }
  return false;
}

World::Impl::WallTouch World::Impl::touch_wall(std::uint32_t ball, std::uint32_t wall,
                                               double t) const {
  const BallSlot& b = balls[ball];
  const Ball shape{b.position, radius_at(ball, t)};
  const Motion motion = motion_of(ball);
  Impact now = detail::time_of_impact(walls[wall], shape, motion, 0.0);
  if (!now.hit) {
    // A contact a sliver ahead that the motion cannot reach (resolve_ball_wall says why), or
    // that the world's clock cannot (a time below its rounding: the event came up now).
    const Impact ahead = detail::time_of_impact(walls[wall], shape, motion, kFarFuture);
    if (ahead.hit && (ahead.a_at == b.position || t + ahead.t == t)) now = ahead;
  }
  const Vec2 point = now.hit ? now.point : detail::nearest_point(walls[wall], b.position);
  const Vec2 normal = now.hit ? now.normal : normalized(point - b.position);
  return {now, point, normal};
}

}  // namespace carom
