#pragma once
// The run's physical checks after every step ([health], docs/health.md): what a numerically
// "successful" step can still get wrong. HealthCheck (health_check.hpp) catches states that are
// not numbers or left the box; this catches a flow that is no longer the one the method models:
//   density    more than 2% of the fluid compressed (or expanded) beyond the method's bound (wcsph
//              2 (U / c0)^2, twice what the flow's own pressure does to a weakly compressible fluid)
//              for longer than a pressure wave takes to cross the fluid, L / c0
//   energy     the fluid's kinetic plus potential energy above its start by more than a fraction
//              of the energy scale, where nothing in the scene adds energy
//   pressure   |p| beyond a multiple of the scene's hydrostatic and dynamic pressure scale
//   walls      a fluid particle surrounded by the wall particles of a static wall
// All four come from one pass over the particles (the cost is a reduction, measured in
// docs/health.md). Each finding names the step, the check, the particle and the likely cause.
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "ecs/world.hpp"
#include "scene/scene.hpp"
#include "systems/method_context.hpp"

namespace ryushi {

struct HealthFinding {
  std::string check;    // density, energy, pressure, walls
  std::string message;  // without the step: the runner adds where and when
  std::string column;   // the column whose last writer the runner names
  std::string cause;    // the likely causes, for the message's end
};

// Fluid particles inside static wall layers: a grid of cells of one spacing over the walls, a
// cell marked where a wall (or dummy) particle's centre lies. A fluid particle whose cell and the
// 3^D - 1 cells around it (diagonals included) are all marked stands a spacing or more inside a
// wall of three layers or more; fluid beside a wall's face, or past both faces of a corner by a
// fraction of a spacing (an MPS dam break's tongue in the far corner), has an unmarked cell
// around it on the fluid's side.
template <int D>
class WallCells {
 public:
  // Marks the cells of the particles of kind kWall and kDummy; nothing when there are none or
  // the grid would exceed 2^30 cells (a huge domain at a tiny spacing: the check is then off).
  void build(const World<D>& w, double spacing) {
    auto& x = w.column(components::position);
    auto& kind = w.column(components::kind);
    Vec<D> lo = Vec<D>::Constant(1e300), hi = Vec<D>::Constant(-1e300);
    for (std::size_t i = 0; i < w.size(); ++i)
      if (kind[i] == kWall || kind[i] == kDummy) lo = lo.cwiseMin(x[i]), hi = hi.cwiseMax(x[i]);
    marked_.clear();
    if (lo[0] > hi[0]) return;
    inv_ = 1 / spacing;
    origin_ = lo - Vec<D>::Constant(0.5 * spacing);  // lattice walls' centres mid-cell
    double cells = 1;
    for (int a = 0; a < D; ++a) {
      count_[a] = static_cast<long>(std::floor((hi[a] - origin_[a]) * inv_)) + 1;
      cells *= double(count_[a]);
    }
    if (cells > double(1LL << 30)) return;
    marked_.assign(static_cast<std::size_t>(cells), false);
    for (std::size_t i = 0; i < w.size(); ++i)
      if (kind[i] == kWall || kind[i] == kDummy) marked_[index(cell_of(x[i]))] = true;
  }
  bool empty() const { return marked_.empty(); }
  bool inside(const Vec<D>& x) const {
    const auto c = cell_of(x);
    if (!marked(c)) return false;
    for (int k = 0; k < (D == 2 ? 9 : 27); ++k) {
      auto n = c;
      for (int a = 0, rest = k; a < D; ++a, rest /= 3) n[a] += rest % 3 - 1;
      if (!marked(n)) return false;
    }
    return true;
  }

 private:
  std::array<long, D> cell_of(const Vec<D>& x) const {
    std::array<long, D> c;
    for (int a = 0; a < D; ++a) c[a] = static_cast<long>(std::floor((x[a] - origin_[a]) * inv_));
    return c;
  }
  bool marked(const std::array<long, D>& c) const {
    for (int a = 0; a < D; ++a)
      if (c[a] < 0 || c[a] >= count_[a]) return false;
    return marked_[index(c)];
  }
  std::size_t index(const std::array<long, D>& c) const {
    std::size_t k = 0;
    for (int a = D - 1; a >= 0; --a) k = k * std::size_t(count_[a]) + std::size_t(c[a]);
    return k;
  }
  std::vector<bool> marked_;
  Vec<D> origin_ = Vec<D>::Zero();
  std::array<long, D> count_{};
  double inv_ = 1;
};

template <int D>
class HealthMonitor {
 public:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  // More than this fraction of the fluid particles, and more than this many, beyond the density bound.
  static constexpr double kDensityFraction = 0.02, kDensityCount = 10;

