#pragma once
// Constants of an MPH-I run (moving particle hydrodynamics for incompressible flow; seed paper
// "MPH-I法を高速化するマルチグリッド前処理ソルバー", eqs. 1-4), fixed at scene load.
//
// Both weights are (1 - r/h)^2 inside h (eq. 3): h_p (the paper's 1.75 l) for the number
// density, its rate and the pressure force, h_v (3.5 l) for the shear viscosity. The paper
// normalises the weight by its continuous integral S; here each weight's constant is taken on
// the initial lattice instead, so that the discrete operators are exact there for the fields that
// define them (as MPS takes n0 and lambda0 from the lattice):
//   pressure weight w_p = s_p (1 - r/h_p)^2 with V0 sum_j r w_p'(r) e_x^2 = -1 over the lattice,
//     i.e. V0 sum_j (psi_i + psi_j) w_p' e_ij = -grad psi for a linear psi, and the number density
//     n = V0 sum w_p changes by exactly the volumetric strain under a uniform dilation (dn/d(eps) =
//     1), so kappa (n - n0) is kappa times the volume strain;
//   viscous coefficient c_v (the paper's 2 (d + 2)) with -c_v V0 sum_j (w_v'/r) ((u_j - u_i).e) e
//     = lap u for u = (y^2, 0, 0).
// Against the continuous S (2D, h_p = 1.75 l, h_v = 3.5 l): w_p's constant 0.23% larger, c_v 6.3%
// larger (the lattice's pair sum is 6% short of the integral). n0 is 0.551, not 1: the density
// change is n - n0, the volume strain, not (n - n0) / n0 (which would make the force 1.81 grad psi).
#include <cmath>

#include "ecs/lattice.hpp"
#include "ecs/math.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
struct MphParameters {
  Domain<D> domain;
  Vec<D> gravity = Vec<D>::Zero();
  double spacing = 1, volume = 1;  // l and V0 = l^D
  double rho0 = 1000;
  double mu = 0;                     // shear viscosity (Pa s)
  double lambda = 0;                 // bulk viscosity (Pa s), eq. 2
  double kappa = 0;                  // bulk modulus (Pa), eq. 2
  bool implicit_compression = true;  // kappa dt added to lambda where compressed (mph.cpp)
  double h_p = 1.75, h_v = 3.5;      // radii (m)
  double s_p = 1, c_v = 1, n0 = 1;   // lattice constants (above)
  double cfl = 0.2;
  double reference_speed = 1;

  // Unnormalised (1 - r/h)^2 and its derivative.
  static double shape(double r, double h) { return r < h ? (1 - r / h) * (1 - r / h) : 0.0; }
  static double shape_derivative(double r, double h) { return r < h ? -2 * (1 - r / h) / h : 0.0; }
  double w_p(double r) const { return s_p * shape(r, h_p); }
  double dw_p(double r) const { return s_p * shape_derivative(r, h_p); }
  // The shear term's pair coefficient a_ij = -c_v mu V0 w_v'(r) / r >= 0: the force on i is
  // sum_j a_ij ((u_j - u_i).e_ij) e_ij.
  double shear_coefficient(double r) const { return -c_v * mu * volume * shape_derivative(r, h_v) / r; }
  // The neighbour lists' radius: the shear pairs and the bulk term's pairs through a common
  // neighbour (up to 2 h_p apart).
  double coupling_radius() const { return std::max(h_v, 2 * h_p); }

  void set_radii(double pressure_radius, double viscous_radius) {
    h_p = pressure_radius;
    h_v = viscous_radius;
    volume = std::pow(spacing, D);
    // Lattice sums over the neighbours of a particle at the origin.
    const long reach = static_cast<long>(std::ceil(std::max(h_p, h_v) / spacing)) + 1;
    std::array<long, D> lo, hi;
    lo.fill(-reach);
    hi.fill(reach + 1);
    double grad = 0, visc = 0, n = 0;
    for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& k) {
      Vec<D> x;
      for (int a = 0; a < D; ++a) x[a] = k[a] * spacing;
      const double r = x.norm();
      if (r == 0) return;
      const double ex = x[0] / r, ey = x[1] / r;
      grad += r * shape_derivative(r, h_p) * ex * ex;
      visc += r * shape_derivative(r, h_v) * ex * ex * ey * ey;
      n += shape(r, h_p);
    });
    s_p = -1.0 / (volume * grad);
    c_v = -2.0 / (volume * visc);
    n0 = volume * s_p * n;
  }
};

}  // namespace ryushi
