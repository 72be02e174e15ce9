// carom web: the "Compression" page's world, a box or periodic cell of disks compressed live
// (Lubachevsky–Stillinger, as carom::science::compress does it) one animation frame at a time.
//
// make_packing is carom::science::make_packing_world with arguments JavaScript can pass;
// compress_frame runs one frame of the compression: windows of N collisions while every radius
// grows, the thermostat after each window, and the reduced pressure from the collisional virial
// of the ball–ball contacts. Windows end only after N collisions or at the frame's `until`, never
// at its collision budget, so the run is the same however a machine's speed splits it into
// frames. docs/science.md, "Compression and jamming".
#pragma once

#include <cstdint>

#include "carom/world.hpp"
#include "drawn_world.hpp"

namespace carom::web {

// science::PackingSpec, in the types embind passes (no 64-bit integers): N disks, a fraction of
// them `second_diameter` times the first's, at random at packing fraction start_eta, the cell
// sized so that the first species' diameter is 1 at sized_for_eta.
struct PackingStart {
  int count = 400;
  double second_diameter = 1.0;
  double second_fraction = 0.0;
  Boundary boundary = Boundary::periodic;
  double aspect = 1.0;  // the cell's height over its width
  double start_eta = 0.3;
  double sized_for_eta = 0.84;
  std::uint32_t seed = 1;
};

// Throws carom::InvalidArgument (science::make_packing_world's) for a start out of range.
[[nodiscard]] DrawnWorld make_packing(const PackingStart& start);

struct CompressionFrame {
  // The smallest diameter's growth speed in thermal speeds √(kT/m), as
  // science::CompressionSettings::rate; 0: the radii keep their size.
  double rate = 0.0;
  double kT = 1.0;  // the thermostat's temperature, > 0
  // The world time the frame ends at, at most (a window ends there too); finite. A frame cut
  // short by its collision budget leaves the rest to the next one with the same `until`.
  double until = 0.0;
  int collisions = 100000;  // at most about this many: whole windows of N, at least one
  // The frame stops after a window whose reduced pressure passes this; 0: never.
  double pressure_limit = 0.0;
};

struct CompressionFrameResult {
  double collisions = 0.0;  // resolved (a double: JavaScript numbers)
  double time = 0.0;        // the world time the frame covered
  // Σ σ_ij·J_ij / kT over the frame's ball–ball contacts, kT each window's mean kinetic energy
  // a disk: the reduced pressure over several frames is 1 + Σ virial / (2·N·Σ time).
  double virial = 0.0;
  double pressure = 0.0;             // Z = PA/(NkT) over this frame; 0 when no time passed
  double window_pressure = 0.0;      // Z over its last window that moved time on; 0 when none did
  double work = 0.0;                 // the thermostat's changes of kinetic energy, summed
  bool over_pressure_limit = false;  // the last window's Z passed the frame's pressure_limit
  // A window of N collisions moved the world's time on by nothing: the gaps between the disks
  // have reached rounding, so the packing is as jammed as the arithmetic can say.
  bool stalled = false;
};

// One frame: sets the world's growth from `rate` (kept when it already grows at that speed, so
// that frames continue one growth), then runs windows of N collisions up to `until`, the
// collision budget or a window over the pressure limit, scaling the velocities to kT after each.
// Growth stays on afterwards; set the world's growth rate to 0 to stop it. The world must hold
// movable disks only, without gravity.
[[nodiscard]] CompressionFrameResult compress_frame(DrawnWorld& world,
                                                    const CompressionFrame& frame);

}  // namespace carom::web
