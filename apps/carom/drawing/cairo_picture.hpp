// carom tool: painting a scene picture with Cairo, for PNG pictures and animation frames.
#pragma once

#include <cairo.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "drawing/scene_picture.hpp"

namespace carom::cli {

// Where a picture lands in an image: its size and the world-to-pixel mapping.
struct ImageLayout {
  int width = 0;
  int height = 0;
  double scale = 1.0;   // pixels per length unit
  double left = 0.0;    // pixel x of the view's lower-left corner
  double bottom = 0.0;  // pixel y of the view's lower-left corner (y grows down on screen)
  double font_size = 0.0;
  double title_band = 0.0;  // pixels above the view for the title
  bool legend = false;      // a speed legend below the view
};

// Layout for a view drawn `width` pixels wide (at least kSmallestWidth): the view as large as it
// fits (never more than twice as tall as wide), a title band above, a legend band below when
// asked. With even_size, both sides are rounded up to even numbers (H.264 video needs them).
[[nodiscard]] ImageLayout layout_image(const ViewBox& view, int width, bool legend, bool even_size);
inline constexpr int kSmallestWidth = 64;
inline constexpr int kLargestWidth = 8192;

// An RGB image in memory (Cairo's RGB24: 4 bytes a pixel, native-endian 0x00RRGGBB).
class CairoImage {
 public:
  CairoImage(int width, int height);
  ~CairoImage();
  CairoImage(const CairoImage&) = delete;
  CairoImage& operator=(const CairoImage&) = delete;

  [[nodiscard]] cairo_surface_t* surface() const { return surface_; }
  [[nodiscard]] int width() const;
  [[nodiscard]] int height() const;
  [[nodiscard]] int stride() const;  // bytes per row
  // The pixels, row by row from the top, after Cairo has finished drawing.
  [[nodiscard]] const unsigned char* pixels() const;
  // The image as a PNG file's bytes; nothing if Cairo could not encode it.
  [[nodiscard]] std::optional<std::string> png() const;

 private:
  cairo_surface_t* surface_;
};

// Paints picture over the whole image, background included.
void paint_picture(CairoImage& image, const ImageLayout& layout, const ScenePicture& picture);

}  // namespace carom::cli
