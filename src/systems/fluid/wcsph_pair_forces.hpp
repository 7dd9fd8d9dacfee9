#pragma once
// WCSPH pair forces: one pass over each fluid particle's neighbours that evaluates every pair
// term of a stage, sharing the gather, the distance and the kernel gradient (issue 13):
//   continuity + delta-SPH diffusion   (continuity_delta_sph.hpp, seed 002 eqs. 17-19)
//   pressure + artificial viscosity    (momentum.hpp, seed 002 eqs. 22-24)
//   laminar viscosity, Morris 1997     (laminar_viscosity_morris.hpp)
// Those three systems hold the formulas one term per file and remain the reference: a test
// checks that this pass reproduces them to round-off (the products by 1/rho and 1/(r^2 + eta^2)
// in place of divisions differ from them in the last bits). The density gradient stays a separate
// pass because this one needs its neighbours' values.
//
// Neighbours beyond the kernel support (a Verlet list's skin) are skipped before any work.
// Two variants: each pair once in parallel blocks (pairs_once.hpp; 1.5x faster measured) when
// the particle order allows it, else each particle gathering all its pairs.
#include <algorithm>
#include <vector>

#include "ecs/io.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/fluid/pairs_once.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class WcsphPairForces final : public System<D> {
 public:
  explicit WcsphPairForces(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "wcsph_pair_forces"; }
  auto io() const {
    return Io{reads(components::position, components::velocity, components::density, components::pressure,
                    components::mass, components::kind, neighbours_resource),
              writes(components::density_rate, components::acceleration),
              optional(p_.delta > 0, reads(components::density_gradient)),
              optional(p_.viscous(), reads(components::viscosity, components::wall_velocity))};
  }
  Access access() const override { return io().access(); }
  void initialise(World<D>& world, Resources&) override {
    if (!p_.viscous() || p_.variable_viscosity) return;  // a rheology model writes it each stage
    auto& mu = world.ensure(components::viscosity);
    std::fill(mu.begin(), mu.end(), p_.mu);
  }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, rho, p, m, kind, nl, drho, a, grad, mu, vw] = io().fetch(ctx);
    Columns c{x, v, rho, p, m, kind, grad, mu, vw, {}, {}, drho, a};
    particle_volumes(c.m, c.rho, volume_);
    inverse_densities(c.rho, inv_rho_);
    c.V = volume_;
    c.inv_rho = inv_rho_;
    // The branches that are fixed for a run become template arguments, out of the pair loop.
    const bool periodic = p_.domain.any_periodic(), diffusion = p_.delta > 0, viscous = p_.viscous();
    const std::size_t block = pairs_once_block_size(nl, pairs_once_);
    dispatch(periodic, [&](auto P) {
      dispatch(diffusion, [&](auto Dif) {
        dispatch(viscous, [&](auto Vis) {
          if (block > 0)
            pass_pairs_once<P.value, Dif.value, Vis.value>(c, nl, block);
          else
            pass<P.value, Dif.value, Vis.value>(c, nl);
        });
      });
    });
  }

  // Test hook: both variants are checked against the reference systems.
  void set_pairs_once(PairsOnce mode) { pairs_once_ = mode; }

 private:
  struct Columns {
    std::span<const Vec<D>> x, v;
    std::span<const double> rho, p, m;
    std::span<const std::int32_t> kind;
    std::span<const Vec<D>> grad;
    std::span<const double> mu;
    std::span<const Vec<D>> vw;
    std::span<const double> V, inv_rho;
    std::span<double> drho;
    std::span<Vec<D>> a;
  };

  template <class F>
  static void dispatch(bool flag, F&& f) {
    if (flag)
      f(std::true_type{});
    else
      f(std::false_type{});
  }

  template <bool Periodic>
  Vec<D> displacement(const Vec<D>& xi, const Vec<D>& xj) const {
    if constexpr (Periodic)
      return p_.domain.displacement(xi, xj);
    else
      return xi - xj;
  }

  double pressure_coefficient(double pi, double pj, double rhoi, double rhoj, double inv_rho_ij, double vx,
                              double inv_r2_eta2) const {
    return p_.pair_pressure_coefficient(pi, pj, rhoi, rhoj, inv_rho_ij, vx, inv_r2_eta2);
  }

  // The particle's rates from its pair sums, the same for both variants: the same sums in the
  // same order as the separate systems, a = (pressure + g) + viscous.
  template <bool Viscous>
  void store(const Columns& c, std::size_t i, double divergence, double diffusive, const Vec<D>& acc,
             const Vec<D>& acc_visc) const {
    c.drho[i] = c.rho[i] * divergence + p_.delta * p_.kernel.h() * p_.c0 * diffusive;
    c.a[i] = acc + p_.gravity;
    if constexpr (Viscous) c.a[i] += acc_visc;
  }

  template <bool Periodic, bool Diffusion, bool Viscous>
  void pass(const Columns& c, const NeighbourList& nl) const {
    const double support2 = p_.kernel.support() * p_.kernel.support();
    const double h = p_.kernel.h(), eta2 = 0.01 * h * h;
    const bool no_slip = p_.wall_no_slip;
    for_each_of_kind(c.kind, kFluid, [&](std::size_t i) {
      const Vec<D> xi = c.x[i], vi = c.v[i];
      const double rhoi = c.rho[i], pi = c.p[i], inv_rhoi = c.inv_rho[i];
      Vec<D> gi = Vec<D>::Zero();
      if constexpr (Diffusion) gi = c.grad[i];
      double mui = 0;
      if constexpr (Viscous) mui = c.mu[i];
      double divergence = 0, diffusive = 0;
      Vec<D> acc = Vec<D>::Zero(), acc_visc = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        const Vec<D> xij = displacement<Periodic>(xi, c.x[j]);
        const double r2 = xij.squaredNorm();
        if (r2 >= support2) continue;
        const double F = p_.kernel.grad_factor(std::sqrt(r2));
        const Vec<D> gradW = xij * F;
        const Vec<D> vij = vi - c.v[j];
        const double rhoj = c.rho[j], Vj = c.V[j];
        const bool fluid_j = c.kind[j] == kFluid;
        // Continuity and delta-SPH diffusion ((x_j - x_i) . grad_i W / r^2 = -F exactly).
        divergence += Vj * vij.dot(gradW);
        if constexpr (Diffusion)
          if (fluid_j) diffusive += Vj * (-2.0 * (rhoj - rhoi) * F - (gi + c.grad[j]).dot(gradW));
        // Pressure and artificial viscosity for approaching pairs. Divisions are the costly
        // part of a pair: 1/rho comes per particle and 1/(r^2 + eta^2) is shared.
        const double inv_rho_ij = inv_rhoi * c.inv_rho[j];
        const double inv_r2_eta2 = 1.0 / (r2 + eta2);
        const double coeff =
            pressure_coefficient(pi, c.p[j], rhoi, rhoj, inv_rho_ij, vij.dot(xij), inv_r2_eta2);
        acc -= c.m[j] * coeff * gradW;
        // Laminar viscosity; walls use their ghost velocity (no-slip) or are left out (slip).
        if constexpr (Viscous) {
          if (fluid_j || no_slip) {
            const double muj = fluid_j ? c.mu[j] : mui;
            const Vec<D> vj = fluid_j ? c.v[j] : c.vw[j];
            acc_visc += (c.m[j] * (mui + muj) * inv_rho_ij * (r2 * F) * inv_r2_eta2) * (vi - vj);
          }
        }
      }
      store<Viscous>(c, i, divergence, diffusive, acc, acc_visc);
    });
  }

  // Each pair once (pairs_once.hpp): v_ij . grad W, the pressure/artificial-viscosity
  // coefficient and the viscous factor are symmetric in (i, j); the kernel gradient, the
  // diffusion term and v_ij change sign.
  template <bool Periodic, bool Diffusion, bool Viscous>
  void pass_pairs_once(const Columns& c, const NeighbourList& nl, std::size_t block) {
    const std::size_t N = c.x.size();
    div_.resize(N);
    dif_.resize(N);
    acc_.resize(N);
    visc_.resize(N);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 4096), [&](auto r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        div_[i] = dif_[i] = 0.0;
        acc_[i] = visc_[i] = Vec<D>::Zero();
      }
    });
    const double support2 = p_.kernel.support() * p_.kernel.support();
    const double h = p_.kernel.h(), eta2 = 0.01 * h * h;
    const bool no_slip = p_.wall_no_slip;
    auto particles = [&](std::size_t lo, std::size_t hi) {
      for (std::size_t i = lo; i < hi; ++i) {
        const bool fluid_i = c.kind[i] == kFluid;
        const Vec<D> xi = c.x[i], vi = c.v[i];
        const double rhoi = c.rho[i], pi = c.p[i], inv_rhoi = c.inv_rho[i], Vi = c.V[i], mi = c.m[i];
        Vec<D> gi = Vec<D>::Zero();
        if constexpr (Diffusion) gi = c.grad[i];
        double mui = 0;
        if constexpr (Viscous) mui = c.mu[i];
        double div_i = 0, dif_i = 0;
        Vec<D> acc_i = Vec<D>::Zero(), visc_i = Vec<D>::Zero();
        for (const std::uint32_t j : neighbours_above(nl, i)) {
          const bool fluid_j = c.kind[j] == kFluid;
          if (!fluid_i && !fluid_j) continue;
          const Vec<D> xij = displacement<Periodic>(xi, c.x[j]);
          const double r2 = xij.squaredNorm();
          if (r2 >= support2) continue;
          const double F = p_.kernel.grad_factor(std::sqrt(r2));
          const Vec<D> gradW = xij * F;  // grad_i W_ij = -grad_j W_ji
          const Vec<D> vij = vi - c.v[j];
          const double rhoj = c.rho[j], Vj = c.V[j], mj = c.m[j];
          // v_ij . grad_i W_ij is the same seen from j (both factors change sign).
          const double t = vij.dot(gradW);
          const double inv_rho_ij = inv_rhoi * c.inv_rho[j];
          const double inv_r2_eta2 = 1.0 / (r2 + eta2);
          const double coeff =
              pressure_coefficient(pi, c.p[j], rhoi, rhoj, inv_rho_ij, vij.dot(xij), inv_r2_eta2);
          if (fluid_i) {
            div_i += Vj * t;
            acc_i -= mj * coeff * gradW;
          }
          if (fluid_j) {
            div_[j] += Vi * t;
            acc_[j] += mi * coeff * gradW;
          }
          if constexpr (Diffusion) {
            if (fluid_i && fluid_j) {  // antisymmetric: what i gains, j loses (weighted by V)
              const double s = -2.0 * (rhoj - rhoi) * F - (gi + c.grad[j]).dot(gradW);
              dif_i += Vj * s;
              dif_[j] -= Vi * s;
            }
          }
          if constexpr (Viscous) {
            const double k = inv_rho_ij * (r2 * F) * inv_r2_eta2;
            if (fluid_i && fluid_j) {
              const double kk = (mui + c.mu[j]) * k;
              visc_i += (mj * kk) * vij;
              visc_[j] -= (mi * kk) * vij;
            } else if (no_slip) {  // the fluid side sees the wall's ghost velocity and its own mu
              if (fluid_i)
                visc_i += (mj * 2.0 * mui * k) * (vi - c.vw[j]);
              else
                visc_[j] += (mi * 2.0 * c.mu[j] * k) * (c.v[j] - c.vw[i]);
            }
          }
        }
        if (fluid_i) {
          div_[i] += div_i;
          dif_[i] += dif_i;
          acc_[i] += acc_i;
          visc_[i] += visc_i;
        }
      }
    };
    for_each_block_in_two_phases(N, block, particles);
    for_each_of_kind(c.kind, kFluid,
                     [&](std::size_t i) { store<Viscous>(c, i, div_[i], dif_[i], acc_[i], visc_[i]); });
  }

  WcsphParameters<D> p_;
  std::vector<double> volume_, inv_rho_;
  std::vector<double> div_, dif_;  // per-particle sums of the each-pair-once pass
  std::vector<Vec<D>> acc_, visc_;
  PairsOnce pairs_once_ = PairsOnce::Auto;
};

}  // namespace ryushi
