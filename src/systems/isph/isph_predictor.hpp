#pragma once
// ISPH predictor (ISPH paper eq. 3): v* = v^n + dt (nu <lap v>_i + g - c . <grad v>_i), then the
// particles move to x* = x^n + dt v* (not in the Eulerian description), where the pressure
// equation and the corrector are evaluated: the projection makes the flow divergence-free at
// the positions the step leads to (at x^n a rigidly rotating patch has div v = 0 exactly and
// its first pressure would vanish).
//   viscous term (eq. 15): the scene's Laplacian over fluid and wall neighbours; a wall
//     neighbour carries v_wall (no-slip) or v_i (slip, no contribution).
//   convective term: only in the Eulerian description (c = v), with the corrected gradient;
//     the ALE description corrects the velocity where the shifting moves a particle.
#include <algorithm>
#include <span>
#include <vector>

#include "ecs/io.hpp"
#include "systems/isph/isph_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/operators/gradient.hpp"
#include "systems/operators/laplacian_choice.hpp"

namespace ryushi {

template <int D>
class IsphPredictor final : public System<D> {
 public:
  explicit IsphPredictor(const IsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "isph_predictor"; }
  // The domain is the parameters' copy (p_.domain): no system writes the resource.
  static constexpr auto io =
      Io{reads(components::kind, components::mass, components::density, neighbours_resource, resources::dt),
         writes(components::position, components::velocity, components::acceleration)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [kind, m, rho, nl, dt, x, v, a] = io.fetch(ctx);
    particle_volumes(m, rho, volume_);
    ParticleView<D> view{std::span<const Vec<D>>(x.data(), x.size()), volume_, nl, p_.kernel, p_.domain};
    const bool eulerian = p_.description == IsphDescription::Eulerian;
    // Eulerian particles never move: their weights depend on nothing that changes until the list
    // is rebuilt (positions fixed; volumes m / rho constant, since no ISPH system writes mass or
    // density), so they are computed once per list (the 3D pipe's predictor: 10x faster).
    const bool cached = eulerian && cache_builds_ == nl.builds && cache_size_ == x.size();
    if (eulerian && !cached) {
      offset_.assign(x.size() + 1, 0);
      for (std::size_t i = 0; i < x.size(); ++i)
        offset_[i + 1] = offset_[i] + (kind[i] == kFluid ? nl.of(i).size() : 0);
      lap_w_.assign(offset_.back(), 0.0);
      grad_w_.assign(offset_.back(), Vec<D>::Zero());
    }
    auto weights = [&](std::size_t i, std::vector<double>& w, std::vector<Vec<D>>& g, Stencil<D>& stencil) {
      stencil.gather(view, i);
      if (p_.nu > 0) {
        laplacian_weights(p_.viscous_laplacian, stencil, w);
        // Explicit diffusion is stable only with non-negative neighbour weights (then the row
        // is a weighted average that cannot overshoot once dt < 1 / (nu sum w)). The corrected
        // and SPH(2) rows at a free surface or a wall corner have negative ones, and a
        // viscosity-dominated flow (1e4 Pa s) blew up at any dt, 1/5 of the viscous limit
        // included: those rows use the standard weights.
        if (p_.viscous_laplacian != LaplacianOrder::Standard &&
            std::any_of(w.begin(), w.end(), [](double wk) { return wk < 0; }))
          laplacian_weights_standard(stencil, w);
      }
      if (eulerian) gradient_weights_corrected(stencil, g);
    };
    // The standard viscous Laplacian of a moving fluid in one pass over the neighbours (the same
    // arithmetic as laplacian_weights_standard on a stencil, without the stencil's arrays): the
    // dam break's predictor at a/d = 100: 3.3 -> 2.8 ms per step over the run to T = 2.5.
    const bool fused = p_.nu > 0 && !eulerian && p_.viscous_laplacian == LaplacianOrder::Standard;
    const double eta2 = 0.01 * p_.kernel.h() * p_.kernel.h();
    // Gather every acceleration from v^n first, then move.
    if (fused)
      for_each_of_kind(kind, kFluid, [&](std::size_t i) {
        Vec<D> lap = Vec<D>::Zero();
        for (auto j : nl.of(i)) {
          if (kind[j] != kFluid && !p_.wall_no_slip) continue;  // slip: v_j = v_i
          const Vec<D> r = view.r(i, j);
          const double len = r.norm(), r2 = len * len;
          lap += volume_[j] * (-2.0 * p_.kernel.grad_factor(len) * r2 / (r2 + eta2)) * (v[j] - v[i]);
        }
        a[i] = p_.gravity + p_.nu * lap;
      });
    else
      for_each_of_kind(kind, kFluid, [&](std::size_t i) {
        thread_local std::vector<double> w;
        thread_local std::vector<Vec<D>> g;
        thread_local Stencil<D> stencil;
        Vec<D> acc = p_.gravity;
        auto nb = nl.of(i);
        std::span<const double> lap_w;
        std::span<const Vec<D>> grad_w;
        if (cached) {
          lap_w = std::span<const double>(lap_w_).subspan(offset_[i], nb.size());
          grad_w = std::span<const Vec<D>>(grad_w_).subspan(offset_[i], nb.size());
        } else if (p_.nu > 0 || eulerian) {
          weights(i, w, g, stencil);
          lap_w = w, grad_w = g;
          if (eulerian) {
            if (p_.nu > 0) std::copy(w.begin(), w.end(), lap_w_.begin() + offset_[i]);
            std::copy(g.begin(), g.end(), grad_w_.begin() + offset_[i]);
          }
        }
        if (p_.nu > 0) {
          Vec<D> lap = Vec<D>::Zero();
          for (std::size_t k = 0; k < nb.size(); ++k) {
            std::size_t j = nb[k];
            if (kind[j] != kFluid && !p_.wall_no_slip) continue;  // slip: v_j = v_i
            lap += lap_w[k] * (v[j] - v[i]);                      // no-slip: the wall's velocity
          }
          acc += p_.nu * lap;
        }
        if (eulerian) {
          Vec<D> convective = Vec<D>::Zero();
          for (std::size_t k = 0; k < nb.size(); ++k) convective += v[i].dot(grad_w[k]) * (v[nb[k]] - v[i]);
          acc -= convective;
        }
        a[i] = acc;
      });
    if (eulerian) cache_builds_ = nl.builds, cache_size_ = x.size();
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      v[i] += dt * a[i];
      if (!eulerian) {
        x[i] += dt * v[i];
        p_.domain.wrap(x[i]);
      }
    });
  }

 private:
  IsphParameters<D> p_;
  std::vector<double> volume_;
  // Eulerian: the weights of each fluid particle's neighbours, per list build.
  std::size_t cache_builds_ = 0, cache_size_ = 0;
  std::vector<std::size_t> offset_;
  std::vector<double> lap_w_;
  std::vector<Vec<D>> grad_w_;
};

}  // namespace ryushi
