#include "disk_motion.hpp"

#include <algorithm>
#include <cmath>

namespace carom::science {
namespace {

// x reduced into [−side/2, side/2]: the nearest periodic image of a difference.

}  // namespace

DiskMotion::DiskMotion(const World& world, std::span<const BallId> ids, const PeriodicCell& cell,
                       double bin_width, std::size_t bins)
    : ids_(ids),
      cell_(cell),
      inverse_mass_(ids.size()),
      since_(ids.size(), world.time()),
      velocity_(ids.size()),
      start_(ids.size()),
      displacement_(ids.size()),
      histogram_(bins + 1, 0.0),
      inverse_bin_width_(1.0 / bin_width) {
  std::uint32_t largest_slot = 0;
  for (const BallId id : ids) largest_slot = std::max(largest_slot, id.index);
  disk_of_slot_.assign(static_cast<std::size_t>(largest_slot) + 1, 0);
  for (std::size_t disk = 0; disk < ids.size(); ++disk) {
    disk_of_slot_[ids[disk].index] = static_cast<std::uint32_t>(disk);
    inverse_mass_[disk] = 1.0 / world.mass(ids[disk]);
    velocity_[disk] = world.velocity(ids[disk]);
    start_[disk] = world.position(ids[disk]);
  }
}

void DiskMotion::close(std::size_t disk, double time) {
  const double dt = time - since_[disk];
  const Vec2 v = velocity_[disk];
  const double speed2 = dot(v, v);
  const double speed = std::sqrt(speed2);
  integrals_.speed += speed * dt;
  integrals_.speed2 += speed2 * dt;
  integrals_.speed4 += speed2 * speed2 * dt;
  const std::size_t overflow = histogram_.size() - 1;
  // The product is finite and >= 0, so the conversion is defined once clamped below overflow.
  const double bin = std::min(speed * inverse_bin_width_, static_cast<double>(overflow));
  histogram_[static_cast<std::size_t>(bin)] += dt;
  displacement_[disk] += v * dt;
  since_[disk] = time;
}

void DiskMotion::on_contact(const ContactEvent& contact) {
  const std::size_t a = disk_of_slot_[contact.a.index];
  close(a, contact.time);
  // The ball receives −impulse·normal, the other ball +impulse·normal (bounce.hpp).
  velocity_[a] -= contact.normal * (contact.impulse * inverse_mass_[a]);
  if (contact.kind != ContactKind::ball_ball) return;
  const std::size_t b = disk_of_slot_[contact.b.index];
  close(b, contact.time);
  velocity_[b] += contact.normal * (contact.impulse * inverse_mass_[b]);
}

void DiskMotion::advance(double now) {
  for (std::size_t disk = 0; disk < ids_.size(); ++disk) close(disk, now);
}

void DiskMotion::synchronise(const World& world) {
  advance(world.time());
  for (std::size_t disk = 0; disk < ids_.size(); ++disk) {
    velocity_[disk] = world.velocity(ids_[disk]);
    const Vec2 unwrapped = start_[disk] + displacement_[disk];
    const Vec2 off = unwrapped - world.position(ids_[disk]);
    const double error = length(cell_.minimum_image(off));
    max_unwrap_error_ = std::max(max_unwrap_error_, error);
  }
}

SpeedIntegrals DiskMotion::take_integrals() {
  const SpeedIntegrals taken = integrals_;
  integrals_ = {};
  return taken;
}

}  // namespace carom::science
