// Resting and sliding under gravity (docs/engine.md, "Resting and sliding"). An inelastic ball on
// a floor would bounce infinitely often in finite time, and a pile would do the same among its
// balls: a contact whose bounce would lift the ball less than the rest height off a support that
// stands still ends in contact instead. The ball then slides along the support with gravity's
// part along it (a segment exactly; a curved support along its tangent, until the gap has opened
// by the rest height, when it falls back onto it), or rests where its supports hold gravity up.
// Kinetic energy is taken (the normal speed; all of it in a jam of pressing balls), never given.
// A resting ball costs no events until something disturbs it; then every ball it carried is
// freed too.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "carom/geometry.hpp"
#include "core/bowl_bounce.hpp"
#include "core/impulse.hpp"
#include "engine_tuning.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using detail::Carriage;
using detail::Carried;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

namespace {

// Gravity's part along a support below this fraction of gravity is none: the ball stands (a
// floor at an angle of 2^-40 rad would take longer than the age of the universe to slide a
// radius off under Earth's gravity).
constexpr double kLevel = 0x1p-40;
// An elastic contact rests a ball only when it leaves its support slower than this fraction of
// the rest speed: the rounding of a touch, never a bounce.
constexpr double kElasticRest = 0x1p-26;
// Balls in slow contacts (below the rest speed) at one instant beyond which the balls pressed
// together rest as a jam. A settling pile hands a press on through a few balls at once; this
// many is a cycle. (A fast impact handed on through a pile is no jam: its contacts are not
// counted.)
constexpr std::size_t kJamContacts = 256;

Vec2 without_part_along(Vec2 v, Vec2 unit) { return v - unit * dot(v, unit); }

}  // namespace

detail::Carriage World::Impl::free_carriage() const {
  Carriage carriage;
  carriage.acceleration = def.gravity;
  return carriage;
}

void World::Impl::reset_carriages() {
  if (!gravity_on) {
    carriages.clear();
    carriages.shrink_to_fit();
    return;
  }
  carriages.assign(balls.size(), free_carriage());
}

double World::Impl::rest_speed(std::uint32_t ball) const {
  return std::sqrt(2.0 * length(def.gravity) * def.rest_height * radius_of(ball));
}

bool World::Impl::can_carry(std::uint32_t ball) const {
  return balls[ball].velocity == Vec2{} &&
         (!movable(ball) || carriages[ball].state == Carried::resting);
}

void World::Impl::disturb(std::uint32_t ball) {
  if (movable(ball)) {
    // A free ball carries nothing (a ball that carries or pushes another is resting or
    // sliding), so the look at its neighbours is spared: most contacts are of free balls.
    if (carriages[ball].state == Carried::free) return;
    carriages[ball] = free_carriage();
  }
  wake_carried(ball);
}

void World::Impl::wake_carried(std::uint32_t ball) {
  // The balls it carried (resting or sliding on it, pushed along by it, or pushing it) are freed
  // in turn, and those they carried: each is among its carrier's neighbours.
  std::vector<std::uint32_t> carriers{ball};
  while (!carriers.empty()) {
    const std::uint32_t carrier = carriers.back();
    carriers.pop_back();
    const std::uint32_t key = handle_of[carrier] | detail::kBallSupport;
    grid.for_each_neighbour(grid.cell_of_ball(carrier), [&](std::int32_t cell) {
      for (std::int32_t j = grid.first_ball(cell); j != detail::kNoBall;
           j = grid.next_ball(static_cast<std::uint32_t>(j))) {
        const auto other = static_cast<std::uint32_t>(j);
        if (other == carrier || !movable(other)) continue;
        Carriage& carriage = carriages[other];
        const auto end = carriage.support.begin() + carriage.supports;
        if (std::find(carriage.support.begin(), end, key) == end) continue;
        carriers.push_back(other);
        advance(other, time);
        carriage = free_carriage();
        ++balls[other].version;
        predict(other);
      }
    });
  }
}

