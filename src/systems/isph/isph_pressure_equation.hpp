#pragma once
// Assembles the ISPH pressure equation (ISPH paper eq. 18) at the predicted positions x*:
//   fluid, free surface          p = p_s at the surface (0, or the Laplace pressure a surface
//                                tension system writes in surface_pressure): with
//                                free_surface_pressure = extrapolated
//                                p_i + d/2 N_i . <grad p>_i = p_s (the surface lies half a spacing
//                                outside the particle's centre, along its normal N_i; where
//                                det M_i < 0.2, a splash, and with = particle: p_i = p_s, no row,
//                                as eq. 18 writes it)
//   fluid, interior              -<lap p>_i = -rho0/dt <div v*>_i                      (eq. 5)
//   wetted wall                  n_i . <grad p>_i = rho0/dt (v*_i - v_wall,i) . n_i     (eq. 17)
//   wall, wall_rows = "adami"    p_i - sum_f s_f p_f = rho0 (g - a_w) . sum_f s_f (x_i - x_f)
//                                on every layer a fluid support reaches (Adami et al. 2012)
//   fluid in a [[fixed_pressure]] box: no row, its value moves to its neighbours' b (Eulerian
//                                inlet and outlet: ISPH paper section 6(1))
// <lap p> is the scene's Laplacian as weights (operators/laplacian_choice.hpp); <div v*> is the
// corrected divergence, uncorrected where det(M_i) < uncorrected_divergence_det (I-SPH(2) 3(2));
// wall neighbours carry their own velocity. The wall row holds the corrected gradient at the wall
// particle (one layer, ISPH paper section 4) with v*_i interpolated from the fluid neighbours
// (Shepard), scaled by 1/h so its entries are of the order of the fluid rows'. A wall is wetted
// when a fluid particle lies in front of it (within 41 degrees of -n; in 3D the distance from the
// wall counted at most d) inside d* = 1.1 sqrt(D) d (the first shell of the lattice): wall
// particles above the water carry p = 0 (air), not the hydrostatic line continued upwards, whose
// negative pressure pulled the surface up the walls of a resting tank; they drop out of every
// stencil (pressure_neighbours_resource). A wall or surface row without weight along
// its normal (diagonal below 0.1/h^2 or 0.1/d^2) becomes p_i = 0. The matrix is not symmetric
// (BiCGSTAB); every diagonal is positive. Surface rows are scaled by 1/d^2.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <span>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "ecs/io.hpp"
#include "systems/free_surface/free_surface_detection.hpp"
#include "systems/isph/compression_density.hpp"
#include "systems/isph/isph_parameters.hpp"
#include "systems/isph/wetted_neighbours.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/operators/gradient.hpp"
#include "systems/operators/laplacian_choice.hpp"
#include "systems/pressure/pressure_gauge.hpp"
#include "systems/pressure/pressure_system.hpp"

namespace ryushi {

template <int D>
class IsphPressureEquation final : public System<D> {
 public:
  explicit IsphPressureEquation(const IsphParameters<D>& p)
      : p_(p),
        compression_error_(p.kernel, p.spacing, p.compression_density, p.wall_adami, p.compression_dead_band) {}
  std::string name() const override { return "ppe_assembly"; }
  auto io() const {  // id: to name a particle whose row is bad
    return Io{reads(components::position, components::velocity, components::mass, components::density,
                    components::kind, components::id, components::free_surface, components::surface_normal,
                    components::wall_normal, neighbours_resource, resources::dt),
              writes(pressure_system_resource, pressure_neighbours_resource),
              optional(p_.fixed_pressure, reads(components::fixed_pressure)),
              optional((p_.wall_adami || p_.wall_shepard_hydrostatic) && p_.wall_acceleration,
                       reads(components::body_acceleration)),
              optional(p_.surface_pressure, reads(components::surface_pressure))};
  }
  Access access() const override { return io().access(); }
  void initialise(World<D>&, Resources& res) override {
    res.ensure(pressure_system_resource);
    res.ensure(pressure_neighbours_resource);
  }

