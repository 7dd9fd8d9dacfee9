#pragma once
// The Franke function (V&V paper eq. 18) on the unit square, and a 3D analogue in which every
// term gets a z factor equal to its y factor, with exact gradient and Hessian:
//   f = sum_k c_k exp(-a_k (9x - x_k)^2 - b_k (9y - y_k)^2 [- b_k (9z - y_k)^2 in 3D])
#include <array>
#include <cmath>

#include "ecs/math.hpp"

namespace ryushi {

struct FrankeTerm {
  double c, a, x0, b, y0;
};

inline constexpr std::array<FrankeTerm, 4> kFrankeTerms{{{0.75, 1.0 / 4, 2, 1.0 / 4, 2},
                                                         {0.75, 1.0 / 49, -1, 1.0 / 10, -1},
                                                         {0.50, 1.0 / 4, 7, 1.0 / 4, 3},
                                                         {-0.20, 1.0, 4, 1.0, 7}}};

template <int D>
struct FrankeValue {
  double value = 0;
  Vec<D> gradient = Vec<D>::Zero();
  Mat<D> hessian = Mat<D>::Zero();
};

template <int D>
FrankeValue<D> franke(const Vec<D>& x) {
  FrankeValue<D> out;
  for (auto& t : kFrankeTerms) {
    // Per axis: exponent -alpha (9 x - centre)^2; derivative factors g = -18 alpha (9x - c),
    // second derivative of the exponent -162 alpha.
    Vec<D> g, h2;
    double exponent = 0;
    for (int k = 0; k < D; ++k) {
      double alpha = k == 0 ? t.a : t.b, centre = k == 0 ? t.x0 : t.y0, s = 9 * x[k] - centre;
      exponent -= alpha * s * s;
      g[k] = -18 * alpha * s;
      h2[k] = -162 * alpha;
    }
    double e = t.c * std::exp(exponent);
    out.value += e;
    out.gradient += e * g;
    Mat<D> H = g * g.transpose();
    H.diagonal() += h2;
    out.hessian += e * H;
  }
  return out;
}

}  // namespace ryushi
