// PairBatch::solve, the world's pair kernel. On x86-64 CPUs with AVX2 four pairs go through one
// vector operation a step, written with intrinsics: a prediction has only 3 to 7 pairs, too few
// for the compiler's own vectorised loops, which fall back to scalar steps below about eight
// (measured: the same instructions as the scalar loop). Each lane does the scalar loop's
// operations, in the same order, each one correctly rounded (no fused multiply-add: the
// intrinsics name every operation, and FMA contraction is off), and every comparison has the
// scalar one's meaning for NaN (the ordered, non-signalling predicates): the results are the same
// bits (tests/core/pair_batch_tests.cpp holds both paths to the scalar time of impact).
#include "pair_batch.hpp"

#include <cmath>

#include "core/exact_range.hpp"

#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
#include <immintrin.h>

#include "cpu_avx2.hpp"
#define CAROM_PAIR_BATCH_AVX2 1
#endif

namespace carom::detail {
namespace {

// Pair k, one at a time, from its values; its bits of the masks are clear on entry.
void solve_pair(PairBatch& batch, std::size_t k, double s_x, double s_y, double u_x, double u_y,
                double r, double horizon) {
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
  batch.hits |= static_cast<std::uint32_t>(hit & in_range) << k;
  batch.rescales |= static_cast<std::uint32_t>(!in_range) << k;
}

// Pair k of the pushed arrays.
void solve_pushed_pair(PairBatch& batch, std::size_t k, double horizon) {
  solve_pair(batch, k, batch.sx[k], batch.sy[k], batch.ux[k], batch.uy[k], batch.reach[k], horizon);
}

#ifdef CAROM_PAIR_BATCH_AVX2

constexpr std::size_t kLanes = 4;
static_assert(PairBatch::kCapacity % kLanes == 0);

// solve_pair's operations on four pairs at once: the lanes' times (stored to t), and the
// lanes in the exact range and those that hit as bits 0 to 3.
struct FourPairs {
  std::uint32_t in_range;
  std::uint32_t hit;
};
__attribute__((target("avx2"), always_inline)) inline FourPairs solve_four(__m256d s_x, __m256d s_y,
                                                                           __m256d u_x, __m256d u_y,
                                                                           __m256d r, __m256d limit,
                                                                           double* t) {
  const __m256d zero = _mm256_setzero_pd();
  const __m256d low = _mm256_set1_pd(kSquareLow);
  const __m256d high = _mm256_set1_pd(kSquareHigh);
  const __m256d b = _mm256_add_pd(_mm256_mul_pd(s_x, u_x), _mm256_mul_pd(s_y, u_y));
  const __m256d ss = _mm256_add_pd(_mm256_mul_pd(s_x, s_x), _mm256_mul_pd(s_y, s_y));
  const __m256d uu = _mm256_add_pd(_mm256_mul_pd(u_x, u_x), _mm256_mul_pd(u_y, u_y));
  const __m256d rr = _mm256_mul_pd(r, r);
  const __m256d c = _mm256_sub_pd(ss, rr);
  const __m256d h = _mm256_sub_pd(_mm256_mul_pd(s_x, u_y), _mm256_mul_pd(s_y, u_x));
  const __m256d discriminant = _mm256_sub_pd(_mm256_mul_pd(uu, rr), _mm256_mul_pd(h, h));
  const __m256d hit_time = _mm256_div_pd(c, _mm256_sub_pd(_mm256_sqrt_pd(discriminant), b));
  const __m256d s_zero =
      _mm256_and_pd(_mm256_cmp_pd(s_x, zero, _CMP_EQ_OQ), _mm256_cmp_pd(s_y, zero, _CMP_EQ_OQ));
  const __m256d u_zero =
      _mm256_and_pd(_mm256_cmp_pd(u_x, zero, _CMP_EQ_OQ), _mm256_cmp_pd(u_y, zero, _CMP_EQ_OQ));
  const __m256d s_in = _mm256_or_pd(
      _mm256_and_pd(_mm256_cmp_pd(ss, low, _CMP_GE_OQ), _mm256_cmp_pd(ss, high, _CMP_LE_OQ)),
      s_zero);
  const __m256d u_in = _mm256_or_pd(
      _mm256_and_pd(_mm256_cmp_pd(uu, low, _CMP_GE_OQ), _mm256_cmp_pd(uu, high, _CMP_LE_OQ)),
      u_zero);
  const __m256d r_in =
      _mm256_and_pd(_mm256_cmp_pd(rr, low, _CMP_GE_OQ), _mm256_cmp_pd(rr, high, _CMP_LE_OQ));
  const __m256d in_range = _mm256_and_pd(_mm256_and_pd(s_in, u_in), r_in);
  const __m256d inside = _mm256_cmp_pd(c, zero, _CMP_LE_OQ);
  const __m256d meets = _mm256_and_pd(_mm256_cmp_pd(discriminant, zero, _CMP_GT_OQ),
                                      _mm256_cmp_pd(hit_time, limit, _CMP_LE_OQ));
  const __m256d hit =
      _mm256_and_pd(_mm256_cmp_pd(b, zero, _CMP_LT_OQ), _mm256_or_pd(inside, meets));
  _mm256_store_pd(t, _mm256_blendv_pd(hit_time, zero, inside));
  return {static_cast<std::uint32_t>(_mm256_movemask_pd(in_range)),
          static_cast<std::uint32_t>(_mm256_movemask_pd(hit))};
}

// The lanes used by `count` pairs (a full batch keeps all 32 bits).
std::uint32_t used_lanes(std::size_t count) {
  return count == PairBatch::kCapacity ? ~0U : (1U << count) - 1U;
}

__attribute__((target("avx2"))) void solve_avx2(PairBatch& batch, double horizon) {
  // The last group's unused lanes get pairs moving apart (which miss); their outcomes are never
  // read, since the caller reads `count` of them. Four lanes are always written (the arrays have
  // room), whatever the count: no loop, no branch.
  const std::size_t padded = (batch.count + kLanes - 1) / kLanes * kLanes;
  static_assert(PairBatch::kInputCapacity >= PairBatch::kCapacity + kLanes);
  const __m256d apart = _mm256_set1_pd(1.0);
  const __m256d half = _mm256_set1_pd(0.5);
  _mm256_storeu_pd(&batch.sx[batch.count], apart);
  _mm256_storeu_pd(&batch.sy[batch.count], apart);
  _mm256_storeu_pd(&batch.ux[batch.count], apart);
  _mm256_storeu_pd(&batch.uy[batch.count], apart);
  _mm256_storeu_pd(&batch.reach[batch.count], half);
  const __m256d limit = _mm256_set1_pd(horizon);
  std::uint32_t hits = 0;
  std::uint32_t rescales = 0;
  for (std::size_t k = 0; k < padded; k += kLanes) {
    const FourPairs four = solve_four(_mm256_load_pd(&batch.sx[k]), _mm256_load_pd(&batch.sy[k]),
                                      _mm256_load_pd(&batch.ux[k]), _mm256_load_pd(&batch.uy[k]),
                                      _mm256_load_pd(&batch.reach[k]), limit, &batch.t[k]);
    hits |= (four.hit & four.in_range) << k;
    rescales |= (~four.in_range & 0xFU) << k;
  }
  const std::uint32_t used = used_lanes(batch.count);
  batch.hits = hits & used;
  batch.rescales = rescales & used;
}

// Two Vec2s, 16-byte aligned, as one vector: [first.x first.y second.x second.y].
__attribute__((target("avx2"), always_inline)) inline __m256d pair_of(const double* first,
                                                                      const double* second) {
  return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_load_pd(first)), _mm_load_pd(second), 1);
}

