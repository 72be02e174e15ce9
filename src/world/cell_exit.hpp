// carom internal: when and through which side a ball's centre leaves its grid cell, for
// prediction (prediction_steps.hpp). Written without branches (the signs of a ball's velocity are
// random, and a mispredicted branch costs more than computing both axes), with both axes in one
// SSE2 vector where the CPU has it (every x86-64): one division for the two.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "carom/vec2.hpp"
#include "world_event.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace carom::detail {

struct CellExit {
  double time;         // +infinity when the ball leaves through no side
  std::uint32_t side;  // a CrossingSide; kLeft when it leaves through none
};

// The ball at p moving at v at time `now`; side_x and side_y are where it leaves its cell along
// each axis in the direction it moves (the grid's exit_x(cx, v.x > 0) and exit_y), ±infinity
// for a side never left. An axis the ball does not move along, or whose side is infinite, is
// never left through; of the two the earlier, x on a tie.
[[nodiscard]] inline CellExit cell_exit_scalar(Vec2 p, Vec2 v, double now, double side_x,
                                               double side_y) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const bool up_x = v.x > 0.0;
  const bool up_y = v.y > 0.0;
  // (& and | on the conditions, and the choices made by indexing pairs of values: GCC turns a ?:
  // between doubles into a branch. An exit not taken may divide by zero, harmlessly.)
  const bool leaves_x = (up_x | (v.x < 0.0)) & (std::abs(side_x) != kNever);
  const bool leaves_y = (up_y | (v.y < 0.0)) & (std::abs(side_y) != kNever);
  const double exit_x[2] = {kNever, now + std::max(0.0, (side_x - p.x) / v.x)};
  const double exit_y[2] = {kNever, now + std::max(0.0, (side_y - p.y) / v.y)};
  const double exits[2] = {exit_x[leaves_x], exit_y[leaves_y]};
  const bool through_y = exits[1] < exits[0];
  const std::uint32_t sides[2] = {(leaves_x & up_x) ? kRight : kLeft, up_y ? kUp : kDown};
  return {exits[through_y], sides[through_y]};
}

// The same, bit for bit (tests/core/cell_exit_tests.cpp).
[[nodiscard]] inline CellExit cell_exit(Vec2 p, Vec2 v, double now, double side_x, double side_y) {
#if defined(__SSE2__)
  const __m128d zero = _mm_setzero_pd();
  const __m128d never = _mm_set1_pd(std::numeric_limits<double>::infinity());
  const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7FFFFFFFFFFFFFFF));
  const __m128d side = _mm_set_pd(side_y, side_x);
  const __m128d velocity = _mm_set_pd(v.y, v.x);
  const __m128d up = _mm_cmpgt_pd(velocity, zero);
  // (cmpneq is true for NaN, as != is.)
  const __m128d leaves = _mm_and_pd(_mm_or_pd(up, _mm_cmplt_pd(velocity, zero)),
                                    _mm_cmpneq_pd(_mm_and_pd(side, magnitude), never));
  // max(t, 0) is std::max(0.0, t) for every t: t when t > 0, else 0 (NaN included).
  const __m128d after =
      _mm_max_pd(_mm_div_pd(_mm_sub_pd(side, _mm_set_pd(p.y, p.x)), velocity), zero);
  const __m128d at = _mm_add_pd(_mm_set1_pd(now), after);
  const __m128d exits = _mm_or_pd(_mm_and_pd(leaves, at), _mm_andnot_pd(leaves, never));
  const double exit_x = _mm_cvtsd_f64(exits);
  const double exit_y = _mm_cvtsd_f64(_mm_unpackhi_pd(exits, exits));
  const auto leaving = static_cast<std::uint32_t>(_mm_movemask_pd(leaves));
  const auto upward = static_cast<std::uint32_t>(_mm_movemask_pd(up));
  const bool through_y = exit_y < exit_x;
  // min_sd(y, x) is y when y < x, else x: the earlier, x on a tie (and for NaN, as above).
  const double time = _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(exit_y), _mm_set_sd(exit_x)));
  // The sides by arithmetic, and the choice by a mask: GCC makes a branch of a ?: here, which
  // mispredicts as often as the axis a ball leaves through changes.
  static_assert(kLeft == 0 && kRight == 1 && kDown == 2 && kUp == 3);
  const std::uint32_t side_x_name = leaving & upward & 1U;
  const std::uint32_t side_y_name = kDown + ((upward >> 1) & 1U);
  const std::uint32_t pick_y = 0U - static_cast<std::uint32_t>(through_y);
  return {time, (side_x_name & ~pick_y) | (side_y_name & pick_y)};
#else
  return cell_exit_scalar(p, v, now, side_x, side_y);
#endif
}

}  // namespace carom::detail
