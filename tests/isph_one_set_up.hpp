#pragma once
// The candidate for ISPH's one set-up (issue 49, docs/isph.md "One set-up"): the paper's corrected
// operators (Laplacians, gradient, divergence; solver tolerance 1e-8), pair collisions at 0.8 d,
// Shepard wall rows with the gradient along the wall hydrostatic, the full support's compression
// term at alpha = 0.5 and Fickian shifting. Written out in full so that it overrides the
// dam-break scene's violent-flow keys too. Not the default yet: the Taylor-Green vortices, the
// coarse I-SPH(2) column's tip and the 3D dam break's front do not hold with it (docs/isph.md).
#include <string>
#include <vector>

namespace ryushi::test {

inline std::vector<std::string> isph_one_set_up(std::vector<std::string> sets = {}) {
  sets.insert(sets.end(), {"method.name=\"isph\"", "method.ppe_laplacian=\"corrected\"",
                           "method.viscous_laplacian=\"corrected\"", "method.pressure_gradient=\"corrected\"",
                           "solver.tolerance=1e-8", "method.collision_distance=0.8",
                           "method.wall_rows=\"shepard_hydrostatic\"", "method.compression_relaxation=0.5",
                           "method.compression_density=\"full_support\"", "method.compression_dead_band=5e-4",
                           "shifting.model=\"fickian\""});
  return sets;
}

}  // namespace ryushi::test
