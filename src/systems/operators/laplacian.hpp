#pragma once
// Laplacian operators of a scalar field f at particle i.
//   standard   sum_j V_j (f_j - f_i) (-2 F_ij |r|^2 / (|r|^2 + 0.01 h^2))
//              (Morris et al. 1997 / Cummins & Rudman 1999; V&V eq. 17 with a 0.01 h^2 guard;
//              F = grad_factor. Not consistent: its error does not vanish with d at fixed h/d.)
//   corrected  Fatehi & Manzari (2011), the form of the ISPH paper eqs. 11-14, derived here as
//                lap_i = sum_j 2 V_j (B_i : e_j (x) gW_j) [ (f_j - f_i)/|r_j| - e_j . G_i ]
//              with G_i the corrected gradient and the symmetric B_i chosen so that the operator
//              is exact for every quadratic f:
//                sum_j V_j (B_i : e_j (x) gW_j) [ |r_j| e_j (x) e_j - e_j . Y ] = I,
//                Y_cd = L_i sum_k V_k gW_k r_k,c r_k,d.
//              (D(D+1)/2 unknowns; the ISPH paper's eq. 14 is this condition written with its
//              own sign conventions.) Falls back to `standard` where that system is singular.
//   mps        2 d / (lambda0 n0) sum_j (f_j - f_i) w_ij   (MPS paper eqs. 7-8; the paper writes
//              f_i - f_j with the sign carried by its pressure equation)
#include <Eigen/LU>

#include <array>
#include <vector>

#include "ecs/outer_sum.hpp"
#include "systems/operators/renormalisation.hpp"
#include "systems/operators/symmetric_pairs.hpp"

namespace ryushi {

// Every Laplacian here is linear in f and written as weights on the differences,
//   lap_i = sum_k w_k (f_k - f_i),  k over neighbours.of(i) in order,
// so that the value functions below, the pressure-equation assembly and the viscous terms use
// one implementation. The *_weights functions fill `w` (resized to the neighbour count).

// Y_p = L_i sum_k V_k gW_k r_k,a r_k,b over the symmetric pairs p = (a, b): the corrected
// gradient's response to the quadratic monomials, shared by the corrected and SPH(2) weights.
template <int D>
std::array<Vec<D>, kSymmetricCount<D>> corrected_quadratic_moments(const Stencil<D>& s, const Mat<D>& L) {
  constexpr auto pairs = symmetric_pairs<D>();
  std::array<Vec<D>, kSymmetricCount<D>> Y;
  Y.fill(Vec<D>::Zero());
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec<D>& r = s.r[k];
    const Vec<D> gw = s.volume[k] * s.grad_w(k);
    for (int p = 0; p < kSymmetricCount<D>; ++p) Y[p] += gw * r[pairs[p].first] * r[pairs[p].second];
  }
  for (auto& y : Y) y = L * y;
  return Y;
}

template <int D>
std::array<Vec<D>, kSymmetricCount<D>> corrected_quadratic_moments(const ParticleView<D>& v, std::size_t i,
                                                                   const Mat<D>& L) {
  return corrected_quadratic_moments(gathered_stencil(v, i), L);
}

template <int D>
void laplacian_weights_standard(const Stencil<D>& s, std::vector<double>& w) {
  const double eta2 = 0.01 * s.h * s.h;
  w.resize(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double r2 = s.len[k] * s.len[k];
    w[k] = s.volume[k] * (-2.0 * s.factor[k] * r2 / (r2 + eta2));
  }
}

template <int D>
void laplacian_weights_standard(const ParticleView<D>& v, std::size_t i, std::vector<double>& w) {
  laplacian_weights_standard(gathered_stencil(v, i), w);
}

