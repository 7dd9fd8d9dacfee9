#pragma once
// What every SPH/MPS operator needs: positions, volumes, the neighbour list, the kernel and the
// domain. Operators are plain functions of (view, field, i), so systems, tests, the pressure
// assembly and later methods share one implementation.
//
// Conventions (as in the V&V paper, seed 000 "空間2次精度を有するSPH"):
//   r_ij  = x_j - x_i (minimum image on periodic axes)
//   gW_ij = grad_{x_i} W(|x_i - x_j|) = -r_ij * grad_factor(|r_ij|), pointing from i towards j
//   so sum_j V_j gW_ij (x) r_ij is positive definite and L_i = [sum_j V_j gW_ij (x) r_ij]^-1.
#include <span>

#include "ecs/math.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
struct ParticleView {
  std::span<const Vec<D>> x;
  std::span<const double> volume;
  const NeighbourList& neighbours;
  Kernel<D> kernel;
  Domain<D> domain;

  std::size_t size() const { return x.size(); }
  Vec<D> r(std::size_t i, std::size_t j) const { return domain.offset(x[i], x[j]); }
  Vec<D> grad_w(const Vec<D>& r) const { return -r * kernel.grad_factor(r.norm()); }
};

}  // namespace ryushi
