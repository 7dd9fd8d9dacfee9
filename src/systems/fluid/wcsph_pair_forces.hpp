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
#include <vector>

#include "ecs/system.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class WcsphPairForces final : public System<D> {
 public:
  explicit WcsphPairForces(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "wcsph_pair_forces"; }
  Access access() const override {
    Access a;
    a.read(components::position, components::velocity, components::density, components::pressure,
           components::mass, components::kind, neighbours_resource)
        .write(components::density_rate, components::acceleration);
    if (p_.delta > 0) a.read(components::density_gradient);
    if (p_.mu > 0) a.read(components::viscosity, components::wall_velocity);
    return a;
  }
  void initialise(World<D>& world, Resources&) override {
    if (p_.mu <= 0) return;
    auto& mu = world.ensure(components::viscosity);
    std::fill(mu.begin(), mu.end(), p_.mu);
  }
  void run(SystemContext<D>& ctx) override {
    Columns c{ctx.read(components::position),
              ctx.read(components::velocity),
              ctx.read(components::density),
              ctx.read(components::pressure),
              ctx.read(components::mass),
              ctx.read(components::kind),
              {},
              {},
              {},
              {},
              {},
              ctx.write(components::density_rate),
              ctx.write(components::acceleration)};
    if (p_.delta > 0) c.grad = ctx.read(components::density_gradient);
    if (p_.mu > 0) {
      c.mu = ctx.read(components::viscosity);
      c.vw = ctx.read(components::wall_velocity);
    }
    particle_volumes(c.m, c.rho, volume_);
    inverse_densities(c.rho, inv_rho_);
    c.V = volume_;
    c.inv_rho = inv_rho_;
    const auto& nl = ctx.read(neighbours_resource);
    // The branches that are fixed for a run become template arguments, out of the pair loop.
    const bool periodic = p_.domain.any_periodic(), diffusion = p_.delta > 0, viscous = p_.mu > 0;
    dispatch(periodic, [&](auto P) {
      dispatch(diffusion, [&](auto Dif) {
        dispatch(viscous, [&](auto Vis) { pass<P.value, Dif.value, Vis.value>(c, nl); });
      });
    });
  }

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

  template <bool Periodic, bool Diffusion, bool Viscous>
  void pass(const Columns& c, const NeighbourList& nl) const {
    const double support2 = p_.kernel.support() * p_.kernel.support();
    const double h = p_.kernel.h(), eta2 = 0.01 * h * h;
    const double diffusion = p_.delta * h * p_.c0;
    const double alpha_c0 = p_.alpha * p_.c0, beta = p_.beta;
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
        Vec<D> xij;
        if constexpr (Periodic)
          xij = p_.domain.displacement(xi, c.x[j]);
        else
          xij = xi - c.x[j];
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
        double coeff = (pi + c.p[j]) * inv_rho_ij;
        // Branch-free: about half the pairs approach, a branch on it mispredicts (mu = 0 and
        // the term vanishes for receding pairs).
        const double mu = h * std::min(vij.dot(xij), 0.0) * inv_r2_eta2;
        coeff += (-alpha_c0 * mu + beta * mu * mu) / (0.5 * (rhoi + rhoj));
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
      c.drho[i] = rhoi * divergence + diffusion * diffusive;
      // The same sums in the same order as the separate systems: a = (pressure + g) + viscous.
      c.a[i] = acc + p_.gravity;
      if constexpr (Viscous) c.a[i] += acc_visc;
    });
  }

  WcsphParameters<D> p_;
  std::vector<double> volume_, inv_rho_;
};

}  // namespace ryushi
