#pragma once
// Constants of an ISPH run (Morikawa, Tsuji & Asai, "Corrected ALE-ISPH with novel Neumann
// boundary condition and density-based particle shifting technique", seed 000), fixed at scene
// load, and the columns only ISPH uses.
#include <cmath>
#include <vector>

#include "ecs/component.hpp"
#include "ecs/math.hpp"
#include "kernels/kernel.hpp"
#include "systems/isph/compression_density.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/operators/laplacian_choice.hpp"

namespace ryushi {

namespace components {
// A fluid particle's Dirichlet pressure ([[fixed_pressure]], Eulerian channels); NaN where the
// pressure is solved for. Only present when the scene has such boxes.
inline constexpr Component<Scalar> fixed_pressure{"fixed_pressure"};
}  // namespace components

// The pressure stencil of a step: the neighbour list without the dry wall particles (walls above
// the water carry p = 0 as air and must not enter a gradient or Laplacian as if they were a
// p = 0 boundary inside the fluid's support). Built by the assembly, read by the corrector.
inline constexpr Resource<NeighbourList> pressure_neighbours_resource{"pressure_neighbours"};

// lagrangian: particles move with the fluid (w = v); ale: w = v + dr_shift/dt (eq. 7);
// eulerian: particles stay (w = 0) and the predictor carries the convective term.
enum class IsphDescription { Lagrangian, Ale, Eulerian };

// The corrector's pressure gradient: corrected (eq. 9), symmetric (I-SPH(2) eq. 11), or hybrid:
// symmetric where the free surface cuts the support (det M_i < symmetric_gradient_det and a
// surface particle in it: the surface, spray), corrected elsewhere. See IsphPressureCorrection.
enum class PressureGradientForm { Corrected, Symmetric, Hybrid };

// The CFL number of ISPH's step rule until 2026-11-28 (cfl d / max(|v|max, sqrt(2 g H))), at which
// the stabilised source's relaxation time and density shifting's C_shift per step were tuned:
// both keep that rule's rate whatever step the flow takes now (isph.cpp, density_shifting.hpp).
inline constexpr double kTunedCfl = 0.2;

// Water at rest takes at most kSurfaceWaveStep sqrt(d / g): the free surface is explicit (p = 0
// where the particles are), and its particle-scale waves set a step limit that no speed shows.
// Measured (docs/isph.md, "The step"): the violent-flow sloshing tank (H/d = 20) keeps its energy
// at 0.1 and blows up within 0.07 s at 0.2; the 3D box tank at rest holds 1.9e-5 J at fixed steps
// of 0.18 sqrt(d / g) and grows to 0.03 J at 0.27. The dam break at a/d = 20 takes its column's
// first collapse in a few such steps: its front agrees with a/d = 40's within 3% at 0.03 (3.85%
// at 0.1), about the old floor's step at H/d = 20-40.
inline constexpr double kSurfaceWaveStep = 0.03;

template <int D>
struct IsphParameters {
  Kernel<D> kernel{KernelType::CubicSpline, 1.0};
  Domain<D> domain;
  Vec<D> gravity = Vec<D>::Zero();
  double spacing = 1;
  double rho0 = 1000;
  double nu = 0;  // kinematic viscosity
  IsphDescription description = IsphDescription::Ale;
  LaplacianOrder ppe_laplacian = LaplacianOrder::Corrected, viscous_laplacian = LaplacianOrder::Corrected;
  PressureGradientForm pressure_gradient = PressureGradientForm::Corrected;
  double symmetric_gradient_det = 0.8;
  double uncorrected_divergence_det = 0.8;
  // alpha of the stabilised source (Asai et al. 2012), and the density error it answers.
  double compression_relaxation = 0.0;
  CompressionDensity compression_density = CompressionDensity::FirstShell;
  double compression_dead_band = 0;  // full_support: an error within it counts as 0
  double relaxation_time = 0.0;      // kTunedCfl d / max(sqrt(2 g H), initial speed)
  bool extrapolated_surface = true;  // p = 0 half a spacing outside a surface particle
  bool wall_no_slip = true;
  // Neumann wall rows (eq. 17) with the corrected gradient at the wall particle (the paper's), or
  // with the Shepard one-sided difference to the fluid neighbours (positive weights, no wall-wall
  // coupling): see IsphPressureEquation.
  bool wall_shepard = false;
  bool wall_shepard_hydrostatic = false;  // the Shepard row's gradient along the wall hydrostatic
  // Or the layers that cover the support with Adami's wall pressure as their rows (round and
  // mesh containers); a moving body's acceleration enters it (g - a_w).
  bool wall_adami = false;
  bool wall_acceleration = false;
  // Per [[solid]] (components::body): whether a prescribed motion moves it (a lid's `velocity` is
  // its surface's, not a motion of its particles).
  std::vector<bool> moving_bodies;
  bool implicit_density = false;  // formulation = "implicit_density" (implicit_density_solve.hpp)
  bool fixed_pressure = false;  // the scene has [[fixed_pressure]] boxes (the column exists)
  bool surface_pressure = false;  // a system sets the free surface's Dirichlet values
  double cfl = 0.2;
  double reference_speed = 1;  // sqrt(2 g H); bounds the step only without gravity

  // The list is built at x^n and reused at the predicted x*: a particle moves at most cfl * d
  // per step (isph_time_step, VelocityTimeStep), two approach by at most twice that, plus the shift.
  // Eulerian particles stay put: the support is enough (the 3D pipe's step took 40% less time).
  // The implicit density formulation does not shift: the two particles' motion alone.
  double search_radius() const {
    const double motion = description == IsphDescription::Eulerian ? 0.0 : implicit_density ? 2.0 : 3.0;
    return kernel.support() + motion * cfl * spacing;
  }
};

}  // namespace ryushi
