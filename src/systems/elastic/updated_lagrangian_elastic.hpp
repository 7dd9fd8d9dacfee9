#pragma once
// Linear-elastic bodies in seed 002's own, updated form ([method] solid_formulation =
// "updated"; Gray, Monaghan & Swift 2001): every sum runs over the current neighbours of the same
// body, the state is the density and the deviatoric stress, advanced in time by their rates:
//   drho_i/dt = -rho_i tr(grad v_i)                                   (continuity, seed eq. 1)
//   p_i = K (rho_i / rho0 - 1)                                        (eq. 5)
//   ds_i/dt = 2G (eps'_i - tr(eps'_i) I / 3) + s_i w_i^T + w_i s_i     (Hooke, Jaumann rate: eq. 7)
//   sigma_i = -p_i I + s_i                                            (eq. 6)
//   dv_i/dt = sum_j m_j [(sigma_i + sigma_j)/(rho_i rho_j) - Pi_ij I + (R_i + R_j) f_ij^n] grad W_ij
//                                                                     (eqs. 22, 25)
// with eps' and w the symmetric and antisymmetric parts of grad v_i = sum_j V_j (v_j - v_i)
// (L_i grad W_ij)^T, corrected by L_i = [sum_j V_j grad W_ij (x_j - x_i)^T]^-1 (the seed leaves the
// gradient uncorrected; corrected, a linear velocity field gives its exact rate, which the thin
// plate's bending needs); V_j = m_j / rho_j, m_j = rho0_j d^D. Monaghan's artificial stress
// (eq. 26): f_ij = W(r_ij) / W(d), n = 4, and R_i in the principal axes of sigma_i is
// -eps sigma_a / rho_i^2 where sigma_a > 0 (tension), 0 otherwise (eps = [method]
// solid_artificial_stress, the seed's 0.3). In 2D the deviator is plane strain's (tr / 3).
// Its strain energy, for output, is V (p^2 / 2K + s:s / 4G).
// Measured (docs/multiphysics.md): stable with the seed's artificial viscosity (without it the
// oscillating plate blows up in 4 ms), but soft: the plate's period +16.9% at H/d = 10, +11.3%
// at 20 (the total Lagrangian form: +7.6%, +2.8%), a block on a wall settles 19% too far, and
// the plate's pressure noise grows (rms 205 -> 1,776 Pa over 0.6 s): the sums, cut at the free
// surfaces, under-represent the stress there. Kept for comparison with the seed; not the default.
// Contact with other bodies and the artificial viscosity are the total Lagrangian form's
// (elastic_model.hpp); walls either push with the same contact springs, or ([method] solid_walls
// = "seed") enter the momentum sum as particles at rest with the pressure of seed 002's eq. 28
// interpolated from the solid (section 4.1), and at rest in the velocity gradient. Clamped
// particles get no acceleration; their stress still evolves. The density and stress advance in
// the integration's substeps (advance()), with the rates at the drifted positions and the
// half-step velocities.
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "ecs/outer_sum.hpp"
#include "systems/elastic/elastic_model.hpp"
#include "systems/operators/renormalisation.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Tensor> deviatoric_stress{"deviatoric_stress"};  // s
}  // namespace components

