#include "carom/science/block_average.hpp"

#include <cmath>
#include <limits>

namespace carom::science {

BlockEstimate block_estimate(std::span<const double> block_values) {
  BlockEstimate estimate;
  estimate.blocks = block_values.size();
  if (block_values.empty()) {
    estimate.mean = std::numeric_limits<double>::quiet_NaN();
    return estimate;
  }
  const auto count = static_cast<double>(block_values.size());
  double sum = 0.0;
  for (const double value : block_values) sum += value;
  estimate.mean = sum / count;
  if (block_values.size() < 2) return estimate;
  double squares = 0.0;
  for (const double value : block_values)
    squares += (value - estimate.mean) * (value - estimate.mean);
  const double variance = squares / (count - 1.0);  // unbiased sample variance of one block
  estimate.error = std::sqrt(variance / count);
  return estimate;
}

}  // namespace carom::science
