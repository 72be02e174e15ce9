#include "drawing/picture_file.hpp"

#include <stdexcept>

#include "drawing/cairo_picture.hpp"
#include "drawing/scene_svg.hpp"

namespace carom::cli {

PictureFile encode_picture(const ScenePicture& picture, bool svg, int width,
                           std::optional<double> arrow_seconds) {
  if (svg) return {scene_svg(picture, arrow_seconds), 0, 0};
  const ImageLayout layout = layout_image(picture.view, width, picture.legend.has_value(), false);
  CairoImage image(layout.width, layout.height);
  paint_picture(image, layout, picture);
  std::optional<std::string> png = image.png();
  if (!png) throw std::runtime_error("Cairo could not encode the PNG picture");
  return {std::move(*png), layout.width, layout.height};
}

}  // namespace carom::cli
