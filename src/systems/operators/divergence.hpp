#pragma once
// Divergence of a vector field u at particle i:
//   standard   sum_j V_j (u_j - u_i) . gW_ij
//   corrected  sum_j V_j (u_j - u_i) . L_i gW_ij   (exact for linear u)
#include "systems/operators/renormalisation.hpp"

namespace ryushi {

template <int D>
double divergence_standard(const ParticleView<D>& v, std::span<const Vec<D>> u, std::size_t i) {
  double d = 0;
  for (auto j : v.neighbours.of(i)) d += v.volume[j] * (u[j] - u[i]).dot(v.grad_w(v.r(i, j)));
  return d;
}

template <int D>
double divergence_corrected(const ParticleView<D>& v, std::span<const Vec<D>> u, std::size_t i) {
  Mat<D> L = renormalisation(v, i);
  double d = 0;
  for (auto j : v.neighbours.of(i)) d += v.volume[j] * (u[j] - u[i]).dot(L * v.grad_w(v.r(i, j)));
  return d;
}

}  // namespace ryushi
