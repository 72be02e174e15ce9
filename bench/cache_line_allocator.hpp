// carom benchmarks: an allocator that aligns arrays to the cache line, so that a vector load of
// a whole line (AVX-512 loads 64 bytes) never straddles two lines. A structure-of-arrays user
// would allocate the same way; std::allocator only promises 16 bytes.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace carom::bench {

inline constexpr std::size_t kCacheLineBytes = 64;

template <class T>
struct CacheLineAllocator {
  using value_type = T;

  CacheLineAllocator() = default;
  template <class U>
  explicit CacheLineAllocator(const CacheLineAllocator<U>& /*other*/) noexcept {}

  [[nodiscard]] T* allocate(std::size_t count) {
    return static_cast<T*>(::operator new (count * sizeof(T), std::align_val_t{kCacheLineBytes}));
  }
  void deallocate(T* pointer, std::size_t /*count*/) noexcept {
    ::operator delete (pointer, std::align_val_t{kCacheLineBytes});
  }

  template <class U>
  friend bool operator==(const CacheLineAllocator& /*a*/, const CacheLineAllocator<U>& /*b*/) {
    return true;
  }
};

// One column of a structure of arrays.
using Column = std::vector<double, CacheLineAllocator<double>>;

}  // namespace carom::bench
