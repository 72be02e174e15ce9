#include "save_format.hpp"

#include "carom/error.hpp"

namespace carom::detail {

std::uint64_t fnv1a64(std::string_view bytes) noexcept {
  constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ULL;
  constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  std::uint64_t hash = kOffsetBasis;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= kPrime;
  }
  return hash;
}

void ByteReader::inconsistent(const std::string& field, const std::string& value,
                              const std::string& why) const {
  throw InvalidArgument(
      function_, field, value,
      "inconsistent content (payload byte " + std::to_string(position_) + "): " + why);
}

std::uint64_t ByteReader::unsigned_bytes(const char* field, std::size_t count) {
  if (remaining() < count) {
    inconsistent(field, "-", "the payload ends before this field (a count is wrong)");
  }
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < count; ++i) {
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[position_ + i]))
             << (8 * i);
  }
  position_ += count;
  return value;
}

}  // namespace carom::detail
