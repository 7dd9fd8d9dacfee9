#pragma once
// Damping of the velocity's particle-scale part (a biharmonic filter):
//   L v_i = 1 / (S m_i) sum_j mu_ij W_ij (v_j - v_i)    (fluid neighbours; S the lattice's kernel
//                                                        sum, mu_ij = 2 m_i m_j / (m_i + m_j))
//   v_i  <- v_i - eps L(L v)_i
// L is XSPH's smoothing without its coefficient. For a smooth field L v ~ (sigma^2 / 2) lap v, so
// XSPH (v + eps L v) damps a wave of length lambda at a rate of eps (k sigma)^2 / 2 a step: with
// the few-hundred steps a sloshing period takes it is a viscosity of hundreds of times water's.
// L applied twice damps it at eps (k sigma)^4 / 4 instead (a 1 m wave against a support of 3 cm:
// 400x less) while a particle-scale mode, where L v ~ -v, still loses about eps a step. Each pair
// term is antisymmetric, so the momentum is kept; L is symmetric in the mass-weighted product, so
// the kinetic energy changes by -eps |L v|^2 + eps^2 / 2 |L^2 v|^2 (mass-weighted norms): it falls
// while eps lambda^2 <= 2 for L's eigenvalues lambda (on the lattice |lambda| <= about 1.5, so eps
// up to 0.5; a compressed cluster has larger row sums). What it is for (docs/isph.md,
// "Particle-scale damping"): the implicit density formulation's resting tanks jitter at 6-8e-4
// sqrt(g H) below the surface rows, where water's viscosity damps nothing at the particle scale.
//
// It runs on a caller's packed pairs (each particle's neighbours within the support and their W),
// so that it costs two passes over numbers already computed: as a system of its own, with the
// kernel evaluated again over the neighbour list, it took 3.7 ms of an 18.7 ms step (a/d = 100).
#include <tbb/parallel_for.h>

#include <cstdint>
#include <span>
#include <vector>

#include "ecs/component.hpp"
#include "ecs/math.hpp"

namespace ryushi {

template <int D>
class ParticleScaleDamping {
 public:
  // inverse_sum: 1 / S, the lattice's kernel sum (kernels/lattice_kernel_sum.hpp).
  ParticleScaleDamping(double epsilon, double inverse_sum) : epsilon_(epsilon), inverse_sum_(inverse_sum) {}

  // Pairs: particle i's neighbours j_[offset[i] .. offset[i + 1]) with their kernel values w.
  void apply(std::span<const std::int32_t> kind, std::span<const double> m,
             std::span<const std::uint32_t> offset, std::span<const std::uint32_t> j,
             std::span<const double> w, std::span<Vec<D>> v) {
    once_.assign(v.size(), Vec<D>::Zero());
    smoothing(kind, m, offset, j, w, std::span<const Vec<D>>(v.data(), v.size()), once_);
    twice_.assign(v.size(), Vec<D>::Zero());
    smoothing(kind, m, offset, j, w, std::span<const Vec<D>>(once_), twice_);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, v.size(), 4096), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        if (kind[i] == kFluid) v[i] -= epsilon_ * twice_[i];
    });
  }

 private:
  // out_i = L in_i over the fluid neighbours.
  void smoothing(std::span<const std::int32_t> kind, std::span<const double> m,
                 std::span<const std::uint32_t> offset, std::span<const std::uint32_t> j,
                 std::span<const double> w, std::span<const Vec<D>> in, std::vector<Vec<D>>& out) const {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, in.size(), 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kFluid) continue;
        Vec<D> sum = Vec<D>::Zero();
        for (auto k = offset[i]; k < offset[i + 1]; ++k) {
          const auto n = j[k];
          if (kind[n] == kFluid) sum += (2.0 * m[n] / (m[i] + m[n]) * w[k]) * (in[n] - in[i]);
        }
        out[i] = inverse_sum_ * sum;
      }
    });
  }

  double epsilon_, inverse_sum_;
  std::vector<Vec<D>> once_, twice_;
};

}  // namespace ryushi
