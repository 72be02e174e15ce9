// `carom render SCENE --out FILE.png`: a real PNG of the asked size, read back with Cairo, with
// each ball painted in its colour where the picture's layout puts it.
#include <cairo.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

#include "cairo_picture.hpp"
#include "carom/scene.hpp"
#include "render_scenes.hpp"
#include "run_tool.hpp"
#include "scene_picture.hpp"

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

}  // namespace
}  // namespace carom::cli::test
