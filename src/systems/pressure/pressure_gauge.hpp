#pragma once
// A pressure equation with no Dirichlet value anywhere (a fully periodic box, a closed box filled
// with water: no free surface, no p = 0 row) fixes the pressure only up to a constant: every row
// of A sums to zero, A 1 = 0, and the Krylov solvers stall (the periodic shear layer stopped CG at
// relative residual 0.23). Two steps make it solvable without changing the flow:
//   1. the source b loses its weighted mean, b -= (y . b / y . 1) 1, with y the left null vector
//      of A when it is known (the particle volumes for the standard SPH Laplacian and for MPS,
//      whose columns sum to zero with those weights): a uniform compression or expansion has no
//      pressure field that makes it (the box cannot change volume), so only the rest of b is
//      solved for;
//   2. one row (the first) is pinned to p = 0: its off-diagonals and its column go, which keeps a
//      symmetric A symmetric and makes it definite.
// The solve then shifts the pressure so that its lowest value is 0 (`gauge_free`): in a box without
// a surface the level is a convention; the difference gradients (MPS, corrected ISPH) do not see
// it, and the symmetric one, (p_i + p_j), clumps particles where it is negative.
// With the corrected Laplacian the volumes are only close to the left null vector: what remains of
// b's inconsistency would land on the pinned particle as a point source (the periodic shear layer
// blew up at t = 0.26 s near the pin in the first row, at 0.24 s near a pin in the middle). Then
// (`gauge_exact` false) the solve finds the uniform source beta that makes the pinned row's own
// equation hold, with a second solve of the pinned system against the uniform source
// (LinearSolve): p = x - beta z.
#include <cmath>
#include <cstddef>
#include <vector>

#include "systems/pressure/pressure_system.hpp"

namespace ryushi {

// True when no row of A reaches a Dirichlet value: each row sums to zero within round-off.
inline bool pressure_equation_is_gauge_free(const PressureSystem& sys) {
  const auto& A = sys.A;
  if (A.rows == 0) return false;
  for (std::size_t r = 0; r < A.rows; ++r) {
    double sum = 0, diagonal = 0;
    for (auto k = A.row_ptr[r]; k < A.row_ptr[r + 1]; ++k) {
      sum += A.val[k];
      if (A.col[k] == r) diagonal = A.val[k];
    }
    if (!(std::abs(sum) <= 1e-9 * std::abs(diagonal))) return false;
  }
  return true;
}

// Applies steps 1 and 2 above when the system is gauge free; `weight(r)` is y_r (row r's volume),
// `exact` whether it is A's left null vector.
template <class Weight>
void fix_pressure_gauge(PressureSystem& sys, Weight&& weight, bool exact) {
  sys.gauge_free = pressure_equation_is_gauge_free(sys);
  sys.gauge_exact = exact;
  if (!sys.gauge_free) return;
  auto& A = sys.A;
  double yb = 0, y1 = 0;
  for (std::size_t r = 0; r < A.rows; ++r) yb += weight(r) * sys.b[r], y1 += weight(r);
  const double mean = yb / y1;
  for (auto& br : sys.b) br -= mean;
  const std::size_t pinned = 0;
  sys.pinned_row = pinned;
  sys.pinned_rhs = sys.b[pinned];
  sys.pinned_equation.clear();
  for (auto k = A.row_ptr[pinned]; k < A.row_ptr[pinned + 1]; ++k) sys.pinned_equation.emplace_back(A.col[k], A.val[k]);
  for (std::size_t r = 0; r < A.rows; ++r)
    for (auto k = A.row_ptr[r]; k < A.row_ptr[r + 1]; ++k)
      if ((r == pinned) != (A.col[k] == pinned)) A.val[k] = 0.0;
  sys.b[pinned] = 0.0;
}

}  // namespace ryushi
