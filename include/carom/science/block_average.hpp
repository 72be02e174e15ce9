// carom science: the error of a time average by block averaging.
//
// A run is cut into B blocks of equal length; each block gives its own estimate of a quantity,
// and when blocks are much longer than the time over which the system remembers (the correlation
// time), the B estimates are independent draws, so their mean's standard error is their sample
// standard deviation over √B. Derivation and the check of the condition: docs/science.md.
#pragma once

#include <cstddef>
#include <span>

namespace carom::science {

struct BlockEstimate {
  double mean = 0.0;   // the mean of the block values
  double error = 0.0;  // its standard error: sd / √B (0 for fewer than two blocks)
  std::size_t blocks = 0;
};

// The mean and standard error of per-block values. Empty input gives NaN with zero blocks.
[[nodiscard]] BlockEstimate block_estimate(std::span<const double> block_values);

}  // namespace carom::science
