#pragma once
// Dynamic particle splitting (Saigo & Koshizuka, seed 000 section 2(3) and appendix A): a
// particle whose area grew past area_ratio * A0 splits in two, at
//   x_new = x_i +/- (alpha_s l_i / 2) t_i,   l_i = sqrt(A_i)                       eq. 10
// along t_i, an eigenvector of the moment matrix C_i = sum_j x_ij x_ij^T w_ij (eqs. 11, A-1 ..
// Eq. 11 takes the larger eigenvalue's (`spread`: the axis along which the neighbours lie
// most). ryushi's default takes the smaller one's (`gap`: across the largest gap). Measured on
// Ritter's dam break (docs/swe.md): at a thinning front the particles stand in rows across the
// flow, the kernel-weighted moment is largest along the row, and `spread` puts the children
// into the row: its front lags the unsplit one (4.96 against 4.98 m at t = 0.5 s, d = 0.1 m) and
// hardly moves with resolution (5.01, 5.04 m at d = 0.05, 0.025); `gap` fills the gaps between
// the rows as the paper's Fig. 8 shows (fronts 5.18, 5.47, 5.69 m,
// against the analytic 6.22 m). Then
//   u_new = u_i + (dx . grad) u_i,   h_new = h_i + dx . <grad h>_i                 eq. 12
// (MPS gradients with area ratios, eq. 6). The children's volumes follow from momentum
// conservation in x and y: V+ u+ + V- u- = V u with u+- = u +- e gives (V+ + V-) u + (V+ - V-) e
// = V u, so V+ = V- = V / 2 (the unique solution when u and e are independent, and one that
// conserves volume in every case). Total volume and momentum are kept to round-off.
// The parent is erased and the two children appended between steps (the world's deferred
// structural changes); they get fresh ids, inherit every other column and record the parent's
// id in `parent_id`. A cap on the particle count stops splitting with one warning.
#include <spdlog/spdlog.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "ecs/io.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/swe/ghost_images.hpp"
#include "systems/swe/swe_parameters.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Flags> parent_id{"parent_id"};  // -1: not a split child
}  // namespace components

struct SplitParameters {
  double area_ratio = 1.5;  // split when A_i > area_ratio * A0
  double alpha_s = 0.7;     // children alpha_s l_i apart (eq. 10)
  double area0 = 0;         // A0
  double rho0 = 1000;       // mass = rho0 V
  bool along_gap = true;    // t_i: the smaller eigenvalue's eigenvector (gap) or the larger's (spread)
  std::size_t max_particles = 0;
};

struct SplittingStatistics {
  long long splits = 0;
  bool capped = false;  // the particle cap stopped splitting at least once
};
inline constexpr Resource<SplittingStatistics> splitting_statistics_resource{"splitting_statistics"};

// t_i: the unit eigenvector of the symmetric moment matrix C with the smallest eigenvalue
// (along_gap) or the largest (eq. 11 / A-6). An isotropic or empty neighbourhood (equal
// eigenvalues) has no preferred direction: `fallback` (the flow direction, or x) then.
template <int D>
Vec<D> split_direction(const Mat<D>& C, const Vec<D>& fallback, bool along_gap) {
  Eigen::SelfAdjointEigenSolver<Mat<D>> eig;
  eig.computeDirect(C);
  const auto& lambda = eig.eigenvalues();  // ascending
  if (!(lambda[D - 1] > lambda[0] * (1 + 1e-9)) || !(lambda[D - 1] > 0)) return fallback;
  Vec<D> t = eig.eigenvectors().col(along_gap ? 0 : D - 1);
  return t / t.norm();
}

// The MPS gradient with area ratios (eq. 6) of a per-particle field f, at particle i.
template <int D, class Field>
Vec<D> area_weighted_gradient(std::size_t i, std::span<const Vec<D>> x, const GhostImages<D>& g,
                              const NeighbourList& nl, std::span<const double> A, const Kernel<D>& w,
                              Field&& f) {
  double n = 0;
  Vec<D> grad = Vec<D>::Zero();
  const double fi = f(std::uint32_t(i), i);
  for (auto j : nl.of(i)) {
    const Vec<D> r = g.where(j, x) - x[i];
    const double r2 = r.squaredNorm();
    if (r2 == 0) continue;
    const std::uint32_t o = g.owner(j);
    const double weight = A[o] / A[i] * w.w(std::sqrt(r2));
    n += weight;
    grad += (f(j, o) - fi) / r2 * weight * r;
  }
  return n > 0 ? Vec<D>(D / n * grad) : Vec<D>::Zero();
}

