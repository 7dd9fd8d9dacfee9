#pragma once
// Gradient operators of a scalar field f at particle i.
//   standard   sum_j V_j (f_j - f_i) gW_ij                      (V&V eq. 4; exact only if M_i = I)
//   symmetric  sum_j V_j (f_i + f_j) gW_ij                      (the momentum form
//              rho_i sum_j m_j (f_i/rho_i^2 + f_j/rho_j^2) gW_ij at uniform density; conserves
//              momentum pairwise but is not consistent even to zeroth order on a cut support)
//   corrected  L_i sum_j V_j (f_j - f_i) gW_ij                  (ISPH eqs. 9-10; exact for linear f)
//              (gradient_corrected_where: only where det M_i reaches a bound)
//   mps        d/n0 sum_j (f_j - f_i) r_ij / |r_ij|^2 w_ij      (MPS, with f_i in place of the
//              local minimum so that the operator is linear)
#include <algorithm>
#include <optional>
#include <vector>

#include "ecs/outer_sum.hpp"
#include "systems/operators/renormalisation.hpp"

namespace ryushi {

template <int D>
Vec<D> gradient_standard(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  Vec<D> g = Vec<D>::Zero();
  for (auto j : v.neighbours.of(i)) g += v.volume[j] * (f[j] - f[i]) * v.grad_w(v.r(i, j));
  return g;
}

template <int D>
Vec<D> gradient_symmetric(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  Vec<D> g = Vec<D>::Zero();
  for (auto j : v.neighbours.of(i)) g += v.volume[j] * (f[i] + f[j]) * v.grad_w(v.r(i, j));
  return g;
}

// The standard gradient and the moment matrix M_i = L_i^-1 of its support, in one pass.
template <int D>
struct GradientMoments {
  Vec<D> standard;
  Mat<D> moments;
};

template <int D>
GradientMoments<D> gradient_moments(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  OuterSum<D> moments;
  Vec<D> g = Vec<D>::Zero();
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j), gw = v.volume[j] * v.grad_w(r);
    moments.add(gw, r);
    g += (f[j] - f[i]) * gw;
  }
  return {g, moments.matrix()};
}

template <int D>
Vec<D> gradient_corrected(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  const auto [g, M] = gradient_moments(v, f, i);
  return M.determinant() > kMinRenormalisationDeterminant ? Vec<D>(M.inverse() * g) : g;
}

// The corrected gradient where the support is full enough to trust L_i (det M_i >= min_det),
// nothing elsewhere: the caller chooses the form for cut supports (ISPH's hybrid gradient).
template <int D>
std::optional<Vec<D>> gradient_corrected_where(const ParticleView<D>& v, std::span<const double> f,
                                               std::size_t i, double min_det) {
  const auto [g, M] = gradient_moments(v, f, i);
  if (M.determinant() < std::max(min_det, kMinRenormalisationDeterminant)) return std::nullopt;
  return Vec<D>(M.inverse() * g);
}

template <int D>
Vec<D> gradient_mps(const ParticleView<D>& v, std::span<const double> f, std::size_t i, double n0) {
  Vec<D> g = Vec<D>::Zero();
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j);
    g += (f[j] - f[i]) / r.squaredNorm() * v.kernel.w(r.norm()) * r;
  }
  return (D / n0) * g;
}

// The corrected gradient as weights: grad_i = sum_k g_k (f_k - f_i), g_k = V_k L_i gW_ik (k over
// neighbours.of(i) in order), for assembling rows that hold a gradient (Neumann walls).
template <int D>
void gradient_weights_corrected(const Stencil<D>& s, const Mat<D>& L, std::vector<Vec<D>>& g) {
  g.resize(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) g[k] = s.volume[k] * (L * s.grad_w(k));
}

template <int D>
void gradient_weights_corrected(const Stencil<D>& s, std::vector<Vec<D>>& g) {
  gradient_weights_corrected(s, renormalisation(s), g);
}

template <int D>
void gradient_weights_corrected(const ParticleView<D>& v, std::size_t i, std::vector<Vec<D>>& g) {
  gradient_weights_corrected(gathered_stencil(v, i), g);
}

}  // namespace ryushi
