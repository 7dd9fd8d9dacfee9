#pragma once
// Renormalisation (gradient-correction) matrix L_i = [sum_j V_j gW_ij (x) r_ij]^-1
// (ISPH paper eq. 10, V&V paper eq. 3). With a full support M_i = I; where the support is badly
// cut (an isolated or splashing particle) M_i is near-singular and its inverse amplifies noise.
// Then the correction is dropped: L_i = I, i.e. the uncorrected operator is used. The test is
// det(M_i) < kMinRenormalisationDeterminant (det = 1 for a full support, about 0.5 on a flat free
// surface, 0 for a single neighbour).
#include <Eigen/LU>

#include "ecs/outer_sum.hpp"
#include "systems/operators/stencil.hpp"

namespace ryushi {

inline constexpr double kMinRenormalisationDeterminant = 0.05;

template <int D>
Mat<D> moment_matrix(const Stencil<D>& s) {
  OuterSum<D> M;
  for (std::size_t k = 0; k < s.size(); ++k) M.subtract(Vec<D>((s.volume[k] * s.factor[k]) * s.r[k]), s.r[k]);
  return M.matrix();
}

template <int D>
Mat<D> moment_matrix(const ParticleView<D>& v, std::size_t i) {
  return moment_matrix(gathered_stencil(v, i));
}

// L_i from the moment matrix M_i, or the identity where M_i is too close to singular (then
// `corrected` is false).
template <int D>
Mat<D> renormalisation(const Mat<D>& M, bool* corrected = nullptr) {
  bool ok = M.determinant() > kMinRenormalisationDeterminant;
  if (corrected) *corrected = ok;
  return ok ? Mat<D>(M.inverse()) : Mat<D>::Identity();
}

template <int D>
Mat<D> renormalisation(const Stencil<D>& s, bool* corrected = nullptr) {
  return renormalisation(moment_matrix(s), corrected);
}

template <int D>
Mat<D> renormalisation(const ParticleView<D>& v, std::size_t i, bool* corrected = nullptr) {
  return renormalisation(gathered_stencil(v, i), corrected);
}

}  // namespace ryushi
