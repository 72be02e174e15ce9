#include "structure_sampler.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace carom::science {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// The 3×3 block of cells is visited only when each axis has at least three cells; fewer, and a
// cell would be its own neighbour twice.
constexpr std::size_t kFewestCells = 3;
// g(σ) is extrapolated from this many bins next to contact by a quadratic in r. With the default
// bins of 0.02σ that spans 0.12σ, over which g(r) is smooth; a straight line would be biased by
// its curvature, a higher order amplifies noise. See docs/science.md.
constexpr std::size_t kContactFitBins = 6;

// The value at x = 0 of the least-squares quadratic through (x[k], y[k]).
double quadratic_at_zero(std::span<const double> x, std::span<const double> y) {
  // Normal equations M·(a, b, c) = v for y ≈ a + b·x + c·x².
  std::array<std::array<double, 4>, 3> m{};
  for (std::size_t k = 0; k < x.size(); ++k) {
    const std::array<double, 3> basis{1.0, x[k], x[k] * x[k]};
    for (std::size_t row = 0; row < 3; ++row) {
      for (std::size_t col = 0; col < 3; ++col) m[row][col] += basis[row] * basis[col];
      m[row][3] += basis[row] * y[k];
    }
  }
  // Gaussian elimination; the matrix is a Gram matrix of independent columns, so no pivoting.
  for (std::size_t pivot = 0; pivot < 3; ++pivot) {
    for (std::size_t row = pivot + 1; row < 3; ++row) {
      const double factor = m[row][pivot] / m[pivot][pivot];
      for (std::size_t col = pivot; col < 4; ++col) m[row][col] -= factor * m[pivot][col];
    }
  }
  std::array<double, 3> solution{};
  for (std::size_t row = 3; row-- > 0;) {
    double rest = m[row][3];
    for (std::size_t col = row + 1; col < 3; ++col) rest -= m[row][col] * solution[col];
    solution[row] = rest / m[row][row];
  }
  return solution[0];
}

}  // namespace

StructureSampler::StructureSampler(const StructureSettings& settings, std::vector<bool> reference)
    : settings_(settings), reference_(std::move(reference)), side_(settings.cell.period()) {
  reference_count_ =
      static_cast<std::size_t>(std::count(reference_.begin(), reference_.end(), true));
  range_ = std::min(settings.rdf_range * settings.sigma, 0.5 * std::min(side_.x, side_.y));
  range2_ = range_ * range_;
  const double psi6_cutoff = settings.psi6_cutoff * settings.sigma;
  psi6_cutoff2_ = psi6_cutoff * psi6_cutoff;
  bin_width_ = settings.rdf_bin * settings.sigma;
  bins_ = range_ > settings.sigma
              ? static_cast<std::size_t>(std::ceil((range_ - settings.sigma) / bin_width_))
              : 0;
  // The pair search must reach both the g(r) range and the ψ₆ neighbours.
  const double reach = std::max(range_, psi6_cutoff);
  const auto cells_x = static_cast<std::size_t>(side_.x / reach);
  const auto cells_y = static_cast<std::size_t>(side_.y / reach);
  if (cells_x >= kFewestCells && cells_y >= kFewestCells) {
    cells_x_ = cells_x;
    cells_y_ = cells_y;
    head_.assign(cells_x_ * cells_y_, kNone);
  }
  next_.assign(reference_.size(), kNone);
  psi6_.assign(reference_.size(), {});
  neighbours_.assign(reference_.size(), 0);
  block_counts_.assign(bins_, 0.0);
  total_counts_.assign(bins_, 0.0);
  psi6_histogram_.assign(settings.psi6_bins, 0.0);
}

void StructureSampler::visit_pair(std::size_t i, std::size_t j, Vec2 position_i, Vec2 position_j) {
  const Vec2 d = settings_.cell.minimum_image(position_j - position_i);
  const double r2 = dot(d, d);
  if (r2 >= range2_ && r2 >= psi6_cutoff2_) return;
  if (r2 < psi6_cutoff2_ && r2 > 0.0) {
    // e^{6iθ} = ((dx + i·dy)/r)^6 by squaring, without trigonometry; the opposite bond has
    // θ + π and the same e^{6iθ}, so both disks get it.
    const std::complex<double> unit = std::complex<double>(d.x, d.y) / std::sqrt(r2);
    const std::complex<double> cube = unit * unit * unit;
    const std::complex<double> bond = cube * cube;
    psi6_[i] += bond;
    psi6_[j] += bond;
    ++neighbours_[i];
    ++neighbours_[j];
  }
  if (r2 < range2_ && reference_[i] && reference_[j]) {
    const double r = std::sqrt(r2);
    // Disks never overlap beyond rounding, so r < σ only by a rounding: count it in the first bin.
    const double offset = std::max(0.0, (r - settings_.sigma) / bin_width_);
    const auto bin = static_cast<std::size_t>(offset);
    if (bin < bins_) block_counts_[bin] += 1.0;
  }
}

