#pragma once
// The steady-state stop ([time] steady_tolerance, steady_window): a flow driven to a steady state
// (a lid-driven cavity, a Couette or Poiseuille channel) stops once its kinetic energy has changed
// by less than the tolerance over the window; the run's status is then "steady". Off (tolerance 0)
// it costs nothing; on, one pass over the fluid's velocities a step.
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "ecs/component.hpp"
#include "ecs/world.hpp"

namespace ryushi {

template <int D>
double fluid_kinetic_energy(const World<D>& world) {
  const auto& kind = world.column(components::kind);
  const auto& m = world.column(components::mass);
  const auto& v = world.column(components::velocity);
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, kind.size(), 4096), 0.0,
      [&](auto range, double e) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
          if (kind[i] == kFluid) e += 0.5 * m[i] * v[i].squaredNorm();
        return e;
      },
      std::plus<>());
}

class SteadyStop {
 public:
  // window <= 0: a tenth of the time run so far (the "last 10% of the run").
  SteadyStop(double tolerance, double window) : tolerance_(tolerance), window_(window) {}
  bool enabled() const { return tolerance_ > 0; }

  // After a step at time t with kinetic energy e: true once |e - e(t - window)| <= tolerance
  // max(e, e(t - window)), the window inside the run and ten steps long at least. `message` then
  // says so.
  bool reached(double t, double e) {
    history_.emplace_back(t, e);
    const double window = window_ > 0 ? window_ : 0.1 * t;
    const double since = t - window;
    if (since < history_.front().first) return false;
    // The last sample at or before t - window; the window must span ten steps at least.
    auto it = std::upper_bound(history_.begin(), history_.end(), since,
                               [](double s, const auto& h) { return s < h.first; });
    if (history_.end() - it < 10) return false;
    const auto& [t0, e0] = *(it - 1);
    const double change = std::abs(e - e0), scale = std::max(e, e0);
    if (change > tolerance_ * scale) return false;
    char b[200];
    std::snprintf(b, sizeof b,
                  "steady at t = %.6g s: the kinetic energy changed by %.3g of itself since t = %.6g s", t,
                  scale > 0 ? change / scale : 0.0, t0);
    message = b;
    return true;
  }
  std::string message;

 private:
  double tolerance_, window_;
  std::vector<std::pair<double, double>> history_;  // (t, kinetic energy) after every step
};

}  // namespace ryushi
