#pragma once
// Assembles the MPS pressure Poisson equation (BMG paper eqs. 4 and 7) at the predicted
// positions:
//   -<lap p>_i = 2d/(lambda0 n0) sum_j (p_i - p_j) w_ij = gamma rho0/dt^2 (n*_i - n0)/n0
// for every particle whose pressure is unknown (fluid and wall particles below the surface).
// Neighbours on the free surface carry p = 0 (they add to the diagonal only); dummy particles
// carry no pressure and are left out, as in Koshizuka's MPS. gamma is the source relaxation
// (0.2 in the paper's dam break). With the smooth source (the 2D default) (n*_i - n0)/n0
// is (rho*_i - rho0)/rho0, the density of mps_number_density from a smooth kernel. A is symmetric positive
// definite when every connected group of unknowns touches the surface (a closed, completely filled container
// would be singular).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "ecs/io.hpp"
#include "systems/mps/mps_pair_weights.hpp"
#include "systems/mps/mps_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/pressure/pressure_gauge.hpp"
#include "systems/pressure/pressure_system.hpp"

namespace ryushi {

template <int D>
class MpsPressureEquation final : public System<D> {
 public:
  explicit MpsPressureEquation(const MpsParameters<D>& p) : p_(p) {}
  std::string name() const override { return "ppe_assembly"; }
  // kind, id: to name a particle whose row is bad.
  static constexpr auto io = Io{reads(components::position, components::number_density, components::density,
                                      components::pressure_role, components::id, components::kind,
                                      neighbours_resource, mps_pair_weights_resource, resources::dt_chosen),
                                writes(pressure_system_resource)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(pressure_system_resource); }
  void run(SystemContext<D>& ctx) override {
    // The control's step, not the driver's shortened one: the relaxed source gamma (n* - n0)/dt^2
    // holds a full step's compression, which a shortened step would amplify into a wrong
    // pressure (an end-time frame showed 71% of the fluid negative). The shortened step then
    // applies (dt/dt_chosen)^2 of the correction: a weaker relaxation for that one step.
    auto [x, n, rho, role, id, kind, nl, weights, dt, sys] = io.fetch(ctx);
    const double* weight = weights.of(nl, "ppe_assembly");
    const double c = p_.laplacian_coefficient();
    const double source = p_.relaxation * p_.rho0 / (dt * dt * p_.n0);

    // Each particle's row, or what it is without one: the passes gather this one array per
    // neighbour instead of its role and its row (the gather was a third of the assembly).
    row_of_.resize(x.size());
    sys.particle_of_row.clear();
    for (std::size_t i = 0; i < x.size(); ++i)
      if (role[i] == kPressureUnknown) {
        row_of_[i] = static_cast<std::uint32_t>(sys.particle_of_row.size());
        sys.particle_of_row.push_back(static_cast<std::uint32_t>(i));
      } else {
        row_of_[i] = role[i] == kPressureSurface ? kSurface : kNoPressure;
      }
    const std::size_t rows = sys.particle_of_row.size();
    // Pass 1: entries per row (the diagonal plus the unknown neighbours with a positive weight,
    // i.e. inside r_e). Both passes read the number density's weights, so they agree on every
    // pair.
    auto& A = sys.A;
    A.rows = A.cols = rows;
    A.row_ptr.assign(rows + 1, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 512), [&](auto range) {
      for (std::size_t r = range.begin(); r != range.end(); ++r) {
        const std::size_t i = sys.particle_of_row[r];
        std::uint64_t count = 1;
        for (auto k = nl.offsets[i], end = nl.end(i); k != end; ++k)
          count += row_of_[nl.indices[k]] < kSurface && weight[k] > 0;
        A.row_ptr[r + 1] = count;
      }
    });
    for (std::size_t r = 0; r < rows; ++r) A.row_ptr[r + 1] += A.row_ptr[r];
    A.col.resize(A.row_ptr[rows]);
    A.val.resize(A.row_ptr[rows]);
    sys.b.resize(rows);
    sys.coordinates.resize(rows * D);
    // Pass 2: values, written in place. Rows follow the particle order and each list is
    // ascending, so the columns come sorted and the diagonal goes before the first column above
    // the row's own; a row that is not sorted (a list built before particles were reordered) is
    // sorted afterwards.
    std::atomic<std::size_t> bad_row_found{kNoRow};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 512), [&](auto range) {
      std::vector<std::pair<std::uint32_t, double>> unsorted_row;
      std::size_t bad_row = kNoRow;
      for (std::size_t r = range.begin(); r != range.end(); ++r) {
        const std::size_t i = sys.particle_of_row[r];
        const auto row = static_cast<std::uint32_t>(r);
        double diagonal = 0;
        auto slot = A.row_ptr[r];
        auto diagonal_slot = A.row_ptr[r + 1];  // none yet
        std::uint32_t previous = 0;
        bool sorted = true;
        for (auto k = nl.offsets[i], end = nl.end(i); k != end; ++k) {
          const double w = weight[k];
          const std::uint32_t col = row_of_[nl.indices[k]];
          if (col == kNoPressure || !(w > 0)) continue;
          diagonal += c * w;
          if (col == kSurface) continue;
          if (col > row && diagonal_slot == A.row_ptr[r + 1]) diagonal_slot = slot++;
          sorted &= col >= previous;
          previous = col;
          A.col[slot] = col;
          A.val[slot++] = -c * w;
        }
        if (diagonal_slot == A.row_ptr[r + 1]) diagonal_slot = slot;
        A.col[diagonal_slot] = row;
        A.val[diagonal_slot] = diagonal;
        if (!sorted) sort_row(A, r, unsorted_row);
        if (!(diagonal > 0) || !std::isfinite(diagonal)) bad_row = std::min<std::size_t>(bad_row, r);
        sys.b[r] = p_.smooth_source ? source * p_.n0 * (rho[i] / p_.rho0 - 1) : source * (n[i] - p_.n0);
        for (int a = 0; a < D; ++a) sys.coordinates[r * D + a] = x[i][a];
      }
      for (auto seen = bad_row_found.load();
           bad_row < seen && !bad_row_found.compare_exchange_weak(seen, bad_row);) {
      }
    });
    if (bad_row_found != kNoRow) report_bad_row(kind, id, sys.particle_of_row[bad_row_found], x, n);
    sys.dimension = D;
    sys.bucket_width = p_.weight.support();
    sys.symmetric = true;
    fix_pressure_gauge(sys, [](std::size_t) { return 1.0; }, true);  // symmetric: y = 1
  }

 private:
  // A row without a positive, finite diagonal would make the system singular: a particle whose
  // number density is full but whose neighbours within r_e carry no pressure (it has passed
  // into the dummy layers), or two particles at the same point.
  [[noreturn]] void report_bad_row(std::span<const std::int32_t> kind, std::span<const std::int32_t> id,
                                   std::size_t i, std::span<const Vec<D>> x,
                                   std::span<const double> n) const {
    std::ostringstream m;
    m << (kind[i] == kFluid ? "fluid" : "wall") << " particle id " << id[i] << " at (";
    for (int a = 0; a < D; ++a) m << (a ? ", " : "") << x[i][a];
    m << ") has n* = " << n[i] / p_.n0
      << " n0 but no pressure-carrying neighbour at a finite distance within r_e (inside the dummy wall "
         "layers, or "
         "on top of another particle): its pressure row would be singular";
    throw std::runtime_error(m.str());
  }

  static void sort_row(solvers::CsrMatrix<double>& A, std::size_t r,
                       std::vector<std::pair<std::uint32_t, double>>& scratch) {
    scratch.clear();
    for (auto k = A.row_ptr[r]; k != A.row_ptr[r + 1]; ++k) scratch.emplace_back(A.col[k], A.val[k]);
    std::sort(scratch.begin(), scratch.end());
    auto k = A.row_ptr[r];
    for (auto& [col, val] : scratch) {
      A.col[k] = col;
      A.val[k++] = val;
    }
  }

  static constexpr std::uint32_t kNoRow = UINT32_MAX;        // bad_row_found's "none"
  static constexpr std::uint32_t kNoPressure = UINT32_MAX;   // row_of_: a dummy
  static constexpr std::uint32_t kSurface = UINT32_MAX - 1;  // row_of_: p = 0, the diagonal only
  MpsParameters<D> p_;
  std::vector<std::uint32_t> row_of_;  // a row, kSurface or kNoPressure; kept between steps
};

}  // namespace ryushi
