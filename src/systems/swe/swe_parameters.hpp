#pragma once
// Plain parameters of the shallow-water MPS method (Saigo & Koshizuka, seed 000; docs/swe.md)
// and the columns its systems share. Particles live in the x-y plane (2D); each carries a
// volume V (constant but for splitting), a depth h (SPH sum, eq. 7) and an area A = V / h.
#include <memory>
#include <vector>

#include "ecs/component.hpp"
#include "ecs/math.hpp"
#include "ecs/resources.hpp"
#include "geometry/bed.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> water_volume{"volume"};  // V = A h, m^3
inline constexpr Component<Scalar> depth{"depth"};          // h, m
inline constexpr Component<Scalar> area{"area"};            // A = V / h, m^2
inline constexpr Component<Scalar> bed_elevation{"bed_elevation"};
inline constexpr Component<Scalar> surface_elevation{"surface_elevation"};  // z_s = h + z_b
}  // namespace components

// One straight wall of a container: the line x[axis] = at, the water on the side `inward`
// (+1: x[axis] > at), spanning [lo, hi] along the other axis.
struct MirrorWall {
  int axis = 0;
  double at = 0;
  int inward = 1;
  double lo = 0, hi = 0;
};

struct SweParameters {
  double g = 9.81;              // gravity, m/s^2 (along -z, normal to the plane)
  double manning = 0;           // n_M, s/m^(1/3)
  double alpha_e = 1.3;         // r_e = alpha_e sqrt(A_max) (eq. 9)
  double cfl = 0.5;             // eq. 13
  double rho0 = 1000;           // water density (mass = rho0 V, pressure = rho0 g h)
  double area0 = 0;             // A0 = d^2, the initial particle area
  double dry_depth = 1e-6;      // friction's hydraulic radius is at least this (m)
  bool edge_correction = true;  // momentum = mps only
  // The pressure term of the momentum equation (docs/swe.md, "Momentum"): mps, eq. 6's gradient of
  // the surface with the faded dry-side term; sph, the gradient of the depth sum of eq. 7 itself.
  enum class Momentum { Mps, Sph } momentum = Momentum::Mps;
  bool slip = true;  // wall ghosts: tangential velocity kept (slip) or reversed (no-slip)
  std::vector<MirrorWall> walls;
  std::shared_ptr<const Bed> bed;
};

// r_e of this step (eq. 9) and the ghost images of the particles next to walls (section 2(5)).
inline constexpr Resource<double> swe_influence_radius_resource{"swe_influence_radius"};

}  // namespace ryushi
