#pragma once
// The method context (systems/method_context.hpp) filled from a scene: the scene's kernel,
// spacing, domain, gravity and material; a method sets how its solid forces are read.
#include "scene/scene.hpp"
#include "systems/method_context.hpp"

namespace ryushi {

template <int D>
Vec<D> scene_vector(const std::vector<double>& v) {
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = v[a];
  return x;
}

template <int D>
Domain<D> scene_domain(const Scene& s) {
  Domain<D> d;
  d.min = scene_vector<D>(s.domain_min);
  d.max = scene_vector<D>(s.domain_max);
  for (int a = 0; a < D; ++a) d.periodic[a] = s.periodic[a];
  return d;
}

// The context of a scene run with `kernel` (each method chooses its kernel).
template <int D>
MethodContext<D> method_context(const Scene& s, const Kernel<D>& kernel) {
  MethodContext<D> c;
  c.method = s.method;
  c.kernel = kernel;
  c.domain = scene_domain<D>(s);
  c.gravity = scene_vector<D>(s.gravity);
  c.gravity_magnitude = s.gravity_magnitude();
  c.spacing = s.spacing;
  c.rho0 = s.density;
  c.viscosity = s.viscosity;
  return c;
}

}  // namespace ryushi
