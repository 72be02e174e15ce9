// carom: a double as text that reads back to the same bits — what messages, scene files and the
// tool's exact outputs write.
#pragma once

#include <string>

namespace carom {

// The shortest decimal text that reads back to the same double (std::to_chars): "0.1", "1e+300",
// "-0"; "nan", "inf" and "-inf" for those.
[[nodiscard]] std::string number_text(double value);

}  // namespace carom
