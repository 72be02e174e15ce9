#include "drawing/cairo_picture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "drawing/svg_elements.hpp"
#include "options/readable_number.hpp"

namespace carom::cli {
namespace {

// Proportions, as in the SVG figures (svg_elements.hpp): all sizes follow the image's width.
constexpr double kFontShare = 1.0 / 40.0;       // font size per pixel of width
constexpr double kLineShare = 1.0 / 320.0;      // a thin line's width per pixel of width
constexpr double kTitleBandFonts = 3.4;         // title and subtitle lines with some air
constexpr double kLegendBandFonts = 3.2;        // the colour bar and its labels
constexpr double kMarginFonts = 2.0;            // blank around the view, as in the SVG pictures
constexpr double kViewGapFonts = 0.6;           // between the subtitle and the view
constexpr double kTextLeftFonts = 1.2;          // the title's and the legend's left edge
constexpr double kLegendGapFonts = 1.0;         // between the view and the legend
constexpr double kTallestAspect = 2.0;          // the view is never drawn taller than this × width
constexpr double kLegendBarFonts = 14.0;        // the colour bar's length
constexpr double kLegendBarHeightFonts = 0.8;   // and its height
constexpr double kOutlineWidth = 0.5;           // a ball's outline, in thin lines
constexpr double kOutlineSmallestRadius = 2.0;  // pixels: smaller balls are drawn without one
constexpr double kArrowWidth = 1.0;
constexpr double kHeadLengthLines = 5.0;  // an arrow head's length, in thin lines
constexpr int kLegendStops = 16;
constexpr const char* kFontFamily = "DejaVu Sans";

void set_colour(cairo_t* cr, Rgb c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

struct Painter {
  cairo_t* cr;
  const ImageLayout& layout;
  const ViewBox& view;
  double line;  // a thin line's width in pixels

  [[nodiscard]] Vec2 at(Vec2 p) const {
    return {layout.left + (p.x - view.lower.x) * layout.scale,
            layout.bottom - (p.y - view.lower.y) * layout.scale};
  }

  void stroke(const PictureStroke& s) const {
    if (s.points.size() < 2) return;
    const Vec2 first = at(s.points.front());
    cairo_move_to(cr, first.x, first.y);
    for (std::size_t i = 1; i < s.points.size(); ++i) {
      const Vec2 p = at(s.points[i]);
      cairo_line_to(cr, p.x, p.y);
    }
    set_colour(cr, s.colour);
    cairo_set_line_width(cr, s.width * line);
    if (s.dashed) {
      const std::array<double, 2> dashes{4.0 * line, 3.0 * line};
      cairo_set_dash(cr, dashes.data(), static_cast<int>(dashes.size()), 0.0);
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
  }

  void disc(const PictureDisc& d) const {
    const Vec2 c = at(d.center);
    const double r = d.radius * layout.scale;
    cairo_new_sub_path(cr);
    cairo_arc(cr, c.x, c.y, r, 0.0, 2.0 * std::numbers::pi);
    set_colour(cr, d.fill);
    if (r < kOutlineSmallestRadius) {
      cairo_fill(cr);
      return;
    }
    // The outline lies inside the disc, so the disc's centre keeps the exact fill colour and
    // touching balls do not merge.
    cairo_fill_preserve(cr);
    set_colour(cr, {d.fill.r * 0.5, d.fill.g * 0.5, d.fill.b * 0.5});
    cairo_new_path(cr);
    const double w = std::min(kOutlineWidth * line, r);
    cairo_arc(cr, c.x, c.y, r - 0.5 * w, 0.0, 2.0 * std::numbers::pi);
    cairo_set_line_width(cr, w);
    cairo_stroke(cr);
  }

  void arrow(const PictureArrow& a) const {
    const Vec2 from = at(a.from);
    const Vec2 to = at(a.to);
    const double len = distance(from, to);
    if (!(len > 0.0)) return;
    const Vec2 direction = (to - from) / len;
    const double head = std::min(kHeadLengthLines * line, len / 1.6);
    const Vec2 base = to - direction * head;
    const Vec2 side = left_normal(direction) * (kHeadHalfWidthShare * head);
    const Vec2 shaft_end = base + direction * (0.5 * head);
    const auto shaft = [&](double width) {
      cairo_set_line_width(cr, width);
      cairo_move_to(cr, from.x, from.y);
      cairo_line_to(cr, shaft_end.x, shaft_end.y);
      cairo_stroke(cr);
    };
    const auto head_path = [&] {
      cairo_move_to(cr, to.x, to.y);
      cairo_line_to(cr, base.x + side.x, base.y + side.y);
      cairo_line_to(cr, base.x - side.x, base.y - side.y);
      cairo_close_path(cr);
    };
    // The outline first: the same shaft and head, wider on each side.
    const double outline = kOutlineWidth * line;
    set_colour(cr, a.outline);
    shaft((kArrowWidth * line) + 2.0 * outline);
    head_path();
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 2.0 * outline);
    cairo_stroke(cr);
    set_colour(cr, a.colour);
    shaft(kArrowWidth * line);
    head_path();
    cairo_fill(cr);
  }

  void text(Vec2 baseline, double size, bool bold, const std::string& words) const {
    cairo_select_font_face(cr, kFontFamily, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_move_to(cr, baseline.x, baseline.y);
    cairo_show_text(cr, words.c_str());
  }

  void legend(const SpeedLegend& legend) const {
    const double font = layout.font_size;
    const double x = kTextLeftFonts * font;
    const double y = layout.bottom + kLegendGapFonts * font;
    const double bar = std::min(kLegendBarFonts * font, layout.width * 0.5);
    const double height = kLegendBarHeightFonts * font;
    cairo_pattern_t* gradient = cairo_pattern_create_linear(x, 0.0, x + bar, 0.0);
    for (int i = 0; i <= kLegendStops; ++i) {
      const double share = static_cast<double>(i) / kLegendStops;
      const Rgb c = speed_colour(share);
      cairo_pattern_add_color_stop_rgb(gradient, share, c.r, c.g, c.b);
    }
    cairo_rectangle(cr, x, y, bar, height);
    cairo_set_source(cr, gradient);
    cairo_fill(cr);
    cairo_pattern_destroy(gradient);
    set_colour(cr, {0.0, 0.0, 0.0});
    const double label_y = y + height + 1.1 * font;
    const double small = 0.8 * font;
    text({x, label_y}, small, false, "0");
    const std::string top = readable(legend.top_speed) + "+";
    cairo_text_extents_t extents;
    cairo_text_extents(cr, top.c_str(), &extents);
    text({x + bar - extents.x_advance, label_y}, small, false, top);
    text({x + bar + 0.8 * font, y + height}, font, false, "speed (" + legend.unit + ")");
  }
};

}  // namespace

ImageLayout layout_image(const ViewBox& view, int width, bool legend, bool even_size) {
  ImageLayout layout;
  layout.width = std::clamp(width, kSmallestWidth, kLargestWidth);
  if (even_size) layout.width += layout.width % 2;
  const double w = layout.width;
  layout.font_size = w * kFontShare;
  layout.title_band = kTitleBandFonts * layout.font_size;
  layout.legend = legend;
  const double margin = kMarginFonts * layout.font_size;
  layout.scale = std::min((w - 2.0 * margin) / view.width(), kTallestAspect * w / view.height());
  const double view_height = view.height() * layout.scale;
  layout.left = (w - view.width() * layout.scale) / 2.0;
  layout.bottom = layout.title_band + kViewGapFonts * layout.font_size + view_height;
  const double below = legend ? (kLegendGapFonts + kLegendBandFonts) * layout.font_size : margin;
  layout.height = static_cast<int>(std::ceil(layout.bottom + below));
  if (even_size) layout.height += layout.height % 2;
  return layout;
}

CairoImage::CairoImage(int width, int height)
    : surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)) {
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    const std::string reason = cairo_status_to_string(cairo_surface_status(surface_));
    cairo_surface_destroy(surface_);
    throw std::runtime_error("cannot make a " + std::to_string(width) + "x" +
                             std::to_string(height) + " image: " + reason);
  }
}

