#pragma once
// Assembles MPH-I's implicit velocity equation (MPH-I paper eq. 4) at x^k: backward Euler on
// the velocity with the pressure of eq. 2 substituted, per unit volume,
//   rho0 u_i / dt + sum_j a_ij E_ij (u_i - u_j) + sum_k lambda_k b_ki (sum_m b_km . u_m)
//     = rho0 u_i^k / dt + sum_j (psi_i + psi_j) g_ij + rho0 g
// with a_ij the shear pair coefficient (mph_parameters.hpp), E_ij = e_ij e_ij^T, psi the elastic
// pressure and lambda_k the bulk coefficient (mph_number_density.hpp), and b_km the coefficient of
// u_m in particle k's rate D_k (g_km for a neighbour, G_k for k itself). The bulk term is
// lambda B^T B over every particle k whose rate involves a fluid velocity, fluid or wall: the
// derivative of the dissipation sum_k lambda_k D_k^2 / 2, as the shear term is of
// sum_pairs a_ij ((u_j - u_i).e_ij)^2 / 2. The matrix is therefore symmetric positive definite
// (not diagonally dominant: the bulk term couples neighbours of neighbours), one D x D block per
// pair of fluid particles within max(h_v, 2 h_p); wall velocities are known and go to the
// right-hand side. Unknowns: the fluid particles' velocities, row = fluid row * D + component.
// In a shear pair with a wall particle j the wall's velocity is extrapolated across the wall's
// face (Morris, Fox & Zhu 1997): u_j = u_w - beta (u_i - u_w), beta = min(d_j / d_i, 1.5) with
// d_j, d_i the distances of j and i from the face, so the no-slip holds at the face to second
// order; with u_j = u_w the discrete steady channel profile on the lattice is 13% fast at 20
// spacings across (docs/mph.md; the shear pairs then see a wall a fraction of a spacing inside the face).
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "ecs/io.hpp"
#include "solvers/csr_matrix.hpp"
#include "systems/mph/mph_number_density.hpp"

