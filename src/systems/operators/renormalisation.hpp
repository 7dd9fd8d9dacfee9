#pragma once
// Renormalisation (gradient-correction) matrix L_i = [sum_j V_j gW_ij (x) r_ij]^-1
// (ISPH paper eq. 10, V&V paper eq. 3). With a full support M_i = I; where the support is badly
// cut (an isolated or splashing particle) M_i is near-singular and its inverse amplifies noise.
// Then the correction is dropped: L_i = I, i.e. the uncorrected operator is used. The test is
// det(M_i) < kMinRenormalisationDeterminant (det = 1 for a full support, about 0.5 on a flat free
// surface, 0 for a single neighbour).
#include <Eigen/LU>

#include "systems/operators/particle_view.hpp"

namespace ryushi {

inline constexpr double kMinRenormalisationDeterminant = 0.05;

template <int D>
Mat<D> moment_matrix(const ParticleView<D>& v, std::size_t i) {
  Mat<D> M = Mat<D>::Zero();
  for (auto j : v.neighbours.of(i)) {
    Vec<D> r = v.r(i, j);
    M += v.volume[j] * v.grad_w(r) * r.transpose();
  }
  return M;
}

// L_i, or the identity where M_i is too close to singular (then `corrected` is false).
template <int D>
Mat<D> renormalisation(const ParticleView<D>& v, std::size_t i, bool* corrected = nullptr) {
  Mat<D> M = moment_matrix(v, i);
  bool ok = M.determinant() > kMinRenormalisationDeterminant;
  if (corrected) *corrected = ok;
  return ok ? Mat<D>(M.inverse()) : Mat<D>::Identity();
}

}  // namespace ryushi
