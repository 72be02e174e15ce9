// carom tool: a scene picture as an SVG document (SvgFigure), for `carom render --out X.svg`.
#pragma once

#include <optional>
#include <string>

#include "drawing/scene_picture.hpp"

namespace carom::cli {

// One element per thing drawn: a <circle> per ball and pocket, a <line> per segment and box
// side, a <polyline> per polyline, arc and trail, an arrow per moving ball when asked; then the
// speed legend (discs) in speed mode. Wrapped copies across a periodic cell are left out: SVG
// pictures are not clipped. arrow_seconds labels the arrows in the legend.
[[nodiscard]] std::string scene_svg(const ScenePicture& picture,
                                    std::optional<double> arrow_seconds);

}  // namespace carom::cli
