// carom internal: exact division of a non-negative 31-bit number by a divisor fixed in advance,
// as a multiplication and a shift (the grid's cell number by its column count, on every
// prediction and cell crossing, where a division instruction sat on the critical path).
// Why it is exact: docs/derivation.md, "Dividing by a fixed number".
#pragma once

#include <bit>
#include <cstdint>

namespace carom::detail {

class FixedDivisor {
 public:
  // divisor in [1, 2^31).
  explicit FixedDivisor(std::uint32_t divisor = 1)
      : shift_(32 + static_cast<std::uint32_t>(std::bit_width(divisor - 1))),
        multiplier_((((std::uint64_t{1} << shift_) - 1) / divisor) + 1) {}

  // n / divisor, rounded down, for n in [0, 2^31).
  [[nodiscard]] std::uint32_t divide(std::uint32_t n) const {
    return static_cast<std::uint32_t>((static_cast<std::uint64_t>(n) * multiplier_) >> shift_);
  }

 private:
  std::uint32_t shift_;       // 32 + ceil(log2(divisor))
  std::uint64_t multiplier_;  // ceil(2^shift / divisor), at most 2^33
};

}  // namespace carom::detail