  // At the start (or a resume: the scales are the scene's start, which a resume does not have,
  // so they are taken from the restored state then).
  void prepare(const Scene& sc, const World<D>& w, const MethodContext<D>& ctx) {
    spec_ = sc.health;
    rho0_ = ctx.rho0;
    gravity_ = ctx.gravity;
    const bool adds_energy = !sc.elastic.empty() || !sc.fixed_pressure.empty() || !sc.systems.empty() ||
                             std::any_of(sc.solids.begin(), sc.solids.end(),
                                         [](auto& s) { return s.moves() || !s.velocity.empty(); });
    bool periodic_along_gravity = false;  // the potential energy jumps where a particle wraps
    for (int a = 0; a < D; ++a) periodic_along_gravity |= sc.periodic[a] && gravity_[a] != 0;
    // A disordered start is not in equilibrium: its pressure field holds energy that the first
    // steps release (an MPS tank at 30% disorder: +11.7% of the scale in one step), which kinetic
    // plus potential energy does not count.
    check_energy_ = spec_.energy_rise > 0 && !adds_energy && !periodic_along_gravity && sc.disorder == 0;
    const bool solids_move =
        std::any_of(sc.solids.begin(), sc.solids.end(), [](auto& s) { return s.moves(); });
    if (spec_.wall_penetration && !solids_move) walls_.build(w, ctx.spacing);
    // A [[systems]] entry may move wall particles itself (elastic_line_contact's surface): the
    // cells are then marked again at every check, from where the walls are.
    rebuild_walls_ = !walls_.empty() && !sc.systems.empty();
    spacing_ = ctx.spacing;
    if (rebuild_walls_) wall_signature_ = wall_signature(w);
    // The scales, from the start.
    auto& x = w.column(components::position);
    auto& v = w.column(components::velocity);
    auto& m = w.column(components::mass);
    auto& p = w.column(components::pressure);
    auto& kind = w.column(components::kind);
    const double g = gravity_.norm();
    const Vec<D> down = g > 0 ? Vec<D>(gravity_ / g) : Vec<D>::Zero();
    double lowest = 1e300, highest = -1e300, speed = 0, p0 = 0, kinetic = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (kind[i] != kFluid) {
        if (kind[i] == kWall) speed = std::max(speed, v[i].norm());
        continue;
      }
      const double height = -down.dot(x[i]);
      lowest = std::min(lowest, height), highest = std::max(highest, height);
      speed = std::max(speed, v[i].norm());
      p0 = std::max(p0, std::abs(p[i]));
      kinetic += 0.5 * m[i] * v[i].squaredNorm();
    }
    for (auto& s : sc.solids)
      if (!s.velocity.empty()) {
        double s2 = 0;
        for (double c : s.velocity) s2 += c * c;
        speed = std::max(speed, std::sqrt(s2));
      }
    for (auto& box : sc.fixed_pressure) p0 = std::max(p0, std::abs(box.pressure));
    const double depth = highest > lowest ? highest - lowest : 0;
    const double u = std::max(speed, std::sqrt(2 * g * depth));
    // A slow viscous flow's pressure is its viscous stress at the particle scale, mu U / d (a
    // sliding plate at Re << 1: rho U^2 / 2 was 7.8e-8 Pa and the flow's pressure 50 times that).
    pressure_scale_ = std::max({rho0_ * (g * depth + 0.5 * u * u), ctx.viscosity * u / ctx.spacing, p0});
    double potential = 0;
    for (std::size_t i = 0; i < w.size(); ++i)
      if (kind[i] == kFluid) potential += m[i] * g * (-down.dot(x[i]) - lowest);
    energy_scale_ = kinetic + potential;
    const Pass start = pass(w);
    energy0_ = start.energy, volume0_ = start.volume;
    extremes_ = RunExtremes{};
    // The longest way across the fluid at the start, for the density check's wait L / c0.
    Vec<D> lo = Vec<D>::Constant(1e300), hi = Vec<D>::Constant(-1e300);
    for (std::size_t i = 0; i < w.size(); ++i)
      if (kind[i] == kFluid) lo = lo.cwiseMin(x[i]), hi = hi.cwiseMax(x[i]);
    crossing_ = spec_.sound_speed > 0 && lo[0] <= hi[0] ? (hi - lo).maxCoeff() / spec_.sound_speed : 0.0;
    if (!(energy_scale_ > 0)) check_energy_ = false;
  }

