#include "detectors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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
                                                       Vec2 lower, Vec2 upper, double min_depth) {
  sorted_breaks_.assign(breaks.begin(), breaks.end());
  std::stable_sort(sorted_breaks_.begin(), sorted_breaks_.end(),
                   [](const PathBreak& a, const PathBreak& b) {
                     return a.ball != b.ball ? a.ball < b.ball : a.fraction < b.fraction;
                   });
  // Each disk's path as straight pieces in time order, its pieces contiguous (first_piece_), and
  // the box that holds the whole path, so that the grid pairs disks, not pieces: a disk that an
  // event-driven engine bounced hundreds of times in a step (a heap under gravity) then costs in
  // proportion to its pieces, not to the product of its and each neighbour's.
  pieces_.clear();
  first_piece_.assign(start.size() + 1, 0);
  boxes_.resize(start.size());
  std::size_t next_break = 0;
  for (std::uint32_t i = 0; i < start.size(); ++i) {
    first_piece_[i] = static_cast<std::uint32_t>(pieces_.size());
    double t = 0.0;
    Vec2 at = start[i];
    Vec2 low = at;
    Vec2 high = at;
    const auto reach_to = [&](Vec2 p) {
      low = {std::min(low.x, p.x), std::min(low.y, p.y)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    };
    for (; next_break < sorted_breaks_.size() && sorted_breaks_[next_break].ball == i;
         ++next_break) {
      const PathBreak& bend = sorted_breaks_[next_break];
      pieces_.push_back({i, t, bend.fraction, at, bend.position});
      reach_to(bend.position);
      t = bend.fraction;
      at = bend.position;
    }
    pieces_.push_back({i, t, 1.0, at, end[i]});
    reach_to(end[i]);
    // A non-finite point makes the box non-finite (std::min and std::max may drop a NaN, so test
    // the points themselves), and the grid leaves the disk out.
    bool finite_path = finite(start[i]) && finite(end[i]);
    for (std::size_t k = first_piece_[i]; k < pieces_.size(); ++k) {
      finite_path = finite_path && finite(pieces_[k].p1);
    }
    const Vec2 reach{radii[i], radii[i]};
    boxes_[i] = finite_path ? Box{low - reach, high + reach} : Box{{kNaN, kNaN}, {kNaN, kNaN}};
  }
  first_piece_[start.size()] = static_cast<std::uint32_t>(pieces_.size());
  grid_.build(boxes_, lower, upper, 2.0 * largest_radius(radii));

  std::vector<PassThrough> found;
  grid_.for_each_overlapping_pair([&](std::uint32_t a, std::uint32_t b) {
    double deepest = -1.0;  // below every depth: no pass yet
    // The two paths' pieces, merged by time: each stretch on which both move in a straight line
    // is the overlap of one piece of each.
    std::uint32_t k = first_piece_[a];
    std::uint32_t l = first_piece_[b];
    while (k < first_piece_[a + 1] && l < first_piece_[b + 1]) {
      const Piece& p = pieces_[k];
      const Piece& q = pieces_[l];
      const double depth = pass_depth(p, q, radii[a], radii[b]);
      deepest = std::max(deepest, depth);
      if (p.t1 < q.t1) {
        ++k;
      } else if (q.t1 < p.t1) {
        ++l;
      } else {
        ++k;
        ++l;
      }
    }
    if (deepest >= min_depth) found.push_back({std::min(a, b), std::max(a, b), deepest});
  });
  std::sort(found.begin(), found.end(), [](const PassThrough& x, const PassThrough& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return found;
}

// How deep two pieces of path went through each other on the stretch of time both cover
// (PassThrough::depth), or −1 when they did not: no stretch, no approaching contact on it, or
// one that left the two overlapping or still approaching at its end.
double Detectors::pass_depth(const Piece& p, const Piece& q, double rp, double rq) {
  const double from = std::max(p.t0, q.t0);
  const double to = std::min(p.t1, q.t1);
  if (!(to > from)) return -1.0;
  const auto at = [](const Piece& piece, double t) {
    const double span = piece.t1 - piece.t0;
    return span > 0.0 ? piece.p0 + (piece.p1 - piece.p0) * ((t - piece.t0) / span) : piece.p0;
  };
  const Vec2 p_from = at(p, from);
  const Vec2 q_from = at(q, from);
  const Vec2 p_move = at(p, to) - p_from;
  const Vec2 q_move = at(q, to) - q_from;
  // The grid skips disks with a non-finite point, so every number here is finite and the swept
  // test (which throws on NaN) accepts them.
  const Impact impact = sweep_ball_ball(Ball{p_from, rp}, p_move, Ball{q_from, rq}, q_move);
  if (!impact.hit || impact.overlapping) return -1.0;
  const Vec2 apart = (q_from + q_move) - (p_from + p_move);
  if (length(apart) < rp + rq) return -1.0;             // caught, late: an overlap
  if (dot(apart, q_move - p_move) <= 0.0) return -1.0;  // they meet at the end: still approaching
  const Vec2 offset = q_from - p_from;
  const Vec2 relative = q_move - p_move;
  const double closest_t = std::clamp(-dot(offset, relative) / length_squared(relative), 0.0, 1.0);
  return 1.0 - length(offset + relative * closest_t) / (rp + rq);
}

bool outside_box(Vec2 position, Vec2 lower, Vec2 upper) noexcept {
  if (!finite(position)) return true;
  return position.x < lower.x || position.x > upper.x || position.y < lower.y ||
         position.y > upper.y;
}

double largest_wall_overlap(std::span<const Vec2> positions, std::span<const double> radii,
                            Vec2 lower, Vec2 upper) noexcept {
  double largest = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec2 p = positions[i];
    const double gap =
        std::min(std::min(p.x - lower.x, upper.x - p.x), std::min(p.y - lower.y, upper.y - p.y));
    // std::max drops a NaN gap (its comparisons are false); outside_box counts those disks.
    largest = std::max(largest, (radii[i] - gap) / radii[i]);
  }
  return largest;
}

double kinetic_energy(std::span<const Vec2> velocities, std::span<const double> masses) noexcept {
  double energy = 0.0;
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    energy += 0.5 * masses[i] * length_squared(velocities[i]);
  }
  return energy;
}

double potential_energy(std::span<const Vec2> positions, std::span<const double> masses,
                        Vec2 gravity, Vec2 origin) noexcept {
  double energy = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    energy -= masses[i] * dot(gravity, positions[i] - origin);
  }
  return energy;
}

}  // namespace carom::peers
