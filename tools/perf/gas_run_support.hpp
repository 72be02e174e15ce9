// carom benchmarks: what the hard-disk gas programs (carom_world_gas_probe, carom_textbook_gas)
// share so that their figures compare: the CPU clock they are timed by, the
// random order in which SHUFFLED=1 numbers the disks (one permutation for all, by construction),
// the start read out of carom's World, and the equal-mass bounce of the simulators beside it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <ctime>
#include <random>
#include <vector>

#include "carom/world.hpp"

namespace carom::bench {

// This process's CPU time in seconds: meaningful on a machine that other jobs share.
inline double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// 0 .. count − 1 in SHUFFLED=1's random order: position k of the shuffled numbering holds the
// disk that was number order[k].
inline std::vector<std::size_t> shuffled_order(std::size_t count) {
  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(2));
  return order;
}

// What a simulator beside carom's engine reports of its timed collisions.
struct TimedCollisions {
  std::uint64_t collisions = 0;
  double cpu_seconds = 0.0;
  double crossings_per_collision = 0.0;
  double stale_per_collision = 0.0;
  double energy_drift = 0.0;  // relative, over the timed collisions
};

// Runs `wanted` collisions of such a simulator (its run_collisions, crossings, stale and
// kinetic_energy), timed by this process's CPU time.
template <class Gas>
TimedCollisions timed_collisions(Gas& gas, std::uint64_t wanted) {
  const double energy_before = gas.kinetic_energy();
  const std::uint64_t crossings_before = gas.crossings();
  const std::uint64_t stale_before = gas.stale();
  const double cpu_start = cpu_seconds();
  TimedCollisions timed;
  timed.collisions = gas.run_collisions(wanted);
  timed.cpu_seconds = cpu_seconds() - cpu_start;
  const auto count = static_cast<double>(timed.collisions);
  timed.crossings_per_collision = static_cast<double>(gas.crossings() - crossings_before) / count;
  timed.stale_per_collision = static_cast<double>(gas.stale() - stale_before) / count;
  timed.energy_drift = (gas.kinetic_energy() - energy_before) / energy_before;
  return timed;
}

// A gas's start as plain arrays (positions and velocities, in the World's order of balls()),
// for the simulators that run it without carom's engine.
struct GasStart {
  double side = 0.0;
  std::vector<double> x, y, vx, vy;
};

inline GasStart start_of(const carom::World& world, double side) {
  GasStart start;
  start.side = side;
  for (const carom::BallId id : world.balls()) {
    const carom::Vec2 p = world.position(id);
    const carom::Vec2 v = world.velocity(id);
    start.x.push_back(p.x);
    start.y.push_back(p.y);
    start.vx.push_back(v.x);
    start.vy.push_back(v.y);
  }
  return start;
}

// Brings a disk stored at its local time t to time `now` (position + velocity·(now − t)).
template <class Disk>
void advance_to(Disk& disk, double now) {
  const double dt = now - disk.t;
  disk.x += disk.vx * dt;
  disk.y += disk.vy * dt;
  disk.t = now;
}

// A ball's cell along one axis, one step up or down, through the periodic box's edge: leaving the
// last cell upward it enters cell 0 and its coordinate moves down by the box's side (and the
// reverse), so that positions stay inside the box and inside their cells.
template <class Cell>
void step_cell(Cell& cell, double& coordinate, bool upward, Cell cells, double side) {
  if (upward) {
    if (++cell == cells) {
      cell = 0;
      coordinate -= side;
    }
  } else if (cell-- == 0) {
    cell = cells - 1;
    coordinate += side;
  }
}

// The elastic equal-mass bounce of two disks whose centres are (dx, dy) apart (from a to b, the
// nearest image): the components of the velocities along the line of centres are exchanged. The
// impulse is divided by |d|² as computed, so that energy is conserved whatever the rounding of
// the contact positions.
template <class Disk>
void exchange_normal_velocities(Disk& a, Disk& b, double dx, double dy) {
  const double factor = ((b.vx - a.vx) * dx + (b.vy - a.vy) * dy) / (dx * dx + dy * dy);
  a.vx += factor * dx;
  a.vy += factor * dy;
  b.vx -= factor * dx;
  b.vy -= factor * dy;
}

}  // namespace carom::bench