void World::Impl::settle(std::uint32_t ball, std::uint32_t support, Vec2 normal,
                         const Carriage& before) {
  wake_carried(ball);  // its course changes: what it carried, or pushed, falls free
  BallSlot& b = balls[ball];
  Carriage& carriage = carriages[ball];
  const Vec2 g = def.gravity;
  const double radius = radius_of(ball);
  const double slow = rest_speed(ball);
  // (Supports stand still: walls, and balls that can_carry.)
  const auto slot_of_support = [&](std::uint32_t key) {
    return slot_of_handle[key & ~detail::kBallSupport];
  };
  const auto rest_on = [&](std::uint32_t first, std::uint32_t second, std::uint8_t count) {
    carriage = Carriage{};
    carriage.state = Carried::resting;
    carriage.support = {first, second};
    carriage.supports = count;
    b.velocity = {};
  };

  // The support it slid on before, where it still touches it: the two may hold it together.
  std::uint32_t other_support = support;
  Vec2 other_normal;
  if (before.state == Carried::sliding && before.support[0] != support) {
    const std::uint32_t key = before.support[0];
    Vec2 toward;
    double gap = 0.0;
    if ((key & detail::kBallSupport) != 0) {
      const std::uint32_t slot = slot_of_support(key);
      toward = minimum_image(position_at(slot, time) - b.position);
      gap = length(toward) - radius - radius_of(slot);
    } else {
      toward = detail::nearest_point(walls[key], b.position) - b.position;
      gap = length(toward) - radius;
    }
    if (gap <= 2.0 * def.rest_height * radius && toward != Vec2{}) {
      other_support = key;
      other_normal = normalized(toward);
    }
  }
  if (other_support != support && dot(b.velocity, other_normal) >= -slow) {
    // Pinned between the two (not moving off the old one faster than the rest speed: a slide
    // along a curved support leaves it a little at its tangent): it slides on one whose slope leads
    // away from the other, and rests where each slope leads into the other (gravity then lies
    // between the normals).
    if (dot(without_part_along(g, normal), other_normal) > 0.0) {
      if (dot(without_part_along(g, other_normal), normal) > 0.0) {
        rest_on(other_support, support, 2);
        return;
      }
      b.velocity = without_part_along(b.velocity, other_normal);
      std::swap(support, other_support);
      std::swap(normal, other_normal);
    }
  }

  // One support: where gravity has no part along it and the ball is slow, it rests.
  const Vec2 along = without_part_along(g, normal);
  const bool level = length(along) <= kLevel * length(g);
  if (level && length(b.velocity) <= slow) {
    rest_on(support, 0, 1);
    return;
  }
  carriage = Carriage{};
  carriage.state = Carried::sliding;
  carriage.acceleration = level ? Vec2{} : along;
  carriage.normal = normal;
  carriage.support = {support, 0};
  carriage.supports = 1;
  const Vec2 tangent = left_normal(normal);
  if ((support & detail::kBallSupport) != 0) {
    // Along the tangent of a ball, in that ball's frame: the offset from its centre.
    const std::uint32_t slot = slot_of_support(support);
    carriage.origin = minimum_image(b.position - position_at(slot, time));
  } else {
    carriage.origin = b.position;
    const detail::Wall& wall = walls[support];
    if (!wall.is_arc) {
      // A segment's interior: it slides along the line until its foot passes an end. (A foot
      // within a curved slide's reach of an end is taken at the end, a point: else a ball at a
      // segment's very end would slide a rounding, fall, land and slide again, for ever.)
      const double at_a = dot(wall.segment.a - b.position, tangent);
      const double at_b = dot(wall.segment.b - b.position, tangent);
      const double rise = def.rest_height * radius;
      const double near_end = std::sqrt(rise * (2.0 * radius + rise));
      if (std::min(std::abs(at_a), std::abs(at_b)) > near_end) {
        carriage.lower = std::min(at_a, at_b);
        carriage.upper = std::max(at_a, at_b);
        return;
      }
    }
  }
  // A curved support (a ball, a point, an arc's outside) of curvature radius R at the centre:
  // along its tangent the gap opens as √(R² + x²) − R, reaching the rest height δ at
  // x = ±√(2Rδ + δ²).
  double reach = radius;
  if ((support & detail::kBallSupport) != 0) {
    reach += radius_of(slot_of_support(support));
  } else if (walls[support].is_arc) {
    const double from_center = length(b.position - walls[support].frame.center);
    if (from_center > walls[support].frame.radius) reach = from_center;
  }
  const double rise = def.rest_height * radius;
  const double half_width = std::sqrt(rise * (2.0 * reach + rise));
  carriage.lower = -half_width;
  carriage.upper = half_width;
}

