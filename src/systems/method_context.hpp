#pragma once
// What a method tells the driver and the systems it runs, whatever the method: its kernel, the
// spacing, domain, gravity and material, and how its forces on a [[solid]] are read. Systems
// registered by name ([[systems]]) are built from it, so one extension runs under WCSPH, MPS
// and every method registered later. The method fills it from the scene (methods/
// method_context.hpp); systems know no scene.
#include <string>

#include "ecs/math.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

// How the `force` probe reads the fluid's force on a [[solid]] body.
enum class SolidForceReading {
  WallLayer,  // the surface pressure and the wall shear on the body's first layer (solid_surface_force.hpp)
  PairReaction,  // the surface pressure, and the reaction to the method's viscous pair forces
                 // (solid_force.hpp)
};

template <int D>
struct MethodContext {
  static constexpr int dimension = D;
  std::string method;                             // the method's registered name (messages)
  Kernel<D> kernel{KernelType::WendlandC2, 1.0};  // the method's kernel (MPS: its weight, h = r_e)
  Domain<D> domain;
  Vec<D> gravity = Vec<D>::Zero();
  double gravity_magnitude = 9.81;  // g of the flow's scales (swe: [swe] gravity, out of the plane), m/s^2
  double spacing = 1;               // initial particle spacing d (MPS: l0), m
  double rho0 = 1000;               // reference density, kg/m^3
  double viscosity = 0;             // dynamic viscosity mu, Pa s
  SolidForceReading solid_force = SolidForceReading::WallLayer;
  // The wall layer's shear as the method's viscous term writes it: nu 2D / (lambda0 n0) for MPS's
  // Laplacian; 0: the Shepard slope of the wall's velocity.
  double wall_layer_viscous = 0;
};

}  // namespace ryushi
