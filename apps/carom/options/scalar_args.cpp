#include "options/scalar_args.hpp"

#include "carom/bounce.hpp"
#include "options/option_value.hpp"

namespace carom::cli {

double parse_mass(std::string_view option, std::string_view text) {
  const OptionValue value{option, text, "a number > 0, or inf or immovable"};
  if (text == kImmovableWord || text == kInfiniteWord) return kImmovable;
  const double mass = parse_finite_number(text, value);
  if (!(mass > 0.0)) reject(value, "a mass must be > 0");
  return mass;
}

double parse_restitution(std::string_view option, std::string_view text) {
  const OptionValue value{option, text, "a number in [0, 1]"};
  const double restitution = parse_finite_number(text, value);
  if (!(restitution >= 0.0 && restitution <= 1.0)) {
    reject(value, "the restitution must lie in [0, 1]");
  }
  return restitution;
}

}  // namespace carom::cli
