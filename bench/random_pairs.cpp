// carom benchmarks: the random pairs, drawn from std::mt19937_64 with a fixed seed.
#include "random_pairs.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>

namespace carom::bench {
namespace {

// The scene of each pair, in length units (metres for Box2D).
constexpr double kFieldSize = 10.0;  // A's centre lies in [0, kFieldSize)²
constexpr double kMinRadius = 0.1;
constexpr double kMaxRadius = 0.5;
constexpr double kMaxGap = 1.0;  // between the surfaces at the start
// A heads for B, off the line of centres by up to kMaxAimError, and moves up to kMaxMoveA; B
// drifts up to kMaxMoveB in any direction. These three set the hit rate, about one half.
constexpr double kMaxMoveA = 2.0;
constexpr double kMaxAimError = 0.25 * std::numbers::pi;
constexpr double kMaxMoveB = 0.5;

// unit() keeps the top 53 bits of each 64-bit draw: a double's whole significand.
constexpr int kSignificandBits = std::numeric_limits<double>::digits;
constexpr int kDroppedBits = std::numeric_limits<std::uint64_t>::digits - kSignificandBits;

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1), every value a multiple of 2^-53.
  double unit() {
    return static_cast<double>(engine_() >> kDroppedBits) * std::ldexp(1.0, -kSignificandBits);
  }
  double uniform(double low, double high) { return low + (high - low) * unit(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace

BallPairArrays RandomPairs::arrays() const {
  return {a_x, a_y, a_radius, a_move_x, a_move_y, b_x, b_y, b_radius, b_move_x, b_move_y};
}

RandomPairs make_random_pairs(std::size_t count, std::uint64_t seed) {
  Generator random(seed);
  RandomPairs p;
  for (Column* column : {&p.a_x, &p.a_y, &p.a_radius, &p.a_move_x, &p.a_move_y, &p.b_x, &p.b_y,
                         &p.b_radius, &p.b_move_x, &p.b_move_y}) {
    column->resize(count);
  }
  for (std::size_t i = 0; i < count; ++i) {
    p.a_x[i] = random.uniform(0.0, kFieldSize);
    p.a_y[i] = random.uniform(0.0, kFieldSize);
    p.a_radius[i] = random.uniform(kMinRadius, kMaxRadius);
    p.b_radius[i] = random.uniform(kMinRadius, kMaxRadius);

    const double towards_b = random.uniform(0.0, 2.0 * std::numbers::pi);
    const double distance = p.a_radius[i] + p.b_radius[i] + random.uniform(0.0, kMaxGap);
    p.b_x[i] = p.a_x[i] + distance * std::cos(towards_b);
    p.b_y[i] = p.a_y[i] + distance * std::sin(towards_b);

    const double aim = towards_b + random.uniform(-kMaxAimError, kMaxAimError);
    const double move_a = random.uniform(0.0, kMaxMoveA);
    p.a_move_x[i] = move_a * std::cos(aim);
    p.a_move_y[i] = move_a * std::sin(aim);

    // Uniform over the disc of radius kMaxMoveB: the square root spreads the lengths by area.
    const double drift = random.uniform(0.0, 2.0 * std::numbers::pi);
    const double move_b = kMaxMoveB * std::sqrt(random.unit());
    p.b_move_x[i] = move_b * std::cos(drift);
    p.b_move_y[i] = move_b * std::sin(drift);
  }
  return p;
}

const RandomPairs& shared_random_pairs(std::size_t count) {
  static std::map<std::size_t, RandomPairs> made;
  auto found = made.find(count);
  if (found == made.end()) found = made.emplace(count, make_random_pairs(count)).first;
  return found->second;
}

}  // namespace carom::bench
