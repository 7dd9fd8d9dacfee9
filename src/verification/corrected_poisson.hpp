#pragma once
// A non-symmetric test system: -lap(phi) = f on the unit square with the Fatehi-Manzari
// corrected Laplacian (ISPH paper eqs. 11-14) on 20%-jittered particles, Dirichlet ghost layers
// (exact values) on the left, right and top, and a single layer of wall particles below the
// bottom whose rows impose the Neumann condition n . <grad phi>_corrected = dphi/dn (exact).
// Exact solution phi = sin(pi x) cos(pi y) + x y. Rows come from the operator library by
// linearity: each coefficient is the operator applied to a unit vector over the support.
#include <vector>

#include "solvers/csr_matrix.hpp"

namespace ryushi {

struct CorrectedPoissonProblem {
  solvers::CsrMatrix<double> A;
  std::vector<double> b, exact, coordinates;
  double spacing, coupling_radius;
  std::size_t wall_rows = 0;
};

CorrectedPoissonProblem corrected_poisson_problem(int n, unsigned seed = 1);

}  // namespace ryushi
