// carom web: the figures of the "Two moving balls" and "Walls and arcs" pages.
#include <emscripten/bind.h>

#include "js_error.hpp"
#include "two_balls_figure.hpp"
#include "walls_figure.hpp"

namespace carom::web {
namespace {

WallsFigure solve_walls(const WallsScene& scene, const Ball& ball, Vec2 move, double restitution) {
  return guarded_call([&] { return scene.solve(ball, move, restitution); });
}

void set_segment(WallsScene& scene, int index, const Segment& segment) {
  guarded_call([&] { scene.set_segment(index, segment); });
}

void set_arc(WallsScene& scene, int index, const Arc& arc) {
  guarded_call([&] { scene.set_arc(index, arc); });
}

}  // namespace

EMSCRIPTEN_BINDINGS(carom_figures) {
  using emscripten::value_object;

  value_object<TwoBallsInput>("TwoBallsInput")
      .field("a", &TwoBallsInput::a)
      .field("move_a", &TwoBallsInput::move_a)
      .field("b", &TwoBallsInput::b)
      .field("move_b", &TwoBallsInput::move_b)
      .field("mass_a", &TwoBallsInput::mass_a)
      .field("mass_b", &TwoBallsInput::mass_b)
      .field("restitution", &TwoBallsInput::restitution);
  value_object<TwoBallsFigure>("TwoBallsFigure")
      .field("impact", &TwoBallsFigure::impact)
      .field("v3", &TwoBallsFigure::v3)
      .field("a_end", &TwoBallsFigure::a_end)
      .field("b_end", &TwoBallsFigure::b_end)
      .field("a_relative_at", &TwoBallsFigure::a_relative_at)
      .field("split_a", &TwoBallsFigure::split_a)
      .field("split_b", &TwoBallsFigure::split_b)
      .field("after", &TwoBallsFigure::after);
  emscripten::function("two_balls_figure", &guarded<&two_balls_figure>::call);

  emscripten::enum_<ShapeKind>("ShapeKind")
      .value("none", ShapeKind::none)
      .value("segment", ShapeKind::segment)
      .value("arc", ShapeKind::arc);
  value_object<WallsFigure>("WallsFigure")
      .field("kind", &WallsFigure::kind)
      .field("index", &WallsFigure::index)
      .field("at_end_point", &WallsFigure::at_end_point)
      .field("impact", &WallsFigure::impact)
      .field("end", &WallsFigure::end)
      .field("split", &WallsFigure::split)
      .field("after", &WallsFigure::after);
  emscripten::class_<WallsScene>("WallsScene")
      .constructor<>()
      .function("set_segment", &set_segment)
      .function("set_arc", &set_arc)
      .function("segment_count", &WallsScene::segment_count)
      .function("arc_count", &WallsScene::arc_count)
      .function("solve", &solve_walls);
}

}  // namespace carom::web
