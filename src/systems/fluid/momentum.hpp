#pragma once
// Momentum equation for weakly compressible SPH (seed 002 eq. 22 with sigma = -p I):
//   dv_i/dt = g - sum_j m_j [ (p_i + p_j)/(rho_i rho_j) + Pi_ij ] grad_i W_ij
// with Monaghan's artificial viscosity (seed 002 eqs. 23-24)
//   Pi_ij = (-alpha c0 mu_ij + beta mu_ij^2) / rho_ij,  mu_ij = h v_ij.x_ij / (r^2 + 0.01 h^2)
// for approaching pairs (v_ij.x_ij < 0), zero otherwise. Walls contribute their Adami pressure
// and their own (zero) velocity.
#include "ecs/io.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class Momentum final : public System<D> {
 public:
  explicit Momentum(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "momentum_pressure_artificial_viscosity"; }
  static constexpr auto io =
      Io{reads(components::position, components::velocity, components::density, components::pressure,
               components::mass, components::kind, neighbours_resource),
         writes(components::acceleration)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, rho, p, m, kind, nl, a] = io.fetch(ctx);
    const bool periodic = p_.domain.any_periodic();
    const double h = p_.kernel.h(), eta2 = 0.01 * h * h;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> acc = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        Vec<D> xij = periodic ? p_.domain.displacement(x[i], x[j]) : Vec<D>(x[i] - x[j]);
        double r2 = xij.squaredNorm();
        Vec<D> gradW = xij * p_.kernel.grad_factor(std::sqrt(r2));
        double coeff = (p[i] + p[j]) / (rho[i] * rho[j]);
        double vx = (v[i] - v[j]).dot(xij);
        if (vx < 0) {
          double mu = h * vx / (r2 + eta2);
          coeff += (-p_.alpha * p_.c0 * mu + p_.beta * mu * mu) / (0.5 * (rho[i] + rho[j]));
        }
        acc -= m[j] * coeff * gradW;
      }
      a[i] = acc + p_.gravity;
    });
  }

 private:
  WcsphParameters<D> p_;
};

}  // namespace ryushi
