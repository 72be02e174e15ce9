// carom science (internal): the structure of one configuration of disks in a periodic cell —
// pair distances for g(r) and each disk's bond-orientational order ψ₆ — found with a cell list,
// so a sample costs O(N) rather than O(N²).
#pragma once

#include <complex>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "carom/geometry.hpp"
#include "carom/vec2.hpp"

namespace carom::science {

struct StructureSettings {
  PeriodicCell cell;
  double sigma = 1.0;        // reference diameter: g(r) starts here
  double rdf_range = 5.0;    // in σ; clipped to half the cell's shorter side
  double rdf_bin = 0.02;     // in σ
  double psi6_cutoff = 1.4;  // in σ
  std::size_t psi6_bins = 20;
};

class StructureSampler {
 public:
  // reference[i] says whether disk i counts for g(r); every disk counts for ψ₆.
  StructureSampler(const StructureSettings& settings, std::vector<bool> reference);

  // Adds one configuration (wrapped positions, in the disks' order) to the current block.
  void sample(std::span<const Vec2> positions);
  // Ends the current block: its g(r) contact value (NaN without samples) and mean global ψ₆;
  // its pair counts join the whole run's.
  struct BlockValues {
    double g_contact = 0.0;
    double psi6 = 0.0;
    std::size_t samples = 0;
  };
  [[nodiscard]] BlockValues end_block();

  // g(r) over the whole run: bin centres (length units) and values.
  void rdf(std::vector<double>& r, std::vector<double>& g) const;
  // Histogram of |ψ₆,j| over every disk of every sample, as a probability density on [0, 1].
  void psi6_local_density(std::vector<double>& modulus, std::vector<double>& density) const;
  // The last sample's local ψ₆ of each disk (0 without neighbours).
  [[nodiscard]] const std::vector<std::complex<double>>& last_psi6() const noexcept {
    return psi6_;
  }
  [[nodiscard]] std::size_t samples() const noexcept { return total_samples_; }

 private:
  void visit_pair(std::size_t i, std::size_t j, Vec2 positions_i, Vec2 positions_j);
  // g(r) from pair counts of `samples` configurations.
  [[nodiscard]] double g_of_bin(double count, std::size_t bin, std::size_t samples) const;
  [[nodiscard]] double contact_value(const std::vector<double>& counts, std::size_t samples) const;

  StructureSettings settings_;
  std::vector<bool> reference_;
  std::size_t reference_count_ = 0;
  Vec2 side_;
  double range_ = 0.0;  // r_max, length units
  double range2_ = 0.0;
  double psi6_cutoff2_ = 0.0;
  double bin_width_ = 0.0;
  std::size_t bins_ = 0;
  // The cell list: cells_x × cells_y cells at least range_ wide (0 means: all pairs directly).
  std::size_t cells_x_ = 0;
  std::size_t cells_y_ = 0;
  std::vector<std::uint32_t> head_;
  std::vector<std::uint32_t> next_;

  std::vector<std::complex<double>> psi6_;
  std::vector<std::uint32_t> neighbours_;
  std::vector<double> block_counts_;
  std::vector<double> total_counts_;
  std::vector<double> psi6_histogram_;
  double block_psi6_sum_ = 0.0;
  std::size_t block_samples_ = 0;
  std::size_t total_samples_ = 0;
};

}  // namespace carom::science
