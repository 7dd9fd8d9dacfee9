#pragma once
// Renormalised density gradient <grad rho>_i = L_i sum_j V_j (rho_j - rho_i) grad_i W_ij with
// L_i = [sum_j V_j (x_j - x_i) (x) grad_i W_ij]^-1 (seed 002 eqs. 20-21), feeding the delta-SPH
// diffusion term. Where L_i cannot be inverted reliably (a particle with few neighbours, e.g.
// a splash) the uncorrected gradient is used: det(M_i) below kMinDeterminant.
#include <Eigen/LU>

#include "ecs/system.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class RenormalisedDensityGradient final : public System<D> {
 public:
  // For a full, regular neighbourhood M_i = I; below this its inverse amplifies noise.
  static constexpr double kMinDeterminant = 0.1;

  explicit RenormalisedDensityGradient(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "density_gradient_renormalised"; }
  Access access() const override {
    return Access{}
        .read(components::position, components::density, components::mass, components::kind,
              neighbours_resource)
        .write(components::density_gradient);
  }
  void run(SystemContext<D>& ctx) override {
    auto x = ctx.read(components::position);
    auto rho = ctx.read(components::density);
    auto m = ctx.read(components::mass);
    auto kind = ctx.read(components::kind);
    auto& nl = ctx.read(neighbours_resource);
    auto grad = ctx.write(components::density_gradient);
    const bool periodic = p_.domain.any_periodic();
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Mat<D> M = Mat<D>::Zero();
      Vec<D> g = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        Vec<D> xij = periodic ? p_.domain.displacement(x[i], x[j]) : Vec<D>(x[i] - x[j]);
        Vec<D> gradW = xij * p_.kernel.grad_factor(xij.norm());
        double Vj = m[j] / rho[j];
        M -= Vj * xij * gradW.transpose();  // (x_j - x_i) (x) grad W
        g += Vj * (rho[j] - rho[i]) * gradW;
      }
      grad[i] = std::abs(M.determinant()) > kMinDeterminant ? Vec<D>(M.inverse() * g) : g;
    });
  }

 private:
  WcsphParameters<D> p_;
};

}  // namespace ryushi