bool World::Impl::push_along(std::uint32_t slider, std::uint32_t pushed, Vec2 normal) {
  if (!movable(slider) || !movable(pushed)) return false;
  Carriage& s = carriages[slider];
  Carriage& f = carriages[pushed];
  if (s.state != Carried::sliding || s.supports != 1 || f.state != Carried::free) return false;
  const std::uint32_t key = s.support[0];
  if ((key & detail::kBallSupport) != 0 &&
      !can_carry(slot_of_handle[key & ~detail::kBallSupport])) {
    return false;
  }
  // The contact forces λs (from the support, along −ns) and λ (between the two, along −n on
  // the slider and +n on the pushed ball) that keep the slider on its support and the two
  // touching: a_s = g − (λs·ns + λ·n)/m_s, a_f = g + λ·n/m_f, with a_s·ns = 0 and
  // (a_s − a_f)·n = 0. Both must push (≥ 0), else the two part of themselves.
  const Vec2 g = def.gravity;
  const Vec2 ns = s.normal;
  const double c = dot(ns, normal);
  const double inverse_s = species_of(slider).inverse_mass;
  const double inverse_f = species_of(pushed).inverse_mass;
  const double denominator = (c * c - 1.0) * inverse_s - inverse_f;
  if (!(denominator < 0.0)) return false;
  const double lambda = c * dot(g, ns) / denominator;
  const double lambda_s = dot(g, ns) / inverse_s - lambda * c;
  if (!(lambda > 0.0) || !(lambda_s >= 0.0) || !std::isfinite(lambda)) return false;
  wake_carried(slider);  // its course changes
  s.acceleration = g - (ns * lambda_s + normal * lambda) * inverse_s;
  s.acceleration -= ns * dot(s.acceleration, ns);  // (exactly along the support)
  s.support[1] = handle_of[pushed] | detail::kBallSupport;
  s.supports = 2;
  // The pushed ball slides along the slider's tangent, in the slider's frame, until the gap
  // opens by the rest height.
  f = Carriage{};
  f.state = Carried::sliding;
  f.acceleration = g + normal * (lambda * inverse_f);
  f.normal = -normal;
  f.origin = minimum_image(balls[pushed].position - balls[slider].position);
  f.support = {handle_of[slider] | detail::kBallSupport, 0};
  f.supports = 1;
  const double rise = def.rest_height * radius_of(pushed);
  const double reach = radius_of(slider) + radius_of(pushed);
  f.upper = std::sqrt(rise * (2.0 * reach + rise));
  f.lower = -f.upper;
  return true;
}

