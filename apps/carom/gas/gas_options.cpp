#include "gas/gas_options.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"

namespace carom::cli {
namespace {

// A typo with extra zeros should be refused at once, not after allocating gigabytes; the
// measurements keep a few arrays per disk and the lattice code is exact below 2^31 disks.
constexpr std::uint64_t kMaxDisks = 10'000'000;
// Collision counts are computed as K·N in doubles; beyond 2^53 they would no longer be exact.
constexpr double kMaxCollisions = 9007199254740992.0;
// Blocks: at least 2 for an error; more than a few hundred only shortens each block below the
// correlation time.
constexpr std::uint64_t kFewestBlocks = 2;
constexpr std::uint64_t kMostBlocks = 1000;

double parse_per_disk(const std::string& option, const std::string& text, bool zero_allowed) {
  const OptionValue value{option, text, zero_allowed ? "a number >= 0" : "a number > 0"};
  const double per_disk = parse_finite_number(text, value);
  if (zero_allowed ? !(per_disk >= 0.0) : !(per_disk > 0.0)) {
    reject(value,
           zero_allowed ? "collisions per disk must be >= 0" : "collisions per disk must be > 0");
  }
  return per_disk;
}

// The diameters of n disks: 1, and d for a fraction f of them spread evenly through the lattice
// (disk i is of the second kind when ⌊(i+1)·f⌋ > ⌊i·f⌋).
std::vector<double> diameters_of(std::uint64_t n, double second_diameter, double fraction) {
  std::vector<double> diameters(n, science::kDiskDiameter);
  for (std::uint64_t i = 0; i < n; ++i) {
    const auto index = static_cast<double>(i);
    if (std::floor((index + 1.0) * fraction) > std::floor(index * fraction)) {
      diameters[i] = second_diameter;
    }
  }
  return diameters;
}

}  // namespace

GasSpec parse_gas_spec(const GasOptionText& text) {
  const OptionValue eta_value{"--eta", text.eta, "a number in (0, 0.9069)"};
  return parse_gas_spec(text, parse_finite_number(text.eta, eta_value), text.eta);
}

GasSpec parse_gas_spec(const GasOptionText& text, double eta, const std::string& eta_text) {
  GasSpec spec;
  spec.n = parse_whole_number({"--n", text.n, "a whole number >= 2"});
  if (spec.n < 2) throw UsageError("--n", text.n, "at least 2 disks are needed for a collision");
  if (spec.n > kMaxDisks) {
    throw UsageError("--n", text.n, "at most " + std::to_string(kMaxDisks) + " disks");
  }
  if (!(eta > 0.0 && eta < science::kTriangularPackingLimit)) {
    throw UsageError("--eta", eta_text,
                     "the packing fraction must lie above 0 and below that of the densest "
                     "packing of equal disks, pi/(2*sqrt(3)) = 0.9069");
  }
  spec.eta = eta;
  double second = science::kDiskDiameter;
  double fraction = 0.0;
  if (!text.mix.empty()) {
    const OptionValue mix{"--mix", text.mix, "D:F, a diameter D > 0 and a fraction F in (0, 1)"};
    const std::size_t colon = text.mix.find(':');
    if (colon == std::string::npos) reject(mix, "the colon between D and F is missing");
    second = parse_finite_number(std::string_view(text.mix).substr(0, colon), mix);
    fraction = parse_finite_number(std::string_view(text.mix).substr(colon + 1), mix);
    if (!(second > 0.0)) reject(mix, "the diameter must be > 0");
    if (!(fraction > 0.0 && fraction < 1.0)) reject(mix, "the fraction must lie in (0, 1)");
  }
  spec.second_diameter = second;
  spec.second_fraction = fraction;
  if (text.start == "compress") {
    spec.compress_start = true;
  } else if (text.start != "lattice") {
    throw UsageError("--start", text.start, "must be lattice or compress");
  }
  spec.diameters = diameters_of(spec.n, second, fraction);
  const double sum_squares = std::accumulate(spec.diameters.begin(), spec.diameters.end(), 0.0,
                                             [](double sum, double d) { return sum + d * d; });
  const double largest = *std::max_element(spec.diameters.begin(), spec.diameters.end());
  // The box for unit disks at this packing fraction is the box of eta for these diameters.
  const double unit_eta = eta * static_cast<double>(spec.n) / sum_squares;
  spec.layout = science::hard_disk_layout(spec.n, unit_eta);
  spec.layout.eta = eta;
  if (!spec.layout.box_wide_enough() ||
      spec.layout.side <= science::kMinPeriodicSideInDiameters * largest) {
    throw UsageError("--n", text.n,
                     "at packing fraction " + readable(eta) + " the periodic box is only " +
                         readable(spec.layout.side) +
                         " wide, and it must be more than 3 of the "
                         "largest diameters wide: raise --n or lower --eta");
  }
  if (!spec.compress_start && spec.layout.nearest < largest * (1.0 + science::kLatticeSlack)) {
    throw UsageError("--eta", eta_text,
                     "the best triangular lattice for " + std::to_string(spec.n) +
                         " disks in this box has sites only " + readable(spec.layout.nearest) +
                         " apart, less than the largest diameter (" + readable(largest) +
                         "): this gas can start at packing fraction " +
                         readable(eta * std::pow(spec.layout.nearest / largest, 2.0)) +
                         " at most (--start compress reaches denser states)");
  }
  const double equilibrate = parse_per_disk("--equilibrate", text.equilibrate, true);
  spec.collisions_per_disk = parse_per_disk("--collisions", text.collisions, false);
  const auto count = static_cast<double>(spec.n);
  if (std::max(equilibrate, spec.collisions_per_disk) * count > kMaxCollisions) {
    throw UsageError(equilibrate > spec.collisions_per_disk ? "--equilibrate" : "--collisions",
                     equilibrate > spec.collisions_per_disk ? text.equilibrate : text.collisions,
                     "more than 2^53 collisions in all");
  }
  spec.equilibration_collisions = static_cast<std::uint64_t>(std::round(equilibrate * count));
  spec.seed = parse_whole_number({"--seed", text.seed, "a whole number >= 0"});
  spec.blocks = parse_whole_number({"--blocks", text.blocks, "a whole number in [2, 1000]"});
  if (spec.blocks < kFewestBlocks || spec.blocks > kMostBlocks) {
    throw UsageError("--blocks", text.blocks, "between 2 and 1000 blocks");
  }
  return spec;
}

}  // namespace carom::cli
