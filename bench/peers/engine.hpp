// carom peers benchmark: one engine behind a small interface, so that the harness times and
// checks carom, Box2D and Chipmunk the same way. Each adapter sets its engine up as the scene
// asks (its gravity and restitution, frictionless, no damping, four static walls) with the
// engine's documented defaults for everything else; each adapter's file says what it had to set.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "carom/vec2.hpp"
#include "detectors.hpp"
#include "scene.hpp"

namespace carom::peers {

class Engine {
 public:
  Engine() = default;
  virtual ~Engine() = default;
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;
  Engine(Engine&&) = delete;
  Engine& operator=(Engine&&) = delete;

  // Advances the world by dt seconds: the work that is timed.
  virtual void step(double dt) = 0;
  // Every disk's centre and velocity, in the scene's order (untimed).
  virtual void read(std::span<Vec2> positions, std::span<Vec2> velocities) const = 0;
  // Where the last step bent each disk's path (an event-driven engine's contacts within the
  // step), appended to `breaks`; a time-stepped engine moves each disk in one straight line per
  // step and adds nothing.
  virtual void path_breaks(double dt, std::vector<PathBreak>& breaks) const {
    static_cast<void>(dt);
    static_cast<void>(breaks);
  }
  // Contacts resolved so far, where the engine counts them (carom does); -1 where it does not.
  [[nodiscard]] virtual std::int64_t contact_count() const { return -1; }
};

struct EngineInfo {
  std::string name;     // as on the command line: carom, box2d, chipmunk
  std::string version;  // the library's version, for the report
};

// The engines this build has, carom first.
[[nodiscard]] std::vector<EngineInfo> available_engines();

// The engine named `name` holding `scene`; throws std::invalid_argument for an unknown name.
[[nodiscard]] std::unique_ptr<Engine> make_engine(std::string_view name, const Scene& scene);

[[nodiscard]] std::unique_ptr<Engine> make_carom_engine(const Scene& scene);
#if CAROM_PEERS_BOX2D
[[nodiscard]] std::unique_ptr<Engine> make_box2d_engine(const Scene& scene);
[[nodiscard]] std::string box2d_version();
#endif
#if CAROM_PEERS_CHIPMUNK
[[nodiscard]] std::unique_ptr<Engine> make_chipmunk_engine(const Scene& scene);
[[nodiscard]] std::string chipmunk_version();
#endif

}  // namespace carom::peers
