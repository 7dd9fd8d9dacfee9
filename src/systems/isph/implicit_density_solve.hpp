#pragma once
// ISPH's pressure solve with SPH's symmetric operators (formulation = "implicit_density"; after
// Ihmsen et al. 2014, "Implicit incompressible SPH", and the solves of Bender & Koschier's DFSPH),
// at the predicted positions x* = x^n + dt v*:
//   rho_i(x)  = rho0 sum_j m_j W_ij / (m_i S)       S: the kernel summed over the starting lattice
//   a_i       = -(1/m) sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad W_ij   (walls: Adami's p)
//   rho_i(x*) - rho_i(x^n) + dt^2 rho0 / (m_i S) sum_j m_j (a_i - a_j) . grad W_ij = 0
// where p_i > 0, and p_i >= 0 where it would be negative (the particle's kernel sum falls: it
// separates, as at a free surface; no surface detection). Relaxed Jacobi from the last step's
// pressure; then v = v* + dt a, x = x* + dt^2 a. m is the lattice's gradient moment, so that a
// linear pressure on the lattice has its own gradient (the hydrostatic pressure rho0 g depth, not
// 1% above it).
// Why this form (docs/isph.md, "The implicit density formulation"):
// - the change of the kernel sum that the solve cancels is the negative adjoint of the pressure
//   force in the mass-weighted product, so the pressure does no work in the fluid: the kinetic
//   energy cannot grow from the projection (the corrected operators' projection gained 6 J/m in
//   two sloshing periods);
// - the source is the step's own change of each particle's kernel sum, not its distance from the
//   lattice's: the free surface's deficit (a surface particle reads 0.6 rho0) is the particle's
//   state, not a compression to undo. Against rho0 itself (DFSPH's density solve) a resting tank's
//   surface layer sank 0.2-0.3 d into the rows below and the water kept moving at 0.07 sqrt(g H)
//   below the top rows; only its compression corrected, a sloshing tank swelled by 2.9 J/m of
//   potential energy in 0.1 s (every dilation kept, every compression undone).
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "ecs/io.hpp"
#include "kernels/lattice_kernel_sum.hpp"
#include "systems/fluid/particle_scale_damping.hpp"
#include "systems/isph/isph_parameters.hpp"
#include "systems/mps/mps_parameters.hpp"  // components::pressure_gradient
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/pressure/pressure_system.hpp"

namespace ryushi {

// Below this fraction of the lattice's kernel sum a particle is spray: no pressure of its own (its
// neighbours' still push it). A lone particle reads 0.32, a pair a spacing apart 0.44; a flat
// surface's particle 0.78, its corner with a wall 0.61 (cubic spline, h = 1.2 d, 2D). Two drops
// approaching near the edge of each other's support (1.9-2.4 d, where grad W nearly vanishes) made
// the linear response tiny and the pressure 1e7-1e10 Pa: the dam break at a/d = 20 threw a particle
// at 386 m/s at t = 1.64 s.
inline constexpr double kSprayDensity = 0.5;

struct ImplicitDensitySettings {
  // The mean density error left, over rho0: |error| where p > 0, compression where p = 0.
  double tolerance = 1e-4;
  int max_iterations = 500;
  double relaxation = 0.5;  // Jacobi's omega (density_relaxation)
  double damping = 0;       // eps of the particle-scale damping after the solve (particle_damping)
};

template <int D>
class ImplicitDensitySolve final : public System<D> {
 public:
  ImplicitDensitySolve(const IsphParameters<D>& p, ImplicitDensitySettings s)
      : p_(p),
        s_(s),
        lattice_sum_(lattice_kernel_sum(p.kernel, p.spacing, p.kernel.support())),
        moment_(lattice_gradient_moment(p.kernel, p.spacing)),
        damping_(s.damping, 1.0 / lattice_sum_) {}
  std::string name() const override { return "implicit_density_solve"; }
  // acceleration: a moving body's (prescribed_motion), for the walls' hydrostatic head.
  auto io() const {
    return Io{reads(components::kind, components::mass, neighbours_resource, resources::dt),
              writes(components::position, components::velocity, components::pressure,
                     components::pressure_gradient, solve_statistics_resource),
              optional(p_.wall_acceleration, reads(components::body_acceleration, components::body))};
  }
  Access access() const override { return io().access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(solve_statistics_resource); }