namespace ryushi {

struct MphVelocitySystem {
  solvers::CsrMatrix<double> A;
  std::vector<double> b;
  std::vector<std::uint32_t> particle_of_block;  // block row -> particle
  std::vector<double> coordinates;               // block rows x D, for the bucket multigrid
  double bucket_width = 0;                       // the coupling radius
};

inline constexpr Resource<MphVelocitySystem> mph_system_resource{"mph_velocity_system"};

template <int D>
class MphVelocityAssembly final : public System<D> {
 public:
  explicit MphVelocityAssembly(const MphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "mph_assembly"; }
  static constexpr auto io =
      Io{reads(components::position, components::velocity, components::kind, components::wall_normal,
               components::mph_wall_depth, neighbours_resource, mph_terms_resource<D>, domain_resource<D>,
               resources::dt),
         writes(mph_system_resource)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(mph_system_resource); }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, kind, normal, depth, nl, terms, domain, dt, sys] = io.fetch(ctx);
    using Block = Eigen::Matrix<double, D, D>;
    const std::size_t N = x.size();
    const double R = p_.coupling_radius();
    block_of_.assign(N, kNone);
    sys.particle_of_block.clear();
    for (std::size_t i = 0; i < N; ++i)
      if (kind[i] == kFluid) {
        block_of_[i] = static_cast<std::uint32_t>(sys.particle_of_block.size());
        sys.particle_of_block.push_back(static_cast<std::uint32_t>(i));
      }
    const std::size_t blocks = sys.particle_of_block.size();
    auto columns_of = [&](std::size_t i, std::vector<std::uint32_t>& cols) {  // fluid, ascending
      cols.clear();
      bool self = false;
      for (auto k = nl.offsets[i], end = nl.end(i); k != end; ++k) {
        const std::uint32_t j = nl.indices[k];
        if (kind[j] != kFluid || !(domain.offset(x[i], x[j]).norm() < R)) continue;
        if (!self && j > i) cols.push_back(static_cast<std::uint32_t>(i)), self = true;
        cols.push_back(j);
      }
      if (!self) cols.push_back(static_cast<std::uint32_t>(i));
    };
    auto& A = sys.A;
    A.rows = A.cols = blocks * D;
    A.row_ptr.assign(A.rows + 1, 0);
    tbb::enumerable_thread_specific<Scratch> scratch([&] { return Scratch(N); });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 256), [&](auto range) {
      auto& s = scratch.local();
      for (std::size_t r = range.begin(); r != range.end(); ++r) {
        columns_of(sys.particle_of_block[r], s.cols);
        for (int a = 0; a < D; ++a) A.row_ptr[r * D + a + 1] = s.cols.size() * D;
      }
    });
    for (std::size_t r = 0; r < A.rows; ++r) A.row_ptr[r + 1] += A.row_ptr[r];
    A.col.resize(A.row_ptr[A.rows]);
    A.val.resize(A.row_ptr[A.rows]);
    sys.b.resize(A.rows);
    sys.coordinates.resize(blocks * D);
    sys.bucket_width = R;
    const double inertia = p_.rho0 / dt;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 256), [&](auto range) {
      auto& s = scratch.local();
      for (std::size_t r = range.begin(); r != range.end(); ++r) {
        const std::size_t i = sys.particle_of_block[r];
        columns_of(i, s.cols);
        s.blocks.assign(s.cols.size(), Block::Zero());
        for (std::size_t c = 0; c < s.cols.size(); ++c) s.slot[s.cols[c]] = static_cast<std::int32_t>(c);
        Vec<D> rhs = inertia * v[i] + p_.rho0 * p_.gravity;
        // A block of the row at particle m: a fluid column, or a known wall velocity moved over.
        auto add = [&](std::uint32_t m, const Block& B) {
          if (kind[m] != kFluid) {
            rhs -= B * v[m];
            return;
          }
          if (s.slot[m] < 0) throw std::logic_error("mph_assembly: a coupling beyond the neighbour list");
          s.blocks[s.slot[m]] += B;
        };
        add(static_cast<std::uint32_t>(i), inertia * Block::Identity());
        for (auto k = nl.offsets[i], end = nl.end(i); k != end; ++k) {  // shear pairs
          const std::uint32_t j = nl.indices[k];
          const Vec<D> rij = domain.offset(x[i], x[j]);
          const double dist = rij.norm();
          if (!(dist < p_.h_v) || dist == 0) continue;
          const Vec<D> e = rij / dist;
          double mirror = 1;  // 1 + beta for a wall particle
          if (kind[j] != kFluid) {
            const double fluid_distance = normal[j].dot(rij) - depth[j];  // rij = x_j - x_i
            mirror += fluid_distance > 0 ? std::min(depth[j] / fluid_distance, 1.5) : 1.5;
          }
          const Block E = mirror * p_.shear_coefficient(dist) * e * e.transpose();
          add(static_cast<std::uint32_t>(i), E);
          add(j, -E);
        }
        // Elastic force, and the bulk term through i itself and each k within h_p.
        const auto first = terms.pair_offsets[i], last = terms.pair_offsets[i + 1];
        for (auto q = first; q != last; ++q)
          rhs +=
              (terms.elastic_pressure[i] + terms.elastic_pressure[terms.pair_index[q]]) * terms.pair_rate[q];
        auto through = [&](std::size_t k, const Vec<D>& b_ki) {  // lambda_k b_ki (B_k u)
          const Vec<D> scaled = terms.bulk_coefficient[k] * b_ki;
          add(static_cast<std::uint32_t>(k), scaled * terms.self_rate[k].transpose());
          for (auto q = terms.pair_offsets[k]; q != terms.pair_offsets[k + 1]; ++q)
            add(terms.pair_index[q], scaled * terms.pair_rate[q].transpose());
        };
        through(i, terms.self_rate[i]);
        for (auto q = first; q != last; ++q)
          through(terms.pair_index[q], -terms.pair_rate[q]);  // g_ki = -g_ik
        for (int a = 0; a < D; ++a) {
          const std::size_t row = r * D + a;
          auto out = A.row_ptr[row];
          for (std::size_t c = 0; c < s.cols.size(); ++c)
            for (int bcol = 0; bcol < D; ++bcol) {
              A.col[out] = static_cast<std::uint32_t>(block_of_[s.cols[c]] * D + bcol);
              A.val[out++] = s.blocks[c](a, bcol);
            }
          sys.b[row] = rhs[a];
          sys.coordinates[r * D + a] = x[i][a];
        }
        for (auto c : s.cols) s.slot[c] = -1;
      }
    });
  }

 private:
  struct Scratch {
    explicit Scratch(std::size_t n) : slot(n, -1) {}
    std::vector<std::int32_t> slot;  // particle -> the row's column slot, -1 elsewhere
    std::vector<std::uint32_t> cols;
    std::vector<Eigen::Matrix<double, D, D>> blocks;
  };
  static constexpr std::uint32_t kNone = UINT32_MAX;
  MphParameters<D> p_;
  std::vector<std::uint32_t> block_of_;
};

}  // namespace ryushi