void StructureSampler::sample(std::span<const Vec2> positions) {
  const std::size_t n = positions.size();
  std::fill(psi6_.begin(), psi6_.end(), std::complex<double>{});
  std::fill(neighbours_.begin(), neighbours_.end(), 0U);
  if (cells_x_ == 0) {
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) visit_pair(i, j, positions[i], positions[j]);
    }
  } else {
    std::fill(head_.begin(), head_.end(), kNone);
    const double cells_per_x = static_cast<double>(cells_x_) / side_.x;
    const double cells_per_y = static_cast<double>(cells_y_) / side_.y;
    for (std::size_t i = n; i-- > 0;) {
      const Vec2 p = positions[i] - settings_.cell.lower();
      // Positions lie in [0, side) up to a rounding; clamp so a rounding cannot index outside.
      const auto cx =
          std::min(cells_x_ - 1, static_cast<std::size_t>(std::max(0.0, p.x * cells_per_x)));
      const auto cy =
          std::min(cells_y_ - 1, static_cast<std::size_t>(std::max(0.0, p.y * cells_per_y)));
      const std::size_t cell = cy * cells_x_ + cx;
      next_[i] = head_[cell];
      head_[cell] = static_cast<std::uint32_t>(i);
    }
    // Each pair once: within a cell, and with four of the eight neighbouring cells.
    constexpr std::array<std::array<std::size_t, 2>, 4> kForward{{{1, 0}, {0, 1}, {1, 1}, {2, 1}}};
    for (std::size_t cy = 0; cy < cells_y_; ++cy) {
      for (std::size_t cx = 0; cx < cells_x_; ++cx) {
        const std::size_t cell = cy * cells_x_ + cx;
        for (std::uint32_t i = head_[cell]; i != kNone; i = next_[i]) {
          for (std::uint32_t j = next_[i]; j != kNone; j = next_[j]) {
            visit_pair(i, j, positions[i], positions[j]);
          }
          for (const auto& [step_x, step_y] : kForward) {
            // {2, 1} stands for (−1, +1): x steps back one cell, written as + (cells − 1).
            const std::size_t nx = (cx + (step_x == 2 ? cells_x_ - 1 : step_x)) % cells_x_;
            const std::size_t ny = (cy + step_y) % cells_y_;
            for (std::uint32_t j = head_[ny * cells_x_ + nx]; j != kNone; j = next_[j]) {
              visit_pair(i, j, positions[i], positions[j]);
            }
          }
        }
      }
    }
  }
  std::complex<double> sum;
  const auto bins = static_cast<double>(psi6_histogram_.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (neighbours_[i] > 0) psi6_[i] /= static_cast<double>(neighbours_[i]);
    sum += psi6_[i];
    const double bin = std::min(std::abs(psi6_[i]) * bins, bins - 1.0);
    psi6_histogram_[static_cast<std::size_t>(bin)] += 1.0;
  }
  block_psi6_sum_ += std::abs(sum) / static_cast<double>(n);
  ++block_samples_;
  ++total_samples_;
}

double StructureSampler::g_of_bin(double count, std::size_t bin, std::size_t samples) const {
  const double inner = settings_.sigma + static_cast<double>(bin) * bin_width_;
  const double outer = inner + bin_width_;
  const auto pairs =
      static_cast<double>(reference_count_) * static_cast<double>(reference_count_ - 1) / 2.0;
  const double expected = pairs * std::numbers::pi * (outer * outer - inner * inner) /
                          (side_.x * side_.y) * static_cast<double>(samples);
  return count / expected;
}

double StructureSampler::contact_value(const std::vector<double>& counts,
                                       std::size_t samples) const {
  if (samples == 0 || bins_ < kContactFitBins || reference_count_ < 2) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  std::array<double, kContactFitBins> x{};
  std::array<double, kContactFitBins> g{};
  for (std::size_t bin = 0; bin < kContactFitBins; ++bin) {
    x[bin] = (static_cast<double>(bin) + 0.5) * bin_width_;
    g[bin] = g_of_bin(counts[bin], bin, samples);
  }
  return quadratic_at_zero(x, g);
}

StructureSampler::BlockValues StructureSampler::end_block() {
  BlockValues values;
  values.samples = block_samples_;
  values.g_contact = contact_value(block_counts_, block_samples_);
  values.psi6 = block_samples_ > 0 ? block_psi6_sum_ / static_cast<double>(block_samples_)
                                   : std::numeric_limits<double>::quiet_NaN();
  for (std::size_t bin = 0; bin < bins_; ++bin) total_counts_[bin] += block_counts_[bin];
  std::fill(block_counts_.begin(), block_counts_.end(), 0.0);
  block_psi6_sum_ = 0.0;
  block_samples_ = 0;
  return values;
}

void StructureSampler::rdf(std::vector<double>& r, std::vector<double>& g) const {
  r.clear();
  g.clear();
  if (total_samples_ == 0 || reference_count_ < 2) return;
  for (std::size_t bin = 0; bin < bins_; ++bin) {
    r.push_back(settings_.sigma + (static_cast<double>(bin) + 0.5) * bin_width_);
    g.push_back(g_of_bin(total_counts_[bin], bin, total_samples_));
  }
}

void StructureSampler::psi6_local_density(std::vector<double>& modulus,
                                          std::vector<double>& density) const {
  modulus.clear();
  density.clear();
  double total = 0.0;
  for (const double count : psi6_histogram_) total += count;
  if (total == 0.0) return;
  const auto bins = static_cast<double>(psi6_histogram_.size());
  for (std::size_t bin = 0; bin < psi6_histogram_.size(); ++bin) {
    modulus.push_back((static_cast<double>(bin) + 0.5) / bins);
    density.push_back(psi6_histogram_[bin] / total * bins);
  }
}

}  // namespace carom::science
