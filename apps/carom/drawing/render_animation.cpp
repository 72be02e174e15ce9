#include "drawing/render_animation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "carom/atomic_file.hpp"
#include "drawing/cairo_picture.hpp"
#include "drawing/scene_picture.hpp"
#include "drawing/trail_recorder.hpp"
#include "system/progress_bar.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {
namespace {

double frame_time(double until, long long frames, long long k) {
  return until * (static_cast<double>(k) / static_cast<double>(frames - 1));
}

// What the first run learns: where the balls go (their centres at contacts too, where trails
// bend), how fast they get, and how many frames' times it reached (fewer when a signal stopped
// it).
struct RunSurvey {
  ViewBox balls_seen;
  double top_speed = 0.0;
  long long frames = 0;
};

// The run is made twice; the first (no drawing) is taken as a tenth of the work.
constexpr double kSurveyShare = 0.1;

RunSurvey survey(const Scene& scene, double until, long long frames, ProgressBar& bar) {
  SceneWorld scene_world = make_world(scene);
  stop_world_on_signals(scene_world.world);
  RunSurvey result;
  std::vector<ContactEvent> contacts;
  for (long long k = 0; k < frames; ++k) {
    bar.update(kSurveyShare * static_cast<double>(k) / static_cast<double>(frames),
               "surveying the run");
    const double target = frame_time(until, frames, k);
    contacts.clear();
    step_scene(scene_world, target - scene_world.world.time(), &contacts);
    if (scene_world.world.stop_reason() == StopReason::interrupted) break;
    result.frames = k + 1;
    result.balls_seen.add(balls_box(scene_world));
    result.balls_seen.add(contact_centres(scene_world, contacts));
    result.top_speed = std::max(result.top_speed, top_speed(scene_world));
  }
  return result;
}

}  // namespace

long long frame_count(double until, double fps) {
  return std::max(1LL, std::llround(until * fps)) + 1;
}

AnimationResult render_animation(const Scene& scene, const AnimationRequest& request) {
  const long long all_frames = frame_count(request.until, request.fps);
  // On a terminal, how far the two runs have got (stderr; nothing in a pipe or a log).
  ProgressBar bar(true);
  const RunSurvey seen = survey(scene, request.until, all_frames, bar);
  // A signal in the survey ends the verb before anything is drawn (drawing the frames surveyed
  // would take long after the user asked to stop); one while drawing ends the video at the last
  // frame drawn.
  if (seen.frames < all_frames) return {0, 0, 0, true, 0.0};
  long long frames = 0;

  PictureStyle style;
  style.mode = request.mode;
  style.top_speed = seen.top_speed > 0.0 ? seen.top_speed : 1.0;
  style.name_colours = request.name_colours;
  frame_picture(style, scene, seen.balls_seen, request.view, request.arrows);
  style.title = request.title;
  const ImageLayout layout =
      layout_image(style.view, request.width, request.mode == ColourMode::speed, true);
  CairoImage image(layout.width, layout.height);

  // ffmpeg writes the video into the temporary file (TARGET.tmp beside a link's target, the link
  // kept) that is renamed onto the target when complete.
  std::optional<AtomicFile> video;
  try {
    video.emplace(request.path,
                  AtomicFileOptions{.temporary = TemporaryName::fixed, .sync = false});
  } catch (const FileError& error) {
    throw std::runtime_error("cannot write " + request.path + ": " + error.reason());
  }
  const TemporaryFileGuard guard(video->temporary().string());
  {
    FfmpegPipe ffmpeg(request.ffmpeg, video->temporary().string(), request.format, layout.width,
                      layout.height, request.fps);
    SceneWorld scene_world = make_world(scene);
    stop_world_on_signals(scene_world.world);
    std::optional<TrailRecorder> trails;
    if (request.trail_seconds > 0.0) {
      trails.emplace(scene_world, request.trail_seconds);
      style.trails = &*trails;
    }
    std::vector<ContactEvent> contacts;
    for (long long k = 0; k < seen.frames; ++k) {
      contacts.clear();
      const double time = frame_time(request.until, all_frames, k);
      step_scene(scene_world, time - scene_world.world.time(), &contacts);
      if (scene_world.world.stop_reason() == StopReason::interrupted) break;
      frames = k + 1;
      bar.update(kSurveyShare + (1.0 - kSurveyShare) * static_cast<double>(frames) /
                                    static_cast<double>(seen.frames),
                 "frame " + std::to_string(frames) + " of " + std::to_string(seen.frames));
      if (trails) trails->record(scene_world, contacts);
      paint_picture(image, layout, draw_scene(scene_world, style));
      ffmpeg.write_frame(image.pixels(), image.stride());
    }
    bar.finish();
    ffmpeg.finish();
  }
  try {
    video->commit();
  } catch (const FileError& error) {
    throw std::runtime_error("cannot write " + request.path + ": " + error.reason());
  }
  return {static_cast<int>(frames), layout.width, layout.height, frames < all_frames,
          frame_time(request.until, all_frames, frames - 1)};
}

}  // namespace carom::cli
