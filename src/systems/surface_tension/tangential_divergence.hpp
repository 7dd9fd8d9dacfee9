#pragma once
// The divergence of the surface normal along the surface, corrected on the surface stencil: at a
// surface particle i with normal N_i, E a basis of the plane normal to N_i (D - 1 columns),
// s_k = E^T r_k and q_k = E^T V_k gW_ik over its surface neighbours k,
//   grad_s f = M^-1 sum_k (f_k - f_i) q_k,  M = sum_k q_k s_k^T,
// exact for f linear along the plane whatever the kernel and however many surface neighbours, so
//   div_s N = sum_k (N_k - N_i)^T E M^-1 q_k
// is 1/R on a circle and 2/R on a sphere to leading order (the normal part of N_k - N_i and of r_k
// is second order and drops out). Eq. 27's sum over the same neighbours with L_i of the full
// support reads 0.74 / R on the 2D lattice disc at R/d = 20 (docs/surface_tension.md): its moment
// over the surface row is a fraction of the support's, which the paper's 0.41 tunes for 3D.
#include <Eigen/Dense>
#include <cmath>
#include <optional>

#include "systems/operators/stencil.hpp"

namespace ryushi {

template <int D>
Eigen::Matrix<double, D, D - 1> tangent_basis(const Vec<D>& n) {
  Eigen::Matrix<double, D, D - 1> E;
  if constexpr (D == 2) {
    E.col(0) = Vec<D>(-n[1], n[0]);
  } else {
    Vec<D> axis = Vec<D>::Zero();
    int least = 0;
    for (int a = 1; a < D; ++a)
      if (std::abs(n[a]) < std::abs(n[least])) least = a;
    axis[least] = 1;
    const Vec<D> t1 = n.cross(axis).normalized();
    E.col(0) = t1;
    E.col(1) = n.cross(t1);
  }
  return E;
}

// nullopt where the surface neighbours do not span the plane (an isolated surface particle).
template <int D, class OnSurface>
std::optional<double> tangential_divergence(const Stencil<D>& s, OnSurface on_surface,
                                            std::span<const Vec<D>> normal, const Vec<D>& n_i) {
  using Plane = Eigen::Matrix<double, D - 1, D - 1>;
  using PlaneVec = Eigen::Matrix<double, D - 1, 1>;
  const auto E = tangent_basis<D>(n_i);
  Plane M = Plane::Zero();
  for (std::size_t k = 0; k < s.size(); ++k)
    if (on_surface(s.neighbours[k])) {
      const PlaneVec q = E.transpose() * Vec<D>(s.volume[k] * s.grad_w(k));
      M += q * (E.transpose() * s.r[k]).transpose();
    }
  // |det M| is about 1 (times the surface row's share of the support) on a full row; the bound
  // drops a particle with one neighbour or all of them on one side along a line.
  double scale = 0;
  for (std::size_t k = 0; k < s.size(); ++k)
    if (on_surface(s.neighbours[k])) scale += std::abs(s.volume[k] * s.factor[k]) * s.len[k] * s.len[k];
  if (!(std::abs(M.determinant()) > 1e-3 * std::pow(scale, D - 1))) return std::nullopt;
  const Plane Minv = M.inverse();
  double div = 0;
  for (std::size_t k = 0; k < s.size(); ++k)
    if (on_surface(s.neighbours[k])) {
      const PlaneVec q = E.transpose() * Vec<D>(s.volume[k] * s.grad_w(k));
      div += (normal[s.neighbours[k]] - n_i).dot(E * (Minv * q));
    }
  return div;
}

}  // namespace ryushi
