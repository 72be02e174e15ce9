#include "json_walk.hpp"

#include <cstdint>

namespace carom::scene_detail {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::size_t skip_space(std::string_view text, std::size_t pos) {
  while (pos < text.size() && is_space(text[pos])) ++pos;
  return pos;
}

// pos at an opening quote: the position after the closing quote, and the content with the
// escapes of a quote, a backslash and a slash undone (keys with other escapes compare as
// written, which only affects locating them).
std::size_t skip_string(std::string_view text, std::size_t pos, std::string* content) {
  ++pos;
  while (pos < text.size() && text[pos] != '"') {
    if (text[pos] == '\\' && pos + 1 < text.size()) {
      ++pos;
      if (content != nullptr) {
        if (text[pos] == '"' || text[pos] == '\\' || text[pos] == '/') {
          content->push_back(text[pos]);
        } else {
          content->push_back('\\');
          content->push_back(text[pos]);
        }
      }
    } else if (content != nullptr) {
      content->push_back(text[pos]);
    }
    ++pos;
  }
  return pos < text.size() ? pos + 1 : pos;
}

bool ends_scalar(char c) { return is_space(c) || c == ',' || c == ']' || c == '}' || c == ':'; }

// pos at the start of a value: the position just after it. Iterative, so deep nesting cannot
// exhaust the stack.
std::size_t skip_value(std::string_view text, std::size_t pos) {
  if (pos >= text.size()) return pos;
  if (text[pos] == '"') return skip_string(text, pos, nullptr);
  if (text[pos] == '{' || text[pos] == '[') {
    std::size_t depth = 0;
    while (pos < text.size()) {
      const char c = text[pos];
      if (c == '"') {
        pos = skip_string(text, pos, nullptr);
        continue;
      }
      if (c == '{' || c == '[') ++depth;
      if (c == '}' || c == ']') {
        --depth;
        if (depth == 0) return pos + 1;
      }
      ++pos;
    }
    return pos;
  }
  while (pos < text.size() && !ends_scalar(text[pos])) ++pos;
  return pos;
}

}  // namespace

std::string path_text(const JsonPath& path) {
  std::string text;
  for (const PathStep& step : path) {
    if (const auto* key = std::get_if<std::string>(&step)) {
      if (!text.empty()) text += '.';
      text += *key;
    } else {
      text += '[' + std::to_string(std::get<std::size_t>(step)) + ']';
    }
  }
  return text;
}

std::optional<TextSpan> locate(std::string_view text, const JsonPath& path, bool key) {
  std::size_t pos = skip_space(text, 0);
  for (std::size_t depth = 0; depth < path.size(); ++depth) {
    const PathStep& step = path[depth];
    const bool last = depth + 1 == path.size();
    if (pos >= text.size()) return std::nullopt;
    if (const auto* wanted = std::get_if<std::string>(&step)) {
      if (text[pos] != '{') return std::nullopt;
      pos = skip_space(text, pos + 1);
      bool found = false;
      while (pos < text.size() && text[pos] == '"') {
        std::string name;
        const std::size_t key_begin = pos;
        pos = skip_string(text, pos, &name);
        const std::size_t key_end = pos;
        pos = skip_space(text, pos);
        if (pos >= text.size() || text[pos] != ':') return std::nullopt;
        pos = skip_space(text, pos + 1);
        if (name == *wanted) {
          if (key && last) return TextSpan{key_begin, key_end};
          found = true;
          break;
        }
        pos = skip_space(text, skip_value(text, pos));
        if (pos >= text.size() || text[pos] != ',') return std::nullopt;
        pos = skip_space(text, pos + 1);
      }
      if (!found) return std::nullopt;
    } else {
      if (text[pos] != '[') return std::nullopt;
      pos = skip_space(text, pos + 1);
      for (std::size_t index = std::get<std::size_t>(step); index > 0; --index) {
        pos = skip_space(text, skip_value(text, pos));
        if (pos >= text.size() || text[pos] != ',') return std::nullopt;
        pos = skip_space(text, pos + 1);
      }
      if (pos >= text.size() || text[pos] == ']') return std::nullopt;
      if (key && last) return std::nullopt;
    }
  }
  if (pos >= text.size()) return std::nullopt;
  return TextSpan{pos, skip_value(text, pos)};
}

std::optional<FoundNumber> find_number(std::string_view text, std::string_view token) {
  struct Frame {
    bool object = false;
    bool expect_key = false;
  };
  std::vector<Frame> frames;
  JsonPath path;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const char c = text[pos];
    if (c == '"') {
      std::string content;
      const std::size_t end = skip_string(text, pos, &content);
      if (!frames.empty() && frames.back().object && frames.back().expect_key) {
        path.back() = content;
        frames.back().expect_key = false;
      }
      pos = end;
      continue;
    }
    if (c == '{' || c == '[') {
      frames.push_back({c == '{', c == '{'});
      path.emplace_back(c == '{' ? PathStep{std::string()} : PathStep{std::size_t{0}});
    } else if (c == '}' || c == ']') {
      if (!frames.empty()) {
        frames.pop_back();
        path.pop_back();
      }
    } else if (c == ',') {
      if (!frames.empty()) {
        if (frames.back().object) {
          frames.back().expect_key = true;
        } else {
          path.back() = std::get<std::size_t>(path.back()) + 1;
        }
      }
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = pos;
      while (end < text.size() && !ends_scalar(text[end])) ++end;
      if (text.substr(pos, end - pos) == token) return FoundNumber{path, {pos, end}};
      pos = end;
      continue;
    }
    ++pos;
  }
  return std::nullopt;
}

LineColumn line_column(std::string_view text, std::size_t offset) {
  if (offset > text.size()) offset = text.size();
  LineColumn at;
  for (std::size_t i = 0; i < offset; ++i) {
    const auto byte = static_cast<std::uint8_t>(text[i]);
    if (text[i] == '\n') {
      ++at.line;
      at.column = 1;
    } else if ((byte & 0xC0U) != 0x80U) {  // not a UTF-8 continuation byte
      ++at.column;
    }
  }
  return at;
}

}  // namespace carom::scene_detail
