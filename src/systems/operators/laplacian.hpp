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

#include "systems/operators/renormalisation.hpp"
#include "systems/operators/symmetric_pairs.hpp"

namespace ryushi {

template <int D>
double laplacian_standard(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  const double eta2 = 0.01 * v.kernel.h() * v.kernel.h();
  double lap = 0;
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j);
    double r2 = r.squaredNorm();
    lap += v.volume[j] * (f[j] - f[i]) * (-2.0 * v.kernel.grad_factor(std::sqrt(r2)) * r2 / (r2 + eta2));
  }
  return lap;
}

template <int D>
double laplacian_mps(const ParticleView<D>& v, std::span<const double> f, std::size_t i, double n0, double lambda0) {
  double sum = 0;
  for (auto j : v.neighbours.of(i)) sum += (f[j] - f[i]) * v.kernel.w(v.r(i, j).norm());
  return 2.0 * D / (lambda0 * n0) * sum;
}

template <int D>
double laplacian_corrected(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  constexpr int K = kSymmetricCount<D>;
  constexpr auto pairs = symmetric_pairs<D>();
  bool corrected = false;
  const Mat<D> L = renormalisation(v, i, &corrected);
  if (!corrected) return laplacian_standard(v, f, i);
  // Y_cd and the corrected gradient G_i.
  std::array<Vec<D>, K> Y;
  Y.fill(Vec<D>::Zero());
  Vec<D> G = Vec<D>::Zero();
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j), gw = v.volume[j] * v.grad_w(r);
    for (int p = 0; p < K; ++p) Y[p] += gw * r[pairs[p].first] * r[pairs[p].second];
    G += (f[j] - f[i]) * gw;
  }
  for (auto& y : Y) y = L * y;
  G = L * G;
  // K beta = delta, beta = B's independent entries; u_j holds e (x) gW with off-diagonals doubled.
  Eigen::Matrix<double, K, K> Kmat = Eigen::Matrix<double, K, K>::Zero();
  Eigen::Matrix<double, K, 1> delta = Eigen::Matrix<double, K, 1>::Zero();
  for (int p = 0; p < D; ++p) delta[p] = 1.0;
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j), gw = v.grad_w(r);
    double len = r.norm();
    Vec<D> e = r / len;
    Eigen::Matrix<double, K, 1> u, w;
    for (int p = 0; p < K; ++p) {
      auto [a, b] = pairs[p];
      u[p] = (a == b ? 1.0 : 2.0) * 0.5 * (e[a] * gw[b] + e[b] * gw[a]);
      w[p] = len * e[a] * e[b] - e.dot(Y[p]);
    }
    Kmat += v.volume[j] * w * u.transpose();
  }
  Eigen::FullPivLU<Eigen::Matrix<double, K, K>> lu(Kmat);
  if (!lu.isInvertible()) return laplacian_standard(v, f, i);
  Eigen::Matrix<double, K, 1> beta = lu.solve(delta);
  double lap = 0;
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j), gw = v.grad_w(r);
    double len = r.norm();
    Vec<D> e = r / len;
    double contraction = 0;
    for (int p = 0; p < K; ++p) {
      auto [a, b] = pairs[p];
      contraction += beta[p] * (a == b ? 1.0 : 2.0) * 0.5 * (e[a] * gw[b] + e[b] * gw[a]);
    }
    lap += 2.0 * v.volume[j] * contraction * ((f[j] - f[i]) / len - e.dot(G));
  }
  return lap;
}

}  // namespace ryushi
