#include "detectors.hpp"

#include <algorithm>
#include <cmath>

#include "carom/shapes.hpp"
#include "carom/sweep.hpp"

namespace carom::peers {
namespace {

double largest_radius(std::span<const double> radii) {
  double largest = 0.0;
  for (const double r : radii) largest = std::max(largest, r);
  return largest;
}

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

}  // namespace

double Detectors::largest_overlap(std::span<const Vec2> positions, std::span<const double> radii,
                                  Vec2 lower, Vec2 upper) {
  boxes_.resize(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec2 reach{radii[i], radii[i]};
    boxes_[i] = {positions[i] - reach, positions[i] + reach};
  }
  grid_.build(boxes_, lower, upper, 2.0 * largest_radius(radii));
  double largest = 0.0;
  grid_.for_each_overlapping_pair([&](std::uint32_t i, std::uint32_t j) {
    const double contact = radii[i] + radii[j];
    const double gap = distance(positions[i], positions[j]);
    largest = std::max(largest, (contact - gap) / contact);
  });
  return largest;
}

std::vector<PassThrough> Detectors::find_pass_throughs(std::span<const Vec2> start,
                                                       std::span<const Vec2> end,
                                                       std::span<const double> radii,
                                                       std::span<const PathBreak> breaks,
                                                       Vec2 lower, Vec2 upper) {
  sorted_breaks_.assign(breaks.begin(), breaks.end());
  std::stable_sort(sorted_breaks_.begin(), sorted_breaks_.end(),
                   [](const PathBreak& a, const PathBreak& b) {
                     return a.ball != b.ball ? a.ball < b.ball : a.fraction < b.fraction;
                   });
  pieces_.clear();
  std::size_t next_break = 0;
  for (std::uint32_t i = 0; i < start.size(); ++i) {
    double t = 0.0;
    Vec2 at = start[i];
    for (; next_break < sorted_breaks_.size() && sorted_breaks_[next_break].ball == i;
         ++next_break) {
      const PathBreak& bend = sorted_breaks_[next_break];
      pieces_.push_back({i, t, bend.fraction, at, bend.position});
      t = bend.fraction;
      at = bend.position;
    }
    pieces_.push_back({i, t, 1.0, at, end[i]});
  }

  boxes_.resize(pieces_.size());
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    const Piece& piece = pieces_[k];
    const Vec2 reach{radii[piece.ball], radii[piece.ball]};
    const Vec2 low{std::min(piece.p0.x, piece.p1.x), std::min(piece.p0.y, piece.p1.y)};
    const Vec2 high{std::max(piece.p0.x, piece.p1.x), std::max(piece.p0.y, piece.p1.y)};
    boxes_[k] = {low - reach, high + reach};
  }
  grid_.build(boxes_, lower, upper, 2.0 * largest_radius(radii));

  std::vector<PassThrough> found;
  grid_.for_each_overlapping_pair([&](std::uint32_t k, std::uint32_t l) {
    const Piece& p = pieces_[k];
    const Piece& q = pieces_[l];
    if (p.ball == q.ball) return;
    // The stretch of time both pieces cover; on it both disks move in straight lines.
    const double from = std::max(p.t0, q.t0);
    const double to = std::min(p.t1, q.t1);
    if (!(to > from)) return;
    const auto at = [](const Piece& piece, double t) {
      const double span = piece.t1 - piece.t0;
      return span > 0.0 ? piece.p0 + (piece.p1 - piece.p0) * ((t - piece.t0) / span) : piece.p0;
    };
    const Vec2 p_from = at(p, from);
    const Vec2 q_from = at(q, from);
    const Vec2 p_move = at(p, to) - p_from;
    const Vec2 q_move = at(q, to) - q_from;
    // The grid skips non-finite boxes, so every number here is finite and the swept test (which
    // throws on NaN) accepts them.
    const double rp = radii[p.ball];
    const double rq = radii[q.ball];
    const Impact impact = sweep_ball_ball(Ball{p_from, rp}, p_move, Ball{q_from, rq}, q_move);
    if (!impact.hit || impact.overlapping) return;
    const Vec2 apart = (q_from + q_move) - (p_from + p_move);
    if (length(apart) < rp + rq) return;             // caught, late: an overlap
    if (dot(apart, q_move - p_move) <= 0.0) return;  // they meet at the end: still approaching
    const Vec2 offset = q_from - p_from;
    const Vec2 relative = q_move - p_move;
    const double closest_t =
        std::clamp(-dot(offset, relative) / length_squared(relative), 0.0, 1.0);
    const double depth = 1.0 - length(offset + relative * closest_t) / (rp + rq);
    found.push_back({std::min(p.ball, q.ball), std::max(p.ball, q.ball), depth});
  });
  std::sort(found.begin(), found.end(), [](const PassThrough& x, const PassThrough& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  // A pair listed for several stretches counts once, with its deepest.
  std::size_t kept = 0;
  for (std::size_t k = 0; k < found.size(); ++k) {
    if (kept > 0 && found[kept - 1].a == found[k].a && found[kept - 1].b == found[k].b) {
      found[kept - 1].depth = std::max(found[kept - 1].depth, found[k].depth);
    } else {
      found[kept++] = found[k];
    }
  }
  found.resize(kept);
  return found;
}

bool outside_box(Vec2 position, Vec2 lower, Vec2 upper) noexcept {
  if (!finite(position)) return true;
  return position.x < lower.x || position.x > upper.x || position.y < lower.y ||
         position.y > upper.y;
}

double kinetic_energy(std::span<const Vec2> velocities, std::span<const double> masses) noexcept {
  double energy = 0.0;
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    energy += 0.5 * masses[i] * length_squared(velocities[i]);
  }
  return energy;
}

}  // namespace carom::peers
