#pragma once
// The driver's checks after every step (app/runner.hpp): a particle that is not finite, left the
// domain or (with a fixed step) crossed more than a spacing is a numerical failure, exit 3; and
// the conservation figures summary.json reports (mass, volume, momentum, energy).
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ecs/world.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The first fluid particle (lowest index) with a non-finite or out-of-domain state, or, with a
// fixed time.dt, one that crossed more than a spacing in the last step (|v| dt > d: CFL above 1;
// a fixed step that is too large otherwise "completes" a tank at rest with particles at 26 m/s,
// MPS at twice its limit). With the adaptive step the control shortens the next step instead: a
// splash particle that jumps to 3x the fastest speed within one step is not a failure (an MPS
// dam break at CFL 0.4 survives one at t = 0.24 s).
template <int D>
struct HealthCheck {
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t index = kNone;
  std::string column, problem;

  bool density_may_vanish = false;

  // dt: the step just taken (0: not checked); spacing: the initial particle spacing d.
  void run(const World<D>& w, const Domain<D>& domain, double dt = 0, double spacing = 0) {
    auto& x = w.column(components::position);
    auto& v = w.column(components::velocity);
    auto& rho = w.column(components::density);
    auto& p = w.column(components::pressure);
    auto& kind = w.column(components::kind);
    auto bad = [&](std::size_t i) -> int {
      if (kind[i] != kFluid && kind[i] != kElastic) return 0;  // walls are placed, not integrated
      if (!x[i].allFinite()) return 1;
      if (!v[i].allFinite()) return 2;
      if (!std::isfinite(rho[i]) || rho[i] < 0 || (rho[i] == 0 && !density_may_vanish)) return 3;
      if (!std::isfinite(p[i])) return 4;
      if (!domain.contains(x[i])) return 5;
      if (dt > 0 && v[i].squaredNorm() * dt * dt > spacing * spacing) return 6;
      return 0;
    };
    index = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, w.size(), 8192), kNone,
        [&](auto r, std::size_t found) {
          for (std::size_t i = r.begin(); i != r.end() && i < found; ++i)
            if (bad(i)) return i;
          return found;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
    if (index == kNone) return;
    static const char* columns[] = {"",         "position", "velocity", "density",
                                    "pressure", "position", "velocity"};
    static const char* problems[] = {"",
                                     "non-finite position",
                                     "non-finite velocity",
                                     "non-finite or non-positive density",
                                     "non-finite pressure",
                                     "left the domain",
                                     ""};
    int code = bad(index);
    column = columns[code];
    problem = problems[code];
    if (code == 6) {
      std::ostringstream m;
      m << "crossed " << v[index].norm() * dt / spacing << " spacings in one step (|v| = " << v[index].norm()
        << " m/s, dt = " << dt << " s: CFL above 1; the time step is too large for this flow)";
      problem = m.str();
    }
  }
};

struct Diagnostics {
  std::size_t fluid = 0, walls = 0;
  double fluid_mass = 0, fluid_volume = 0, kinetic_energy = 0, max_speed = 0, max_density_deviation = 0;
  // Total fluid momentum (x, y, z) and sum m |v|, the scale it is judged against: in a closed
  // periodic box a pairwise-antisymmetric method keeps the total to round-off.
  std::array<double, 3> momentum{0, 0, 0};
  double momentum_scale = 0;
};

template <int D>
Diagnostics diagnose(const World<D>& w, double rho0) {
  Diagnostics d;
  auto& kind = w.column(components::kind);
  auto& m = w.column(components::mass);
  auto& v = w.column(components::velocity);
  auto& rho = w.column(components::density);
  auto& id = w.column(components::id);
  // The mass is summed in id order, so reordering particles by cell cannot change the total
  // by round-off: an unchanged set of particles gives a bit-identical mass.
  std::vector<double> mass_by_id, volume_by_id;
  std::vector<Vec<D>> momentum_by_id;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (kind[i] != kFluid) {
      ++d.walls;
      continue;
    }
    ++d.fluid;
    if (mass_by_id.size() <= std::size_t(id[i]))
      mass_by_id.resize(id[i] + 1, 0.0), volume_by_id.resize(id[i] + 1, 0.0),
          momentum_by_id.resize(id[i] + 1, Vec<D>::Zero());
    mass_by_id[id[i]] = m[i];
    momentum_by_id[id[i]] = m[i] * v[i];
    d.momentum_scale += m[i] * v[i].norm();
    volume_by_id[id[i]] = rho[i] > 0 ? m[i] / rho[i] : 0.0;
    d.kinetic_energy += 0.5 * m[i] * v[i].squaredNorm();
    d.max_speed = std::max(d.max_speed, v[i].norm());
    d.max_density_deviation = std::max(d.max_density_deviation, std::abs(rho[i] / rho0 - 1));
  }
  for (double mi : mass_by_id) d.fluid_mass += mi;
  for (double vi : volume_by_id) d.fluid_volume += vi;
  for (auto& p : momentum_by_id)
    for (int a = 0; a < D; ++a) d.momentum[a] += p[a];
  return d;
}

}  // namespace ryushi
