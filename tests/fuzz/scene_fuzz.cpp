// libFuzzer target for the scene loader: any bytes are either a scene or one SceneError, never a
// crash, a hang, undefined behaviour or another exception; and a scene that loads saves to text
// that loads back to the same text (the exact round trip).
//
// Build: cmake --preset fuzz && cmake --build --preset fuzz; run: make fuzz (or fuzz-smoke).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "carom/scene.hpp"

namespace {

// Generators may ask for up to 10^7 balls, which is legitimate but would make each run take
// seconds; the harness skips inputs that ask for more than this many, so the fuzzer spends its
// time on the parser and the checks rather than on placing balls.
constexpr std::uint64_t kMaxGeneratedBalls = 500;

bool asks_for_many_balls(std::string_view text) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (!json.is_object() || !json.contains("generators") || !json["generators"].is_array()) {
    return false;
  }
  std::uint64_t total = 0;
  for (const auto& generator : json["generators"]) {
    if (!generator.is_object() || !generator.contains("count")) continue;
    const auto& count = generator["count"];
    if (count.is_number_unsigned()) total += count.get<std::uint64_t>();
    if (total > kMaxGeneratedBalls) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (asks_for_many_balls(text)) return -1;  // not added to the corpus
  carom::Scene scene;
  try {
    scene = carom::parse_scene(text, "fuzz.json");
  } catch (const carom::SceneError& error) {
    // The message is built, and every part of it is readable.
    if (error.what() == nullptr) std::abort();
    return 0;
  }
  const std::string saved = carom::to_json_text(scene);
  std::string again;
  try {
    again = carom::to_json_text(carom::parse_scene(saved, "saved.json"));
  } catch (const carom::SceneError&) {
    std::abort();  // a scene carom wrote must load
  }
  if (again != saved) std::abort();  // the round trip must be exact
  return 0;
}
