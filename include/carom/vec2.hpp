// carom: 2D vector of doubles, everything the time-of-impact and bounce code needs.
// All operations are constexpr except those that take a square root.
#pragma once

#include <cmath>

namespace carom {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2& operator+=(Vec2 o) noexcept {
    x += o.x;
    y += o.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 o) noexcept {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr Vec2& operator*=(double s) noexcept {
    x *= s;
    y *= s;
    return *this;
  }
  constexpr Vec2& operator/=(double s) noexcept {
    x /= s;
    y /= s;
    return *this;
  }
  friend constexpr bool operator==(Vec2, Vec2) noexcept = default;
};

[[nodiscard]] constexpr Vec2 operator+(Vec2 a, Vec2 b) noexcept { return {a.x + b.x, a.y + b.y}; }
[[nodiscard]] constexpr Vec2 operator-(Vec2 a, Vec2 b) noexcept { return {a.x - b.x, a.y - b.y}; }
[[nodiscard]] constexpr Vec2 operator-(Vec2 a) noexcept { return {-a.x, -a.y}; }
[[nodiscard]] constexpr Vec2 operator*(Vec2 a, double s) noexcept { return {a.x * s, a.y * s}; }
[[nodiscard]] constexpr Vec2 operator*(double s, Vec2 a) noexcept { return {a.x * s, a.y * s}; }
[[nodiscard]] constexpr Vec2 operator/(Vec2 a, double s) noexcept { return {a.x / s, a.y / s}; }

[[nodiscard]] constexpr double dot(Vec2 a, Vec2 b) noexcept { return a.x * b.x + a.y * b.y; }

// The z component of the 3D cross product: positive when b is counter-clockwise from a.
[[nodiscard]] constexpr double cross(Vec2 a, Vec2 b) noexcept { return a.x * b.y - a.y * b.x; }

[[nodiscard]] constexpr double length_squared(Vec2 a) noexcept { return dot(a, a); }

// std::hypot avoids overflow and underflow for components near the ends of the double range.
[[nodiscard]] inline double length(Vec2 a) noexcept { return std::hypot(a.x, a.y); }

[[nodiscard]] inline double distance(Vec2 a, Vec2 b) noexcept { return length(b - a); }

// Unit vector in the direction of a; the zero vector stays zero (there is no direction to keep).
// A vector so short that its length would be subnormal, or so long that it would overflow, is
// first scaled by a power of two (exact), so that the quotient stays a unit vector.
[[nodiscard]] inline Vec2 normalized(Vec2 a) noexcept {
  const double len = length(a);
  if (!(len > 0.0)) return {};
  if (len < 0x1p-900 || len > 0x1p+900) [[unlikely]] {
    const Vec2 rescaled = a * (len < 1.0 ? 0x1p+600 : 0x1p-600);
    return rescaled / length(rescaled);
  }
  return a / len;
}

// a turned a quarter turn counter-clockwise (to its left) and clockwise (to its right).
[[nodiscard]] constexpr Vec2 left_normal(Vec2 a) noexcept { return {-a.y, a.x}; }
[[nodiscard]] constexpr Vec2 right_normal(Vec2 a) noexcept { return {a.y, -a.x}; }

// The part of v along axis ("a" component in the tutorial's words). A zero axis gives zero.
[[nodiscard]] constexpr Vec2 project_onto(Vec2 v, Vec2 axis) noexcept {
  const double axis_sq = length_squared(axis);
  return axis_sq > 0.0 ? axis * (dot(v, axis) / axis_sq) : Vec2{};
}

// The part of v along axis's normal ("b" component): v minus its projection onto axis.
[[nodiscard]] constexpr Vec2 project_onto_normal(Vec2 v, Vec2 axis) noexcept {
  const double axis_sq = length_squared(axis);
  return axis_sq > 0.0 ? left_normal(axis) * (cross(axis, v) / axis_sq) : v;
}

// v split into its part along axis and its part across it: along + across == v to rounding.
struct Components {
  Vec2 along;
  Vec2 across;
};

[[nodiscard]] constexpr Components decompose(Vec2 v, Vec2 axis) noexcept {
  return {project_onto(v, axis), project_onto_normal(v, axis)};
}

[[nodiscard]] inline bool is_finite(Vec2 a) noexcept {
  return std::isfinite(a.x) && std::isfinite(a.y);
}

}  // namespace carom
