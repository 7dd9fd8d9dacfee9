#pragma once
// An array kept from one use to the next, grown only when asked for more, never zero-filled.
// Arrays over 32 MiB are mapped afresh by glibc at every allocation, and the kernel's zeroing
// of their pages was 12% of an MPS step at 1.3M particles (a fresh page costs about 0.7 ms per
// MB to fault in on the benchmark VM): per-step arrays keep their storage here. The caller
// writes every element it reads, often in parallel, so a serial fill would only cost.
#include <cstddef>
#include <memory>

namespace ryushi {

template <class U>
struct ReusableBuffer {
  std::unique_ptr<U[]> data;
  std::size_t capacity = 0;
  U* ensure(std::size_t n) {
    if (n > capacity) {
      data = std::make_unique_for_overwrite<U[]>(n);
      capacity = n;
    }
    return data.get();
  }
  std::size_t bytes() const { return capacity * sizeof(U); }
};

}  // namespace ryushi