  void run(SystemContext<D>& ctx) override {
    // dt: the step's own (the source is the motion it integrates). fixed: Dirichlet values other
    // than 0 (moved to b); acceleration: a moving body's, for the wall rows. Empty if none.
    // surface_value: the free surface's Dirichlet values (a surface tension's Laplace pressure).
    auto [x, v, m, rho, kind, id, surface, surface_normal, normal, full, dt, sys, pressure_neighbours, fixed,
          acceleration, surface_value] = io().fetch(ctx);
    const std::size_t n = x.size();
    particle_volumes(m, rho, volume_);
    ParticleView<D> full_view{x, volume_, full, p_.kernel, p_.domain};
    const double h = p_.kernel.h(), support = p_.kernel.support(), d = p_.spacing;
    const double shell = 1.1 * std::sqrt(double(D)) * d;
    auto known = [&](std::size_t j) {
      if (!fixed.empty() && std::isfinite(fixed[j])) return fixed[j];
      return surface_value.empty() ? 0.0 : surface_value[j];  // 0 off the surface
    };

    // Which particles carry an unknown: interior fluid, extrapolated surface fluid, wetted walls.
    unknown_.assign(n, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] == kFluid) {
          unknown_[i] =
              !surface[i] || (p_.extrapolated_surface && moment_matrix(full_view, i).determinant() >= 0.2);
          if (!fixed.empty() && std::isfinite(fixed[i])) unknown_[i] = 0;  // [[fixed_pressure]]
        } else if (kind[i] == kWall && p_.wall_adami) {
          // Every wall particle a fluid particle's support reaches: the layers complete it.
          for (auto j : full.of(i))
            if (kind[j] == kFluid && full_view.r(i, j).norm() < support) {
              unknown_[i] = 1;
              break;
            }
        } else if (kind[i] == kWall) {
          for (auto j : full.of(i)) {
            const Vec<D> r = full_view.r(i, j);
            // In front: on the fluid side of the wall's plane, the offset along the wall within
            // 0.882 x the distance from it (41 degrees of -n), in 3D that distance counted at
            // most d. Without the cap a 3D box's edge particle (bisector normal, sqrt(2) d from
            // the corner's fluid column) saw the fluid one spacing below it within 35 degrees:
            // above the water line it was wetted alone in its row, at -148 Pa in a tank at rest,
            // and pulled the corner's surface particles in until the tank blew up (docs/isph.md).
            // The face particles beside it (distance d) see that fluid at 45 degrees: dry. 2D has
            // no edge at the water line and keeps the plain angle: with the cap its dam break's
            // water stood back from the far wall at t = 2 s (front 3.81 a against >= 3.9 a).
            if (kind[j] != kFluid || r.norm() >= shell) continue;
            const double along = -r.dot(normal[i]);
            const bool within_cap =
                D == 2 || along <= d || 0.5625 * (r + along * normal[i]).squaredNorm() < 0.4375 * d * d;
            if (along > 0.75 * r.norm() && within_cap) {
              unknown_[i] = 1;
              break;
            }
          }
        }
      }
    });
    const auto& nl = restrict_to_wetted(kind, unknown_, full, pressure_neighbours);
    ParticleView<D> view{x, volume_, nl, p_.kernel, p_.domain};
    // v* seen at wall particles: the Shepard interpolation of their fluid neighbours' v*, used in
    // the Neumann rows and in the fluid rows' divergence. With the wall's own (zero) velocity
    // there, the fluid falling by g dt towards the floor read as compression and doubled the
    // pressure at the bottom row (the Neumann rows already hold the fluid up).
    v_star_.resize(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        v_star_[i] = v[i];
        if (kind[i] != kWall) continue;
        if (p_.wall_adami) {
          // The wall moves with its own velocity plus the step's gravity, as the fluid resting on
          // it does before the pressure acts: water at rest reads no divergence there and the
          // rows below hold it up; water running into the wall reads compression.
          v_star_[i] = v[i] + dt * p_.gravity;
          continue;
        }
        Vec<D> sum = Vec<D>::Zero();
        double weight = 0;
        for (auto j : nl.of(i))
          if (kind[j] == kFluid) {
            double vw = volume_[j] * p_.kernel.w(view.r(i, j).norm());
            sum += vw * v[j];
            weight += vw;
          }
        if (weight > 0) v_star_[i] = sum / weight;
      }
    });
    row_of_.assign(n, kNoRow);
    sys.particle_of_row.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (unknown_[i]) {
        row_of_[i] = static_cast<std::uint32_t>(sys.particle_of_row.size());
        sys.particle_of_row.push_back(static_cast<std::uint32_t>(i));
      }
    const std::size_t rows = sys.particle_of_row.size();
    std::size_t stride = 1;
    for (std::size_t r = 0; r < rows; ++r)
      stride = std::max(stride, nl.of(sys.particle_of_row[r]).size() + 1);
    cols_.resize(rows * stride);
    vals_.resize(rows * stride);
    counts_.assign(rows, 0);
    sys.b.resize(rows);
    sys.coordinates.resize(rows * D);

    // Eulerian particles never move: each row's operator weights stay what they were until the
    // list is rebuilt, so they are kept (the pipe's assembly: 12.2 -> 3.3 ms per step at l/d = 16).
    // Not with the compression term, which reads the stencil's distances.
    const bool keep_weights = p_.description == IsphDescription::Eulerian && p_.compression_relaxation == 0;
    const bool kept = keep_weights && kept_builds_ == full.builds && kept_rows_ == sys.particle_of_row;
    if (keep_weights && !kept) {
      kept_offset_.assign(rows + 1, 0);
      for (std::size_t r = 0; r < rows; ++r)
        kept_offset_[r + 1] = kept_offset_[r] + nl.of(sys.particle_of_row[r]).size();
      kept_w_.assign(kept_offset_[rows], 0.0);
      kept_g_.assign(kept_offset_[rows], Vec<D>::Zero());
      kept_corrected_.assign(rows, 0);
    }
    // Pass 1: each row's entries into its slot range (the weights are computed once).
    std::atomic<std::size_t> bad_row_found{kNoRow};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 256), [&](auto range) {
      std::vector<double> w;
      std::vector<Vec<D>> g;
      std::vector<std::pair<std::uint32_t, double>> entries;
      Stencil<D> stencil;  // the row particle's neighbourhood, gathered once for all its operators
      std::size_t bad_row = kNoRow;
      for (std::size_t r = range.begin(); r != range.end(); ++r) {
        const std::size_t i = sys.particle_of_row[r];
        auto nb = nl.of(i);
        entries.clear();
        if (!kept && (kind[i] == kFluid || !(p_.wall_shepard || p_.wall_adami))) stencil.gather(view, i);
        // The row's weights: computed (and kept, in the Eulerian description) or the kept ones.
        std::span<const double> wk;
        std::span<const Vec<D>> gk;
        auto kept_w = [&] { return std::span<const double>(kept_w_).subspan(kept_offset_[r], nb.size()); };
        auto kept_g = [&] { return std::span<const Vec<D>>(kept_g_).subspan(kept_offset_[r], nb.size()); };
        auto keep = [&](const std::vector<double>* wv, const std::vector<Vec<D>>& gv) {
          if (!keep_weights) return;
          if (wv) std::copy(wv->begin(), wv->end(), kept_w_.begin() + kept_offset_[r]);
          std::copy(gv.begin(), gv.end(), kept_g_.begin() + kept_offset_[r]);
        };
        auto corrected_gradient = [&]() -> std::span<const Vec<D>> {  // surface and wall rows
          if (kept) return kept_g();
          gradient_weights_corrected(stencil, g);
          keep(nullptr, g);
          return g;
        };
        double diagonal = 0, rhs = 0, from_known = 0;
        if (kind[i] == kFluid && surface[i]) {
          // p_i + d/2 N . sum_k g_k (p_k - p_i) = 0, times 1/d^2.
          gk = corrected_gradient();
          diagonal = 1.0 / (d * d);
          for (std::size_t k = 0; k < nb.size(); ++k) {
            const double along = 0.5 * surface_normal[i].dot(gk[k]) / d;
            diagonal -= along;
            if (row_of_[nb[k]] != kNoRow && along != 0)
              entries.emplace_back(row_of_[nb[k]], along);
            else
              from_known -= along * known(nb[k]);
          }
          rhs = known(i) / (d * d);
        } else if (kind[i] == kFluid) {
          bool corrected = false;  // the divergence: corrected weights, or V_k gW_k where M_i is poor
          if (kept) {
            wk = kept_w(), gk = kept_g(), corrected = kept_corrected_[r];
          } else {
            laplacian_weights(p_.ppe_laplacian, stencil, w);
            // The corrected and SPH(2) weights are not all positive: on a distorted support their
            // sum (the diagonal) can vanish or turn negative, and the row would make the matrix
            // singular. That row takes the standard (Morris) weights.
            double sum = 0;
            for (double wj : w) sum += wj;
            if (!(sum > 0)) laplacian_weights_standard(stencil, w);
            const Mat<D> M = moment_matrix(stencil);
            corrected = M.determinant() >= p_.uncorrected_divergence_det;
            if (corrected) {
              gradient_weights_corrected(stencil, renormalisation(M), g);
            } else {
              g.resize(nb.size());
              for (std::size_t k = 0; k < nb.size(); ++k) g[k] = stencil.grad_w(k);
            }
            keep(&w, g);
            if (keep_weights) kept_corrected_[r] = corrected;
            wk = w, gk = g;
          }
          for (std::size_t k = 0; k < nb.size(); ++k) {
            diagonal += wk[k];
            if (row_of_[nb[k]] != kNoRow && wk[k] != 0)
              entries.emplace_back(row_of_[nb[k]], -wk[k]);
            else
              from_known += wk[k] * known(nb[k]);
          }
          double div = 0;
          if (corrected) {
            for (std::size_t k = 0; k < nb.size(); ++k) div += gk[k].dot(v_star_[nb[k]] - v[i]);
          } else {
            for (std::size_t k = 0; k < nb.size(); ++k)
              div += volume_[nb[k]] * gk[k].dot(v_star_[nb[k]] - v[i]);
          }
          rhs = -p_.rho0 / dt * div;
          if (p_.compression_relaxation > 0) {
            // Stabilised ISPH (Asai et al. 2012): + alpha rho0 e_i / tau^2, e_i the density error of
            // compression_density.hpp (eq. 19 over the first shell where it exceeds rho0, or the
            // whole support's both ways). Without it the projection let the dam break's particles
            // pair up (median neighbour distance 0.85 d) until the surge was a cloud of surface
            // particles.
            const double excess = compression_error_(stencil, kind, surface, normal);
            // Over the scene's reference step, not the step's own: with 1/dt^2 a particle
            // pressed against a wall in an impact got a pressure that grew as the step shrank,
            // which shrank the step further (the dam break at a/d = 40 blew up at t = 1.8 s).
            const double tau = std::max(dt, p_.relaxation_time);
            rhs += p_.compression_relaxation * p_.rho0 * excess / (tau * tau);
          }
        } else if (p_.wall_adami || p_.wall_shepard) {
          // Both rows are p_i - sum_f s_f p_f = (a pressure difference), s_f = V_f W_if / sum V W
          // over the fluid neighbours, scaled by 1/h^2: diagonally dominant, no wall-wall coupling
          // (the corrected gradient along a wall carried an odd-even mode); lever = sum_f s_f (x_i - x_f).
          double total = 0, lever_n = 0;
          Vec<D> lever = Vec<D>::Zero();
          for (std::size_t k = 0; k < nb.size(); ++k)
            if (kind[nb[k]] == kFluid) total += volume_[nb[k]] * p_.kernel.w(view.r(i, nb[k]).norm());
          diagonal = 1.0 / (h * h);
          if (total > 0)
            for (std::size_t k = 0; k < nb.size(); ++k) {
              const std::size_t j = nb[k];
              if (kind[j] != kFluid) continue;
              const Vec<D> r = view.r(i, j);  // x_j - x_i
              const double s = volume_[j] * p_.kernel.w(r.norm()) / total;
              lever -= s * r;
              lever_n -= s * normal[i].dot(r);
              if (row_of_[j] != kNoRow && s != 0)
                entries.emplace_back(row_of_[j], -s / (h * h));
              else
                from_known += s / (h * h) * known(j);
            }
          const Vec<D> felt = acceleration.empty() ? p_.gravity : Vec<D>(p_.gravity - acceleration[i]);
          if (p_.wall_adami) {
            // Adami's wall pressure (seed 002 eq. 27): rho0 (g - a_w) . lever. Exact for a
            // hydrostatic field, on every layer a fluid support reaches.
            rhs = p_.rho0 * felt.dot(lever) / (h * h);
          } else {
            // p_i - p_j = (x_i - x_j) . grad p averaged with s_j: along n eq. 17's rho0/dt (v*_i -
            // v_wall) . n, along the wall 0 or (shepard_hydrostatic) rho0 (g - a_w)_t. With 0 a wall
            // particle at the contact line reads its fluid neighbours' (all below it) higher pressure
            // as its own: a resting tank circulated at 0.08 m/s (H/d = 40; hydrostatic: 1.5e-4 m/s).
            const Vec<D> along =
                p_.wall_shepard_hydrostatic ? Vec<D>(felt - normal[i].dot(felt) * normal[i]) : Vec<D>::Zero();
            rhs = (p_.rho0 / dt * (v_star_[i] - v[i]).dot(normal[i]) * lever_n + p_.rho0 * along.dot(lever)) /
                  (h * h);
          }
        } else {
          gk = corrected_gradient();
          for (std::size_t k = 0; k < nb.size(); ++k) {
            const std::size_t j = nb[k];
            const double along = normal[i].dot(gk[k]) / h;
            diagonal -= along;
            if (row_of_[j] != kNoRow && along != 0)
              entries.emplace_back(row_of_[j], along);
            else
              from_known -= along * known(j);
          }
          rhs = p_.rho0 / dt * (v_star_[i] - v[i]).dot(normal[i]) / h;
        }
        rhs += from_known;
        if (!std::isfinite(diagonal) || !std::isfinite(rhs)) bad_row = std::min(bad_row, r);
        // A boundary row (surface or wall) that lost its weight along the normal (a thin splash,
        // a wall whose wetted neighbours lie beside it) is a Dirichlet row p_i = 0 instead.
        if (kind[i] != kFluid || surface[i]) {
          const double scale = kind[i] == kFluid ? 1.0 / (d * d) : 1.0 / (h * h);
          if (!(diagonal > 0.1 * scale)) {
            entries.clear();
            diagonal = 1.0 / (d * d);
            rhs = kind[i] == kFluid ? known(i) / (d * d) : 0.0;
          }
        } else if (!(diagonal > 0)) {
          bad_row = std::min(bad_row, r);  // even the standard weights: particles on top of each other
        }
        entries.emplace_back(static_cast<std::uint32_t>(r), diagonal);
        std::sort(entries.begin(), entries.end());
        // Neighbours listed twice cannot occur; merge equal columns all the same (periodic images).
        std::size_t k = r * stride, c = 0;
        for (auto& [col, val] : entries) {
          if (c > 0 && cols_[k + c - 1] == col) {
            vals_[k + c - 1] += val;
          } else {
            cols_[k + c] = col;
            vals_[k + c++] = val;
          }
        }
        counts_[r] = c;
        sys.b[r] = rhs;
        for (int a = 0; a < D; ++a) sys.coordinates[r * D + a] = x[i][a];
      }
      for (auto seen = bad_row_found.load();
           bad_row < seen && !bad_row_found.compare_exchange_weak(seen, bad_row);) {
      }
    });
    if (bad_row_found != kNoRow) report_bad_row(kind, id, sys.particle_of_row[bad_row_found], x);
    if (keep_weights && !kept) kept_builds_ = full.builds, kept_rows_ = sys.particle_of_row;
    // Pass 2: compact into CSR.
    auto& A = sys.A;
    A.rows = A.cols = rows;
    A.row_ptr.assign(rows + 1, 0);
    for (std::size_t r = 0; r < rows; ++r) A.row_ptr[r + 1] = A.row_ptr[r] + counts_[r];
    A.col.resize(A.row_ptr[rows]);
    A.val.resize(A.row_ptr[rows]);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 1024), [&](auto range) {
      for (std::size_t r = range.begin(); r != range.end(); ++r)
        for (std::size_t c = 0; c < counts_[r]; ++c) {
          A.col[A.row_ptr[r] + c] = cols_[r * stride + c];
          A.val[A.row_ptr[r] + c] = vals_[r * stride + c];
        }
    });
    sys.fixed_values.clear();
    if (!fixed.empty())
      for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(fixed[i])) sys.fixed_values.emplace_back(static_cast<std::uint32_t>(i), fixed[i]);
    for (std::size_t i = 0; i < n && !surface_value.empty(); ++i)  // surface particles without a row
      if (kind[i] == kFluid && surface[i] && !unknown_[i] && (fixed.empty() || !std::isfinite(fixed[i])))
        sys.fixed_values.emplace_back(static_cast<std::uint32_t>(i), surface_value[i]);
    sys.dimension = D;
    sys.bucket_width = support;
    sys.symmetric = false;
    // The volumes are the left null vector of the standard (Morris) Laplacian of the fluid rows
    // only (not of the corrected one, nor of wall rows): the solve finds the exact source.
    fix_pressure_gauge(
        sys, [&](std::size_t r) { return volume_[sys.particle_of_row[r]]; }, false);
  }

 private:
  [[noreturn]] void report_bad_row(std::span<const std::int32_t> kind, std::span<const std::int32_t> id,
                                   std::size_t i, std::span<const Vec<D>> x) const {
    std::ostringstream m;
    m << (kind[i] == kFluid ? "fluid" : "wall") << " particle id " << id[i] << " at (";
    for (int a = 0; a < D; ++a) m << (a ? ", " : "") << x[i][a];
    m << ") has a pressure row without a finite diagonal or right-hand side (a particle on top of another, "
         "or a "
         "non-finite velocity)";
    throw std::runtime_error(m.str());
  }

  static constexpr std::uint32_t kNoRow = UINT32_MAX;
  IsphParameters<D> p_;
  CompressionError<D> compression_error_;
  std::vector<double> volume_;
  std::vector<Vec<D>> v_star_;
  std::vector<std::uint8_t> unknown_;
  std::vector<std::uint32_t> row_of_;
  std::vector<std::uint32_t> cols_;
  std::vector<double> vals_;
  std::vector<std::size_t> counts_;
  // Eulerian: each row's Laplacian and gradient weights (and whether its divergence is
  // corrected), kept for the list build and the rows they were computed for.
  std::size_t kept_builds_ = 0;
  std::vector<std::uint32_t> kept_rows_;
  std::vector<std::size_t> kept_offset_;
  std::vector<double> kept_w_;
  std::vector<Vec<D>> kept_g_;
  std::vector<std::uint8_t> kept_corrected_;
};

}  // namespace ryushi
