// carom tool: the span of a plotted series' finite values, for choosing a plot's axes.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom::cli {

// Empty (low > high) until a finite value is added; infinities and NaN are passed over.
struct ValueRange {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  void add(double value) {
    if (!std::isfinite(value)) return;
    low = std::min(low, value);
    high = std::max(high, value);
  }
  [[nodiscard]] bool empty() const { return !(low <= high); }
};

}  // namespace carom::cli
