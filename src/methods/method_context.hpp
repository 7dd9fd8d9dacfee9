#pragma once
// What a method tells the driver and the systems it runs, whatever the method: the scene's
// kernel, spacing, domain, gravity and material. Systems registered by name ([[systems]]) are
// built from it, so one extension runs under WCSPH, MPS and every method registered later.
#include <string>

#include "ecs/math.hpp"
#include "scene/scene.hpp"
#include "systems/kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
struct MethodContext {
  static constexpr int dimension = D;
  std::string method;                              // [method] name
  Kernel<D> kernel{KernelType::WendlandC2, 1.0};   // the method's kernel (MPS: its weight, h = r_e)
  Domain<D> domain;
  Vec<D> gravity = Vec<D>::Zero();
  double spacing = 1;    // initial particle spacing d (MPS: l0), m
  double rho0 = 1000;    // reference density, kg/m^3
  double viscosity = 0;  // dynamic viscosity mu, Pa s
};

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
  c.spacing = s.spacing;
  c.rho0 = s.density;
  c.viscosity = s.viscosity;
  return c;
}

}  // namespace ryushi
