#include "systems/probes/probes.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <limits>

namespace ryushi {

namespace {

template <class Body>
auto reduce_particles(std::size_t n, std::pair<double, double> init, Body&& body, bool take_max) {
  using Pair = std::pair<double, double>;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, 4096), init,
      [&](auto r, Pair acc) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) body(i, acc);
        return acc;
      },
      [take_max](Pair a, Pair b) {
        return take_max ? Pair{std::max(a.first, b.first), 0.0} : Pair{a.first + b.first, a.second + b.second};
      });
}

}  // namespace

template <int D>
std::vector<double> sample_probes(const std::vector<ProbeSpec>& probes, const World<D>& world,
                                  const Kernel<D>& kernel, double d) {
  auto& x = world.column(components::position);
  auto& kind = world.column(components::kind);
  auto& p = world.column(components::pressure);
  auto& rho = world.column(components::density);
  auto& m = world.column(components::mass);
  const double lowest = -std::numeric_limits<double>::infinity();
  std::vector<double> out;
  for (auto& probe : probes) {
    Vec<D> at = Vec<D>::Zero();
    for (std::size_t a = 0; a < probe.position.size(); ++a) at[a] = probe.position[a];
    if (probe.type == "pressure") {
      auto [num, den] = reduce_particles(world.size(), {0.0, 0.0}, [&](std::size_t i, auto& acc) {
        if (kind[i] != kFluid) return;
        double w = kernel.w((x[i] - at).norm()) * m[i] / rho[i];
        acc.first += p[i] * w;
        acc.second += w;
      }, false);
      out.push_back(den > 0 ? num / den : std::numeric_limits<double>::quiet_NaN());
    } else if (probe.type == "surge_front") {
      auto r = reduce_particles(world.size(), {lowest, 0.0}, [&](std::size_t i, auto& acc) {
        if (kind[i] == kFluid) acc.first = std::max(acc.first, x[i][0]);
      }, true);
      out.push_back(r.first + 0.5 * d);
    } else {  // water_height
      auto r = reduce_particles(world.size(), {lowest, 0.0}, [&](std::size_t i, auto& acc) {
        if (kind[i] != kFluid) return;
        for (int a = 0; a < D - 1; ++a)
          if (std::abs(x[i][a] - at[a]) > d) return;
        acc.first = std::max(acc.first, x[i][D - 1]);
      }, true);
      out.push_back(std::isfinite(r.first) ? r.first + 0.5 * d : 0.0);
    }
  }
  return out;
}

template std::vector<double> sample_probes<2>(const std::vector<ProbeSpec>&, const World<2>&, const Kernel<2>&, double);
template std::vector<double> sample_probes<3>(const std::vector<ProbeSpec>&, const World<3>&, const Kernel<3>&, double);

}  // namespace ryushi
