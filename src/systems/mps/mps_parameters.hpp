#pragma once
// Constants of an MPS run (BMG paper "粒子法におけるポアソンソルバのマルチグリッド法", section 2),
// fixed at scene load: the weight w(r) = r_e / r - 1 (eq. 5, as Kernel<D>::Mps with h = r_e),
// the reference number density n0 (eq. 6) and lambda0 (eq. 8) of the initial lattice.
#include "ecs/component.hpp"
#include "ecs/math.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/operators/mps_reference.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> number_density{"number_density"};
// 0: pressure unknown; 1: free surface (Dirichlet p = 0); 2: no pressure (dummy).
inline constexpr Component<Flags> pressure_role{"pressure_role"};
inline constexpr Component<Vector> pressure_gradient{"pressure_gradient"};
}  // namespace components

enum PressureRole : std::int32_t { kPressureUnknown = 0, kPressureSurface = 1, kPressureNone = 2 };

template <int D>
struct MpsParameters {
  Kernel<D> weight{KernelType::Mps, 1.0};  // h = r_e
  Domain<D> domain;
  Vec<D> gravity = Vec<D>::Zero();
  double spacing = 1;  // l0
  double rho0 = 1000;
  double nu = 0;  // kinematic viscosity mu / rho0
  double n0 = 1, lambda0 = 1;
  double surface_threshold = 0.97;  // beta in n* < beta n0
  double relaxation = 0.2;          // gamma on the Poisson source
  // The density of the Poisson source: n* with the weight (the BMG paper's), or the smooth kernel
  // sum of `source_kernel` (Wendland C2 within r_e) against its lattice value source_n0
  // (set_source_kernel; docs/mps.md, "The source's density").
  bool smooth_source = false;
  Kernel<D> source_kernel{KernelType::WendlandC2, 1.0};
  double source_n0 = 1;
  bool clamp_negative_pressure = true;
  double cfl = 0.2;
  double reference_speed = 1;  // sqrt(2 g H): bounds the first steps' dt before anything moves
  // The neighbour list is built once per step at x^k and reused at the predicted x*, so its
  // radius has a skin covering how far two particles can approach in one predictor step
  // (each moves at most cfl * l0, see mps_time_step, VelocityTimeStep).
  double search_radius() const { return weight.support() + 2.5 * cfl * spacing; }

  void set_weight(double influence_radius) {
    weight = Kernel<D>(KernelType::Mps, influence_radius);
    auto ref = mps_reference<D>(weight, spacing);
    n0 = ref.n0;
    lambda0 = ref.lambda0;
  }
  // The smooth source's kernel: Wendland C2 with support `fraction` * r_e.
  void set_source_kernel(double fraction) {
    smooth_source = true;
    source_kernel = Kernel<D>(KernelType::WendlandC2, 0.5 * fraction * weight.support());
    source_n0 = mps_reference<D>(source_kernel, spacing).n0;
  }
  double laplacian_coefficient() const { return 2.0 * D / (lambda0 * n0); }
};

}  // namespace ryushi
