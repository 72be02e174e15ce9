#include "json_fields.hpp"

#include <cmath>
#include <utility>

#include "nearest_key.hpp"

namespace carom::scene_detail {
namespace {

// Values quoted in messages are cut to one line of this many characters.
constexpr std::size_t kQuotedValueLength = 60;

std::string quoted_value(std::string_view text, TextSpan span) {
  std::string_view value = text.substr(span.begin, span.end - span.begin);
  bool cut = false;
  if (const std::size_t newline = value.find('\n'); newline != std::string_view::npos) {
    value = value.substr(0, newline);
    cut = true;
  }
  if (value.size() > kQuotedValueLength) {
    value = value.substr(0, kQuotedValueLength);
    cut = true;
  }
  std::string quoted(value);
  while (!quoted.empty() && (quoted.back() == ' ' || quoted.back() == '\r')) quoted.pop_back();
  return cut ? quoted + "..." : quoted;
}

JsonPath child(JsonPath path, std::string_view key) {
  path.emplace_back(std::string(key));
  return path;
}

JsonPath child(JsonPath path, std::size_t index) {
  path.emplace_back(index);
  return path;
}

}  // namespace

std::string type_name(const nlohmann::json& json) {
  switch (json.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::object:
      return "an object";
    default:
      return "a number";
  }
}

SceneError JsonSource::error(const JsonPath& path, std::string problem, bool at_key,
                             std::string suggestion, std::optional<std::string> value) const {
  SceneError::Details details;
  details.file = std::string(name_);
  details.path = path_text(path);
  details.problem = std::move(problem);
  details.suggestion = std::move(suggestion);
  // A missing field is located at the object that lacks it.
  JsonPath where = path;
  std::optional<TextSpan> span = locate(text_, where, at_key);
  while (!span && !where.empty()) {
    where.pop_back();
    span = locate(text_, where, false);
  }
  if (span) {
    const LineColumn at = line_column(text_, span->begin);
    details.line = at.line;
    details.column = at.column;
    if (!value && where.size() == path.size() && !at_key) value = quoted_value(text_, *span);
  }
  if (value) details.value = std::move(*value);
  return SceneError(std::move(details));
}

SceneError JsonSource::located(const SceneError& error, const JsonPath& path) const {
  const SceneError::Details& d = error.details();
  return this->error(path, d.problem, false, d.suggestion,
                     d.value.empty() ? std::nullopt : std::optional<std::string>(d.value));
}

SceneError JsonSource::error_at(std::size_t offset, std::string problem) const {
  SceneError::Details details;
  details.file = std::string(name_);
  const LineColumn at = line_column(text_, offset);
  details.line = at.line;
  details.column = at.column;
  details.problem = std::move(problem);
  return SceneError(std::move(details));
}

ObjectFields::ObjectFields(const JsonSource& source, const nlohmann::json& json, JsonPath path,
                           std::initializer_list<std::string_view> known_keys)
    : source_(&source), json_(&json), path_(std::move(path)) {
  if (!json.is_object()) {
    throw source.error(path_, "must be an object, not " + type_name(json));
  }
  const std::vector<std::string_view> known(known_keys);
  for (const auto& item : json.items()) {
    bool is_known = false;
    for (const std::string_view k : known) is_known = is_known || k == item.key();
    if (!is_known) {
      throw source.error(child(path_, item.key()), "unknown key", true,
                         nearest_key(item.key(), known), "\"" + item.key() + "\"");
    }
  }
}

bool ObjectFields::has(std::string_view key) const { return json_->contains(key); }

JsonPath ObjectFields::path_of(std::string_view key) const { return child(path_, key); }

void ObjectFields::fail(std::string_view key, std::string problem) const {
  throw source_->error(path_of(key), std::move(problem));
}

const nlohmann::json& ObjectFields::at(std::string_view key) const {
  const auto found = json_->find(key);
  if (found == json_->end()) fail(key, "is missing");
  return *found;
}

double ObjectFields::number_value(const JsonSource& source, const nlohmann::json& json,
                                  const JsonPath& path) {
  if (!json.is_number()) {
    std::string problem = "must be a number, not " + type_name(json);
    if (json.is_string()) problem += " (JSON numbers have no NaN or infinity)";
    throw source.error(path, problem);
  }
  const double value = json.get<double>();
  // The parser refuses numbers beyond a double's range; this guards against anything else.
  if (!std::isfinite(value)) throw source.error(path, "must be a finite number");
  return value;
}

Vec2 ObjectFields::vector_value(const JsonSource& source, const nlohmann::json& json,
                                const JsonPath& path) {
  if (!json.is_array() || json.size() != 2) {
    throw source.error(path, "must be an array of two numbers [x, y], not " +
                                 (json.is_array() ? "an array of " + std::to_string(json.size())
                                                  : type_name(json)));
  }
  return {number_value(source, json[0], child(path, std::size_t{0})),
          number_value(source, json[1], child(path, std::size_t{1}))};
}

double ObjectFields::number(std::string_view key) const {
  return number_value(*source_, at(key), path_of(key));
}

std::optional<double> ObjectFields::optional_number(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return number(key);
}

double ObjectFields::number_or(std::string_view key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

Vec2 ObjectFields::vector(std::string_view key) const {
  return vector_value(*source_, at(key), path_of(key));
}

std::optional<Vec2> ObjectFields::optional_vector(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return vector(key);
}

std::string ObjectFields::string(std::string_view key) const {
  const nlohmann::json& value = at(key);
  if (!value.is_string()) fail(key, "must be a string, not " + type_name(value));
  return value.get<std::string>();
}

std::optional<std::string> ObjectFields::optional_string(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return string(key);
}

bool ObjectFields::boolean_or(std::string_view key, bool fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& value = at(key);
  if (!value.is_boolean()) fail(key, "must be true or false, not " + type_name(value));
  return value.get<bool>();
}

std::uint64_t ObjectFields::whole_number(std::string_view key) const {
  const nlohmann::json& value = at(key);
  if (value.is_number_unsigned()) return value.get<std::uint64_t>();
  if (value.is_number_integer()) fail(key, "must be >= 0");
  if (value.is_number_float()) fail(key, "must be a whole number (no decimal point or exponent)");
  fail(key, "must be a whole number, not " + type_name(value));
}

std::optional<std::uint64_t> ObjectFields::optional_whole_number(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return whole_number(key);
}

const nlohmann::json* ObjectFields::array(std::string_view key) const {
  if (!has(key)) return nullptr;
  const nlohmann::json& value = at(key);
  if (!value.is_array()) fail(key, "must be an array, not " + type_name(value));
  return &value;
}

}  // namespace carom::scene_detail