bool World::Impl::meet_on_support(std::uint32_t slider, std::uint32_t other, Vec2 normal) {
  if (!movable(slider) || !movable(other)) return false;
  const Carriage& s = carriages[slider];
  const Carriage& o = carriages[other];
  // (A sloping wall only: on a level one, acceleration zero, a jam that stops is held up; over a
  // ball of a pile it stops as ever, the pile settling by such jams.)
  if (s.state != Carried::sliding || s.supports != 1 || s.acceleration == Vec2{}) return false;
  const std::uint32_t key = s.support[0];
  if ((key & detail::kBallSupport) != 0) return false;
  const Vec2 ns = s.normal;
  const double c = dot(ns, normal);
  BallSlot& a = balls[slider];
  BallSlot& b = balls[other];
  if (o.state == Carried::free && !walls[key].is_arc) {
    // A free ball that touches the slider's segment too, not leaving it, slides on it as well.
    const Vec2 toward = detail::nearest_point(walls[key], b.position) - b.position;
    const double gap = length(toward) - radius_of(other);
    if (gap <= 2.0 * def.rest_height * radius_of(other) && toward != Vec2{}) {
      const Vec2 wall_normal = normalized(toward);
      if (dot(wall_normal, ns) > 1.0 - 0x1p-40 && dot(b.velocity, wall_normal) >= 0.0) {
        b.velocity = without_part_along(b.velocity, wall_normal);
        settle(other, key, wall_normal, Carriage{o});
      }
    }
  }
  const double inverse_s = species_of(slider).inverse_mass;
  const double inverse_o = species_of(other).inverse_mass;
  const double approach = std::max(0.0, dot(a.velocity - b.velocity, normal));
  double impulse = 0.0;
  if (o.state == Carried::free) {
    // The limit of the slow contacts handed back and forth at this instant between the two balls
    // and the support (each taking the normal speed) is one impulse P along the normal n, whose
    // part along the support's normal ns the support bears: the slider keeps to its line and the
    // two stop approaching. With c = n·ns < 0 the impulse presses the slider into its support
    // (else the support takes no part, and this is no such press).
    if (!(c < 0.0)) return false;
    impulse = approach / ((1.0 - c * c) * inverse_s + inverse_o);
  } else if (o.state == Carried::sliding && o.supports == 1 && o.support[0] == key &&
             !walls[key].is_arc && dot(o.normal, ns) > 1.0 - 0x1p-40) {
    // Both slide along one segment: a contact along the line, taking the approach (the segment
    // bears the rest), so that they slide on at one speed.
    impulse = approach / ((1.0 - c * c) * (inverse_s + inverse_o));
  } else {
    return false;
  }
  if (!std::isfinite(impulse)) return false;
  wake_carried(slider);  // their courses change
  a.velocity -= without_part_along(normal, ns) * (impulse * inverse_s);
  a.velocity = without_part_along(a.velocity, ns);  // (exactly along the support)
  if (o.state == Carried::free) {
    b.velocity += normal * (impulse * inverse_o);
  } else {
    wake_carried(other);
    b.velocity += without_part_along(normal, o.normal) * (impulse * inverse_o);
    b.velocity = without_part_along(b.velocity, o.normal);
  }
  return true;
}

bool World::Impl::hold_each_other(std::uint32_t i, std::uint32_t j, bool only_slow) {
  // A jam of pressing balls (one pushed by a second into a wall or a third) rests as it stands,
  // each on the other and on what it stood on. Only kinetic energy is taken.
  for (const std::uint32_t ball : {i, j}) {
    if (only_slow && movable(ball) && length(balls[ball].velocity) > rest_speed(ball)) {
      return false;
    }
  }
  // A ball at rest already stays as it is (the other rests on it); one that moved stops, and
  // what it carried falls free.
  const bool still_i = can_carry(i);
  const bool still_j = can_carry(j);
  if (!still_i) wake_carried(i);
  if (!still_j) wake_carried(j);
  for (const auto& [ball, other] : {std::pair{i, j}, std::pair{j, i}}) {
    if (!movable(ball) || (ball == i ? still_i : still_j)) continue;
    Carriage& carriage = carriages[ball];
    const std::uint32_t leaning_on = handle_of[other] | detail::kBallSupport;
    // What it stood on, where that still stands (a wall, or a ball that can carry).
    std::uint32_t standing_on = leaning_on;
    if (carriage.state != Carried::free && carriage.support[0] != leaning_on) {
      const std::uint32_t key = carriage.support[0];
      if ((key & detail::kBallSupport) == 0 ||
          can_carry(slot_of_handle[key & ~detail::kBallSupport])) {
        standing_on = key;
      }
    }
    carriage = Carriage{};
    carriage.state = Carried::resting;
    carriage.support = {leaning_on, standing_on};
    carriage.supports = standing_on == leaning_on ? 1 : 2;
    balls[ball].velocity = {};
  }
  return true;
}