CairoImage::~CairoImage() { cairo_surface_destroy(surface_); }

int CairoImage::width() const { return cairo_image_surface_get_width(surface_); }
int CairoImage::height() const { return cairo_image_surface_get_height(surface_); }
int CairoImage::stride() const { return cairo_image_surface_get_stride(surface_); }

const unsigned char* CairoImage::pixels() const {
  cairo_surface_flush(surface_);
  return cairo_image_surface_get_data(surface_);
}

std::optional<std::string> CairoImage::png() const {
  std::string bytes;
  const auto append = [](void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  };
  if (cairo_surface_write_to_png_stream(surface_, append, &bytes) != CAIRO_STATUS_SUCCESS) {
    return std::nullopt;
  }
  return bytes;
}

void paint_picture(CairoImage& image, const ImageLayout& layout, const ScenePicture& picture) {
  cairo_t* cr = cairo_create(image.surface());
  const Painter painter{cr, layout, picture.view, layout.width * kLineShare};
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);

  // Nothing outside the view: a view the user chose (--view) may cut through the scene.
  const auto clip_to = [&](const ViewBox& box) {
    const Vec2 a = painter.at(box.lower);
    const Vec2 b = painter.at(box.upper);
    cairo_rectangle(cr, a.x, b.y, b.x - a.x, a.y - b.y);
    cairo_clip(cr);
  };
  cairo_save(cr);
  clip_to(picture.view);
  for (const PictureStroke& s : picture.boundary) painter.stroke(s);
  cairo_save(cr);
  if (picture.clip) clip_to(*picture.clip);
  for (const PictureStroke& s : picture.trails) painter.stroke(s);
  for (const PictureDisc& d : picture.pockets) painter.disc(d);
  for (const PictureStroke& s : picture.walls) painter.stroke(s);
  for (const PictureDisc& d : picture.balls) painter.disc(d);
  for (const PictureStroke& s : picture.overlay) painter.stroke(s);
  cairo_restore(cr);
  for (const PictureArrow& a : picture.arrows) painter.arrow(a);
  cairo_restore(cr);

  set_colour(cr, {0.0, 0.0, 0.0});
  const double font = layout.font_size;
  painter.text({kTextLeftFonts * font, 1.4 * font}, 1.2 * font, true, picture.title);
  painter.text({kTextLeftFonts * font, 2.8 * font}, font, false, picture.subtitle);
  if (picture.legend && layout.legend) painter.legend(*picture.legend);

  const cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("drawing failed: ") + cairo_status_to_string(status));
  }
}

}  // namespace carom::cli
