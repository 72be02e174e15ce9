// GrowingPairBatch::solve, the pair kernel of a world whose balls grow. On x86-64 CPUs with AVX2
// four pairs go through one vector operation a step, written with intrinsics (a prediction has
// only 3 to 7 pairs, too few for the compiler's own vectorised loops: pair_batch.cpp says why).
// Each lane does growing_pair_closing's operations, in the same order, each one correctly rounded
// (no fused multiply-add: the intrinsics name every operation, and FMA contraction is off), and
// every comparison has the scalar one's meaning for NaN (the ordered, non-signalling
// predicates): the answers are the same bits (tests/world/growing_pair_batch_tests.cpp).
#include "growing_pair_batch.hpp"

#include "core/growing_pair.hpp"

#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
#include <immintrin.h>

#include "cpu_avx2.hpp"
#define CAROM_GROWING_BATCH_AVX2 1
#endif

namespace carom::detail {
namespace {

#ifdef CAROM_GROWING_BATCH_AVX2

constexpr std::size_t kLanes = 4;
static_assert(GrowingPairBatch::kCapacity % kLanes == 0);

// growing_pair_closing on four pairs at once: the lanes' times (stored to t), and the lanes that
// close and those left undecided as bits 0 to 3.
struct FourClosings {
  std::uint32_t closing;
  std::uint32_t undecided;
};

__attribute__((target("avx2"), always_inline)) inline __m256d magnitude(__m256d x) {
  return _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
}

// |x| > kGrowingUndecided · bound: x clear of the rounding its terms (bounded by `bound`) allow.
__attribute__((target("avx2"), always_inline)) inline __m256d clear_of(__m256d x, __m256d bound) {
  return _mm256_cmp_pd(magnitude(x), _mm256_mul_pd(_mm256_set1_pd(kGrowingUndecided), bound),
                       _CMP_GT_OQ);
}

__attribute__((target("avx2"), always_inline)) inline FourClosings close_four(
    __m256d s_x, __m256d s_y, __m256d u_x, __m256d u_y, __m256d r, __m256d g, double* t) {
  const __m256d zero = _mm256_setzero_pd();
  const __m256d low = _mm256_set1_pd(kGrowingLow);
  const __m256d high = _mm256_set1_pd(kGrowingHigh);
  const __m256d ss = _mm256_add_pd(_mm256_mul_pd(s_x, s_x), _mm256_mul_pd(s_y, s_y));
  const __m256d uu = _mm256_add_pd(_mm256_mul_pd(u_x, u_x), _mm256_mul_pd(u_y, u_y));
  const __m256d rr = _mm256_mul_pd(r, r);
  const __m256d gg = _mm256_mul_pd(g, g);
  const __m256d rg = _mm256_mul_pd(r, g);
  const __m256d su_x = _mm256_mul_pd(s_x, u_x);
  const __m256d su_y = _mm256_mul_pd(s_y, u_y);
  const __m256d a = _mm256_sub_pd(uu, gg);
  const __m256d b = _mm256_sub_pd(_mm256_add_pd(su_x, su_y), rg);
  const __m256d c = _mm256_sub_pd(ss, rr);
  const __m256d in_range = _mm256_and_pd(
      _mm256_and_pd(
          _mm256_and_pd(_mm256_cmp_pd(ss, high, _CMP_LE_OQ), _mm256_cmp_pd(uu, high, _CMP_LE_OQ)),
          _mm256_and_pd(_mm256_cmp_pd(rr, low, _CMP_GE_OQ), _mm256_cmp_pd(rr, high, _CMP_LE_OQ))),
      _mm256_and_pd(_mm256_cmp_pd(gg, low, _CMP_GE_OQ), _mm256_cmp_pd(gg, high, _CMP_LE_OQ)));
  const __m256d b_clear =
      clear_of(b, _mm256_add_pd(_mm256_add_pd(magnitude(su_x), magnitude(su_y)), rg));
  const __m256d a_clear = clear_of(a, _mm256_add_pd(uu, gg));
  const __m256d c_clear = clear_of(c, _mm256_add_pd(ss, rr));
  const __m256d b_negative = _mm256_cmp_pd(b, zero, _CMP_LT_OQ);
  // (The unordered "not" predicates: true for NaN, as the scalar form's `!(x > 0)` is.)
  const __m256d b_not_negative = _mm256_cmp_pd(b, zero, _CMP_NLT_UQ);
  const __m256d a_positive = _mm256_cmp_pd(a, zero, _CMP_GT_OQ);
  const __m256d a_not_positive = _mm256_cmp_pd(a, zero, _CMP_NGT_UQ);
  const __m256d parting = _mm256_and_pd(_mm256_and_pd(b_clear, _mm256_cmp_pd(b, zero, _CMP_GT_OQ)),
                                        _mm256_and_pd(a_clear, a_positive));
  const __m256d bb = _mm256_mul_pd(b, b);
  const __m256d ac = _mm256_mul_pd(a, c);
  const __m256d d = _mm256_sub_pd(bb, ac);
  const __m256d d_clear = clear_of(d, _mm256_add_pd(bb, magnitude(ac)));
  // Decided by its roots: every coefficient clear, not overlapping, no graze.
  const __m256d by_roots =
      _mm256_and_pd(_mm256_and_pd(_mm256_and_pd(c_clear, _mm256_cmp_pd(c, zero, _CMP_NLT_UQ)),
                                  _mm256_and_pd(b_clear, a_clear)),
                    d_clear);
  // Closing now with a real root, or opening now with the growth outrunning the relative speed.
  const __m256d closes = _mm256_and_pd(
      by_roots, _mm256_or_pd(_mm256_and_pd(b_negative, _mm256_cmp_pd(d, zero, _CMP_NLT_UQ)),
                             _mm256_and_pd(b_not_negative, a_not_positive)));
  const __m256d root = _mm256_sqrt_pd(d);
  const __m256d first_root = _mm256_div_pd(c, _mm256_sub_pd(root, b));
  const __m256d second_root =
      _mm256_div_pd(_mm256_add_pd(b, root), _mm256_xor_pd(a, _mm256_set1_pd(-0.0)));
  _mm256_store_pd(t, _mm256_blendv_pd(second_root, first_root, b_negative));
  const __m256d decided = _mm256_and_pd(in_range, _mm256_or_pd(parting, by_roots));
  return {static_cast<std::uint32_t>(_mm256_movemask_pd(_mm256_and_pd(in_range, closes))),
          static_cast<std::uint32_t>(_mm256_movemask_pd(decided)) ^ 0xFU};
}

// The lanes used by `count` pairs (a full batch keeps all 32 bits).
std::uint32_t used_lanes(std::size_t count) {
  return count == GrowingPairBatch::kCapacity ? ~0U : (1U << count) - 1U;
}

__attribute__((target("avx2"))) void solve_avx2(GrowingPairBatch& batch) {
  // The last group's unused lanes get a pair that parts (any finite values would do): their
  // outcomes are never read. Four lanes are always written (the arrays have room): no loop.
  const std::size_t padded = (batch.count + kLanes - 1) / kLanes * kLanes;
  static_assert(GrowingPairBatch::kInputCapacity >= GrowingPairBatch::kCapacity + kLanes);
  const __m256d apart = _mm256_set1_pd(1.0);
  const __m256d half = _mm256_set1_pd(0.5);
  _mm256_storeu_pd(&batch.sx[batch.count], apart);
  _mm256_storeu_pd(&batch.sy[batch.count], apart);
  _mm256_storeu_pd(&batch.ux[batch.count], apart);
  _mm256_storeu_pd(&batch.uy[batch.count], apart);
  _mm256_storeu_pd(&batch.reach[batch.count], half);
  _mm256_storeu_pd(&batch.growth[batch.count], half);
  std::uint32_t closings = 0;
  std::uint32_t undecided = 0;
  for (std::size_t k = 0; k < padded; k += kLanes) {
    const FourClosings four =
        close_four(_mm256_load_pd(&batch.sx[k]), _mm256_load_pd(&batch.sy[k]),
                   _mm256_load_pd(&batch.ux[k]), _mm256_load_pd(&batch.uy[k]),
                   _mm256_load_pd(&batch.reach[k]), _mm256_load_pd(&batch.growth[k]), &batch.t[k]);
    closings |= four.closing << k;
    undecided |= four.undecided << k;
  }
  const std::uint32_t used = used_lanes(batch.count);
  batch.closings = closings & used;
  batch.undecided = undecided & used;
}

#endif

}  // namespace

void GrowingPairBatch::solve() {
#ifdef CAROM_GROWING_BATCH_AVX2
  if (kCpuHasAvx2) {
    solve_avx2(*this);
    return;
  }
#endif
  solve_one_by_one();
}

void GrowingPairBatch::solve_one_by_one() {
  closings = 0;
  undecided = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const GrowingPairClosing closing =
        growing_pair_closing({sx[k], sy[k]}, {ux[k], uy[k]}, reach[k], growth[k]);
    t[k] = closing.t;
    closings |= static_cast<std::uint32_t>(closing.found) << k;
    undecided |= static_cast<std::uint32_t>(!closing.decided) << k;
  }
}

}  // namespace carom::detail
