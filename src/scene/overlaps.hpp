#pragma once
// Overlap tests between a scene's boxes, so that fluid placed inside a wall's particle layers or
// on top of another fluid block is refused at load (two particles at one place give r = 0 pairs:
// WCSPH skips them and keeps trapped fluid in the wall, MPS's collision throws them out of the box).
#include <algorithm>
#include <vector>

#include "scene/scene.hpp"

namespace ryushi {

// True when the boxes [a0, a1] and [b0, b1] share a volume thicker than tol on every axis.
inline bool boxes_overlap(const std::vector<double>& a0, const std::vector<double>& a1,
                          const std::vector<double>& b0, const std::vector<double>& b1, double tol) {
  for (std::size_t k = 0; k < a0.size(); ++k)
    if (std::min(a1[k], b1[k]) - std::max(a0[k], b0[k]) <= tol) return false;
  return true;
}

// True when a fluid block reaches into the layers of a wall box: it shares volume with the box
// grown by the layers, and is not contained in its interior (open along its open ends and top).
inline bool fluid_in_wall_layers(const FluidBlock& b, const WallBox& w, double spacing, double tol) {
  const std::size_t dim = b.min.size();
  std::vector<double> outer_lo = w.min, outer_hi = w.max;
  std::vector<double> inner_lo = w.min, inner_hi = w.max;
  for (std::size_t a = 0; a < dim; ++a) {
    const bool open_end = a < w.open_ends.size() && w.open_ends[a];
    const bool open_top = a + 1 == dim && w.open_top;
    if (open_end) {
      inner_lo[a] = -1e300, inner_hi[a] = 1e300;
      continue;
    }
    outer_lo[a] -= w.layers * spacing;
    if (open_top)
      inner_hi[a] = 1e300;
    else
      outer_hi[a] += w.layers * spacing;
  }
  if (!boxes_overlap(b.min, b.max, outer_lo, outer_hi, tol)) return false;
  for (std::size_t a = 0; a < dim; ++a)
    if (b.min[a] < inner_lo[a] - tol || b.max[a] > inner_hi[a] + tol) return true;
  return false;
}

}  // namespace ryushi
