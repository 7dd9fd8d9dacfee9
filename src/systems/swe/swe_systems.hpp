#pragma once
// The systems of one shallow-water MPS step (Saigo & Koshizuka, seed 000 section 2; docs/swe.md),
// in order:
//   swe_influence_radius  r_e = alpha_e sqrt(A_max)                          eq. 9
//   swe_ghost_walls       mirror images of the particles next to walls       section 2(5)
//   swe_neighbour_search  pairs within 2 r_e over particles and ghosts       (spiky support)
//   swe_depth             h_i = sum_j V_j w_ij, A_i = V_i / h_i, z_s         eqs. 7, 8, 4
//   swe_acceleration      Du/Dt = -g <grad z_s> - g S_f                      eqs. 2, 3, 5, 6
//   swe_integrate         u and x for the step, walls reflect
//   swe_time_step         dt = CFL min l_i / (sqrt(g h_i) + |u_i|)           eq. 13
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

#include "ecs/io.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/swe/ghost_images.hpp"
#include "systems/swe/swe_parameters.hpp"

namespace ryushi {

template <class Body>
void for_each_particle(std::size_t n, Body&& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 512), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
  });
}

template <int D>
class SweNeighbourSearch final : public System<D> {
 public:
  std::string name() const override { return "swe_neighbour_search"; }
  static constexpr auto io =
      Io{reads(ghost_images_resource<D>, swe_influence_radius_resource, domain_resource<D>),
         writes(neighbours_resource, cell_grid_resource<D>)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override {
    res.ensure(neighbours_resource);
    res.ensure(cell_grid_resource<D>);
  }
  void run(SystemContext<D>& ctx) override {
    auto [g, influence, domain, list, grid] = io.fetch(ctx);
    const double radius = 2 * influence;  // the spiky kernel's support
    build_neighbour_list<D>(domain, radius, std::span<const Vec<D>>(g.position), grid, list);
  }
};

// Depth by the SPH sum with the spiky kernel, h = r_e (eqs. 7-8): h_i = sum_j V_j w_ij, the
// particle itself included; the area follows from the constant volume, A_i = V_i / h_i (eq. 4).
template <int D>
class SweDepth final : public System<D> {
 public:
  explicit SweDepth(const SweParameters& p) : p_(p) {}
  std::string name() const override { return "swe_depth"; }
  static constexpr auto io = Io{reads(components::position, components::water_volume, neighbours_resource,
                                      ghost_images_resource<D>, swe_influence_radius_resource),
                                writes(components::depth, components::area, components::bed_elevation,
                                       components::surface_elevation, components::pressure)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, V, nl, g, influence, h, A, zb, zs, p] = io.fetch(ctx);
    const Kernel<D> w(KernelType::Spiky, influence);
    const double w0 = w.w(0.0);
    for_each_particle(x.size(), [&](std::size_t i) {
      double sum = V[i] * w0;
      for (auto j : nl.of(i)) sum += V[g.owner(j)] * w.w((g.position[j] - x[i]).norm());
      h[i] = sum;
      A[i] = V[i] / sum;
      zb[i] = p_.bed->elevation(x[i][0], x[i][1]);
      zs[i] = sum + zb[i];
      p[i] = p_.rho0 * p_.g * sum;  // at the bed (hydrostatic)
    });
  }

 private:
  SweParameters p_;
};

