// carom internal: what balls of one kind share (radius, mass, restitution), kept once in a
// table rather than in every ball's slot, so that a slot is 48 bytes rather than 64 (a gas of
// equal disks is one species). Design: docs/engine.md, "Memory".
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "carom/bounce.hpp"  // kImmovable

namespace carom::detail {

struct Species {
  double radius = 0.0;
  double mass = 0.0;         // kImmovable (+infinity) for an immovable ball
  double restitution = 1.0;  // the ball's own, or the world's where its BallDef left it unset
  std::uint32_t balls = 0;   // live balls of this species; 0: free, to be reused
  // 1/mass (+0 for an immovable ball), kept: a contact's response would otherwise divide for
  // both balls, on the way from the contact to the two balls' next predictions.
  double inverse_mass = 0.0;

  [[nodiscard]] bool movable() const { return mass != kImmovable; }
};

// Species by number. A ball names its species; equal (radius, mass, restitution), bit for bit,
// share one as long as a small cache of recent kinds finds it, so that a world of a few kinds
// has a few species and one of all-different balls one species a ball (40 bytes, 8 more than
// the fields it replaces). Which number a ball gets never changes a result: only its fields are
// read.
class SpeciesTable {
 public:
  // The species for these fields, counting one more ball of it.
  std::uint32_t acquire(double radius, double mass, double restitution) {
    const Key key = key_of(radius, mass, restitution);
    std::uint32_t& cached = cache_[hash(key)];
    if (cached < table_.size() && table_[cached].balls > 0 && key_of(table_[cached]) == key) {
      ++table_[cached].balls;
      return cached;
    }
    ++live_;
    std::uint32_t id = 0;
    if (free_.empty()) {
      id = static_cast<std::uint32_t>(table_.size());
      table_.emplace_back();
    } else {
      id = free_.back();
      free_.pop_back();
    }
    table_[id] = {radius, mass, restitution, 1, 1.0 / mass};
    cached = id;
    return id;
  }
  // One ball fewer of species `id`; the number is reused once none is left.
  void release(std::uint32_t id) {
    if (--table_[id].balls != 0) return;
    free_.push_back(id);
    --live_;
  }
  // Every movable species' radius times `factor` (growth brought to now). Sharing starts afresh:
  // a species' key has changed.
  void scale_movable_radii(double factor) {
    for (Species& s : table_) {
      if (s.balls > 0 && s.movable()) s.radius *= factor;
    }
    cache_ = filled_cache();
  }
  // How many species have balls: 1 in a world whose balls are all of one kind.
  [[nodiscard]] std::uint32_t live() const { return live_; }
  [[nodiscard]] const Species& operator[](std::uint32_t id) const { return table_[id]; }
  [[nodiscard]] const Species* data() const { return table_.data(); }

 private:
  using Key = std::array<std::uint64_t, 3>;
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  static constexpr std::size_t kCacheSize = 64;

  static std::uint64_t bits(double x) {
    std::uint64_t out = 0;
    std::memcpy(&out, &x, sizeof out);
    return out;
  }
  static Key key_of(double radius, double mass, double restitution) {
    return {bits(radius), bits(mass), bits(restitution)};
  }
  static Key key_of(const Species& s) { return key_of(s.radius, s.mass, s.restitution); }
  static std::size_t hash(const Key& key) {
    const std::uint64_t mixed =
        (key[0] * 0x9E3779B97F4A7C15u) ^ (key[1] * 0xC2B2AE3D27D4EB4Fu) ^ key[2];
    return static_cast<std::size_t>(mixed >> 58);  // the top 6 bits: kCacheSize entries
  }

  std::vector<Species> table_;
  std::vector<std::uint32_t> free_;
  std::uint32_t live_ = 0;
  std::array<std::uint32_t, kCacheSize> cache_ = filled_cache();

  static std::array<std::uint32_t, kCacheSize> filled_cache() {
    std::array<std::uint32_t, kCacheSize> out{};
    out.fill(kNone);
    return out;
  }
};

}  // namespace carom::detail