// solve_slots: four neighbours' slots a step. The positions and velocities of balls a and c are
// loaded as one vector ([x_a y_a x_c y_c]), those of b and d as another, and an unpack pairs them
// into [x_a x_b x_c x_d] and [y_a y_b y_c y_d]; then slot_pair's operations, in its order. With
// kOneKind every reach is radius + radius, else radius + each neighbour's species' radius. With
// kTwoBalls each lane takes its ball's position, velocity and radius from `first` or `second`
// by its bit of second_lanes: a selection, so the same operations on the same values.
template <bool kOneKind, bool kTwoBalls>
__attribute__((target("avx2"))) void solve_slots_avx2(PairBatch& batch, const BallSlot* slots,
                                                      const SlotQuery& first,
                                                      const SlotQuery& second,
                                                      std::uint32_t second_lanes) {
  const std::size_t count = batch.count;
  const std::size_t padded = (count + kLanes - 1) / kLanes * kLanes;
  // The last group's unused lanes read the ball itself (any slot would do): their outcomes are
  // dropped below.
  for (std::size_t k = 0; k < kLanes; ++k) batch.other[count + k] = first.self;
  const __m256d p_x1 = _mm256_set1_pd(first.p.x);
  const __m256d p_y1 = _mm256_set1_pd(first.p.y);
  const __m256d v_x1 = _mm256_set1_pd(first.v.x);
  const __m256d v_y1 = _mm256_set1_pd(first.v.y);
  const __m256d radius1 = _mm256_set1_pd(first.radius);
  const __m256d at = _mm256_set1_pd(first.now);
  const __m256d limit = _mm256_set1_pd(first.horizon);
  // The second ball's, and which bit of a group's four of second_lanes is each lane's.
  const __m256d p_x2 = _mm256_set1_pd(second.p.x);
  const __m256d p_y2 = _mm256_set1_pd(second.p.y);
  const __m256d v_x2 = _mm256_set1_pd(second.v.x);
  const __m256d v_y2 = _mm256_set1_pd(second.v.y);
  const __m256d radius2 = _mm256_set1_pd(second.radius);
  const __m256i lane_bits = _mm256_set_epi64x(8, 4, 2, 1);
  std::uint32_t hits = 0;
  std::uint32_t rescales = 0;
  for (std::size_t k = 0; k < padded; k += kLanes) {
    __m256d p_x = p_x1;
    __m256d p_y = p_y1;
    __m256d v_x = v_x1;
    __m256d v_y = v_y1;
    __m256d radius = radius1;
    if constexpr (kTwoBalls) {
      const __m256i group = _mm256_set1_epi64x(static_cast<long long>(second_lanes >> k));
      const __m256d of_second =
          _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(group, lane_bits), lane_bits));
      p_x = _mm256_blendv_pd(p_x1, p_x2, of_second);
      p_y = _mm256_blendv_pd(p_y1, p_y2, of_second);
      v_x = _mm256_blendv_pd(v_x1, v_x2, of_second);
      v_y = _mm256_blendv_pd(v_y1, v_y2, of_second);
      radius = _mm256_blendv_pd(radius1, radius2, of_second);
    }
    const BallSlot& a = slots[batch.other[k]];
    const BallSlot& b = slots[batch.other[k + 1]];
    const BallSlot& c = slots[batch.other[k + 2]];
    const BallSlot& d = slots[batch.other[k + 3]];
    const __m256d position_ac = pair_of(&a.position.x, &c.position.x);
    const __m256d position_bd = pair_of(&b.position.x, &d.position.x);
    const __m256d velocity_ac = pair_of(&a.velocity.x, &c.velocity.x);
    const __m256d velocity_bd = pair_of(&b.velocity.x, &d.velocity.x);
    const __m256d o_vx = _mm256_unpacklo_pd(velocity_ac, velocity_bd);
    const __m256d o_vy = _mm256_unpackhi_pd(velocity_ac, velocity_bd);
    const __m256d elapsed =
        _mm256_sub_pd(at, _mm256_set_pd(d.local_time, c.local_time, b.local_time, a.local_time));
    // position + velocity·(now − local_time), then p minus it, and v minus the velocity.
    const __m256d o_x =
        _mm256_add_pd(_mm256_unpacklo_pd(position_ac, position_bd), _mm256_mul_pd(o_vx, elapsed));
    const __m256d o_y =
        _mm256_add_pd(_mm256_unpackhi_pd(position_ac, position_bd), _mm256_mul_pd(o_vy, elapsed));
    __m256d reach = _mm256_add_pd(radius, radius);
    if constexpr (!kOneKind) {
      const Species* kinds = first.species;
      reach =
          _mm256_add_pd(radius, _mm256_set_pd(kinds[d.species].radius, kinds[c.species].radius,
                                              kinds[b.species].radius, kinds[a.species].radius));
    }
    const FourPairs four =
        solve_four(_mm256_sub_pd(p_x, o_x), _mm256_sub_pd(p_y, o_y), _mm256_sub_pd(v_x, o_vx),
                   _mm256_sub_pd(v_y, o_vy), reach, limit, &batch.t[k]);
    hits |= (four.hit & four.in_range) << k;
    rescales |= (~four.in_range & 0xFU) << k;
  }
  const std::uint32_t used = used_lanes(count);
  batch.hits = hits & used;
  batch.rescales = rescales & used;
}