  // The first broken check after the step that reached `time` (density, walls, pressure, energy in
  // that order), or none.
  std::optional<HealthFinding> check(const World<D>& w, double time) {
    if (rebuild_walls_) {  // only when a wall moved: the grid spans the whole wall extent
      const double moved = wall_signature(w);
      if (moved != wall_signature_) walls_.build(w, spacing_), wall_signature_ = moved;
    }
    const Pass r = pass(w);
    if (r.deviation > extremes_.density_deviation)
      extremes_.density_deviation = r.deviation, extremes_.density_time = time;
    const double dv = volume0_ > 0 ? r.volume / volume0_ - 1 : 0.0;
    if (std::abs(dv) > std::abs(extremes_.volume_change))
      extremes_.volume_change = dv, extremes_.volume_time = time;
    auto& ids = w.column(components::id);
    auto where = [&](std::size_t i) {
      std::ostringstream s;
      s << "particle id " << ids[i] << " at (";
      auto& x = w.column(components::position)[i];
      for (int a = 0; a < D; ++a) s << (a ? ", " : "") << x[a];
      s << ")";
      return s.str();
    };
    std::ostringstream m;
    m.precision(3);
    // The bulk of the fluid, not its extremes: an impact's water hammer compresses the few
    // particles at the wall by up to U / c0 (the dam break's corner 7-8%; seed 002's block on the
    // elastic plate 1.5% of the water beyond 2%), which is the flow, not its failure.
    // And for longer than the impact's compression takes to leave: a pressure wave's crossing of
    // the fluid, L / c0 (the block's impact held 2.01% of the water beyond 2% for a few steps).
    const bool compressed =
        spec_.density_deviation > 0 && r.beyond > std::max(kDensityFraction * r.fluid, kDensityCount);
    if (!compressed) compressed_since_ = -1;
    if (compressed && compressed_since_ < 0) compressed_since_ = time;
    if (compressed && time - compressed_since_ > crossing_) {
      m << r.beyond << " fluid particles (" << 100.0 * r.beyond / r.fluid << "% of the fluid, more than "
        << 100 * kDensityFraction << "% and " << kDensityCount << ") are " << 100 * spec_.density_deviation
        << "% or more from rho0 ([health] density_deviation), the most " << where(r.deviation_at) << " by "
        << 100 * r.deviation << "%, since t = " << compressed_since_
        << " s (longer than a pressure wave's crossing of "
        << "the fluid, " << crossing_ << " s): no longer a weakly compressible flow";
      return HealthFinding{
          "density", m.str(), "density",
          "a step too long (time.cfl), a sound speed too low for the flow's speed, delta-SPH off"};
    }
    if (r.inside_wall != kNone) {
      m << where(r.inside_wall) << ": a fluid particle inside the wall layers";
      return HealthFinding{
          "walls", m.str(), "position",
          "a step too long for the walls' repulsion (time.cfl), delta-SPH or viscosity off in an impact"};
    }
    if (spec_.pressure_factor > 0 && pressure_scale_ > 0 &&
        r.pressure > spec_.pressure_factor * pressure_scale_) {
      m << where(r.pressure_at) << ": |p| = " << r.pressure << " Pa, " << r.pressure / pressure_scale_
        << " times the scene's pressure scale " << pressure_scale_
        << " Pa (above [health] pressure_factor = " << spec_.pressure_factor << ")";
      return HealthFinding{"pressure", m.str(), "pressure",
                           "a step too long (time.cfl), a smoothing_ratio too small"};
    }
    if (check_energy_ && r.energy - energy0_ > spec_.energy_rise * energy_scale_) {
      m << "the fluid's kinetic plus potential energy rose " << r.energy - energy0_ << " J"
        << (D == 2 ? "/m" : "") << " above its start, " << 100 * (r.energy - energy0_) / energy_scale_
        << "% of the energy scale " << energy_scale_
        << " (above [health] energy_rise = " << 100 * spec_.energy_rise
        << "%), with nothing in the scene adding energy; the fastest is " << where(r.fastest) << " at "
        << std::sqrt(r.speed2) << " m/s";
      return HealthFinding{"energy", m.str(), "velocity",
                           "a step too long (time.cfl), no viscosity or density diffusion"};
    }
    return std::nullopt;
  }