// The pressure term of the momentum equation, Du/Dt = -g grad z_s (eq. 2), in one of two forms
// (SweParameters::momentum; Manning friction is the integrator's):
//  mps (the paper's): the MPS gradient with area ratios (eqs. 5-6) of the free surface,
//    n_i = sum_{j != i} (A_j / A_i) w_ij,
//    <grad z_s>_i = D / n_i sum_{j != i} (z_s,j - z_s,i) x_ij / |x_ij|^2 (A_j / A_i) w_ij,
//  plus the dry side of a wet/dry edge (below). On a flat surface every difference is zero,
//  whatever the bed: the lake stays at rest.
//  sph: the gradient of the depth sum of eq. 7 itself. On a flat bed grad h_i = sum_j V_j grad_i
//  w_ij (the self term has no gradient), and with V_j = A_j h_j that is exactly
//    sum_j A_j (z_s,j - z_s,i) grad_i w_ij + h_i sum_j A_j grad_i w_ij,
//  the form used here so that a bed enters through z_s. Force V_i a_i on a flat bed is
//  -g V_i V_j grad_i w_ij per pair, antisymmetric: momentum is conserved pair by pair, and the
//  second sum (zero inside a regular lattice, large where the neighbourhood is cut off) is what
//  pushes a front onto the dry bed. A lattice over relief is not its equilibrium (the second
//  sum is not zero where the areas vary), so this form is not well balanced (docs/swe.md).
template <int D>
class SweAcceleration final : public System<D> {
 public:
  explicit SweAcceleration(const SweParameters& p) : p_(p) {}
  std::string name() const override { return "swe_acceleration"; }
  static constexpr auto io =
      Io{reads(components::position, components::area, components::surface_elevation, components::depth,
               neighbours_resource, ghost_images_resource<D>, swe_influence_radius_resource),
         writes(components::acceleration)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, A, zs, h, nl, g, influence, acc] = io.fetch(ctx);
    const Kernel<D> w(KernelType::Spiky, influence);
    const bool sph = p_.momentum == SweParameters::Momentum::Sph;
    for_each_particle(x.size(), [&](std::size_t i) {
      double n = 0, shepard = A[i] * w.w(0.0);
      // grad: eq. 6's sum (mps) or sum_j A_j (z_s,j - z_s,i) grad_i w_ij (sph);
      // area_gradient (sph): sum_j A_j grad_i w_ij, kernel_gradient (mps): sum_j grad_i w_ij, with
      // grad_i w_ij = (x_i - x_j) (dw/dr) / r.
      Vec<D> grad = Vec<D>::Zero(), area_gradient = Vec<D>::Zero(), kernel_gradient = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        const std::uint32_t o = g.owner(j);
        const Vec<D> r = g.position[j] - x[i];
        const double r2 = r.squaredNorm();
        if (r2 == 0) continue;  // two particles on one spot: no direction
        const double rij = std::sqrt(r2);
        const Vec<D> grad_w = -w.grad_factor(rij) * r;
        if (sph) {
          grad += A[o] * (zs[o] - zs[i]) * grad_w;
          area_gradient += A[o] * grad_w;
          continue;
        }
        kernel_gradient += grad_w;
        const double wij = w.w(rij);
        const double weight = A[o] / A[i] * wij;
        n += weight;
        grad += (zs[o] - zs[i]) / r2 * weight * r;
        shepard += A[o] * wij;
      }
      if (sph) {
        acc[i] = -p_.g * (grad + h[i] * area_gradient);
        return;
      }
      Vec<D> a = n > 0 ? Vec<D>(-p_.g * D / n * grad) : Vec<D>::Zero();
      // The dry side of a wet/dry edge (docs/swe.md): -g h_i A_i sum_j grad_i w_ij, where the
      // kernel sum s_i = sum_j A_j w_ij (1 inside the water) says the neighbourhood is cut off:
      // fully below s = 0.90, fading to nothing at 0.99. Applied everywhere (no fade), the term
      // makes a lake at rest unstable: its round-off grows to 0.15 m/s within 10 s at any CFL.
      const double edge = std::clamp((0.99 - shepard) / 0.09, 0.0, 1.0);
      if (p_.edge_correction && edge > 0) a -= edge * p_.g * h[i] * A[i] * kernel_gradient;
      acc[i] = a;
    });
  }

 private:
  SweParameters p_;
};

// Symplectic Euler with the Manning friction implicit in |u| u (stable as h -> 0 at a wet front):
//   u^{n+1} = (u^n + dt a) / (1 + dt g n_M^2 |u^n| / h^{4/3}),  x^{n+1} = x^n + dt u^{n+1}.
// S_f = n_M^2 |u| u / R^{4/3} with the hydraulic radius R = h of sheet flow (the paper prints
// n_M without the square, which is not dimensionless; Manning's law squares it). A particle
// beyond a wall (one that crossed it, or a split child placed there) is mirrored back, its
// normal velocity reversed if it still moves outward (the ghosts keep all others off the wall).
template <int D>
class SweIntegrate final : public System<D> {
 public:
  explicit SweIntegrate(const SweParameters& p) : p_(p) {}
  std::string name() const override { return "swe_integrate"; }
  static constexpr auto io = Io{reads(components::acceleration, components::depth, resources::dt),
                                writes(components::position, components::velocity)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [a, h, dt, x, v] = io.fetch(ctx);
    const double friction = p_.g * p_.manning * p_.manning;
    for_each_particle(x.size(), [&](std::size_t i) {
      double drag = friction > 0
                        ? dt * friction * v[i].norm() / std::pow(std::max(h[i], p_.dry_depth), 4.0 / 3.0)
                        : 0.0;
      v[i] = (v[i] + dt * a[i]) / (1 + drag);
      x[i] += dt * v[i];
      for (auto& w : p_.walls) {
        const int other = 1 - w.axis;
        if (x[i][other] < w.lo || x[i][other] > w.hi) continue;
        if (w.inward * (x[i][w.axis] - w.at) < 0) {
          x[i][w.axis] = 2 * w.at - x[i][w.axis];
          if (w.inward * v[i][w.axis] < 0) v[i][w.axis] = -v[i][w.axis];
        }
      }
    });
  }

 private:
  SweParameters p_;
};

// dt = CFL min_i l_i / (c_i + |u_i|), l_i = sqrt(A_i), c_i = sqrt(g h_i) (eq. 13), for the next
// step, from this step's areas and depths and the new velocities.
template <int D>
class SweTimeStep final : public System<D> {
 public:
  explicit SweTimeStep(const SweParameters& p) : p_(p) {}
  std::string name() const override { return "time_step_control"; }
  static constexpr auto io =
      Io{reads(components::velocity, components::area, components::depth), writes(resources::dt)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [v, A, h, next] = io.fetch(ctx);
    double dt = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, v.size(), 4096), std::numeric_limits<double>::infinity(),
        [&](auto r, double m) {
          for (std::size_t i = r.begin(); i != r.end(); ++i)
            m = std::min(m, std::sqrt(A[i]) / (std::sqrt(p_.g * std::max(h[i], 0.0)) + v[i].norm()));
          return m;
        },
        [](double a, double b) { return std::min(a, b); });
    if (std::isfinite(dt)) next = p_.cfl * dt;
  }

 private:
  SweParameters p_;
};

}  // namespace ryushi
