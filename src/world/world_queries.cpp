// The world's queries (carom/world_query.hpp): ray casts, ball casts and overlap queries, answered
// from the grid. A ball that can be met has its centre within the query's reach plus its radius
// of what is asked about, and lies in its cell grown by the grid's hysteresis, so a query visits
// the cells its region, grown by that margin (and a millionth of a cell), covers — clamped at an
// open world's edges, where the outer cells hold every ball beyond them, and unwrapped in a
// periodic one, where each copy of a cell brings its balls shifted by whole periods.
// docs/queries.md says why this misses nothing.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <tuple>
#include <vector>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "core/validate.hpp"
#include "wall.hpp"
#include "world_impl.hpp"

namespace carom {
namespace {

using detail::kNoBall;

// The helpers below are templates on the world's state (State = World::Impl, World's private
// part, which World's own members name when they call them).

// A rectangle of cells, by column and row; unwrapped (any integers) in a periodic world.
struct CellRange {
  std::int64_t x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  [[nodiscard]] bool holds(std::int64_t x, std::int64_t y) const {
    return x >= x0 && x <= x1 && y >= y0 && y <= y1;
  }
};

std::int64_t floor_division(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

// The grid cells within margin of the segment from a to a + d, piece by piece along it, each
// cell (each copy of a cell, in a periodic world) once: visit(cell, shift) gets the cell and what
// to add to the positions of its balls; after each piece, done(s) is asked whether every answer
// at fractions up to s is final (true stops the walk). Every piece is at most a cell long, so
// the cells it covers stay few; the ranges of successive pieces move one way along each axis (a
// segment's coordinates are monotone), so a cell in the range before is the only repeat to skip.
template <typename State>
class QueryWalk {
 public:
  QueryWalk(const State& w, Vec2 margin) : w_(w), margin_(margin) {}

  template <typename Visit, typename Done>
  void along(Vec2 a, Vec2 d, Visit&& visit, Done&& done) {
    const detail::Grid& grid = w_.grid;
    const double length = carom::length(d);
    if (w_.def.boundary == Boundary::periodic) {
      static_cast<void>(cell_pieces(a, d, 0.0, 1.0, length, visit, done));
      return;
    }
    // An open world's or a box's grid covers a rectangle; beyond it, each part of the segment
    // outside is one piece (it meets only the outer cells), inside it pieces of a cell.
    double s_in = 0.0;
    double s_out = 1.0;
    const bool crosses = clip(a, d, grid.lower(), grid.upper(), s_in, s_out);
    if (!crosses) {
      piece(a, a + d, visit);
      static_cast<void>(done(1.0));
      return;
    }
    if (s_in > 0.0) {
      piece(a, a + d * s_in, visit);
      if (done(s_in)) return;
    }
    if (cell_pieces(a, d, s_in, s_out, length, visit, done)) return;
    if (s_out < 1.0) {
      piece(a + d * s_out, a + d, visit);
      static_cast<void>(done(1.0));
    }
  }

 private:
  // The part of the segment from fractions `from` to `to`, in pieces at most a cell long; true
  // once done() says to stop.
  template <typename Visit, typename Done>
  bool cell_pieces(Vec2 a, Vec2 d, double from, double to, double length, Visit& visit,
                   Done& done) {
    const Vec2 cell = w_.grid.cell_size();
    const double step = std::min(cell.x, cell.y);
    const double span = to - from;
    const auto count = static_cast<std::int64_t>(std::max(std::ceil(span * length / step), 1.0));
    for (std::int64_t k = 0; k < count; ++k) {
      const double s0 = from + span * static_cast<double>(k) / static_cast<double>(count);
      const double s1 = k + 1 == count
                            ? to
                            : from + span * static_cast<double>(k + 1) / static_cast<double>(count);
      piece(a + d * s0, a + d * s1, visit);
      if (done(s1)) return true;
    }
    return false;
  }

  // Liang–Barsky: the part of a + s·d (s in [0, 1]) inside [lower, upper], if any.
  static bool clip(Vec2 a, Vec2 d, Vec2 lower, Vec2 upper, double& s_in, double& s_out) {
    const double starts[2] = {a.x, a.y};
    const double moves[2] = {d.x, d.y};
    const double lows[2] = {lower.x, lower.y};
    const double highs[2] = {upper.x, upper.y};
    for (int axis = 0; axis < 2; ++axis) {
      if (moves[axis] == 0.0) {
        if (starts[axis] < lows[axis] || starts[axis] > highs[axis]) return false;
        continue;
      }
      double t0 = (lows[axis] - starts[axis]) / moves[axis];
      double t1 = (highs[axis] - starts[axis]) / moves[axis];
      if (t0 > t1) std::swap(t0, t1);
      s_in = std::max(s_in, t0);
      s_out = std::min(s_out, t1);
    }
    return s_in <= s_out;
  }

  template <typename Visit>
  void piece(Vec2 p0, Vec2 p1, Visit& visit) {
    const detail::Grid& grid = w_.grid;
    const Vec2 lower{std::min(p0.x, p1.x) - margin_.x, std::min(p0.y, p1.y) - margin_.y};
    const Vec2 upper{std::max(p0.x, p1.x) + margin_.x, std::max(p0.y, p1.y) + margin_.y};
    CellRange range;
    if (w_.def.boundary == Boundary::periodic) {
      const Vec2 origin = grid.lower();
      const Vec2 cell = grid.cell_size();
      range = {static_cast<std::int64_t>(std::floor((lower.x - origin.x) / cell.x)),
               static_cast<std::int64_t>(std::floor((upper.x - origin.x) / cell.x)),
               static_cast<std::int64_t>(std::floor((lower.y - origin.y) / cell.y)),
               static_cast<std::int64_t>(std::floor((upper.y - origin.y) / cell.y))};
    } else {
      range = {grid.column_of(lower.x), grid.column_of(upper.x), grid.row_of(lower.y),
               grid.row_of(upper.y)};
    }
    const std::int64_t nx = grid.nx();
    const std::int64_t ny = grid.ny();
    const Vec2 period = w_.def.boundary == Boundary::periodic ? w_.periodic_cell.period() : Vec2{};
    for (std::int64_t y = range.y0; y <= range.y1; ++y) {
      for (std::int64_t x = range.x0; x <= range.x1; ++x) {
        if (previous_.holds(x, y)) continue;
        const std::int64_t wraps_x = floor_division(x, nx);
        const std::int64_t wraps_y = floor_division(y, ny);
        const auto cell = grid.index(static_cast<std::int32_t>(x - wraps_x * nx),
                                     static_cast<std::int32_t>(y - wraps_y * ny));
        visit(cell, Vec2{static_cast<double>(wraps_x) * period.x,
                         static_cast<double>(wraps_y) * period.y});
      }
    }
    previous_ = range;
  }

  const State& w_;
  Vec2 margin_;
  CellRange previous_;
};

// What a query weighs: the balls of the cells visited and the walls listed there, each wall
// once, or, without a grid to ask, every ball and wall.
template <typename State>
class QueryVisitor {
 public:
  QueryVisitor(const State& w, const QueryFilter& filter) : w_(w), filter_(filter) {
    if (filter.walls) wall_seen_.assign(w.walls.size(), 0);
  }

  // The largest radius a ball can have now (growing balls grow from their settled radii).
  [[nodiscard]] static double largest_radius_now(const State& w) {
    double largest = w.largest_radius;
    if (w.growth_on) largest *= std::max(1.0, 1.0 + w.growth_relative * (w.time - w.growth_start));
    return largest;
  }

  // The margin around a region within which a ball of radius `reach` beyond it may lie filed.
  // A ball's centre lies within its cell grown by the grid's hysteresis, to a rounding (a
  // millionth of a cell covers it); a wall is listed in the cell of each of its points.
  [[nodiscard]] static Vec2 margin(const State& w, Vec2 reach) {
    const Vec2 cell = w.grid.cell_size();
    const Vec2 hysteresis = w.grid.hysteresis();
    const double largest = largest_radius_now(w);
    return {reach.x + largest + hysteresis.x + 1e-6 * cell.x,
            reach.y + largest + hysteresis.y + 1e-6 * cell.y};
  }

  // Calls ball(slot, position) and wall(id) for what the segment from a to a + d, grown by
  // `reach`, may meet, in pieces along it; done(s) as QueryWalk's.
  template <typename Ball, typename WallVisit, typename Done>
  void along(Vec2 a, Vec2 d, Vec2 reach, Ball&& ball, WallVisit&& wall, Done&& done) {
    if (!w_.grid_valid) {
      every(a, d, reach, ball, wall);
      static_cast<void>(done(1.0));
      return;
    }
    // Moving walls are listed in no cell: each is weighed first.
    if (filter_.walls) {
      for (const std::uint32_t id : w_.moving_walls) {
        wall_seen_[id] = 1;
        if (sees_wall(id)) wall(id);
      }
    }
    QueryWalk<State> walk(w_, margin(w_, reach));
    walk.along(
        a, d,
        [&](std::int32_t cell, Vec2 shift) {
          if (filter_.balls) {
            for (std::int32_t j = w_.grid.first_ball(cell); j != kNoBall;
                 j = w_.grid.next_ball(static_cast<std::uint32_t>(j))) {
              const auto slot = static_cast<std::uint32_t>(j);
              ball(slot, w_.position_at(slot, w_.time) + shift);
            }
          }
          if (filter_.walls) {
            for (const std::uint32_t id : w_.grid.walls(cell)) {
              if (wall_seen_[id] != 0) continue;
              wall_seen_[id] = 1;
              if (sees_wall(id)) wall(id);
            }
          }
        },
        done);
  }

  // Whether a ball the geometry found is one the filter lets the query see.
  [[nodiscard]] bool accepts(std::uint32_t slot) const {
    const BallId id = w_.id_of(slot);
    if (id == filter_.ignore) return false;
    if ((w_.filters[w_.infos[slot].filter].category & filter_.mask) == 0) return false;
    return !filter_.accept || filter_.accept(id);
  }

 private:
  // Queries see solid walls: a sensor is nothing a ray or a ball stops at.
  [[nodiscard]] bool sees_wall(std::uint32_t id) const {
    return w_.walls[id].solid() && (w_.filters[w_.walls[id].filter].category & filter_.mask) != 0;
  }

  // Without a grid (no ball yet, or walls added since the last run): every ball at each of its
  // periodic copies near the region, every wall.
  template <typename Ball, typename WallVisit>
  void every(Vec2 a, Vec2 d, Vec2 reach, Ball& ball, WallVisit& wall) {
    const double largest = largest_radius_now(w_);
    const Vec2 lower{std::min(a.x, a.x + d.x) - reach.x - largest,
                     std::min(a.y, a.y + d.y) - reach.y - largest};
    const Vec2 upper{std::max(a.x, a.x + d.x) + reach.x + largest,
                     std::max(a.y, a.y + d.y) + reach.y + largest};
    if (filter_.balls) {
      w_.for_each_live([&](std::uint32_t slot) {
        const Vec2 p = w_.position_at(slot, w_.time);
        if (w_.def.boundary != Boundary::periodic) {
          ball(slot, p);
          return;
        }
        const Vec2 period = w_.periodic_cell.period();
        for (double kx = std::ceil((lower.x - p.x) / period.x);
             kx <= std::floor((upper.x - p.x) / period.x); ++kx) {
          for (double ky = std::ceil((lower.y - p.y) / period.y);
               ky <= std::floor((upper.y - p.y) / period.y); ++ky) {
            ball(slot, p + Vec2{kx * period.x, ky * period.y});
          }
        }
      });
    }
    if (filter_.walls) {
      for (std::uint32_t id = 0; id < w_.walls.size(); ++id) {
        if (sees_wall(id)) wall(id);
      }
    }
  }

  const State& w_;
  const QueryFilter& filter_;
  std::vector<char> wall_seen_;
};

// The order of hits at one fraction: balls before walls, then by handle and by wall id, so that
// the answer never depends on the order cells are visited in.
struct HitOrder {
  double fraction;
  int kind;
  std::uint32_t name;
  friend bool operator<(const HitOrder& a, const HitOrder& b) {
    return std::tie(a.fraction, a.kind, a.name) < std::tie(b.fraction, b.kind, b.name);
  }
};

HitOrder order_of(const QueryHit& hit) {
  return hit.kind == HitKind::ball ? HitOrder{hit.fraction, 0, hit.ball.index}
                                   : HitOrder{hit.fraction, 1, hit.wall};
}

// Keeps the earliest hit by HitOrder.
struct FirstHit {
  QueryHit hit;
  void offer(const QueryHit& candidate) {
    if (!hit || order_of(candidate) < order_of(hit)) hit = candidate;
  }
  [[nodiscard]] bool final_up_to(double s) const { return hit && hit.fraction <= s; }
};

// Whether a centre at p is farther than reach from the segment from o to o + d by more than the
// rounding of the distance: such a ball cannot be met, and the closed form need not be asked.
bool out_of_reach(Vec2 p, Vec2 o, Vec2 d, double reach) {
  const Vec2 op = p - o;
  const double dd = dot(d, d);
  const double along = dd > 0.0 ? std::clamp(dot(op, d) / dd, 0.0, 1.0) : 0.0;
  const double slack =
      1e-9 * (reach + std::abs(op.x) + std::abs(op.y) + std::abs(d.x) + std::abs(d.y));
  const double limit = reach + slack;
  return length_squared(op - d * along) > limit * limit;
}

// A ray against ball `slot` at p: where o + s·d enters it (a ray starting inside sees nothing).
template <typename State>
std::optional<QueryHit> ray_meets_ball(const State& w, std::uint32_t slot, Vec2 p, Vec2 o, Vec2 d) {
  const double r = w.radius_at(slot, w.time);
  if (out_of_reach(p, o, d, r)) return std::nullopt;
  // The ball moving by −d against the fixed point o: the same contact, from the ball's side.
  const Impact impact = sweep_ball_point({p, r}, -d, o);
  if (!impact.hit || impact.overlapping) return std::nullopt;
  QueryHit hit;
  hit.kind = HitKind::ball;
  hit.ball = w.id_of(slot);
  hit.fraction = impact.t;
  hit.normal = impact.normal;
  hit.point = p + impact.normal * r;
  hit.center = hit.point;
  return hit;
}

template <typename State>
std::optional<QueryHit> ray_meets_wall(const State& w, WallId id, Vec2 o, Vec2 d) {
  const detail::RayCrossing crossing = detail::ray_crossing(w.walls[id], o, d);
  if (!crossing.hit) return std::nullopt;
  QueryHit hit;
  hit.kind = HitKind::wall;
  hit.wall = id;
  hit.fraction = crossing.s;
  hit.point = crossing.point;
  hit.normal = crossing.normal;
  hit.center = crossing.point;
  return hit;
}

// Sorted by handle, each once (a periodic world may find a ball at two copies).
template <typename State>
std::vector<BallId> in_handle_order(const State& w, std::vector<std::uint32_t>& slots) {
  std::sort(slots.begin(), slots.end(),
            [&w](std::uint32_t a, std::uint32_t b) { return w.id_of(a).index < w.id_of(b).index; });
  slots.erase(std::unique(slots.begin(), slots.end()), slots.end());
  std::vector<BallId> ids;
  ids.reserve(slots.size());
  for (const std::uint32_t slot : slots) ids.push_back(w.id_of(slot));
  return ids;
}

template <typename State>
std::vector<BallId> balls_in_circle_of(const State& w, Vec2 center, double radius,
                                       const QueryFilter& filter) {
  QueryFilter balls_only = filter;
  balls_only.walls = false;
  QueryVisitor<State> visitor(w, balls_only);
  std::vector<std::uint32_t> found;
  visitor.along(
      center, Vec2{}, Vec2{radius, radius},
      [&](std::uint32_t slot, Vec2 p) {
        const double reach = radius + w.radius_at(slot, w.time);
        if (length_squared(p - center) <= reach * reach && visitor.accepts(slot))
          found.push_back(slot);
      },
      [](WallId) {}, [](double) { return false; });
  return in_handle_order(w, found);
}

}  // namespace

QueryHit World::cast_ray(Vec2 origin, Vec2 translation, const QueryFilter& filter) const {
  constexpr const char* kFunction = "World::cast_ray";
  detail::require_finite(kFunction, "origin", origin);
  detail::require_finite(kFunction, "translation", translation);
  const Impl& w = *impl_;
  QueryVisitor<Impl> visitor(w, filter);
  FirstHit first;
  visitor.along(
      origin, translation, Vec2{},
      [&](std::uint32_t slot, Vec2 p) {
        const std::optional<QueryHit> hit = ray_meets_ball(w, slot, p, origin, translation);
        if (hit && (!first.hit || order_of(*hit) < order_of(first.hit)) && visitor.accepts(slot))
          first.offer(*hit);
      },
      [&](WallId id) {
        if (const std::optional<QueryHit> hit = ray_meets_wall(w, id, origin, translation))
          first.offer(*hit);
      },
      [&](double s) { return first.final_up_to(s); });
  return first.hit;
}

std::vector<QueryHit> World::cast_ray_all(Vec2 origin, Vec2 translation,
                                          const QueryFilter& filter) const {
  constexpr const char* kFunction = "World::cast_ray_all";
  detail::require_finite(kFunction, "origin", origin);
  detail::require_finite(kFunction, "translation", translation);
  const Impl& w = *impl_;
  QueryVisitor<Impl> visitor(w, filter);
  std::vector<QueryHit> hits;
  visitor.along(
      origin, translation, Vec2{},
      [&](std::uint32_t slot, Vec2 p) {
        const std::optional<QueryHit> hit = ray_meets_ball(w, slot, p, origin, translation);
        if (hit && visitor.accepts(slot)) hits.push_back(*hit);
      },
      [&](WallId id) {
        if (const std::optional<QueryHit> hit = ray_meets_wall(w, id, origin, translation))
          hits.push_back(*hit);
      },
      [](double) { return false; });
  std::sort(hits.begin(), hits.end(),
            [](const QueryHit& a, const QueryHit& b) { return order_of(a) < order_of(b); });
  // Each ball once, at its first meeting (a long ray in a periodic world meets its copies).
  std::vector<QueryHit> once;
  once.reserve(hits.size());
  for (const QueryHit& hit : hits) {
    const bool again = std::any_of(once.begin(), once.end(), [&](const QueryHit& kept) {
      return kept.kind == hit.kind && kept.ball == hit.ball && kept.wall == hit.wall;
    });
    if (!again) once.push_back(hit);
  }
  return once;
}

QueryHit World::cast_ball(Vec2 center, double radius, Vec2 translation,
                          const QueryFilter& filter) const {
  constexpr const char* kFunction = "World::cast_ball";
  detail::require_finite(kFunction, "center", center);
  detail::require_positive(kFunction, "radius", radius);
  detail::require_finite(kFunction, "translation", translation);
  const Impl& w = *impl_;
  const Ball moving{center, radius};
  QueryVisitor<Impl> visitor(w, filter);
  FirstHit first;
  visitor.along(
      center, translation, Vec2{radius, radius},
      [&](std::uint32_t slot, Vec2 p) {
        const double r = w.radius_at(slot, w.time);
        if (out_of_reach(p, center, translation, radius + r)) return;
        const Impact impact = sweep_ball_ball(moving, translation, {p, r});
        if (!impact.hit && !impact.overlapping) return;
        QueryHit hit;
        hit.kind = HitKind::ball;
        hit.ball = w.id_of(slot);
        hit.overlapping = impact.overlapping;
        hit.fraction = impact.overlapping ? 0.0 : impact.t;
        // From the obstacle's side: its centre less the normal times the two radii.
        hit.normal = -impact.normal;
        hit.point = p - impact.normal * r;
        hit.center = impact.overlapping ? center : p - impact.normal * (radius + r);
        if ((!first.hit || order_of(hit) < order_of(first.hit)) && visitor.accepts(slot))
          first.offer(hit);
      },
      [&](WallId id) {
        const detail::Wall& wall = w.walls[id];
        const Impact impact = detail::time_of_impact(wall, moving, translation, 1.0);
        if (!impact.hit && !impact.overlapping) return;
        QueryHit hit;
        hit.kind = HitKind::wall;
        hit.wall = id;
        hit.overlapping = impact.overlapping;
        hit.fraction = impact.overlapping ? 0.0 : impact.t;
        hit.normal = -impact.normal;
        // The wall's own point nearest the centre, and the centre a radius back from it.
        const Vec2 at = impact.overlapping ? center : impact.a_at;
        const Vec2 on_wall = detail::nearest_point(wall, at);
        const Vec2 gap = on_wall - at;
        hit.point = on_wall;
        hit.center = impact.overlapping
                         ? center
                         : on_wall - (gap == Vec2{} ? impact.normal : normalized(gap)) * radius;
        first.offer(hit);
      },
      [&](double s) { return first.final_up_to(s); });
  return first.hit;
}

std::vector<BallId> World::balls_at_point(Vec2 point, const QueryFilter& filter) const {
  detail::require_finite("World::balls_at_point", "point", point);
  return balls_in_circle_of(*impl_, point, 0.0, filter);
}

std::vector<BallId> World::balls_in_circle(Vec2 center, double radius,
                                           const QueryFilter& filter) const {
  constexpr const char* kFunction = "World::balls_in_circle";
  detail::require_finite(kFunction, "center", center);
  detail::require_non_negative(kFunction, "radius", radius);
  return balls_in_circle_of(*impl_, center, radius, filter);
}

std::vector<BallId> World::balls_in_box(Vec2 lower, Vec2 upper, const QueryFilter& filter) const {
  constexpr const char* kFunction = "World::balls_in_box";
  detail::require_finite(kFunction, "lower", lower);
  detail::require_finite(kFunction, "upper", upper);
  if (!(lower.x <= upper.x && lower.y <= upper.y)) {
    throw InvalidArgument(kFunction, "upper", detail::vector_text(upper),
                          "must be at or above lower on both axes");
  }
  const Impl& w = *impl_;
  QueryFilter balls_only = filter;
  balls_only.walls = false;
  QueryVisitor<Impl> visitor(w, balls_only);
  const Vec2 middle = (lower + upper) * 0.5;
  const Vec2 half = (upper - lower) * 0.5;
  std::vector<std::uint32_t> found;
  visitor.along(
      middle, Vec2{}, half,
      [&](std::uint32_t slot, Vec2 p) {
        const Vec2 nearest{std::clamp(p.x, lower.x, upper.x), std::clamp(p.y, lower.y, upper.y)};
        const double r = w.radius_at(slot, w.time);
        if (length_squared(nearest - p) <= r * r && visitor.accepts(slot)) found.push_back(slot);
      },
      [](WallId) {}, [](double) { return false; });
  return in_handle_order(w, found);
}

}  // namespace carom
