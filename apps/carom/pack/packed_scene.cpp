#include "pack/packed_scene.hpp"

#include <stdexcept>
#include <vector>

#include "carom/geometry.hpp"
#include "drawing/cairo_picture.hpp"
#include "drawing/scene_picture.hpp"
#include "drawing/scene_svg.hpp"

namespace carom::cli {
namespace {

constexpr int kPackingPictureWidth = 960;  // pixels
constexpr Rgb kRattlerColour = rgb_from_hex(0xb0b0b0);
constexpr Rgb kNetworkColour = rgb_from_hex(0x202020);

// A colour a contact number, from 3 (the fewest a disk held in place has) to 6 and more.
Rgb contact_colour(std::uint32_t contacts) {
  switch (contacts) {
    case 0:
    case 1:
    case 2:
      return kRattlerColour;
    case 3:
      return rgb_from_hex(0x4c72b0);  // blue: under the isostatic mean
    case 4:
      return rgb_from_hex(0x55a868);  // green: isostatic
    case 5:
      return rgb_from_hex(0xdd8452);  // orange
    default:
      return rgb_from_hex(0xc44e52);  // red: 6, a disk in a triangular crystal
  }
}

}  // namespace

Scene packed_scene(const World& world, const std::string& description) {
  Scene scene;
  scene.description = description;
  scene.units = {"diameter", "time", "mass"};
  scene.world = world.def();
  scene.world.growth_rate = world.growth_rate_from_now();
  for (const BallId id : world.balls()) {
    SceneBall ball;
    ball.position = world.position(id);
    ball.velocity = world.velocity(id);
    ball.radius = world.radius(id);
    ball.mass = world.mass(id);
    scene.balls.push_back(ball);
  }
  return scene;
}

std::string packing_picture(const Scene& scene, const science::ContactNetwork& network,
                            const std::string& title, const std::string& subtitle, bool svg) {
  const SceneWorld scene_world = make_world(scene);
  PictureStyle style;
  style.mode = ColourMode::name;
  style.name_colours.reserve(scene.balls.size());
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    style.name_colours.push_back(network.rattler[i] != 0 ? kRattlerColour
                                                         : contact_colour(network.contacts[i]));
  }
  frame_picture(style, scene, balls_box(scene_world), std::nullopt, false);
  style.title = title;
  ScenePicture picture = draw_scene(scene_world, style);
  picture.subtitle = subtitle;
  // Each contact as two half-lines, one from each centre towards the other, so that a contact
  // through the periodic cell's edge shows on both sides.
  const bool periodic = scene.world.boundary == Boundary::periodic;
  const PeriodicCell cell(scene.world.lower, scene.world.upper);
  for (const science::ContactNetwork::Pair& pair : network.pairs) {
    const Vec2 a = scene.balls[pair.a].position;
    const Vec2 b = scene.balls[pair.b].position;
    Vec2 offset = b - a;
    if (periodic) offset = cell.minimum_image(offset);
    picture.overlay.push_back({{a, a + offset * 0.5}, kNetworkColour, 1.0, false});
    picture.overlay.push_back({{b, b - offset * 0.5}, kNetworkColour, 1.0, false});
  }
  if (svg) return scene_svg(picture, std::nullopt);
  const ImageLayout layout = layout_image(picture.view, kPackingPictureWidth, false, false);
  CairoImage image(layout.width, layout.height);
  paint_picture(image, layout, picture);
  std::optional<std::string> png = image.png();
  if (!png) throw std::runtime_error("Cairo could not encode the PNG picture");
  return std::move(*png);
}

}  // namespace carom::cli
