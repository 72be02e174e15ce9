// carom scenes internal: the known key nearest to a misspelt one, for "did you mean" hints.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace carom::scene_detail {

// Levenshtein distance (insertions, deletions, substitutions, each costing 1), case-sensitive.
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

// The known key with the smallest edit distance to `key` (the first of equals, in the order
// given), or "" when none is close enough to be a plausible typo: more than half of the longer
// word's length would have to change.
[[nodiscard]] std::string nearest_key(std::string_view key,
                                      std::span<const std::string_view> known);

}  // namespace carom::scene_detail
