#include "commands/render_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "carom/scene.hpp"
#include "drawing/ball_colours.hpp"
#include "drawing/cairo_picture.hpp"
#include "drawing/ffmpeg_pipe.hpp"
#include "drawing/picture_file.hpp"
#include "drawing/render_animation.hpp"
#include "drawing/render_plot.hpp"
#include "drawing/scene_picture.hpp"
#include "drawing/scene_svg.hpp"
#include "drawing/trail_recorder.hpp"
#include "drawing/view_box.hpp"
#include "options/exit_codes.hpp"
#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "options/vector_args.hpp"
#include "run/scene_input.hpp"
#include "system/output_file.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {
namespace {

constexpr int kAnimationWidth = 640;  // smaller: a GIF grows with every pixel of every frame
// More frames than this is almost surely a typo in --until or --fps (an hour at 30 fps is
// 108000): refused before a long run.
constexpr long long kMostFrames = 200'000;
constexpr double kMostFps = 240.0;

// The options as typed; every value is parsed here so one set of rules and messages covers all.
struct RenderOptions {
  std::string scene;
  std::string out;
  std::string at = "0";
  std::string animate;
  std::string until;
  std::string fps = "25";
  std::string color = "auto";
  bool arrows = false;
  std::string trails;
  std::string plot;
  std::string width;
  std::optional<std::string> view;  // given, even as "", or not
};

enum class PictureFormat { svg, png };

// What the options ask for, checked.
struct RenderRequest {
  std::optional<PictureFormat> picture;  // --out without --plot
  std::optional<PlotKind> plot;          // --plot (written to --out)
  std::optional<VideoFormat> animation;  // --animate
  double at = 0.0;
  double until = 0.0;
  double fps = 25.0;
  std::optional<ColourMode> mode;  // nothing: by name if the scene gives colours, else by speed
  double trails = 0.0;
  std::optional<int> width;
  std::optional<ViewBox> view;  // --view: the part of the plane to show, instead of the scene's
  std::string ffmpeg;
};

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

double parse_time(std::string_view option, const std::string& text, std::string_view expected) {
  const OptionValue value{option, text, expected};
  const double t = parse_finite_number(text, value);
  if (t < 0.0) reject(value, "a time must be >= 0");
  return t;
}

// "XMIN,YMIN,XMAX,YMAX": a box of positive width and height, small enough that its sides are
// finite numbers.
ViewBox parse_view(const std::string& text) {
  constexpr std::string_view kForm = "XMIN,YMIN,XMAX,YMAX";
  const std::vector<double> n = parse_number_list("--view", text, kForm);
  const OptionValue value{"--view", text, kForm};
  if (!(n[0] < n[2])) reject(value, "XMIN must be less than XMAX");
  if (!(n[1] < n[3])) reject(value, "YMIN must be less than YMAX");
  const ViewBox view{{n[0], n[1]}, {n[2], n[3]}};
  if (!std::isfinite(view.width()) || !std::isfinite(view.height())) {
    reject(value, "the box is too large to draw");
  }
  return view;
}

RenderRequest parse(const RenderOptions& o) {
  RenderRequest r;
  if (o.out.empty() && o.animate.empty()) {
    throw UsageError("--out", "",
                     "say what to write: --out FILE (.svg, .png), --animate FILE "
                     "(.gif, .mp4), or --plot KIND with --out FILE.svg");
  }
  if (!o.plot.empty()) {
    if (o.plot == "energy") {
      r.plot = PlotKind::energy;
    } else if (o.plot == "momentum") {
      r.plot = PlotKind::momentum;
    } else if (o.plot == "rate") {
      r.plot = PlotKind::rate;
    } else {
      throw UsageError("--plot", o.plot, "is not a plot; the plots are energy, momentum, rate");
    }
    if (o.out.empty()) throw UsageError("--plot", o.plot, "needs --out FILE.svg to write to");
    if (extension_of(o.out) != ".svg") {
      throw UsageError("--out", o.out, "a plot is written as SVG: the file name must end in .svg");
    }
  } else if (!o.out.empty()) {
    const std::string ext = extension_of(o.out);
    if (ext == ".svg") {
      r.picture = PictureFormat::svg;
    } else if (ext == ".png") {
      r.picture = PictureFormat::png;
    } else {
      throw UsageError("--out", o.out, "the file name must end in .svg or .png");
    }
  }
  if (!o.animate.empty()) {
    const std::string ext = extension_of(o.animate);
    if (ext == ".gif") {
      r.animation = VideoFormat::gif;
    } else if (ext == ".mp4") {
      r.animation = VideoFormat::mp4;
    } else {
      throw UsageError("--animate", o.animate, "the file name must end in .gif or .mp4");
    }
  }

  r.at = parse_time("--at", o.at, "a time T >= 0 after the scene's start");
  if (r.plot || r.animation) {
    if (o.until.empty()) {
      throw UsageError(
          "--until", "",
          std::string(r.plot ? "a plot" : "an animation") + " needs the time to run to: --until T");
    }
    r.until = parse_time("--until", o.until, "a time T > 0 after the scene's start");
    if (!(r.until > 0.0)) {
      reject({"--until", o.until, "a time T > 0 after the scene's start"}, "must be > 0");
    }
  }
  const OptionValue fps{"--fps", o.fps, "frames per second F, 0 < F <= 240"};
  r.fps = parse_finite_number(o.fps, fps);
  if (!(r.fps > 0.0 && r.fps <= kMostFps)) reject(fps, "out of range");
  if (r.animation && frame_count(r.until, r.fps) > kMostFrames) {
    reject(fps, "--until " + o.until + " at this rate makes " +
                    std::to_string(frame_count(r.until, r.fps)) + " frames; at most " +
                    std::to_string(kMostFrames));
  }

  if (o.color == "speed") {
    r.mode = ColourMode::speed;
  } else if (o.color == "name") {
    r.mode = ColourMode::name;
  } else if (o.color != "auto") {
    throw UsageError("--color", o.color, "is not a colouring; use speed, name or auto");
  }
  if (!o.trails.empty()) {
    const OptionValue value{"--trails", o.trails, "a length of time S > 0"};
    r.trails = parse_finite_number(o.trails, value);
    if (!(r.trails > 0.0)) reject(value, "must be > 0");
  }
  if (o.view) r.view = parse_view(*o.view);
  if (!o.width.empty()) {
    const OptionValue value{"--width", o.width, "a whole number of pixels from 64 to 8192"};
    const double w = parse_finite_number(o.width, value);
    if (w != std::floor(w) || w < kSmallestWidth || w > kLargestWidth)
      reject(value, "out of range");
    r.width = static_cast<int>(w);
  }
  return r;
}

// The outputs must be writable, and ffmpeg there, before the scene is even read.
void check_outputs(const RenderOptions& o, RenderRequest& r) {
  if (r.animation) {
    const std::optional<std::string> ffmpeg = find_ffmpeg();
    if (!ffmpeg) {
      throw UsageError("--animate", o.animate,
                       "needs the ffmpeg program, which is not on PATH (on Debian: "
                       "apt-get install ffmpeg)");
    }
    r.ffmpeg = *ffmpeg;
    if (auto error = check_output(o.animate)) throw UsageError("--animate", o.animate, *error);
    // ffmpeg writes the video into a temporary file that is renamed when complete (an MP4's
    // index comes last), so the target must be a file.
    if (!replaced_by_rename(o.animate)) {
      throw UsageError("--animate", o.animate,
                       "an animation is written to a file (through links too), not to standard "
                       "output, a device or a FIFO");
    }
  }
  if (!o.out.empty()) {
    if (auto error = check_output(o.out)) throw UsageError("--out", o.out, *error);
  }
}

void advance_to(SceneWorld& scene_world, double time, std::vector<ContactEvent>* contacts) {
  if (time > scene_world.world.time()) {
    step_scene(scene_world, time - scene_world.world.time(), contacts);
  }
}

void write_or_throw(const std::string& option, const std::string& path, std::string_view bytes) {
  if (auto error = write_output(path, bytes)) throw UsageError(option, path, *error);
}

// Where the verb's own lines go: stdout, unless a picture or plot is written there.
std::ostream& report_stream(const RenderOptions& o) {
  return o.out == kStandardOutput ? std::cerr : std::cout;
}

void render_picture(const Scene& scene, const RenderOptions& o, const RenderRequest& r,
                    ColourMode mode, const std::vector<Rgb>& name_colours) {
  SceneWorld scene_world = make_world(scene);
  // A signal stops the run: the picture is then of the time reached.
  stop_world_on_signals(scene_world.world);
  std::optional<TrailRecorder> trails;
  const double window_start = std::max(0.0, r.at - r.trails);
  if (r.trails > 0.0) {
    // Without gravity the path is exact from the contacts: where each ball was when the window
    // opened, its centre at each contact since, and where it is now.
    advance_to(scene_world, window_start, nullptr);
    trails.emplace(scene_world, r.trails);
    trails->record(scene_world, {});
  }
  std::vector<ContactEvent> contacts;
  if (trails && (scene.world.gravity != Vec2{} || scene.world.table)) {
    // Under gravity, and on a table's cloth, a ball moves on parabolas: the trail is drawn
    // through its centre at kTrailPieces even times across the window as well (a chord then
    // strays from the parabola by at most |a|·(window/kTrailPieces)²/8). Splitting the run into
    // steps changes none of it.
    constexpr int kTrailPieces = 64;
    for (int k = 1; k <= kTrailPieces; ++k) {
      contacts.clear();
      const double piece_end =
          k == kTrailPieces
              ? r.at
              : window_start + (r.at - window_start) * (static_cast<double>(k) / kTrailPieces);
      advance_to(scene_world, piece_end, &contacts);
      trails->record(scene_world, contacts);
    }
  } else {
    advance_to(scene_world, r.at, &contacts);
    if (trails) trails->record(scene_world, contacts);
  }

  PictureStyle style;
  style.mode = mode;
  const double top = top_speed(scene_world);
  style.top_speed = top > 0.0 ? top : 1.0;
  style.name_colours = name_colours;
  ViewBox seen = balls_box(scene_world);
  if (trails) seen.add(trails->extent(scene_world.time()));
  frame_picture(style, scene, seen, r.view, o.arrows);
  style.title = std::filesystem::path(scene_source_name(o.scene)).filename().string();
  if (trails) style.trails = &*trails;
  const ScenePicture picture = draw_scene(scene_world, style);

  const bool svg = *r.picture == PictureFormat::svg;
  const PictureFile file =
      encode_picture(picture, svg, r.width.value_or(kPictureWidth), style.arrow_seconds);
  write_or_throw("--out", o.out, file.bytes);
  report_stream(o) << "picture: " << o.out << " ("
                   << (svg ? ""
                           : std::to_string(file.width) + "x" + std::to_string(file.height) +
                                 " pixels, ")
                   << "t = " << rounded(scene_world.time()) << " " << scene.units.time << ")\n";
}

int run(const RenderOptions& o) {
  RenderRequest r = parse(o);
  check_outputs(o, r);
  // Ctrl-C or SIGTERM stops the run: what is written then shows the time reached.
  const StopOnSignals stop_on_signals;
  const Scene scene = read_scene_argument(o.scene);
  const std::string title = std::filesystem::path(scene_source_name(o.scene)).filename().string();

  if (r.plot) {
    write_or_throw("--out", o.out, render_plot(scene, *r.plot, r.until, title));
    report_stream(o) << "plot: " << o.out << " (" << readable(r.until) << " " << scene.units.time
                     << " of the run)\n";
  }

  if (!r.picture && !r.animation) return kExitSuccess;
  const ColourMode mode =
      r.mode.value_or(scene_gives_colours(scene) ? ColourMode::name : ColourMode::speed);
  // Checked even in speed mode: a colour no picture can draw is a mistake in the scene.
  const std::vector<Rgb> name_colours = named_ball_colours(scene, expand_balls(scene), o.scene);

  if (r.picture) render_picture(scene, o, r, mode, name_colours);
  if (r.animation) {
    AnimationRequest request;
    request.path = o.animate;
    request.format = *r.animation;
    request.ffmpeg = r.ffmpeg;
    request.until = r.until;
    request.fps = r.fps;
    request.width = r.width.value_or(kAnimationWidth);
    request.mode = mode;
    request.name_colours = name_colours;
    request.arrows = o.arrows;
    request.view = r.view;
    request.trail_seconds = r.trails;
    request.title = title;
    const AnimationResult result = render_animation(scene, request);
    if (result.frames == 0) {
      std::cerr << "carom render: " << StopOnSignals::what()
                << " before the first frame was drawn: no animation written\n";
      return StopOnSignals::exit_code();
    }
    report_stream(o) << "animation: " << o.animate << " (" << result.frames << " frames, "
                     << result.width << "x" << result.height << " pixels, " << readable(r.fps)
                     << " fps, " << readable(result.end_time) << " " << scene.units.time
                     << " of the run)\n";
  }
  if (StopOnSignals::requested()) {
    std::cerr << "carom render: " << StopOnSignals::what()
              << "; what was written shows the run up to there\n";
    return StopOnSignals::exit_code();
  }
  return kExitSuccess;
}

// Scene errors and failures of the tools carom calls end the verb here with one message: the
// dispatcher knows only command-line errors.
int run_reporting_errors(const RenderOptions& o) {
  try {
    return run(o);
  } catch (const SceneError& error) {
    std::cerr << "carom render: error: " << error.what() << '\n';
    return kExitUsage;
  } catch (const UsageError&) {
    throw;
  } catch (const std::runtime_error& error) {
    std::cerr << "carom render: error: " << error.what() << '\n';
    return kExitFailure;
  }
}

}  // namespace