template <int D>
class UpdatedLagrangianElasticity final : public ElasticModel<D> {
 public:
  explicit UpdatedLagrangianElasticity(const ElasticParameters<D>& p) : p_(p) {}
  // evaluate() and advance() both take the whole list (advance uses part of it).
  static constexpr auto io =
      Io{reads(components::position, components::velocity, components::kind, components::solid_rest_density,
               components::bulk_modulus, components::shear_modulus, components::clamped,
               components::elastic_body, neighbours_resource),
         writes(components::acceleration, components::stress, components::solid_density,
                components::solid_pressure, components::strain_energy, components::deviatoric_stress)};
  void declare(Access& a) const override { io.declare(a); }
  void initialise(World<D>& world) override { world.ensure(components::deviatoric_stress); }
  void evaluate(SystemContext<D>& ctx) override {
    auto [x, v, kind, rho0, K, G, clamped, body, nl, a, sigma, rho, pressure, energy, s_state] =
        io.fetch(ctx);
    const std::span<const Mat<D>> s = s_state;  // read here; advance() writes it
    const std::size_t N = x.size();
    const double volume = p_.volume(), eps = p_.artificial_stress;
    const double w_d = p_.kernel.w(p_.spacing);
    R_.resize(N);
    auto for_each_partner = [&](std::size_t i, auto&& f) { partners(nl, kind, body, x, i, f); };
    // The stress of the state, and its artificial part.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 256), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kElastic) continue;
        pressure[i] = K[i] * (rho[i] / rho0[i] - 1.0);
        sigma[i] = -pressure[i] * Mat<D>::Identity() + s[i];
        // s:s of the 3D deviator: in 2D (plane strain) s_zz = -tr(s) too.
        const double ss = s[i].squaredNorm() + (D == 2 ? s[i].trace() * s[i].trace() : 0.0);
        energy[i] = volume * rho0[i] / rho[i] * (pressure[i] * pressure[i] / (2.0 * K[i]) + ss / (4.0 * G[i]));
        // Artificial stress: in the principal axes, -eps sigma_a / rho^2 on the tensile ones.
        Eigen::SelfAdjointEigenSolver<Mat<D>> principal(sigma[i]);
        Vec<D> r_axes = Vec<D>::Zero();
        for (int k = 0; k < D; ++k)
          if (principal.eigenvalues()[k] > 0) r_axes[k] = -eps * principal.eigenvalues()[k] / (rho[i] * rho[i]);
        R_[i] = principal.eigenvectors() * r_axes.asDiagonal() * principal.eigenvectors().transpose();
      }
    });
    if (p_.seed_walls) wall_pressure(nl, kind, x, rho0, K, rho, pressure);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 256), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kElastic) continue;
        if (clamped[i]) {
          a[i] = Vec<D>::Zero();
          continue;
        }
        const double c = std::sqrt((K[i] + 4.0 / 3.0 * G[i]) / rho0[i]);
        Vec<D> acc = Vec<D>::Zero();
        for_each_partner(i, [&](std::size_t j, const Vec<D>& r, double dist) {
          const double mj = rho0[j] * volume, fn = std::pow(p_.kernel.w(dist) / w_d, 4);
          Mat<D> T = (sigma[i] + sigma[j]) / (rho[i] * rho[j]) + (R_[i] + R_[j]) * fn;
          const double vx = (v[i] - v[j]).dot(r);
          if (vx < 0) T -= solid_viscosity(p_, vx, dist * dist, c, rho[i], rho[j]) * Mat<D>::Identity();
          acc += mj * T * (p_.kernel.grad_factor(dist) * r);
        });
        if (p_.seed_walls)  // the walls' pressure for the solid (seed 002 section 4.1), walls at rest
          within_support(
              nl, x, i, [&](std::size_t j) { return kind[j] == kWall && wall_rho_[j] > 0; },
              [&](std::size_t j, const Vec<D>& r, double dist) {
                Mat<D> T = (sigma[i] - wall_p_[j] * Mat<D>::Identity()) / (rho[i] * wall_rho_[j]);
                const double vx = v[i].dot(r);
                if (vx < 0)
                  T -= solid_viscosity(p_, vx, dist * dist, c, rho[i], wall_rho_[j]) * Mat<D>::Identity();
                acc += wall_rho_[j] * volume * T * (p_.kernel.grad_factor(dist) * r);
              });
        if (p_.contacts)
          add_solid_contact<D>(p_, nl, i, c, rho0[i], rho[i], kind, body, x, v, acc, !p_.seed_walls);
        a[i] = acc + p_.gravity;
      }
    });
    this->current_ = true;
  }
  // The rates at the drifted positions x^{n+1} with the half-step velocities v^{n+1/2}, the
  // state then advanced by them: the stress follows the motion as the positions do in velocity
  // Verlet (rates taken before the kick, an explicit Euler step, made the plate's pressure noise
  // grow from the first period).
  void advance(SystemContext<D>& ctx, double h) override {
    auto [x, v, kind, rho0, K, G, clamped, body, nl, a, sigma, rho, pressure, energy, s] = io.fetch(ctx);
    const std::size_t N = x.size();
    const double volume = p_.volume();
    ds_.resize(N);
    drho_.resize(N);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 256), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kElastic) continue;
        OuterSum<D> M, A;  // the moments and the uncorrected velocity gradient
        partners(nl, kind, body, x, i, [&](std::size_t j, const Vec<D>& r, double dist) {
          const Vec<D> g = (rho0[j] * volume / rho[j]) * p_.kernel.grad_factor(dist) * r;  // V_j grad W_ij
          M.subtract(g, r);                                                               // g (x_j - x_i)^T
          A.add(Vec<D>(v[j] - v[i]), g);
        });
        // Seed walls: wall particles at rest (v_w = 0, volume d^D) in the sums, so that a solid
        // pressing on a wall compresses as the seed's continuity has it.
        if (p_.seed_walls)
          within_support(
              nl, x, i, [&](std::size_t j) { return kind[j] == kWall; },
              [&](std::size_t, const Vec<D>& r, double dist) {
                const Vec<D> g = volume * p_.kernel.grad_factor(dist) * r;
                M.subtract(g, r);
                A.subtract(v[i], g);
              });
        const Mat<D> grad_v = A.matrix() * renormalisation<D>(M.matrix()).transpose();
        const Mat<D> rate = 0.5 * (grad_v + grad_v.transpose()), spin = 0.5 * (grad_v - grad_v.transpose());
        drho_[i] = -rho[i] * grad_v.trace();
        ds_[i] = 2.0 * G[i] * (rate - rate.trace() / 3.0 * Mat<D>::Identity()) + s[i] * spin.transpose() +
                 spin * s[i];
      }
    });
    for_each_of_kind(kind, kElastic, [&](std::size_t i) {
      rho[i] += h * drho_[i];
      s[i] += h * ds_[i];
    });
  }

 private:
  // Seed 002 eq. 28 for a wall particle w beside the solid: the solid particles' pressure
  // interpolated to it with the weight they press it with,
  //   p_w = [sum_i p_i W_wi + g . sum_i rho_i (x_w - x_i) W_wi] / sum_i W_wi,
  // and its density from the solid's equation of state, rho_w = rho0 (1 + p_w / K) (rho0, K
  // weighted the same way). Walls without solid neighbours get rho_w = 0 (left out).
  template <class Kinds, class Positions, class Scalars, class Columns>
  void wall_pressure(const NeighbourList& nl, const Kinds& kind, const Positions& x, const Scalars& rho0,
                     const Scalars& K, const Columns& rho, const Columns& pressure) {
    const std::size_t N = x.size();
    wall_p_.assign(N, 0.0);
    wall_rho_.assign(N, 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 256), [&](auto range) {
      for (std::size_t w = range.begin(); w != range.end(); ++w) {
        if (kind[w] != kWall) continue;
        double weight = 0, pw = 0, r0 = 0, k = 0;
        for (auto i : nl.of(w)) {
          if (kind[i] != kElastic) continue;
          const Vec<D> r = p_.domain.displacement(x[w], x[i]);
          const double W = p_.kernel.w(r.norm());
          if (W <= 0) continue;
          weight += W;
          pw += (pressure[i] + rho[i] * p_.gravity.dot(r)) * W;
          r0 += rho0[i] * W;
          k += K[i] * W;
        }
        if (weight <= 0) continue;
        wall_p_[w] = pw / weight;
        wall_rho_[w] = (r0 / weight) * (1.0 + wall_p_[w] / (k / weight));
      }
    });
  }

  // Each neighbour j of particle i within the support that `accept(j)` takes:
  // f(j, r_ij = x_i - x_j, |r_ij|).
  template <class Positions, class Accept, class F>
  void within_support(const NeighbourList& nl, const Positions& x, std::size_t i, Accept&& accept, F&& f) const {
    const double support = p_.kernel.support();
    for (auto j : nl.of(i)) {
      if (!accept(j)) continue;
      const Vec<D> r = p_.domain.displacement(x[i], x[j]);
      const double dist = r.norm();
      if (dist < support && dist > 0) f(j, r, dist);
    }
  }
  // ... of the same body as elastic particle i.
  template <class Kinds, class Bodies, class Positions, class F>
  void partners(const NeighbourList& nl, const Kinds& kind, const Bodies& body, const Positions& x, std::size_t i,
                F&& f) const {
    within_support(nl, x, i, [&](std::size_t j) { return kind[j] == kElastic && body[j] == body[i]; }, f);
  }

  ElasticParameters<D> p_;
  std::vector<Mat<D>> R_, ds_;  // artificial stress, deviatoric stress rate, by world index
  std::vector<double> drho_;     // density rate
  std::vector<double> wall_p_, wall_rho_;  // seed walls: each wall particle's pressure and density for the solid
};

}  // namespace ryushi
