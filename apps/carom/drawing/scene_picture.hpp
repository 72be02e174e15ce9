// carom tool: a picture of a scene at one instant, as shapes in world coordinates — what both
// the SVG writer and the Cairo painter draw, so a picture looks the same in either format.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "carom/scene.hpp"
#include "carom/vec2.hpp"
#include "drawing/ball_colours.hpp"
#include "drawing/css_colour.hpp"
#include "drawing/trail_recorder.hpp"
#include "drawing/view_box.hpp"

namespace carom::cli {

struct PictureDisc {
  Vec2 center;
  double radius = 0.0;
  Rgb fill;
  // A copy of a ball that crosses the edge of a periodic cell, drawn on the other side; only a
  // painter that clips to the cell draws these (the SVG picture leaves them out).
  bool wrapped_copy = false;
};

// A polyline; widths count the figure's line widths (1 thin, 2 bold).
struct PictureStroke {
  std::vector<Vec2> points;
  Rgb colour;
  double width = 1.0;
  bool dashed = false;
};

// An arrow over a band of its outline colour, so that it shows on a ball of any colour.
struct PictureArrow {
  Vec2 from;
  Vec2 to;
  Rgb colour;
  Rgb outline;
};

// The colour scale of balls drawn by speed: 0 at one end, top_speed (and faster) at the other.
struct SpeedLegend {
  double top_speed = 1.0;
  std::string unit;  // "m/s"
};

struct ScenePicture {
  std::string title;            // the scene file's name
  std::string subtitle;         // the time and what is drawn
  ViewBox view;                 // what to show, margins included; nothing is drawn outside it
  std::optional<ViewBox> clip;  // the periodic cell, to clip wrapped copies to
  // In drawing order.
  std::vector<PictureStroke> boundary;  // the box (solid) or periodic cell (dashed)
  std::vector<PictureStroke> trails;
  std::vector<PictureDisc> pockets;
  std::vector<PictureStroke> walls;  // a segment or polyline as a line; an arc as points
  std::vector<PictureDisc> balls;
  std::vector<PictureStroke> overlay;  // over the balls: a packing's contact network
  std::vector<PictureArrow> arrows;
  std::optional<SpeedLegend> legend;
  std::string time_unit;  // the scene's, for the arrows' legend
};

// How to draw; fixed for a whole animation so that frames compare.
struct PictureStyle {
  ColourMode mode = ColourMode::speed;
  double top_speed = 1.0;               // speed mode: the speed at the top of the scale (> 0)
  std::vector<Rgb> name_colours;        // name mode: per scene ball (named_ball_colours)
  std::optional<double> arrow_seconds;  // arrows from each centre to where it is this much later
  const TrailRecorder* trails = nullptr;
  ViewBox view;  // from picture_view
  std::string title;
};

// The view of a whole picture or animation: static_view, plus for an open world the balls in
// `balls_seen` (wherever they were in the frames, and their trails), with a margin.
[[nodiscard]] ViewBox picture_view(const Scene& scene, const ViewBox& balls_seen);

// Sets style.view and style.arrow_seconds (with arrows; style.top_speed set first). A `fixed`
// view (--view) is shown as given. Otherwise the view is picture_view(scene, balls_seen), and
// with arrows it grows on every side by the length of the top speed's arrow, so that the arrows
// of balls near its edge stay in the picture.
void frame_picture(PictureStyle& style, const Scene& scene, const ViewBox& balls_seen,
                   const std::optional<ViewBox>& fixed, bool arrows);

// The top of the speed scale now: the 99th percentile of the movable balls' speeds (the
// fastest ball's speed when there are fewer than 100), 0 when none moves.
[[nodiscard]] double top_speed(const SceneWorld& scene_world);
// The box around every live ball now.
[[nodiscard]] ViewBox balls_box(const SceneWorld& scene_world);

// How long ahead the velocity arrows reach: the fastest ball's arrow (at top_speed > 0) is a
// tenth of the view's longer side, long enough to read, short enough not to cross the picture.
[[nodiscard]] double arrow_seconds(const ViewBox& view, double top_speed);

// The scene as it is now.
[[nodiscard]] ScenePicture draw_scene(const SceneWorld& scene_world, const PictureStyle& style);

}  // namespace carom::cli
