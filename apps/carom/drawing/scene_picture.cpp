#include "drawing/scene_picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "options/readable_number.hpp"

namespace carom::cli {
namespace {

// Room around what is drawn, as a share of its longer side: outlines and arrow heads at the
// edge stay inside the picture.
constexpr double kViewMargin = 0.02;
// Line widths, in the figure's thin lines.
constexpr double kWallWidth = 2.0;
constexpr double kBoundaryWidth = 1.5;
constexpr double kTrailWidth = 1.0;
constexpr Rgb kWallColour = rgb_from_hex(0x202020);
constexpr Rgb kCellColour = rgb_from_hex(0x808080);
constexpr Rgb kPocketColour = rgb_from_hex(0x303030);
constexpr Rgb kArrowColour = rgb_from_hex(0xc00000);
constexpr Rgb kArrowOutline = rgb_from_hex(0xffffff);
// The fastest ball's arrow (at the top speed) is this share of the view's longer side: long
// enough to read, short enough not to cross the picture.
constexpr double kArrowShare = 0.1;
// The top of the speed scale is the speed 99 % of the balls do not exceed, so that one fast ball
// does not squeeze everyone else into the dark end; faster balls take the top colour.
constexpr double kTopSpeedShare = 0.99;

std::vector<Vec2> box_outline(Vec2 lower, Vec2 upper) {
  return {lower, {upper.x, lower.y}, upper, {lower.x, upper.y}, lower};
}

// A trail in its ball's colour, darkened so that a white ball's trail still shows on white.
Rgb trail_colour(Rgb ball) {
  constexpr double kDarken = 0.75;
  return {ball.r * kDarken, ball.g * kDarken, ball.b * kDarken};
}

bool is_immovable(const SceneBall& ball) { return ball.mass == kImmovable; }

Rgb ball_colour(const SceneWorld& scene_world, std::size_t index, Vec2 velocity,
                const PictureStyle& style) {
  const SceneBall& ball = scene_world.scene.balls[index];
  if (style.mode == ColourMode::name) return style.name_colours[index];
  if (is_immovable(ball)) return kImmovableColour;
  return speed_colour(length(velocity) / style.top_speed);
}

// The copies of a disc that crosses the edge of the periodic cell, shifted by a period so that
// they show on the other side.
void add_wrapped_copies(std::vector<PictureDisc>& discs, const PictureDisc& disc, Vec2 lower,
                        Vec2 upper) {
  const Vec2 period = upper - lower;
  const auto shifts = [](double c, double r, double lo, double hi, double p) {
    std::array<double, 2> out{0.0, 0.0};
    std::size_t n = 0;
    if (c - r < lo) out[n++] = p;
    if (c + r > hi) out[n++] = -p;
    return std::pair{out, n};
  };
  const auto [xs, nx] = shifts(disc.center.x, disc.radius, lower.x, upper.x, period.x);
  const auto [ys, ny] = shifts(disc.center.y, disc.radius, lower.y, upper.y, period.y);
  for (std::size_t i = 0; i <= nx; ++i) {
    for (std::size_t j = 0; j <= ny; ++j) {
      if (i == 0 && j == 0) continue;
      PictureDisc copy = disc;
      copy.center += Vec2{i == 0 ? 0.0 : xs[i - 1], j == 0 ? 0.0 : ys[j - 1]};
      copy.wrapped_copy = true;
      discs.push_back(copy);
    }
  }
}

}  // namespace

ViewBox picture_view(const Scene& scene, const ViewBox& balls_seen) {
  ViewBox view = static_view(scene);
  if (scene.world.boundary == Boundary::open || view.empty()) view.add(balls_seen);
  return view.padded(kViewMargin);
}

double top_speed(const SceneWorld& scene_world) {
  std::vector<double> speeds;
  for (std::size_t i = 0; i < scene_world.balls.size(); ++i) {
    const BallId id = scene_world.balls[i];
    if (id.is_null() || !scene_world.world.contains(id)) continue;
    if (is_immovable(scene_world.scene.balls[i])) continue;
    speeds.push_back(length(scene_world.world.velocity(id)));
  }
  if (speeds.empty()) return 0.0;
  // The nearest-rank percentile: with fewer than 1 / (1 - kTopSpeedShare) balls, the fastest.
  const auto rank =
      static_cast<std::size_t>(std::ceil(kTopSpeedShare * static_cast<double>(speeds.size())));
  const auto top = speeds.begin() + static_cast<std::ptrdiff_t>(std::max<std::size_t>(rank, 1) - 1);
  std::nth_element(speeds.begin(), top, speeds.end());
  return *top;
}

ViewBox balls_box(const SceneWorld& scene_world) {
  ViewBox box;
  for (const BallId id : scene_world.balls) {
    if (id.is_null() || !scene_world.world.contains(id)) continue;
    box.add(scene_world.world.position(id), scene_world.world.radius(id));
  }
  return box;
}

double arrow_seconds(const ViewBox& view, double top_speed) {
  return kArrowShare * std::max(view.width(), view.height()) / top_speed;
}

void frame_picture(PictureStyle& style, const Scene& scene, const ViewBox& balls_seen,
                   const std::optional<ViewBox>& fixed, bool arrows) {
  style.view = fixed ? *fixed : picture_view(scene, balls_seen);
  if (!arrows) return;
  style.arrow_seconds = arrow_seconds(style.view, style.top_speed);
  if (fixed) return;
  const double reach = kArrowShare * std::max(style.view.width(), style.view.height());
  style.view.add(style.view.lower, reach);
  style.view.add(style.view.upper, reach);
}

ScenePicture draw_scene(const SceneWorld& scene_world, const PictureStyle& style) {
  const Scene& scene = scene_world.scene;
  ScenePicture picture;
  picture.title = style.title;
  picture.view = style.view;
  picture.time_unit = scene.units.time;

  const WorldDef& settings = scene.world;
  if (settings.boundary == Boundary::box) {
    picture.boundary.push_back(
        {box_outline(settings.lower, settings.upper), kWallColour, kBoundaryWidth, false});
  } else if (settings.boundary == Boundary::periodic) {
    picture.boundary.push_back(
        {box_outline(settings.lower, settings.upper), kCellColour, kBoundaryWidth, true});
    picture.clip = ViewBox{settings.lower, settings.upper};
  }

  // A moving wall is drawn where it is now.
  for (std::size_t i = 0; i < scene.segments.size(); ++i) {
    const bool moves = !scene.segment_motions.empty() && scene.segment_motions[i];
    const Segment s = moves
                          ? std::get<Segment>(scene_world.world.wall(segment_wall(scene_world, i)))
                          : scene.segments[i];
    picture.walls.push_back({{s.a, s.b}, kWallColour, kWallWidth});
  }
  for (const ScenePolyline& p : scene.polylines) {
    std::vector<Vec2> points = p.points;
    if (p.closed && !points.empty()) points.push_back(points.front());
    picture.walls.push_back({std::move(points), kWallColour, kWallWidth});
  }
  for (std::size_t i = 0; i < scene.arcs.size(); ++i) {
    const bool moves = !scene.arc_motions.empty() && scene.arc_motions[i];
    const Arc a =
        moves ? std::get<Arc>(scene_world.world.wall(arc_wall(scene_world, i))) : scene.arcs[i];
    picture.walls.push_back({arc_points(a), kWallColour, kWallWidth});
  }
  for (const ScenePocket& p : scene.pockets) {
    picture.pockets.push_back({p.position, p.radius, kPocketColour});
  }

  const double now = scene_world.world.time();
  std::size_t live = 0;
  for (std::size_t i = 0; i < scene_world.balls.size(); ++i) {
    const BallId id = scene_world.balls[i];
    if (id.is_null() || !scene_world.world.contains(id)) continue;
    ++live;
    const Vec2 position = scene_world.world.position(id);
    const Vec2 velocity = scene_world.world.velocity(id);
    const PictureDisc disc{position, scene_world.world.radius(id),
                           ball_colour(scene_world, i, velocity, style)};
    picture.balls.push_back(disc);
    if (picture.clip)
      add_wrapped_copies(picture.balls, disc, picture.clip->lower, picture.clip->upper);
    if (style.trails != nullptr) {
      for (std::vector<Vec2>& run : style.trails->paths(i, now)) {
        picture.trails.push_back({std::move(run), trail_colour(disc.fill), kTrailWidth});
      }
    }
    if (style.arrow_seconds && !is_immovable(scene.balls[i])) {
      const Vec2 tip = position + velocity * *style.arrow_seconds;
      if (tip != position) picture.arrows.push_back({position, tip, kArrowColour, kArrowOutline});
    }
  }

  picture.subtitle = "t = " + readable(scene_world.time()) + " " + scene.units.time + ", " +
                     std::to_string(live) + (live == 1 ? " ball" : " balls");
  if (style.mode == ColourMode::speed) {
    picture.legend = SpeedLegend{style.top_speed, scene.units.length + "/" + scene.units.time};
  }
  return picture;
}

}  // namespace carom::cli
