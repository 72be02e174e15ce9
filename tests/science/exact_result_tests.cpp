// Measurements on the hard-disk gas against exact results (docs/science.md derives each).
// Every run has a fixed seed, so a test is deterministic; its tolerance is set by the error the
// run itself estimates (block averaging with 16 blocks). The bound used is 4 standard errors:
// for an estimate from 16 blocks, the Student t distribution with 15 degrees of freedom puts
// 99.9 % of its mass within ±4.07, so a correct measurement fails about once in a thousand
// seeds, while a wrong formula (a missing factor, a wrong finite-N term) shows as tens of errors.
#include <gtest/gtest.h>

#include <cmath>

#include "carom/science/exact.hpp"
#include "science/gas_run.hpp"

namespace carom::science::test {
namespace {

constexpr double kErrors = 4.0;

// One small gas serves the finite-N tests: 16 disks at η = 0.3, 20 000 collisions per disk
// (about 3·10⁵ collisions, a fraction of a second).
const GasResults& small_gas() {
  static const GasResults results = [] {
    GasRunSpec spec;
    spec.n = 16;
    spec.eta = 0.3;
    spec.collisions_per_disk = 20000.0;
    spec.seed = 3;
    return run_gas(spec);
  }();
  return results;
}

TEST(MomentRatio, MatchesTheFiniteNValueNotTheInfiniteOne) {
  const GasResults& gas = small_gas();
  const double exact = moment_ratio_exact(gas.n);  // 2·15/16 = 1.875
  EXPECT_NEAR(gas.moment_ratio.mean, exact, kErrors * gas.moment_ratio.error);
  // The run resolves the 1/N term: 2 lies many errors away.
  EXPECT_GT(std::abs(gas.moment_ratio.mean - 2.0), 3.0 * kErrors * gas.moment_ratio.error);
}

TEST(MomentRatio, TwoDisksKeepOneSpeed) {
  // Two disks with zero total momentum move with opposite velocities; an elastic collision keeps
  // that, so both speeds never change and ⟨v⁴⟩/⟨v²⟩² = 1 = 2(N − 1)/N exactly, to rounding.
  GasRunSpec spec;
  spec.n = 2;
  spec.eta = 0.05;
  spec.equilibrate_per_disk = 5.0;
  spec.collisions_per_disk = 200.0;
  const GasResults gas = run_gas(spec);
  EXPECT_NEAR(gas.moment_ratio.mean, moment_ratio_exact(2), 1e-12);
}

TEST(RatePressureIdentity, HoldsWithItsFiniteNFactor) {
  const GasResults& gas = small_gas();
  const double exact = rate_pressure_ratio_exact(gas.n);  // 1.0242 for 16 disks
  EXPECT_NEAR(gas.rate_pressure_ratio.mean, exact, kErrors * gas.rate_pressure_ratio.error);
  // The finite-N factor is resolved: the textbook value 1 is excluded.
  EXPECT_GT(std::abs(gas.rate_pressure_ratio.mean - 1.0),
            3.0 * kErrors * gas.rate_pressure_ratio.error);
}

TEST(RatePressureIdentity, HoldsForFourHundredDisks) {
  GasRunSpec spec;
  spec.n = 400;
  spec.eta = 0.3;
  spec.collisions_per_disk = 500.0;
  const GasResults gas = run_gas(spec);
  EXPECT_NEAR(gas.rate_pressure_ratio.mean, rate_pressure_ratio_exact(400),
              kErrors * gas.rate_pressure_ratio.error);
}

// Z at low density against the exact virial series to η³. The series' next term, b5·η⁴, is at
// most 3.3·10⁻⁵ here and is added to the tolerance. A thousand disks keep the finite-size
// corrections, of order (Z − 1)/N ≤ 10⁻⁴, within about one standard error. The run must be long
// enough for Z's error to resolve the b3·η² term (checked below): at η = 0.02 that term is
// 1.25·10⁻³, and 300 collisions a disk gave standard errors of 0.65·10⁻⁴ and 1.11·10⁻⁴ on two
// trajectories that differ only in rounding, against the 1.04·10⁻⁴ the check allows; 800 bring
// the error to about 0.5·10⁻⁴.
void expect_virial_series(double eta, std::uint64_t seed, double collisions_per_disk) {
  GasRunSpec spec;
  spec.n = 1000;
  spec.eta = eta;
  spec.collisions_per_disk = collisions_per_disk;
  spec.seed = seed;
  const GasResults gas = run_gas(spec);
  const double truncation = kVirialB5 * std::pow(eta, 4.0);
  EXPECT_NEAR(gas.z.mean, virial_z(eta), kErrors * gas.z.error + truncation);
  // The test resolves the second virial term beyond the first: Z − 1 − 2η is many errors wide.
  EXPECT_GT(kVirialB3 * eta * eta, 3.0 * kErrors * gas.z.error);
}

TEST(LowDensity, ZFollowsTheVirialSeriesAtEta0_02) { expect_virial_series(0.02, 1, 800.0); }
TEST(LowDensity, ZFollowsTheVirialSeriesAtEta0_05) { expect_virial_series(0.05, 2, 300.0); }

// Henderson's equation of state is accurate to about 0.3 % for η ≤ 0.3, so Z must lie within
// 0.3 % of it; the run is long enough that its own error is at most a quarter of that, so the
// check is not swamped by noise. 400 disks: finite-size effects on Z are below 0.1 % here. Run
// lengths: with 1 500 and 2 500 collisions a disk, Z's error at η = 0.2 and 0.3 came to 0.36–0.96
// and 0.67–1.08 of the quarter allowed (six seeds each, on two builds whose trajectories differ
// by rounding), so the check could fail on noise; with 3 000 and 6 000, 0.38–0.53 and 0.40–0.65
// (|Z − Henderson| at most 0.33 of the 0.3 % throughout). η = 0.1's 1 000 gave 0.39–0.52.
void expect_henderson(double eta, double collisions_per_disk) {
  GasRunSpec spec;
  spec.n = 400;
  spec.eta = eta;
  spec.collisions_per_disk = collisions_per_disk;
  const GasResults gas = run_gas(spec);
  const double henderson = henderson_z(eta);
  EXPECT_NEAR(gas.z.mean, henderson, 0.003 * henderson);
  EXPECT_LT(gas.z.error, 0.00075 * henderson);
}

TEST(Henderson, WithinPointThreePercentAtEta0_1) { expect_henderson(0.1, 1000.0); }
TEST(Henderson, WithinPointThreePercentAtEta0_2) { expect_henderson(0.2, 3000.0); }
TEST(Henderson, WithinPointThreePercentAtEta0_3) { expect_henderson(0.3, 6000.0); }

}  // namespace
}  // namespace carom::science::test