  void run(SystemContext<D>& ctx) override {
    auto [kind, m, nl, dt, x, v, p, grad, stats, acceleration, body] = io().fetch(ctx);
    const std::size_t n = x.size();
    const double rho0 = p_.rho0, dt2 = dt * dt;
    fluid_count_ = 0;
    for (auto k : kind) fluid_count_ += k == kFluid;
    pairs(kind, body, x, v, dt, nl);
    densities_and_diagonals(kind, m, dt, acceleration);
    a_.assign(n, Vec<D>::Zero());
    int iterations = 0;
    double error = 0;
    for (;; ++iterations) {
      wall_pressures(kind, p);
      accelerations(kind, m, p);
      error = tbb::parallel_reduce(
          tbb::blocked_range<std::size_t>(0, n, 1024), 0.0,
          [&](auto range, double e) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
              if (kind[i] != kFluid) continue;
              double change = 0;
              for (auto k = offset_[i]; k < offset_[i + 1]; ++k) {
                const auto j = j_[k];
                change += m[j] * (kind[j] == kFluid ? Vec<D>(a_[i] - a_[j]) : a_[i]).dot(g_[k]);
              }
              const double residual = -growth_[i] - kappa_[i] * dt2 * change;  // > 0: the sum falls
              if (diagonal_[i] == 0) {  // spray: no pressure of its own
                next_[i] = 0;
                continue;
              }
              e += p[i] > 0 ? std::abs(residual) : std::max(0.0, -residual);
              next_[i] =
                  diagonal_[i] < 0 ? std::max(0.0, p[i] + s_.relaxation * residual / diagonal_[i]) : 0.0;
            }
            return e;
          },
          std::plus<>());
      error /= double(std::max<std::size_t>(fluid_count_, 1)) * rho0;
      if ((iterations >= 1 && error < s_.tolerance) || iterations == s_.max_iterations) break;
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](auto range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
          if (kind[i] == kFluid) p[i] = next_[i];
      });
    }
    // Not converged within max_iterations: a percent of compression left is a failed step.
    if (!(error < 1e-2))
      throw std::runtime_error("the density solve stopped after " + std::to_string(iterations) +
                               " iterations with a mean density error of " + std::to_string(error) +
                               " of rho0 (a particle thrown into another, or a non-finite velocity)");
    // a_ holds the accelerations of the pressure that the last check accepted.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kFluid) continue;
        grad[i] = -rho0 * a_[i];
        v[i] += dt * a_[i];
        x[i] += dt2 * a_[i];
        p_.domain.wrap(x[i]);
      }
    });
    // The jitter out of the new velocity, over the pairs at x* (the particles have moved dt^2 a
    // since: a filter's weights need not follow).
    if (s_.damping > 0) damping_.apply(kind, m, offset_, j_, w_, v);
    ++stats.solves;
    stats.iterations += iterations;
    stats.max_iterations = std::max(stats.max_iterations, iterations);
    stats.max_relative_residual = std::max(stats.max_relative_residual, error);
    stats.max_rows = std::max(stats.max_rows, fluid_count_);
    stats.krylov = "jacobi (implicit density)";
  }

 private:
  // Each particle's neighbours within the support with W and grad_i W at x*, and W at x^n (fluid
  // neighbours back by dt v*; the particles of a body under a prescribed motion back by dt times
  // its velocity: the motion moved them at the start of this step, from where they stood during
  // the last one, and that push is this step's to answer; other walls stand still), packed.
  void pairs(std::span<const std::int32_t> kind, std::span<const std::int32_t> body,
             std::span<const Vec<D>> x, std::span<const Vec<D>> v, double dt, const NeighbourList& nl) {
    const std::size_t n = x.size();
    offset_.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) offset_[i + 1] = offset_[i] + nl.count(i);
    j_.resize(offset_[n]);
    w_.resize(offset_[n]);
    w_before_.resize(offset_[n]);
    g_.resize(offset_[n]);
    r_.resize(offset_[n]);
    next_.assign(n, 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        auto k = offset_[i];
        auto motion = [&](std::size_t a) {
          const bool moved =
              kind[a] == kFluid || (!body.empty() && body[a] >= 0 && p_.moving_bodies[body[a]]);
          return moved ? v[a] : Vec<D>::Zero();
        };
        const Vec<D> vi = motion(i);
        for (auto j : nl.of(i)) {
          const Vec<D> r = p_.domain.offset(x[i], x[j]);  // x_j - x_i
          const double q = r.norm();
          const Vec<D> vj = motion(j);
          j_[k] = j;
          r_[k] = r;
          w_[k] = p_.kernel.w(q);
          w_before_[k] = p_.kernel.w((r - dt * (vj - vi)).norm());
          g_[k] = -r * p_.kernel.grad_factor(q);
          ++k;
        }
      }
    });
  }

  // rho_i at x* (walls: rho0), the step's growth rho_i(x*) - rho_i(x^n), and Jacobi's diagonal
  // d(density change)/d p_i (negative): the particle's own term and its fluid neighbours' reaction.
  void densities_and_diagonals(std::span<const std::int32_t> kind, std::span<const double> m, double dt,
                               std::span<const Vec<D>> acceleration) {
    const std::size_t n = kind.size();
    rho_.assign(n, p_.rho0);
    growth_.assign(n, 0.0);
    kappa_.assign(n, 0.0);
    diagonal_.assign(n, 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kFluid) continue;
        double now = m[i] * p_.kernel.w(0.0), before = now;
        for (auto k = offset_[i]; k < offset_[i + 1]; ++k) {
          now += m[j_[k]] * w_[k];
          before += m[j_[k]] * w_before_[k];
        }
        kappa_[i] = p_.rho0 / (m[i] * lattice_sum_);
        rho_[i] = kappa_[i] * now;
        growth_[i] = kappa_[i] * (now - before);
      }
    });
    // A wall particle's weights over its fluid neighbours and the hydrostatic part of its Adami
    // pressure, the W-mean of rho0 (g - a_w) . (x_w - x_f) (a_w a moving body's acceleration):
    // both fixed within the step.
    wall_weight_.assign(n, 0.0);
    wall_head_.assign(n, 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kWall) continue;
        double head = 0;
        const Vec<D> felt = acceleration.empty() ? p_.gravity : Vec<D>(p_.gravity - acceleration[i]);
        for (auto k = offset_[i]; k < offset_[i + 1]; ++k)
          if (kind[j_[k]] == kFluid) {
            wall_weight_[i] += w_[k];
            head -= w_[k] * p_.rho0 * felt.dot(r_[k]);  // r_ = x_f - x_w
          }
        if (wall_weight_[i] > 0) wall_head_[i] = head / wall_weight_[i];
      }
    });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kFluid) continue;
        // d a_i / d p_i = -(1/m) c: its own term, and the walls' pressures, which rise with p_i
        // (left out, Jacobi overshot and diverged in a 3D tank's edges).
        Vec<D> sum = Vec<D>::Zero(), c = Vec<D>::Zero();
        double reaction = 0;
        const double inv_rho2 = 1.0 / (rho_[i] * rho_[i]), inv_rho02 = 1.0 / (p_.rho0 * p_.rho0);
        for (auto k = offset_[i]; k < offset_[i + 1]; ++k) {
          const auto j = j_[k];
          sum += m[j] * g_[k];
          if (kind[j] == kFluid)
            reaction += m[j] * g_[k].squaredNorm();
          else if (wall_weight_[j] > 0)
            c += m[j] * w_[k] / wall_weight_[j] * inv_rho02 * g_[k];
        }
        c += inv_rho2 * sum;
        diagonal_[i] = -kappa_[i] * dt * dt / moment_ * (c.dot(sum) + m[i] * inv_rho2 * reaction);
        if (rho_[i] < kSprayDensity * p_.rho0) diagonal_[i] = 0;
      }
    });
  }

  // Adami's wall pressure (seed 002 eq. 27) from the fluid's current iterate, at least 0.
  void wall_pressures(std::span<const std::int32_t> kind, std::span<double> p) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kind.size(), 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kWall) continue;
        if (!(wall_weight_[i] > 0)) {
          p[i] = 0;
          continue;
        }
        double sum = 0;
        for (auto k = offset_[i]; k < offset_[i + 1]; ++k)
          if (kind[j_[k]] == kFluid) sum += w_[k] * p[j_[k]];
        p[i] = std::max(0.0, sum / wall_weight_[i] + wall_head_[i]);
      }
    });
  }

  void accelerations(std::span<const std::int32_t> kind, std::span<const double> m,
                     std::span<const double> p) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kind.size(), 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] != kFluid) continue;
        Vec<D> a = Vec<D>::Zero();
        const double pi = p[i] / (rho_[i] * rho_[i]);
        for (auto k = offset_[i]; k < offset_[i + 1]; ++k) {
          const auto j = j_[k];
          a -= m[j] * (pi + p[j] / (rho_[j] * rho_[j])) * g_[k];
        }
        a_[i] = a / moment_;
      }
    });
  }

  IsphParameters<D> p_;
  ImplicitDensitySettings s_;
  double lattice_sum_, moment_;
  ParticleScaleDamping<D> damping_;
  std::size_t fluid_count_ = 0;
  std::vector<std::uint32_t> offset_, j_;
  std::vector<double> w_, w_before_, wall_weight_, wall_head_, rho_, growth_, kappa_, diagonal_, next_;
  std::vector<Vec<D>> g_, r_, a_;
};

}  // namespace ryushi
