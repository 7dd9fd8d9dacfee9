#pragma once
// The elastic solid's time integration inside the two stages of the fluid's midpoint step:
// velocity Verlet, which is symplectic (an undamped elastic body keeps its energy; the midpoint
// rule's amplification |1 + i w dt - (w dt)^2/2| > 1 makes every undamped oscillation grow,
// measured: an oscillating plate without artificial viscosity blew up within 0.15 s), in m
// substeps of length dt_s = dt / m:
//   first stage (ElasticSubsteps), with a^n the forces at x^n (the previous step's last):
//     m - 1 whole substeps  v += dt_s/2 a, x += dt_s v, q += dt_s q', a = a(x, v, q), v += dt_s/2 a,
//     then the last one's   v += dt_s/2 a, x += dt_s v, q += dt_s q'     (x^{n+1})
//   (q: the force model's own state, if it has one: the updated form's density and deviatoric
//   stress, advanced with their rates at the drifted positions and half-step velocities)
//   second stage (ElasticForces, then ElasticCorrector), with the fluid at t^{n+1/2}:
//     a = a(x^{n+1}, v, q),  v^{n+1} = v + dt_s/2 a + dt f
// Velocity Verlet evaluates the forces once per substep: a step's first substep starts from the
// forces its predecessor's second stage computed at the same positions (only the artificial
// viscosity's velocities differ from a fresh evaluation: v^{n-1/2} for v^n, as velocity Verlet
// takes velocity-dependent forces; without it the results are those of evaluating twice).
// m = 1 unless the scene allows more ([method] solid_substeps = N): then the step is bounded by
// N times the solid's wave limit instead of once, and the solid takes ceil(dt / its limit)
// substeps, at most N: a stiff body in slow water no longer sets the water's step.
// The second stage therefore sees the solid at t^{n+1} where the fluid is at t^{n+1/2}. The
// fluid's push f (force / mass, fluid_on_solid.hpp) enters once, from the second stage, times dt:
// exactly the impulse the midpoint fluid takes from the same pairs (dt times its second-stage
// force), so the momentum they exchange balances to round-off (with f in both kicks it missed by
// 2e-4 of the total in a water-on-block impact).
// Clamped particles keep their place and zero velocity. The step ends with the displacement from
// the rest position (output). The forces, stress and density are the force model's
// (elastic_model.hpp: total_lagrangian_elastic.hpp or updated_lagrangian_elastic.hpp).
#include <algorithm>
#include <cmath>
#include <memory>

#include "ecs/io.hpp"
#include "systems/elastic/elastic_model.hpp"
#include "systems/elastic/elastic_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
class ElasticSubsteps final : public System<D> {
 public:
  ElasticSubsteps(std::shared_ptr<ElasticModel<D>> model, const ElasticParameters<D>& p)
      : model_(std::move(model)), p_(p) {}
  std::string name() const override { return "elastic_substeps"; }
  // The integration's own list; the model's (evaluate, advance) joins it.
  static constexpr auto io =
      Io{reads(components::kind, components::clamped, components::acceleration, resources::dt,
               domain_resource<D>),
         writes(components::position, components::velocity, elastic_substeps_resource)};
  Access access() const override {
    Access a = io.access();
    model_->declare(a);
    return a;
  }
  void initialise(World<D>& world, Resources& res) override {
    model_->initialise(world);
    res.ensure(elastic_substeps_resource) = 1;
  }
  void run(SystemContext<D>& ctx) override {
    auto [kind, clamped, a, dt, domain, x, v, substeps] = io.fetch(ctx);
    int m = 1;
    if (p_.max_substeps > 1 && p_.substep_limit > 0)
      m = std::clamp(static_cast<int>(std::ceil(dt / p_.substep_limit - 1e-9)), 1, p_.max_substeps);
    substeps = m;
    const double h = dt / m;
    auto kick = [&] {
      for_each_of_kind(kind, kElastic, [&](std::size_t i) {
        if (!clamped[i]) v[i] += 0.5 * h * a[i];
      });
    };
    if (!model_->current()) model_->evaluate(ctx);
    for (int s = 0; s < m; ++s) {
      if (s > 0) {
        model_->evaluate(ctx);
        kick();
      }
      kick();
      for_each_of_kind(kind, kElastic, [&](std::size_t i) {
        if (clamped[i]) return;
        x[i] += h * v[i];
        if (domain.any_periodic()) domain.wrap(x[i]);
      });
      model_->advance(ctx, h);
    }
    model_->set_current(false);
  }
  // Between steps the forces in the column are those at the positions (the last second stage's).
  std::vector<double> checkpoint_state(const World<D>&, const Resources&) const override {
    return {model_->current() ? 1.0 : 0.0};
  }
  void restore_state(const World<D>&, Resources&, std::span<const double> state) override {
    if (state.size() == 1) model_->set_current(state[0] == 1.0);
  }

 private:
  std::shared_ptr<ElasticModel<D>> model_;
  ElasticParameters<D> p_;
};

// The forces at x^{n+1}, for the last half kick (and the next step's first substep).
template <int D>
class ElasticForces final : public System<D> {
 public:
  explicit ElasticForces(std::shared_ptr<ElasticModel<D>> model) : model_(std::move(model)) {}
  std::string name() const override { return "elastic_forces"; }
  Access access() const override {
    Access a;
    model_->declare(a);
    return a;
  }
  void run(SystemContext<D>& ctx) override { model_->evaluate(ctx); }

 private:
  std::shared_ptr<ElasticModel<D>> model_;
};

template <int D>
class ElasticCorrector final : public System<D> {
 public:
  explicit ElasticCorrector(bool fluid) : fluid_(fluid) {}
  std::string name() const override { return "elastic_kick"; }
  auto io() const {
    return Io{reads(components::acceleration, components::kind, components::clamped,
                    components::rest_position, resources::dt, elastic_substeps_resource, domain_resource<D>),
              writes(components::velocity, components::displacement, components::position),
              optional(fluid_, reads(components::fluid_force))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    auto [a, kind, clamped, rest, dt, substeps, domain, v, u, x, f] = io().fetch(ctx);
    const double h = dt / substeps;
    for_each_of_kind(kind, kElastic, [&](std::size_t i) {
      if (!clamped[i]) v[i] += 0.5 * h * a[i] + (f.empty() ? Vec<D>::Zero() : Vec<D>(dt * f[i]));
      u[i] = domain.displacement(x[i], rest[i]);
    });
  }

 private:
  bool fluid_;
};

}  // namespace ryushi
