// carom scenes internal: positions in JSON text. nlohmann::json keeps no source positions, so a
// field's line and column are found by walking the (already valid) text again along its path.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace carom::scene_detail {

// One step of a JSON path: an object key or an array index.
using PathStep = std::variant<std::string, std::size_t>;
using JsonPath = std::vector<PathStep>;

// "balls[3].radius"; the empty path is "".
[[nodiscard]] std::string path_text(const JsonPath& path);

// A run of characters in the text: [begin, end).
struct TextSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
};

// Where the value at path lies in text (or, with key = true, the key that names it; the root has
// no key). Nothing if the path is not in the text. The text should be valid JSON; on anything
// else this stops without reading past the end.
[[nodiscard]] std::optional<TextSpan> locate(std::string_view text, const JsonPath& path,
                                             bool key = false);

// The first number token in text (outside strings) that reads exactly `token`, with its path.
struct FoundNumber {
  JsonPath path;
  TextSpan span;
};
[[nodiscard]] std::optional<FoundNumber> find_number(std::string_view text, std::string_view token);

// 1-based line and column (in UTF-8 code points) of a byte offset (clamped to the text).
struct LineColumn {
  std::size_t line = 1;
  std::size_t column = 1;
};
[[nodiscard]] LineColumn line_column(std::string_view text, std::size_t offset);

}  // namespace carom::scene_detail
