#include "options/vector_args.hpp"

#include <algorithm>
#include <cstddef>
#include <string>

#include "options/option_value.hpp"

namespace carom::cli {
namespace {

constexpr char kSeparator = ',';

std::size_t count_parts(std::string_view text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), kSeparator)) + 1;
}

}  // namespace

std::vector<double> parse_number_list(std::string_view option, std::string_view text,
                                      std::string_view form) {
  const OptionValue value{option, text, form};
  const std::size_t wanted = count_parts(form);
  if (text.empty()) reject(value, "the value is empty");
  const std::size_t given = count_parts(text);
  if (given != wanted) {
    reject(value, std::to_string(given) + " comma-separated part" + (given == 1 ? "" : "s") +
                      " where " + std::to_string(wanted) + " are needed");
  }

  std::vector<double> numbers;
  numbers.reserve(wanted);
  std::size_t start = 0;
  for (std::size_t part = 1; part <= wanted; ++part) {
    const std::size_t stop = std::min(text.find(kSeparator, start), text.size());
    const std::string_view item = text.substr(start, stop - start);
    if (item.empty()) reject(value, "part " + std::to_string(part) + " is empty");
    numbers.push_back(parse_finite_number(item, value));
    start = stop + 1;
  }
  return numbers;
}

Ball parse_ball(std::string_view option, std::string_view text) {
  const std::vector<double> n = parse_number_list(option, text, "X,Y,R");
  return Ball{{n[0], n[1]}, n[2]};
}

Vec2 parse_vector(std::string_view option, std::string_view text) {
  const std::vector<double> n = parse_number_list(option, text, "DX,DY");
  return Vec2{n[0], n[1]};
}

}  // namespace carom::cli
