// carom tool: the "X,Y,R" and "DX,DY" values that describe balls and movements.
#pragma once

#include <string_view>
#include <vector>

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"

namespace carom::cli {

// The value of option as exactly as many comma-separated finite numbers as form has parts
// (form "X,Y,R" asks for three). Nothing else is allowed: no spaces, no empty parts, no trailing
// characters. A bad value throws UsageError naming the option, the value and the problem.
[[nodiscard]] std::vector<double> parse_number_list(std::string_view option, std::string_view text,
                                                    std::string_view form);

// "X,Y,R": a ball's centre and radius. Only the syntax is checked here; the radius's range is
// the library's rule (carom::sweep_* throws for a radius <= 0).
[[nodiscard]] Ball parse_ball(std::string_view option, std::string_view text);

// "DX,DY": a movement vector (how far a ball moves during the step).
[[nodiscard]] Vec2 parse_vector(std::string_view option, std::string_view text);

}  // namespace carom::cli
