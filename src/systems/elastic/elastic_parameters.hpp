#pragma once
// Linear-elastic solid bodies in WCSPH (seed 002 eqs. 1-8 and 22-28; Gray, Monaghan & Swift
// 2001): the columns of a scene with [[elastic]] bodies and the constants of their systems.
//
// An elastic particle (kind kElastic) is two things. To the fluid it is a wall particle that
// moves: `density`, `pressure` and `wall_velocity` hold the fluid-side values Adami's wall system
// gives it, and `mass` is the fluid's rho0 d^D, so every fluid system treats it as it treats a
// wall. Its own state is its rest position and the solid columns below
// (total_lagrangian_elastic.hpp).
#include <cstdint>

#include "ecs/component.hpp"
#include "ecs/resources.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> solid_density{"solid_density"};            // rho0 / J
inline constexpr Component<Scalar> solid_pressure{"solid_pressure"};          // -tr(sigma) / dim
inline constexpr Component<Scalar> solid_rest_density{"solid_rest_density"};  // rho0 of its body
inline constexpr Component<Scalar> bulk_modulus{"bulk_modulus"};              // K, Pa
inline constexpr Component<Scalar> shear_modulus{"shear_modulus"};            // G, Pa
inline constexpr Component<Scalar> strain_energy{"strain_energy"};            // the particle's, J (J/m in 2D)
inline constexpr Component<Tensor> stress{"stress"};                          // Cauchy sigma (output)
inline constexpr Component<Vector> fluid_force{"fluid_force"};  // the fluid's force / the solid mass
inline constexpr Component<Vector> rest_position{"rest_position"};
inline constexpr Component<Vector> displacement{"displacement"};  // x - rest position (output)
inline constexpr Component<Flags> clamped{"clamped"};             // 1: held in place
inline constexpr Component<Flags> elastic_body{"elastic_body"};   // the [[elastic]] index (-1: none)
}  // namespace components

// The solid substeps of the current step (elastic_midpoint.hpp): written by the first stage,
// read by the final kick.
inline constexpr Resource<int> elastic_substeps_resource{"elastic_substeps"};

template <int D>
struct ElasticParameters {
  Kernel<D> kernel{KernelType::WendlandC2, 1.0};
  Domain<D> domain;
  Vec<D> gravity = Vec<D>::Zero();
  double spacing = 1;              // d: each solid particle's volume is d^D
  double alpha = 1.0, beta = 1.0;  // artificial viscosity A, B (seed 002: A = B = 1)
  double artificial_stress = 0.3;  // eps of the updated form's artificial stress (seed 002 eq. 26)
  bool seed_walls = false;         // updated form: walls by seed 002's eq. 28, not contact springs
  double max_sound_speed = 0;      // sqrt((K + 4G/3)/rho0), the largest body's (time step)
  bool fluid = false;              // the fluid pushes on the solid (fluid_force)
  bool contacts = true;            // walls or other bodies to touch (else no contact search)
  // The solid's own step limit (cfl h / c_s) and the most substeps it may take in one step of
  // the fluid ([method] solid_substeps; 1: the step itself keeps the solid's limit).
  double substep_limit = 0;
  int max_substeps = 1;
  double volume() const {
    double v = 1;
    for (int a = 0; a < D; ++a) v *= spacing;
    return v;
  }
};

}  // namespace ryushi
