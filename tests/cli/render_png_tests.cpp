// `carom render SCENE --out FILE.png`: a real PNG of the asked size, read back with Cairo, with
// each ball painted in its colour where the picture's layout puts it.
#include <cairo.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "carom/scene.hpp"
#include "drawing/cairo_picture.hpp"
#include "drawing/scene_picture.hpp"
#include "render_scenes.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;

Surface read_png(const std::filesystem::path& path) {
  return Surface(cairo_image_surface_create_from_png(path.c_str()));
}

// The pixel's colour as 0xRRGGBB (the image is opaque, so premultiplying changes nothing).
std::uint32_t pixel(cairo_surface_t* surface, Vec2 at) {
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const auto x = static_cast<std::ptrdiff_t>(std::floor(at.x));
  const auto y = static_cast<std::ptrdiff_t>(std::floor(at.y));
  std::uint32_t argb = 0;
  std::memcpy(&argb, data + y * stride + x * 4, sizeof argb);
  return argb & 0xffffffU;
}

// Where the picture puts world point p, from the same layout the tool uses.
Vec2 pixel_of(const ImageLayout& layout, const ViewBox& view, Vec2 p) {
  return {layout.left + (p.x - view.lower.x) * layout.scale,
          layout.bottom - (p.y - view.lower.y) * layout.scale};
}

TEST(RenderPng, SignatureSizeAndTheBallsColourAtItsCentre) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "one.json", kOneBallScene);
  const ToolRun run =
      run_render({"render", scene, "--width", "400", "--out", (dir / "one.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;

  const std::string bytes = read_file(dir / "one.png");
  ASSERT_GE(bytes.size(), 8U);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));

  const Surface png = read_png(dir / "one.png");
  ASSERT_EQ(cairo_surface_status(png.get()), CAIRO_STATUS_SUCCESS);
  const int width = cairo_image_surface_get_width(png.get());
  const int height = cairo_image_surface_get_height(png.get());
  EXPECT_EQ(width, 400);
  // A square box: as tall as wide, plus the title band above (no legend in name mode).
  const ViewBox view = picture_view(parse_scene(kOneBallScene), {});
  const ImageLayout layout = layout_image(view, 400, false, false);
  EXPECT_EQ(height, layout.height);
  EXPECT_GT(height, width);
  EXPECT_THAT(run.out, HasSubstr("400x" + std::to_string(height)));

  // The scene colours the ball #2060c0, so name colouring is chosen without asking.
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {5.0, 5.0})), 0x2060c0U);
  // Inside the box, away from the ball: the white background.
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {1.0, 1.0})), 0xffffffU);
  // Just outside the box's right side, level with the ball: background too.
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {10.15, 5.0})), 0xffffffU);
}

TEST(RenderPng, BySpeedARestingBallHasTheScalesBottomColour) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "one.json", kOneBallScene);
  const ToolRun run = run_render(
      {"render", scene, "--color", "speed", "--width", "400", "--out", (dir / "one.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Surface png = read_png(dir / "one.png");
  ASSERT_EQ(cairo_surface_status(png.get()), CAIRO_STATUS_SUCCESS);
  const ViewBox view = picture_view(parse_scene(kOneBallScene), {});
  const ImageLayout layout = layout_image(view, 400, true, false);
  // The legend band makes the picture taller than without it.
  EXPECT_EQ(cairo_image_surface_get_height(png.get()), layout.height);
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {5.0, 5.0})), 0x440154U);  // viridis at 0
}

TEST(RenderPng, AMovedBallIsDrawnWhereItIsAtTheAskedTime) {
  const ScratchDir dir;
  // The ball moves right at 1 length unit per time unit: at t = 2 its centre is at (7, 5).
  const std::string scene = write_test_scene(dir, "moving.json", R"({
    "carom_scene": 1,
    "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10]},
    "balls": [{"position": [5, 5], "velocity": [1, 0], "radius": 1.5, "color": "#c03030"}]
  })");
  const ToolRun run = run_render({"render", scene, "--at", "2", "--color", "name", "--width", "400",
                                  "--out", (dir / "moving.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Surface png = read_png(dir / "moving.png");
  ASSERT_EQ(cairo_surface_status(png.get()), CAIRO_STATUS_SUCCESS);
  const ViewBox view = picture_view(parse_scene(read_file(scene)), {});
  const ImageLayout layout = layout_image(view, 400, false, false);
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {7.0, 5.0})), 0xc03030U);
  // Where it started, 2 units back (more than its radius): empty now.
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {4.0, 5.0})), 0xffffffU);
}

// The font size and the blank margin of a picture `width` pixels wide: a fortieth of the width,
// and two font sizes (cairo_picture.cpp).
constexpr double kFontShare = 1.0 / 40.0;
constexpr double kMarginFonts = 2.0;

bool is_white(std::uint32_t rgb) { return rgb == 0xffffffU; }

// How many pixels of the row band [top, bottom) and column band [left, right) are not white.
int inked_pixels(cairo_surface_t* surface, int left, int right, int top, int bottom) {
  int inked = 0;
  for (int y = top; y < bottom; ++y) {
    for (int x = left; x < right; ++x) {
      inked += is_white(pixel(surface, {x + 0.5, y + 0.5})) ? 0 : 1;
    }
  }
  return inked;
}

