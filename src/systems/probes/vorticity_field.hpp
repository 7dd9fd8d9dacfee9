#pragma once
// The vorticity as a frame field (`[output] fields = ["vorticity"]`; issue 56): computed when a
// frame is written, not every step, from the fluid particles around each fluid particle (binned
// afresh, FluidCells), with the kernel-corrected velocity gradient
//   G_i = (sum_j V_j (v_j - v_i) g_ij^T) A_i^-T,  A_i = sum_j V_j g_ij r_ij^T
// (g_ij = grad_i W_ij, r_ij = x_j - x_i, V_j = m_j / rho0), exact for a linear velocity field
// wherever A_i is invertible, the free surface's one-sided support included. 2D: the scalar
// dv/dx - du/dy (1/s, positive anticlockwise); 3D: the vector curl v. A particle without
// enough fluid around it to invert A_i (a drop) reads 0. Walls are left out: the field is the
// fluid's, not a wall condition's.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/LU>
#include <cmath>

#include "ecs/component.hpp"
#include "ecs/world.hpp"
#include "systems/method_context.hpp"
#include "systems/probes/fluid_cells.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> vorticity{"vorticity"};     // 2D: dv/dx - du/dy
inline constexpr Component<Vector> vorticity_3d{"vorticity"};  // 3D: curl v
}  // namespace components

// The frame field's column, of the dimension's type (made if missing).
template <int D>
auto& vorticity_column(World<D>& world) {
  if constexpr (D == 2)
    return world.ensure(components::vorticity);
  else
    return world.ensure(components::vorticity_3d);
}

template <int D>
void compute_vorticity(World<D>& world, const MethodContext<D>& context) {
  auto& omega = vorticity_column(world);
  auto write = [&](std::size_t i, const Mat<D>& gradient) {
    if constexpr (D == 2)
      omega[i] = gradient(1, 0) - gradient(0, 1);
    else
      omega[i] = Vec<D>(gradient(2, 1) - gradient(1, 2), gradient(0, 2) - gradient(2, 0),
                        gradient(1, 0) - gradient(0, 1));
  };
  const auto& kind = world.column(components::kind);
  const auto& x = world.column(components::position);
  const auto& v = world.column(components::velocity);
  const auto& m = world.column(components::mass);
  const double support = context.kernel.support();
  const FluidCells<D> cells(world, context.domain, support);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, world.size(), 512), [&](auto range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      write(i, Mat<D>::Zero());
      if (kind[i] != kFluid) continue;
      Mat<D> a = Mat<D>::Zero(), moment = Mat<D>::Zero();
      cells.around(x[i], [&](std::size_t j) {
        if (j == i) return;
        const Vec<D> r = context.domain.offset(x[i], x[j]);  // x_j - x_i
        const double q = r.norm();
        if (q >= support || q == 0) return;
        const Vec<D> g = -r * context.kernel.grad_factor(q);  // grad_i W_ij
        const double volume = m[j] / context.rho0;
        a += volume * g * r.transpose();
        moment += volume * (v[j] - v[i]) * g.transpose();
      });
      // A lattice's A is about the identity; a drop's is far from invertible.
      if (!(std::abs(a.determinant()) > 1e-3)) continue;
      write(i, moment * a.inverse().transpose());  // G(a, b) = dv_a / dx_b
    }
  });
}

}  // namespace ryushi
