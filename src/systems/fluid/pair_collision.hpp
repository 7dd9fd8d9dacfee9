#pragma once
// Pair collisions (Koshizuka et al. 1998; Lee et al. 2011): two particles closer than the
// collision distance that still approach each other exchange the approaching part of their
// relative velocity as an inelastic collision with restitution e,
//   du_i = -(1 + e) m_j / (m_i + m_j) ((u_i - u_j) . n) n,   n = (x_j - x_i) / |x_j - x_i|,
// with walls as infinite masses at rest; then x_i += dt du_i. Momentum is conserved pair by pair;
// kinetic energy is only lost. A pair at the lattice spacing or farther, or moving apart, is never
// touched, so a fluid at rest does not see it.
// Why a projection method needs it: the pressure gradient of a consistent (corrected) operator does
// not push a close pair apart, so nothing stops particles from closing in on each other in a
// violent flow (MPS: a fast particle reaching a wall particle, where the weight r_e / r - 1
// diverges; ISPH: the fragmented flow after a plunging wave, docs/isph.md, "One set-up").
// Wall pairs may take a longer distance: a particle crossing a wall layer through the middle of a
// lattice square passes 0.71 d from its four corners (3D); 0 leaves wall pairs alone. Every
// particle gathers from the velocities before the collision (no order dependence) and writes only
// itself.
// With `beyond_resolved_flow`, a fluid pair collides only with the part of its approach that the
// flow around it does not explain: a smooth strain brings pairs closer than the collision distance
// too (a stretched lattice at a stagnation point), and taking their approach as a collision drains
// the flow's energy (the Taylor-Green vortices lost 4.8% by t = 0.2 s at 0.8 d). The resolved
// approach is -n . G r, G the mean of the pair's velocity gradients, each a least-squares fit
// (exact for a linear field on any particle arrangement) over the fluid neighbours that are not
// themselves close: a clump is judged against its surroundings, not against itself. Where the
// surroundings cannot fit a gradient (a drop of a few particles, a thin jet: the fit's smallest
// moment below a quarter of its mean) G = 0 and the whole approach counts, as without the option.
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <string>
#include <vector>

#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

struct PairCollisionParameters {
  std::string name;                   // the system's name in the timings: mps_collision, isph_collision
  double fluid_distance;              // between fluid particles (m)
  double wall_distance;               // between a fluid and a wall or dummy particle (m); 0: none
  double restitution;                 // e
  bool beyond_resolved_flow = false;  // collide only with the approach the velocity gradient does not explain
};

template <int D>
class PairCollision final : public System<D> {
 public:
  explicit PairCollision(PairCollisionParameters p) : p_(std::move(p)) {}
  std::string name() const override { return p_.name; }
  static constexpr auto io =
      Io{reads(components::kind, neighbours_resource, resources::dt, domain_resource<D>),
         writes(components::position, components::velocity)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [kind, nl, dt, domain, x, v] = io.fetch(ctx);
    dv_.resize(x.size());
    if (p_.beyond_resolved_flow) fit_gradients(kind, nl, domain, x, v);
    auto& dv = dv_;
    const double fluid2 = p_.fluid_distance * p_.fluid_distance, wall2 = p_.wall_distance * p_.wall_distance;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> change = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        Vec<D> r = domain.offset(x[i], x[j]);
        double r2 = r.squaredNorm();
        if (r2 >= (kind[j] == kFluid ? fluid2 : wall2) || r2 == 0) continue;
        Vec<D> n = r / std::sqrt(r2);
        Vec<D> closing = v[i] - v[j];
        if (p_.beyond_resolved_flow && kind[j] == kFluid) closing += 0.5 * (gradient_[i] + gradient_[j]) * r;
        double approach = closing.dot(n);  // > 0: closing in
        if (approach <= 0) continue;
        double share = kind[j] == kFluid ? 0.5 : 1.0;  // equal masses; a wall does not move
        change -= (1 + p_.restitution) * share * approach * n;
      }
      dv[i] = change;
    });
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      v[i] += dv[i];
      x[i] += dt * dv[i];
      domain.wrap(x[i]);
    });
  }

 private:
  // G_i = B A^-1 with A = sum w r r^T, B = sum w (v_j - v_i) r^T over the fluid neighbours at or
  // beyond the collision distance, w = (1 - |r| / radius)^2; only for particles that have a close
  // fluid pair (closeness is symmetric, so both ends of every colliding pair get one).
  template <class Kind, class List, class Domain, class Positions, class Velocities>
  void fit_gradients(const Kind& kind, const List& nl, const Domain& domain, const Positions& x,
                     const Velocities& v) {
    gradient_.resize(x.size());
    const double close2 = p_.fluid_distance * p_.fluid_distance, radius = nl.radius;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Mat<D> a = Mat<D>::Zero(), b = Mat<D>::Zero();
      bool close = false;
      for (auto j : nl.of(i)) {
        if (kind[j] != kFluid) continue;
        Vec<D> r = domain.offset(x[i], x[j]);
        double r2 = r.squaredNorm();
        if (r2 < close2) {
          close = true;
          continue;
        }
        double w = 1 - std::sqrt(r2) / radius;
        w *= w;
        a += w * r * r.transpose();
        b += w * (v[j] - v[i]) * r.transpose();
      }
      gradient_[i] = Mat<D>::Zero();
      if (!close) return;
      Eigen::SelfAdjointEigenSolver<Mat<D>> moments(a, Eigen::EigenvaluesOnly);
      if (moments.eigenvalues()(0) > 0.25 * a.trace() / D) gradient_[i] = b * a.inverse();
    });
  }

  PairCollisionParameters p_;
  std::vector<Vec<D>> dv_;        // this step's velocity change per particle (scratch)
  std::vector<Mat<D>> gradient_;  // fitted velocity gradients, where a close pair needs one (scratch)
};

}  // namespace ryushi