// Corrected (Fatehi-Manzari) weights: with c_j = B_i : e_j (x) gW_j and the corrected gradient
// G_i = L_i sum_k V_k (f_k - f_i) gW_k,
//   lap_i = sum_j 2 V_j c_j (f_j - f_i)/|r_j| - E . G_i,  E = sum_j 2 V_j c_j e_j,
// so w_k = 2 V_k c_k/|r_k| - V_k E . L_i gW_k (the ISPH paper's A*_ij, eq. 12). Where L_i or the
// B_i system is singular the standard weights are used; returns false then.
template <int D>
bool laplacian_weights_corrected(const Stencil<D>& s, std::vector<double>& w) {
  constexpr int K = kSymmetricCount<D>;
  constexpr auto pairs = symmetric_pairs<D>();
  bool corrected = false;
  const Mat<D> L = renormalisation(s, &corrected);
  if (!corrected) {
    laplacian_weights_standard(s, w);
    return false;
  }
  const auto Y = corrected_quadratic_moments(s, L);
  // K beta = delta, beta = B's independent entries; u_j holds e (x) gW with off-diagonals doubled.
  Eigen::Matrix<double, K, 1> delta = Eigen::Matrix<double, K, 1>::Zero();
  for (int p = 0; p < D; ++p) delta[p] = 1.0;
  auto u_of = [&](const Vec<D>& e, const Vec<D>& gw) {
    Eigen::Matrix<double, K, 1> u;
    for (int p = 0; p < K; ++p) {
      auto [a, b] = pairs[p];
      u[p] = (a == b ? 1.0 : 2.0) * 0.5 * (e[a] * gw[b] + e[b] * gw[a]);
    }
    return u;
  };
  // Plain scalars for the outer products (ecs/outer_sum.hpp): Eigen's K x K update through the
  // stack stalled on store forwarding (60% of this function's time in two instructions).
  OuterSum<K> moments;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double len = s.len[k];
    const Vec<D> e = s.r[k] / len;
    const Eigen::Matrix<double, K, 1> u = u_of(e, s.grad_w(k));
    Eigen::Matrix<double, K, 1> wv;
    for (int p = 0; p < K; ++p)
      wv[p] = s.volume[k] * (len * e[pairs[p].first] * e[pairs[p].second] - e.dot(Y[p]));
    moments.add(wv, u);
  }
  const Eigen::Matrix<double, K, K> Kmat = moments.matrix();
  Eigen::FullPivLU<Eigen::Matrix<double, K, K>> lu(Kmat);
  if (!lu.isInvertible()) {
    laplacian_weights_standard(s, w);
    return false;
  }
  Eigen::Matrix<double, K, 1> beta = lu.solve(delta);
  w.resize(s.size());
  Vec<D> E = Vec<D>::Zero();
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double len = s.len[k];
    const Vec<D> e = s.r[k] / len;
    double c = beta.dot(u_of(e, s.grad_w(k)));
    w[k] = 2.0 * s.volume[k] * c / len;
    E += 2.0 * s.volume[k] * c * e;
  }
  const Vec<D> LtE = L.transpose() * E;
  for (std::size_t k = 0; k < s.size(); ++k) w[k] -= s.volume[k] * LtE.dot(s.grad_w(k));
  return true;
}

template <int D>
bool laplacian_weights_corrected(const ParticleView<D>& v, std::size_t i, std::vector<double>& w) {
  return laplacian_weights_corrected(gathered_stencil(v, i), w);
}

// sum_k w_k (f_k - f_i) for weights aligned with neighbours.of(i).
template <int D>
double apply_weights(const ParticleView<D>& v, std::span<const double> f, std::size_t i, const std::vector<double>& w) {
  auto nb = v.neighbours.of(i);
  double sum = 0;
  for (std::size_t k = 0; k < nb.size(); ++k) sum += w[k] * (f[nb[k]] - f[i]);
  return sum;
}

template <int D>
double laplacian_standard(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  thread_local std::vector<double> w;
  laplacian_weights_standard(v, i, w);
  return apply_weights(v, f, i, w);
}

template <int D>
double laplacian_mps(const ParticleView<D>& v, std::span<const double> f, std::size_t i, double n0, double lambda0) {
  double sum = 0;
  for (auto j : v.neighbours.of(i)) sum += (f[j] - f[i]) * v.kernel.w(v.r(i, j).norm());
  return 2.0 * D / (lambda0 * n0) * sum;
}

template <int D>
double laplacian_corrected(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  thread_local std::vector<double> w;
  laplacian_weights_corrected(v, i, w);
  return apply_weights(v, f, i, w);
}

}  // namespace ryushi
