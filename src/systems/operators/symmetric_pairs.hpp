#pragma once
// Index pairs (I, J), I <= J, of a symmetric D x D tensor, diagonal first:
// 2D: xx yy xy; 3D: xx yy zz xy xz yz. K = D (D + 1) / 2 of them.
#include <array>
#include <utility>

namespace ryushi {

template <int D>
constexpr int kSymmetricCount = D * (D + 1) / 2;

template <int D>
constexpr std::array<std::pair<int, int>, kSymmetricCount<D>> symmetric_pairs() {
  if constexpr (D == 2) {
    return {{{0, 0}, {1, 1}, {0, 1}}};
  } else {
    return {{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};
  }
}

}  // namespace ryushi