bool World::Impl::move_together(std::uint32_t i, std::uint32_t j, double t) {
  // The limit of slow inelastic contacts handed back and forth through touching balls is one
  // velocity for all (exactly so along a row): momentum is kept and kinetic energy only taken.
  // Stopping them instead would leave them hanging in the air.
  std::vector<std::uint32_t> group{i, j};
  for (std::size_t k = 0; k < group.size(); ++k) {
    const std::uint32_t member = group[k];
    if (!movable(member) || carriages[member].state != Carried::free) return false;
    if (group.size() > kJamContacts) return false;
    bool grounded = false;
    grid.for_each_neighbour(grid.cell_of_ball(member), [&](std::int32_t cell) {
      for (std::int32_t n = grid.first_ball(cell); n != detail::kNoBall;
           n = grid.next_ball(static_cast<std::uint32_t>(n))) {
        const auto other = static_cast<std::uint32_t>(n);
        if (std::find(group.begin(), group.end(), other) != group.end()) continue;
        if (!balls_meet(member, other)) continue;  // it passes through: no part of the group
        const double reach = radius_of(member) + radius_of(other);
        const double gap =
            length(minimum_image(position_at(other, t) - position_at(member, t))) - reach;
        if (gap > def.rest_height * reach) continue;
        if (!movable(other) || carriages[other].state != Carried::free) grounded = true;
        group.push_back(other);
      }
    });
    if (grounded) return false;
  }
  Vec2 momentum;
  double mass = 0.0;
  for (const std::uint32_t member : group) {
    advance(member, t);
    momentum += balls[member].velocity * species_of(member).mass;
    mass += species_of(member).mass;
  }
  const Vec2 together = momentum / mass;
  for (const std::uint32_t member : group) {
    balls[member].velocity = together;
    ++balls[member].version;
  }
  for (const std::uint32_t member : group) predict_under_gravity(member);
  return true;
}

bool World::Impl::supports_hold(std::uint32_t ball) const {
  const Carriage& carriage = carriages[ball];
  const std::uint32_t me = handle_of[ball] | detail::kBallSupport;
  const auto lists = [&](std::uint32_t other, std::uint32_t key) {
    const Carriage& c = carriages[other];
    const auto end = c.support.begin() + c.supports;
    return std::find(c.support.begin(), end, key) != end;
  };
  // A resting ball's supports all; a sliding ball's first (its second is a ball it pushes).
  const std::uint8_t count = carriage.state == Carried::resting ? carriage.supports : 1;
  for (std::uint8_t k = 0; k < count; ++k) {
    const std::uint32_t key = carriage.support[k];
    if ((key & detail::kBallSupport) == 0) continue;  // walls stay
    const std::uint32_t other = slot_of_handle[key & ~detail::kBallSupport];
    if (!balls[other].alive()) return false;
    if (can_carry(other)) continue;
    // Two balls holding each other up, or a ball pushed along by a slider.
    if (movable(other) && carriages[other].state != Carried::free && lists(other, me)) continue;
    return false;
  }
  return true;
}

