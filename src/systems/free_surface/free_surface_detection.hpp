#pragma once
// Free-surface detection: a flag and an outward unit normal per fluid particle.
//   marrone  Marrone et al. (2010): lambda = min eigenvalue of the moment matrix
//            M_i = sum_j V_j gW_ij (x) r_ij (the inverse of the correction matrix). lambda <= 0.2:
//            surface; lambda > 0.75: interior; in between, the scan-region test: i is on the
//            surface when no neighbour lies in the "umbrella" on its outer side,
//              |r_ij| >= sqrt(2) h  and |x_j - T| < h,  or
//              |r_ij| <  sqrt(2) h  and |n . (x_j - T)| + |tangential part of (x_j - T)| < h,
//            with T = x_i + h n_i, the point one smoothing length outside i.
//   isph2    the I-SPH(2) rule (free-surface paper section 3(1)): marrone, plus every particle
//            with det(M_i) < 0.6.
//   mps      particle number density n_i = sum_j w_ij below beta n0. beta = 0.85 with the MPS
//            weight at r_e = 2.1 l0: Koshizuka & Oka's 0.97 flags 40-60% false positives once
//            particles are 10% disordered (docs/operators.md).
// Normal: n_i = -L_i sum_j V_j gW_ij / |.|, the corrected gradient of the kernel sum, which
// points into the fluid (uncorrected where M_i is singular). Walls count as neighbours (they
// fill the support) and are never flagged.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "ecs/component.hpp"
#include "systems/operators/mps_reference.hpp"
#include "systems/operators/renormalisation.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Flags> free_surface{"free_surface"};      // 1 on the free surface
inline constexpr Component<Vector> surface_normal{"surface_normal"};  // unit, out of the fluid
// The Dirichlet value of a free-surface particle's pressure row where a system sets one (surface
// tension's Laplace pressure), Pa; read by the pressure rows of methods that provide
// "free_surface_pressure".
inline constexpr Component<Scalar> surface_pressure{"surface_pressure"};
}  // namespace components

enum class FreeSurfaceRule { Marrone, Isph2, Mps };

FreeSurfaceRule free_surface_rule(const std::string& name);  // throws std::invalid_argument

struct FreeSurfaceParameters {
  double lambda_surface = 0.2, lambda_interior = 0.75;  // Marrone's thresholds
  double det_surface = 0.6;                             // I-SPH(2)
  double beta = 0.85;                                   // MPS (see docs/operators.md)
};

template <int D>
struct FreeSurfaceResult {
  bool surface;
  Vec<D> normal;
};

template <int D>
Vec<D> surface_normal(const Stencil<D>& s, const Mat<D>& M) {
  Vec<D> g = Vec<D>::Zero();
  for (std::size_t k = 0; k < s.size(); ++k) g += s.volume[k] * s.grad_w(k);
  if (M.determinant() > kMinRenormalisationDeterminant) g = M.inverse() * g;
  double len = g.norm();
  return len > 0 ? Vec<D>(-g / len) : Vec<D>::Zero();
}

// The smallest eigenvalue of the moment matrix M_i (Marrone's lambda: 1 inside, about 0.5 on a
// flat surface), in closed form for the symmetric 2x2 / 3x3 (the iterative QR solver was 1% of an
// ISPH step).
template <int D>
double smallest_moment_eigenvalue(const Mat<D>& M) {
  Eigen::SelfAdjointEigenSolver<Mat<D>> eig;
  eig.computeDirect(0.5 * (M + M.transpose()), Eigen::EigenvaluesOnly);
  return eig.eigenvalues()[0];
}

template <int D>
bool scan_region_empty(const Stencil<D>& s, const Vec<D>& n) {
  const Vec<D> T = s.h * n;  // relative to x_i
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec<D> from_T = s.r[k] - T;
    if (s.len[k] >= std::sqrt(2.0) * s.h) {
      if (from_T.norm() < s.h) return false;
    } else {
      double along = n.dot(from_T);
      if (std::abs(along) + (from_T - along * n).norm() < s.h) return false;
    }
  }
  return true;
}

template <int D>
FreeSurfaceResult<D> detect_free_surface(const ParticleView<D>& v, std::size_t i, FreeSurfaceRule rule,
                                         const FreeSurfaceParameters& p, double n0 = 0) {
  const Stencil<D>& s = gathered_stencil(v, i);
  const Mat<D> M = moment_matrix(s);
  const Vec<D> n = surface_normal(s, M);
  if (rule == FreeSurfaceRule::Mps) {
    double number_density = 0;
    for (double len : s.len) number_density += v.kernel.w(len);
    return {number_density < p.beta * n0, n};
  }
  if (rule == FreeSurfaceRule::Isph2 && M.determinant() < p.det_surface) return {true, n};
  const double lambda = smallest_moment_eigenvalue(M);
  if (lambda <= p.lambda_surface) return {true, n};
  if (lambda > p.lambda_interior) return {false, n};
  return {scan_region_empty(s, n), n};
}

}  // namespace ryushi
