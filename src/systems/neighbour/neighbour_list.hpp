#pragma once
// CSR neighbour list: offsets (N+1) and indices. The interface (count, neighbours of i) is
// separate from how the list is built, so operators only see "the neighbours of i".
// A particle is not its own neighbour; pairs are included when |x_i - x_j| <= radius.
#include <cstdint>
#include <span>
#include <vector>

#include "ecs/resources.hpp"

namespace ryushi {

struct NeighbourList {
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;
  // Empty: packed, row i is [offsets[i], offsets[i + 1]). Otherwise row i is [offsets[i],
  // ends[i]), and rows need not follow each other in memory: a filtered list (filter_rows.hpp,
  // filter_candidates) has gaps between blocks of rows or its blocks out of index order.
  std::vector<std::uint32_t> ends;
  double radius = 0;
  std::size_t builds = 0;           // how many times it was built (a Verlet list is reused in between)
  std::size_t candidate_bytes = 0;  // the Verlet candidates this list is filtered from, if any

  std::size_t size() const { return offsets.size() - 1; }
  std::uint32_t end(std::size_t i) const { return ends.empty() ? offsets[i + 1] : ends[i]; }
  std::uint32_t count(std::size_t i) const { return end(i) - offsets[i]; }
  std::span<const std::uint32_t> of(std::size_t i) const {
    return {indices.data() + offsets[i], indices.data() + end(i)};
  }
  std::size_t bytes() const {
    return (offsets.size() + indices.size() + ends.size()) * sizeof(std::uint32_t) + candidate_bytes;
  }
};

inline constexpr Resource<NeighbourList> neighbours_resource{"neighbours"};

}  // namespace ryushi