bool World::Impl::jammed(double t, std::uint32_t i, std::uint32_t j, bool inelastic) {
  // (One instant to a few roundings of the clock: a cycle of contacts may creep by an ulp.)
  if (!(std::abs(t - jam_time) <= 0x1p-44 * std::abs(t))) {
    jam_time = t;
    jam_balls.clear();
    jam_slides = 0;
  }
  // A ball pressed between two others (or a ball and a wall) would pass the press back and forth
  // infinitely often at this instant, each time slower by the restitution: the three are a jam.
  // (Elastic contacts hand a press on and end by themselves: a row of touching balls hit slowly
  // passes the hit along once.)
  const auto seen = [&](std::uint32_t ball) {
    return std::find(jam_balls.begin(), jam_balls.end(), handle_of[ball]) != jam_balls.end();
  };
  if (inelastic && (seen(i) || seen(j))) return true;
  jam_balls.push_back(handle_of[i]);
  if (j != i) jam_balls.push_back(handle_of[j]);
  return jam_balls.size() > kJamContacts;
}

bool World::Impl::resolve_wall_under_gravity(std::uint32_t i, std::uint32_t wall, double t) {
  advance(i, t);
  BallSlot& a = balls[i];
  const auto [now, point, normal] = touch_wall(i, wall, t);
  const double approach = dot(a.velocity, normal);
  const bool in_bowl = detail::inside_arc(walls[wall], a.position);
  const bool movable_ball = movable(i);
  const Carriage before = movable_ball ? carriages[i] : Carriage{};
  const double restitution = collided_recently(i, t) ? 1.0 : restitution_of(i);
  bool resolved = false;
  if (approach > 0.0 || (in_bowl && now.hit)) {
    double speed_change = 0.0;
    if (in_bowl) {
      const detail::BowlBounce bounce = detail::bounce_inside_arc(a.velocity, normal, restitution);
      a.velocity = bounce.velocity;
      speed_change = bounce.normal_speed_change;
    } else {
      speed_change = detail::wall_speed_change(approach, restitution);
      a.velocity -= normal * speed_change;
    }
    resolved = speed_change > 0.0;
    if (resolved) record_ball_wall(i, wall, t, point, normal, approach, speed_change);
  }
  // Whether gravity presses the ball into the wall, or its own acceleration does (a ball sliding
  // down a slope into an upright wall, or pushed into it by another).
  const bool bears = dot(def.gravity, normal) > 0.0 || dot(before.acceleration, normal) > 0.0;
  // Whether the wall alone holds the ball up where it touches: gravity presses it in and has no
  // part along it.
  const bool level =
      dot(def.gravity, normal) > 0.0 &&
      length(without_part_along(def.gravity, normal)) <= kLevel * length(def.gravity);
  const bool jam =
      movable_ball && now.hit && approach <= rest_speed(i) && jammed(t, i, i, restitution < 1.0);
  // (A jam against a wall, as in resolve_pair_under_gravity. Against a wall it bears on that
  // cannot hold it alone, a slope, an inelastic ball slides on instead, below: no ball rests on a
  // frictionless slope, and one resting there on the wall alone would stay for ever, since a
  // wall never moves to wake it. The press it hands back to the ball that pressed it makes that
  // pair a jam. Past kJamContacts such jams at this instant it rests: the press may be handed
  // round and round.)
  const bool slides_on =
      jam && !in_bowl && !level && bears && restitution < 1.0 && jam_slides < kJamContacts;
  if (slides_on) ++jam_slides;
  if (jam && !slides_on) {
    wake_carried(i);
    carriages[i] = Carriage{};
    carriages[i].state = Carried::resting;
    carriages[i].support = {wall, 0};
    carriages[i].supports = 1;
    a.velocity = {};
    ++a.version;
    predict(i);
    return false;
  }
  if (movable_ball && (resolved || now.hit)) {
    // What is left of the normal speed, leaving the wall; a support bears the ball where gravity
    // presses it in.
    const double leaving = -dot(a.velocity, normal);
    const double slow = rest_speed(i) * (restitution < 1.0 ? 1.0 : kElasticRest);
    if (bears && leaving <= slow) {
      if (!in_bowl) {
        a.velocity = without_part_along(a.velocity, normal);
        settle(i, wall, normal, before);
      } else if (length(without_part_along(def.gravity, normal)) <= kLevel * length(def.gravity) &&
                 length(a.velocity) <= rest_speed(i)) {
        // At the bottom of a bowl, slow: at rest there.
        wake_carried(i);
        carriages[i] = Carriage{};
        carriages[i].state = Carried::resting;
        carriages[i].support = {wall, 0};
        carriages[i].supports = 1;
        a.velocity = {};
      } else {
        disturb(i);
      }
    } else {
      disturb(i);
    }
    ++a.version;
  }
  predict(i);
  return resolved;
}

