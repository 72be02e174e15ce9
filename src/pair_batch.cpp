// PairBatch::solve, the world's pair kernel: one function called once a prediction or so, so
// that it can be emitted for several instruction sets (vector_clones.hpp) and run through the
// widest SIMD lanes the machine has. It is compiled with -fno-trapping-math (CMakeLists.txt):
// without it GCC will not turn the loop's selects into vector blends. The flag lets the compiler
// assume no floating-point operation traps, which carom never asks of one; it changes no value.
#include "pair_batch.hpp"

#include <cmath>

#include "exact_range.hpp"
#include "vector_clones.hpp"

namespace carom::detail {

namespace {

// The loop itself, with internal linkage: clang 14 defines a cloned function only under its
// ifunc's own symbol, so an external one (PairBatch::solve) would not link.
CAROM_VECTOR_CLONES void solve_pairs(PairBatch& batch, double horizon) {
  const std::size_t count = batch.count;
  for (std::size_t k = 0; k < count; ++k) {
    // The lane's values first, so that every test below is on plain locals.
    const double s_x = batch.sx[k];
    const double s_y = batch.sy[k];
    const double u_x = batch.ux[k];
    const double u_y = batch.uy[k];
    const double r = batch.reach[k];
    const double b = s_x * u_x + s_y * u_y;  // dot(s, u)
    const double ss = s_x * s_x + s_y * s_y;
    const double uu = u_x * u_x + u_y * u_y;
    const double rr = r * r;
    const double c = ss - rr;
    const double h = s_x * u_y - s_y * u_x;  // cross(s, u)
    const double discriminant = uu * rr - h * h;
    const double hit_time = c / (std::sqrt(discriminant) - b);
    // vector_in_range and square_in_range, on the squares already formed; & and | rather than
    // && and || so that nothing branches.
    const bool s_zero = (s_x == 0.0) & (s_y == 0.0);
    const bool u_zero = (u_x == 0.0) & (u_y == 0.0);
    const bool s_in = ((ss >= kSquareLow) & (ss <= kSquareHigh)) | s_zero;
    const bool u_in = ((uu >= kSquareLow) & (uu <= kSquareHigh)) | u_zero;
    const bool in_range = s_in & u_in & (rr >= kSquareLow) & (rr <= kSquareHigh);
    const bool inside = c <= 0.0;  // already touching and moving inwards: t = 0
    const bool hit = (b < 0.0) & (inside | ((discriminant > 0.0) & (hit_time <= horizon)));
    batch.t[k] = inside ? 0.0 : hit_time;
    // kMiss 0, kHit 1, kRescale 2, as arithmetic rather than branches.
    batch.outcome[k] = static_cast<std::uint8_t>(in_range ? static_cast<int>(hit) : 2);
  }
}

}  // namespace

void PairBatch::solve(double horizon) { solve_pairs(*this, horizon); }

}  // namespace carom::detail
