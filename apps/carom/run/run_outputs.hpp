// carom tool: what `carom run` writes while it runs — frames (CSV or extended XYZ) and contact
// events (JSON lines) — each streamed to an OutputFile (a file appears only when complete).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "carom/number_text.hpp"
#include "carom/scene.hpp"
#include "system/output_file.hpp"

namespace carom::cli {

enum class FrameFormat : std::uint8_t { csv, xyz };

// The format a frames file's name asks for: ".csv" or ".xyz" (any case); nothing otherwise.
[[nodiscard]] std::optional<FrameFormat> frame_format_of(const std::string& path);

// Ball ids to scene indices and names, fixed when the run starts, so that a ball potted (and
// removed from the world) is still named in the events that mention it.
class BallDirectory {
 public:
  explicit BallDirectory(const SceneWorld& built);
  // The scene index of a ball; nothing if unknown.
  [[nodiscard]] std::optional<std::size_t> ball_index(BallId id) const;

 private:
  static std::uint64_t key(BallId id);
  std::unordered_map<std::uint64_t, std::size_t> balls_;
};

// Positions and velocities of every ball in the world, one frame at a time.
class FrameWriter {
 public:
  FrameWriter(FrameFormat format, const Scene& scene) : format_(format), scene_(&scene) {}
  [[nodiscard]] std::optional<std::string> open(const std::string& path) { return out_.open(path); }
  void write_frame(const SceneWorld& built);
  [[nodiscard]] std::optional<std::string> commit() { return out_.commit(); }
  [[nodiscard]] std::uint64_t frames() const { return frames_; }

 private:
  FrameFormat format_;
  const Scene* scene_;
  OutputFile out_;
  std::uint64_t frames_ = 0;
  std::string buffer_;
};

// Every contact, one JSON object per line, with scene time and scene indices.
class EventWriter {
 public:
  [[nodiscard]] std::optional<std::string> open(const std::string& path) { return out_.open(path); }
  // wall_offset: how many walls the world's boundary added before the scene's own (4 for a box).
  // The sensors' enters and exits (built.sensor_events) go in among the contacts, in order.
  void write(const std::vector<ContactEvent>& contacts, const BallDirectory& directory,
             const SceneWorld& built, std::size_t wall_offset);
  [[nodiscard]] std::optional<std::string> commit() { return out_.commit(); }

 private:
  OutputFile out_;
  std::string buffer_;
};

}  // namespace carom::cli
