#pragma once
// SPH(2): all second derivatives of f at particle i, exact for quadratic fields on any particle
// configuration with a non-degenerate support (V&V paper eqs. 6-16):
//   [M_i] (D f)_i = 2 sum_j V_j q_ij (f_j - f_i - r_ij . <grad f>_1) F_ij
//   M_i = sum_j V_j q_ij p_ij^T F_ij,   F_ij = r_ij . gW~_ij / |r_ij|^4,   gW~ = L_i gW
//   q_ij = (r_I r_J)_{I<=J},  p_ij = (A(I,J))_{I<=J},  A(I,J) = r_I r_J - r_ij . sum_k V_k r_I^ik r_J^ik gW~_ik
//   D f = (f_xx, f_yy, 2 f_xy) in 2D; (f_xx, f_yy, f_zz, 2 f_xy, 2 f_xz, 2 f_yz) in 3D.
// The 3x3 (2D) / 6x6 (3D) system is solved with fixed-size Eigen. Where M_i or L_i is singular
// (too few neighbours) the Hessian falls back to (standard Laplacian / D) I.
// Also the second-order gradient of eq. 6: <grad f>_2 = <grad f>_1 - 1/2 sum_k V_k (r^T H r) gW~_k.
#include <Eigen/LU>

#include "ecs/outer_sum.hpp"
#include "systems/operators/gradient.hpp"
#include "systems/operators/laplacian.hpp"

namespace ryushi {

template <int D>
struct SecondOrderDerivatives {
  Mat<D> hessian;
  Vec<D> gradient;  // second-order gradient, eq. 6
  bool corrected;   // false where the fallback was used
};

template <int D>
SecondOrderDerivatives<D> second_derivatives_sph2(const ParticleView<D>& v, std::span<const double> f, std::size_t i) {
  constexpr int K = kSymmetricCount<D>;
  constexpr auto pairs = symmetric_pairs<D>();
  bool corrected = false;
  const Mat<D> L = renormalisation(v, i, &corrected);
  auto fallback = [&] {
    double lap = laplacian_standard(v, f, i);
    return SecondOrderDerivatives<D>{Mat<D>::Identity() * (lap / D), gradient_standard(v, f, i), false};
  };
  if (!corrected) return fallback();
  Vec<D> G1 = Vec<D>::Zero();
  std::array<Vec<D>, K> Q;  // sum_k V_k r_I r_J gW~_k
  Q.fill(Vec<D>::Zero());
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j), gw = v.volume[j] * (L * v.grad_w(r));
    G1 += (f[j] - f[i]) * gw;
    for (int p = 0; p < K; ++p) Q[p] += gw * r[pairs[p].first] * r[pairs[p].second];
  }
  OuterSum<K> moments;
  Eigen::Matrix<double, K, 1> rhs = Eigen::Matrix<double, K, 1>::Zero();
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j), gw = L * v.grad_w(r);
    double r2 = r.squaredNorm();
    double F = r.dot(gw) / (r2 * r2);
    Eigen::Matrix<double, K, 1> q, p;
    for (int k = 0; k < K; ++k) {
      auto [a, b] = pairs[k];
      q[k] = r[a] * r[b];
      p[k] = q[k] - r.dot(Q[k]);
    }
    moments.add(Eigen::Matrix<double, K, 1>(v.volume[j] * F * q), p);
    rhs += v.volume[j] * F * (f[j] - f[i] - r.dot(G1)) * q;
  }
  Eigen::FullPivLU<Eigen::Matrix<double, K, K>> lu(moments.matrix());
  if (!lu.isInvertible()) return fallback();
  Eigen::Matrix<double, K, 1> Df = 2.0 * lu.solve(rhs);
  SecondOrderDerivatives<D> out{Mat<D>::Zero(), G1, true};
  for (int k = 0; k < K; ++k) {
    auto [a, b] = pairs[k];
    if (a == b) {
      out.hessian(a, a) = Df[k];
    } else {
      out.hessian(a, b) = out.hessian(b, a) = 0.5 * Df[k];
    }
  }
  // eq. 6: remove the quadratic part from the first-order gradient.
  for (int k = 0; k < K; ++k) {
    auto [a, b] = pairs[k];
    double weight = (a == b ? 1.0 : 2.0) * out.hessian(a, b);
    out.gradient -= 0.5 * weight * Q[k];
  }
  return out;
}

// The trace of the SPH(2) Hessian as Laplacian weights (laplacian.hpp's convention): with
// s = M_i^-T t (t picks the diagonal entries of D f), lap_i = 2 s . rhs, so
//   c_j = 2 V_j F_ij (s . q_ij),  w_k = c_k - (sum_j c_j r_ij) . V_k L_i gW_k.
// Falls back to the standard weights (returns false) where L_i or M_i is singular.
template <int D>
bool laplacian_weights_sph2(const Stencil<D>& s, std::vector<double>& w) {
  constexpr int K = kSymmetricCount<D>;
  constexpr auto pairs = symmetric_pairs<D>();
  bool corrected = false;
  const Mat<D> L = renormalisation(s, &corrected);
  if (!corrected) {
    laplacian_weights_standard(s, w);
    return false;
  }
  const auto Q = corrected_quadratic_moments(s, L);
  OuterSum<K> moments;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec<D>& r = s.r[k];
    const Vec<D> gw = L * s.grad_w(k);
    double r2 = r.squaredNorm();
    Eigen::Matrix<double, K, 1> q, p;
    for (int m = 0; m < K; ++m) {
      q[m] = r[pairs[m].first] * r[pairs[m].second];
      p[m] = q[m] - r.dot(Q[m]);
    }
    moments.add(Eigen::Matrix<double, K, 1>(s.volume[k] * (r.dot(gw) / (r2 * r2)) * q), p);
  }
  Eigen::FullPivLU<Eigen::Matrix<double, K, K>> lu(moments.matrix().transpose());
  if (!lu.isInvertible()) {
    laplacian_weights_standard(s, w);
    return false;
  }
  Eigen::Matrix<double, K, 1> t = Eigen::Matrix<double, K, 1>::Zero();
  for (int k = 0; k < D; ++k) t[k] = 1.0;  // the diagonal entries come first in symmetric_pairs
  Eigen::Matrix<double, K, 1> sv = lu.solve(t);
  w.resize(s.size());
  Vec<D> C = Vec<D>::Zero();
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec<D>& r = s.r[k];
    const Vec<D> gw = L * s.grad_w(k);
    double r2 = r.squaredNorm();
    Eigen::Matrix<double, K, 1> q;
    for (int m = 0; m < K; ++m) q[m] = r[pairs[m].first] * r[pairs[m].second];
    w[k] = 2.0 * s.volume[k] * (r.dot(gw) / (r2 * r2)) * sv.dot(q);
    C += w[k] * r;
  }
  for (std::size_t k = 0; k < s.size(); ++k) w[k] -= s.volume[k] * C.dot(L * s.grad_w(k));
  return true;
}

template <int D>
bool laplacian_weights_sph2(const ParticleView<D>& v, std::size_t i, std::vector<double>& w) {
  return laplacian_weights_sph2(gathered_stencil(v, i), w);
}

}  // namespace ryushi
