// carom internal: argument checks shared by every public function. Each throws
// carom::InvalidArgument naming the function, the argument and the offending value.
#pragma once

#include <string>

#include "carom/number_text.hpp"
#include "carom/vec2.hpp"

namespace carom::detail {

// "(x, y)", each as carom::number_text writes it.
[[nodiscard]] std::string vector_text(Vec2 value);

void require_finite(const char* function, const char* argument, double value);
void require_finite(const char* function, const char* argument, Vec2 value);
void require_positive(const char* function, const char* argument, double value);
void require_non_negative(const char* function, const char* argument, double value);
// low <= value <= high; requirement is the message's last part, e.g. "must lie in [0, 1]".
void require_in_range(const char* function, const char* argument, double value, double low,
                      double high, const char* requirement);
void require_restitution(const char* function, const char* argument, double value);
// A mass is finite and > 0, or carom::kImmovable (+infinity).
void require_mass(const char* function, const char* argument, double value);
// A requirement that the caller tests itself; throws with that requirement when condition is false.
void require_that(bool condition, const char* function, const char* argument, double value,
                  const char* requirement);
void require_nonzero(const char* function, const char* argument, Vec2 value);

}  // namespace carom::detail
