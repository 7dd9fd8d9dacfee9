#pragma once
// The Poisson benchmark of the multigrid paper (section 5(1), eqs. 20-25): -lap(phi) =
// prod_a sin(2 pi x_a) on the unit square / cube, exact phi = prod_a sin(2 pi x_a) / (4 pi^2 D).
// n^D unknown particles at (k + 1/2) l0 jittered by up to 0.3 l0 per axis; two layers of
// Dirichlet particles outside the box carry the exact solution. MPS Laplacian (eq. 7) with the
// weight r_e/r - 1, r_e = 3.1 l0 (2D) or 2.1 l0 (3D), n0 and lambda0 from the regular lattice.
// The matrix is symmetric positive definite.
#include <vector>

#include "solvers/csr_matrix.hpp"

namespace ryushi {

struct PoissonProblem {
  int dimension;
  double spacing, influence_radius;
  solvers::CsrMatrix<double> A;
  std::vector<double> b, exact, coordinates;  // coordinates: unknowns x dimension, row-major
};

PoissonProblem mps_poisson_problem(int dimension, int n, unsigned seed = 1, double jitter = 0.3);

}  // namespace ryushi
