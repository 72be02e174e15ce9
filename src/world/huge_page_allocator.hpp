// carom internal: an allocator for the world's per-ball and per-cell arrays that asks the kernel
// to back their large allocations with 2 MiB pages (Linux transparent huge pages, "madvise"
// mode). Prediction reads a few balls, their queue entries and grid links at addresses that
// are far apart in a large world; with 4 KiB pages nearly each of those reads also misses the
// TLB (docs/decisions/0011-huge-pages-for-large-arrays.md). Elsewhere, or when the kernel
// declines, it behaves as
// std::allocator: the advice changes where memory lies, never what the engine computes.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <new>
#include <vector>

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sys/mman.h>
#endif

namespace carom::detail {

// The size of an x86-64 and AArch64 (4 KiB granule) transparent huge page.
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

template <class T>
class HugePageAllocator {
 public:
  using value_type = T;

  HugePageAllocator() noexcept = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}

  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageBytes) {
      return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
    }
    // aligned_alloc wants a multiple of the alignment; the rounded-up tail is never touched,
    // so it costs address space only.
    const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
    void* memory = std::aligned_alloc(kHugePageBytes, rounded);
    if (memory == nullptr) throw std::bad_alloc();
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
    // Only whole pages inside the request: a huge page past its end would be faulted in whole
    // (2 MiB of resident memory) by the first element written there. Advice only: failure is
    // harmless, so its result is ignored.
    (void)madvise(memory, bytes / kHugePageBytes * kHugePageBytes, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(memory);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePageBytes) {
      ::operator delete (p, std::align_val_t{alignof(T)});
    } else {
      std::free(p);  // NOLINT(cppcoreguidelines-no-malloc): allocated by aligned_alloc above
    }
  }

  template <class U>
  friend bool operator==(const HugePageAllocator& /*a*/, const HugePageAllocator<U>& /*b*/) {
    return true;
  }
};

// A std::vector whose large buffers may lie on huge pages.
template <class T>
using BigVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace carom::detail
