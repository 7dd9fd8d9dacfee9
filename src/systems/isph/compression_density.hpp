#pragma once
// The density error that the stabilised source of the ISPH pressure equation answers
// (`[method] compression_relaxation` alpha, `compression_density`): interior rows add
// alpha rho0 e_i / tau^2, with e_i one of
//   first_shell   <rho>_i/rho0 - 1 by eq. 19 over S* (the lattice's first shell, which one wall
//                 layer fills), where it is positive only. Both ways, the deficit that a disordered
//                 first shell reads (a neighbour drifting across its edge) held a 0.2 m pool at
//                 -6 kPa; one way, nothing returns a slow dilation: over 200 periods of a sloshing
//                 tank the water's volume grew about 0.3% (docs/stability.md).
//   full_support  where no free-surface particle lies in the support: the kernel sum over the
//                 whole support, the wall's two missing layers completed (copies of each wall
//                 particle one and two spacings further into the wall; wall_rows = "adami" has
//                 them), over the lattice's own sum,
//                 both ways. On shifted (blue-noise) arrangements of the same density that sum
//                 reads within a fraction of a percent of the lattice's, so a dilation is seen and
//                 returned. A dilation counts at most kDilationCap: a deeper deficit is air in a
//                 splash, and pulling it together clumped the spray (the a/d = 20 dam break lost 9
//                 of 800 particles over the walls uncapped, none capped). A support that reaches
//                 the surface is short by geometry: first_shell there. Within the dead band
//                 (`compression_dead_band`) of the lattice's sum the error counts as 0: with tau of
//                 about a step (0.2 d / sqrt(2 g H)) the term is stiff, and with the corrected
//                 gradient a resting tank's floor rows, a few 1e-4 off the lattice, held a standing
//                 velocity divergence against the wall rows (1.3e-4 sqrt(g H) of motion, and the
//                 pressure 3.7% off rho g depth after a step shorter than the last, when the next
//                 source no longer cancelled it). It lets the volume wander within the band: the
//                 200-period sloshing tank's period means by about 1-3 J/m.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "ecs/component.hpp"
#include "ecs/math.hpp"
#include "kernels/kernel.hpp"
#include "kernels/lattice_kernel_sum.hpp"
#include "systems/operators/stencil.hpp"

namespace ryushi {

enum class CompressionDensity { FirstShell, FullSupport };

template <int D>
class CompressionError {
 public:
  static constexpr double kDilationCap = 0.01;

  // walls_complete: the walls have their layers (wall_rows = "adami"), no copies are needed.
  // dead_band: a full-support error within it counts as 0 (`compression_dead_band`).
  CompressionError(const Kernel<D>& kernel, double spacing, CompressionDensity measure,
                   bool walls_complete = false, double dead_band = 0.0)
      : walls_complete_(walls_complete),
        dead_band_(dead_band),
        kernel_(kernel),
        spacing_(spacing),
        shell_(1.1 * std::sqrt(double(D)) * spacing),
        shell_sum_(lattice_kernel_sum(kernel, spacing, shell_)),
        support_sum_(lattice_kernel_sum(kernel, spacing, kernel.support())),
        measure_(measure) {}

  // e_i at the fluid particle whose neighbourhood `st` holds (within the support).
  double operator()(const Stencil<D>& st, std::span<const std::int32_t> kind,
                    std::span<const std::int32_t> surface, std::span<const Vec<D>> wall_normal) const {
    double shell = kernel_.w(0.0), whole = shell;
    bool complete = measure_ == CompressionDensity::FullSupport;
    for (std::size_t k = 0; k < st.size(); ++k) {
      const double len = st.len[k];
      if (len >= kernel_.support()) continue;
      const double w = kernel_.w(len);
      if (len <= shell_) shell += w;
      if (!complete) continue;
      const std::size_t j = st.neighbours[k];
      if (kind[j] == kFluid && surface[j]) complete = false;
      whole += w;
      if (kind[j] == kWall && !walls_complete_) whole += missing_layers(st.r[k], wall_normal[j]);
    }
    if (complete) {
      const double e = whole / support_sum_ - 1.0;
      return std::max(e > dead_band_ ? e - dead_band_ : e < -dead_band_ ? e + dead_band_ : 0.0, -kDilationCap);
    }
    return std::max(shell / shell_sum_ - 1.0, 0.0);
  }

 private:
  // The kernel sum of the wall's two missing layers behind wall particle j, seen at offset r (x_j -
  // x_i): copies one and two spacings out along its normal. A box's corner (or 3D edge) particle
  // has the bisector of two or three axes as its normal; behind it the layers fill a quarter plane
  // (or an octant's part), copies at every combination of 0-2 spacings along each of those axes:
  // along the bisector alone a resting tank's corner particles read 4e-4 of dilation (the
  // violent-flow set-up's 200-period tank: period means within 0.60 J/m with this, 0.70 without).
  double missing_layers(const Vec<D>& r, const Vec<D>& n) const {
    int axes[D], active = 0;
    double size = 0;
    bool lattice_corner = true;
    for (int a = 0; a < D; ++a) {
      if (std::abs(n[a]) < 1e-6) continue;
      if (active > 0 && std::abs(std::abs(n[a]) - size) > 1e-6) lattice_corner = false;
      size = std::abs(n[a]);
      axes[active++] = a;
    }
    double sum = 0;
    if (active < 2 || !lattice_corner) {
      for (int layer = 1; layer <= 2; ++layer) sum += kernel_.w((r + layer * spacing_ * n).norm());
      return sum;
    }
    int counts[D] = {};
    while (true) {  // every combination of 0-2 layers along each active axis but none at all
      int a = 0;
      while (a < active && ++counts[a] == 3) counts[a++] = 0;
      if (a == active) break;
      Vec<D> offset = r;
      for (int b = 0; b < active; ++b)
        offset[axes[b]] += counts[b] * spacing_ * (n[axes[b]] > 0 ? 1.0 : -1.0);
      sum += kernel_.w(offset.norm());
    }
    return sum;
  }

  bool walls_complete_;
  double dead_band_;
  Kernel<D> kernel_;
  double spacing_, shell_, shell_sum_, support_sum_;
  CompressionDensity measure_;
};

}  // namespace ryushi
