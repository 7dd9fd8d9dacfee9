#pragma once
// Surface tension on the free surface (corrected ALE-ISPH paper, eqs. 24-27), after the method's
// free-surface detection and before its pressure rows:
//   lambda_i   the smallest eigenvalue of M_i = L_i^-1 (about 1 inside, 0.5 on a flat surface)
//   N_i        the outward unit normal -N*_i / |N*_i|, N*_i = sum_j V_j (lambda_j - lambda_i) L_i gW_ij
//              over fluid neighbours (eqs. 24-25; lambda falls towards the surface, so its
//              gradient points in); or, with normal = "kernel_sum", the detection's normal (the
//              corrected gradient of the kernel sum)
//   contact    at a surface particle whose support reaches a wall: N = cos(theta) n_w + sin(theta) t_w,
//              n_w the nearest wall particle's normal into the fluid, t_w the part of N along the
//              wall, normalised (it points away from the liquid): the paper's Fig. 9
//   kappa_i    div N / 2 on the outline (the flagged particles that Marrone's test confirms):
//              fit (default) from a quadratic fitted to the outline's positions
//              (curvature_fit.hpp), tangential from the normals' divergence along the surface
//              (tangential_divergence.hpp), both at the surface half a spacing outside the
//              particles; or paper: c sum_{j on the outline} V_j (N_j - N_i) . L_i gW_ij (eq. 27,
//              c = 0.41 in place of the 1/2, tuned to that truncated sum in 3D). Other flagged
//              particles and unresolved stencils continue their neighbours' kappa; |kappa| is
//              clamped to (D - 1) / (2 min_radius d)
//   p_s        2 sigma kappa_i: the free-surface row's Dirichlet value (surface_pressure)
//   force      f_i = -sigma kappa_i delta N_i (eq. 26), delta = delta_coefficient / d (the paper's
//              0.1 / d, not a smoothed Dirac delta), added to v* and x* as the predictor's
//              external force: v += dt f / rho, x += dt^2 f / rho (off by default: docs/surface_tension.md)
// and a capillary step limit dt <= C sqrt(rho0 d^3 / (2 pi sigma)) (Brackbill et al. 1992) for
// the driver (resources::dt_limit). Interior particles carry kappa = 0 and p_s = 0.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "ecs/io.hpp"
#include "systems/free_surface/free_surface_detection.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/method_context.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/operators/renormalisation.hpp"
#include "systems/surface_tension/curvature_fit.hpp"
#include "systems/surface_tension/tangential_divergence.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> curvature{"curvature"};            // kappa of eq. 27, 1/m
inline constexpr Component<Vector> tension_normal{"tension_normal"};  // N_i, unit, out of the liquid
}  // namespace components

// fit: kappa = div N / 2 of a quadratic fitted to the surface positions (curvature_fit.hpp);
// tangential: div_s N / 2 of the normals, corrected on the surface stencil
// (tangential_divergence.hpp); paper: eq. 27 with its factor.
enum class SurfaceCurvature { Fit, Tangential, Paper };

struct SurfaceTensionParameters {
  double sigma = 0.07;  // N/m
  SurfaceCurvature curvature = SurfaceCurvature::Fit;
  double curvature_factor = 0.41;       // c of eq. 27 (0.5: kappa = div N / 2)
  double delta_coefficient = 0;         // delta d of eq. 26 (the paper: 0.1)
  bool eigenvalue_normal = true;        // eqs. 24-25, else the detection's normal
  double contact_angle = std::nan("");  // degrees through the liquid; NaN: no wall correction
  double capillary_step = 0.5;          // C of the capillary step limit
  double min_radius = 3;                // the smallest radius kappa is clamped to, in spacings
  bool viscous_normal_stress = true;    // p_s += 2 mu N . grad(v) N
};

