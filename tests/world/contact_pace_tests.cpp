// The world's rule for runs whose contacts pile up towards one instant (src/contact_pace.hpp),
// fed contact times of known shape: steady, exponentially quickening, converging.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "world/contact_pace.hpp"

namespace carom::detail {
namespace {

constexpr std::uint64_t kPaceContacts = std::uint64_t{1} << 23;  // 4 doublings past the earliest

// The contact count at which the watch first says "piling up" for contacts at times time(k),
// k = 1, 2, ..., or 0 when it never does within kPaceContacts.
template <typename Time>
std::uint64_t first_piling_up(Time time) {
  ContactPace pace;
  for (std::uint64_t k = 1; k <= kPaceContacts; ++k) {
    if (pace.piling_up(time(static_cast<double>(k)))) return k;
  }
  return 0;
}

TEST(ContactPace, SteadyContactsNeverPileUp) {
  EXPECT_EQ(first_piling_up([](double k) { return 0.001 * k; }), 0u);
}

// A rate that doubles with every doubling of the count: each doubling takes as long as the one
// before (a gas heating up exponentially), which is no pile-up.
TEST(ContactPace, ExponentiallyQuickeningContactsNeverPileUp) {
  EXPECT_EQ(first_piling_up([](double k) { return std::log2(k); }), 0u);
}

// A ball crushed by a mover closing at speed 1: the k-th bounce at t* − c/k, so each doubling
// of the count takes half the time of the one before. Refused at the first chance: the eighth
// doubling that took less, 2^19 contacts.
TEST(ContactPace, ContactsConvergingOnAnInstantPileUpAtTheEighthFasterDoubling) {
  EXPECT_EQ(first_piling_up([](double k) { return 4.0 - 1.0 / k; }), std::uint64_t{1} << 19);
}

// Contacts at one instant (a jam: the jam rule's case) take no time at all, doubling after
// doubling: none is faster than the one before.
TEST(ContactPace, ContactsAtOneInstantAreNotAPileUp) {
  EXPECT_EQ(first_piling_up([](double) { return 2.5; }), 0u);
}

// One doubling no faster than the one before starts the count again.
TEST(ContactPace, ASlowDoublingStartsTheCountAgain) {
  // Converging, but the doubling ending at 2^15 contacts is slowed by a pause of 1.
  const auto time = [](double k) { return (k > 0x1p14 ? 1.0 : 0.0) + 4.0 - 1.0 / k; };
  EXPECT_EQ(first_piling_up(time), std::uint64_t{1} << 23);  // 2^15 and 8 doublings
}

}  // namespace
}  // namespace carom::detail
