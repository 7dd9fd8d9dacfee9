#pragma once
// Parallel loop over the fluid particles: each particle gathers over its own neighbours and
// writes only itself, so no atomics are needed.
#include <tbb/parallel_for.h>

#include <cstdint>
#include <span>

#include "ecs/component.hpp"

namespace ryushi {

template <class Body>
void for_each_of_kind(std::span<const std::int32_t> kind, std::int32_t wanted, Body&& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kind.size(), 1024), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      if (kind[i] == wanted) body(i);
  });
}

}  // namespace ryushi
