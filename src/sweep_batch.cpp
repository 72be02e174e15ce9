// The batch form of sweep_ball_ball: the same arithmetic as detail::entry_crossing, written
// without branches so that the loop vectorises. Derivation: docs/derivation.md.
#include "carom/sweep_batch.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "validate.hpp"

namespace carom {
namespace {

constexpr const char* kFunction = "sweep_ball_ball_batch";

struct NamedArray {
  const char* name;
  std::span<const double> values;
  bool radius;  // must be > 0, not only finite
};

// Finds the first bad value and throws; called only after the fast check saw one.
[[noreturn]] void report_bad_value(const BallPairArrays& p) {
  const NamedArray arrays[] = {
      {"pairs.a_x", p.a_x, false},           {"pairs.a_y", p.a_y, false},
      {"pairs.a_radius", p.a_radius, true},  {"pairs.a_move_x", p.a_move_x, false},
      {"pairs.a_move_y", p.a_move_y, false}, {"pairs.b_x", p.b_x, false},
      {"pairs.b_y", p.b_y, false},           {"pairs.b_radius", p.b_radius, true},
      {"pairs.b_move_x", p.b_move_x, false}, {"pairs.b_move_y", p.b_move_y, false},
  };
  for (std::size_t i = 0; i < p.a_x.size(); ++i) {
    for (const NamedArray& array : arrays) {
      const std::string name = std::string(array.name) + "[" + std::to_string(i) + "]";
      if (array.radius) {
        detail::require_positive(kFunction, name.c_str(), array.values[i]);
      } else {
        detail::require_finite(kFunction, name.c_str(), array.values[i]);
      }
    }
  }
  throw std::logic_error("carom::sweep_ball_ball_batch: bad value reported but not found");
}

void check_sizes(const BallPairArrays& p, std::span<double> t) {
  const std::size_t n = p.a_x.size();
  const std::span<const double> others[] = {p.a_y, p.a_radius, p.a_move_x, p.a_move_y, p.b_x,
                                            p.b_y, p.b_radius, p.b_move_x, p.b_move_y};
  for (const auto& other : others) {
    if (other.size() != n) {
      detail::require_in_range(kFunction, "pairs (array sizes differ)",
                               static_cast<double>(other.size()), static_cast<double>(n),
                               static_cast<double>(n), "every array must have a_x's size");
    }
  }
  if (t.size() != n) {
    detail::require_in_range(kFunction, "t.size()", static_cast<double>(t.size()),
                             static_cast<double>(n), static_cast<double>(n),
                             "must equal the number of pairs");
  }
}

}  // namespace

std::size_t sweep_ball_ball_batch(const BallPairArrays& pairs, std::span<double> t) {
  check_sizes(pairs, t);
  const std::size_t n = pairs.a_x.size();
  const double* a_x = pairs.a_x.data();
  const double* a_y = pairs.a_y.data();
  const double* a_r = pairs.a_radius.data();
  const double* a_mx = pairs.a_move_x.data();
  const double* a_my = pairs.a_move_y.data();
  const double* b_x = pairs.b_x.data();
  const double* b_y = pairs.b_y.data();
  const double* b_r = pairs.b_radius.data();
  const double* b_mx = pairs.b_move_x.data();
  const double* b_my = pairs.b_move_y.data();
  double* out = t.data();

  std::size_t hits = 0;
  bool all_valid = true;
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = a_x[i] - b_x[i];
    const double sy = a_y[i] - b_y[i];
    const double ux = a_mx[i] - b_mx[i];
    const double uy = a_my[i] - b_my[i];
    const double reach = a_r[i] + b_r[i];
    const double b = sx * ux + sy * uy;
    const double c = (sx * sx + sy * sy) - reach * reach;
    const double a = ux * ux + uy * uy;
    const double h = sx * uy - sy * ux;
    const double discriminant = a * (reach * reach) - h * h;
    const double root = std::sqrt(discriminant > 0.0 ? discriminant : 0.0);
    const double entry = c / (root - b);
    // Coincident centres moving apart still count as approaching (as in sweep_ball_ball).
    const bool coincident = sx == 0.0 && sy == 0.0 && a > 0.0;
    const bool overlapping_approach = (b < 0.0 || coincident) && c <= 0.0;
    const bool later_hit = b < 0.0 && c > 0.0 && discriminant > 0.0 && entry <= 1.0;
    out[i] = overlapping_approach ? 0.0 : (later_hit ? entry : kNoHit);
    hits += (overlapping_approach || later_hit) ? 1u : 0u;
    // x·0 is 0 for every finite x and NaN for NaN or infinity, so one NaN anywhere makes the
    // probe NaN (a plain sum could overflow for finite values). A radius <= 0 fails below.
    const double probe = a_x[i] * 0.0 + a_y[i] * 0.0 + a_mx[i] * 0.0 + a_my[i] * 0.0 +
                         b_x[i] * 0.0 + b_y[i] * 0.0 + b_mx[i] * 0.0 + b_my[i] * 0.0 +
                         a_r[i] * 0.0 + b_r[i] * 0.0;
    all_valid &= (probe == 0.0) & (a_r[i] > 0.0) & (b_r[i] > 0.0);
  }
  if (!all_valid) report_bad_value(pairs);
  return hits;
}

}  // namespace carom
