#include "render_animation.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "cairo_picture.hpp"
#include "scene_picture.hpp"
#include "trail_recorder.hpp"

namespace carom::cli {
namespace {

double frame_time(double until, long long frames, long long k) {
  return until * (static_cast<double>(k) / static_cast<double>(frames - 1));
}

// What the first run learns: where the balls go (their centres at contacts too, where trails
// bend) and how fast they get.
struct RunSurvey {
  ViewBox balls_seen;
  double top_speed = 0.0;
};

RunSurvey survey(const Scene& scene, double until, long long frames) {
  SceneWorld scene_world = make_world(scene);
  RunSurvey result;
  std::vector<ContactEvent> contacts;
  for (long long k = 0; k < frames; ++k) {
    const double target = frame_time(until, frames, k);
    contacts.clear();
    step_scene(scene_world, target - scene_world.world.time(), &contacts);
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
  const long long frames = frame_count(request.until, request.fps);
  const RunSurvey seen = survey(scene, request.until, frames);

  PictureStyle style;
  style.mode = request.mode;
  style.top_speed = seen.top_speed > 0.0 ? seen.top_speed : 1.0;
  style.name_colours = request.name_colours;
  frame_picture(style, scene, seen.balls_seen, request.view, request.arrows);
  style.title = request.title;
  const ImageLayout layout =
      layout_image(style.view, request.width, request.mode == ColourMode::speed, true);
  CairoImage image(layout.width, layout.height);

  const std::string temporary = request.path + ".tmp";
  std::error_code ignored;
  try {
    FfmpegPipe ffmpeg(request.ffmpeg, temporary, request.format, layout.width, layout.height,
                      request.fps);
    SceneWorld scene_world = make_world(scene);
    std::optional<TrailRecorder> trails;
    if (request.trail_seconds > 0.0) {
      trails.emplace(scene_world, request.trail_seconds);
      style.trails = &*trails;
    }
    std::vector<ContactEvent> contacts;
    for (long long k = 0; k < frames; ++k) {
      contacts.clear();
      const double target = frame_time(request.until, frames, k);
      step_scene(scene_world, target - scene_world.world.time(), &contacts);
      if (trails) trails->record(scene_world, contacts);
      paint_picture(image, layout, draw_scene(scene_world, style));
      ffmpeg.write_frame(image.pixels(), image.stride());
    }
    ffmpeg.finish();
  } catch (...) {
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code renamed;
  std::filesystem::rename(temporary, request.path, renamed);
  if (renamed) {
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error("cannot rename " + temporary + " to " + request.path + ": " +
                             renamed.message());
  }
  return {static_cast<int>(frames), layout.width, layout.height};
}

}  // namespace carom::cli
