#pragma once
// Physical and numerical constants of a weakly compressible SPH run, fixed at scene load.
#include <algorithm>
#include <cmath>

#include "ecs/math.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
struct WcsphParameters {
  Kernel<D> kernel{KernelType::WendlandC2, 1.0};
  Domain<D> domain;
  Vec<D> gravity = Vec<D>::Zero();
  double spacing = 1;
  double rho0 = 1000;
  double c0 = 10;
  double gamma = 7;
  double delta = 0.1;            // delta-SPH diffusion coefficient (seed 002 eq. 18)
  double alpha = 0.02;           // artificial viscosity, linear term (seed 002 eq. 23, "A")
  double beta = 0.0;             // artificial viscosity, quadratic term ("B")
  bool riemann = false;          // the pair dissipation: Zhang, Hu & Adams's Riemann limiter, not alpha/beta
  double riemann_limiter = 3.0;  // eta of their limiter beta = min(eta max(U_L - U_R, 0) / c0, 1)
  double mu = 0;                 // dynamic viscosity, Pa s (0: no laminar viscosity system); with a
                                 // rheology model the largest at the start (the first step's limit)
  bool variable_viscosity = false;  // a rheology model writes the viscosity column each stage
  bool wall_no_slip = true;
  bool wall_acceleration = false;  // some body moves: Adami's wall pressure takes its acceleration
  bool elastic_bodies = false;     // [[elastic]] particles: moving walls to the fluid (Adami's rows)
  double solid_sound_speed = 0;    // the stiffest elastic body's sqrt((K + 4G/3)/rho0) over [method]
                                   // solid_substeps: a step limit

  // The continuity's density diffusion: delta-SPH's, or the Riemann problem's (continuity_delta_sph.hpp).
  bool density_diffusion() const { return riemann || delta > 0; }
  bool viscous() const { return mu > 0 || variable_viscosity; }  // the laminar viscous term is on

  // 2 P*_ij / (rho_i rho_j), the momentum equation's pair coefficient, symmetric in (i, j).
  // artificial viscosity: (p_i + p_j)/(rho_i rho_j) + Pi_ij, Monaghan's viscosity for approaching
  // pairs (v_ij.x_ij < 0), mu_ij = h v_ij.x_ij / (r^2 + 0.01 h^2).
  // riemann (Zhang, Hu & Adams 2017, J. Comput. Phys. 335): P* of the linearised acoustic Riemann
  // problem along the pair, P* = (p_i + p_j)/2 + beta rho0 c0 U/2 for an approach speed U (the
  // caller's riemann_approach), with their limiter beta = min(eta max(U, 0) / c0, 1): quadratic
  // in U, so slow relative motion is hardly damped and an impact is.
  // inv_rho_ij = 1/(rho_i rho_j), inv_r2_eta2 = 1/(r^2 + 0.01 h^2): the pair loop's shared divisions.
  double pair_pressure_coefficient(double pi, double pj, double rhoi, double rhoj, double inv_rho_ij,
                                   double vx, double inv_r2_eta2, double approach) const {
    double coeff = (pi + pj) * inv_rho_ij;
    if (riemann) {
      if (approach > 0)
        coeff += std::min(riemann_limiter * approach / c0, 1.0) * rho0 * c0 * approach * inv_rho_ij;
    } else if (vx < 0) {
      const double m = kernel.h() * vx * inv_r2_eta2;
      coeff += (-alpha * c0 * m + beta * m * m) / (0.5 * (rhoi + rhoj));
    }
    return coeff;
  }
  // The approach speed U_L - U_R of a pair's Riemann problem: -v_ij.x_ij / r between two fluid (or
  // elastic) particles. Against a wall particle the right state is the fluid's mirror across the
  // wall, U = 2 (v_f - v_w).n_w with the wall's normal n_w (out of the fluid), but only as far as
  // the fluid particle also closes in on that wall particle, U = 2 min((v_f - v_w).n_w, -(v_f -
  // v_w).x_fw / r): along the pair alone the floor's particles ahead of a tongue sliding over it
  // braked it (arrival t* 2.82 against 2.57 at H/d = 40), along the normal alone an edge
  // particle's bisector braked the flow turning round a column's edge and held it there in
  // tension (a 3D column: -82 kPa beside the edge, then a particle at 14 m/s).
  static double riemann_approach(const Vec<D>& vij, const Vec<D>& xij, double r) { return -vij.dot(xij) / r; }
  static double riemann_wall_approach(const Vec<D>& v_fluid_minus_wall, const Vec<D>& x_fluid_minus_wall,
                                      double r, const Vec<D>& wall_normal) {
    return 2.0 *
           std::min(v_fluid_minus_wall.dot(wall_normal), -v_fluid_minus_wall.dot(x_fluid_minus_wall) / r);
  }

  // Tait stiffness B = rho0 c0^2 / gamma (seed 002 eq. 3 with p0 = B).
  double stiffness() const { return rho0 * c0 * c0 / gamma; }
  double pressure(double rho) const {
    double x = rho / rho0;
    double xg = gamma == 7.0 ? x * x * x * x * x * x * x : std::pow(x, gamma);
    return stiffness() * (xg - 1.0);
  }
  double density(double p) const {
    double base = p / stiffness() + 1.0;
    return rho0 * std::pow(base > 0 ? base : 0.0, 1.0 / gamma);
  }
};

}  // namespace ryushi
