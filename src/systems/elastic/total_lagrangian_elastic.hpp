#pragma once
// Linear-elastic bodies in the total Lagrangian form (Bonet & Lok 1999; Vignjevic et al. 2006):
// every sum runs over each particle's neighbours in the body's rest configuration X, found once,
// with kernel gradients corrected there,
//   B_i = [sum_j V0_j grad0 W_ij (X_j - X_i)^T]^-1,
//   F_i = sum_j V0_j (x_j - x_i) (B_i grad0 W_ij)^T               (deformation gradient)
//   E = (F^T F - I)/2,  S = lambda tr(E) I + 2 G E,  P = F S       (St Venant-Kirchhoff; small
//                                                                   strain: Hooke's law)
//   dv_i/dt = 1/rho0_i sum_j V0_j (P_i B_i + P_j B_j) grad0 W_ij + g
//             - sum_j m_j Pi_ij grad W_ij(x)                      (Monaghan's viscosity, A, B)
// (the fluid's push is fluid_on_solid.hpp's, added by the integrator: elastic_midpoint.hpp)
// lambda = K - 2G/3 (in 2D: plane strain). The rest-configuration neighbours make it free of the
// tensile instability that the seed's updated form (continuity, Jaumann rate, artificial stress;
// seed 002 eqs. 5-8, 25-26) needs its artificial stress against: implemented first, that form
// left an oscillating plate's energy growing (pressure noise 512 -> 1395 Pa rms in 0.4 s) and its
// period 17-37% long (docs/multiphysics.md). The Cauchy stress sigma = P F^T / J, the density
// rho0 / J and the strain energy are written for output and probes.
// Contact: particles of another body or of a wall closer than the spacing d push apart with
// (c_s^2 / d)(1 - r/d) along x_ij (c_s = sqrt((K + 4G/3)/rho0)), with the same viscosity.
// Clamped particles get no acceleration.
// This is a force model, not a system (elastic_model.hpp): the integration systems
// (elastic_midpoint.hpp) call it once per solid (sub)step.
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "ecs/io.hpp"
#include "ecs/lattice.hpp"
#include "ecs/outer_sum.hpp"
#include "systems/elastic/elastic_model.hpp"
#include "systems/elastic/elastic_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class TotalLagrangianElasticity final : public ElasticModel<D> {
 public:
  explicit TotalLagrangianElasticity(const ElasticParameters<D>& p) : p_(p) {}
  // The rest positions enter through initialise() (outside the flow graph) only.
  auto io() const {
    return Io{reads(components::position, components::velocity, components::kind, components::id,
                    components::solid_rest_density, components::bulk_modulus, components::shear_modulus,
                    components::clamped, components::elastic_body),
              writes(components::acceleration, components::stress, components::solid_density,
                     components::solid_pressure, components::strain_energy),
              optional(p_.contacts, reads(neighbours_resource))};
  }
  void declare(Access& a) const override { io().declare(a); }
  // The rest configuration: each elastic particle's neighbours within the support among the
  // particles of its own body (by id, so reordering cannot change them) and its B.
  void initialise(World<D>& world) override {
    auto& kind = world.column(components::kind);
    auto& id = world.column(components::id);
    auto& X = world.column(components::rest_position);
    auto& body = world.column(components::elastic_body);
    ids_.clear();
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < world.size(); ++i)
      if (kind[i] == kElastic) ids_.push_back(id[i]), index.push_back(i);
    const std::size_t n = ids_.size();
    const double support = p_.kernel.support(), volume = p_.volume();
    offsets_.assign(1, 0);
    neighbour_.clear(), gradient_.clear();
    B_.assign(n, Mat<D>::Identity());
    // Cells of the support over the rest positions: each particle looks in its own and the
    // adjacent cells.
    Vec<D> lo = X[index.empty() ? 0 : index[0]];
    for (auto i : index) lo = lo.cwiseMin(X[i]);
    auto cell_of = [&](const Vec<D>& x) {
      std::array<long, D> c{};
      for (int a = 0; a < D; ++a) c[a] = static_cast<long>(std::floor((x[a] - lo[a]) / support));
      return c;
    };
    std::map<std::array<long, D>, std::vector<std::size_t>> cells;
    for (std::size_t k = 0; k < n; ++k) cells[cell_of(X[index[k]])].push_back(k);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec<D> Xi = X[index[k]];
      Mat<D> M = Mat<D>::Zero();
      const auto c = cell_of(Xi);
      std::array<long, D> from{}, to{};
      for (int a = 0; a < D; ++a) from[a] = -1, to[a] = 2;
      for_each_lattice_index<D>(from, to, [&](const std::array<long, D>& offset) {
        std::array<long, D> cc;
        for (int a = 0; a < D; ++a) cc[a] = c[a] + offset[a];
        auto it = cells.find(cc);
        if (it == cells.end()) return;
        for (std::size_t l : it->second) {
          if (l == k || body[index[l]] != body[index[k]]) continue;
          const Vec<D> r = Xi - X[index[l]];  // X_i - X_j
          const double dist = r.norm();
          if (dist >= support) continue;
          const Vec<D> g = volume * p_.kernel.grad_factor(dist) * r;  // V0_j grad0 W_ij
          neighbour_.push_back(static_cast<std::uint32_t>(l));
          gradient_.push_back(g);
          M -= g * r.transpose();  // grad0 W (x) (X_j - X_i)
        }
      });
      offsets_.push_back(neighbour_.size());
      // The rest configuration is exact and fixed, so B is M's inverse wherever M has one: the
      // threshold that guards a moving configuration's noise (renormalisation.hpp) would leave B =
      // I at the corners of a 3D body (det(M) there about 0.03), F != I at rest, and the body
      // flying apart under no load.
      if (std::abs(M.determinant()) > 1e-9) B_[k] = M.inverse();
    }
    // The corrected gradients B_i V0_j grad0 W_ij of the deformation gradient, kept.
    corrected_.resize(gradient_.size());
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t e = offsets_[k]; e < offsets_[k + 1]; ++e) corrected_[e] = B_[k] * gradient_[e];
    PB_.assign(n, Mat<D>::Zero());
    version_ = ~std::uint64_t(0);
  }
  void evaluate(SystemContext<D>& ctx) override {
    // nl: null without contacts.
    auto [x, v, kind, id, rho0, K, G, clamped, body, a, sigma, rho, pressure, energy, nl] = io().fetch(ctx);
    const std::size_t n = ids_.size();
    if (ctx.structure_version() != version_) {  // particles reordered or removed: find them by id
      index_.assign(n, 0);
      std::vector<std::int64_t> slot_of_id;
      for (std::size_t k = 0; k < n; ++k) {
        if (slot_of_id.size() <= std::size_t(ids_[k])) slot_of_id.resize(ids_[k] + 1, -1);
        slot_of_id[ids_[k]] = static_cast<std::int64_t>(k);
      }
      for (std::size_t i = 0; i < x.size(); ++i)
        if (kind[i] == kElastic && std::size_t(id[i]) < slot_of_id.size() && slot_of_id[id[i]] >= 0)
          index_[slot_of_id[id[i]]] = i;
      slot_of_id_ = std::move(slot_of_id);
      version_ = ctx.structure_version();
    }
    const double volume = p_.volume();
    // The stress of each particle.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](auto range) {
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        const std::size_t i = index_[k];
        OuterSum<D> deformation;  // F = sum_j (x_j - x_i) (B grad0 W_ij)^T
        for (std::size_t e = offsets_[k]; e < offsets_[k + 1]; ++e)
          deformation.add(Vec<D>(x[index_[neighbour_[e]]] - x[i]), corrected_[e]);
        const Mat<D> F = deformation.matrix();
        const Mat<D> E = 0.5 * (F.transpose() * F - Mat<D>::Identity());
        const double lambda = K[i] - 2.0 / 3.0 * G[i];
        const Mat<D> S = lambda * E.trace() * Mat<D>::Identity() + 2.0 * G[i] * E;
        const Mat<D> P = F * S;
        PB_[k] = P * B_[k];
        const double J = F.determinant();
        sigma[i] = P * F.transpose() / J;
        rho[i] = rho0[i] / J;
        pressure[i] = -sigma[i].trace() / D;
        energy[i] = volume * (0.5 * lambda * E.trace() * E.trace() + G[i] * E.squaredNorm());
      }
    });
    const double support2 = p_.kernel.support() * p_.kernel.support();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](auto range) {
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        const std::size_t i = index_[k];
        if (clamped[i]) {
          a[i] = Vec<D>::Zero();
          continue;
        }
        const double c = std::sqrt((K[i] + 4.0 / 3.0 * G[i]) / rho0[i]);
        Vec<D> acc = Vec<D>::Zero();
        for (std::size_t e = offsets_[k]; e < offsets_[k + 1]; ++e) {
          const std::size_t l = neighbour_[e], j = index_[l];
          acc += (PB_[k] + PB_[l]) * gradient_[e] / rho0[i];
          // Monaghan's viscosity between approaching neighbours, in the current configuration.
          const Vec<D> xij = p_.domain.displacement(x[i], x[j]), vij = v[i] - v[j];
          const double vx = vij.dot(xij), r2 = xij.squaredNorm();
          if (vx < 0 && r2 < support2)
            acc -= rho0[j] * volume * solid_viscosity(p_, vx, r2, c, rho[i], rho[j]) *
                   p_.kernel.grad_factor(std::sqrt(r2)) * xij;
        }
        if (nl) add_solid_contact<D>(p_, *nl, i, c, rho0[i], rho[i], kind, body, x, v, acc);
        a[i] = acc + p_.gravity;
      }
    });
    this->current_ = true;
  }

 private:
  ElasticParameters<D> p_;
  std::vector<std::int32_t> ids_;         // the elastic particles, by id (slot k)
  std::vector<std::size_t> offsets_;      // slot k's rest neighbours: [offsets_[k], offsets_[k + 1])
  std::vector<std::uint32_t> neighbour_;  // their slots
  std::vector<Vec<D>> gradient_;          // V0_j grad0 W_ij
  std::vector<Vec<D>> corrected_;         // B_i V0_j grad0 W_ij
  std::vector<Mat<D>> B_, PB_;
  std::vector<std::size_t> index_;  // slot -> world index
  std::vector<std::int64_t> slot_of_id_;
  std::uint64_t version_ = ~std::uint64_t(0);
};

}  // namespace ryushi