Command add_render_command(CLI::App& app) {
  CLI::App* render = app.add_subcommand(
      "render", "Draw a scene (SVG, PNG), animate a run (GIF, MP4) or plot it (SVG)");
  render->footer(
      "Times are in the scene's time units after the scene's start. Colours: by speed on a\n"
      "colour scale (with a legend), by the scene's colours and names, or auto (by name when\n"
      "the scene gives colours, else by speed). Animations need the ffmpeg program.\n\n"
      "Examples:\n"
      "  carom render examples/billiards.json --at 0.5 --out break.png\n"
      "  carom render examples/billiards.json --animate break.gif --until 2 --fps 25\n"
      "  carom render examples/pinball.json --at 1 --arrows --trails 0.5 --out pinball.svg\n"
      "  carom render examples/billiards.json --at 1 --view 0,0,1.4,1.4 --out corner.png\n"
      "  carom render examples/box-of-1000.json --plot energy --until 10 --out energy.svg");

  auto o = std::make_shared<RenderOptions>();
  render->add_option("SCENE", o->scene, "The scene file (JSON)")->required();
  render
      ->add_option("-o,--out", o->out,
                   "Write a picture (.svg, .png), or the --plot (.svg), to FILE")
      ->type_name("FILE");
  render->add_option("--at", o->at, "Draw the scene at this time after its start")
      ->type_name("T")
      ->capture_default_str();
  render->add_option("--animate", o->animate, "Write an animation of the run (.gif, .mp4)")
      ->type_name("FILE");
  render->add_option("--until", o->until, "Run to this time (for --animate and --plot)")
      ->type_name("T");
  render->add_option("--fps", o->fps, "Frames per second, of video and of scene time")
      ->type_name("F")
      ->capture_default_str();
  render->add_option("--color", o->color, "Colour balls by speed, by name, or auto")
      ->type_name("speed|name|auto")
      ->capture_default_str();
  render->add_flag("--arrows", o->arrows, "Draw each moving ball's velocity as an arrow");
  render->add_option("--trails", o->trails, "Draw where each ball was over the last S time units")
      ->type_name("S");
  render->add_option("--plot", o->plot, "Plot energy, momentum or the collision rate (to --out)")
      ->type_name("energy|momentum|rate");
  render
      ->add_option("--width", o->width,
                   "Image width in pixels (default 960 for PNG, 640 for animations)")
      ->type_name("PIXELS");
  render
      ->add_option_function<std::string>(
          "--view", [o](const std::string& text) { o->view = text; },
          "Show this box of the plane (scene units) instead of the whole scene")
      ->type_name("XMIN,YMIN,XMAX,YMAX");
  return {render, [o] { return run_reporting_errors(*o); }};
}

}  // namespace carom::cli
