// carom tool: `carom render --animate`: a run drawn frame by frame with Cairo and encoded by
// ffmpeg into an animated GIF or an MP4 that browsers play.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "carom/scene.hpp"
#include "drawing/ball_colours.hpp"
#include "drawing/ffmpeg_pipe.hpp"
#include "drawing/view_box.hpp"

namespace carom::cli {

struct AnimationRequest {
  std::string path;  // the file to write (replaced atomically once ffmpeg has finished)
  VideoFormat format = VideoFormat::gif;
  std::string ffmpeg;  // the program (find_ffmpeg)
  double until = 1.0;  // time units after the scene's start; > 0
  double fps = 25.0;   // frames per second of video, and of scene time
  int width = 640;
  ColourMode mode = ColourMode::speed;
  std::vector<Rgb> name_colours;  // name mode
  bool arrows = false;
  std::optional<ViewBox> view;  // the part of the plane to show (--view); else the whole run's
  double trail_seconds = 0.0;   // 0: no trails
  std::string title;
};

struct AnimationResult {
  int frames = 0;
  int width = 0;
  int height = 0;
  bool interrupted = false;  // a signal ended the video early, after `frames` frames
  double end_time = 0.0;     // of the last frame, in time units after the scene's start
};

// The frame count for a run of `until` at fps: one frame at the start and one per 1/fps after,
// the last at `until` exactly.
[[nodiscard]] long long frame_count(double until, double fps);

// Runs the scene twice (the runs are deterministic, so they agree): once to learn the view of
// an open world and the top speed for the colour scale, once to draw. Throws
// std::runtime_error when drawing or ffmpeg fails; the file is then left as it was. A signal
// (StopOnSignals) while drawing ends the video at the last frame drawn, complete; one during the
// first run ends it with no video (frames 0).
AnimationResult render_animation(const Scene& scene, const AnimationRequest& request);

}  // namespace carom::cli
