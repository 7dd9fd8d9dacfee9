#pragma once
// The per-particle terms of an MPH-I step at x^k (MPH-I paper eqs. 2-4), for fluid and wall
// particles alike (walls are frozen particles of the same material: their number density, its
// rate and their pressure enter the fluid's sums as any neighbour's):
//   n_i = V0 sum_{j, r < h_p} w_p(r_ij), the number density;
//   g_ij = V0 w_p'(r_ij) e_ij for the pairs within h_p (e_ij from i to j), kept as a list: the
//         rate D_i = dn_i/dt = sum_j g_ij.(u_j - u_i), and the pressure force on i is
//         sum_j (psi_i + psi_j) g_ij;
//   G_i = -sum_j g_ij, the coefficient of u_i in D_i (so D_i = G_i.u_i + sum_j g_ij.u_j);
//   the elastic pressure kappa max(n_i - n0, 0): the potential acts on compression only, so a
//         free surface carries no pressure (with it on both sides a surface particle's missing
//         neighbours pulled the surface in at kappa times its deficit, about 1e5 rho g H);
//   the bulk coefficient lambda_i = lambda + kappa dt where n_i > n0 (implicit_compression): the
//         elastic pressure at the end of the step, kappa (n_i + dt D_i - n0), taken implicitly
//         through its rate; explicit, the step is stable only while kappa dt < 2 lambda.
#include <tbb/parallel_for.h>

#include <vector>

#include "ecs/io.hpp"
#include "systems/mph/mph_parameters.hpp"
#include "systems/neighbour/neighbour_search.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> mph_number_density{"number_density"};
// A wall particle's distance from the wall's face, (layer - 1/2) spacings (0 for fluid).
inline constexpr Component<Scalar> mph_wall_depth{"wall_depth"};
}  // namespace components

template <int D>
struct MphParticleTerms {
  std::vector<std::uint32_t> pair_offsets{0}, pair_index;  // the pairs within h_p, row by row
  std::vector<Vec<D>> pair_rate;                           // g_ij
  std::vector<Vec<D>> self_rate;                           // G_i
  std::vector<double> elastic_pressure;                    // kappa max(n_i - n0, 0)
  std::vector<double> bulk_coefficient;                    // lambda_i
};

template <int D>
inline constexpr Resource<MphParticleTerms<D>> mph_terms_resource{"mph_particle_terms"};

template <int D>
class MphNumberDensity final : public System<D> {
 public:
  explicit MphNumberDensity(const MphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "mph_number_density"; }
  static constexpr auto io =
      Io{reads(components::position, neighbours_resource, domain_resource<D>, resources::dt),
         writes(components::mph_number_density, mph_terms_resource<D>)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(mph_terms_resource<D>); }
  void run(SystemContext<D>& ctx) override {
    auto [x, nl, domain, dt, n, terms] = io.fetch(ctx);
    const std::size_t N = x.size();
    terms.self_rate.resize(N);
    terms.elastic_pressure.resize(N);
    terms.bulk_coefficient.resize(N);
    const double compression_rate = p_.implicit_compression ? p_.kappa * dt : 0.0;
    auto within = [&](std::size_t i, std::uint32_t k, Vec<D>& rij, double& r) {
      rij = domain.offset(x[i], x[nl.indices[k]]);
      r = rij.norm();
      return r < p_.h_p && r > 0;
    };
    terms.pair_offsets.assign(N + 1, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 512), [&](auto range) {
      Vec<D> rij;
      double r;
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        std::uint32_t count = 0;
        for (auto k = nl.offsets[i], end = nl.end(i); k != end; ++k) count += within(i, k, rij, r);
        terms.pair_offsets[i + 1] = count;
      }
    });
    for (std::size_t i = 0; i < N; ++i) terms.pair_offsets[i + 1] += terms.pair_offsets[i];
    terms.pair_index.resize(terms.pair_offsets[N]);
    terms.pair_rate.resize(terms.pair_offsets[N]);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 512), [&](auto range) {
      Vec<D> rij;
      double r;
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        double sum = 0;
        Vec<D> g = Vec<D>::Zero();
        auto slot = terms.pair_offsets[i];
        for (auto k = nl.offsets[i], end = nl.end(i); k != end; ++k) {
          if (!within(i, k, rij, r)) continue;
          sum += p_.w_p(r);
          const Vec<D> gij = p_.volume * p_.dw_p(r) / r * rij;
          terms.pair_index[slot] = nl.indices[k];
          terms.pair_rate[slot++] = gij;
          g -= gij;
        }
        n[i] = p_.volume * sum;
        terms.self_rate[i] = g;
        const bool compressed = n[i] > p_.n0;
        terms.elastic_pressure[i] = compressed ? p_.kappa * (n[i] - p_.n0) : 0.0;
        terms.bulk_coefficient[i] = p_.lambda + (compressed ? compression_rate : 0.0);
      }
    });
  }

 private:
  MphParameters<D> p_;
};

}  // namespace ryushi