#endif

}  // namespace

void PairBatch::solve(double horizon) {
#ifdef CAROM_PAIR_BATCH_AVX2
  if (kCpuHasAvx2) {
    solve_avx2(*this, horizon);
    return;
  }
#endif
  solve_one_by_one(horizon);
}

void PairBatch::solve_one_by_one(double horizon) {
  hits = 0;
  rescales = 0;
  for (std::size_t k = 0; k < count; ++k) solve_pushed_pair(*this, k, horizon);
}

void PairBatch::solve_slots_one_by_one(const BallSlot* slots, const SlotQuery& query) {
  solve_slots_of_two_one_by_one(slots, query, query, 0);
}

void PairBatch::solve_slots_of_two_one_by_one(const BallSlot* slots, const SlotQuery& first,
                                              const SlotQuery& second, std::uint32_t second_lanes) {
  hits = 0;
  rescales = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const SlotQuery& query = ((second_lanes >> k) & 1U) != 0 ? second : first;
    const BallSlot& neighbour = slots[other[k]];
    const SlotPair pair = slot_pair(neighbour, query.p, query.v, query.now);
    solve_pair(*this, k, pair.s.x, pair.s.y, pair.u.x, pair.u.y, slot_reach(neighbour, query),
               query.horizon);
  }
}

