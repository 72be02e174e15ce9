// Reproducible random inputs for the property and reference tests (fixed seeds).
#pragma once

#include <cstdint>
#include <numbers>
#include <random>

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"

namespace carom::testing {

class RandomCases {
 public:
  explicit RandomCases(std::uint64_t seed) : engine_(seed) {}

  double uniform(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine_);
  }
  // Log-uniform: as many values in [0.01, 0.1] as in [1, 10].
  double log_uniform(double low, double high) {
    return std::exp(uniform(std::log(low), std::log(high)));
  }
  Vec2 point(double half_width) {
    return {uniform(-half_width, half_width), uniform(-half_width, half_width)};
  }
  Ball ball(double half_width) { return {point(half_width), log_uniform(0.05, 3.0)}; }
  // A move that often aims at a target, so that about half the cases hit.
  Vec2 move_towards(Vec2 from, Vec2 target, double spread) {
    const Vec2 aim = target - from + point(spread);
    return aim * uniform(0.2, 2.0);
  }
  Segment segment(double half_width) { return {point(half_width), point(half_width)}; }
  Arc arc(double half_width) {
    const double start = uniform(-10.0, 10.0);
    return {point(half_width), log_uniform(0.2, 8.0), start,
            start + uniform(0.0, 2.0 * std::numbers::pi)};
  }
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace carom::testing
