// carom tool: the single-number options, masses and restitution, checked against the library's
// rules before anything is computed (the library checks them only when a bounce happens).
#pragma once

#include <string_view>

namespace carom::cli {

// The words that give a ball carom::kImmovable (an infinite mass: a post nothing moves).
inline constexpr std::string_view kImmovableWord = "immovable";
inline constexpr std::string_view kInfiniteWord = "inf";

// A finite number > 0, or one of the words above for carom::kImmovable.
[[nodiscard]] double parse_mass(std::string_view option, std::string_view text);

// A finite number in [0, 1].
[[nodiscard]] double parse_restitution(std::string_view option, std::string_view text);

}  // namespace carom::cli