template <int D>
class SurfaceTension : public System<D> {
 public:
  SurfaceTension(const SurfaceTensionParameters& p, const MethodContext<D>& context)
      : p_(p), context_(context), contact_(std::isfinite(p.contact_angle)) {
    const double theta = p.contact_angle * std::numbers::pi / 180;
    cos_theta_ = std::cos(theta), sin_theta_ = std::sin(theta);
  }
  std::string name() const override { return "surface_tension"; }
  std::string place_after() const override { return "free_surface_detection"; }
  auto io() const {
    return Io{reads(components::mass, components::density, components::kind, components::free_surface,
                    components::surface_normal, neighbours_resource, resources::dt),
              writes(components::position, components::velocity, components::surface_pressure,
                     components::curvature, components::tension_normal),
              optional(contact_, reads(components::wall_normal))};
  }
  Access access() const override { return io().access(); }
  void initialise(World<D>&, Resources& res) override {
    const double d = context_.spacing;
    const double limit =
        p_.capillary_step * std::sqrt(context_.rho0 * d * d * d / (2 * std::numbers::pi * p_.sigma));
    const bool had = res.has(resources::dt_limit.name);
    double& dt_limit = res.ensure(resources::dt_limit);
    dt_limit = had ? std::min(dt_limit, limit) : limit;
  }
  void run(SystemContext<D>& ctx) override {
    auto [m, rho, kind, surface, detected_normal, nl, dt, x, v, surface_pressure, kappa, normal,
          wall_normal] = io().fetch(ctx);
    particle_volumes(m, rho, volume_);
    ParticleView<D> view{std::span<const Vec<D>>(x.data(), x.size()), volume_, nl, context_.kernel,
                         context_.domain};
    lambda_.assign(x.size(), 1.0);
    const double delta = p_.delta_coefficient / context_.spacing;
    const double kappa_limit = 0.5 * (D - 1) / (p_.min_radius * context_.spacing);
    if (p_.eigenvalue_normal)
      for_each_of_kind(kind, kFluid, [&](std::size_t i) {
        if (!near_surface(nl, surface, i))
          return;  // the normal needs lambda on surface rows' neighbours only
        lambda_[i] = smallest_moment_eigenvalue(moment_matrix(view, i));
      });
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      normal[i] =
          surface[i] ? surface_unit_normal(view, kind, detected_normal, wall_normal, i) : Vec<D>::Zero();
    });

    // The curvature is taken on the surface that Marrone's test confirms (the outline): where a
    // strained lattice reads det M_i < 0.6, the I-SPH(2) rule flags particles layers deep inside
    // (the tips of a square drop swinging into a diamond), and their curvature from each other's
    // positions was noise of +-1/d that blew the drop apart. They keep their rows' flags and take
    // the outline's curvature by continuation (fill_unresolved).
    outline_.assign(x.size(), 0);
    const FreeSurfaceParameters marrone;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      outline_[i] = surface[i] && detect_free_surface(view, i, FreeSurfaceRule::Marrone, marrone).surface;
    });
    auto on_outline = [&](std::size_t j) { return kind[j] == kFluid && outline_[j]; };
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      kappa[i] = 0, surface_pressure[i] = 0;
      if (surface[i]) kappa[i] = outline_[i] ? curvature(view, on_outline, normal, i) : kUnresolved;
    });
    fill_unresolved(view, kind, surface, kappa);
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      if (!surface[i]) return;
      // No surface the kernel resolves bends on a radius below a few spacings: a larger |kappa| is
      // a particle-scale feature (a fold, a lattice step) whose Laplace pressure is not resolved.
      kappa[i] = std::clamp(kappa[i], -kappa_limit, kappa_limit);
      // The free surface's normal stress balance, p - 2 mu N . grad(v) N = sigma div N: without the
      // viscous part an irrotational oscillation (where mu lap v = 0 inside) loses its energy only
      // by numerical dissipation (a mode-2 drop decayed at 44% of 4 nu / R^2).
      const double stretch = p_.viscous_normal_stress ? normal_stretch(view, v, normal[i], i) : 0.0;
      surface_pressure[i] = 2 * p_.sigma * kappa[i] + 2 * context_.viscosity * stretch;
    });
    if (p_.delta_coefficient > 0)  // the paper's surface force (off by default)
      for_each_of_kind(kind, kFluid, [&](std::size_t i) {
        if (!surface[i]) return;
        const Vec<D> a = (-p_.sigma * kappa[i] * delta / rho[i]) * normal[i];
        v[i] += dt * a;
        x[i] += dt * dt * a;
      });
  }

 private:
  // N . grad(v) N at particle i: the corrected velocity gradient over its neighbours.
  double normal_stretch(const ParticleView<D>& view, std::span<const Vec<D>> v, const Vec<D>& n,
                        std::size_t i) const {
    const Stencil<D>& s = gathered_stencil(view, i);
    const Mat<D> L = renormalisation(s);
    double stretch = 0;
    for (std::size_t k = 0; k < s.size(); ++k)
      stretch += s.volume[k] * n.dot(v[s.neighbours[k]] - v[i]) * n.dot(L * s.grad_w(k));
    return stretch;
  }

  // kappa = div N / 2 at outline particle i by the scene's model; kUnresolved where its surface
  // neighbours do not determine it.
  template <class OnOutline>
  double curvature(const ParticleView<D>& view, OnOutline on_outline, std::span<const Vec<D>> normal,
                   std::size_t i) const {
    const Stencil<D>& s = gathered_stencil(view, i);
    // The fit and the tangential divergence bend with the surface particles' centres; the free
    // surface lies half a spacing outside them (as the extrapolated surface rows take it), and a
    // surface parallel to it at distance d/2 has the mean curvature H / (1 + H d/2), H = div / (D - 1).
    auto at_surface = [&](std::optional<double> div) {
      if (!div) return kUnresolved;
      const double mean = *div / (D - 1);
      return 0.5 * *div / (1 + 0.5 * context_.spacing * mean);
    };
    if (p_.curvature == SurfaceCurvature::Fit)
      return at_surface(fitted_normal_divergence(
          s, on_outline, [&](double r) { return context_.kernel.w(r); }, normal[i], context_.spacing));
    if (p_.curvature == SurfaceCurvature::Tangential)
      return at_surface(tangential_divergence(s, on_outline, normal, normal[i]));
    const Mat<D> L = renormalisation(s);
    double div = 0;
    for (std::size_t k = 0; k < s.size(); ++k)
      if (on_outline(s.neighbours[k]))
        div += s.volume[k] * (normal[s.neighbours[k]] - normal[i]).dot(L * s.grad_w(k));
    return p_.curvature_factor * div;
  }

  // Surface particles without a curvature of their own (off the outline, or a stencil that does
  // not determine it) continue their surface neighbours' mean, a few rings deep; what is left
  // (spray) takes the mean of the whole outline. 0 there gave a particle sticking out of a drop a
  // lower Laplace pressure than the liquid behind it, which pushed such particles off one by one.
  void fill_unresolved(const ParticleView<D>& view, std::span<const std::int32_t> kind,
                       std::span<const std::int32_t> surface, std::span<double> kappa) {
    for (int ring = 0; ring < 4; ++ring) {
      smoothed_.assign(kappa.begin(), kappa.end());
      std::atomic<bool> left{false};
      for_each_of_kind(kind, kFluid, [&](std::size_t i) {
        if (!surface[i] || std::isfinite(kappa[i])) return;
        double sum = 0;
        int count = 0;
        for (auto j : view.neighbours.of(i))
          if (kind[j] == kFluid && surface[j] && std::isfinite(kappa[j])) sum += kappa[j], ++count;
        if (count > 0)
          smoothed_[i] = sum / count;
        else
          left = true;
      });
      std::copy(smoothed_.begin(), smoothed_.end(), kappa.begin());
      if (!left) return;
    }
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < kappa.size(); ++i)
      if (outline_[i] && std::isfinite(kappa[i])) sum += kappa[i], ++count;
    for (std::size_t i = 0; i < kappa.size(); ++i)
      if (surface[i] && !std::isfinite(kappa[i])) kappa[i] = count > 0 ? sum / double(count) : 0.0;
  }

  static bool near_surface(const NeighbourList& nl, std::span<const std::int32_t> surface, std::size_t i) {
    if (surface[i]) return true;
    for (auto j : nl.of(i))
      if (surface[j]) return true;
    return false;
  }

  Vec<D> surface_unit_normal(const ParticleView<D>& view, std::span<const std::int32_t> kind,
                             std::span<const Vec<D>> detected, std::span<const Vec<D>> wall_normal,
                             std::size_t i) const {
    const Stencil<D>& s = gathered_stencil(view, i);
    Vec<D> n = detected[i];
    if (p_.eigenvalue_normal) {
      const Mat<D> L = renormalisation(s);
      Vec<D> g = Vec<D>::Zero();
      for (std::size_t k = 0; k < s.size(); ++k) {
        const auto j = s.neighbours[k];
        if (kind[j] == kFluid) g += s.volume[k] * (lambda_[j] - lambda_[i]) * (L * s.grad_w(k));
      }
      // Oriented as the detection's normal: in a notch of the surface the gradient of lambda can
      // point out of the liquid, and a flipped normal flips the curvature's sign.
      if (g.norm() > 0) n = (g.dot(detected[i]) > 0 ? 1.0 : -1.0) * g / g.norm();
    }
    if (!contact_) return n;
    // The nearest wall particle in the support sets the wall's direction.
    double nearest = INFINITY;
    Vec<D> into_fluid = Vec<D>::Zero();
    for (std::size_t k = 0; k < s.size(); ++k)
      if (kind[s.neighbours[k]] == kWall && s.len[k] < nearest)
        nearest = s.len[k], into_fluid = -wall_normal[s.neighbours[k]];
    if (!std::isfinite(nearest)) return n;
    Vec<D> along = n - n.dot(into_fluid) * into_fluid;
    if (along.norm() < 1e-6) return n;  // the surface lies flat on the wall: no direction to turn to
    return cos_theta_ * into_fluid + sin_theta_ * along / along.norm();
  }

  static constexpr double kUnresolved = std::numeric_limits<double>::quiet_NaN();
  SurfaceTensionParameters p_;
  MethodContext<D> context_;
  bool contact_;
  double cos_theta_ = 1, sin_theta_ = 0;
  std::vector<double> volume_, lambda_, smoothed_;
  std::vector<std::uint8_t> outline_;
};

}  // namespace ryushi
