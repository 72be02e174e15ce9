// carom science (internal): each disk's motion between its contacts, followed from the contact
// list. A disk moves in a straight line at constant velocity between two contacts, so closing
// each interval at the next contact (or at a synchronisation) gives exact time integrals: the
// time-weighted moments and histogram of the speed, and the unwrapped displacement.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "carom/geometry.hpp"
#include "carom/vec2.hpp"
#include "carom/world.hpp"

namespace carom::science {

// Time integrals over every disk, Σᵢ ∫ f(|vᵢ|) dt, since the last take_sums().
struct SpeedIntegrals {
  double speed = 0.0;   // Σ ∫ |v| dt: the distance travelled by all disks
  double speed2 = 0.0;  // Σ ∫ |v|² dt
  double speed4 = 0.0;  // Σ ∫ |v|⁴ dt
};

class DiskMotion {
 public:
  // Starts every disk's interval at the world's time, with its position and velocity there.
  // The speed histogram has `bins` bins of width bin_width, plus one for faster disks.
  DiskMotion(const World& world, std::span<const BallId> ids, const PeriodicCell& cell,
             double bin_width, std::size_t bins);

  // Closes the interval of each disk of the contact at its time, then applies the impulse.
  void on_contact(const ContactEvent& contact);
  // Closes every disk's interval at time `now` (the world's time, with no contact pending).
  void advance(double now);
  // advance(world.time()), then takes the world's velocities (the tracked ones differ from them
  // by the rounding of the applied impulses) and measures the distance between each unwrapped
  // position, wrapped into the cell, and the world's position. Costs two handle look-ups per
  // disk, so it is done once per block, not after every run.
  void synchronise(const World& world);

  [[nodiscard]] std::span<const Vec2> displacements() const noexcept { return displacement_; }
  [[nodiscard]] SpeedIntegrals take_integrals();
  // Time spent in each speed bin by all disks together; the last entry is the overflow.
  [[nodiscard]] const std::vector<double>& speed_histogram() const noexcept { return histogram_; }
  [[nodiscard]] double max_unwrap_error() const noexcept { return max_unwrap_error_; }

 private:
  void close(std::size_t disk, double time);

  std::span<const BallId> ids_;
  PeriodicCell cell_;
  std::vector<std::uint32_t> disk_of_slot_;
  std::vector<double> inverse_mass_;
  std::vector<double> since_;  // start time of each disk's open interval
  std::vector<Vec2> velocity_;
  std::vector<Vec2> start_;         // world position at the start
  std::vector<Vec2> displacement_;  // unwrapped, since the start
  std::vector<double> histogram_;
  double inverse_bin_width_;
  SpeedIntegrals integrals_;
  double max_unwrap_error_ = 0.0;
};

}  // namespace carom::science
