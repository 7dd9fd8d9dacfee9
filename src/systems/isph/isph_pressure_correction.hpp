#pragma once
// ISPH corrector (ISPH paper eq. 4) at the predicted positions:
//   v^{n+1} = v* - dt/rho0 <grad p>_i,   x^{n+1} = x* + dt (v^{n+1} - v*)   (x fixed if Eulerian)
// <grad p>: corrected difference form L_i sum_j V_j (p_j - p_i) gW_ij (eq. 9), or the symmetric
// form sum_j V_j (p_i + p_j) gW_ij (I-SPH(2) eq. 11: pairwise antisymmetric, momentum-conserving,
// not consistent on a cut support), or the hybrid of the two: symmetric where the free surface
// cuts the support (det M_i < symmetric_gradient_det and a free-surface particle in it, i
// included), corrected everywhere else.
// Why the hybrid: the symmetric form is the consistent one plus 2 p_i sum_j V_j gW_ij, a push down
// the gradient of the particle density that grows with the absolute pressure. It keeps spray and
// the run-up sheet from clumping and a returning wave out of the single wall layer (with the
// corrected form alone the a/d = 20 dam break fails at t = 1.25-1.42 s), but inside a deep column
// it drives a pressure mode that grows with the resolution (a/d = 200: -12 kPa at t = 0.09 s
// against rho g depth 4.5 kPa; docs/isph.md). Near the surface the pressure is small; the
// interior, where it is large, takes the consistent form. Why the surface and not det M_i alone:
// a disordered interior reads det M_i < 0.8 too (91 of 16,374 particles of the a/d = 200 column
// at t = 0.30 s, 47 of 3,947 at a/d = 100), and there the push, switched on and off particle by
// particle under the column's full pressure, fed a period-two pressure mode that grew 1.6-1.8x per
// step and blew the a/d = 200 dam break up at t = 0.37 s (docs/isph.md, "The column's pressure
// bursts"). The wall's corner is no reason either: with the symmetric form kept there too, the
// mode grew sooner.
// Free-surface particles carry p = 0 and wall particles their solved pressure. The gradient is
// kept in `pressure_gradient` (an output field).
#include <vector>

#include "ecs/io.hpp"
#include "systems/free_surface/free_surface_detection.hpp"
#include "systems/isph/isph_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/mps/mps_parameters.hpp"  // components::pressure_gradient
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/operators/gradient.hpp"

namespace ryushi {

template <int D>
class IsphPressureCorrection final : public System<D> {
 public:
  explicit IsphPressureCorrection(const IsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "isph_pressure_correction"; }
  static constexpr auto io = Io{
      reads(components::pressure, components::kind, components::mass, components::density,
            components::wall_normal, components::free_surface, pressure_neighbours_resource, resources::dt),
      writes(components::position, components::velocity, components::pressure_gradient)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    // nl: the pressure rows' neighbours, without dry walls.
    auto [p, kind, m, rho, normal, surface, nl, dt, x, v, grad] = io.fetch(ctx);
    particle_volumes(m, rho, volume_);
    ParticleView<D> view{std::span<const Vec<D>>(x.data(), x.size()), volume_, nl, p_.kernel, p_.domain};
    auto surface_in_support = [&](std::size_t i) {
      if (surface[i]) return true;
      for (auto j : nl.of(i))
        if (kind[j] == kFluid && surface[j]) return true;
      return false;
    };
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      if (p_.pressure_gradient == PressureGradientForm::Corrected) {
        grad[i] = gradient_corrected(view, p, i);
        return;
      }
      if (p_.pressure_gradient == PressureGradientForm::Hybrid) {
        if (!surface_in_support(i)) {
          grad[i] = gradient_corrected(view, p, i);
          return;
        }
        if (auto g = gradient_corrected_where(view, p, i, p_.symmetric_gradient_det)) {
          grad[i] = *g;
          return;
        }
      }
      grad[i] = gradient_symmetric(view, p, i);
      // The symmetric form pushes a particle away from every neighbour, so a support cut by the
      // one wall layer pushes it into the wall, the harder the higher its pressure: in the
      // corner of the dam break at a/d = 100 the pressure grew to 47 kPa in 0.04 s and the run
      // failed at t = 0.11 s. The wall's two missing layers are completed, as copies of each
      // wall particle one and two spacings out along its normal, with the hydrostatic pressure
      // p_j + rho0 (g . n_j) k d (with wall_rows = "adami" they exist).
      for (auto j : nl.of(i)) {
        if (kind[j] != kWall || p_.wall_adami) continue;  // adami: the layers are there
        const Vec<D> r = view.r(i, j);
        for (int layer = 1; layer <= 2; ++layer) {
          const Vec<D> offset = layer * p_.spacing * normal[j];
          const double p_copy = p[j] + p_.rho0 * p_.gravity.dot(offset);
          grad[i] += volume_[j] * (p[i] + p_copy) * view.grad_w(r + offset);
        }
      }
    });
    const double scale = dt / p_.rho0;
    const bool eulerian = p_.description == IsphDescription::Eulerian;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> dv = -scale * grad[i];
      v[i] += dv;
      if (!eulerian) {
        x[i] += dt * dv;
        p_.domain.wrap(x[i]);
      }
    });
  }

 private:
  IsphParameters<D> p_;
  std::vector<double> volume_;
};

}  // namespace ryushi
