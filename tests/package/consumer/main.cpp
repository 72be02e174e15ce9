// The smallest useful carom program: two balls meeting head-on. Exits 0 when the answer is right.
#include <carom/bounce.hpp>
#include <carom/sweep.hpp>
#include <cstdio>

int main() {
  const carom::Ball a{{0.0, 0.0}, 1.0};
  const carom::Ball b{{10.0, 0.0}, 1.0};
  const carom::Impact impact = carom::sweep_ball_ball(a, {8.0, 0.0}, b, {-8.0, 0.0});
  // Centres 10 apart close at 16 per step and touch at distance 2: t = 8/16 = 0.5.
  if (!impact.hit || impact.t != 0.5) return 1;
  const carom::BounceResult after = carom::bounce({8.0, 0.0}, 1.0, {-8.0, 0.0}, 1.0, impact.normal);
  std::printf("t = %g, A leaves with (%g, %g)\n", impact.t, after.velocity_a.x, after.velocity_a.y);
  return after.velocity_a.x == -8.0 ? 0 : 1;
}