bool World::Impl::resolve_pair_under_gravity(std::uint32_t i, std::uint32_t j, double t) {
  advance(i, t);
  advance(j, t);
  BallSlot& a = balls[i];
  BallSlot& b = balls[j];
  const Vec2 between = minimum_image(b.position - a.position);
  const Vec2 normal = between == Vec2{} ? normalized(a.velocity - b.velocity) : normalized(between);
  // (An approach within the rounding of the velocities is none: an impulse that small changes
  // nothing, and the pair would meet again at once, for ever.)
  const double approach = detail::approaching(a.velocity, b.velocity, normal)
                              ? dot(a.velocity - b.velocity, normal)
                              : 0.0;
  const bool pressing = dot(acceleration_of(i) - acceleration_of(j), normal) > 0.0;
  if (!(approach > 0.0) && !pressing) {
    // A graze, or a rounding past the touch.
    predict_under_gravity(i);
    predict_under_gravity(j);
    return false;
  }
  if (approach <= std::min(rest_speed(i), rest_speed(j)) &&
      jammed(t, i, j, pair_restitution(i, j, t) < 1.0)) {
    // Slow contacts that keep handing a press on at one instant: a jam of several balls (the
    // engine solves no chains of contact forces). In flight the balls move on together; on a
    // support, it rests as it stands.
    if (move_together(i, j, t)) return false;
    // A ball sliding down a sloping wall, pressed into it by a free ball or met by one sliding on
    // the same segment, slides on: the wall bears the press, and the two, no longer approaching,
    // part, or the slider pushes the free ball along. Else they rest as they stand.
    // (Past kJamContacts such jams at this instant, they rest: the press may be handed round
    // and round between balls that slide on.)
    const bool slides_on = jam_slides < kJamContacts &&
                           (meet_on_support(i, j, normal) || meet_on_support(j, i, -normal));
    if (slides_on) ++jam_slides;
    // (Pressed together still? The carriages may have changed.)
    const bool still_pressing = dot(acceleration_of(i) - acceleration_of(j), normal) > 0.0;
    if (!slides_on || (still_pressing && !push_along(i, j, normal) && !push_along(j, i, -normal))) {
      hold_each_other(i, j, false);
    }
    ++a.version;
    ++b.version;
    predict_under_gravity(i);
    predict_under_gravity(j);
    return false;
  }
  const double restitution = pair_restitution(i, j, t);
  const Carriage before_i = movable(i) ? carriages[i] : Carriage{};
  const Carriage before_j = movable(j) ? carriages[j] : Carriage{};

  // A ball pressed onto a slow carried ball with no acceleration of its own (on a level floor):
  // that ball comes to rest first, so that it can bear the other.
  const auto stand_still = [&](std::uint32_t ball) {
    if (!movable(ball) || carriages[ball].state != Carried::sliding) return;
    if (carriages[ball].acceleration != Vec2{} || length(balls[ball].velocity) > rest_speed(ball))
      return;
    wake_carried(ball);
    // (A ball that carried its own support, through a ring of balls holding each other up, fell
    // with the ring.)
    if (carriages[ball].state != Carried::sliding) return;
    carriages[ball].state = Carried::resting;
    balls[ball].velocity = {};
    ++balls[ball].version;
  };
  if (pressing) {
    // Gravity presses the upper ball onto the lower.
    const double downward = dot(def.gravity, normal);  // > 0: i is above j
    if (downward > 0.0) stand_still(j);
    if (downward < 0.0) stand_still(i);
  }

  // A movable ball pressed by gravity onto one that can carry it (moving without acceleration):
  // the carrier, standing on its own supports, answers as a wall would; a bounce too low to
  // leave ends in contact.
  for (const bool first : {true, false}) {
    const std::uint32_t mover = first ? i : j;
    const std::uint32_t still = first ? j : i;
    const Vec2 toward = first ? normal : -normal;
    if (!movable(mover) || can_carry(mover) || !can_carry(still)) continue;
    if (!(dot(def.gravity, toward) > 0.0)) continue;
    BallSlot& m = balls[mover];
    const Vec2 carried_by = balls[still].velocity;
    const double closing = dot(m.velocity - carried_by, toward);
    const double speed = std::max(0.0, closing);
    const double slow = rest_speed(mover) * (restitution < 1.0 ? 1.0 : kElasticRest);
    if (restitution * speed > slow) break;
    // Taking the normal speed in the carrier's frame takes kinetic energy when the carrier stands
    // still; when it moves, only where it does (else the two bounce as two balls).
    const Vec2 kept = m.velocity - toward * closing;
    if (length_squared(kept) > length_squared(m.velocity) * (1.0 + 0x1p-40)) break;
    if (speed > 0.0) {
      if (def.collapse_time > 0.0) last_contact_times[mover] = t;
      if (contact_wanted()) {
        const double impulse = speed * species_of(mover).mass;
        record_ball_ball(i, j, t, between, normal, approach, impulse);
      }
    }
    m.velocity = kept;
    settle(mover, handle_of[still] | detail::kBallSupport, toward, first ? before_i : before_j);
    ++a.version;
    ++b.version;
    predict_under_gravity(i);
    predict_under_gravity(j);
    return speed > 0.0;
  }

  bool resolved = false;
  if (!(approach > 0.0)) {
    // Pressed together with no approach, and neither can carry the other (each accelerates): two
    // slow balls hold each other up; else a ball sliding on a support pushes a free one along;
    // else the two stop where they stand, a jam that rests until disturbed (the engine solves no
    // chains of contact forces; docs/engine.md, "Resting and sliding").
    if (!hold_each_other(i, j, true) && !push_along(i, j, normal) && !push_along(j, i, -normal)) {
      hold_each_other(i, j, false);
    }
  } else {
    double e = restitution;
    // Below the rest speed two balls part no more (inelastic collapse of a row along a floor
    // would otherwise bounce them infinitely often).
    if (e < 1.0 && e * approach <= std::min(rest_speed(i), rest_speed(j))) e = 0.0;
    const double inverse_a = species_of(i).inverse_mass;
    const double inverse_b = species_of(j).inverse_mass;
    const double impulse = detail::normal_impulse(approach, inverse_a, inverse_b, e);
    detail::apply_impulse(a.velocity, b.velocity, normal, impulse, inverse_a, inverse_b);
    if (def.collapse_time > 0.0) {
      last_contact_times[i] = t;
      last_contact_times[j] = t;
    }
    if (contact_wanted()) record_ball_ball(i, j, t, between, normal, approach, impulse);
    resolved = true;
    if (inverse_a == 0.0 ? a.velocity != Vec2{} : (inverse_b == 0.0 && b.velocity != Vec2{})) {
      mover_met = true;
    }
    if (inverse_a != 0.0) disturb(i);
    if (inverse_b != 0.0) disturb(j);
  }
  ++a.version;
  ++b.version;
  predict_under_gravity(i);
  predict_under_gravity(j);
  return resolved;
}

}  // namespace carom