  // The state a checkpoint carries, so that a resumed run keeps the original start's energy and
  // scales and the density check's timer (what prepare() would take from the resumed state).
  // And the run's extremes so far (from 2026-11-29; a checkpoint of the five-value layout before
  // that resumes with the extremes from the resumed state on).
  std::vector<double> state() const {
    return {energy0_,
            energy_scale_,
            pressure_scale_,
            compressed_since_,
            check_energy_ ? 1.0 : 0.0,
            volume0_,
            extremes_.density_deviation,
            extremes_.density_time,
            extremes_.volume_change,
            extremes_.volume_time};
  }
  void restore(const std::vector<double>& s) {
    if (s.size() != 5 && s.size() != 10) return;  // another version's layout: keep the resumed state's
    energy0_ = s[0], energy_scale_ = s[1], pressure_scale_ = s[2], compressed_since_ = s[3];
    check_energy_ = check_energy_ && s[4] != 0;
    if (s.size() == 10) volume0_ = s[5], extremes_ = RunExtremes{s[6], s[7], s[8], s[9]};
  }
  // The largest |rho / rho0 - 1| of a fluid particle and the largest change of the fluid volume
  // sum m / rho (signed, relative to the start) after any step of the run, with their times:
  // what a check of the last frame alone would miss (an impact's peak).
  struct RunExtremes {
    double density_deviation = 0, density_time = 0, volume_change = 0, volume_time = 0;
  };
  const RunExtremes& extremes() const { return extremes_; }
  double pressure_scale() const { return pressure_scale_; }
  double energy_scale() const { return check_energy_ ? energy_scale_ : 0.0; }

 private:
  struct Pass {
    double deviation = 0, pressure = 0, energy = 0, speed2 = 0, volume = 0;
    std::size_t fluid = 0, beyond = 0;  // fluid particles, and those beyond the density bound
    std::size_t deviation_at = kNone, pressure_at = kNone, inside_wall = kNone, fastest = kNone;
  };

  Pass pass(const World<D>& w) const {
    auto& x = w.column(components::position);
    auto& v = w.column(components::velocity);
    auto& m = w.column(components::mass);
    auto& rho = w.column(components::density);
    auto& p = w.column(components::pressure);
    auto& kind = w.column(components::kind);
    const bool density = spec_.density_deviation > 0, walls = !walls_.empty();
    const double inv_rho0 = 1 / rho0_;
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, w.size(), 8192), Pass{},
        [&](auto range, Pass r) {
          for (std::size_t i = range.begin(); i != range.end(); ++i) {
            if (kind[i] != kFluid) continue;
            ++r.fluid;
            // The deviation and the volume for every method: the run's extremes (summary.json).
            const double e = std::abs(rho[i] * inv_rho0 - 1);
            if (e > r.deviation) r.deviation = e, r.deviation_at = i;
            if (density && e > spec_.density_deviation) ++r.beyond;
            if (rho[i] > 0) r.volume += m[i] / rho[i];
            const double a = std::abs(p[i]);
            if (a > r.pressure) r.pressure = a, r.pressure_at = i;
            const double v2 = v[i].squaredNorm();
            if (v2 > r.speed2) r.speed2 = v2, r.fastest = i;
            r.energy += m[i] * (0.5 * v2 - gravity_.dot(x[i]));
            if (walls && i < r.inside_wall && walls_.inside(x[i])) r.inside_wall = i;
          }
          return r;
        },
        [](Pass a, const Pass& b) {
          if (b.deviation > a.deviation) a.deviation = b.deviation, a.deviation_at = b.deviation_at;
          if (b.pressure > a.pressure) a.pressure = b.pressure, a.pressure_at = b.pressure_at;
          a.fluid += b.fluid, a.beyond += b.beyond;
          if (b.speed2 > a.speed2) a.speed2 = b.speed2, a.fastest = b.fastest;
          a.energy += b.energy, a.volume += b.volume;
          a.inside_wall = std::min(a.inside_wall, b.inside_wall);
          return a;
        });
  }

  HealthSpec spec_;
  double rho0_ = 1000, pressure_scale_ = 0, energy_scale_ = 0, energy0_ = 0;
  double volume0_ = 0;  // the fluid volume sum m / rho at the start
  RunExtremes extremes_;
  double crossing_ = 0;           // L / c0, the density check's wait
  double compressed_since_ = -1;  // when the fluid's bulk last went beyond the density bound (-1: it is not)
  Vec<D> gravity_ = Vec<D>::Zero();
  bool check_energy_ = false;
  WallCells<D> walls_;
  bool rebuild_walls_ = false;
  double spacing_ = 0, wall_signature_ = 0;
  // The sum of the wall particles' coordinates, weighted by index: changes when any of them moves.
  static double wall_signature(const World<D>& w) {
    auto& x = w.column(components::position);
    auto& kind = w.column(components::kind);
    double s = 0;
    for (std::size_t i = 0; i < w.size(); ++i)
      if (kind[i] == kWall || kind[i] == kDummy) s += double(i + 1) * x[i].sum();
    return s;
  }
};

}  // namespace ryushi
