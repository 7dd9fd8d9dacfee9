#pragma once
// The divergence of the outward normal from the surface particles' positions: in the frame of a
// surface particle i (tangent coordinates s along the plane normal to N_i, height h along N_i),
// the weighted least-squares fit h(s) = a + b . s + s^T C s / 2 through i and its surface
// neighbours (weights W_ik, i's own W(0)), and of the fitted graph
//   div N = -[(1 + |b|^2) tr C - b^T C b] / (1 + |b|^2)^(3/2)
// (2D: -c / (1 + b^2)^(3/2)); 1/R on a circle, 2/R on a sphere. Unlike a divergence of normals,
// which are themselves smoothed over the support, the fit answers a particle's own position: one
// that sticks out bends the fit towards convex at it and so reads a higher Laplace pressure.
#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <vector>

#include "systems/operators/stencil.hpp"
#include "systems/surface_tension/tangential_divergence.hpp"

namespace ryushi {

// A second, reweighted fit: a surface neighbour whose height is off the first fit by a good part
// of `trim` (d) lies on another layer (a particle of the second row that the detection also
// flagged, which held a viscous drop's outline as a rounded polygon 4% off the circle's
// curvature); Tukey's biweight takes it out smoothly. The particle itself always stays in.
template <int D, class OnSurface, class Weight>
std::optional<double> fitted_normal_divergence(const Stencil<D>& s, OnSurface on_surface, Weight weight,
                                               const Vec<D>& n_i, double trim) {
  constexpr int kTerms = D == 2 ? 3 : 6;  // a, b (D - 1), C (symmetric)
  using Row = Eigen::Matrix<double, kTerms, 1>;
  const auto E = tangent_basis<D>(n_i);
  struct Point {
    Row phi;
    double h, w;
  };
  thread_local std::vector<Point> points;
  points.clear();
  auto add = [&](const Vec<D>& r, double w) {
    const Eigen::Matrix<double, D - 1, 1> t = E.transpose() * r;
    Row phi;  // in smoothing lengths: the system stays well scaled
    if constexpr (D == 2) {
      const double u = t[0] / s.h;
      phi << 1, u, 0.5 * u * u;
    } else {
      const double u = t[0] / s.h, v = t[1] / s.h;
      phi << 1, u, v, 0.5 * u * u, u * v, 0.5 * v * v;
    }
    points.push_back({phi, n_i.dot(r) / s.h, w});
  };
  add(Vec<D>::Zero(), weight(0.0));
  for (std::size_t k = 0; k < s.size(); ++k)
    if (on_surface(s.neighbours[k])) add(s.r[k], weight(s.len[k]));
  auto solve = [&]() -> std::optional<Row> {
    Eigen::Matrix<double, kTerms, kTerms> A = Eigen::Matrix<double, kTerms, kTerms>::Zero();
    Row rhs = Row::Zero();
    int used = 0;
    for (auto& p : points) {
      if (!(p.w > 0)) continue;
      A += p.w * p.phi * p.phi.transpose();
      rhs += (p.w * p.h) * p.phi;
      ++used;
    }
    if (used < kTerms) return std::nullopt;
    const auto lu = A.fullPivLu();
    if (lu.rank() < kTerms || lu.rcond() < 1e-8) return std::nullopt;
    return Row(lu.solve(rhs));
  };
  auto c = solve();
  if (!c) return std::nullopt;
  // Tukey's biweight on the first fit's residual, zero beyond `trim`: continuous in the positions,
  // so a neighbour drifting off the layer fades out of the fit instead of leaving it in one step.
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double u = (points[k].h - points[k].phi.dot(*c)) * s.h / trim;
    points[k].w *= std::abs(u) < 1 ? (1 - u * u) * (1 - u * u) : 0.0;
  }
  if (!(c = solve())) return std::nullopt;
  if constexpr (D == 2) {
    const double b = (*c)[1], curve = (*c)[2];
    return -curve / std::pow(1 + b * b, 1.5) / s.h;
  } else {
    const double b1 = (*c)[1], b2 = (*c)[2], c11 = (*c)[3], c12 = (*c)[4], c22 = (*c)[5];
    const double g = 1 + b1 * b1 + b2 * b2;
    return -((1 + b2 * b2) * c11 - 2 * b1 * b2 * c12 + (1 + b1 * b1) * c22) / std::pow(g, 1.5) / s.h;
  }
}

}  // namespace ryushi
