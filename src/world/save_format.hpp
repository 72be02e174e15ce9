// carom internal: the byte-level pieces of the world's save format (docs/world.md, "Saving and
// resuming"): little-endian integers, doubles as their raw IEEE-754 bits, and the FNV-1a 64
// checksum. The reader throws carom::InvalidArgument naming the field it could not read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "carom/vec2.hpp"

namespace carom::detail {

// FNV-1a, 64 bits: simple, fast enough for a save, and catches any single changed byte.
[[nodiscard]] std::uint64_t fnv1a64(std::string_view bytes) noexcept;

class ByteWriter {
 public:
  void u8(std::uint8_t value) { bytes_.push_back(static_cast<char>(value)); }
  void u32(std::uint32_t value) { unsigned_bytes(value, 4); }
  void u64(std::uint64_t value) { unsigned_bytes(value, 8); }
  void i32(std::int32_t value) { u32(static_cast<std::uint32_t>(value)); }
  // Raw bits: every double (NaN payloads, -0, infinities) comes back exactly.
  // memcpy rather than std::bit_cast: the libc++ of Debian's emscripten 3.1.6 (the wasm preset)
  // has no bit_cast yet; for a trivially copyable type the two compile to the same move.
  void f64(double value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    u64(bits);
  }
  void vec2(Vec2 value) {
    f64(value.x);
    f64(value.y);
  }
  [[nodiscard]] const std::string& bytes() const noexcept { return bytes_; }

 private:
  void unsigned_bytes(std::uint64_t value, int count) {
    for (int i = 0; i < count; ++i) bytes_.push_back(static_cast<char>((value >> (8 * i)) & 0xffU));
  }
  std::string bytes_;
};

// Reads a payload whose checksum already matched: running out of bytes therefore means the
// content disagrees with itself (a count larger than what follows), reported as such.
class ByteReader {
 public:
  ByteReader(const char* function, std::string_view bytes) : function_(function), bytes_(bytes) {}

  [[nodiscard]] std::uint8_t u8(const char* field) {
    return static_cast<std::uint8_t>(unsigned_bytes(field, 1));
  }
  [[nodiscard]] std::uint32_t u32(const char* field) {
    return static_cast<std::uint32_t>(unsigned_bytes(field, 4));
  }
  [[nodiscard]] std::uint64_t u64(const char* field) { return unsigned_bytes(field, 8); }
  [[nodiscard]] std::int32_t i32(const char* field) {
    return static_cast<std::int32_t>(u32(field));
  }
  [[nodiscard]] double f64(const char* field) {
    const std::uint64_t bits = u64(field);
    double value = 0.0;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  [[nodiscard]] Vec2 vec2(const char* field) {
    const double x = f64(field);
    return {x, f64(field)};
  }
  [[nodiscard]] std::size_t remaining() const noexcept { return bytes_.size() - position_; }
  [[nodiscard]] std::size_t position() const noexcept { return position_; }
  // Throws InvalidArgument: the save's content at the current byte is inconsistent.
  [[noreturn]] void inconsistent(const std::string& field, const std::string& value,
                                 const std::string& why) const;

 private:
  [[nodiscard]] std::uint64_t unsigned_bytes(const char* field, std::size_t count);

  const char* function_;
  std::string_view bytes_;
  std::size_t position_ = 0;
};

}  // namespace carom::detail
