#pragma once
// The MPS weight w(|r_ij|) of every pair in the step's neighbour list at x*, stored in the list's
// own slots: row i's weights at [offsets[i], end(i)), beside its indices. The number density
// computes them; the pressure rows and the pressure gradient, at the same positions, read them
// instead of a square root and a division per pair each (at 1.28M particles those were a third
// of the two systems' time). The values are the ones those systems computed before, bit for bit.
#include <cstddef>
#include <stdexcept>
#include <string>

#include "ecs/resources.hpp"
#include "solvers/reusable_buffer.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

struct MpsPairWeights {
  // Not zero-filled: the slots in the gaps between a filtered list's blocks are never touched,
  // so their pages never become resident.
  ReusableBuffer<double> w;
  std::size_t slots = 0;  // the slot count of the list they were computed for

  // The weights, indexed like nl.indices; `reader` names the system in the error when they were
  // computed for another list (a pipeline that narrows the list again after the number density).
  const double* of(const NeighbourList& nl, const char* reader) const {
    if (slots != nl.indices.size())
      throw std::logic_error(std::string(reader) + ": the pair weights do not belong to this neighbour list");
    return w.data.get();
  }
};

inline constexpr Resource<MpsPairWeights> mps_pair_weights_resource{"mps_pair_weights"};

}  // namespace ryushi
