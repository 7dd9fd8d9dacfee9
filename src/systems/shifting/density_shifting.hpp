#pragma once
// Density-based particle shifting (ISPH paper section 5, eqs. 19-25), as two systems any method
// can add after its particles have moved:
//   shifting_density   <rho>_i = beta sum_{j in S*} m_j W_ij                            (eq. 19)
//                      over S*, the particles within d* = 1.1 sqrt(D) d (i itself included):
//                      a radius a single wall layer fills. beta makes <rho> = rho0 on the
//                      initial lattice (shifting_beta; 1.028 for the cubic spline, h = 1.2 d, 3D).
//   particle_shifting  dr_i = C_shift h (dr_w,i + dr_dens,i)                          (eq. 20)
//                      dr_w* = sum_{S*} V_j W_ij e_ij (eq. 22: spreads clumps);
//                      dr_dens = sum_{S*} (<rho>_i/rho0 - 1 + <rho>_j/rho0 - 1) e_ij (eq. 23,
//                      read with i and j: pushes a dense pair apart, pulls a sparse pair
//                      together, so the fluid keeps its volume). e_ij = (x_i - x_j)/|x_i - x_j|.
//                      On the free surface the normal part of the whole shift is removed (eq. 21
//                      removes it from dr_w only) and surface particles count at rho0 in
//                      dr_dens: their density is short by geometry, not by expansion.
//                      The shift moves the particle (w = v + dr/dt, eq. 7); its velocity is
//                      carried to the new place, v_i += (dr_i . grad) v_i with the corrected
//                      gradient (the ALE convective term for the shift).
// The surface normal N_i is the free-surface system's (`surface_normal`, the corrected gradient
// of the kernel sum; eqs. 24-25 use the gradient of the minimum eigenvalue of L_i^-1 instead).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "ecs/io.hpp"
#include "kernels/lattice_kernel_sum.hpp"
#include "systems/free_surface/free_surface_detection.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/operators/gradient.hpp"
#include "systems/shifting/shift_velocity.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> shifting_density{"shifting_density"};
inline constexpr Component<Vector> shift{"shift"};  // the last step's dr
}  // namespace components

template <int D>
struct ShiftingParameters {
  Kernel<D> kernel{KernelType::CubicSpline, 1.0};
  Domain<D> domain;
  double spacing = 1, rho0 = 1000, coefficient = 0.005;
  // Eq. 20 moves C_shift h per step: a rate set by the step. With reference_cfl > 0 it is the
  // rate of the step reference_cfl d / max(|v|max, reference_speed) (ISPH's rule until
  // 2026-11-28, at CFL 0.2, where C_shift was tuned), whatever the step now taken: a step twice
  // as long shifts twice as far. 0 keeps the shift per step.
  double reference_cfl = 0, reference_speed = 0;
  double radius() const { return 1.1 * std::sqrt(double(D)) * spacing; }  // d*
};

// beta of eq. 19: 1 / (d^D sum_{lattice points within d*} W), the centre included.
template <int D>
double shifting_beta(const Kernel<D>& kernel, double d) {
  return 1.0 / (std::pow(d, D) * lattice_kernel_sum(kernel, d, 1.1 * std::sqrt(double(D)) * d));
}

template <int D>
class ShiftingDensity final : public System<D> {
 public:
  explicit ShiftingDensity(const ShiftingParameters<D>& p)
      : p_(p), beta_(shifting_beta(p.kernel, p.spacing)) {}
  std::string name() const override { return "shifting_density"; }
  static constexpr auto io =
      Io{reads(components::position, components::mass, components::kind, neighbours_resource),
         writes(components::shifting_density)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, m, kind, nl, rho] = io.fetch(ctx);
    const double radius = p_.radius();
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      double sum = m[i] * p_.kernel.w(0.0);
      for (auto j : nl.of(i)) {
        double r = p_.domain.offset(x[i], x[j]).norm();
        if (r <= radius) sum += m[j] * p_.kernel.w(r);
      }
      rho[i] = beta_ * sum;
    });
  }

 private:
  ShiftingParameters<D> p_;
  double beta_;
};

template <int D>
class DensityShifting final : public System<D> {
 public:
  explicit DensityShifting(const ShiftingParameters<D>& p) : p_(p) {}
  std::string name() const override { return "particle_shifting"; }
  static constexpr auto io =
      Io{reads(components::mass, components::density, components::kind, components::shifting_density,
               components::free_surface, components::surface_normal, neighbours_resource, resources::dt),
         writes(components::position, components::velocity, components::shift)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [m, density, kind, rho, surface, normal, nl, dt, x, v, shift] = io.fetch(ctx);
    particle_volumes(m, density, volume_);
    dv_.resize(m.size());
    ParticleView<D> view{std::span<const Vec<D>>(x.data(), x.size()), volume_, nl, p_.kernel, p_.domain};
    const double radius = p_.radius();
    double scale = p_.coefficient * p_.kernel.h();
    if (p_.reference_cfl > 0) {
      const double speed = std::max(max_fluid_speed<D>(kind, v), p_.reference_speed);
      scale *= dt * speed / (p_.reference_cfl * p_.spacing);
    }
    // Gather every shift and velocity change from the unshifted state first, then apply.
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      thread_local std::vector<Vec<D>> g;
      Vec<D> spread = Vec<D>::Zero(), dens = Vec<D>::Zero();
      // A surface particle's numerical density is short by geometry (no fluid outside), not by
      // expansion: it counts as rho0. Read literally, eq. 23 pulled the surface of a resting
      // tank inwards (surface 0.5 d lower and the pressure 7% low after 2 s).
      auto excess = [&](std::size_t j) {
        return kind[j] == kFluid && !surface[j] ? rho[j] / p_.rho0 - 1 : 0.0;
      };
      const double excess_i = excess(i);
      for (auto j : nl.of(i)) {
        Vec<D> r = view.r(i, j);  // x_j - x_i
        double len = r.norm();
        if (len > radius || len == 0) continue;
        Vec<D> e = -r / len;  // e_ij, from j towards i
        spread += volume_[j] * p_.kernel.w(len) * e;
        dens += (excess_i + excess(j)) * e;  // walls count at rho0
      }
      Vec<D> dr = scale * (spread + dens);
      if (surface[i]) dr -= dr.dot(normal[i]) * normal[i];  // the surface slides along itself
      shift[i] = dr;
      dv_[i] = shifted_velocity_change(view, std::span<const Vec<D>>(v.data(), v.size()), i, dr, g);
    });
    apply_shifts<D>(kind, p_.domain, shift, dv_, x, v);
  }

 private:
  ShiftingParameters<D> p_;
  std::vector<double> volume_;
  std::vector<Vec<D>> dv_;
};

}  // namespace ryushi
