#pragma once
// What an elastic force model gives the solid's integration (elastic_midpoint.hpp): the
// accelerations at the current state, and, for a model with its own state (the updated form's
// density and deviatoric stress), that state advanced over a substep with the rates of the last
// evaluation. Two models: total_lagrangian_elastic.hpp (the default) and
// updated_lagrangian_elastic.hpp (seed 002's own form). Also the pair terms both share:
// Monaghan's artificial viscosity (seed 002 eqs. 23-24) and the contact with walls and other
// bodies.
#include <cmath>

#include "ecs/io.hpp"
#include "systems/elastic/elastic_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class ElasticModel {
 public:
  virtual ~ElasticModel() = default;
  // Everything evaluate() and advance() read and write: the model's Io (ecs/io.hpp), which they
  // fetch, added to the systems' own.
  virtual void declare(Access& a) const = 0;
  virtual void initialise(World<D>& world) = 0;
  // The accelerations (and the model's rates, stress, density, strain energy for output) at the
  // current positions, velocities and state.
  virtual void evaluate(SystemContext<D>& ctx) = 0;
  // The model's own state over a substep h, with the rates of the last evaluation.
  virtual void advance(SystemContext<D>&, double /*h*/) {}
  // Whether the accelerations in the column are this model's at the current state (the
  // integration's first substep reuses the last step's).
  bool current() const { return current_; }
  void set_current(bool c) { current_ = c; }

 protected:
  bool current_ = false;
};

// Pi_ij (seed 002 eqs. 23-24) for an approaching pair (v_ij . x_ij < 0).
template <int D>
double solid_viscosity(const ElasticParameters<D>& p, double vx, double r2, double c, double rhoi,
                       double rhoj) {
  const double h = p.kernel.h(), mu = h * vx / (r2 + 0.01 * h * h);
  return (-p.alpha * c * mu + p.beta * mu * mu) / (0.5 * (rhoi + rhoj));
}

// Adds the push of walls (unless walls is false) and other bodies on solid particle i (of sound
// speed c) to acc: a stiff spring (c^2 / d)(1 - r/d) along x_ij inside the spacing d, and the
// artificial viscosity.
template <int D, class Kinds, class Bodies, class Positions, class Velocities>
void add_solid_contact(const ElasticParameters<D>& p, const NeighbourList& nl, std::size_t i, double c,
                       double rho0, double rho, const Kinds& kind, const Bodies& body, const Positions& x,
                       const Velocities& v, Vec<D>& acc, bool walls = true) {
  const double d = p.spacing, volume = p.volume();
  for (auto j : nl.of(i)) {
    const bool wall = walls && kind[j] == kWall;
    if (!wall && !(kind[j] == kElastic && body[j] != body[i])) continue;
    const Vec<D> xij = p.domain.displacement(x[i], x[j]);
    const double r2 = xij.squaredNorm();
    if (r2 >= d * d) continue;
    const double r = std::sqrt(r2);
    acc += (c * c / d) * (1.0 - r / d) / r * xij;
    const double vx = (v[i] - v[j]).dot(xij);
    if (vx < 0)
      acc -= rho0 * volume * solid_viscosity(p, vx, r2, c, rho, rho) * p.kernel.grad_factor(r) * xij;
  }
}

}  // namespace ryushi
