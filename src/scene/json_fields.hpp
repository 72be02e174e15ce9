// carom scenes internal: reading typed fields out of parsed JSON, with every complaint located in
// the source text (file, line, column, JSON path, the value as written).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "carom/scene.hpp"
#include "json_walk.hpp"

namespace carom::scene_detail {

// The text a scene was parsed from, to locate errors in.
class JsonSource {
 public:
  JsonSource(std::string_view text, std::string_view name) : text_(text), name_(name) {}

  // An error about the value at path (or its key, with at_key), located in the text. value
  // overrides the text found there when given.
  [[nodiscard]] SceneError error(const JsonPath& path, std::string problem, bool at_key = false,
                                 std::string suggestion = "",
                                 std::optional<std::string> value = std::nullopt) const;
  // The error with file, line and column filled in from its path (value kept if it has one).
  [[nodiscard]] SceneError located(const SceneError& error, const JsonPath& path) const;
  // An error at a byte offset with no path (malformed JSON).
  [[nodiscard]] SceneError error_at(std::size_t offset, std::string problem) const;

  [[nodiscard]] std::string_view text() const { return text_; }
  [[nodiscard]] std::string_view name() const { return name_; }

 private:
  std::string_view text_;
  std::string_view name_;
};

// One JSON object of the scene, with the keys it may hold. Construction checks that the value is
// an object and that every key is known (an unknown key is an error naming the nearest known one).
class ObjectFields {
 public:
  ObjectFields(const JsonSource& source, const nlohmann::json& json, JsonPath path,
               std::initializer_list<std::string_view> known_keys);

  [[nodiscard]] bool has(std::string_view key) const;
  [[nodiscard]] JsonPath path_of(std::string_view key) const;
  [[noreturn]] void fail(std::string_view key, std::string problem) const;

  // Required (an error when missing) and optional forms of each type.
  [[nodiscard]] double number(std::string_view key) const;
  [[nodiscard]] std::optional<double> optional_number(std::string_view key) const;
  [[nodiscard]] double number_or(std::string_view key, double fallback) const;
  [[nodiscard]] Vec2 vector(std::string_view key) const;
  [[nodiscard]] std::optional<Vec2> optional_vector(std::string_view key) const;
  [[nodiscard]] std::string string(std::string_view key) const;
  [[nodiscard]] std::optional<std::string> optional_string(std::string_view key) const;
  [[nodiscard]] bool boolean_or(std::string_view key, bool fallback) const;
  [[nodiscard]] std::uint64_t whole_number(std::string_view key) const;
  [[nodiscard]] std::optional<std::uint64_t> optional_whole_number(std::string_view key) const;
  // The array at key (empty when missing), each element with its path.
  [[nodiscard]] const nlohmann::json* array(std::string_view key) const;
  [[nodiscard]] const nlohmann::json& at(std::string_view key) const;
  [[nodiscard]] const JsonSource& source() const { return *source_; }

  // Reading a value that is not a field of an object (an array element).
  [[nodiscard]] static double number_value(const JsonSource& source, const nlohmann::json& json,
                                           const JsonPath& path);
  [[nodiscard]] static Vec2 vector_value(const JsonSource& source, const nlohmann::json& json,
                                         const JsonPath& path);

 private:
  const JsonSource* source_;
  const nlohmann::json* json_;
  JsonPath path_;
};

// "a number", "a string": the JSON type of a value as a message names it.
[[nodiscard]] std::string type_name(const nlohmann::json& json);

}  // namespace carom::scene_detail
