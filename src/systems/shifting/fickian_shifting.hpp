#pragma once
// Fickian particle shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231; the
// velocity-scaled diffusion coefficient of Skillen, Lind, Stansby & Rogers 2013): particles
// diffuse down the gradient of their concentration C_i = sum_j V_j W_ij,
//   dr_i = -A h |v_i| dt grad C_i,
//   grad C_i = sum_j V_j (1 + R (W_ij / W(d))^4) gW_ij          (Lind 2012 eq. 17: the R term
//                                                                pushes clumped pairs apart),
// walls included (they repel the fluid that comes near them). The shift scales with the
// distance the particle travels in the step, so it keeps up with the deformation of a fast
// flow: the density-based model's C_shift h per step does not (docs/isph.md: the dam break's
// collapsing column turns into columns of particles 0.4 d apart vertically and 2.5 d apart
// horizontally at C_shift = 0.005). On the free surface only the tangential part is kept (a
// particle there has no neighbours outside, and grad C would push it out); the shift is capped at
// `max_shift` d. Same interface as the density model: the velocity is carried to the new place.
//
// The optimised variant (OPS, Khayyer, Gotoh & Shimizu 2017, J. Comput. Phys. 332, as the ISPH
// paper compares it in its Fig. 5) keeps only the tangential part in the whole free-surface
// region, not only on the flagged particles: a particle with a surface particle inside its
// support (the "vicinity") has a support cut by the surface too, and the normal part of its
// grad C would still push it outwards, thinning the layer under the surface. The normal is the
// one free-surface detection writes for every fluid particle, n_i = -L_i sum_j V_j gW_ij / |.|
// (the corrected gradient of the kernel sum); in the vicinity it is the surface's normal.
#include <cmath>
#include <vector>

#include "ecs/io.hpp"
#include "systems/free_surface/free_surface_detection.hpp"
#include "systems/isph/isph_parameters.hpp"  // components::wall_normal
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/shifting/density_shifting.hpp"  // components::shift
#include "systems/shifting/shift_velocity.hpp"

namespace ryushi {

template <int D>
struct FickianShiftingParameters {
  Kernel<D> kernel{KernelType::CubicSpline, 1.0};
  Domain<D> domain;
  double spacing = 1;
  double coefficient = 2.0;       // A (Skillen et al. 2013 recommend 1-6)
  double clumping = 0.2;          // R of the anti-clumping term, exponent 4 (Lind 2012)
  double max_shift = 0.2;         // cap, in spacings
  bool complete_walls = false;    // one wall layer with normals (ISPH): see the loop below
  bool surface_vicinity = false;  // optimised (OPS): tangential only within a support of the surface
};

template <int D>
class FickianShifting final : public System<D> {
 public:
  explicit FickianShifting(const FickianShiftingParameters<D>& p)
      : p_(p), w_spacing_(p.kernel.w(p.spacing)) {}
  std::string name() const override { return "particle_shifting"; }
  auto io() const {
    return Io{reads(components::mass, components::density, components::kind, components::free_surface,
                    components::surface_normal, neighbours_resource, resources::dt),
              writes(components::position, components::velocity, components::shift),
              optional(p_.complete_walls, reads(components::wall_normal))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    auto [m, density, kind, surface, normal, nl, dt, x, v, shift, wall_normal] = io().fetch(ctx);
    const bool complete_walls = p_.complete_walls;
    particle_volumes(m, density, volume_);
    dv_.resize(m.size());
    ParticleView<D> view{std::span<const Vec<D>>(x.data(), x.size()), volume_, nl, p_.kernel, p_.domain};
    const double h = p_.kernel.h(), cap = p_.max_shift * p_.spacing;
    // Gather every shift and velocity change from the unshifted state first, then apply.
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      thread_local std::vector<Vec<D>> g;
      const Stencil<D>& stencil = gathered_stencil(view, i);  // also for the velocity change below
      Vec<D> grad_c = Vec<D>::Zero();
      bool tangential_only = surface[i] != 0;
      auto add = [&](const Vec<D>& r, double len, double factor, double volume) {
        if (len >= p_.kernel.support() || len == 0) return;
        double ratio = p_.kernel.w(len) / w_spacing_;
        grad_c -= volume * (1 + p_.clumping * ratio * ratio * ratio * ratio) * factor * r;  // gW = -F r
      };
      for (std::size_t k = 0; k < stencil.size(); ++k) {
        add(stencil.r[k], stencil.len[k], stencil.factor[k], stencil.volume[k]);
        // One wall layer leaves the support short behind the wall: C falls towards it and -grad C
        // would push the fluid into the wall. The layers it lacks are completed on the fly, as
        // copies of the wall particle one and two spacings further out along its normal.
        const std::size_t j = stencil.neighbours[k];
        if (p_.surface_vicinity && kind[j] == kFluid && surface[j] && stencil.len[k] < p_.kernel.support())
          tangential_only = true;
        if (complete_walls && kind[j] == kWall)
          for (int layer = 1; layer <= 2; ++layer) {
            const Vec<D> r = stencil.r[k] + layer * p_.spacing * wall_normal[j];
            const double len = r.norm();
            add(r, len, p_.kernel.grad_factor(len), stencil.volume[k]);
          }
      }
      Vec<D> dr = -p_.coefficient * h * v[i].norm() * dt * grad_c;
      if (tangential_only) dr -= dr.dot(normal[i]) * normal[i];
      double len = dr.norm();
      if (len > cap) dr *= cap / len;
      shift[i] = dr;
      dv_[i] = shifted_velocity_change(stencil, std::span<const Vec<D>>(v.data(), v.size()), dr, g);
    });
    apply_shifts<D>(kind, p_.domain, shift, dv_, x, v);
  }

 private:
  FickianShiftingParameters<D> p_;
  double w_spacing_;
  std::vector<double> volume_;
  std::vector<Vec<D>> dv_;
};

}  // namespace ryushi
