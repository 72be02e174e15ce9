// carom tool: where each ball has been lately, for the trails `carom render --trails` draws.
//
// Between contacts a ball moves in a straight line, so its path is exactly the polyline through
// its centre at each of its contacts, plus where it was at the start and where it is now. Under
// gravity it flies on parabolas, and the callers record it at many times between too (frames, or
// even pieces of the window). The recorder keeps those points for the last `seconds` of scene
// time.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <span>
#include <vector>

#include "carom/scene.hpp"
#include "carom/vec2.hpp"
#include "drawing/view_box.hpp"

namespace carom::cli {

// Where each ball's centre was at each of these contacts (world times, as step_scene gives them):
// the points a trail bends at, which may lie outside the box of the frames' positions.
[[nodiscard]] ViewBox contact_centres(const SceneWorld& scene_world,
                                      std::span<const ContactEvent> contacts);

class TrailRecorder {
 public:
  // For the balls of scene_world (scene indices), keeping `seconds` of history.
  TrailRecorder(const SceneWorld& scene_world, double seconds);

  // The centres of the balls at each of these contacts (world times, as step_scene gives them),
  // then every live ball where it is now. Call after each advance with that advance's contacts.
  void record(const SceneWorld& scene_world, std::span<const ContactEvent> contacts);

  // Each ball's path over the last `seconds` up to world time now, as runs of points: one run,
  // or several where a periodic world wrapped the ball around (each run then leaves the cell by
  // the short way, for the picture's clip to cut). A ball that has not moved gives no run.
  [[nodiscard]] std::vector<std::vector<Vec2>> paths(std::size_t ball, double now) const;
  // The box around every ball's paths up to world time now: what a picture must show of them.
  [[nodiscard]] ViewBox extent(double now) const;
  [[nodiscard]] std::size_t ball_count() const { return points_.size(); }

 private:
  struct Point {
    double time;
    Vec2 at;
  };
  void add(std::size_t ball, double time, Vec2 at);
  [[nodiscard]] Vec2 shortest(Vec2 from, Vec2 to) const;  // to - from, by the minimum image

  double seconds_;
  std::optional<Vec2> period_;  // the periodic cell's sides
  std::vector<std::deque<Point>> points_;
};

}  // namespace carom::cli
