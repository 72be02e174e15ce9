// Longer variants of the exact-result tests, run only with CAROM_LONG_TESTS=1 (make test-long):
// the rate/pressure identity and the moment ratio at every density of a fluid sweep, and
// Henderson at a thousand disks with ten times the collisions. Tolerances as in
// exact_result_tests.cpp: 4 block-average standard errors (99.9 % of Student's t with 15
// degrees of freedom).
#include <gtest/gtest.h>

#include "carom/science/exact.hpp"
#include "science/gas_run.hpp"

namespace carom::science::test {
namespace {

constexpr double kLongErrors = 4.0;

TEST(LongSweep, RatePressureIdentityAndMomentsAtEveryFluidDensity) {
  if (!long_tests_enabled()) GTEST_SKIP() << "set CAROM_LONG_TESTS=1";
  for (const double eta : {0.1, 0.2, 0.3, 0.4, 0.5, 0.6}) {
    GasRunSpec spec;
    spec.n = 400;
    spec.eta = eta;
    spec.equilibrate_per_disk = 100.0;
    spec.collisions_per_disk = 5000.0;
    const GasResults gas = run_gas(spec);
    EXPECT_NEAR(gas.rate_pressure_ratio.mean, rate_pressure_ratio_exact(spec.n),
                kLongErrors * gas.rate_pressure_ratio.error)
        << "eta " << eta;
    EXPECT_NEAR(gas.moment_ratio.mean, moment_ratio_exact(spec.n),
                kLongErrors * gas.moment_ratio.error)
        << "eta " << eta;
    // Z = 1 + 2η·g(σ): the structural and mechanical routes agree.
    EXPECT_NEAR(gas.g_contact.mean, (gas.z.mean - 1.0) / (2.0 * eta),
                kLongErrors * (gas.g_contact.error + gas.z.error / (2.0 * eta)))
        << "eta " << eta;
  }
}

TEST(LongSweep, HendersonAtAThousandDisks) {
  if (!long_tests_enabled()) GTEST_SKIP() << "set CAROM_LONG_TESTS=1";
  for (const double eta : {0.1, 0.2, 0.3}) {
    GasRunSpec spec;
    spec.n = 1000;
    spec.eta = eta;
    spec.collisions_per_disk = 10000.0;
    const GasResults gas = run_gas(spec);
    const double henderson = henderson_z(eta);
    EXPECT_NEAR(gas.z.mean, henderson, 0.003 * henderson) << "eta " << eta;
    EXPECT_LT(gas.z.error, 0.00075 * henderson) << "eta " << eta;
  }
}

}  // namespace
}  // namespace carom::science::test
