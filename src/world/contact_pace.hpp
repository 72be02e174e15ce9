// carom internal: notices a run whose contacts come ever faster, piling up towards one instant,
// so that the run would never end. A ball caught between a moving immovable ball and a wall,
// alone or in a row of balls, is crushed: the gap closes at a finite time and the contacts come
// infinitely often before it, each moving the balls measurably (so the jam rule, which counts
// contacts without motion, never sees it). Derivation of the rule: docs/world.md, "Known limits".
#pragma once

#include <cstdint>

namespace carom::detail {

// Times each doubling of a run's contact count (2¹⁰ to 2¹¹, 2¹¹ to 2¹², ...). A steady run takes
// twice as long for each doubling as for the one before (its contacts come at a constant rate), a
// run whose rate grows exponentially equally long; only contacts piling up towards an instant
// take less and less: a ball crushed by a mover at speed u bounces at ever higher speeds in an
// ever narrower gap, and each doubling takes half the time of the one before.
class ContactPace {
 public:
  // Counts a contact at time t (times never decrease); true once each of the last kDoublings
  // doublings of the count took under kShrink of the time of the doubling before it.
  bool piling_up(double t) {
    ++contacts_;
    if (contacts_ < kFirstMark || (contacts_ & (contacts_ - 1)) != 0) return false;
    const double took = t - mark_;
    mark_ = t;
    if (contacts_ == kFirstMark) return false;  // the first mark: nothing timed yet
    shorter_in_a_row_ = previous_ >= 0.0 && took < kShrink * previous_ ? shorter_in_a_row_ + 1 : 0;
    previous_ = took;
    return shorter_in_a_row_ >= kDoublings;
  }

 private:
  // Timing starts here, past a run's opening (a break, balls that start touching).
  static constexpr std::uint64_t kFirstMark = std::uint64_t{1} << 10;
  // A doubling counts as faster below 3/4 of the time of the one before: far from the steady
  // run's 2 and the exponential run's 1, and well above a crush's 1/2.
  static constexpr double kShrink = 0.75;
  // So many faster doublings in a row (the rate grown 2⁸/0.75⁸ ≈ 2 500 times while the count
  // grew 256 times): refused at 2¹⁹ contacts at the earliest.
  static constexpr int kDoublings = 8;

  std::uint64_t contacts_ = 0;
  double mark_ = 0.0;       // the time of the last power of two
  double previous_ = -1.0;  // the time the last doubling took (< 0: none yet)
  int shorter_in_a_row_ = 0;
};

}  // namespace carom::detail