// Left, right and below the view a band of blank paper two font sizes wide, whatever the scene
// draws: a box's walls, an open world's balls flying apart with their trails and arrows.
TEST(RenderPng, AMarginOfBlankPaperAroundTheScene) {
  const ScratchDir dir;
  const std::string box = write_test_scene(dir, "every.json", kEveryKindScene);
  const std::string open = write_test_scene(dir, "two.json", kTwoBallsScene);
  for (const auto& [scene, extra] :
       {std::pair{box, std::vector<std::string>{}},
        std::pair{open, std::vector<std::string>{"--at", "1", "--trails", "1", "--arrows"}}}) {
    std::vector<std::string> args{"render",  scene, "--color", "name",
                                  "--width", "960", "--out",   (dir / "m.png").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const ToolRun run = run_render(args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Surface png = read_png(dir / "m.png");
    ASSERT_EQ(cairo_surface_status(png.get()), CAIRO_STATUS_SUCCESS);
    const int width = cairo_image_surface_get_width(png.get());
    const int height = cairo_image_surface_get_height(png.get());
    const auto margin = static_cast<int>(kMarginFonts * kFontShare * width);
    // Below the title band (three and a half font sizes), down to the bottom.
    const auto title = static_cast<int>(3.5 * kFontShare * width);
    EXPECT_EQ(inked_pixels(png.get(), 0, margin, title, height), 0) << scene << ": left";
    EXPECT_EQ(inked_pixels(png.get(), width - margin, width, title, height), 0) << scene;
    EXPECT_EQ(inked_pixels(png.get(), 0, width, height - margin, height), 0) << scene << ": below";
    // And the scene itself is drawn: ink just inside the margins.
    EXPECT_GT(inked_pixels(png.get(), margin, width - margin, title, height - margin), 0);
  }
}

// An arrow the colour of its ball still shows: a band of white runs along it.
TEST(RenderPng, AnArrowShowsOnABallOfItsOwnColour) {
  const ScratchDir dir;
  // The arrows are #c00000 (scene_picture.cpp); so is this ball, moving right.
  const std::string text = R"({
    "carom_scene": 1,
    "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10]},
    "balls": [{"position": [5, 5], "velocity": [1, 0], "radius": 3, "color": "#c00000"}]
  })";
  const std::string scene = write_test_scene(dir, "red.json", text);
  const ToolRun run = run_render(
      {"render", scene, "--arrows", "--width", "960", "--out", (dir / "red.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Surface png = read_png(dir / "red.png");
  ASSERT_EQ(cairo_surface_status(png.get()), CAIRO_STATUS_SUCCESS);

  const Scene parsed = parse_scene(text);
  PictureStyle style;
  style.top_speed = 1.0;
  frame_picture(style, parsed, {}, std::nullopt, true);
  ASSERT_TRUE(style.arrow_seconds.has_value());
  const ImageLayout layout = layout_image(style.view, 960, false, false);
  // A column across the arrow's shaft, halfway along it, from above the shaft to below it.
  const Vec2 middle = pixel_of(layout, style.view, {5.0 + 0.5 * *style.arrow_seconds, 5.0});
  int white = 0;
  int red = 0;
  for (int dy = -12; dy <= 12; ++dy) {
    const std::uint32_t rgb = pixel(png.get(), middle + Vec2{0.0, static_cast<double>(dy)});
    const unsigned r = rgb >> 16U;
    const unsigned g = (rgb >> 8U) & 0xffU;
    const unsigned b = rgb & 0xffU;
    white += r > 0xe0U && g > 0xe0U && b > 0xe0U ? 1 : 0;
    red += rgb == 0xc00000U ? 1 : 0;
  }
  // The ball's red above and below, the outline's white on both sides of the red shaft.
  EXPECT_GE(white, 2);
  EXPECT_GE(red, 10);
}

// --view shows exactly the box asked for, and nothing of the scene outside it.
TEST(RenderPng, ViewShowsTheAskedBoxAndCutsTheRest) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "one.json", kOneBallScene);
  // The lower-left quarter of the box: the ball (radius 3 around (5, 5)) reaches into it.
  const ToolRun run = run_render({"render", scene, "--view", "0,0,5,5", "--width", "400", "--out",
                                  (dir / "quarter.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Surface png = read_png(dir / "quarter.png");
  ASSERT_EQ(cairo_surface_status(png.get()), CAIRO_STATUS_SUCCESS);
  const ViewBox view{{0.0, 0.0}, {5.0, 5.0}};
  const ImageLayout layout = layout_image(view, 400, false, false);
  EXPECT_EQ(cairo_image_surface_get_height(png.get()), layout.height);
  // The view fills the width but the margins: 5 units across 400 − 2 × 20 pixels.
  EXPECT_DOUBLE_EQ(layout.scale, (400.0 - 2.0 * kMarginFonts * kFontShare * 400.0) / 5.0);
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {4.0, 4.0})), 0x2060c0U);  // in the ball
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {1.0, 1.0})), 0xffffffU);  // beside it
  // Past the view's right edge, where the ball goes on in the world: not drawn.
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {5.1, 4.0})), 0xffffffU);
  EXPECT_EQ(pixel(png.get(), pixel_of(layout, view, {4.0, 5.1})), 0xffffffU);
}

}  // namespace
}  // namespace carom::cli::test
