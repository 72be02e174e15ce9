// The measurement machinery itself: exact bookkeeping (unwrapped positions, time weighting),
// the checks on its arguments, determinism, and the block average.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "carom/error.hpp"
#include "carom/science/block_average.hpp"
#include "carom/science/gas_monitor.hpp"
#include "carom/science/hard_disk_gas.hpp"
#include "science/gas_run.hpp"

namespace carom::science::test {
namespace {

// A dilute gas: 16 disks at η = 0.02 in a cell 25 wide, mean free path about 14 diameters, so
// every disk crosses the cell many times during the run.
GasRunSpec dilute() {
  GasRunSpec spec;
  spec.n = 16;
  spec.eta = 0.02;
  spec.collisions_per_disk = 400.0;
  return spec;
}

TEST(Unwrapping, FollowsTheWorldAcrossManyCells) {
  const GasRunSpec spec = dilute();
  const GasResults gas = run_gas(spec);
  const double side = science::hard_disk_layout(spec.n, spec.eta).side;
  // The integrated displacement, wrapped, lands on the world's position up to the rounding of
  // summing a few hundred intervals per disk (each ~10⁻¹⁶ relative of a path of ~10⁴).
  EXPECT_LT(gas.max_unwrap_error, 1e-9 * side);
  // ... while the disks went far beyond half a cell, where a minimum image would fold them back.
  ASSERT_FALSE(gas.msd.y.empty());
  EXPECT_GT(gas.msd.y.back(), side * side);
}

TEST(TimeWeighting, MeanSquareSpeedIsTheEnergyExactly) {
  // Σ|v|² = 2K/m at every instant, so the time-weighted ⟨v²⟩ must equal 2kT/m to rounding; a
  // sample taken per contact, or an interval counted twice or missed, would break it.
  GasRunSpec spec = dilute();
  spec.eta = 0.3;
  const GasResults gas = run_gas(spec);
  double second_moment = 0.0;
  double total = 0.0;
  const double width = gas.speed.x[1] - gas.speed.x[0];
  for (std::size_t bin = 0; bin < gas.speed.x.size(); ++bin) {
    total += gas.speed.y[bin] * width;
    second_moment += gas.speed.y[bin] * width * gas.speed.x[bin] * gas.speed.x[bin];
  }
  // The histogram holds all the time except the overflow beyond 5√(kT/m) (weight e^-12.5 ≈ 4·10⁻⁶
  // for Maxwell–Boltzmann, more only by the finite-N tail, which is lighter).
  EXPECT_NEAR(total, 1.0, 1e-4);
  // Bin centres stand for the bin: the second moment is off by width²/12 relative to 2kT.
  EXPECT_NEAR(second_moment, 2.0 * gas.kT, 2.0 * width * width + 1e-3);
  // The energy does not drift: elastic collisions, rounding only.
  EXPECT_LT(std::abs(gas.energy_drift), 1e-12);
  EXPECT_LT(gas.momentum_drift, 1e-12);
}

TEST(Determinism, SameSeedSameBits) {
  const GasResults first = run_gas(dilute());
  const GasResults second = run_gas(dilute());
  EXPECT_EQ(first.z.mean, second.z.mean);
  EXPECT_EQ(first.collisions, second.collisions);
  EXPECT_EQ(first.msd.y, second.msd.y);
  EXPECT_EQ(first.rdf.y, second.rdf.y);
}

TEST(Structure, GOfRTendsToOneAndItsContactValueToThePressureRoute) {
  GasRunSpec spec;
  spec.n = 400;
  spec.eta = 0.3;
  spec.collisions_per_disk = 1000.0;
  spec.structure_every = 2.0;
  const GasResults gas = run_gas(spec);
  ASSERT_GT(gas.rdf.x.size(), 150U);
  // Beyond 3σ the correlations of a fluid at η = 0.3 are below a percent.
  double far = 0.0;
  std::size_t count = 0;
  for (std::size_t bin = 0; bin < gas.rdf.x.size(); ++bin) {
    if (gas.rdf.x[bin] > 3.0) {
      far += gas.rdf.y[bin];
      ++count;
    }
  }
  EXPECT_NEAR(far / static_cast<double>(count), 1.0, 0.01);
  // Z = 1 + 2η·g(σ) exactly (docs/science.md): the structural and mechanical routes agree within
  // their combined errors.
  const double from_pressure = (gas.z.mean - 1.0) / (2.0 * spec.eta);
  const double combined = std::hypot(gas.g_contact.error, gas.z.error / (2.0 * spec.eta));
  EXPECT_NEAR(gas.g_contact.mean, from_pressure, 4.0 * combined);
  EXPECT_GT(gas.structure_samples, 0U);
  EXPECT_EQ(gas.final_positions.size(), spec.n);
}

TEST(Arguments, AreChecked) {
  const science::HardDiskLayout layout = science::hard_disk_layout(16, 0.3);
  World world = science::make_hard_disk_world(layout, 1);
  GasMonitorSettings one_block;
  one_block.blocks = 1;
  EXPECT_THROW((void)measure_gas(world, 1.0, one_block), InvalidArgument);
  EXPECT_THROW((void)measure_gas(world, 0.0), InvalidArgument);
  EXPECT_THROW((void)measure_gas(world, std::numeric_limits<double>::infinity()), InvalidArgument);
  GasMonitorSettings one_run;
  one_run.runs_per_block = 1;
  EXPECT_THROW((void)measure_gas(world, 1.0, one_run), InvalidArgument);
  World walled(WorldDef{});
  walled.add_ball(BallDef{});
  EXPECT_THROW((void)measure_gas(walled, 1.0), InvalidArgument);
}

TEST(BlockAverage, MeanAndStandardError) {
  const std::vector<double> values{1.0, 2.0, 3.0, 4.0};
  const BlockEstimate estimate = block_estimate(values);
  EXPECT_DOUBLE_EQ(estimate.mean, 2.5);
  // Sample variance 5/3, over four blocks: √(5/12).
  EXPECT_DOUBLE_EQ(estimate.error, std::sqrt(5.0 / 12.0));
  EXPECT_EQ(estimate.blocks, 4U);
  EXPECT_TRUE(std::isnan(block_estimate({}).mean));
  EXPECT_EQ(block_estimate(std::vector<double>{7.0}).error, 0.0);
}

}  // namespace
}  // namespace carom::science::test