namespace {

// solve_slots and solve_slots_of_two: the AVX2 kernel for one or two balls where the CPU has it,
// for a world of one kind or several; else one pair at a time (which the second ball's lanes,
// none for one ball, only select between).
template <bool kTwoBalls>
void solve_named(PairBatch& batch, const BallSlot* slots, const SlotQuery& first,
                 const SlotQuery& second, std::uint32_t second_lanes) {
#ifdef CAROM_PAIR_BATCH_AVX2
  if (kCpuHasAvx2) {
    if (first.species == nullptr) {
      solve_slots_avx2<true, kTwoBalls>(batch, slots, first, second, second_lanes);
    } else {
      solve_slots_avx2<false, kTwoBalls>(batch, slots, first, second, second_lanes);
    }
    return;
  }
#endif
  batch.solve_slots_of_two_one_by_one(slots, first, second, second_lanes);
}

}  // namespace

void PairBatch::solve_slots(const BallSlot* slots, const SlotQuery& query) {
  solve_named<false>(*this, slots, query, query, 0);
}

void PairBatch::solve_slots_of_two(const BallSlot* slots, const SlotQuery& first,
                                   const SlotQuery& second, std::uint32_t second_lanes) {
  solve_named<true>(*this, slots, first, second, second_lanes);
}

}  // namespace carom::detail
