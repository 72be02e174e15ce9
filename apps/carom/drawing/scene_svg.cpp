#include "drawing/scene_svg.hpp"

#include <array>
#include <cstddef>

#include "drawing/svg_writer.hpp"
#include "options/readable_number.hpp"

namespace carom::cli {
namespace {

// The speeds the legend shows, as shares of the top speed.
constexpr std::array kLegendShares{0.0, 0.25, 0.5, 0.75, 1.0};

Pen pen_of(const PictureStroke& stroke) {
  return Pen{hex_colour(stroke.colour), stroke.width, stroke.dashed};
}

void add_stroke(SvgFigure& figure, const PictureStroke& stroke) {
  if (stroke.points.size() == 2) {
    figure.line(stroke.points[0], stroke.points[1], pen_of(stroke));
  } else {
    figure.polyline(stroke.points, pen_of(stroke));
  }
}

void add_disc(SvgFigure& figure, const PictureDisc& disc) {
  if (disc.wrapped_copy) return;
  const Rgb outline{disc.fill.r * 0.5, disc.fill.g * 0.5, disc.fill.b * 0.5};
  figure.circle(disc.center, disc.radius, Pen{hex_colour(outline), 0.5}, hex_colour(disc.fill));
}

}  // namespace

std::string scene_svg(const ScenePicture& picture, std::optional<double> arrow_seconds) {
  SvgFigure figure;
  figure.heading(picture.title);
  figure.heading(picture.subtitle);
  figure.view(picture.view.lower, picture.view.upper);
  // Box sides one by one, so each wall is one element a reader (or a test) can count.
  for (const PictureStroke& side : picture.boundary) {
    if (side.dashed) {
      figure.polyline(side.points, pen_of(side));
      continue;
    }
    for (std::size_t i = 1; i < side.points.size(); ++i) {
      figure.line(side.points[i - 1], side.points[i], pen_of(side));
    }
  }
  for (const PictureStroke& trail : picture.trails) figure.polyline(trail.points, pen_of(trail));
  for (const PictureDisc& pocket : picture.pockets) add_disc(figure, pocket);
  for (const PictureStroke& wall : picture.walls) add_stroke(figure, wall);
  for (const PictureDisc& ball : picture.balls) add_disc(figure, ball);
  for (const PictureStroke& line : picture.overlay) add_stroke(figure, line);
  for (const PictureArrow& arrow : picture.arrows) {
    figure.arrow(arrow.from, arrow.to, Pen{hex_colour(arrow.colour), 1.0, false},
                 hex_colour(arrow.outline));
  }

  if (picture.legend) {
    for (const double share : kLegendShares) {
      const Rgb colour = speed_colour(share);
      figure.legend(LegendMark::kDisc, Pen{hex_colour(colour), 0.5},
                    (share == 0.0 ? "speed " : "") + readable(share * picture.legend->top_speed) +
                        " " + picture.legend->unit + (share == 1.0 ? " or more" : ""),
                    hex_colour(colour));
    }
  }
  if (!picture.arrows.empty() && arrow_seconds) {
    figure.legend(LegendMark::kArrow, Pen{hex_colour(picture.arrows.front().colour), 1.0},
                  "where each ball is " + readable(*arrow_seconds) + " " + picture.time_unit +
                      " later if nothing is hit");
  }
  return figure.render();
}

}  // namespace carom::cli
