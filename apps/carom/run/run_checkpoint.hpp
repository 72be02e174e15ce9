// carom tool: checkpoints of `carom run` — everything a run needs to go on after a stop or a
// crash: the world (World::save), what the scene layer adds to it (the expanded scene, which world
// ball is which scene ball, the pockets, the scene clock) and the run's own progress. Format and
// guarantees: docs/checkpoints.md.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "carom/scene.hpp"

namespace carom::cli {

// How far a run got, and what it was asked to do (a resumed run must be asked the same).
struct RunProgress {
  // The run's plan: mode (0 until, 1 steps, 2 collisions, 3 until rest) and its numbers; every and
  // checkpoint_every are 0 when not given.
  std::uint8_t mode = 0;
  double until = 0.0;
  std::uint64_t steps = 0;
  double dt = 0.0;
  std::uint64_t collisions = 0;
  bool has_time_limit = false;  // --collisions with --time-limit
  double time_limit = 0.0;      // scene time
  double every = 0.0;
  double checkpoint_every = 0.0;
  // Where it stands.
  double run_start_time = 0.0;  // scene time when the first run started
  std::uint64_t next_frame = 1;
  std::uint64_t next_chunk = 1;
  std::uint64_t next_checkpoint = 1;
  std::uint64_t steps_done = 0;
  // --steps: a step cut short by a signal, and the world time it ends at (fixed when it began).
  bool in_step = false;
  double step_end = 0.0;
  std::uint64_t collisions_done = 0;  // contacts counted by --collisions
  std::uint64_t ball_ball = 0;
  std::uint64_t ball_wall = 0;
  std::uint64_t potted = 0;
  double last_frame_time = 0.0;
  // The state at the first run's start, so that --stats reports drift over the whole run.
  std::uint64_t balls_at_start = 0;
  double energy_before = 0.0;     // kinetic
  double potential_before = 0.0;  // of gravity
  double momentum_before_x = 0.0;
  double momentum_before_y = 0.0;
  double movable_mass = 0.0;
  std::string scene_file;
};

struct Checkpoint {
  SceneWorld built;
  RunProgress progress;
};

// A checkpoint that cannot be read: what() names the file and the problem.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The checkpoint as bytes: header (magic, version, content size, checksum), then the content.
[[nodiscard]] std::string encode_checkpoint(const SceneWorld& built, const RunProgress& progress);
// Reads bytes written by encode_checkpoint; file names them in errors. Throws CheckpointError.
[[nodiscard]] Checkpoint decode_checkpoint(std::string_view bytes, const std::string& file);

// Writes bytes to path + ".tmp" (beside a link's target), syncs it to the disk, then renames path
// (if any) to path + ".prev" and the new file onto path (an AtomicFile keeping the previous one):
// a complete checkpoint exists at every moment, in path or, between the two renames, in
// path + ".prev". Returns what went wrong, or nothing.
[[nodiscard]] std::optional<std::string> write_checkpoint(const std::string& path,
                                                          std::string_view bytes);
// Reads and decodes a checkpoint file. Throws CheckpointError.
[[nodiscard]] Checkpoint read_checkpoint(const std::string& path);

}  // namespace carom::cli