template <int D>
class ParticleSplitting final : public System<D> {
 public:
  explicit ParticleSplitting(const SplitParameters& p) : p_(p) {}
  std::string name() const override { return "particle_splitting"; }
  // The children's columns (parent_id among them) are written by the structural change, which
  // the driver applies after the step, outside the flow graph: the system fetches none of them.
  static constexpr auto io =
      Io{reads(components::position, components::velocity, components::area, components::depth,
               components::water_volume, components::id, neighbours_resource, ghost_images_resource<D>,
               swe_influence_radius_resource),
         writes(structural_changes_resource<D>, splitting_statistics_resource)};
  Access access() const override { return io.access(); }
  void initialise(World<D>& world, Resources& res) override {
    auto& parent = world.ensure(components::parent_id);
    std::fill(parent.begin(), parent.end(), -1);
    res.ensure(structural_changes_resource<D>);
    res.ensure(splitting_statistics_resource);
  }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, A, h, V, id, nl, g, influence, changes, stats] = io.fetch(ctx);
    const Kernel<D> w(KernelType::Spiky, influence);
    const double threshold = p_.area_ratio * p_.area0;

    std::vector<std::uint32_t> parents;
    for (std::uint32_t i = 0; i < x.size(); ++i)
      if (A[i] > threshold) parents.push_back(i);
    if (parents.empty()) return;
    if (p_.max_particles > 0) {
      const std::size_t room = p_.max_particles > x.size() ? p_.max_particles - x.size() : 0;
      if (parents.size() > room) {
        if (!stats.capped)
          spdlog::warn(
              "particle splitting stopped: {} particles would exceed [splitting] max_particles = {}; the "
              "run goes on without splitting where the cap is reached",
              x.size() + parents.size(), p_.max_particles);
        stats.capped = true;
        parents.resize(room);
        if (parents.empty()) return;
      }
    }
    struct Child {
      Vec<D> x, v;
      double h, V;
    };
    std::vector<Child> children(2 * parents.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, parents.size(), 64), [&](auto range) {
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        const std::uint32_t i = parents[k];
        Mat<D> C = Mat<D>::Zero();
        for (auto j : nl.of(i)) {
          const Vec<D> r = g.where(j, x) - x[i];
          C += w.w(r.norm()) * r * r.transpose();
        }
        Vec<D> fallback = Vec<D>::Unit(0);
        if (v[i].norm() > 0) fallback = v[i] / v[i].norm();
        const Vec<D> dx = 0.5 * p_.alpha_s * std::sqrt(A[i]) * split_direction<D>(C, fallback, p_.along_gap);
        // (dx . grad) u: the gradient of each velocity component (a ghost's velocity is its
        // particle's with the wall's signs).
        Vec<D> du = Vec<D>::Zero();
        for (int a = 0; a < D; ++a) {
          auto component = [&](std::uint32_t j, std::uint32_t o) {
            return j < g.fluid ? v[o][a] : g.velocity_sign[j - g.fluid][a] * v[o][a];
          };
          du[a] = dx.dot(area_weighted_gradient<D>(i, x, g, nl, A, w, component));
        }
        const double dh = dx.dot(area_weighted_gradient<D>(
            i, x, g, nl, A, w, [&](std::uint32_t, std::uint32_t o) { return h[o]; }));
        children[2 * k] = {x[i] + dx, v[i] + du, h[i] + dh, 0.5 * V[i]};
        children[2 * k + 1] = {x[i] - dx, v[i] - du, h[i] - dh, 0.5 * V[i]};
      }
    });
    stats.splits += static_cast<long long>(parents.size());
    std::vector<std::int32_t> parent_ids(parents.size());
    for (std::size_t k = 0; k < parents.size(); ++k) parent_ids[k] = id[parents[k]];
    const double rho0 = p_.rho0;
    const std::size_t count = children.size();  // before the capture below moves them
    changes.append(
        count, kFluid,
        [parents, parent_ids, children = std::move(children), rho0](World<D>& world, std::size_t first) {
          for (std::size_t c = 0; c < children.size(); ++c) world.copy_particle(parents[c / 2], first + c);
          auto& X = world.column(components::position);
          auto& U = world.column(components::velocity);
          auto& H = world.column(components::depth);
          auto& Vol = world.column(components::water_volume);
          auto& Ar = world.column(components::area);
          auto& M = world.column(components::mass);
          auto& P = world.column(components::parent_id);
          for (std::size_t c = 0; c < children.size(); ++c) {
            const std::size_t k = first + c;
            X[k] = children[c].x;
            U[k] = children[c].v;
            H[k] = children[c].h;
            Vol[k] = children[c].V;
            Ar[k] = children[c].h > 0 ? children[c].V / children[c].h : Ar[k] / 2;
            M[k] = rho0 * children[c].V;
            P[k] = parent_ids[c / 2];
          }
        });
    changes.erase(std::move(parents));
  }

 private:
  SplitParameters p_;
};

}  // namespace ryushi
